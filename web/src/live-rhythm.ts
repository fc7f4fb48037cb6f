// Live rhythm (docs/design.md#live): onsets, a running tempo and beats as the frames come, with
// the offline definitions of docs/design.md#rhythm made causal, on librosa's onset strength
// (live-beat.ts: its mean over mels for the onsets, its median for the tempo, as offline) —
// librosa's peak picking (onset_detect's windows, the envelope normalised by its largest value
// so far instead of the song's), librosa's tempo (the autocorrelation tempogram averaged over
// the frames so far, the same log-normal prior around 120 BPM) — and beats predicted on that
// tempo's grid at the phase where the 100-frames-per-second envelope's comb peaks.
import FFT from "fft.js";
import ANALYSIS from "../../src/eigendance/music/analysis.json";
import { RATE } from "./live-analysis";
import { FRAME_RATE as BEAT_RATE } from "./live-beat";

// librosa.onset.onset_detect's peak-picking windows at librosa's frame rate (frames).
const PRE_MAX = Math.floor(0.03 * BEAT_RATE);
const POST_MAX = Math.floor(0.0 * BEAT_RATE) + 1;
const PRE_AVG = Math.floor(0.1 * BEAT_RATE);
const POST_AVG = Math.floor(0.1 * BEAT_RATE) + 1;
const WAIT = Math.floor(0.03 * BEAT_RATE);
const DELTA = 0.07;
/** librosa's onset strength at frame k tells of the rise into frame k − DELAY (its lag and
 * centring compensation): live frame k's values are placed at k + DELAY. */
const DELAY = 2;
/** librosa.feature.tempo's tempogram window (frames of BEAT_RATE: ⌊ac_size·rate⌋, even here). */
const WIN = 2 * Math.floor(Math.floor(ANALYSIS.onset.tempo_window * BEAT_RATE) / 2);
const START_BPM = 120;
const MAX_BPM = 320;
/** The tempo is re-estimated every this many frames (of RATE); the tempogram takes a column
 * every STRIDE frames of the tempo's envelope. */
const TEMPO_EVERY = 25;
const STRIDE = 4;
/** The beat grid's phase is fitted on the envelope's last COMB_SECONDS. */
const COMB_SECONDS = 6;
/** Frames kept (the envelope's tail for the tempogram and the comb). */
const KEEP = 1024;

export class LiveRhythm {
  /** onset and beat times, s (the stream's clock: frame j at j/RATE) */
  readonly onsets: number[] = [];
  readonly beats: number[] = [];
  /** beats per minute, 0 until estimated */
  tempo = 0;
  /** the envelope's last KEEP frames (a ring), and the number of frames seen */
  private readonly envelope = new Float64Array(KEEP);
  private count = 0;
  /** the onsets' envelope (the mean over mels of live-beat.ts) at BEAT_RATE: a ring */
  private readonly strength = new Float64Array(KEEP);
  private strengthCount = DELAY;
  private largest = 0;
  private lastOnset = -Infinity;
  private readonly gram = new Float64Array(WIN);
  private gramFrames = 0;
  /** the tempo's envelope (live-beat.ts, frame k at k/BEAT_RATE s): a ring */
  private readonly pooled = new Float64Array(2 * WIN);
  private pooledCount = 0;
  /** the autocorrelation's FFT (2·WIN rounded up to a power of two: no wrap-around) */
  private readonly fft = new FFT(2 ** Math.ceil(Math.log2(2 * WIN)));
  private readonly fftInput = new Float64Array(this.fft.size);
  private readonly fftSpectrum = this.fft.createComplexArray();
  private readonly fftPower = this.fft.createComplexArray();
  private readonly fftOut = this.fft.createComplexArray();
  private readonly window = Float64Array.from({ length: WIN },
    (_, n) => 0.5 - 0.5 * Math.cos((2 * Math.PI * n) / WIN));

  /** e_j of frame j (in order) and the [median, mean] values of librosa's onset strength
   * (live-beat.ts) that came with it. Returns whether an onset or a beat was added. */
  push(onset: number, beat: [number, number][] = []): boolean {
    const j = this.count++;
    this.envelope[j % KEEP] = onset;
    let changed = false;
    for (const [median, mean] of beat) {
      this.addBeatValue(median);
      const k = this.strengthCount++;
      this.strength[k % KEEP] = mean;
      this.largest = Math.max(this.largest, mean);
      changed = this.pickPeak(k - POST_AVG + 1) || changed;
    }
    if (j % TEMPO_EVERY === 0 && this.pooledCount) this.tempo = this.estimateTempo();
    if (this.tempo > 0) changed = this.predictBeat(j) || changed;
    return changed;
  }

  /** The tempo envelope's next frame k; now and then a tempogram column centred WIN/2 before. */
  private addBeatValue(value: number): void {
    const k = this.pooledCount++;
    this.pooled[k % this.pooled.length] = value;
    if (k >= WIN / 2 && k % STRIDE === 0) this.addToTempogram(k - WIN / 2);
  }

  private pooledAt(k: number): number {
    return k < 0 || k >= this.pooledCount || k <= this.pooledCount - this.pooled.length ? 0
      : this.pooled[k % this.pooled.length];
  }

  private at(j: number): number {
    return j < 0 || j >= this.count || j <= this.count - KEEP ? 0 : this.envelope[j % KEEP];
  }

  private strengthAt(k: number): number {
    return k < 0 || k >= this.strengthCount || k <= this.strengthCount - KEEP ? 0
      : this.strength[k % KEEP];
  }

  /** librosa.util.peak_pick at frame n of BEAT_RATE (its windows complete now), on the onsets'
   * envelope / its largest value so far. */
  private pickPeak(n: number): boolean {
    if (n < 0 || !(this.largest > 0)) return false;
    const x = (k: number) => this.strengthAt(k) / this.largest;
    const value = x(n);
    for (let j = Math.max(0, n - PRE_MAX); j < n + POST_MAX; j++) if (x(j) > value) return false;
    let sum = 0, count = 0;
    for (let j = Math.max(0, n - PRE_AVG); j < Math.min(this.strengthCount, n + POST_AVG); j++) {
      sum += x(j); count++;
    }
    if (value < sum / count + DELTA || n - this.lastOnset <= WAIT) return false;
    this.lastOnset = n;
    this.onsets.push(n / BEAT_RATE);
    return true;
  }

  /** One column of librosa's autocorrelation tempogram of the tempo's envelope (Hann window of
   * WIN frames centred on frame c, zeros where the envelope has no frame yet, normalised by its
   * lag-0 value), added to `sum`; returns whether it was. */
  private addColumn(c: number, sum: Float64Array): boolean {
    const x = this.fftInput;
    x.fill(0);
    for (let n = 0; n < WIN; n++) x[n] = this.pooledAt(c - WIN / 2 + n) * this.window[n];
    const spectrum = this.fftSpectrum, power = this.fftPower, out = this.fftOut;
    this.fft.realTransform(spectrum, x);
    this.fft.completeSpectrum(spectrum);
    for (let q = 0; q < spectrum.length; q += 2) {
      power[q] = spectrum[q] ** 2 + spectrum[q + 1] ** 2;
      power[q + 1] = 0;
    }
    this.fft.inverseTransform(out, power); // the autocorrelation, lags 0 … WIN − 1 first
    const peak = out[0];
    if (!(peak > 0)) return false;
    for (let lag = 0; lag < WIN; lag++) sum[lag] += out[2 * lag] / peak;
    return true;
  }

  private addToTempogram(c: number): void {
    if (this.addColumn(c, this.gram)) this.gramFrames++;
  }

  /** librosa.feature.tempo of the mean tempogram: argmax over lags of log1p(10⁶·tg) + the
   * log-normal prior (one octave around 120 BPM), tempi ≥ 320 BPM excluded. The mean takes the
   * columns whose window is complete and, as librosa's over a whole song does at its end, the
   * last WIN/2 frames' columns with zeros for the frames still to come. */
  private estimateTempo(): number {
    const gram = Float64Array.from(this.gram);
    let columns = this.gramFrames;
    const first = Math.max(0, this.pooledCount - WIN / 2);
    for (let c = first + ((STRIDE - (first % STRIDE)) % STRIDE); c < this.pooledCount; c += STRIDE) {
      if (this.addColumn(c, gram)) columns++;
    }
    if (!columns) return 0;
    let best = -Infinity, bestBpm = 0;
    for (let lag = 1; lag < WIN; lag++) {
      const bpm = (60 * BEAT_RATE) / lag;
      if (bpm >= MAX_BPM) continue;
      const prior = -0.5 * (Math.log2(bpm) - Math.log2(START_BPM)) ** 2;
      const score = Math.log1p(1e6 * (gram[lag] / columns)) + prior;
      if (score > best) { best = score; bestBpm = bpm; }
    }
    return bestBpm;
  }

  /** The next beat of the grid (period 60/tempo) whose phase makes the envelope's comb over the
   * last COMB_SECONDS largest, added when it is at most one frame ahead of frame j and at least
   * 0.6 periods after the last beat: beats come as the music does. */
  private predictBeat(j: number): boolean {
    const period = (60 * RATE) / this.tempo; // frames
    const last = this.beats.length ? this.beats[this.beats.length - 1] * RATE : -Infinity;
    if (j - last < 0.6 * period) return false;
    const span = Math.min(COMB_SECONDS * RATE, j);
    let bestPhase = 0, best = -1;
    for (let phase = 0; phase < period; phase += 1) {
      let score = 0;
      for (let g = j - phase; g > j - span; g -= period) {
        const r = Math.round(g);
        score += Math.max(this.at(r), this.at(r - 1), this.at(r + 1));
      }
      if (score > best) { best = score; bestPhase = phase; }
    }
    if (!(best > 0)) return false;
    const next = j - bestPhase + period; // the grid's next point after frame j
    const due = bestPhase <= 1 ? j - bestPhase : next;
    if (due > j + 1 || due - last < 0.6 * period) return false;
    this.beats.push(Math.max(due, j - 1) / RATE);
    return true;
  }
}
