// A mapping's smoothing and envelope applied to a live take frame by frame (docs/design.md#live):
// the same recurrences as `smoothed` and `shapeValues` (filter.ts; eigendance.music.envelope),
// which are causal, carried on from the last frame shaped instead of recomputed over the take.
// Auto-range needs the whole song's percentiles: live, a band is ranged by the percentiles of
// its last RANGE_SECONDS, refreshed every second.
import type { Envelope } from "./filter";

const RANGE_SECONDS = 30;

export class StreamShaper {
  /** frames shaped so far */
  done = 0;
  out: Float32Array;
  private readonly smooth: Float64Array;
  private readonly follow: Float64Array;
  private readonly rise: number[];
  private readonly fall: number[];
  private readonly memory: number;
  private low: Float64Array;
  private span: Float64Array;
  private rangedAt = -Infinity;
  /** the smoothed values of the last RANGE_SECONDS (a ring of frames), for auto-range */
  private readonly recent: Float32Array;
  private readonly ring: number;

  constructor(private readonly bands: number, private readonly rate: number, tau: number,
              private readonly envelope: Envelope) {
    this.out = new Float32Array(0);
    this.smooth = new Float64Array(bands);
    this.follow = new Float64Array(bands);
    const memory = (t: number) => (t > 0 ? Math.exp(-1 / (rate * t)) : 0);
    this.memory = memory(tau);
    this.rise = Array.from(envelope.attack, memory);
    this.fall = Array.from(envelope.release, memory);
    this.low = new Float64Array(bands);
    this.span = new Float64Array(bands).fill(1);
    this.ring = envelope.autoRange ? Math.round(RANGE_SECONDS * rate) : 0;
    this.recent = new Float32Array(this.ring * bands);
  }

  /** Shape frames done … frames − 1 of `values` (frames × bands, the take's raw loudness) into
   * `out` (grown with `values`); returns `out`. */
  extend(values: Float32Array, frames: number): Float32Array {
    const B = this.bands;
    if (this.out.length < values.length) {
      const grown = new Float32Array(values.length);
      grown.set(this.out);
      this.out = grown;
    }
    const m = this.memory, e = this.envelope;
    for (let j = this.done; j < frames; j++) {
      if (e.autoRange && j - this.rangedAt >= this.rate) this.range(j);
      for (let b = 0; b < B; b++) {
        this.smooth[b] = m * this.smooth[b] + (1 - m) * values[j * B + b];
        let x = this.smooth[b];
        if (e.autoRange) {
          this.recent[(j % this.ring) * B + b] = x;
          x = this.span[b] <= 1e-6 ? 0 : Math.min(1, Math.max(0, (x - this.low[b]) / this.span[b]));
        }
        if (x < e.threshold[b]) x = 0;
        const k = x > this.follow[b] ? this.rise[b] : this.fall[b];
        this.follow[b] = x + k * (this.follow[b] - x);
        this.out[j * B + b] = e.identity ? this.smooth[b] : this.follow[b];
      }
    }
    this.done = Math.max(this.done, frames);
    return this.out;
  }

  /** The 5th and 95th percentiles of each band's smoothed loudness over the last
   * RANGE_SECONDS before frame j (numpy's linear interpolation). */
  private range(j: number): void {
    this.rangedAt = j;
    const from = Math.max(0, j - this.ring);
    if (j - from < 2) return;
    const column = new Float64Array(j - from);
    for (let b = 0; b < this.bands; b++) {
      for (let i = from; i < j; i++) column[i - from] = this.recent[(i % this.ring) * this.bands + b];
      column.sort();
      const at = (p: number) => {
        const position = (p / 100) * (column.length - 1);
        const lo = Math.floor(position), hi = Math.min(lo + 1, column.length - 1);
        return column[lo] + (position - lo) * (column[hi] - column[lo]);
      };
      this.low[b] = at(5);
      this.span[b] = at(95) - this.low[b];
    }
  }
}
