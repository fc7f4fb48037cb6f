// A live input (docs/design.md#live): a microphone or line in (getUserMedia, with echo
// cancellation, noise suppression and automatic gain off, so the room is heard as it is) or a
// tab's or the system's sound (getDisplayMedia), analysed by the AudioWorklet (live-worklet.ts)
// in the page's AudioContext. `stop` lets everything go: the stream's tracks, the nodes and the
// worklet's processor, so that switching sources leaves nothing running.
import { RATE, windowLength } from "./live-analysis";
import { LiveTake } from "./live-take";
import type { WorkletMessage } from "./live-worklet";
import workletUrl from "./live-worklet.ts?worker&url";
import type { Clock } from "./transport";

export type LiveKind = "mic" | "tab";

/** What to open: the kind, and for a microphone its device (absent: the default input). */
export interface LiveChoice { kind: LiveKind; deviceId?: string; label?: string; }

/** Frames of the worklet posted at once (live-worklet.ts's POST_EVERY), s. */
const POST_SECONDS = 2 / RATE;

/** The one-line message for a failure to open `choice` (a DOMException's name decides). */
export function openFailure(error: unknown, choice: LiveChoice): string {
  const name = (error as { name?: string })?.name ?? "";
  const what = choice.kind === "tab" ? "tab or system audio" : "the microphone or line in";
  if (name === "NotAllowedError" || name === "SecurityError") {
    return `Live input: the browser was not allowed to use ${what} (permission denied); `
      + "allow it in the site's settings, or keep playing songs";
  }
  if (name === "NotFoundError" || name === "OverconstrainedError") {
    return choice.kind === "tab" ? "Live input: the shared tab or screen gives no sound "
      + "(tick “share audio” when choosing it)" : "Live input: no audio input device was found";
  }
  if (name === "NotReadableError" || name === "AbortError") {
    return `Live input: ${what} could not be opened (in use by another program, or unplugged)`;
  }
  const text = error instanceof Error ? error.message : String(error);
  return `Live input: ${what} could not be opened (${text})`;
}

/** The audio inputs the browser lists (labels only once a permission was given). */
export async function audioInputs(): Promise<MediaDeviceInfo[]> {
  if (!navigator.mediaDevices?.enumerateDevices) return [];
  return (await navigator.mediaDevices.enumerateDevices()).filter((d) => d.kind === "audioinput");
}

/** Whether this browser offers tab or system audio (getDisplayMedia). */
export const offersTabAudio = (): boolean => !!navigator.mediaDevices?.getDisplayMedia;

async function openStream(choice: LiveChoice): Promise<MediaStream> {
  const devices = navigator.mediaDevices;
  if (!devices) {
    throw Object.assign(new Error("this page is not a secure context (use localhost or https)"),
      { name: "TypeError" });
  }
  if (choice.kind === "tab") {
    if (!devices.getDisplayMedia) throw new Error("this browser does not offer tab audio");
    const stream = await devices.getDisplayMedia({ video: true, audio: {
      echoCancellation: false, noiseSuppression: false, autoGainControl: false } });
    for (const track of stream.getVideoTracks()) { track.stop(); stream.removeTrack(track); }
    if (!stream.getAudioTracks().length) {
      throw Object.assign(new Error("no sound shared"), { name: "NotFoundError" });
    }
    return stream;
  }
  return devices.getUserMedia({ audio: {
    deviceId: choice.deviceId ? { exact: choice.deviceId } : undefined,
    echoCancellation: false, noiseSuppression: false, autoGainControl: false } });
}

export class LiveInput implements Clock {
  readonly take: LiveTake;
  /** the input's own latency (track settings or the context's), s */
  readonly inputLatency: number;
  /** analysis delay: half a window, a block and the worklet's posting interval, s */
  readonly analysisDelay: number;
  /** the latency offset (s ≥ 0): the motion is delayed by this much more */
  offset = 0;
  /** the last worklet message's bookkeeping (blocks, CPU time, first sound) */
  stats: Omit<WorkletMessage, "frames"> = { origin: -1, firstSound: -1, samples: 0, blocks: 0,
    busyMs: 0, dropouts: 0, dropoutsAt: [] };
  /** Called once when the input stops by itself (a device unplugged, a shared tab closed). */
  onEnded: (message: string) => void = () => {};
  /** Called after new frames arrived. */
  onFrames: () => void = () => {};
  /** ms the page's thread spent taking frames in (the take, its rhythm), for the benchmark */
  receiveMs = 0;
  private stopped = false;

  private constructor(readonly choice: LiveChoice, readonly name: string,
                      private readonly context: AudioContext, private readonly stream: MediaStream,
                      private readonly source: MediaStreamAudioSourceNode,
                      private readonly node: AudioWorkletNode) {
    this.take = new LiveTake(name, context.sampleRate);
    const settings = stream.getAudioTracks()[0]?.getSettings() as { latency?: number };
    this.inputLatency = settings.latency ?? context.baseLatency ?? 0;
    const sr = context.sampleRate;
    this.analysisDelay = (windowLength(sr) / 2 + 128) / sr + POST_SECONDS;
    node.port.onmessage = (event) => this.receive(event.data as WorkletMessage);
    for (const track of stream.getAudioTracks()) {
      track.addEventListener("ended", () => this.end(`Live input: ${name} stopped (unplugged, `
        + "or its sharing ended); back to the song"));
    }
  }

  /** Open `choice` in `context` and start analysing; `destination` hears the input (the
   * recorder's tap). Throws an Error whose message is one clear line. */
  static async open(context: AudioContext, destination: AudioNode, choice: LiveChoice):
      Promise<LiveInput> {
    if (!context.audioWorklet) {
      throw new Error(openFailure(new Error("this page cannot run an AudioWorklet "
        + "(not a secure context: use localhost or https)"), choice));
    }
    let stream: MediaStream;
    try {
      stream = await openStream(choice);
    } catch (error) {
      throw new Error(openFailure(error, choice));
    }
    try {
      await context.audioWorklet.addModule(workletUrl);
      void context.resume();
      const source = context.createMediaStreamSource(stream);
      const node = new AudioWorkletNode(context, "eigendance-live",
        { numberOfInputs: 1, numberOfOutputs: 0 });
      source.connect(node);
      source.connect(destination);
      const track = stream.getAudioTracks()[0];
      const name = choice.kind === "tab" ? `tab audio: ${track.label || "shared"}`
        : (track.label || choice.label || "microphone");
      return new LiveInput(choice, name, context, stream, source, node);
    } catch (error) {
      for (const track of stream.getTracks()) track.stop();
      throw new Error(openFailure(error, choice));
    }
  }

  /** The device the latency offset is remembered for. */
  get deviceKey(): string {
    return this.choice.kind === "tab" ? "tab" : (this.stream.getAudioTracks()[0]
      ?.getSettings().deviceId ?? this.choice.deviceId ?? "default");
  }

  get running(): boolean { return !this.stopped; }

  /** The stream's tracks (for the recorder of takes). */
  get mediaStream(): MediaStream { return this.stream; }

  get playing(): boolean { return !this.stopped && this.context.state === "running"; }

  /** The time drawn: the stream's time now, less the analysis delay and the offset, never past
   * the newest frame (s, frame j at j/100). */
  now(): number {
    if (this.stats.origin < 0) return 0;
    const streamTime = this.context.currentTime - this.stats.origin / this.context.sampleRate;
    const wanted = streamTime - this.analysisDelay - this.offset;
    return Math.max(0, Math.min(wanted, this.take.seconds));
  }

  /** Input to motion, s: the input's latency, the analysis delay and the offset (the frame
   * drawn on screen adds one frame interval, which the page adds when it shows it). */
  get latency(): number { return this.inputLatency + this.analysisDelay + this.offset; }

  ended(): boolean { return false; }

  rewind(): void {}

  /** Let everything go (idempotent): the worklet's processor returns false, the nodes are
   * disconnected and the stream's tracks stopped. */
  stop(): void {
    if (this.stopped) return;
    this.stopped = true;
    this.node.port.postMessage("stop");
    this.node.port.onmessage = null;
    this.node.port.close();
    this.source.disconnect();
    this.node.disconnect();
    for (const track of this.stream.getTracks()) track.stop();
  }

  private end(message: string): void {
    if (this.stopped) return;
    this.stop();
    this.onEnded(message);
  }

  private receive(message: WorkletMessage): void {
    if (this.stopped) return;
    const started = performance.now();
    const { frames, ...stats } = message;
    this.stats = stats;
    this.take.add(frames);
    this.receiveMs += performance.now() - started;
    this.onFrames();
    if (this.take.full) {
      this.end(`Live input: the take reached ${this.take.seconds.toFixed(0)} s, the most kept; `
        + "choose the input again for a new take");
    }
  }
}
