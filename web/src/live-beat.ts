// The live tempo's envelope (docs/design.md#live): librosa's onset strength as
// `librosa.beat.beat_track(y=y, sr=22050)` computes it (eigendance.music.onset.BeatFeatures),
// without resampling: frames k at k/FRAME_RATE s (FRAME_RATE = 22050/512) centred on stream
// sample ⌊k·sr/FRAME_RATE + ½⌋, a periodic Hann window as long as librosa's 2048 samples at
// 22050 Hz (zero padded to a power of two), the power spectrum through librosa's 128 Slaney mel
// bands up to 11025 Hz (the power scaled to librosa's), dB with librosa's floor 80 dB below the
// loudest value so far, or 30 dB at first (offline: the song's loudest), and the median (the
// tempo's) and mean (the onsets') over mels of the rise from the frame before. Also librosa's mel
// filter bank, which the onset strength of live-analysis.ts uses too.
import FFT from "fft.js";
import ANALYSIS from "../../src/eigendance/music/analysis.json";

/** librosa's Slaney mel scale (linear below 1 kHz, logarithmic above). */
function hzToMel(f: number): number {
  const fSp = 200 / 3, minLogHz = 1000, minLogMel = minLogHz / fSp, step = Math.log(6.4) / 27;
  return f >= minLogHz ? minLogMel + Math.log(f / minLogHz) / step : f / fSp;
}

function melToHz(m: number): number {
  const fSp = 200 / 3, minLogHz = 1000, minLogMel = minLogHz / fSp, step = Math.log(6.4) / 27;
  return m >= minLogMel ? minLogHz * Math.exp(step * (m - minLogMel)) : fSp * m;
}

/** One triangular band of the mel filter bank: its first bin and weights. */
export interface MelBand { first: number; weights: Float64Array; centre: number; }

/** librosa.filters.mel(sr, n_fft = N, n_mels, fmin = 0, fmax, norm = "slaney") as sparse rows,
 * with each band's centre (Hz). */
export function melBank(sampleRate: number, N: number,
                        bands = ANALYSIS.onset.mel_bands): MelBand[] {
  const fmax = Math.min(ANALYSIS.onset.mel_fmax, sampleRate / 2);
  const top = hzToMel(fmax);
  const mel = Float64Array.from({ length: bands + 2 }, (_, i) => melToHz((i * top) / (bands + 1)));
  const bins = N / 2 + 1;
  const out: MelBand[] = [];
  for (let m = 0; m < bands; m++) {
    const lowWidth = mel[m + 1] - mel[m], highWidth = mel[m + 2] - mel[m + 1];
    const norm = 2 / (mel[m + 2] - mel[m]);
    const weights: number[] = [];
    let first = -1;
    for (let q = 0; q < bins; q++) {
      const f = (q * sampleRate) / N;
      const w = Math.max(0, Math.min((f - mel[m]) / lowWidth, (mel[m + 2] - f) / highWidth));
      if (w > 0) {
        if (first < 0) first = q;
        weights.length = q - first;
        weights.push(w * norm);
      }
    }
    out.push({ first: Math.max(first, 0), weights: Float64Array.from(weights, (w) => w || 0),
      centre: mel[m + 1] });
  }
  return out;
}

/** A stream's samples kept for its analysis windows: `held` samples from absolute index
 * `start`. */
export interface Held { buffer: Float32Array; held: number; start: number; }

/** Drop the samples before absolute index `keepFrom` (every later window has passed them), and
 * make room for `more`. */
export function compact(kept: Held, keepFrom: number, more: number): void {
  const drop = Math.max(0, Math.min(keepFrom - kept.start, kept.held));
  kept.buffer.copyWithin(0, drop, kept.held);
  kept.held -= drop;
  kept.start += drop;
  if (kept.held + more > kept.buffer.length) {
    const grown = new Float32Array(2 * (kept.held + more));
    grown.set(kept.buffer.subarray(0, kept.held));
    kept.buffer = grown;
  }
}

export const FRAME_RATE = ANALYSIS.onset.beat_sample_rate / ANALYSIS.onset.beat_hop;
const SECONDS = 2048 / ANALYSIS.onset.beat_sample_rate; // librosa's n_fft at its rate
const TOP_DB = 80;
const AMIN = 1e-10;
/** dB: where the floor's reference starts (a stream does not know its loudest value yet): a
 * full-scale 1 kHz sine reads 40.2 dB on librosa's scale, music peaks about 10 dB below. */
const FIRST_LOUDEST = 30;

export class BeatEnvelope {
  private readonly length: number;
  private readonly half: number;
  private readonly fft: FFT;
  private readonly window: Float64Array;
  private readonly input: Float64Array;
  private readonly spectrum: number[];
  private readonly power: Float64Array;
  private readonly mel: MelBand[];
  private previous: Float64Array | null = null;
  private readonly level: Float64Array;
  private readonly rise: Float64Array;
  private loudest = FIRST_LOUDEST;
  /** the power's scale to librosa's (its 2048-sample window at 22050 Hz, its bin width) */
  private readonly scale: number;
  /** samples from absolute index `start` (zeros before the stream), `held` of them */
  buffer: Float32Array;
  held: number;
  start: number;
  private next = 0;

  constructor(readonly sampleRate: number) {
    const length = (this.length = Math.round(SECONDS * sampleRate));
    this.half = Math.floor(length / 2);
    const size = 2 ** Math.ceil(Math.log2(length));
    this.fft = new FFT(size);
    this.window = Float64Array.from({ length }, (_, n) => 0.5 - 0.5 * Math.cos((2 * Math.PI * n) / length));
    this.input = new Float64Array(size);
    this.spectrum = this.fft.createComplexArray();
    this.power = new Float64Array(size / 2 + 1);
    const librosaBin = ANALYSIS.onset.beat_sample_rate / 2048;
    this.scale = (2048 / length) ** 2 * (sampleRate / size / librosaBin);
    this.mel = melBank(sampleRate, size);
    this.level = new Float64Array(this.mel.length);
    this.rise = new Float64Array(this.mel.length);
    this.buffer = new Float32Array(4 * size);
    this.held = this.half;
    this.start = -this.half;
  }

  private centre(k: number): number { return Math.floor((k * this.sampleRate) / FRAME_RATE + 0.5); }

  /** Add mono samples; returns the [median, mean] over mels of the frames they completed. */
  push(samples: Float32Array): [number, number][] {
    if (this.held + samples.length > this.buffer.length) this.compact(samples.length);
    this.buffer.set(samples, this.held);
    this.held += samples.length;
    const out: [number, number][] = [];
    for (;;) {
      const c = this.centre(this.next);
      if (c - this.half + this.length > this.start + this.held) break;
      out.push(this.analyse(c - this.half - this.start));
      this.next++;
    }
    return out;
  }

  private compact(more: number): void {
    compact(this, this.centre(this.next) - this.half, more);
  }

  private analyse(from: number): [number, number] {
    const { input, window, spectrum, power, level } = this;
    input.fill(0);
    for (let n = 0; n < this.length; n++) input[n] = this.buffer[from + n] * window[n];
    this.fft.realTransform(spectrum, input);
    for (let q = 0; q < power.length; q++) power[q] = (spectrum[2 * q] ** 2 + spectrum[2 * q + 1] ** 2) * this.scale;
    for (let m = 0; m < this.mel.length; m++) {
      const { first, weights } = this.mel[m];
      let p = 0;
      for (let i = 0; i < weights.length; i++) p += weights[i] * power[first + i];
      level[m] = 10 * Math.log10(Math.max(p, AMIN));
      this.loudest = Math.max(this.loudest, level[m]);
    }
    const floor = this.loudest - TOP_DB;
    for (let m = 0; m < level.length; m++) level[m] = Math.max(level[m], floor);
    let median = 0, mean = 0;
    if (this.previous) {
      for (let m = 0; m < level.length; m++) {
        this.rise[m] = Math.max(0, level[m] - Math.max(this.previous[m], floor));
        mean += this.rise[m] / level.length;
      }
      const sorted = this.rise.slice().sort();
      const M = sorted.length;
      median = M % 2 ? sorted[(M - 1) / 2] : (sorted[M / 2 - 1] + sorted[M / 2]) / 2;
      this.previous.set(level);
    } else this.previous = Float64Array.from(level);
    return [median, mean];
  }
}
