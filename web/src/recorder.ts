// Recording the player's view, with the music, as WebM (MediaRecorder). The WebGL canvas lies
// behind the whole page, header and controls included: the recording is of the view alone — a
// canvas of the view's own size, into which every frame drawn copies the view's rectangle of the
// WebGL canvas — plus a tap on the transport's output. MediaRecorder writes a live stream,
// without the Segment's Duration: players could not seek it, so the duration measured while
// recording is written into the file (fix-webm-duration) before it is offered.
import fixWebmDuration from "fix-webm-duration";
import { fileName, saveBlob } from "./dom";
import type { AudioTransport } from "./transport";
import type { Viewer } from "./viewer";

const TYPES = ["video/webm;codecs=vp9,opus", "video/webm;codecs=vp8,opus", "video/webm"];

/** The recording's size for a view of `width` × `height` CSS pixels at this pixel ratio:
 * even sides (video encoders halve the chroma), at least 16 pixels. */
export function recordingSize(width: number, height: number, ratio: number):
    { width: number; height: number } {
  const even = (side: number) => Math.max(16, 2 * Math.round((side * ratio) / 2));
  return { width: even(width), height: even(height) };
}

/** What is recorded: the viewer drawing the view, and the view's element. */
export interface Recorded { viewer: Viewer; element: HTMLElement; /** the model's name (the file's) */ name: string; }

export class Recorder {
  private recorder: MediaRecorder | null = null;
  /** the canvas recorded, of the view's size, and where it copies from */
  private frame: { canvas: HTMLCanvasElement; context: CanvasRenderingContext2D } | null = null;
  private source: Recorded | null = null;
  /** performance.now() when the recording started and stopped (ms) */
  private started = 0;
  private stopped = 0;

  constructor(private readonly transport: AudioTransport,
              private readonly buttons: HTMLButtonElement[],
              /** starts playback (a recording of a still page would be dull) */
              private readonly play: () => void,
              /** the view shown now */
              private readonly shown: () => Recorded) {
    buttons.forEach((button) => button.addEventListener("click", () => this.toggle()));
  }

  get recording(): boolean { return this.recorder !== null; }

  /** The recording's size (pixels), or null when nothing records. */
  get size(): { width: number; height: number } | null {
    return this.frame ? { width: this.frame.canvas.width, height: this.frame.canvas.height } : null;
  }

  /** Start recording (and playing), or stop and download `eigendance.webm`. */
  toggle(): void {
    if (this.recorder) {
      this.stopped = performance.now();
      this.recorder.stop();
      return;
    }
    const source = this.shown();
    const name = source.name;
    const box = source.element.getBoundingClientRect();
    const { width, height } = recordingSize(box.width, box.height, Math.min(devicePixelRatio, 2));
    const canvas = document.createElement("canvas");
    canvas.width = width;
    canvas.height = height;
    this.frame = { canvas, context: canvas.getContext("2d")! };
    this.source = source;
    source.viewer.onDrawn = () => this.copy();
    source.viewer.requestDraw();
    const stream = canvas.captureStream(30);
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
      if (this.source) this.source.viewer.onDrawn = () => {};
      this.recorder = null;
      this.frame = this.source = null;
      this.buttons.forEach((button) => { button.textContent = "● record"; });
      const recorded = new Blob(chunks, { type: "video/webm" });
      // A file without the duration is still a recording: keep it if the fix fails.
      const seekable = await fixWebmDuration(recorded, duration, { logger: false })
        .catch(() => recorded);
      saveBlob(seekable, fileName(name, "dance", "webm"));
    };
    this.started = performance.now();
    recorder.start(250);
    this.recorder = recorder;
    this.buttons.forEach((button) => { button.textContent = "■ stop"; });
    this.play();
  }

  /** After a frame is drawn: its view's rectangle of the WebGL canvas into the recording (the
   * drawing buffer may be smaller than the page: dynamic resolution; it is scaled up). */
  private copy(): void {
    const { frame, source } = this;
    if (!frame || !source) return;
    const area = source.viewer.bufferRect(source.element);
    if (area.width < 1 || area.height < 1) return;
    frame.context.drawImage(source.viewer.renderer.domElement, area.x, area.y, area.width,
      area.height, 0, 0, frame.canvas.width, frame.canvas.height);
  }
}
