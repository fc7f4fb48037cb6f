// The floor under a rig (docs/design.md#the-floor), as `eigendance.modal.floor` and
// `palette.floor_capped` keep the skin above it: the plane of the skin's lowest rest point (y up),
// which no vertex may sink below by more than FLOOR_SLACK of the diagonal — each mode alone, and
// the selected modes together in their worst phases at φ = 1. Modal skinning is linear, so vertex
// i sinks at most Σ_κ |μ_κ|·|τ_iκ,y|: the numbers come from the bundle's `vertices` and the y rows
// of its `tau`. Vitest checks it against the palettes Python resolves.
import type { Rig } from "./rig-bundle";

/** How far (fraction of the skin's diagonal) a limb may sink below the floor
 * (`floor.FLOOR_SLACK`). */
export const FLOOR_SLACK = 0.02;

interface Floor {
  /** (n) how far each vertex may sink: y_i − min y + slack */
  room: Float64Array;
  /** (n·k) |τ_iκ,y|, vertex-major */
  sink: Float32Array;
  /** (k) the largest |μ| of each mode alone */
  caps: Float64Array;
}

const floors = new WeakMap<Rig, Floor>();

/** The rig's floor (made once per bundle). */
export function floorOf(rig: Rig): Floor {
  let floor = floors.get(rig);
  if (floor) return floor;
  const { n, k, G } = rig;
  const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < n; i++) {
    for (let d = 0; d < 3; d++) {
      lo[d] = Math.min(lo[d], rig.vertices[3 * i + d]); hi[d] = Math.max(hi[d], rig.vertices[3 * i + d]);
    }
  }
  const low = lo[1];
  const slack = FLOOR_SLACK * Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  const room = new Float64Array(n), sink = new Float32Array(n * k);
  const caps = new Float64Array(k).fill(Infinity);
  for (let i = 0; i < n; i++) {
    room[i] = rig.vertices[3 * i + 1] - low + slack;
    for (let mode = 0; mode < k; mode++) {
      const g = mode >> 2, q = mode & 3;
      const value = Math.abs(rig.tau[((i * G + g) * 3 + 1) * 4 + q]);
      sink[i * k + mode] = value;
      if (value > 0) caps[mode] = Math.min(caps[mode], room[i] / value);
    }
  }
  floor = { room, sink, caps };
  floors.set(rig, floor);
  return floor;
}

/** The largest reach (radians) of mode κ alone that keeps the skin above the floor. */
export function floorCap(rig: Rig, mode: number): number {
  return floorOf(rig).caps[mode] * rig.reach[mode];
}

/** Amplitudes (reach, radians) of the `selected` modes that keep the skin above the floor:
 * each at most its cap alone, then all scaled down together while their worst phases would sink
 * a vertex too far (`palette.floor_capped`). */
export function floorCapped(rig: Rig, selected: number[], amplitudes: number[]): number[] {
  if (!selected.length) return amplitudes;
  const floor = floorOf(rig);
  const capped = amplitudes.map((a, v) => Math.sign(a)
    * Math.min(Math.abs(a), floor.caps[selected[v]] * rig.reach[selected[v]]));
  const mu = capped.map((a, v) => Math.abs(a) / rig.reach[selected[v]]);
  let worst = 0;
  for (let i = 0; i < rig.n; i++) {
    let sunk = 0;
    for (let v = 0; v < selected.length; v++) sunk += floor.sink[i * rig.k + selected[v]] * mu[v];
    worst = Math.max(worst, sunk / floor.room[i]);
  }
  return worst > 1 ? capped.map((a) => a / worst) : capped;
}
