// GPU pass 1 of the deformation (docs/design.md#rendering): the deformed positions X + U((φ − 1) ⊙ X̃) of up
// to `tiles` gallery tiles at once, drawn as one point per vertex into float render targets (one
// colour attachment per tile), so one harmonic fetch serves every tile of the batch.
import * as THREE from "three";
import type { Basis } from "./bundle";
import { TEXELS, positionsShaders } from "./shaders";

/** Width of the positions targets: vertex v is pixel (v mod width, v div width). */
export const TARGET_WIDTH = 1024;

/** What a positions pass reads from the mesh being deformed (a `Deformer`). */
export interface HarmonicsSource {
  readonly basis: Basis;
  readonly renderer: THREE.WebGLRenderer;
  /** the harmonics, four per RGBA32F texel */
  readonly texture: THREE.DataTexture;
  readonly textureWidth: number;
  /** the rest positions (`position`) and vertex ids (`vid`) */
  readonly geometry: THREE.BufferGeometry;
}

export class PositionsPass {
  readonly material: THREE.ShaderMaterial;
  readonly scene = new THREE.Scene();
  readonly targets: THREE.WebGLRenderTarget[] = [];
  readonly width: number;
  readonly height: number;
  private readonly camera = new THREE.OrthographicCamera(-1, 1, 1, -1, 0, 1);

  constructor(readonly source: HarmonicsSource, readonly tiles: number) {
    const { basis } = source;
    this.width = Math.min(basis.n, TARGET_WIDTH);
    this.height = Math.ceil(basis.n / this.width);
    const shaders = positionsShaders(tiles);
    this.material = new THREE.ShaderMaterial({
      glslVersion: THREE.GLSL3,
      defines: { K4: basis.k4, WEIGHTS: 3 * basis.k4 * tiles, TILES: tiles },
      uniforms: {
        harmonics: { value: source.texture },
        texWidth: { value: source.textureWidth },
        weights: { value: new Float32Array(12 * basis.k4 * tiles) },
        targetWidth: { value: this.width },
        targetSize: { value: new THREE.Vector2(this.width, this.height) },
      },
      vertexShader: TEXELS + shaders.vertex, fragmentShader: shaders.fragment,
      depthTest: false, depthWrite: false,
    });
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute("position", source.geometry.getAttribute("position"));
    geometry.setAttribute("vid", source.geometry.getAttribute("vid"));
    const points = new THREE.Points(geometry, this.material);
    points.frustumCulled = false;
    this.scene.add(points);
  }

  /** Render target `index`, made on first use (a gallery needs ⌈S / tiles⌉ of them). */
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
    const renderer = this.source.renderer;
    const previous = renderer.getRenderTarget();
    const scissor = renderer.getScissorTest();
    renderer.setScissorTest(false);
    renderer.setRenderTarget(target);
    renderer.render(this.scene, this.camera);
    renderer.setRenderTarget(previous);
    renderer.setScissorTest(scissor);
    return target.textures.slice(0, weights.length);
  }

  /** Read tile `tile`'s positions (n*3) back from target `index`. */
  read(tile: number, index = 0): Float32Array {
    const renderer = this.source.renderer;
    const gl = renderer.getContext() as WebGL2RenderingContext;
    const target = this.target(index);
    const pixels = new Float32Array(this.width * this.height * 4);
    const previous = renderer.getRenderTarget();
    renderer.setRenderTarget(target);
    gl.readBuffer(gl.COLOR_ATTACHMENT0 + tile);
    gl.readPixels(0, 0, this.width, this.height, gl.RGBA, gl.FLOAT, pixels);
    gl.readBuffer(gl.COLOR_ATTACHMENT0);
    renderer.setRenderTarget(previous);
    const n = this.source.basis.n;
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
