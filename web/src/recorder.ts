// Recording what is on screen, with the music, as WebM (MediaRecorder): the canvas's stream
// plus a tap on the transport's output.
import { saveBlob } from "./dom";
import type { AudioTransport } from "./transport";

const TYPES = ["video/webm;codecs=vp9,opus", "video/webm;codecs=vp8,opus", "video/webm"];

export class Recorder {
  private recorder: MediaRecorder | null = null;

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
    if (this.recorder) { this.recorder.stop(); return; }
    const stream = this.canvas.captureStream(30);
    const audio = this.transport.tap();
    audio.stream.getAudioTracks().forEach((track) => stream.addTrack(track));
    const mimeType = TYPES.find((type) => MediaRecorder.isTypeSupported(type)) ?? "video/webm";
    const chunks: Blob[] = [];
    const recorder = new MediaRecorder(stream, { mimeType });
    recorder.ondataavailable = (event) => { if (event.data.size) chunks.push(event.data); };
    recorder.onstop = () => {
      this.transport.untap(audio);
      saveBlob(new Blob(chunks, { type: "video/webm" }), "eigendance.webm");
      this.recorder = null;
      this.button.textContent = "● record";
    };
    recorder.start(250);
    this.recorder = recorder;
    this.button.textContent = "■ stop";
    this.play();
  }
}
