// The whole body dances in the page (docs/design.md#surface-of-a-rig): the rig's skin ripples in
// its harmonics while its bones sway. The skin's harmonics (api/rigs/{id}/surface.bin) join the
// modal skin's τ texels, so the one positions pass (GPU) and `deformCPU` add the bind-pose ripple
// d = U((φ − 1) ⊙ X̃) to x + Σ c·τ: first order in the bones' motion, as the page's modal skinning
// (the Python's modal path also turns d by Σ c·ρ, a product of two small motions).
import * as api from "./api";
import type { Basis } from "./bundle";
import { parseBundle } from "./bundle";
import { deformCPU, filterValues, prepare } from "./filter";
import type { Mapping, Prepared } from "./filter";
import type { Motion } from "./motion";
import type { Rig } from "./rig-bundle";
import { normalising, rigBasis } from "./rig-bundle";

/** A rig's dance: its mapping, with its surface genes (the mapping its skin ripples by) or not. */
export type RigDance = Mapping & { surface?: Mapping | null };

/** The skin's harmonics as the server packs them (`server.surface_routes.surface_bundle`). */
export interface RigSurface {
  n: number;
  k: number;
  /** texel groups ⌈k/4⌉ */
  G: number;
  /** n * 4G: four harmonics per texel, on the rig's skin vertices */
  harmonics: Float32Array;
  /** k*3: X̃·scale, the rig's units */
  coefficients: Float32Array;
}

export function surfaceFromBundle(buffer: ArrayBuffer): RigSurface {
  const { meta, arrays } = parseBundle(buffer);
  if (meta.kind !== "rig-surface") throw new Error("not a rig surface bundle");
  return { n: meta.n, k: meta.k, G: meta.groups, harmonics: arrays.harmonics.data as Float32Array,
    coefficients: arrays.coefficients.data as Float32Array };
}

export async function rigSurface(id: string): Promise<RigSurface> {
  const response = await api.checked(await fetch(`api/rigs/${id}/surface.bin`));
  return surfaceFromBundle(await response.arrayBuffer());
}

/** The skin's initial gallery on the song: the surface dances to choose from. */
export async function surfaceGallery(rig: string, song: string, size = 8): Promise<Mapping[]> {
  return (await api.postJSON<{ mappings: Mapping[] }>("api/rig-surface-gallery",
    { rig, song, size })).mappings;
}

/** The rig as a basis (`rigBasis`) with the skin's harmonics appended: K4 = 3G + G_s texels per
 * vertex, texel 3G + h holding harmonics 4h…4h+3. */
export function surfaceBasis(rig: Rig, surface: RigSurface): Basis {
  const base = rigBasis(rig);
  const k4 = 3 * rig.G + surface.G, width = 4 * k4, modal = 12 * rig.G;
  const harmonics = new Float32Array(rig.n * width);
  for (let i = 0; i < rig.n; i++) {
    harmonics.set(rig.tau.subarray(i * modal, (i + 1) * modal), i * width);
    harmonics.set(surface.harmonics.subarray(i * 4 * surface.G, (i + 1) * 4 * surface.G),
      i * width + modal);
  }
  return { ...base, k: 4 * k4, k4, harmonics };
}

/** Weights of the surface texels (after the modal skin's 36G): row d of texel 3G + h gets
 * (φ_{4h+q} − 1)·X̃_{4h+q, d}·σ, so the pass adds U((φ − 1) ⊙ X̃) in normalised units. */
export function surfaceWeights(rig: Rig, surface: RigSurface, phi: ArrayLike<number>,
                               weights: Float32Array): Float32Array {
  const s = normalising(rig);
  for (let h = 0; h < surface.G; h++) {
    const texel = 3 * rig.G + h;
    for (let d = 0; d < 3; d++) {
      for (let q = 0; q < 4; q++) {
        const nu = 4 * h + q;
        weights[12 * texel + 4 * d + q] = nu < surface.k
          ? (phi[nu] - 1) * surface.coefficients[3 * nu + d] * s : 0;
      }
    }
  }
  return weights;
}

/** The skin's ripple per unit of φ_ν − 1, D_ν = u_ν X̃_ν (k arrays of n*3, the rig's units):
 * the glb's morph targets, which the LBS skin applies before skinning (bones.ts). */
export function surfaceTargets(surface: RigSurface): Float32Array[] {
  const width = 4 * surface.G;
  return Array.from({ length: surface.k }, (_, nu) => {
    const target = new Float32Array(3 * surface.n);
    for (let i = 0; i < surface.n; i++) {
      const u = surface.harmonics[i * width + nu];
      for (let d = 0; d < 3; d++) target[3 * i + d] = u * surface.coefficients[3 * nu + d];
    }
    return target;
  });
}

/** What the player's surface plays: the skin's harmonics, a surface mapping and its gain. */
export class SurfacePlay {
  readonly prepared: Prepared;

  constructor(readonly surface: RigSurface, readonly mapping: Mapping, public gain = 1) {
    this.prepared = prepare(mapping, surface.k);
  }

  /** φ (k) of the surface mapping at song time t (its gain times the slider's). */
  phi(music: Motion, t: number): Float64Array {
    if (!music.spectrum) return new Float64Array(this.surface.k).fill(1);
    return filterValues(this.prepared, music.bandValuesAt(t, this.prepared),
      this.prepared.gain * this.gain * music.sectionGain(this.prepared, t), undefined,
      music.kick(this.prepared, t));
  }

  /** The mapping with its gain as played (the rig mapping's `surface` genes). */
  genes(): Mapping {
    return { ...this.mapping, gain: (this.mapping.gain ?? 1) * this.gain } as Mapping;
  }
}

/** The surface's share of the motion (`modal.surface.surface_share`): RMS over `times` and the
 * vertices of (whole − bones) over that of (whole − rest), from the CPU path. `weights(t, on)`
 * gives the pass's weights with the surface on or off. */
export function surfaceShare(basis: Basis, times: number[],
                             weights: (t: number, on: boolean) => Float32Array): number {
  let moved = 0, ripple = 0;
  for (const t of times) {
    const whole = deformCPU(basis, weights(t, true)), bones = deformCPU(basis, weights(t, false));
    for (let i = 0; i < whole.length; i++) {
      moved += (whole[i] - basis.vertices[i]) ** 2;
      ripple += (whole[i] - bones[i]) ** 2;
    }
  }
  return moved > 0 ? Math.sqrt(ripple / moved) : 0;
}
