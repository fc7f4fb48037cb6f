// Recording what is on screen, with the music, as WebM (MediaRecorder): the canvas's stream
// plus a tap on the transport's output. MediaRecorder writes a live stream, without the
// Segment's Duration: players could not seek it, so the duration measured while recording is
// written into the file (fix-webm-duration) before it is offered.
import fixWebmDuration from "fix-webm-duration";
import { saveBlob } from "./dom";
import type { AudioTransport } from "./transport";

const TYPES = ["video/webm;codecs=vp9,opus", "video/webm;codecs=vp8,opus", "video/webm"];

export class Recorder {
  private recorder: MediaRecorder | null = null;
  /** performance.now() when the recording started and stopped (ms) */
  private started = 0;
  private stopped = 0;

  constructor(private readonly canvas: HTMLCanvasElement,
              private readonly transport: AudioTransport,
              private readonly button: HTMLButtonElement,
              /** starts playback (a recording of a still page would be dull) */
              private readonly play: () => void) {
    button.addEventListener("click", () => this.toggle());
  }

  get recording(): boolean { return this.recorder !== null; }

  /** Start recording (and playing), or stop and download `eigendance.webm`. */
  toggle(): void {
    if (this.recorder) {
      this.stopped = performance.now();
      this.recorder.stop();
      return;
    }
    const stream = this.canvas.captureStream(30);
    const audio = this.transport.tap();
    audio.stream.getAudioTracks().forEach((track) => stream.addTrack(track));
    const mimeType = TYPES.find((type) => MediaRecorder.isTypeSupported(type)) ?? "video/webm";
    const chunks: Blob[] = [];
    const recorder = new MediaRecorder(stream, { mimeType });
    recorder.ondataavailable = (event) => { if (event.data.size) chunks.push(event.data); };
    recorder.onstop = async () => {
      // The recording's timeline runs from start() to stop() (ms, as the Duration counts).
      const duration = this.stopped - this.started;
      this.transport.untap(audio);
      this.recorder = null;
      this.button.textContent = "● record";
      const recorded = new Blob(chunks, { type: "video/webm" });
      // A file without the duration is still a recording: keep it if the fix fails.
      const seekable = await fixWebmDuration(recorded, duration, { logger: false })
        .catch(() => recorded);
      saveBlob(seekable, "eigendance.webm");
    };
    this.started = performance.now();
    recorder.start(250);
    this.recorder = recorder;
    this.button.textContent = "■ stop";
    this.play();
  }
}
