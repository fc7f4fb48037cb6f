// The live analysis of docs/design.md#live: the 64-band loudness of docs/design.md#spectrogram
// and the onset-strength envelope of docs/design.md#rhythm, computed sample block by sample
// block as the audio comes (in the AudioWorklet, live-worklet.ts), with the same window, bands,
// floor and smoothing as `eigendance.music.spectrogram` and its own FFT (fft.js). The constants
// come from the one file the Python analysis reads (src/eigendance/music/analysis.json).
import FFT from "fft.js";
import ANALYSIS from "../../src/eigendance/music/analysis.json";
import { BeatEnvelope, compact, melBank } from "./live-beat";
import type { MelBand } from "./live-beat";

export const RATE = ANALYSIS.rate;
export const BANDS = ANALYSIS.bands;

/** N = the smallest power of two ≥ window_seconds·sr (2048 at 44.1 kHz, 4096 at 48 kHz). */
export function windowLength(sampleRate: number): number {
  return 2 ** Math.max(0, Math.ceil(Math.log2(ANALYSIS.window_seconds * sampleRate)));
}

/** geomspace(fmin, min(fmax, sr/2), B + 1), Hz (numpy's: the ends exact). */
export function bandEdges(sampleRate: number, bands = BANDS): Float64Array {
  const low = ANALYSIS.fmin, high = Math.min(ANALYSIS.fmax, sampleRate / 2);
  const edges = Float64Array.from({ length: bands + 1 },
    (_, i) => 10 ** (Math.log10(low) + (i * (Math.log10(high) - Math.log10(low))) / bands));
  edges[0] = low;
  edges[bands] = high;
  return edges;
}

/** One analysis frame: the smoothed loudness of every band, the onset strength (dB per frame),
 * the frame's centre (a sample index of the stream), and librosa's onset strength (live-beat.ts,
 * 22050/512 frames per second: [median, mean] over mels) of the frames completed since the
 * frame before. */
export interface Frame { index: number; centre: number; values: Float32Array; onset: number;
  beat: [number, number][]; }

/** The streaming analysis of one mono stream at `sampleRate`: `push` samples, get frames
 * (100 per second) once their window is complete. Frame j is centred on sample
 * c_j = ⌊j·sr/rate + ½⌋ of the stream (samples before the stream's first are zero). */
export class LiveAnalyser {
  readonly N: number;
  readonly edges: Float64Array;
  private readonly half: number;
  private readonly window: Float64Array;
  private readonly fft: FFT;
  private readonly spectrum: number[];
  private readonly input: Float64Array;
  private readonly magnitude: Float64Array;
  /** per band: [first bin, stop bin) of its bins, or the interpolation at its centre */
  private readonly binStart: Int32Array;
  private readonly binStop: Int32Array;
  private readonly interpBelow: Int32Array;
  private readonly interpWeight: Float64Array;
  private readonly memory: number;
  private readonly state: Float64Array;
  private readonly mel: MelBand[];
  private readonly beat: BeatEnvelope;
  private beatValues: [number, number][] = [];
  private readonly lag: number;
  private readonly history: Float64Array[];
  /** the samples not yet out of every window, from absolute index `start` */
  buffer: Float32Array;
  held = 0;
  start = 0;
  private next = 0;

  constructor(readonly sampleRate: number) {
    const N = (this.N = windowLength(sampleRate));
    this.half = N / 2;
    const hann = Float64Array.from({ length: N }, (_, n) => 0.5 - 0.5 * Math.cos((2 * Math.PI * n) / N));
    const sum = hann.reduce((a, b) => a + b, 0);
    this.window = hann.map((w) => (w * 2) / sum);
    this.fft = new FFT(N);
    this.spectrum = this.fft.createComplexArray();
    this.input = new Float64Array(N);
    this.magnitude = new Float64Array(N / 2 + 1);
    this.edges = bandEdges(sampleRate);
    const B = this.edges.length - 1;
    const firstBin = (f: number) => Math.ceil((f * N) / sampleRate - 1e-9); // first bin ≥ f
    this.binStart = new Int32Array(B); this.binStop = new Int32Array(B);
    this.interpBelow = new Int32Array(B); this.interpWeight = new Float64Array(B);
    for (let b = 0; b < B; b++) {
      this.binStart[b] = firstBin(this.edges[b]);
      this.binStop[b] = firstBin(this.edges[b + 1]);
      const centre = Math.sqrt(this.edges[b] * this.edges[b + 1]);
      const below = Math.floor((centre * N) / sampleRate);
      this.interpBelow[b] = below;
      this.interpWeight[b] = (centre * N) / sampleRate - below;
    }
    this.memory = ANALYSIS.smoothing > 0 ? Math.exp(-1 / (RATE * ANALYSIS.smoothing)) : 0;
    this.state = new Float64Array(B);
    this.mel = melBank(sampleRate, N);
    this.beat = new BeatEnvelope(sampleRate);
    this.lag = Math.max(1, Math.round(ANALYSIS.onset.lag * RATE));
    this.history = Array.from({ length: this.lag },
      () => new Float64Array(this.mel.length).fill(ANALYSIS.onset.floor_db));
    this.buffer = new Float32Array(2 * N + 4096);
    this.start = -this.half; // the half window of zeros before the stream
    this.held = this.half;
  }

  /** The centre (a sample index of the stream) of frame j. */
  centre(j: number): number { return Math.floor((j * this.sampleRate) / RATE + 0.5); }

  /** Add mono samples; returns the frames they completed (often none, at most a few). */
  push(samples: Float32Array): Frame[] {
    if (this.held + samples.length > this.buffer.length) this.compact(samples.length);
    this.buffer.set(samples, this.held);
    this.held += samples.length;
    this.beatValues.push(...this.beat.push(samples));
    const frames: Frame[] = [];
    const end = this.start + this.held;
    for (;;) {
      const c = this.centre(this.next);
      if (c + this.half > end) break;
      frames.push(this.analyse(this.next, c));
      this.next++;
    }
    return frames;
  }

  /** Drop the samples every later window has passed, and make room for `more`. */
  private compact(more: number): void {
    compact(this, this.centre(this.next) - this.half, more);
  }

  private analyse(index: number, centre: number): Frame {
    const { N, input, window, magnitude, spectrum } = this;
    const from = centre - this.half - this.start;
    for (let n = 0; n < N; n++) input[n] = this.buffer[from + n] * window[n];
    this.fft.realTransform(spectrum, input);
    for (let q = 0; q <= N / 2; q++) magnitude[q] = Math.hypot(spectrum[2 * q], spectrum[2 * q + 1]);
    const B = this.state.length;
    const values = new Float32Array(B);
    const floor = ANALYSIS.floor_db;
    for (let b = 0; b < B; b++) {
      let level = 0;
      if (this.binStop[b] > this.binStart[b]) {
        for (let q = this.binStart[b]; q < this.binStop[b]; q++) level = Math.max(level, magnitude[q]);
      } else {
        const q = this.interpBelow[b], w = this.interpWeight[b];
        level = magnitude[q] * (1 - w) + magnitude[q + 1] * w;
      }
      const db = 20 * Math.log10(Math.max(level, 1e-30));
      const v = Math.min(1, Math.max(0, (db - floor) / -floor));
      this.state[b] = this.memory * this.state[b] + (1 - this.memory) * v;
      values[b] = this.state[b];
    }
    const onset = this.onsetStrength();
    const beat = this.beatValues;
    this.beatValues = [];
    return { index, centre, values, onset, beat };
  }

  /** e_j = mean_m max(0, S_j,m − S_{j−L},m) of the mel power in dB (floor −100 dB)
   * (docs/design.md#rhythm). */
  private onsetStrength(): number {
    const level = this.history.shift()!; // S_{j−L}, reused for S_j
    const previous = Float64Array.from(level);
    let sum = 0;
    for (let m = 0; m < this.mel.length; m++) {
      const { first, weights } = this.mel[m];
      let power = 0;
      for (let i = 0; i < weights.length; i++) power += weights[i] * this.magnitude[first + i] ** 2;
      level[m] = Math.max(10 * Math.log10(Math.max(power, 1e-30)), ANALYSIS.onset.floor_db);
      const flux = Math.max(0, level[m] - previous[m]);
      sum += flux;
    }
    this.history.push(level);
    return sum / this.mel.length;
  }
}
