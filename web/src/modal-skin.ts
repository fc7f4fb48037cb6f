// Rig motion in the page (docs/web.md#rig-motion-in-the-page): the palette of a mode mapping,
// the mode coefficients c(t) of `eigendance.modal.motion.rig_coefficients`, the shader weights
// that turn the harmonics' positions pass into GPU modal skinning (thesis §6.5), and the body
// poses that move bones and three.js linear blend skinning. Same numbers as the Python.
import { beatLock, hasBeats } from "./beat-lock";
import { filterValues, prepare } from "./filter";
import type { Mapping, Prepared } from "./filter";
import type { Motion } from "./motion";
import type { ModeSettings, Rig } from "./rig-bundle";
import { lockedPhase, lockRatio, paletteOf } from "./palette";
import { normalising } from "./rig-bundle";
import { surfaceWeights } from "./rig-surface";
import type { SurfacePlay } from "./rig-surface";

/** A mode mapping prepared for one rig: the filter over its k′ selected modes (`Prepared`,
 * k = k′) and the resolved palette, targets ν = 0 … k′−1 being the selected modes ascending. */
export interface RigPrepared extends Prepared {
  /** κ_ν, ascending */
  selected: Int32Array;
  /** palette amplitudes A_ν (reach at φ = 1, radians) */
  amplitudes: Float64Array;
  /** γ_ν, radians */
  phases: Float64Array;
  /** time scale s */
  timeScale: number;
  /** the filter's offset b (0: silence is the rest pose) */
  offset: number;
  /** false: φ ≡ 1 (music off; the mode gallery's tiles) */
  music: boolean;
  /** the palette's tempo mode ("free": never locks; "beat" or null: locks to a song with
   * beats) */
  tempo: "beat" | "free" | null;
  /** false: never locks (the mode gallery's tiles, as `rig_coefficients` without a song) */
  lock: boolean;
}

/** A mode mapping made ready for `rig` (its palette completed by the default rule: palette.ts). */
export function prepareRig(rig: Rig, mapping: Mapping, music = true): RigPrepared {
  const palette = paletteOf(rig, mapping.modes as Partial<ModeSettings> | null);
  const selected = Int32Array.from(palette.selected!);
  return { ...prepare(mapping, selected.length), selected,
    amplitudes: Float64Array.from(palette.amplitudes!), phases: Float64Array.from(palette.phases!),
    timeScale: palette.time_scale!, offset: mapping.offset ?? 0, music,
    tempo: palette.tempo ?? null, lock: true };
}

/** Mode κ alone, as its tile of the mode gallery plays it: φ ≡ 1, the bundle's tile amplitude
 * (made to be seen: docs/design.md#the-floor) and phase, time scale s. */
export function modeTile(rig: Rig, mode: number, timeScale: number): RigPrepared {
  const silent = prepare({ format: "eigendance.mapping", version: 3, bands: 0, transfer: [],
    amplification: [0], seed: null }, 1);
  return { ...silent, gain: 0, selected: Int32Array.of(mode),
    amplitudes: Float64Array.of(rig.tileAmplitudes[mode]),
    phases: Float64Array.of(rig.phases[mode]),
    timeScale, offset: 0, music: false, tempo: "free", lock: false };
}

/** φ_ν = gain·a(ν)·Σ g̃ + b over the selected modes (band values after the mapping's
 * smoothing); null band values (no song) or music off: φ ≡ 1. */
export function modeDrive(prepared: RigPrepared, bandValues: ArrayLike<number> | null,
                          kick = 0, gain = prepared.gain): Float64Array {
  if (!prepared.music || bandValues === null) return new Float64Array(prepared.k).fill(1);
  const phi = filterValues(prepared, bandValues, gain, undefined, kick); // + 1
  for (let v = 0; v < phi.length; v++) phi[v] += prepared.offset - 1;
  return phi;
}

/** c (k) at time t: c_{κ_ν} = φ_ν·(A_ν / reach_{κ_ν})·sin(2π ν_{κ_ν} s t + γ_ν), 0 elsewhere
 * (`rig_coefficients`); locked to the beats (`beat`: B(t), the tempo, the bar's accent), the angle is
 * 2π r_ν B(t) + γ′_ν instead (docs/design.md#tempo-lock). */
export function rigCoefficients(rig: Rig, prepared: RigPrepared, phi: ArrayLike<number>, t: number,
                                out?: Float64Array,
                                beat?: { phase: number; tempo: number; accent?: number }):
    Float64Array {
  const c = out ?? new Float64Array(rig.k);
  c.fill(0);
  prepared.selected.forEach((mode, v) => {
    const mu = prepared.amplitudes[v] / rig.reach[mode];
    const angle = beat
      ? 2 * Math.PI * lockRatio(rig.frequencies[mode], prepared.timeScale, beat.tempo) * beat.phase
        + lockedPhase(prepared.phases[v])
      : 2 * Math.PI * rig.frequencies[mode] * prepared.timeScale * t + prepared.phases[v];
    c[mode] = phi[v] * mu * Math.sin(angle) * (beat?.accent ?? 1);
  });
  return c;
}

/**
 * The positions pass's weights (`Deformer`, `deformCPU`: 12 floats per texel) for
 * coefficients c: texel j = 3g + d of a vertex holds τ_d of modes 4g…4g+3, and its d-th row
 * gets c[4g:4g+4]·σ (σ the page's normalisation), so the pass computes
 * x′ = x + Σ_g Σ_d e_d·dot(c[4g:4g+4], τ[i, g, d]) (`ModalSkin.positions`).
 */
export function modalWeights(rig: Rig, c: ArrayLike<number>, out?: Float32Array): Float32Array {
  const weights = out ?? new Float32Array(36 * rig.G);
  weights.fill(0);
  const s = normalising(rig);
  for (let g = 0; g < rig.G; g++) {
    for (let d = 0; d < 3; d++) {
      const row = 4 * (3 * (3 * g + d) + d);
      for (let q = 0; q < 4 && 4 * g + q < rig.k; q++) weights[row + q] = c[4 * g + q] * s;
    }
  }
  return weights;
}

/** Rodrigues: the row-major 3×3 exp([θ]×). */
export function rotationExp(x: number, y: number, z: number, out = new Float64Array(9)):
    Float64Array {
  const angle = Math.hypot(x, y, z);
  const a = angle < 1e-12 ? 1 : Math.sin(angle) / angle;
  const b = angle < 1e-6 ? 0.5 : (1 - Math.cos(angle)) / (angle * angle);
  out[0] = 1 - b * (y * y + z * z); out[1] = -a * z + b * x * y; out[2] = a * y + b * x * z;
  out[3] = a * z + b * x * y; out[4] = 1 - b * (x * x + z * z); out[5] = -a * x + b * y * z;
  out[6] = -a * y + b * x * z; out[7] = a * x + b * y * z; out[8] = 1 - b * (x * x + y * y);
  return out;
}

/** Every body's world matrix [R_b·exp([θ]×) | c_b + R_b·x] (column-major 4×4, file units) for
 * coefficients c, with p̂_b = Σ_κ c_κ body_twists[κ, b] = [θ; x] (`body_poses`). */
export function bodyMatrices(rig: Rig, c: ArrayLike<number>, out?: Float32Array): Float32Array {
  const matrices = out ?? new Float32Array(16 * rig.b);
  const twist = new Float64Array(6), turn = new Float64Array(9);
  for (let b = 0; b < rig.b; b++) {
    twist.fill(0);
    for (let k = 0; k < rig.k; k++) {
      if (c[k] === 0) continue;
      const base = 6 * (k * rig.b + b);
      for (let e = 0; e < 6; e++) twist[e] += c[k] * rig.bodyTwists[base + e];
    }
    rotationExp(twist[0], twist[1], twist[2], turn);
    const R = rig.bodyRotations.subarray(9 * b, 9 * b + 9);
    const m = matrices.subarray(16 * b, 16 * b + 16);
    for (let r = 0; r < 3; r++) {
      for (let col = 0; col < 3; col++) {
        m[4 * col + r] = R[3 * r] * turn[col] + R[3 * r + 1] * turn[3 + col]
          + R[3 * r + 2] * turn[6 + col];
      }
      m[12 + r] = rig.bodyCenters[3 * b + r] + R[3 * r] * twist[3] + R[3 * r + 1] * twist[4]
        + R[3 * r + 2] * twist[5];
      m[3 + 4 * r] = 0;
    }
    m[15] = 1;
  }
  return matrices;
}

/** The motion of a rig's tiles and player for the Viewer: coefficients from the song (the
 * harmonics' `Motion` holds its spectrum) and the shader weights of modal skinning. */
export class RigMotion {
  rig: Rig | null = null;
  /** the skin's ripple (docs/design.md#surface-of-a-rig), drawn with the basis of
   * `surfaceBasis`; null: off */
  surface: SurfacePlay | null = null;
  /** what ripples the skin of the player or a tile drawn with `prepared` (null: none) */
  surfaceOf: (prepared: Prepared) => SurfacePlay | null = () => null;
  private coefficientsBuffer = new Float64Array(0);

  constructor(readonly music: Motion) {}

  get ready(): boolean { return this.rig !== null; }

  /** c (k) of `prepared` at time t (the array is reused by the next call). */
  coefficients(prepared: RigPrepared, t: number): Float64Array {
    const rig = this.rig!;
    if (this.coefficientsBuffer.length !== rig.k) this.coefficientsBuffer = new Float64Array(rig.k);
    return rigCoefficients(rig, prepared, this.drive(prepared, t), t, this.coefficientsBuffer,
      this.beat(prepared, t));
  }

  /** B(t), the tempo and the bar's accent when `prepared` locks to the song's beats, else
   * undefined. */
  beat(prepared: RigPrepared, t: number): { phase: number; tempo: number; accent: number } |
      undefined {
    const spectrum = this.music.spectrum;
    if (!prepared.lock || prepared.tempo === "free" || !spectrum || !hasBeats(spectrum)) {
      return undefined;
    }
    return beatLock(spectrum, t);
  }

  /** φ over the selected modes at time t. */
  drive(prepared: RigPrepared, t: number): Float64Array {
    const music = prepared.music && this.music.spectrum;
    const bands = music ? this.music.bandValuesAt(t, prepared) : null;
    return modeDrive(prepared, bands, music ? this.music.kick(prepared, t) : 0,
      prepared.gain * (music ? this.music.sectionGain(prepared, t) : 1));
  }

  weights(prepared: Prepared, t: number): Float32Array {
    const c = this.coefficients(prepared as RigPrepared, t);
    if (!this.surface) return modalWeights(this.rig!, c);
    // The skin's ripple (rig-surface.ts): its texels follow the modal skin's; the player's,
    // and each dance tile's by its surface genes.
    const weights = modalWeights(this.rig!, c, new Float32Array(12 * this.texels()));
    const play = this.surfaceOf(prepared);
    return play ? surfaceWeights(this.rig!, play.surface, play.phi(this.music, t), weights)
      : weights;
  }

  /** Texels per vertex of the basis drawn: the modal skin's 3G, and the surface's. */
  texels(): number { return 3 * this.rig!.G + (this.surface?.surface.G ?? 0); }

  loudestTimes(count: number): number[] {
    return this.music.spectrum ? this.music.loudestTimes(count) : [];
  }

  /** Poses that frame a tile or the player: each selected mode alone and all together at the
   * largest |φ| the song gives (at its loudest moments; 1 without music), both signs. */
  framingWeights(prepared: Prepared): Float32Array[] {
    const p = prepared as RigPrepared, rig = this.rig!;
    const largest = new Float64Array(p.k).fill(p.music ? Math.abs(p.offset) : 1);
    if (p.music) {
      for (const t of this.loudestTimes(6)) {
        this.drive(p, t).forEach((phi, v) => { largest[v] = Math.max(largest[v], Math.abs(phi)); });
      }
    }
    const poses: Float32Array[] = [];
    const c = new Float64Array(rig.k);
    const pose = (modes: number[], sign: number) => {
      c.fill(0);
      for (const v of modes) c[p.selected[v]] = sign * largest[v] * p.amplitudes[v] / rig.reach[p.selected[v]];
      poses.push(modalWeights(rig, c, new Float32Array(12 * this.texels())));
    };
    const all = [...p.selected.keys()];
    for (const sign of [1, -1]) {
      all.forEach((v) => pose([v], sign));
      if (all.length > 1) pose(all, sign);
    }
    return poses;
  }
}
