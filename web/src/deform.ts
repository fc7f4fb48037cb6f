// GPU deformation (DESIGN §6): U packed four harmonics per RGBA32F texel in a float texture,
// per tile only the k filter values change, uploaded as a uniform array of weights
// (φ − 1) ⊙ X̃ (see filter.ts shaderWeights). A CPU path gives the same numbers.
import * as THREE from "three";
import type { Basis } from "./bundle";

const TEXELS = /* glsl */ `
precision highp float;
precision highp int;
precision highp sampler2D;
uniform sampler2D harmonics;
uniform int texWidth;
in float vid;

vec4 harmonicTexel(int v, int j) {
  int index = v * K4 + j;
  return texelFetch(harmonics, ivec2(index % texWidth, index / texWidth), 0);
}
`;

const SURFACE_VERTEX = /* glsl */ `
uniform int colorHarmonic;
uniform float colorScale;
#ifdef CPU_PATH
in vec3 displaced;
#else
uniform sampler2D deformed;
uniform int deformedWidth;
#endif
out vec3 vViewPosition;
out vec3 vNormal;
out float vHarmonic;
void main() {
  int v = int(vid + 0.5);
#ifdef CPU_PATH
  vec3 p = displaced;
#else
  vec3 p = texelFetch(deformed, ivec2(v % deformedWidth, v / deformedWidth), 0).xyz;
#endif
  vHarmonic = 0.0;
  if (colorHarmonic >= 0) {
    vec4 u = harmonicTexel(v, colorHarmonic / 4);
    int q = colorHarmonic - 4 * (colorHarmonic / 4);
    vHarmonic = (q == 0 ? u.x : q == 1 ? u.y : q == 2 ? u.z : u.w) * colorScale;
  }
  vec4 mv = modelViewMatrix * vec4(p, 1.0);
  vViewPosition = -mv.xyz;
  vNormal = normalize(normalMatrix * normal);
  gl_Position = projectionMatrix * mv;
}
`;

const SURFACE_FRAGMENT = /* glsl */ `
precision highp float;
uniform vec3 baseColor;
uniform float normalBlend;
uniform int colorHarmonic;
uniform bool wire;
layout(location = 0) out highp vec4 fragColor;
in vec3 vViewPosition;
in vec3 vNormal;
in float vHarmonic;
vec3 diverging(float x) {
  x = clamp(x, -1.0, 1.0);
  vec3 cold = vec3(0.23, 0.30, 0.75), warm = vec3(0.71, 0.02, 0.15), mid = vec3(0.87);
  return x < 0.0 ? mix(mid, cold, -x) : mix(mid, warm, x);
}
void main() {
  vec3 color = colorHarmonic >= 0 ? diverging(vHarmonic) : baseColor;
  if (wire) { fragColor = vec4(color, 1.0); return; }
  vec3 flatNormal = normalize(cross(dFdx(vViewPosition), dFdy(vViewPosition)));
  vec3 smoothNormal = normalize(vNormal);
  if (dot(smoothNormal, flatNormal) < 0.0) smoothNormal = -smoothNormal;
  // normalBlend = weight of the original vertex normal (0: flat deformed normal).
  vec3 n = normalize(mix(flatNormal, smoothNormal, normalBlend));
  vec3 view = normalize(vViewPosition);
  vec3 key = normalize(vec3(0.5, 0.8, 0.6));
  vec3 fill = normalize(vec3(-0.7, -0.2, 0.4));
  float diffuse = max(dot(n, key), 0.0) * 0.75 + max(dot(n, fill), 0.0) * 0.25;
  float rim = pow(1.0 - max(dot(n, view), 0.0), 3.0) * 0.25;
  float spec = pow(max(dot(n, normalize(key + view)), 0.0), 40.0) * 0.25;
  fragColor = vec4(color * (0.22 + diffuse) + vec3(spec + rim), 1.0);
}
`;

/** Positions pass for `tiles` gallery tiles at once: each harmonic texel is fetched once and
 * used for every tile; tile t's positions go to colour attachment t of a float render target. */
function positionsShaders(tiles: number): { vertex: string; fragment: string } {
  const range = [...Array(tiles).keys()];
  const vertex = /* glsl */ `
uniform vec4 weights[WEIGHTS];
uniform int targetWidth;
uniform vec2 targetSize;
${range.map((t) => `out vec3 vPosition${t};`).join("\n")}
void main() {
  int v = int(vid + 0.5);
${range.map((t) => `  vec3 d${t} = vec3(0.0);`).join("\n")}
  for (int j = 0; j < K4; j++) {
    vec4 u = harmonicTexel(v, j);
    int b = 3 * j;
${range.map((t) => `    d${t} += vec3(dot(u, weights[b + ${3 * t} * K4]), dot(u, weights[b + ${3 * t} * K4 + 1]), dot(u, weights[b + ${3 * t} * K4 + 2]));`).join("\n")}
  }
${range.map((t) => `  vPosition${t} = position + d${t};`).join("\n")}
  vec2 pixel = vec2(float(v % targetWidth), float(v / targetWidth)) + 0.5;
  gl_Position = vec4(pixel / targetSize * 2.0 - 1.0, 0.0, 1.0);
  gl_PointSize = 1.0;
}
`;
  const fragment = /* glsl */ `
precision highp float;
${range.map((t) => `in vec3 vPosition${t};\nlayout(location = ${t}) out highp vec4 out${t};`).join("\n")}
void main() {
${range.map((t) => `  out${t} = vec4(vPosition${t}, 1.0);`).join("\n")}
}
`;
  return { vertex, fragment };
}

class PositionsPass {
  readonly material: THREE.ShaderMaterial;
  readonly scene = new THREE.Scene();
  readonly targets: THREE.WebGLRenderTarget[] = [];
  readonly width: number;
  readonly height: number;

  constructor(readonly deformer: Deformer, readonly tiles: number) {
    const { basis } = deformer;
    this.width = Math.min(basis.n, 1024);
    this.height = Math.ceil(basis.n / this.width);
    const shaders = positionsShaders(tiles);
    this.material = new THREE.ShaderMaterial({
      glslVersion: THREE.GLSL3,
      defines: { K4: basis.k4, WEIGHTS: 3 * basis.k4 * tiles, TILES: tiles },
      uniforms: {
        harmonics: { value: deformer.texture },
        texWidth: { value: deformer.gpuMaterial.uniforms.texWidth.value },
        weights: { value: new Float32Array(12 * basis.k4 * tiles) },
        targetWidth: { value: this.width },
        targetSize: { value: new THREE.Vector2(this.width, this.height) },
      },
      vertexShader: TEXELS + shaders.vertex, fragmentShader: shaders.fragment,
      depthTest: false, depthWrite: false,
    });
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute("position", deformer.geometry.getAttribute("position"));
    geometry.setAttribute("vid", deformer.geometry.getAttribute("vid"));
    const points = new THREE.Points(geometry, this.material);
    points.frustumCulled = false;
    this.scene.add(points);
  }

  target(index: number): THREE.WebGLRenderTarget {
    while (this.targets.length <= index) {
      this.targets.push(new THREE.WebGLRenderTarget(this.width, this.height, {
        type: THREE.FloatType, format: THREE.RGBAFormat, depthBuffer: false,
        minFilter: THREE.NearestFilter, magFilter: THREE.NearestFilter, generateMipmaps: false,
        count: this.tiles,
      }));
    }
    return this.targets[index];
  }

  /** Positions of up to `tiles` tiles into target `index`; returns one texture per tile. */
  run(weights: Float32Array[], index = 0): THREE.Texture[] {
    const all = this.material.uniforms.weights.value as Float32Array;
    all.fill(0);
    weights.forEach((w, t) => all.set(w, t * w.length));
    this.material.uniformsNeedUpdate = true;
    const target = this.target(index);
    const renderer = this.deformer.renderer;
    const previous = renderer.getRenderTarget();
    const scissor = renderer.getScissorTest();
    renderer.setScissorTest(false);
    renderer.setRenderTarget(target);
    renderer.render(this.scene, this.deformer.ortho);
    renderer.setRenderTarget(previous);
    renderer.setScissorTest(scissor);
    return target.textures.slice(0, weights.length);
  }

  /** Read tile `tile`'s positions (n*3) back from target `index`. */
  read(tile: number, index = 0): Float32Array {
    const renderer = this.deformer.renderer;
    const gl = renderer.getContext() as WebGL2RenderingContext;
    const target = this.target(index);
    const pixels = new Float32Array(this.width * this.height * 4);
    const previous = renderer.getRenderTarget();
    renderer.setRenderTarget(target);
    gl.readBuffer(gl.COLOR_ATTACHMENT0 + tile);
    gl.readPixels(0, 0, this.width, this.height, gl.RGBA, gl.FLOAT, pixels);
    gl.readBuffer(gl.COLOR_ATTACHMENT0);
    renderer.setRenderTarget(previous);
    const n = this.deformer.basis.n;
    const out = new Float32Array(n * 3);
    for (let i = 0; i < n; i++) {
      out[3 * i] = pixels[4 * i];
      out[3 * i + 1] = pixels[4 * i + 1];
      out[3 * i + 2] = pixels[4 * i + 2];
    }
    return out;
  }

  dispose(): void {
    this.material.dispose();
    this.targets.forEach((t) => t.dispose());
  }
}

export const TILE_COLORS = [0xe8a87c, 0x85cdca, 0xd8c35b, 0xc38d9e, 0x8fb4e3, 0xa3d96b, 0xf2b5d4,
  0xb8a1e6, 0xe6c189, 0x7fd1b9, 0xf28f6b, 0x9cb4cc];

export function maxHarmonicsOnGPU(renderer: THREE.WebGLRenderer): number {
  const gl = renderer.getContext();
  const vectors = gl.getParameter(gl.MAX_VERTEX_UNIFORM_VECTORS) as number;
  return 4 * Math.floor((vectors - 32) / 3);
}

/** Everything drawn for one basis: geometry, the harmonics texture and the two materials. */
export class Deformer {
  readonly geometry: THREE.BufferGeometry;
  readonly texture: THREE.DataTexture;
  readonly gpuMaterial: THREE.ShaderMaterial;
  readonly cpuMaterial: THREE.ShaderMaterial;
  readonly mesh: THREE.Mesh;
  readonly scene = new THREE.Scene();
  readonly ortho = new THREE.OrthographicCamera(-1, 1, 1, -1, 0, 1);
  /** tiles per positions pass (colour attachments, uniform space) */
  readonly batch: number;
  private single: PositionsPass | null = null;
  private batched: PositionsPass | null = null;
  useCPU = false;

  constructor(readonly basis: Basis, readonly renderer: THREE.WebGLRenderer, maxBatch = 8) {
    const gl = renderer.getContext();
    const maxSize = gl.getParameter(gl.MAX_TEXTURE_SIZE) as number;
    const texels = basis.n * basis.k4;
    const width = Math.min(maxSize, 4096, texels);
    const height = Math.ceil(texels / width);
    if (height > maxSize) throw new Error(`basis too large for a ${maxSize}² texture`);
    const data = new Float32Array(width * height * 4);
    data.set(basis.harmonics);
    this.texture = new THREE.DataTexture(data, width, height, THREE.RGBAFormat, THREE.FloatType);
    this.texture.internalFormat = "RGBA32F";
    this.texture.minFilter = this.texture.magFilter = THREE.NearestFilter;
    this.texture.generateMipmaps = false;
    this.texture.needsUpdate = true;

    this.geometry = new THREE.BufferGeometry();
    this.geometry.setAttribute("position", new THREE.BufferAttribute(basis.vertices, 3));
    this.geometry.setIndex(new THREE.BufferAttribute(basis.faces, 1));
    this.geometry.computeVertexNormals();
    const ids = new Float32Array(basis.n).map((_, i) => i);
    this.geometry.setAttribute("vid", new THREE.BufferAttribute(ids, 1));
    const displaced = new THREE.BufferAttribute(new Float32Array(basis.vertices), 3);
    displaced.setUsage(THREE.DynamicDrawUsage);
    this.geometry.setAttribute("displaced", displaced);

    const defines = { K4: basis.k4 };
    const uniforms = () => ({
      harmonics: { value: this.texture }, texWidth: { value: width },
      colorHarmonic: { value: -1 }, colorScale: { value: 1 },
      baseColor: { value: new THREE.Color(TILE_COLORS[0]) }, normalBlend: { value: 0.4 },
      wire: { value: false },
    });
    const make = (extra: Record<string, any>) => new THREE.ShaderMaterial({
      glslVersion: THREE.GLSL3, defines: { ...defines, ...extra }, uniforms: uniforms(),
      vertexShader: TEXELS + SURFACE_VERTEX, fragmentShader: SURFACE_FRAGMENT,
      side: THREE.DoubleSide,
    });
    this.gpuMaterial = make({});
    this.cpuMaterial = make({ CPU_PATH: 1 });
    this.gpuMaterial.uniforms.deformed = { value: null };
    this.gpuMaterial.uniforms.deformedWidth = { value: Math.min(basis.n, 1024) };
    const vectors = gl.getParameter(gl.MAX_VERTEX_UNIFORM_VECTORS) as number;
    const buffers = gl.getParameter((gl as WebGL2RenderingContext).MAX_DRAW_BUFFERS) as number;
    // Up to 1024 uniform vectors of weights per pass: larger uniform arrays made SwiftShader
    // slower than one tile per pass (bunny k = 1000), smaller ones gain 1.3–1.6×.
    this.batch = Math.max(1, Math.min(maxBatch, buffers,
      Math.floor(Math.min(vectors - 32, 1024) / (3 * basis.k4))));
    this.mesh = new THREE.Mesh(this.geometry, this.gpuMaterial);
    this.mesh.frustumCulled = false;
    this.scene.add(this.mesh);
  }

  get material(): THREE.ShaderMaterial {
    return this.useCPU ? this.cpuMaterial : this.gpuMaterial;
  }

  /** Set one tile's look and deformation before `renderer.render(scene, camera)`. */
  setTile(weights: Float32Array, cpuPositions: Float32Array | null, options: {
    color: number; normalBlend: number; wireframe: boolean; harmonic: number; harmonicScale: number;
  }, positions: THREE.Texture | null = null): void {
    const material = this.material;
    this.mesh.material = material;
    const u = material.uniforms;
    (u.baseColor.value as THREE.Color).setHex(options.color);
    u.normalBlend.value = options.normalBlend;
    u.colorHarmonic.value = options.harmonic;
    u.colorScale.value = options.harmonicScale;
    u.wire.value = options.wireframe;
    material.wireframe = options.wireframe;
    material.uniformsNeedUpdate = true;
    if (!this.useCPU) u.deformed.value = positions ?? this.computePositions([weights])[0];
    if (this.useCPU && cpuPositions) {
      const attribute = this.geometry.getAttribute("displaced") as THREE.BufferAttribute;
      (attribute.array as Float32Array).set(cpuPositions);
      attribute.needsUpdate = true;
    }
  }

  /** GPU pass 1: deformed positions of every tile into float render targets, `batch` tiles per
   * pass (one harmonic fetch serves them all); returns one positions texture per tile. */
  computePositions(weights: Float32Array[]): THREE.Texture[] {
    if (weights.length === 1) {
      this.single ??= new PositionsPass(this, 1);
      return this.single.run(weights);
    }
    this.batched ??= new PositionsPass(this, this.batch);
    const textures: THREE.Texture[] = [];
    for (let start = 0, index = 0; start < weights.length; start += this.batch, index++) {
      textures.push(...this.batched.run(weights.slice(start, start + this.batch), index));
    }
    return textures;
  }

  /** Positions (n*3, normalised) computed by the GPU shader and read back from the float target.
   * With several weights, tile `tile` of a batched pass over all of them is read. */
  readPositions(weights: Float32Array[], tile = 0): Float32Array {
    this.computePositions(weights);
    if (weights.length === 1) return this.single!.read(0);
    return this.batched!.read(tile % this.batch, Math.floor(tile / this.batch));
  }

  /** Largest |U[:, ν]| for the harmonics explorer's colour scale. */
  harmonicScale(index: number): number {
    const { n, k4, harmonics } = this.basis;
    let largest = 0;
    for (let i = 0; i < n; i++) largest = Math.max(largest, Math.abs(harmonics[i * 4 * k4 + index]));
    return largest > 0 ? 1 / largest : 1;
  }

  dispose(): void {
    this.geometry.dispose();
    this.texture.dispose();
    this.gpuMaterial.dispose();
    this.cpuMaterial.dispose();
    this.single?.dispose();
    this.batched?.dispose();
  }
}
