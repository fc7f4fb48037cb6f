// A model's own look in the page (docs/design.md#appearance, docs/web.md#appearance-bundle): its
// drawn vertices — split at UV seams, hard edges and materials — each following its welded
// vertex's deformed position (`vid` is the welded vertex), one three.js group per material drawn
// by the surface shader shared with the video (shaders.ts), with the defines, uniforms and
// textures the server's rule (eigendance.shaders.programs.material_shading) gives each material.
import * as THREE from "three";
import * as api from "./api";
import type { Basis } from "./bundle";
import { parseBundle } from "./bundle";
import { DETAIL_ERROR, simplifierReady, trianglesTouching } from "./detail";
import { MeshoptSimplifier } from "meshoptimizer";
import { gatherAttributes } from "./reduced";
import { SURFACE_FRAGMENT, SURFACE_VERTEX } from "./shaders";

/** How the shared surface shader draws one material (`material_shading`). */
export interface Shading {
  defines: Record<string, number | string>;
  uniforms: Record<string, number | number[]>;
  textures: Record<string, { image: number; srgb: boolean; sampler: Record<string, number> }>;
  blend: boolean;
  doubleSided: boolean;
}

/** A model's look as the appearance bundle sends it, its images decoded. */
export interface Appearance {
  name: string;
  /** drawn vertices */
  drawn: number;
  /** (drawn,) each drawn vertex's welded vertex (an index of the basis or rig bundle) */
  welded: Uint32Array;
  normals: Float32Array; // drawn*3, unit, rest
  uvs: Float32Array[]; // drawn*2 per UV set, glTF's convention
  colors: Float32Array | null; // drawn*4 linear RGBA
  parts: { material: number; triangles: Uint32Array }[];
  materials: { name: string; shading: Shading }[];
  images: ImageBitmap[];
}

/** The appearance of a mesh or a rig (kind "meshes" or "rigs"), its images decoded as three.js
 * GLTFLoader decodes them (ImageBitmap, no premultiplied alpha, no colour conversion). */
export async function loadAppearance(kind: "meshes" | "rigs", id: string): Promise<Appearance> {
  const response = await api.checked(await fetch(`api/${kind}/${id}/appearance.bin`));
  const { meta, arrays } = parseBundle(await response.arrayBuffer());
  if (meta.kind !== "appearance") throw new Error("not an appearance bundle");
  const f = (name: string) => arrays[name].data as Float32Array;
  const images = await Promise.all(meta.images.map((image: { mimeType: string }, i: number) =>
    createImageBitmap(new Blob([arrays[`image${i}`].data as Uint8Array], { type: image.mimeType }),
      { premultiplyAlpha: "none", colorSpaceConversion: "none" })));
  return {
    name: meta.name, drawn: meta.drawn, welded: arrays.welded.data as Uint32Array,
    normals: f("normals"), uvs: Array.from({ length: meta.uvSets }, (_, i) => f(`uv${i}`)),
    colors: meta.colors ? f("colors") : null,
    parts: meta.parts.map((part: { material: number }, p: number) => ({
      material: part.material, triangles: arrays[`triangles${p}`].data as Uint32Array })),
    materials: meta.materials, images,
  };
}

const FILTERS: Record<number, THREE.MagnificationTextureFilter | THREE.MinificationTextureFilter> = {
  9728: THREE.NearestFilter, 9729: THREE.LinearFilter,
  9984: THREE.NearestMipmapNearestFilter, 9985: THREE.LinearMipmapNearestFilter,
  9986: THREE.NearestMipmapLinearFilter, 9987: THREE.LinearMipmapLinearFilter };
const WRAPS: Record<number, THREE.Wrapping> = { 33071: THREE.ClampToEdgeWrapping,
  33648: THREE.MirroredRepeatWrapping, 10497: THREE.RepeatWrapping };

/** A uniform's value from the rule's number or list (9 numbers: a column-major mat3). */
function uniformValue(value: number | number[]): unknown {
  if (!Array.isArray(value)) return value;
  if (value.length === 9) return new THREE.Matrix3().fromArray(value);
  if (value.length === 4) return new THREE.Vector4().fromArray(value);
  if (value.length === 3) return new THREE.Vector3().fromArray(value);
  return new THREE.Vector2().fromArray(value);
}

/** The drawn mesh of a model with materials, for one Deformer (its renderer and positions). */
export class DrawnLook {
  readonly geometry: THREE.BufferGeometry;
  readonly mesh: THREE.Mesh;
  private readonly gpuMaterials: THREE.ShaderMaterial[];
  private readonly cpuMaterials: THREE.ShaderMaterial[];
  private readonly textures = new Map<string, THREE.Texture>();
  /** uniforms every material shares (the same objects): the tile's positions and normals */
  private readonly shared: Record<string, THREE.IUniform>;
  /** each detail level's triangles (all parts, one after the other) and each part's count */
  private readonly detail = new Map<number, { index: THREE.BufferAttribute; counts: number[] }>();
  private readonly only = new WeakMap<Uint8Array, { index: THREE.BufferAttribute; counts: number[] }>();
  /** REDUCED for a reduced basis: each drawn vertex gathers its welded vertex's samples */
  private readonly reduced: Record<string, number>;

  constructor(readonly appearance: Appearance, basis: Basis, deformedWidth: number) {
    this.geometry = this.drawnGeometry(basis.vertices);
    this.geometry.setAttribute("vid", new THREE.BufferAttribute(
      Float32Array.from(appearance.welded), 1));
    const displaced = new THREE.BufferAttribute(
      new Float32Array(this.geometry.getAttribute("position").array), 3);
    displaced.setUsage(THREE.DynamicDrawUsage);
    this.geometry.setAttribute("displaced", displaced);
    this.reduced = basis.reduced ? { REDUCED: 1 } : {};
    if (basis.reduced) {
      for (const [name, attribute] of Object.entries(gatherAttributes(basis.reduced,
        appearance.welded))) this.geometry.setAttribute(name, attribute);
    }
    this.useDetail(1);
    this.shared = { deformed: { value: null }, deformedWidth: { value: deformedWidth },
      deformedNormalWeight: { value: 0.4 }, wire: { value: false } };
    this.gpuMaterials = appearance.parts.map((part) => this.material(part.material,
      this.reduced));
    this.cpuMaterials = appearance.parts.map((part) => this.material(part.material,
      { CPU_PATH: 1 }));
    this.mesh = new THREE.Mesh(this.geometry, this.gpuMaterials);
    this.mesh.frustumCulled = false;
  }

  /** The drawn vertices at rest (`vertices` n*3 of the welded ones gathered), their normals,
   * UVs and colours, and the parts' triangles as groups; `extra` welded attributes (name:
   * [values, item size]) gathered too. */
  drawnGeometry(vertices: ArrayLike<number>,
                extra: Record<string, [ArrayLike<number>, number]> = {}): THREE.BufferGeometry {
    const { appearance } = this;
    const geometry = new THREE.BufferGeometry();
    for (const [name, [values, size]] of Object.entries({ position: [vertices, 3], ...extra })) {
      geometry.setAttribute(name, new THREE.BufferAttribute(
        this.gathered(values as ArrayLike<number>, size as number), size as number));
    }
    geometry.setAttribute("normal", new THREE.BufferAttribute(appearance.normals, 3));
    geometry.setAttribute("texcoord0", new THREE.BufferAttribute(appearance.uvs[0]
      ?? new Float32Array(appearance.drawn * 2), 2));
    if (appearance.uvs[1]) geometry.setAttribute("texcoord1",
      new THREE.BufferAttribute(appearance.uvs[1], 2));
    if (appearance.colors) geometry.setAttribute("vertexColor",
      new THREE.BufferAttribute(appearance.colors, 4));
    const level = this.triangles(1, geometry.getAttribute("position").array as Float32Array);
    geometry.setIndex(level.index);
    let start = 0;
    level.counts.forEach((count, part) => { geometry.addGroup(start, count, part); start += count; });
    return geometry;
  }

  /** The parts' materials on another vertex stage (`vertexShader`, a three.js ShaderMaterial
   * with its chunks: a rig's LBS skin), sharing this look's textures. */
  materialsWith(vertexShader: string): THREE.ShaderMaterial[] {
    return this.appearance.parts.map((part) => this.material(part.material, {}, vertexShader));
  }

  /** Per drawn vertex, its welded vertex's `size` values. */
  gathered(values: ArrayLike<number>, size: number): Float32Array {
    const welded = this.appearance.welded, out = new Float32Array(welded.length * size);
    for (let i = 0; i < welded.length; i++) {
      for (let d = 0; d < size; d++) out[size * i + d] = values[size * welded[i] + d];
    }
    return out;
  }

  /** Before drawing a tile: its positions (GPU: the positions pass's texture of the welded
   * vertices, or of a reduced basis's samples; CPU: the welded positions n*3, gathered here) and the flat normal's weight. */
  setTile(positions: THREE.Texture | null, cpu: Float32Array | null, normalWeight: number):
      void {
    this.mesh.material = cpu ? this.cpuMaterials : this.gpuMaterials;
    this.shared.deformed.value = positions;
    this.shared.deformedNormalWeight.value = normalWeight;
    if (cpu) {
      const attribute = this.geometry.getAttribute("displaced") as THREE.BufferAttribute;
      const out = attribute.array as Float32Array, welded = this.appearance.welded;
      for (let i = 0; i < welded.length; i++) {
        const w = 3 * welded[i];
        out[3 * i] = cpu[w]; out[3 * i + 1] = cpu[w + 1]; out[3 * i + 2] = cpu[w + 2];
      }
      attribute.needsUpdate = true;
    }
    for (const material of this.mesh.material as THREE.ShaderMaterial[]) {
      material.uniformsNeedUpdate = true;
    }
  }

  /** Draw about `fraction` of each material's triangles (the gallery's level of detail,
   * detail.ts); borders kept (UV seams, material edges: no cracks). */
  useDetail(fraction: number): void {
    let level = this.detail.get(fraction);
    if (!level) {
      if (fraction < 1 && !simplifierReady()) return this.useDetail(1);
      level = this.triangles(fraction, this.geometry.getAttribute("position").array as
        Float32Array);
      this.detail.set(fraction, level);
    }
    this.useLevel(level);
  }

  /** Draw only the triangles with a vertex whose welded vertex is 1 in `mask` (a close-up's:
   * `Deformer.drawOnly`), of every part, at full detail. */
  drawOnly(mask: Uint8Array): void {
    let level = this.only.get(mask);
    if (!level) {
      const full = this.detail.get(1)!, index = full.index.array as Uint32Array;
      const parts: Uint32Array[] = [];
      let start = 0;
      for (const count of full.counts) {
        parts.push(trianglesTouching(index.subarray(start, start + count), mask,
          this.appearance.welded));
        start += count;
      }
      const all = new Uint32Array(parts.reduce((total, part) => total + part.length, 0));
      parts.reduce((at, part) => { all.set(part, at); return at + part.length; }, 0);
      level = { index: new THREE.BufferAttribute(all, 1), counts: parts.map((part) => part.length) };
      this.only.set(mask, level);
    }
    this.useLevel(level);
  }

  private useLevel(level: { index: THREE.BufferAttribute; counts: number[] }): void {
    if (this.geometry.index === level.index) return;
    this.geometry.setIndex(level.index);
    this.geometry.clearGroups();
    let start = 0;
    level.counts.forEach((count, part) => {
      this.geometry.addGroup(start, count, part);
      start += count;
    });
  }

  dispose(): void {
    this.geometry.dispose();
    for (const material of [...this.gpuMaterials, ...this.cpuMaterials]) material.dispose();
    for (const texture of this.textures.values()) texture.dispose();
  }

  /** Every part's triangles one after the other, about `fraction` of them each. */
  private triangles(fraction: number, position: Float32Array):
      { index: THREE.BufferAttribute; counts: number[] } {
    const attributes = fraction < 1 ? surfaceAttributes(this.appearance) : null;
    const parts = this.appearance.parts.map((part) => {
      if (!attributes || part.triangles.length < 300) return part.triangles;
      const target = Math.max(3, 3 * Math.floor((part.triangles.length / 3) * fraction));
      // Positions alone let a collapse slide a vertex across the texture (a textured model
      // looked speckled at 25%): the UVs and normals count in the error too.
      const [simplified] = MeshoptSimplifier.simplifyWithAttributes(
        Uint32Array.from(part.triangles), position, 3, attributes, ATTRIBUTES,
        ATTRIBUTE_WEIGHTS, null, target, DETAIL_ERROR, ["LockBorder"]);
      return simplified.length >= 3 ? simplified : part.triangles;
    });
    const all = new Uint32Array(parts.reduce((sum, t) => sum + t.length, 0));
    let at = 0;
    for (const triangles of parts) { all.set(triangles, at); at += triangles.length; }
    return { index: new THREE.BufferAttribute(all, 1), counts: parts.map((t) => t.length) };
  }

  /** The material of glTF material `index`: the shared surface shader (a RawShaderMaterial;
   * `defines` CPU_PATH for the CPU path), or a three.js ShaderMaterial of `vertexShader`. */
  private material(index: number, defines: Record<string, number>, vertexShader?: string):
      THREE.ShaderMaterial {
    const shading = this.appearance.materials[index].shading;
    const uniforms: Record<string, THREE.IUniform> = { ...this.shared };
    for (const [name, value] of Object.entries(shading.uniforms)) {
      uniforms[name] = { value: uniformValue(value) };
    }
    for (const [name, info] of Object.entries(shading.textures)) {
      uniforms[name] = { value: this.texture(info.image, info.srgb, info.sampler) };
    }
    const Material = vertexShader ? THREE.ShaderMaterial : THREE.RawShaderMaterial;
    return new Material({
      glslVersion: THREE.GLSL3, vertexShader: vertexShader ?? SURFACE_VERTEX,
      fragmentShader: SURFACE_FRAGMENT, defines: { ...shading.defines, ...defines }, uniforms,
      side: shading.doubleSided ? THREE.DoubleSide : THREE.FrontSide,
      transparent: shading.blend, depthWrite: !shading.blend,
    });
  }

  /** Image `image` as a texture (one per colour space and sampler), as GLTFLoader makes it. */
  private texture(image: number, srgb: boolean, sampler: Record<string, number>): THREE.Texture {
    const key = `${image} ${srgb} ${JSON.stringify(sampler)}`;
    let texture = this.textures.get(key);
    if (!texture) {
      texture = new THREE.Texture(this.appearance.images[image]);
      texture.flipY = false; // glTF's UV origin is the image's top left
      texture.colorSpace = srgb ? THREE.SRGBColorSpace : THREE.NoColorSpace;
      texture.magFilter = FILTERS[sampler.magFilter] as THREE.MagnificationTextureFilter;
      texture.minFilter = FILTERS[sampler.minFilter] as THREE.MinificationTextureFilter;
      texture.generateMipmaps = sampler.minFilter >= 9984;
      texture.wrapS = WRAPS[sampler.wrapS];
      texture.wrapT = WRAPS[sampler.wrapT];
      texture.needsUpdate = true;
      this.textures.set(key, texture);
    }
    return texture;
  }
}

/** Per drawn vertex for the simplifier: its first UV and its normal (ATTRIBUTES floats). */
const ATTRIBUTES = 5;
/** UVs weigh as positions relative to the model's extent (a 2% slide over the texture costs as a
 * 2% move); normals half (meshoptimizer's suggestion). */
const ATTRIBUTE_WEIGHTS = [1, 1, 0.5, 0.5, 0.5];

function surfaceAttributes(appearance: Appearance): Float32Array {
  const uv = appearance.uvs[0], normals = appearance.normals;
  const out = new Float32Array(appearance.drawn * ATTRIBUTES);
  for (let i = 0; i < appearance.drawn; i++) {
    if (uv) { out[ATTRIBUTES * i] = uv[2 * i]; out[ATTRIBUTES * i + 1] = uv[2 * i + 1]; }
    for (let d = 0; d < 3; d++) out[ATTRIBUTES * i + 2 + d] = normals[3 * i + d];
  }
  return out;
}
