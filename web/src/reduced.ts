// A reduced basis in the page (docs/design.md#reduced-basis, docs/web.md#basis-bundle): the
// harmonics texture holds U_r (m samples), the positions pass runs over the samples and gives
// their displacements D_j = Σ_ν U_r[j, ν] (φ_ν − 1) X̃_ν, and every vertex gathers the ≤ 8 of
// its samples, x = rest + Σ_j w_j D_j — linear blend skinning with translation-only joints. The
// surface pass gathers in its vertex shader (the REDUCED define of the shared surface shader,
// src/eigendance/shaders/surface.vert.glsl); `GatherPass` draws that same shader as points into
// a float target (READ_BACK) to read positions back; `deformReducedCPU` is the CPU path, the
// same numbers.
import * as THREE from "three";
import type { Basis, Interpolation } from "./bundle";
import { SURFACE_VERTEX, TEXELS } from "./shaders";

/** Weights are multiples of 2⁻¹¹ (docs/design.md#reduced-basis): sent to the GPU as the
 * integers w·2048 (exact), scaled back in the shader (surface.vert.glsl WEIGHT_UNIT). */
export const WEIGHT_UNITS = 2048;

const ATTRIBUTES = { sampleIndices0: 0, sampleIndices1: 4, sampleWeights0: 0, sampleWeights1: 4 };

/** The four gather attributes of a reduced basis's geometry: the 8 sample indices and weights
 * of each vertex as two vec4 each (interleaved views of one array: no copy of the indices
 * when they fit 16 bits); of the vertices `rows` only (a model's drawn vertices, their welded
 * ones) when given. */
export function gatherAttributes(reduced: Interpolation, rows?: ArrayLike<number>):
    Record<string, THREE.InterleavedBufferAttribute> {
  let indices: Uint16Array | Float32Array = reduced.indices instanceof Uint16Array
    ? reduced.indices : Float32Array.from(reduced.indices); // exact below 2²⁴ samples
  let weights = new Uint16Array(reduced.weights.length);
  for (let i = 0; i < weights.length; i++) weights[i] = Math.round(reduced.weights[i] * WEIGHT_UNITS);
  if (rows) {
    indices = pickRows(indices, rows);
    weights = pickRows(weights, rows);
  }
  const indexBuffer = new THREE.InterleavedBuffer(indices, 8);
  const weightBuffer = new THREE.InterleavedBuffer(weights, 8);
  return {
    sampleIndices0: new THREE.InterleavedBufferAttribute(indexBuffer, 4, 0),
    sampleIndices1: new THREE.InterleavedBufferAttribute(indexBuffer, 4, 4),
    sampleWeights0: new THREE.InterleavedBufferAttribute(weightBuffer, 4, 0),
    sampleWeights1: new THREE.InterleavedBufferAttribute(weightBuffer, 4, 4),
  };
}

/** Rows `rows` (8 values each) of `values`, in that order. */
function pickRows<T extends Uint16Array | Float32Array>(values: T, rows: ArrayLike<number>): T {
  const out = new (values.constructor as new (length: number) => T)(rows.length * 8);
  for (let i = 0; i < rows.length; i++) out.set(values.subarray(8 * rows[i], 8 * rows[i] + 8), 8 * i);
  return out;
}

/** A points geometry of the m samples for the positions pass: rest position 0 (the pass then
 * writes displacements) and `vid` the sample's row of the harmonics texture. */
export function sampleGeometry(m: number): THREE.BufferGeometry {
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute("position", new THREE.BufferAttribute(new Float32Array(3 * m), 3));
  geometry.setAttribute("vid", new THREE.BufferAttribute(new Float32Array(m).map((_, i) => i), 1));
  return geometry;
}

/** The gather into a float target (vertex v at pixel (v mod width, v div width)), to read a
 * tile's positions back: the surface pass's own shader (REDUCED, READ_BACK), drawn as points. */
export class GatherPass {
  readonly target: THREE.WebGLRenderTarget;
  readonly width: number;
  private readonly material: THREE.RawShaderMaterial;
  private readonly scene = new THREE.Scene();
  private readonly camera = new THREE.OrthographicCamera(-1, 1, 1, -1, 0, 1);

  constructor(readonly geometry: THREE.BufferGeometry, readonly n: number, width: number,
              samplesWidth: number, harmonics: THREE.Texture, texWidth: number, k4: number) {
    this.width = Math.min(n, width);
    const height = Math.ceil(n / this.width);
    this.target = new THREE.WebGLRenderTarget(this.width, height, {
      type: THREE.FloatType, format: THREE.RGBAFormat, depthBuffer: false,
      minFilter: THREE.NearestFilter, magFilter: THREE.NearestFilter, generateMipmaps: false,
    });
    this.material = new THREE.RawShaderMaterial({
      glslVersion: THREE.GLSL3, defines: { K4: k4, HARMONICS: 1, REDUCED: 1, READ_BACK: 1 },
      uniforms: { deformed: { value: null }, deformedWidth: { value: samplesWidth },
        harmonics: { value: harmonics }, texWidth: { value: texWidth },
        colorHarmonic: { value: -1 }, colorScale: { value: 1 },
        targetWidth: { value: this.width }, targetSize: { value: new THREE.Vector2(this.width, height) } },
      vertexShader: TEXELS + SURFACE_VERTEX,
      fragmentShader: /* glsl */ `
precision highp float;
in vec3 vViewPosition; // READ_BACK: the vertex's position
layout(location = 0) out highp vec4 outPosition;
void main() { outPosition = vec4(vViewPosition, 1.0); }`,
      depthTest: false, depthWrite: false,
    });
    const vertices = new THREE.BufferGeometry(); // the surface's attributes, without faces
    for (const name of ["position", "normal", "vid", ...Object.keys(ATTRIBUTES)]) {
      vertices.setAttribute(name, geometry.getAttribute(name));
    }
    const points = new THREE.Points(vertices, this.material);
    points.frustumCulled = false;
    this.scene.add(points);
  }

  /** Positions (n*3) of the tile whose sample displacements are `displacements`. */
  read(renderer: THREE.WebGLRenderer, displacements: THREE.Texture): Float32Array {
    this.material.uniforms.deformed.value = displacements;
    const previous = renderer.getRenderTarget();
    const scissor = renderer.getScissorTest();
    renderer.setScissorTest(false);
    renderer.setRenderTarget(this.target);
    renderer.render(this.scene, this.camera);
    const pixels = new Float32Array(this.target.width * this.target.height * 4);
    renderer.readRenderTargetPixels(this.target, 0, 0, this.target.width, this.target.height,
      pixels);
    renderer.setRenderTarget(previous);
    renderer.setScissorTest(scissor);
    const out = new Float32Array(this.n * 3);
    for (let i = 0; i < this.n; i++) {
      out[3 * i] = pixels[4 * i];
      out[3 * i + 1] = pixels[4 * i + 1];
      out[3 * i + 2] = pixels[4 * i + 2];
    }
    return out;
  }

  dispose(): void {
    this.target.dispose();
    this.material.dispose();
  }
}

const coarseBuffers = new WeakMap<Basis, Float32Array>();

/** CPU path of a reduced basis: the samples' displacements (the positions pass's numbers), then
 * each vertex's gather; of every vertex, or of `vertices` only (packed in their order). */
export function deformReducedCPU(basis: Basis, weights: Float32Array, out?: Float32Array,
                                 vertices?: Int32Array): Float32Array {
  const reduced = basis.reduced!;
  const { m } = reduced;
  let coarse = coarseBuffers.get(basis);
  if (!coarse) coarseBuffers.set(basis, coarse = new Float32Array(3 * m));
  const U = basis.harmonics, W = 4 * basis.k4;
  for (let s = 0; s < m; s++) {
    let x = 0, y = 0, z = 0;
    const row = s * W;
    for (let j = 0; j < basis.k4; j++) {
      const u0 = U[row + 4 * j], u1 = U[row + 4 * j + 1], u2 = U[row + 4 * j + 2],
        u3 = U[row + 4 * j + 3];
      const w = 12 * j;
      x += u0 * weights[w] + u1 * weights[w + 1] + u2 * weights[w + 2] + u3 * weights[w + 3];
      y += u0 * weights[w + 4] + u1 * weights[w + 5] + u2 * weights[w + 6] + u3 * weights[w + 7];
      z += u0 * weights[w + 8] + u1 * weights[w + 9] + u2 * weights[w + 10] + u3 * weights[w + 11];
    }
    coarse[3 * s] = x;
    coarse[3 * s + 1] = y;
    coarse[3 * s + 2] = z;
  }
  const count = vertices ? vertices.length : basis.n;
  const positions = out ?? new Float32Array(count * 3);
  const { weights: w, indices } = reduced;
  for (let o = 0; o < count; o++) {
    const i = vertices ? vertices[o] : o;
    let x = 0, y = 0, z = 0;
    for (let s = 8 * i; s < 8 * i + 8; s++) {
      const j = 3 * indices[s], weight = w[s];
      x += weight * coarse[j];
      y += weight * coarse[j + 1];
      z += weight * coarse[j + 2];
    }
    positions[3 * o] = basis.vertices[3 * i] + x;
    positions[3 * o + 1] = basis.vertices[3 * i + 1] + y;
    positions[3 * o + 2] = basis.vertices[3 * i + 2] + z;
  }
  return positions;
}

/** The harmonics explorer's value of harmonic `index` at every vertex, Σ_j w_j U_r[j, index]. */
export function reducedHarmonic(basis: Basis, index: number): Float32Array {
  const { weights, indices } = basis.reduced!;
  const W = 4 * basis.k4;
  const values = new Float32Array(basis.n);
  for (let i = 0; i < basis.n; i++) {
    let value = 0;
    for (let s = 8 * i; s < 8 * i + 8; s++) value += weights[s] * basis.harmonics[indices[s] * W + index];
    values[i] = value;
  }
  return values;
}
