// The AudioWorklet processor of the live input (docs/design.md#live): it mixes the input's
// channels to mono (their mean, as `eigendance.music.decode`), runs the live analysis
// (live-analysis.ts) on every 128-sample block and posts the finished frames to the page about
// every 20 ms, with the stream's first context frame, where its first sound lies and the time
// the analysis took.
import { LiveAnalyser } from "./live-analysis";
import type { Frame } from "./live-analysis";

declare const sampleRate: number;
declare const currentFrame: number;
declare function registerProcessor(name: string, processor: unknown): void;
declare class AudioWorkletProcessor {
  readonly port: MessagePort;
}

/** Frames posted at once (20 ms at 100 frames per second). */
const POST_EVERY = 2;
/** Exact zeros in a row, once sound has come, that count as a dropout of the input (a device
 * or capture that fell behind inserts silence; a microphone's own signal never holds this
 * many exact zeros). */
const DROPOUT_ZEROS = 32;
const DROPOUTS_KEPT = 100;

/** What the worklet posts: new frames, and the stream's bookkeeping. */
export interface WorkletMessage {
  frames: Frame[];
  /** context frame of the stream's sample 0 */
  origin: number;
  /** stream sample index of the first sample that is not zero (−1: none yet) */
  firstSound: number;
  /** samples received */
  samples: number;
  /** dropouts of the input so far, and where the last DROPOUTS_KEPT began (stream samples) */
  dropouts: number;
  dropoutsAt: number[];
  /** 128-sample blocks analysed, and the milliseconds they took (−1: no clock here) */
  blocks: number;
  busyMs: number;
}

const clock = (globalThis as { performance?: { now(): number } }).performance;

class LiveProcessor extends AudioWorkletProcessor {
  private readonly analyser = new LiveAnalyser(sampleRate);
  private pending: Frame[] = [];
  private origin = -1;
  private firstSound = -1;
  private samples = 0;
  private blocks = 0;
  private busyMs = 0;
  private stopped = false;
  private zeros = 0;
  private dropouts = 0;
  private dropoutsAt: number[] = [];
  private mono = new Float32Array(128);

  constructor() {
    super();
    this.port.onmessage = (event) => { if (event.data === "stop") this.stopped = true; };
  }

  process(inputs: Float32Array[][]): boolean {
    if (this.stopped) return false; // the node is let go: no more calls
    const channels = inputs[0] ?? [];
    if (!channels.length) return true; // no input connected yet
    const started = clock ? clock.now() : 0;
    if (this.origin < 0) this.origin = currentFrame;
    const length = channels[0].length;
    if (this.mono.length !== length) this.mono = new Float32Array(length);
    const mono = this.mono;
    for (let i = 0; i < length; i++) {
      let sum = 0;
      for (const channel of channels) sum += channel[i];
      mono[i] = sum / channels.length;
    }
    if (this.firstSound < 0) {
      const first = mono.findIndex((x) => x !== 0);
      if (first >= 0) this.firstSound = this.samples + first;
    } else {
      this.countDropouts(mono);
    }
    this.samples += length;
    for (const frame of this.analyser.push(mono)) this.pending.push(frame);
    this.blocks++;
    if (clock) this.busyMs += clock.now() - started;
    if (this.pending.length >= POST_EVERY) this.post();
    return true;
  }

  private countDropouts(mono: Float32Array): void {
    for (let i = 0; i < mono.length; i++) {
      if (mono[i] !== 0) { this.zeros = 0; continue; }
      if (++this.zeros === DROPOUT_ZEROS) {
        this.dropouts++;
        this.dropoutsAt.push(this.samples + i + 1 - DROPOUT_ZEROS);
        if (this.dropoutsAt.length > DROPOUTS_KEPT) this.dropoutsAt.shift();
      }
    }
  }

  private post(): void {
    const message: WorkletMessage = { frames: this.pending, origin: this.origin,
      firstSound: this.firstSound, samples: this.samples, blocks: this.blocks,
      dropouts: this.dropouts, dropoutsAt: this.dropoutsAt,
      busyMs: clock ? this.busyMs : -1 };
    this.port.postMessage(message, this.pending.map((frame) => frame.values.buffer));
    this.pending = [];
  }
}

registerProcessor("eigendance-live", LiveProcessor);
