// The Viewer owns the WebGL canvas: renderer, cameras, the render loop, drawing the gallery's
// tiles or the player into their viewports, frame timing, and the choice of deformation path
// (docs/design.md#rendering). What to draw comes from the views through `Stage`; time from a `Clock`.
import * as THREE from "three";
import { OrbitControls } from "three/examples/jsm/controls/OrbitControls.js";
import type { Basis } from "./bundle";
import { Deformer, TILE_COLORS, maxHarmonicsOnGPU } from "./deform";
import { deformCPU } from "./filter";
import type { Prepared } from "./filter";
import type { Motion } from "./motion";
import type { Clock } from "./transport";

export type View = "gallery" | "player";
export type DeformationPath = "gpu" | "cpu";

/** How surfaces are shaded (the player's controls; shading applies to the gallery too). */
export interface Look {
  shading: "smooth" | "flat" | "wireframe";
  /** weight of the original vertex normal against the deformed triangle's flat normal */
  normalBlend: number;
  /** harmonics explorer: colour the player's mesh by this eigenvector (−1: off) */
  harmonic: number;
  harmonicScale: number;
}

/** One mesh to draw: where on the page, with which mapping, in which tile colour. */
export interface Shot { element: HTMLElement; prepared: Prepared; colorIndex: number; }

/** What the current frame shows. */
export interface Stage { view: View; tiles: Shot[]; player: Shot | null; look: Look; }

const BACKGROUND = 0x15171c;

export class Viewer {
  readonly renderer: THREE.WebGLRenderer;
  deformer: Deformer | null = null;
  path: DeformationPath = "gpu";
  /** smoothed draw time of one frame (ms) */
  frameMs = 0;
  /** Called after every frame with its time and band values (spectrum strip, seek bar). */
  onFrame: (t: number, bandValues: Float32Array) => void = () => {};

  private readonly tileCamera = new THREE.PerspectiveCamera(32, 1, 0.1, 50);
  private readonly playerCamera = new THREE.PerspectiveCamera(35, 1, 0.05, 50);
  private readonly controls: OrbitControls;
  /** a time set by `pin` (offline rendering, tests) instead of the clock's */
  private pinned: number | null = null;
  private drawRequested = false;
  private cpuPositions: Float32Array | null = null;

  constructor(canvas: HTMLCanvasElement, playerArea: HTMLElement, private readonly motion: Motion,
              private readonly clock: Clock, private readonly stage: () => Stage) {
    this.renderer = new THREE.WebGLRenderer({ canvas, antialias: false,
      preserveDrawingBuffer: true, powerPreference: "high-performance" });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
    this.renderer.autoClear = false;
    this.controls = new OrbitControls(this.playerCamera, playerArea);
    this.controls.enableDamping = false;
    this.controls.addEventListener("change", () => this.requestDraw());
  }

  /** Draw once more at the next animation frame (something other than time changed). */
  requestDraw(): void { this.drawRequested = true; }

  /** The time to draw: the pinned one, else the clock's. */
  time(): number { return this.pinned ?? this.clock.now(); }

  /** Draw at time t regardless of the clock, until `unpin`. */
  pin(t: number): void { this.pinned = t; }

  unpin(): void { this.pinned = null; this.requestDraw(); }

  /** Show a new mesh: its deformer (GPU resources) and cameras framing it. */
  setBasis(basis: Basis, batch: number): void {
    const deformer = new Deformer(basis, this.renderer, batch); // may throw: keep the old one
    this.deformer?.dispose();
    this.deformer = deformer;
    this.aimCameras(basis);
  }

  /** The render loop: a frame whenever the music plays or something asked for one. The end of
   * the song is handled here, not by the clock: stop and rewind to 0. */
  start(): void {
    const tick = () => {
      if (this.clock.ended()) {
        this.clock.rewind();
        this.requestDraw();
      }
      if ((this.clock.playing && this.pinned === null) || this.drawRequested) {
        this.drawRequested = false;
        this.draw(this.time());
      }
      requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
  }

  /** Draw the frame at time t (s) of whatever the stage shows. */
  draw(t: number): void {
    const deformer = this.deformer;
    if (!deformer || !this.motion.ready) return;
    const start = performance.now();
    this.resize();
    const stage = this.stage();
    const bandValues = this.motion.bandValuesAt(t);
    const renderer = this.renderer;
    renderer.setScissorTest(false);
    renderer.setClearColor(BACKGROUND, 1);
    renderer.clear();
    renderer.setScissorTest(true);
    if (stage.view === "gallery") {
      const weights = stage.tiles.map((shot) => this.motion.weights(shot.prepared, bandValues));
      // GPU path: every tile's positions first (batched passes), then the surfaces.
      const positions = deformer.useCPU ? null : deformer.computePositions(weights);
      stage.tiles.forEach((shot, index) => {
        this.drawShot(shot, this.tileCamera, weights[index], stage, positions?.[index] ?? null);
      });
    } else if (stage.player) {
      const weights = this.motion.weights(stage.player.prepared, bandValues);
      this.drawShot(stage.player, this.playerCamera, weights, stage, null);
    }
    renderer.setScissorTest(false);
    const elapsed = performance.now() - start;
    this.frameMs = this.frameMs ? 0.9 * this.frameMs + 0.1 * elapsed : elapsed;
    this.onFrame(t, bandValues);
  }

  /** Wait until the GPU has finished the frame (a 1-pixel read forces it). */
  finish(): void {
    const gl = this.renderer.getContext();
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
  }

  /** Pick the deformation path (docs/design.md#rendering): the CPU when k does not fit the shader's uniforms,
   * else the one `forced`, else the faster of the two timed on a few frames. */
  choosePath(forced: DeformationPath | null): void {
    const deformer = this.deformer!;
    if (deformer.basis.k > maxHarmonicsOnGPU(this.renderer)) {
      deformer.useCPU = true;
    } else if (forced) {
      deformer.useCPU = forced === "cpu";
    } else {
      const gpu = this.timeFrames(false), cpu = this.timeFrames(true);
      deformer.useCPU = cpu < gpu;
      console.info(`eigendance: GPU ${gpu.toFixed(1)} ms, CPU ${cpu.toFixed(1)} ms per frame`);
    }
    this.path = deformer.useCPU ? "cpu" : "gpu";
    this.frameMs = 0;
  }

  /** Use this path from now on (benchmarks compare both). */
  setPath(path: DeformationPath): void {
    this.deformer!.useCPU = path === "cpu";
    this.path = path;
  }

  /** A buffer for CPU positions (n*3), reused across frames. */
  cpuBuffer(): Float32Array {
    const n3 = this.deformer!.basis.n * 3;
    if (!this.cpuPositions || this.cpuPositions.length !== n3) {
      this.cpuPositions = new Float32Array(n3);
    }
    return this.cpuPositions;
  }

  /** Downsampled RGB pixels of each element's area of the canvas, as drawn. */
  pixelsOf(elements: HTMLElement[], step: number): number[][] {
    const gl = this.renderer.getContext();
    const height = this.renderer.domElement.height;
    const ratio = this.renderer.getPixelRatio();
    return elements.map((element) => {
      const r = element.getBoundingClientRect();
      const w = Math.floor(r.width * ratio), h = Math.floor(r.height * ratio);
      const pixels = new Uint8Array(w * h * 4);
      gl.readPixels(Math.floor(r.left * ratio), height - Math.floor(r.bottom * ratio), w, h,
        gl.RGBA, gl.UNSIGNED_BYTE, pixels);
      const out: number[] = [];
      for (let y = 0; y < h; y += step) {
        for (let x = 0; x < w; x += step) {
          const i = 4 * (y * w + x);
          out.push(pixels[i], pixels[i + 1], pixels[i + 2]);
        }
      }
      return out;
    });
  }

  /** Mean time (ms) of a drawn frame on one path, after a warm-up (shader compile, uploads). */
  private timeFrames(useCPU: boolean): number {
    this.deformer!.useCPU = useCPU;
    this.draw(1); this.finish();
    const start = performance.now();
    for (let i = 0; i < 2; i++) { this.draw(1.5 + i); this.finish(); }
    return (performance.now() - start) / 2;
  }

  /** Draw one mesh into its element's rectangle of the canvas (skipped when off screen). */
  private drawShot(shot: Shot, camera: THREE.PerspectiveCamera, weights: Float32Array,
                   stage: Stage, positions: THREE.Texture | null): void {
    const deformer = this.deformer!;
    const renderer = this.renderer;
    const rect = shot.element.getBoundingClientRect();
    const height = renderer.domElement.clientHeight;
    if (rect.width < 2 || rect.height < 2 || rect.bottom < 0 || rect.top > height) return;
    const x = rect.left, y = height - rect.bottom;
    renderer.setViewport(x, y, rect.width, rect.height);
    renderer.setScissor(x, y, rect.width, rect.height);
    camera.aspect = rect.width / rect.height;
    camera.updateProjectionMatrix();
    const cpu = deformer.useCPU ? deformCPU(deformer.basis, weights, this.cpuBuffer()) : null;
    const { look } = stage;
    deformer.setTile(weights, cpu, {
      color: TILE_COLORS[shot.colorIndex % TILE_COLORS.length],
      wireframe: look.shading === "wireframe",
      normalBlend: look.shading === "flat" ? 0 : look.normalBlend,
      harmonic: stage.view === "player" ? look.harmonic : -1,
      harmonicScale: look.harmonicScale,
    }, positions);
    renderer.render(deformer.scene, camera);
  }

  /** Fit the canvas's drawing buffer to the window. */
  private resize(): void {
    const width = window.innerWidth, height = window.innerHeight;
    const size = this.renderer.getSize(new THREE.Vector2());
    if (size.x !== width || size.y !== height) this.renderer.setSize(width, height, false);
  }

  /** Both cameras look at the origin from the same side, far enough to frame the mesh. */
  private aimCameras(basis: Basis): void {
    let radius = 0;
    const v = basis.vertices;
    for (let i = 0; i < basis.n * 3; i += 3) {
      radius = Math.max(radius, Math.hypot(v[i], v[i + 1], v[i + 2]));
    }
    const distance = (radius * 1.15) / Math.sin(THREE.MathUtils.degToRad(16));
    const direction = new THREE.Vector3(0.55, 0.35, 1).normalize();
    this.tileCamera.position.copy(direction).multiplyScalar(distance);
    this.tileCamera.lookAt(0, 0, 0);
    this.playerCamera.position.copy(direction).multiplyScalar(distance * 0.95);
    this.controls.target.set(0, 0, 0);
    this.controls.update();
  }
}
