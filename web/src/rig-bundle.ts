// The rig bundle of docs/web.md#rig-bundle and the rig routes of the HTTP API: an articulated
// model's skin, its vibration modes packed for GPU modal skinning, its bodies and joints.
import * as api from "./api";
import type { Basis } from "./bundle";
import { parseBundle } from "./bundle";
import type { Mapping } from "./filter";

/** A palette as the mapping file's `modes` (docs/design.md#modal-motion); null fields take
 * the bundle's default palette. */
export interface ModeSettings {
  selected: number[] | null;
  amplitudes: number[] | null;
  phases: number[] | null;
  time_scale: number | null;
  /** "beat": locked to the song's beats; "free": the thesis's free-running motion; null (or
   * absent): "beat" when the song has beats (docs/design.md#tempo-lock) */
  tempo?: "beat" | "free" | null;
}

export interface JointInfo {
  name: string;
  type: string;
  bodies: [number, number];
  free_rows: number[];
  constrained_rows: number[];
  /** one per free row */
  stiffness: number[];
  /** the default rule's stiffness, one per free row */
  default_stiffness: number[];
  /** its two bodies stay connected without it: it cannot turn one side (the pose editor) */
  closes_loop: boolean;
}

export interface Rig {
  id: string;
  name: string;
  revision: number;
  /** its pose or stiffness differs from the rig as loaded (the server keeps edits) */
  edited: boolean;
  /** vertices, faces, bodies, joints, vibration modes, texel groups ⌈k/4⌉ */
  n: number; m: number; b: number; j: number; k: number; G: number;
  /** the skin's bounding box: centre and diagonal (file units) */
  center: [number, number, number];
  diagonal: number;
  jointList: JointInfo[];
  bodyNames: string[];
  /** the default palette, every field set; null without modes */
  palette: ModeSettings | null;
  offset: number;
  vertices: Float32Array; // n*3, file units
  faces: Uint32Array; // m*3
  /** (n, G, 3, 4): vertex i's 3G texels hold τ of modes 4g…4g+3, coordinate d */
  tau: Float32Array;
  frequencies: Float32Array; // k, Hz ascending
  amplitudes: Float32Array; // k, each mode alone (radians of reach)
  /** k, each mode's tile in the gallery of modes, made to be seen (docs/design.md#the-floor) */
  tileAmplitudes: Float32Array;
  reach: Float32Array; // k, reach per unit coefficient
  phases: Float32Array; // k, default γ
  skinJoints: Uint32Array; // n*4
  skinWeights: Float32Array; // n*4
  boneMatrices: Float32Array; // b*16 column-major
  bindMatrices: Float32Array; // b*16 column-major
  bodyCenters: Float32Array; // b*3
  bodyRotations: Float32Array; // b*9 row-major
  bodyEnds: Float32Array; // b*6
  bodyTwists: Float32Array; // k*b*6
  jointBodies: Uint32Array; // j*2
  jointPositions: Float32Array; // j*3
  /** (j, k) row-major: each joint's bend per unit coefficient of each mode (the palette's cap) */
  jointBend: Float32Array;
}

export function rigFromBundle(buffer: ArrayBuffer, id: string): Rig {
  const { meta, arrays } = parseBundle(buffer);
  if (meta.kind !== "rig") throw new Error("not a rig bundle");
  const f = (name: string) => arrays[name].data as Float32Array;
  const u = (name: string) => arrays[name].data as Uint32Array;
  return {
    id, name: meta.name, revision: meta.revision, edited: Boolean(meta.edited), n: meta.n,
    m: meta.faces, b: meta.bodies,
    j: meta.joints, k: meta.modes, G: meta.groups, center: meta.center, diagonal: meta.diagonal,
    jointList: meta.joint_list, bodyNames: meta.body_names, palette: meta.palette,
    offset: meta.offset ?? 0,
    vertices: f("vertices"), faces: u("faces"), tau: f("tau"), frequencies: f("frequencies"),
    amplitudes: f("amplitudes"), tileAmplitudes: f("tile_amplitudes"), reach: f("reach"),
    phases: f("phases"),
    skinJoints: u("skin_joints"), skinWeights: f("skin_weights"),
    boneMatrices: f("bone_matrices"), bindMatrices: f("bind_matrices"),
    bodyCenters: f("body_centers"), bodyRotations: f("body_rotations"), bodyEnds: f("body_ends"),
    bodyTwists: f("body_twists"), jointBodies: u("joint_bodies"),
    jointPositions: f("joint_positions"), jointBend: f("joint_bend"),
  };
}

/** A frequency as the page shows it, everywhere: as played, s·ν (Hz), labelled with the time
 * scale s when it is not 1 ("2.40 Hz (×1.20 time scale)"). */
export function playedFrequency(natural: number, timeScale: number): string {
  const played = `${(natural * timeScale).toFixed(2)} Hz`;
  return Math.abs(timeScale - 1) < 5e-3 ? played
    : `${played} (×${timeScale.toFixed(2)} time scale)`;
}

/** The frequencies (Hz) a mode tile is shown between: a page drawing 10 frames a second shows
 * a 1.5 Hz swing in about 7 frames; a mode above it would read as a still, one under 0.4 Hz
 * hardly moves while one looks (the thesis's galleries were time-scaled the same way). */
export const SHOWN_HZ = { low: 0.4, high: 1.5 };

/** A mode tile's time scale: the mode at `natural` Hz × the palette's `timeScale`, brought
 * into SHOWN_HZ; and its label, the frequency as played (s·ν, as everywhere) and the shown
 * one ("56.13 Hz, shown at 1.50 Hz"; one number, with the time scale, when they agree). The
 * natural frequency had stood there beside played ones: "mode 11 · 1.42 Hz (×1.33 time
 * scale)" then "mode 12 · 1.16 Hz, shown at 1.50 Hz", the higher mode reading lower. */
export function shownMode(natural: number, timeScale: number): { timeScale: number;
  label: string } {
  if (!(natural > 0)) return { timeScale, label: playedFrequency(natural, timeScale) };
  const shown = Math.min(SHOWN_HZ.high, Math.max(SHOWN_HZ.low, natural * timeScale));
  if (Math.abs(shown - natural * timeScale) < 1e-9) {
    return { timeScale, label: playedFrequency(natural, timeScale) };
  }
  return { timeScale: shown / natural,
    label: `${(natural * timeScale).toFixed(2)} Hz, shown at ${shown.toFixed(2)} Hz` };
}

/** "mode 4", "modes 1–3, 5": 0-based mode indices as the page numbers them (from 1). */
export function modesLabel(modes: ArrayLike<number>): string {
  const sorted = [...new Set(Array.from(modes))].sort((a, b) => a - b);
  const runs: string[] = [];
  for (let i = 0; i < sorted.length;) {
    let j = i;
    while (j + 1 < sorted.length && sorted[j + 1] === sorted[j] + 1) j++;
    runs.push(j > i ? `${sorted[i] + 1}–${sorted[j] + 1}` : `${sorted[i] + 1}`);
    i = j + 1;
  }
  if (!runs.length) return "still";
  return `${sorted.length === 1 ? "mode" : "modes"} ${runs.join(", ")}`;
}

/** The scale σ = 2 / diagonal that brings the skin to the page's normalised units (the
 * harmonics' size: a diagonal of 2, centred at 0). */
export function normalising(rig: Rig): number { return rig.diagonal > 0 ? 2 / rig.diagonal : 1; }

/**
 * The rig as the harmonics' deformation machinery reads a basis (`Deformer`, `PositionsPass`,
 * `deformCPU`): normalised rest positions, and τ as "harmonics" of K4 = 3G texels per vertex —
 * texel 3g + d holds τ_d of modes 4g…4g+3. `modalWeights` then gives the shader weights that
 * make X + U·w the modal skinning x + Σ_κ c_κ τ_κ (docs/web.md#rig-motion-in-the-page).
 */
export function rigBasis(rig: Rig): Basis {
  const s = normalising(rig);
  const vertices = new Float32Array(rig.n * 3);
  for (let i = 0; i < rig.n; i++) {
    for (let d = 0; d < 3; d++) vertices[3 * i + d] = (rig.vertices[3 * i + d] - rig.center[d]) * s;
  }
  return { name: rig.name, n: rig.n, k: 12 * rig.G, k4: 3 * rig.G, vertices, faces: rig.faces,
    eigenvalues: new Float32Array(0), coefficients: new Float32Array(0), harmonics: rig.tau };
}

/** Normalised positions (n*3) back in the file's units (in place). */
export function toFileUnits(rig: Rig, positions: Float32Array): Float32Array {
  const s = normalising(rig);
  for (let i = 0; i < rig.n; i++) {
    for (let d = 0; d < 3; d++) positions[3 * i + d] = positions[3 * i + d] / s + rig.center[d];
  }
  return positions;
}

// Routes -----------------------------------------------------------------------------------

async function bundleOf(url: string, id: string, body?: unknown): Promise<Rig> {
  const init: RequestInit | undefined = body === undefined ? undefined : {
    method: "POST", headers: { "Content-Type": "application/json" }, body: JSON.stringify(body) };
  const response = await api.checked(await fetch(url, init));
  return rigFromBundle(await response.arrayBuffer(), id);
}

export const rigBundle = (id: string) => bundleOf(`api/rigs/${id}/rig.bin`, id);

/** Equilibrium pose edit (thesis Fig. 4.17): turn `joint`'s second side by `rotation`. */
export const poseRig = (id: string, joint: number, rotation: [number, number, number]) =>
  bundleOf(`api/rigs/${id}/pose`, id, { joint, rotation });

/** Per-joint stiffness (a number per free row, or "auto": the default rule). */
export const stiffenRig = (id: string, joints: Record<string, number | number[] | "auto">) =>
  bundleOf(`api/rigs/${id}/stiffness`, id, { joints });

export const resetRig = (id: string) => bundleOf(`api/rigs/${id}/reset`, id, {});

/** The initial gallery of mode mappings calibrated on the song, and the default mapping. */
export async function rigGallery(rig: string, song: string, size: number | null):
    Promise<{ mappings: Mapping[]; default: Mapping }> {
  return api.postJSON("api/rig-gallery", size === null ? { rig, song } : { rig, song, size });
}

