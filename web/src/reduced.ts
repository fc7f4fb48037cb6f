// A reduced basis in the page (docs/design.md#reduced-basis, docs/web.md#basis-bundle): the
// harmonics texture holds U_r (m samples), the positions pass runs over the samples and gives
// their displacements D_j = Σ_ν U_r[j, ν] (φ_ν − 1) X̃_ν, and every vertex gathers the ≤ 8 of
// its samples, x = rest + Σ_j w_j D_j — linear blend skinning with translation-only joints. The
// surface pass gathers in its vertex shader; `GatherPass` writes the same gather into a float
// target to read positions back; `deformReducedCPU` is the CPU path, the same numbers.
import * as THREE from "three";
import type { Basis, Interpolation } from "./bundle";
import { TEXELS } from "./shaders";

/** Weights are multiples of 2⁻¹¹ (docs/design.md#reduced-basis): sent to the GPU as the
 * integers w·2048 (exact), scaled back in the shader. */
export const WEIGHT_UNITS = 2048;

/** GLSL of the gather (after TEXELS): `deformed` holds one tile's sample displacements, one per
 * texel (row-major, `deformedWidth` wide); the attributes are the vertex's 8 samples and
 * weights. `gatherHarmonicTexel` is the harmonics explorer's value of U = P U_r. */
export const GATHER = /* glsl */ `
uniform sampler2D deformed;
uniform int deformedWidth;
in vec4 sampleIndices0;
in vec4 sampleIndices1;
in vec4 sampleWeights0;
in vec4 sampleWeights1;
vec3 sampleDisplacement(float j) {
  int i = int(j + 0.5);
  return texelFetch(deformed, ivec2(i % deformedWidth, i / deformedWidth), 0).xyz;
}
vec3 gatherDisplacement() {
  vec3 d = sampleWeights0.x * sampleDisplacement(sampleIndices0.x)
    + sampleWeights0.y * sampleDisplacement(sampleIndices0.y)
    + sampleWeights0.z * sampleDisplacement(sampleIndices0.z)
    + sampleWeights0.w * sampleDisplacement(sampleIndices0.w)
    + sampleWeights1.x * sampleDisplacement(sampleIndices1.x)
    + sampleWeights1.y * sampleDisplacement(sampleIndices1.y)
    + sampleWeights1.z * sampleDisplacement(sampleIndices1.z)
    + sampleWeights1.w * sampleDisplacement(sampleIndices1.w);
  return d * ${(1 / WEIGHT_UNITS).toFixed(12)};
}
vec4 gatherHarmonicTexel(int j) {
  vec4 u = vec4(0.0);
  for (int s = 0; s < 4; s++) {
    u += sampleWeights0[s] * harmonicTexel(int(sampleIndices0[s] + 0.5), j);
    u += sampleWeights1[s] * harmonicTexel(int(sampleIndices1[s] + 0.5), j);
  }
  return u * ${(1 / WEIGHT_UNITS).toFixed(12)};
}
`;

const ATTRIBUTES = { sampleIndices0: 0, sampleIndices1: 4, sampleWeights0: 0, sampleWeights1: 4 };

/** The four gather attributes of a reduced basis's geometry: the 8 sample indices and weights
 * of each vertex as two vec4 each (interleaved views of one array: no copy of the indices
 * when they fit 16 bits). */
export function gatherAttributes(reduced: Interpolation):
    Record<string, THREE.InterleavedBufferAttribute> {
  const indices = reduced.indices instanceof Uint16Array ? reduced.indices
    : Float32Array.from(reduced.indices); // exact below 2²⁴ samples
  const weights = new Uint16Array(reduced.weights.length);
  for (let i = 0; i < weights.length; i++) weights[i] = Math.round(reduced.weights[i] * WEIGHT_UNITS);
  const indexBuffer = new THREE.InterleavedBuffer(indices, 8);
  const weightBuffer = new THREE.InterleavedBuffer(weights, 8);
  return {
    sampleIndices0: new THREE.InterleavedBufferAttribute(indexBuffer, 4, 0),
    sampleIndices1: new THREE.InterleavedBufferAttribute(indexBuffer, 4, 4),
    sampleWeights0: new THREE.InterleavedBufferAttribute(weightBuffer, 4, 0),
    sampleWeights1: new THREE.InterleavedBufferAttribute(weightBuffer, 4, 4),
  };
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
 * tile's positions back: the surface pass's own GLSL, drawn as points. */
export class GatherPass {
  readonly target: THREE.WebGLRenderTarget;
  readonly width: number;
  private readonly material: THREE.ShaderMaterial;
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
    this.material = new THREE.ShaderMaterial({
      glslVersion: THREE.GLSL3, defines: { K4: k4 },
      uniforms: { deformed: { value: null }, deformedWidth: { value: samplesWidth },
        harmonics: { value: harmonics }, texWidth: { value: texWidth },
        targetWidth: { value: this.width }, targetSize: { value: new THREE.Vector2(this.width, height) } },
      vertexShader: TEXELS + GATHER + /* glsl */ `
uniform int targetWidth;
uniform vec2 targetSize;
out vec3 vPosition;
void main() {
  int v = int(vid + 0.5);
  vPosition = position + gatherDisplacement();
  vec2 pixel = vec2(float(v % targetWidth), float(v / targetWidth)) + 0.5;
  gl_Position = vec4(pixel / targetSize * 2.0 - 1.0, 0.0, 1.0);
  gl_PointSize = 1.0;
}`,
      fragmentShader: /* glsl */ `
precision highp float;
in vec3 vPosition;
layout(location = 0) out highp vec4 outPosition;
void main() { outPosition = vec4(vPosition, 1.0); }`,
      depthTest: false, depthWrite: false,
    });
    const vertices = new THREE.BufferGeometry(); // the surface's attributes, without faces
    for (const name of ["position", "vid", ...Object.keys(ATTRIBUTES)]) {
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
