// GPU deformation (docs/design.md#rendering): U packed four harmonics per RGBA32F texel in a float texture,
// per tile only the k filter values change, uploaded as a uniform array of weights
// (φ − 1) ⊙ X̃ (see filter.ts shaderWeights). A CPU path gives the same numbers.
// The GLSL is in shaders.ts, the batched positions pass in positions-pass.ts. A reduced basis
// (reduced.ts) runs the positions pass over its samples and gathers in the surface pass (the
// REDUCED define of the shared surface shader). A model with materials is drawn by its
// DrawnLook (look.ts) from the same positions.
import * as THREE from "three";
import { harmonicRows } from "./bundle";
import type { Basis } from "./bundle";
import { simplifiedFaces, trianglesTouching } from "./detail";
import { DrawnLook } from "./look";
import type { Appearance } from "./look";
import { PositionsPass, TARGET_WIDTH } from "./positions-pass";
import type { HarmonicsSource } from "./positions-pass";
import { GatherPass, gatherAttributes, reducedHarmonic, sampleGeometry } from "./reduced";
import { SURFACE_FRAGMENT, SURFACE_VERTEX, TEXELS } from "./shaders";

/** The models' colour (sRGB): one studio clay for every tile and the player, so tiles differ
 * by how they move, not by their paint. */
export const CLAY = 0xd9a47f;

/** The largest k whose weights fit the vertex shader's uniform vectors (3 per 4 harmonics). */
export function maxHarmonicsOnGPU(renderer: THREE.WebGLRenderer): number {
  const gl = renderer.getContext();
  const vectors = gl.getParameter(gl.MAX_VERTEX_UNIFORM_VECTORS) as number;
  return 4 * Math.floor((vectors - 32) / 3);
}

/** How one tile or the player is drawn (`Deformer.setTile`). */
export interface TileLook {
  color: number;
  /** weight of the deformed triangle's flat normal (thesis Fig. 6.4(d)) */
  deformedNormalWeight: number;
  wireframe: boolean;
  /** the harmonics explorer's harmonic (−1: off) and colour scale */
  harmonic: number;
  harmonicScale: number;
  /** in the model's materials (when it has them), else clay */
  materials: boolean;
}

/** Everything drawn for one basis: geometry, the harmonics texture, the two clay materials
 * and, for a model with materials, its drawn look. */
export class Deformer implements HarmonicsSource {
  readonly geometry: THREE.BufferGeometry;
  readonly texture: THREE.DataTexture;
  readonly gpuMaterial: THREE.RawShaderMaterial;
  readonly cpuMaterial: THREE.RawShaderMaterial;
  readonly mesh: THREE.Mesh;
  /** the model's own look (materials, textures), or null: clay */
  look: DrawnLook | null = null;
  /** whether the surface is drawn at all (a rig's LBS skin replaces it) */
  shown = true;
  readonly scene = new THREE.Scene();
  readonly textureWidth: number;
  /** tiles per positions pass (colour attachments, uniform space) */
  readonly batch: number;
  private single: PositionsPass | null = null;
  private batched: PositionsPass | null = null;
  /** a reduced basis: what the positions pass runs over (the samples), and the read-back gather */
  private readonly samples: HarmonicsSource | null = null;
  private gather: GatherPass | null = null;
  /** the triangles of each detail level drawn so far (detail.ts); 1 is the mesh's own */
  private readonly detailIndex = new Map<number, THREE.BufferAttribute>();
  /** the detail level drawn (`useDetail`), and the triangles of each close-up (`drawOnly`) */
  private detail = 1;
  private readonly partIndex = new WeakMap<Uint8Array, THREE.BufferAttribute>();
  useCPU = false;

  constructor(readonly basis: Basis, readonly renderer: THREE.WebGLRenderer, maxBatch = 8) {
    const gl = renderer.getContext();
    const maxSize = gl.getParameter(gl.MAX_TEXTURE_SIZE) as number;
    const texels = harmonicRows(basis) * basis.k4;
    const width = Math.min(maxSize, 4096, texels);
    const height = Math.ceil(texels / width);
    this.textureWidth = width;
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
    this.detailIndex.set(1, this.geometry.index!);
    this.geometry.computeVertexNormals();
    const ids = new Float32Array(basis.n).map((_, i) => i);
    this.geometry.setAttribute("vid", new THREE.BufferAttribute(ids, 1));
    const displaced = new THREE.BufferAttribute(new Float32Array(basis.vertices), 3);
    displaced.setUsage(THREE.DynamicDrawUsage);
    this.geometry.setAttribute("displaced", displaced);
    if (basis.reduced) {
      for (const [name, attribute] of Object.entries(gatherAttributes(basis.reduced))) {
        this.geometry.setAttribute(name, attribute);
      }
      this.samples = { basis: { ...basis, n: basis.reduced.m }, renderer, texture: this.texture,
        textureWidth: width, geometry: sampleGeometry(basis.reduced.m) };
    }

    const defines: Record<string, number> = basis.reduced
      ? { K4: basis.k4, HARMONICS: 1, REDUCED: 1 } : { K4: basis.k4, HARMONICS: 1 };
    const uniforms = () => ({
      harmonics: { value: this.texture }, texWidth: { value: width },
      colorHarmonic: { value: -1 }, colorScale: { value: 1 },
      baseColor: { value: new THREE.Color(CLAY) }, deformedNormalWeight: { value: 0.4 },
      wire: { value: false },
    });
    const make = (extra: Record<string, any>) => new THREE.RawShaderMaterial({
      glslVersion: THREE.GLSL3, defines: { ...defines, ...extra }, uniforms: uniforms(),
      vertexShader: TEXELS + SURFACE_VERTEX, fragmentShader: SURFACE_FRAGMENT,
      side: THREE.DoubleSide,
    });
    this.gpuMaterial = make({});
    this.cpuMaterial = make({ CPU_PATH: 1 });
    this.gpuMaterial.uniforms.deformed = { value: null };
    this.gpuMaterial.uniforms.deformedWidth = { value: Math.min(harmonicRows(basis),
      TARGET_WIDTH) };
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

  get material(): THREE.RawShaderMaterial {
    return this.useCPU ? this.cpuMaterial : this.gpuMaterial;
  }

  /** Draw the model in its own look from now on (null: clay only). */
  setLook(appearance: Appearance | null): void {
    if (this.look) {
      this.scene.remove(this.look.mesh);
      this.look.dispose();
    }
    this.look = appearance ? new DrawnLook(appearance, this.basis,
      this.gpuMaterial.uniforms.deformedWidth.value) : null;
    if (this.look) this.scene.add(this.look.mesh);
  }

  /** Set one tile's look and deformation before `renderer.render(scene, camera)`: in the
   * model's materials when asked and it has them (not for a wireframe or the explorer). */
  setTile(weights: Float32Array, cpuPositions: Float32Array | null, options: TileLook,
          positions: THREE.Texture | null = null): void {
    const look = options.materials && !options.wireframe && options.harmonic < 0 ? this.look
      : null;
    this.mesh.visible = this.shown && !look;
    if (look) {
      look.mesh.visible = this.shown;
      const texture = this.useCPU ? null : positions ?? this.computePositions([weights])[0];
      look.setTile(texture, this.useCPU ? cpuPositions : null, options.deformedNormalWeight);
      return;
    }
    if (this.look) this.look.mesh.visible = false;
    const material = this.material;
    this.mesh.material = material;
    const u = material.uniforms;
    (u.baseColor.value as THREE.Color).setHex(options.color, THREE.SRGBColorSpace);
    u.deformedNormalWeight.value = options.deformedNormalWeight;
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

  /** Draw about `fraction` of the triangles (the gallery's level of detail, detail.ts) over
   * the same vertices; all of them until the simplifier is loaded. Returns the fraction drawn. */
  useDetail(fraction: number): number {
    let index = this.detailIndex.get(fraction);
    if (!index) {
      const faces = simplifiedFaces(this.basis.faces, this.basis.vertices, fraction);
      if (!faces) return this.useDetail(1);
      index = new THREE.BufferAttribute(faces, 1);
      this.detailIndex.set(fraction, index);
    }
    if (this.geometry.index !== index) this.geometry.setIndex(index);
    this.look?.useDetail(fraction);
    this.detail = fraction;
    return fraction;
  }

  /** Draw only the mesh's triangles with a vertex where `mask` (n) is 1 (a close-up's,
   * close-up.ts), all of them there; null: the detail level's triangles again. */
  drawOnly(mask: Uint8Array | null): void {
    if (!mask) { this.useDetail(this.detail); return; }
    let index = this.partIndex.get(mask);
    if (!index) {
      index = new THREE.BufferAttribute(trianglesTouching(this.basis.faces, mask), 1);
      this.partIndex.set(mask, index);
    }
    this.geometry.setIndex(index);
    this.look?.drawOnly(mask);
  }

  /** GPU pass 1: deformed positions of every tile into float render targets, `batch` tiles per
   * pass (one harmonic fetch serves them all); returns one positions texture per tile. A
   * reduced basis: the displacements of its samples (the surface pass gathers them). */
  computePositions(weights: Float32Array[]): THREE.Texture[] {
    const source = this.samples ?? this;
    if (weights.length === 1) {
      this.single ??= new PositionsPass(source, 1);
      return this.single.run(weights);
    }
    this.batched ??= new PositionsPass(source, this.batch);
    const textures: THREE.Texture[] = [];
    for (let start = 0, index = 0; start < weights.length; start += this.batch, index++) {
      textures.push(...this.batched.run(weights.slice(start, start + this.batch), index));
    }
    return textures;
  }

  /** Positions (n*3, normalised) computed by the GPU shader and read back from the float target.
   * With several weights, tile `tile` of a batched pass over all of them is read. */
  readPositions(weights: Float32Array[], tile = 0): Float32Array {
    const textures = this.computePositions(weights);
    if (this.samples) return this.gathered(textures[tile]);
    if (weights.length === 1) return this.single!.read(0);
    return this.batched!.read(tile % this.batch, Math.floor(tile / this.batch));
  }

  /** Positions of every model of `weights` from one batched computation, as drawn. */
  readAll(weights: Float32Array[]): Float32Array[] {
    if (weights.length === 1) return [this.readPositions(weights)];
    const textures = this.computePositions(weights);
    if (this.samples) return textures.map((texture) => this.gathered(texture));
    return weights.map((_, tile) => this.batched!.read(tile % this.batch,
      Math.floor(tile / this.batch)));
  }

  /** A reduced basis: the surface pass's gather of one tile, read back (n*3). */
  private gathered(displacements: THREE.Texture): Float32Array {
    this.gather ??= new GatherPass(this.geometry, this.basis.n, TARGET_WIDTH,
      Math.min(harmonicRows(this.basis), TARGET_WIDTH), this.texture, this.textureWidth,
      this.basis.k4);
    return this.gather.read(this.renderer, displacements);
  }

  /** Largest |U[:, ν]| for the harmonics explorer's colour scale. */
  harmonicScale(index: number): number {
    const { n, k4, harmonics } = this.basis;
    const values = this.basis.reduced ? reducedHarmonic(this.basis, index) : null;
    let largest = 0;
    for (let i = 0; i < n; i++) {
      largest = Math.max(largest, Math.abs(values ? values[i] : harmonics[i * 4 * k4 + index]));
    }
    return largest > 0 ? 1 / largest : 1;
  }

  dispose(): void {
    this.geometry.dispose();
    this.texture.dispose();
    this.gpuMaterial.dispose();
    this.cpuMaterial.dispose();
    this.look?.dispose();
    this.single?.dispose();
    this.batched?.dispose();
    this.samples?.geometry.dispose();
    this.gather?.dispose();
  }
}
