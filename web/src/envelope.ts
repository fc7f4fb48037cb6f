// A mapping's per-band envelope in the page (docs/design.md#mapping): auto-range, threshold and
// an attack/release follower, as eigendance.music.envelope computes them.
import type { Mapping } from "./filter";

/** An envelope with one value per band (eigendance.music.envelope.Envelope.for_bands). */
export interface Envelope {
  attack: Float64Array;
  release: Float64Array;
  threshold: Float64Array;
  autoRange: boolean;
  /** all defaults: the values pass unchanged */
  identity: boolean;
  /** names the envelope (and the smoothing) for caches of shaped spectrograms */
  key: string;
}

export function envelopeOf(mapping: Mapping, bands: number): Envelope {
  const e = mapping.envelope ?? {};
  const perBand = (value: number | number[] | undefined) => {
    const list = value === undefined ? [0] : Array.isArray(value) ? value : [value];
    return Float64Array.from({ length: bands }, (_, b) => list.length === 1 ? list[0] : list[b]);
  };
  const attack = perBand(e.attack), release = perBand(e.release), threshold = perBand(e.threshold);
  const autoRange = e.auto_range ?? false;
  const identity = !autoRange && [attack, release, threshold].every((a) => a.every((x) => x === 0));
  const smoothing = mapping.smoothing ?? 0;
  const key = identity ? `${smoothing}` : `${smoothing}|${autoRange}|${attack}|${release}|${threshold}`;
  return { attack, release, threshold, autoRange, identity, key };
}

/** p-th percentile (linear interpolation, numpy's default) of sorted values. */
function percentile(sorted: Float64Array, p: number): number {
  const position = (p / 100) * (sorted.length - 1);
  const low = Math.floor(position), high = Math.min(low + 1, sorted.length - 1);
  return sorted[low] + (position - low) * (sorted[high] - sorted[low]);
}

/** The envelope applied to frames × bands values at `rate` frames/s (auto-range, threshold,
 * attack/release follower: eigendance.music.envelope.shape_values), as float32. */
export function shapeValues(values: Float32Array, frames: number, bands: number, rate: number,
                            envelope: Envelope): Float32Array {
  if (envelope.identity) return values;
  const v = Float64Array.from(values);
  if (envelope.autoRange) {
    const column = new Float64Array(frames);
    for (let b = 0; b < bands; b++) {
      for (let j = 0; j < frames; j++) column[j] = v[j * bands + b];
      const sorted = column.slice().sort();
      const low = percentile(sorted, 5), high = percentile(sorted, 95), span = high - low;
      for (let j = 0; j < frames; j++) {
        v[j * bands + b] = span <= 1e-6 ? 0
          : Math.min(1, Math.max(0, (column[j] - low) / span));
      }
    }
  }
  const memory = (tau: number) => (tau > 0 ? Math.exp(-1 / (rate * tau)) : 0);
  const rise = Array.from(envelope.attack, memory), fall = Array.from(envelope.release, memory);
  const out = new Float32Array(values.length);
  const state = new Float64Array(bands);
  for (let j = 0; j < frames; j++) {
    for (let b = 0; b < bands; b++) {
      let x = v[j * bands + b];
      if (x < envelope.threshold[b]) x = 0;
      const m = x > state[b] ? rise[b] : fall[b];
      state[b] = x + m * (state[b] - x);
      out[j * bands + b] = state[b];
    }
  }
  return out;
}
