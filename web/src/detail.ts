// Level of detail for the gallery's tiles (docs/design.md#rendering): when even the lowest
// resolution cannot hold the frame rate, what remains is the triangles (a software rasteriser
// sets up each one at a fixed cost, whatever the pixels). meshoptimizer's simplifier (index-only:
// the same vertices, fewer triangles) gives a coarser triangle list over the model's own
// vertices, so the deformation — per vertex, on the GPU or the CPU — is exactly the same.
import { MeshoptSimplifier } from "meshoptimizer";

/** The detail levels, fractions of the triangles drawn (1: all). */
export const DETAIL_LEVELS = [1, 0.5, 0.25];
/** The largest geometric error the simplifier may make, relative to the model's extent. */
export const DETAIL_ERROR = 0.02;

let loaded = false;
MeshoptSimplifier.ready.then(() => { loaded = true; }, () => {});

/** Whether the simplifier is loaded (it compiles its WebAssembly once, at start). */
export function simplifierReady(): boolean { return loaded && MeshoptSimplifier.supported; }

/** The simplifier, once loaded (for tests: `await detailReady()`). */
export const detailReady = (): Promise<void> => MeshoptSimplifier.ready;

/**
 * A triangle list of about `fraction` of `faces`' triangles over the same vertices (rest
 * positions `vertices`, n*3), within DETAIL_ERROR of the model's extent; null when the
 * simplifier is not loaded yet. Fewer triangles may be kept than asked where the error bound
 * stops the simplifier first (a model that is all detail).
 */
export function simplifiedFaces(faces: Uint32Array, vertices: Float32Array, fraction: number):
    Uint32Array | null {
  if (!simplifierReady()) return null;
  if (fraction >= 1) return faces;
  const target = Math.max(3, 3 * Math.floor((faces.length / 3) * fraction));
  const [indices] = MeshoptSimplifier.simplify(Uint32Array.from(faces), vertices, 3, target,
    DETAIL_ERROR);
  return indices.length >= 3 ? indices : faces;
}

/** The triangles of `faces` (m*3) with a vertex i where mask[welded[i]] is 1 (welded: the
 * identity when absent). */
export function trianglesTouching(faces: ArrayLike<number>, mask: Uint8Array,
                                  welded?: ArrayLike<number>): Uint32Array {
  const kept: number[] = [];
  const on = (v: number) => mask[welded ? welded[v] : v] === 1;
  for (let t = 0; t < faces.length; t += 3) {
    if (on(faces[t]) || on(faces[t + 1]) || on(faces[t + 2])) kept.push(faces[t], faces[t + 1], faces[t + 2]);
  }
  return Uint32Array.from(kept);
}
