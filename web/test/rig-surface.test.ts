// The rig's surface in the page (rig-surface.ts, docs/design.md#surface-of-a-rig): the skin's
// harmonics appended to the modal skin's texels make the positions pass (here its CPU path)
// add the ripple d = U((φ − 1) ⊙ X̃), in normalised units, to the modal skinning x + Σ c·τ; the
// LBS skin (bones.ts) morphs by it before skinning.
import { readFileSync } from "node:fs";
import { join } from "node:path";
import { describe, expect, it } from "vitest";
import { deformCPU } from "../src/filter";
import { RigFigure } from "../src/bones";
import { bodyMatrices, modalWeights } from "../src/modal-skin";
import { normalising, rigBasis, rigFromBundle } from "../src/rig-bundle";
import { surfaceBasis, surfaceWeights } from "../src/rig-surface";
import type { RigSurface } from "../src/rig-surface";

const data = readFileSync(join(__dirname, "fixtures", "rig.bin"));
const rig = rigFromBundle(data.buffer.slice(data.byteOffset, data.byteOffset + data.byteLength),
  "chain3");

/** A skin of k = 5 smooth "harmonics" (two texel groups, the last three padded with 0). */
function surfaceOf(k: number): RigSurface {
  const G = Math.ceil(k / 4);
  const harmonics = new Float32Array(rig.n * 4 * G);
  for (let i = 0; i < rig.n; i++) {
    for (let nu = 0; nu < k; nu++) harmonics[i * 4 * G + nu] = Math.cos(0.01 * (nu + 1) * i);
  }
  const coefficients = Float32Array.from({ length: 3 * k }, (_, j) => 0.1 * Math.sin(j + 1));
  return { n: rig.n, k, G, harmonics, coefficients };
}

describe("the rig's surface", () => {
  it("adds the ripple to the modal skin through the one positions pass", () => {
    const surface = surfaceOf(5);
    const basis = surfaceBasis(rig, surface);
    expect(basis.k4).toBe(3 * rig.G + surface.G);
    const c = Float64Array.from({ length: rig.k }, (_, j) => 0.05 * (j + 1));
    const phi = [1.5, 0.25, 1, 2, -0.5];
    const weights = surfaceWeights(rig, surface, phi,
      modalWeights(rig, c, new Float32Array(12 * basis.k4)));
    const moved = deformCPU(basis, weights);
    const bones = deformCPU(rigBasis(rig), modalWeights(rig, c));
    const s = normalising(rig);
    let largest = 0, ripple = 0;
    for (let i = 0; i < rig.n; i++) {
      for (let d = 0; d < 3; d++) {
        let expected = 0; // σ Σ_ν (φ_ν − 1) U[i, ν] X̃[ν, d], summed here term by term
        for (let nu = 0; nu < 5; nu++) {
          expected += s * (phi[nu] - 1) * Math.cos(0.01 * (nu + 1) * i)
            * 0.1 * Math.sin(3 * nu + d + 1);
        }
        largest = Math.max(largest, Math.abs(moved[3 * i + d] - bones[3 * i + d] - expected));
        ripple = Math.max(ripple, Math.abs(expected));
      }
    }
    expect(ripple).toBeGreaterThan(0.01);
    expect(largest).toBeLessThan(1e-5);
  });

  it("leaves the modal skin alone at φ ≡ 1", () => {
    const surface = surfaceOf(5);
    const basis = surfaceBasis(rig, surface);
    const c = Float64Array.from({ length: rig.k }, () => 0.1);
    const weights = surfaceWeights(rig, surface, [1, 1, 1, 1, 1],
      modalWeights(rig, c, new Float32Array(12 * basis.k4)));
    const moved = deformCPU(basis, weights);
    const bones = deformCPU(rigBasis(rig), modalWeights(rig, c));
    for (let i = 0; i < moved.length; i++) expect(Math.abs(moved[i] - bones[i])).toBeLessThan(1e-6);
  });
});

describe("the LBS skin's ripple", () => {
  it("is applied in the bind pose before the skin: Σ_b w_ib T_b (x_i + d_i)", () => {
    const surface = surfaceOf(5);
    const figure = new RigFigure(rig, null, surface);
    const c = Float64Array.from({ length: rig.k }, (_, j) => 0.3 / (j + 1));
    const matrices = bodyMatrices(rig, c);
    const phi = [1.5, 0.25, 1, 2, -0.5];
    figure.pose(matrices);
    figure.ripple(phi);
    const shown = figure.lbsPositions();
    figure.ripple(null);
    const bones = figure.lbsPositions();
    let largest = 0, ripple = 0;
    for (let i = 0; i < rig.n; i++) {
      const x = [0, 1, 2].map((d) => {
        let sum = rig.vertices[3 * i + d]; // x + d, the ripple summed here term by term
        for (let nu = 0; nu < 5; nu++) {
          sum += (phi[nu] - 1) * Math.cos(0.01 * (nu + 1) * i) * 0.1 * Math.sin(3 * nu + d + 1);
        }
        return sum;
      });
      const expected = [0, 0, 0];
      for (let slot = 0; slot < 4; slot++) {
        const w = rig.skinWeights[4 * i + slot], b = rig.skinJoints[4 * i + slot];
        if (w === 0) continue;
        // T_b = posed_b · bind_b (column-major 4×4), applied to the rippled point
        const M = matrices.subarray(16 * b, 16 * b + 16), B = rig.bindMatrices.subarray(16 * b, 16 * b + 16);
        const bound = [0, 1, 2].map((r) => B[r] * x[0] + B[4 + r] * x[1] + B[8 + r] * x[2] + B[12 + r]);
        for (let r = 0; r < 3; r++) {
          expected[r] += w * (M[r] * bound[0] + M[4 + r] * bound[1] + M[8 + r] * bound[2] + M[12 + r]);
        }
      }
      for (let d = 0; d < 3; d++) {
        largest = Math.max(largest, Math.abs(shown[3 * i + d] - expected[d]));
        ripple = Math.max(ripple, Math.abs(shown[3 * i + d] - bones[3 * i + d]));
      }
    }
    expect(ripple).toBeGreaterThan(0.01);
    expect(largest).toBeLessThan(1e-5);
  });
});
