// The filter of docs/design.md#mapping, evaluated per frame in the browser; the same numbers as the Python
// reference (eigendance.music.mapping / eigendance.harmonic.motion).
import { beatLock, hasBeats } from "./beat-lock";
import type { Basis, Spectrum } from "./bundle";
import { deformReducedCPU } from "./reduced";
import { envelopeOf, shapeValues } from "./envelope";
import type { Envelope } from "./envelope";

export type Shading = "smooth" | "flat" | "wireframe";

/** Per-band envelope of a version-3 mapping (docs/design.md#mapping): one number for every
 * band or one per band. */
export interface EnvelopeJSON {
  attack?: number | number[];
  release?: number | number[];
  threshold?: number | number[];
  auto_range?: boolean;
}

/** The pulse of a version-3 mapping: kicks on the beats (or onsets) on a range of targets. */
export interface PulseJSON {
  source?: "beats" | "onsets";
  amount?: number;
  decay?: number;
  range?: [number, number];
}

/** A mapping file (docs/design.md#mapping-file), version 1, 2 or 3 as read; the page writes 3. */
export interface Mapping {
  format: "eigendance.mapping";
  version: number;
  bands: number;
  transfer: number[];
  amplification: number[];
  seed: number | null;
  gain?: number;
  smoothing?: number;
  offset?: number;
  modes?: unknown;
  look?: { deformed_normal_weight?: number; shading?: Shading; materials?: boolean };
  envelope?: EnvelopeJSON | null;
  pulse?: PulseJSON | null;
  /** the basis it was made on: `eigendance animate` solves the same (design.md#mapping-file) */
  basis?: BasisRecord | null;
  /** the section gene: a gain factor per part of the song, cycled (absent: none) */
  sections?: number[] | null;
}

/** What a mapping records of the basis it was made on
 * (`eigendance.harmonic.construction.BasisRecord`). */
export interface BasisRecord {
  k: number;
  construction: "exact" | "reduced";
  /** a reduced basis's samples asked of the sampler (they fix the ones placed), m placed */
  samples: number | null;
  placed?: number | null;
}

/** The mapping with the record of the basis it was made on, for the command line to solve. */
export function withBasis(mapping: Mapping,
    basis: { k: number; reduced?: { m: number; asked: number | null } } | null): Mapping {
  if (!basis) return mapping;
  const record: BasisRecord = basis.reduced ? { k: basis.k, construction: "reduced",
    samples: basis.reduced.asked, placed: basis.reduced.m }
    : { k: basis.k, construction: "exact", samples: null, placed: null };
  return { ...mapping, basis: record };
}

/** What the player applies besides transfer and amplification: all of it is in the mapping. */
export interface Settings {
  /** multiplies the amplification (≥ 0) */
  gain: number;
  /** extra exponential smoothing of the spectrogram, s */
  smoothing: number;
  /** weight of the deformed triangle's flat normal against the original vertex normal */
  deformedNormalWeight: number;
  shading: Shading;
  /** draw a model with materials in them (false: the clay studio look) */
  materials: boolean;
}

/** The defaults of a version-1 file (and of docs/design.md#mapping-file). */
export const DEFAULT_SETTINGS: Settings = { gain: 1, smoothing: 0, deformedNormalWeight: 0.4,
  shading: "smooth", materials: true };

/** A mapping's settings, the defaults where a (version 1) file has none. */
export function settingsOf(mapping: Mapping): Settings {
  const look = mapping.look ?? {};
  return {
    gain: mapping.gain ?? DEFAULT_SETTINGS.gain,
    smoothing: mapping.smoothing ?? DEFAULT_SETTINGS.smoothing,
    deformedNormalWeight: look.deformed_normal_weight ?? DEFAULT_SETTINGS.deformedNormalWeight,
    shading: look.shading ?? DEFAULT_SETTINGS.shading,
    materials: look.materials ?? DEFAULT_SETTINGS.materials,
  };
}

/** The mapping with these settings, as a version-3 file (other fields kept). */
export function withSettings(mapping: Mapping, settings: Settings): Mapping {
  return {
    ...mapping, version: 3, gain: settings.gain, smoothing: settings.smoothing,
    offset: mapping.offset ?? 0, modes: mapping.modes ?? null,
    look: { ...mapping.look, deformed_normal_weight: settings.deformedNormalWeight,
      shading: settings.shading, materials: settings.materials },
  };
}

/** Band values at time t: linear interpolation between the two nearest analysis frames. */
export function spectrumAt(spectrum: Spectrum, t: number, out?: Float32Array,
                           values: Float32Array = spectrum.values): Float32Array {
  const B = spectrum.bands;
  const result = out ?? new Float32Array(B);
  const position = Math.min(Math.max(t * spectrum.rate, 0), spectrum.frames - 1);
  const low = Math.floor(position);
  const high = Math.min(low + 1, spectrum.frames - 1);
  const f = position - low;
  for (let b = 0; b < B; b++) {
    result[b] = (1 - f) * values[low * B + b] + f * values[high * B + b];
  }
  return result;
}

/** Extra smoothing of the spectrogram frames with time constant tau (s); tau = 0: unchanged. */
export function smoothed(spectrum: Spectrum, tau: number): Float32Array {
  if (!(tau > 0)) return spectrum.values;
  const B = spectrum.bands;
  const m = Math.exp(-1 / (spectrum.rate * tau));
  const out = new Float32Array(spectrum.values.length);
  const state = new Float64Array(B);
  for (let j = 0; j < spectrum.frames; j++) {
    for (let b = 0; b < B; b++) {
      state[b] = m * state[b] + (1 - m) * spectrum.values[j * B + b];
      out[j * B + b] = state[b];
    }
  }
  return out;
}

// The envelope (auto-range, threshold, attack and release) lives in envelope.ts.
export { envelopeOf, shapeValues };
export type { Envelope };

/** A pulse ready for k targets: kicks on `source` events, decay (s), amount, and 1 for the
 * targets in its range. */
export interface Pulse {
  amount: number;
  decay: number;
  source: "beats" | "onsets";
  routed: Float64Array;
  /** the targets in the range (where routed is 1) */
  targets: Int32Array;
}

export function pulseOf(mapping: Mapping, k: number): Pulse {
  const p = mapping.pulse ?? {};
  const [low, high] = p.range ?? [0, 1];
  const routed = Float64Array.from({ length: k }, (_, v) => {
    const centre = (v + 0.5) / k;
    return centre >= low && centre <= high ? 1 : 0;
  });
  const targets = Int32Array.from([...routed.keys()].filter((v) => routed[v] === 1));
  return { amount: p.amount ?? 0, decay: p.decay ?? 0.15, source: p.source ?? "beats", routed,
    targets };
}

/** The events a pulse kicks on: the song's beats (none without a beat) or onsets. */
export function pulseEvents(spectrum: Spectrum, pulse: Pulse): Float32Array {
  if (!(pulse.amount > 0)) return new Float32Array(0);
  if (pulse.source === "onsets") return spectrum.onsets;
  return hasBeats(spectrum) ? spectrum.beats : new Float32Array(0);
}

/** w(e), how strong each event's kick is: the bar's accent at a beat (`beatLock`'s: 1 +
 * DOWNBEAT_ACCENT on a bar's first beat, else 1, as the rig's tempo lock accents it), 1 at an
 * onset (eigendance.music.envelope.Pulse.accents). `events` are `pulseEvents`'. */
export function pulseAccents(spectrum: Spectrum, pulse: Pulse,
                             events: Float32Array): Float32Array {
  const accents = new Float32Array(events.length).fill(1);
  if (pulse.source !== "onsets" && hasBeats(spectrum)) {
    for (let i = 0; i < events.length; i++) accents[i] = beatLock(spectrum, events[i]).accent;
  }
  return accents;
}

/** amount·p(t), p(t) = w(e)·exp(−(t − e)/decay) after the last event e ≤ t (w: `accents`,
 * `pulseAccents`; 1 without), else 0. */
export function kickAt(pulse: Pulse, events: ArrayLike<number>, t: number,
                       accents?: ArrayLike<number>): number {
  if (!(pulse.amount > 0) || events.length === 0 || t < events[0]) return 0;
  let low = 0, high = events.length - 1; // the last event ≤ t
  while (low < high) {
    const middle = (low + high + 1) >> 1;
    if (events[middle] <= t) low = middle; else high = middle - 1;
  }
  const weight = accents ? accents[low] : 1;
  return pulse.amount * weight * Math.exp(-Math.max(0, t - events[low]) / pulse.decay);
}

/** Amplification resampled to k entries by normalised index (docs/design.md#mapping). */
export function resampleAmplification(amplification: number[], k: number): Float64Array {
  const K = amplification.length;
  const out = new Float64Array(k);
  for (let v = 0; v < k; v++) {
    out[v] = K === k ? amplification[v]
      : amplification[Math.min(K - 1, Math.floor(((v + 0.5) * K) / k))];
  }
  return out;
}

/** A mapping prepared for one basis: band → harmonic index, amplification per harmonic, and
 * the settings that change its motion. */
export interface Prepared {
  k: number;
  harmonicOfBand: Int32Array;
  amplification: Float64Array;
  gain: number;
  smoothing: number;
  /** the envelope over the mapping's bands (version 3; identity by default) */
  envelope: Envelope;
  /** the pulse (amount 0: none) */
  pulse: Pulse;
  /** the section gene's gain factors (empty: none; `sectionGain`) */
  sections: Float64Array;
}

export function prepare(mapping: Mapping, k: number): Prepared {
  const harmonicOfBand = new Int32Array(mapping.transfer.length);
  mapping.transfer.forEach((t, b) => {
    harmonicOfBand[b] = Math.min(k - 1, Math.floor(t * k));
  });
  const { gain, smoothing } = settingsOf(mapping);
  return { k, harmonicOfBand, amplification: resampleAmplification(mapping.amplification, k),
    gain, smoothing, envelope: envelopeOf(mapping, mapping.transfer.length),
    pulse: pulseOf(mapping, k), sections: Float64Array.from(mapping.sections ?? []) };
}

/** g(t), the section gene's factor at time t: sections[s mod n] with s the song's section
 * starts ≤ t; 1 without the gene or the song's sections (eigendance.music.mapping.Mapping
 * .section_gain). */
export function sectionGain(prepared: Prepared, starts: ArrayLike<number>, t: number): number {
  const gene = prepared.sections;
  if (!gene || gene.length === 0 || starts.length === 0) return 1;
  let part = 0;
  while (part < starts.length && starts[part] <= t) part++;
  return gene[part % gene.length];
}

/** The harmonics a mapping moves: reached by a band and amplified (ascending). */
export function drivenHarmonics(prepared: Prepared): number[] {
  const driven = new Set<number>();
  prepared.harmonicOfBand.forEach((v) => { if (prepared.amplification[v] !== 0) driven.add(v); });
  return [...driven].sort((a, b) => a - b);
}

/** φ(ν) = gain · a(ν) · (Σ_{ξ: ν(ξ)=ν} e(ξ) + kick·[ν in the pulse's range]) + 1, the gain
 * the mapping's unless given; kick = amount·p(t) (`kickAt`). */
export function filterValues(prepared: Prepared, bandValues: ArrayLike<number>,
                             gain = prepared.gain, out?: Float64Array, kick = 0): Float64Array {
  const phi = out ?? new Float64Array(prepared.k);
  const sums = new Float64Array(prepared.k);
  const B = prepared.harmonicOfBand.length;
  for (let b = 0; b < B; b++) sums[prepared.harmonicOfBand[b]] += bandValues[b];
  if (kick !== 0) {
    const targets = prepared.pulse.targets;
    for (let i = 0; i < targets.length; i++) sums[targets[i]] += kick;
  }
  for (let v = 0; v < prepared.k; v++) phi[v] = gain * prepared.amplification[v] * sums[v] + 1;
  return phi;
}

/**
 * Per-tile weights for the deformation shader: for texel j (harmonics 4j…4j+3) three vec4s,
 * the x, y and z rows of (φ − 1) ⊙ X̃. Layout: out[(3j + c)·4 + q] = (φ_{4j+q} − 1) X̃_{4j+q,c}.
 */
export function shaderWeights(basis: Basis, phi: ArrayLike<number>, out?: Float32Array):
    Float32Array {
  const weights = out ?? new Float32Array(basis.k4 * 12);
  weights.fill(0);
  for (let v = 0; v < basis.k; v++) {
    const j = v >> 2, q = v & 3, d = phi[v] - 1;
    for (let c = 0; c < 3; c++) weights[(3 * j + c) * 4 + q] = d * basis.coefficients[3 * v + c];
  }
  return weights;
}

/** The harmonics a frame's weights move (any of their x, y, z weights non-zero) and those
 * weights, packed: a mapping drives at most one harmonic per band (64), a rig's frame one
 * coordinate row per texel, so most of the k weights are zero. */
export function activeWeights(k4: number, weights: Float32Array):
    { index: Int32Array; x: Float32Array; y: Float32Array; z: Float32Array } {
  let count = 0;
  const index = new Int32Array(4 * k4);
  for (let j = 0; j < k4; j++) {
    for (let q = 0; q < 4; q++) {
      const w = 12 * j + q;
      const moves = weights[w] !== 0 || weights[w + 4] !== 0 || weights[w + 8] !== 0;
      if (moves) index[count++] = 4 * j + q;
    }
  }
  const x = new Float32Array(count), y = new Float32Array(count), z = new Float32Array(count);
  for (let a = 0; a < count; a++) {
    const w = 12 * (index[a] >> 2) + (index[a] & 3);
    x[a] = weights[w]; y[a] = weights[w + 4]; z[a] = weights[w + 8];
  }
  return { index: index.subarray(0, count), x, y, z };
}

/** Bytes of harmonic columns kept per basis for the CPU path (`deformCPU`). */
const COLUMN_BYTES = 64 * 2 ** 20;
const columns = new WeakMap<Basis, Map<number, Float32Array>>();

/** U[:, ν] as a contiguous array (the basis packs harmonics per vertex), kept for the next
 * frames — at most COLUMN_BYTES per basis, the least recently used dropped first. */
function harmonicColumn(basis: Basis, v: number): Float32Array {
  let kept = columns.get(basis);
  if (!kept) { kept = new Map(); columns.set(basis, kept); }
  let column = kept.get(v);
  if (column) {
    kept.delete(v); // most recently used goes last
  } else {
    const { n, harmonics } = basis, W = 4 * basis.k4;
    column = new Float32Array(n);
    for (let i = 0; i < n; i++) column[i] = harmonics[i * W + v];
    while (kept.size && (kept.size + 1) * 4 * n > COLUMN_BYTES) {
      kept.delete(kept.keys().next().value!);
    }
  }
  kept.set(v, column);
  return column;
}

/** CPU path: positions X + U((φ − 1) ⊙ X̃) from the same weights the shader gets; of every
 * vertex, or of `vertices` only (packed in their order). Only the harmonics the weights move
 * are read (`activeWeights`): the cost is n × (harmonics moved), not n × k — column by column
 * over every vertex (contiguous, 3 to 7 times faster than vertex by vertex in V8), vertex by
 * vertex for a few vertices. */
export function deformCPU(basis: Basis, weights: Float32Array, out?: Float32Array,
                          vertices?: Int32Array): Float32Array {
  if (basis.reduced) return deformReducedCPU(basis, weights, out, vertices);
  const count = vertices ? vertices.length : basis.n;
  const positions = out ?? new Float32Array(count * 3);
  const U = basis.harmonics, W = 4 * basis.k4, X = basis.vertices;
  const { index, x: wx, y: wy, z: wz } = activeWeights(basis.k4, weights);
  const active = index.length;
  if (!vertices) {
    positions.set(X.subarray(0, 3 * count));
    for (let a = 0; a < active; a++) {
      const column = harmonicColumn(basis, index[a]);
      const x = wx[a], y = wy[a], z = wz[a];
      for (let i = 0, j = 0; i < count; i++, j += 3) {
        const u = column[i];
        positions[j] += u * x;
        positions[j + 1] += u * y;
        positions[j + 2] += u * z;
      }
    }
    return positions;
  }
  for (let o = 0; o < count; o++) {
    const i = vertices[o];
    let x = 0, y = 0, z = 0;
    const row = i * W;
    for (let a = 0; a < active; a++) {
      const u = U[row + index[a]];
      x += u * wx[a];
      y += u * wy[a];
      z += u * wz[a];
    }
    positions[3 * o] = X[3 * i] + x;
    positions[3 * o + 1] = X[3 * i + 1] + y;
    positions[3 * o + 2] = X[3 * i + 2] + z;
  }
  return positions;
}
