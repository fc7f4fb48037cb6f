// The Viewer owns the WebGL canvas: renderer, cameras, the render loop, drawing the gallery's
// tiles or the player into their viewports, the studio around each model, the page's real frame
// rate and the render scale and detail that hold it (resolution.ts), and the choice of
// deformation path (docs/design.md#rendering). What to draw comes from the views through
// `Stage`; time from a `Clock`.
import * as THREE from "three";
import { OrbitControls } from "three/examples/jsm/controls/OrbitControls.js";
import type { Basis } from "./bundle";
import { CloseUpDrawer } from "./close-up";
import { CLAY, Deformer, maxHarmonicsOnGPU } from "./deform";
import { deformCPU } from "./filter";
import type { Prepared } from "./filter";
import type { Appearance } from "./look";
import { fasterOnCPU } from "./path-choice";
import { RESOLUTION, ResolutionGovernor } from "./resolution";
import { Studio, VIEW_DIRECTION, framing, rim, silhouette } from "./studio";
import type { Silhouette } from "./studio";
import type { DeformationPath, MotionSource, Shot, Stage } from "./stage";
import type { Clock } from "./transport";

export type { DeformationPath, Explorer, Look, MotionSource, Shot, Stage, View } from "./stage";

/** Where a camera stands: looking at `target` from `distance` along VIEW_DIRECTION. */
interface Framing { target: THREE.Vector3; distance: number; }

/** Where the time of a frame went (ms); measured by `profile`. */
export interface FrameParts { deformation: number; drawing: number; }

/** The frame rate below which the gallery offers fewer tiles. */
export const SMOOTH_FPS = 20;
const FIELD_OF_VIEW = 30;
/** A model is framed at rest and in the song's POSES loudest moments, by its RIM vertices that
 * reach farthest (all of a small model: on a sphere every vertex reaches as far). */
const POSES = 6;
const RIM = 2000;
/** Frame times are averaged over this window (ms) for the frame-rate readout. */
const RATE_WINDOW_MS = 1000;

/** Whether WebGL runs on a software rasteriser (SwiftShader, llvmpipe): no antialiasing there,
 * it would halve the frame rate. */
export function softwareRenderer(): boolean {
  const gl = document.createElement("canvas").getContext("webgl2");
  if (!gl) return true;
  const info = gl.getExtension("WEBGL_debug_renderer_info");
  const name = String(info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : "");
  gl.getExtension("WEBGL_lose_context")?.loseContext();
  return /swiftshader|llvmpipe|software|softpipe/i.test(name);
}

export class Viewer {
  readonly renderer: THREE.WebGLRenderer;
  readonly studio = new Studio();
  deformer: Deformer | null = null;
  path: DeformationPath = "gpu";
  /** the page's real frame rate while playing (frames drawn per second), 0 when idle */
  fps = 0;
  /** smoothed time of our own work per frame (ms): deformation and drawing */
  frameMs = 0;
  /** frames drawn while the music played, since the page started */
  playedFrames = 0;
  /** Called before every frame is drawn, with its time: what changes the page's layout (the
   * seek bar, the clock, readouts), so the frame is drawn where the views are. */
  onFrame: (t: number) => void = () => {};
  /** Called after every frame is drawn (the recorder copies its view then). */
  onDrawn: () => void = () => {};
  /** the render scale that holds the target frame rate (resolution.ts) */
  readonly resolution: ResolutionGovernor;

  private readonly tileCamera = new THREE.PerspectiveCamera(FIELD_OF_VIEW, 1, 0.05, 100);
  readonly playerCamera = new THREE.PerspectiveCamera(FIELD_OF_VIEW, 1, 0.05, 100);
  private readonly controls: OrbitControls;
  private readonly closeUps = new CloseUpDrawer(FIELD_OF_VIEW);
  private shape: Silhouette | null = null;
  private rim: Int32Array | null = null;
  /** each mapping's rim in its loudest poses, and its framings by view aspect */
  private poses = new WeakMap<Prepared, Silhouette>();
  private framings = new WeakMap<Prepared, Map<number, Framing>>();
  /** the aspect and mapping the player's camera was framed for */
  private playerFramed: { aspect: number; source: object | undefined } | null = null;
  /** a time set by `pin` (offline rendering, tests) instead of the clock's */
  private pinned: number | null = null;
  private drawRequested = false;
  private cpuBuffers: Float32Array[] = [];
  /** start times (ms) of the frames drawn while playing, within the last RATE_WINDOW_MS */
  private frameTimes: number[] = [];

  constructor(canvas: HTMLCanvasElement, playerArea: HTMLElement,
              private readonly motion: MotionSource, private readonly clock: Clock,
              private readonly stage: () => Stage, antialias: boolean,
              /** a fixed render scale (`?scale=`), or null: dynamic resolution */
              private readonly fixedScale: number | null = null,
              /** the frame rate it aims at (`?fps=`), or null: RESOLUTION's */
              target: number | null = null) {
    this.resolution = new ResolutionGovernor(target === null ? RESOLUTION
      : { ...RESOLUTION, target });
    this.renderer = new THREE.WebGLRenderer({ canvas, antialias,
      preserveDrawingBuffer: true, powerPreference: "high-performance" });
    if (fixedScale !== null) this.resolution.scale = fixedScale;
    this.applyScale();
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

  /** Show a new mesh: its deformer (GPU resources), its shadow, and cameras framing it. */
  setBasis(basis: Basis, batch: number, appearance: Appearance | null = null): void {
    const deformer = new Deformer(basis, this.renderer, batch); // may throw: keep the old one
    deformer.setLook(appearance);
    this.deformer?.dispose();
    this.deformer = deformer;
    deformer.scene.add(this.studio.backdrop, this.studio.shadow);
    this.studio.placeShadow(basis);
    this.shape = silhouette(basis.vertices, VIEW_DIRECTION);
    this.rim = rim(this.shape, Math.min(1, RIM / basis.n));
    this.poses = new WeakMap();
    this.framings = new WeakMap();
    this.cpuBuffers = [];
    this.playerFramed = null;
  }

  /** The render loop: a frame whenever the music plays or something asked for one. The end of
   * the song is handled here, not by the clock: stop and rewind to 0. */
  start(): void {
    const tick = () => {
      if (this.clock.ended()) {
        this.clock.rewind();
        this.requestDraw();
      }
      const playing = this.clock.playing && this.pinned === null;
      if (playing || this.drawRequested) {
        this.drawRequested = false;
        this.countFrame(playing);
        this.draw(this.time());
      } else {
        this.countFrame(false);
      }
      requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
  }

  /** Draw the frame at time t (s) of whatever the stage shows. With `profile`, wait for the GPU
   * after each part and return where the time went. */
  draw(t: number, profile = false): FrameParts | null {
    const deformer = this.deformer;
    if (!deformer || !this.motion.ready) {
      if (this.motion.songLoaded) this.onFrame(t); // a rig alone: the clock still follows the song
      return null;
    }
    const start = performance.now();
    this.onFrame(t); // first: what it writes into the page may move the views
    this.resize();
    const stage = this.stage();
    const renderer = this.renderer;
    renderer.setScissorTest(false);
    renderer.setClearColor(0x15171c, 1);
    renderer.clear();
    const shots = stage.view === "gallery" ? stage.tiles : stage.player ? [stage.player] : [];
    const weights = shots.map((shot) => this.motion.weights(shot.prepared, t));
    // Every model's positions first (GPU: batched passes; CPU: one buffer each), then surfaces.
    let positions: THREE.Texture[] | null = null;
    let cpu: Float32Array[] | null = null;
    if (!shots.length) {
      // nothing to deform (a player without a mapping)
    } else if (!deformer.useCPU) {
      positions = deformer.computePositions(weights);
    } else {
      cpu = weights.map((w, i) => deformCPU(deformer.basis, w, this.cpuBuffer(i)));
    }
    if (profile) this.finish();
    const deformed = performance.now();
    renderer.setScissorTest(true);
    shots.forEach((shot, i) => {
      const camera = stage.view === "gallery" ? this.tileCamera : this.playerCamera;
      this.drawShot(shot, camera, weights[i], stage, positions?.[i] ?? null, cpu?.[i] ?? null);
    });
    renderer.setScissorTest(false);
    if (profile) this.finish();
    this.onDrawn();
    const end = performance.now();
    this.frameMs = this.frameMs ? 0.9 * this.frameMs + 0.1 * (end - start) : end - start;
    return { deformation: deformed - start, drawing: end - deformed };
  }

  /** Wait until the GPU has finished the frame (a 1-pixel read forces it). */
  finish(): void {
    const gl = this.renderer.getContext();
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
  }

  /** Pick the deformation path (docs/design.md#rendering): the CPU when k does not fit the
   * shader's uniforms, else the one `forced`, else the faster of the two timed (path-choice.ts). */
  choosePath(forced: DeformationPath | null): void {
    const deformer = this.deformer!;
    if (deformer.basis.k > maxHarmonicsOnGPU(this.renderer)) {
      deformer.useCPU = true;
    } else if (forced) {
      deformer.useCPU = forced === "cpu";
    } else {
      deformer.useCPU = fasterOnCPU({ draw: (t, useCPU) => {
        deformer.useCPU = useCPU;
        return this.draw(t, true);
      }, scale: (scale) => {
        this.resolution.scale = scale;
        this.applyScale();
      }, floor: this.resolution.rule.floor, scaleNow: this.resolution.scale });
    }
    this.path = deformer.useCPU ? "cpu" : "gpu";
    this.frameMs = 0;
  }

  /** Use this path from now on (benchmarks compare both). */
  setPath(path: DeformationPath): void {
    this.deformer!.useCPU = path === "cpu";
    this.path = path;
  }

  /** A buffer for the CPU positions (n*3) of the i-th model of a frame, reused across frames. */
  cpuBuffer(i = 0): Float32Array {
    const n3 = this.deformer!.basis.n * 3;
    while (this.cpuBuffers.length <= i) this.cpuBuffers.push(new Float32Array(n3));
    if (this.cpuBuffers[i].length !== n3) this.cpuBuffers[i] = new Float32Array(n3);
    return this.cpuBuffers[i];
  }

  /** Where `element` lies in the drawing buffer (pixels, origin top left), as drawn. */
  bufferRect(element: HTMLElement): { x: number; y: number; width: number; height: number } {
    const r = element.getBoundingClientRect();
    const ratio = this.renderer.getPixelRatio();
    return { x: Math.floor(r.left * ratio), y: Math.floor(r.top * ratio),
      width: Math.floor(r.width * ratio), height: Math.floor(r.height * ratio) };
  }

  /** Frame the player's model again (after the window changed shape, or on request). */
  resetPlayerCamera(): void { this.playerFramed = null; this.requestDraw(); }

  /** Count a drawn frame (or none) for the frame-rate readout: frames whose start lies in the
   * last RATE_WINDOW_MS, while the music plays; 0 when nothing plays. */
  private countFrame(drawn: boolean): void {
    const now = performance.now();
    if (!drawn) {
      if (!this.clock.playing) {
        this.frameTimes = [];
        this.fps = 0;
        this.resolution.update(0, now, false);
      }
      return;
    }
    this.playedFrames++;
    this.frameTimes.push(now);
    // The last RATE_WINDOW_MS, but at least two frames: a page slower than 1 fps shows it too.
    while (this.frameTimes.length > 2 && this.frameTimes[0] < now - RATE_WINDOW_MS) {
      this.frameTimes.shift();
    }
    const span = now - this.frameTimes[0];
    this.fps = this.frameTimes.length > 1 ? (1000 * (this.frameTimes.length - 1)) / span : 0;
    if (this.fixedScale === null && this.resolution.update(this.fps, now, true)) {
      this.applyScale();
    }
  }

  /** Whether the render scale follows the frame rate (not with `?scale=`). */
  get dynamic(): boolean { return this.fixedScale === null; }

  /** Draw into a buffer of the render scale's size (the browser scales it up to the page). */
  private applyScale(): void {
    const ratio = Math.min(window.devicePixelRatio, 2) * this.resolution.scale;
    if (Math.abs(this.renderer.getPixelRatio() - ratio) > 1e-6) {
      this.renderer.setPixelRatio(ratio);
      this.requestDraw();
    }
  }

  /** Draw one model into its element's rectangle of the canvas (skipped when off screen). */
  private drawShot(shot: Shot, camera: THREE.PerspectiveCamera, weights: Float32Array,
                   stage: Stage, positions: THREE.Texture | null,
                   cpu: Float32Array | null): void {
    const deformer = this.deformer!;
    const renderer = this.renderer;
    const rect = shot.element.getBoundingClientRect();
    const height = renderer.domElement.clientHeight;
    if (rect.width < 2 || rect.height < 2 || rect.bottom < 0 || rect.top > height) return;
    const x = rect.left, y = height - rect.bottom;
    renderer.setViewport(x, y, rect.width, rect.height);
    renderer.setScissor(x, y, rect.width, rect.height);
    this.aim(camera, rect.width, rect.height, shot);
    this.studio.setAspect(rect.width / rect.height);
    const { look } = shot;
    const player = stage.view === "player";
    deformer.useDetail(player ? 1 : this.resolution.detail); // one model: all its triangles
    deformer.setTile(weights, cpu, {
      color: CLAY,
      wireframe: look.shading === "wireframe",
      deformedNormalWeight: look.shading === "flat" ? 1 : look.deformedNormalWeight,
      harmonic: player ? stage.explorer.harmonic : -1,
      harmonicScale: stage.explorer.scale,
      materials: look.materials,
    }, positions);
    renderer.render(deformer.scene, camera);
    if (shot.closeUp) this.closeUps.draw(renderer, deformer, this.studio, shot.closeUp, height);
  }

  /** Frame the model for a view of this size: a tile at every frame (its framing is cached),
   * below the caption over its top (`data-covered` pixels, as a view offset), the player's
   * orbit camera when its view changed shape or shows another mapping. */
  private aim(camera: THREE.PerspectiveCamera, width: number, height: number, shot: Shot): void {
    const covered = Math.min(Number(shot.element.dataset.covered ?? 0), height / 3);
    const aspect = width / (height - covered);
    camera.aspect = aspect;
    if (covered > 0) camera.setViewOffset(width, height - covered, 0, -covered, width, height);
    else camera.clearViewOffset();
    if (camera === this.playerCamera) {
      const framed = this.playerFramed;
      if (!framed || framed.source !== shot.source
          || Math.abs(aspect - framed.aspect) > 0.02 * aspect) {
        this.playerFramed = { aspect, source: shot.source };
        const { target, distance } = this.framingFor(shot.prepared, aspect);
        camera.position.copy(VIEW_DIRECTION).multiplyScalar(distance).add(target);
        this.controls.target.copy(target);
        this.controls.update();
      }
      camera.updateProjectionMatrix();
      return;
    }
    const { target, distance } = this.framingFor(shot.prepared, aspect);
    camera.position.copy(VIEW_DIRECTION).multiplyScalar(distance).add(target);
    camera.lookAt(target);
    camera.updateProjectionMatrix();
  }

  /** A view's camera for this mapping (tests): target, distance along `direction`, vertical
   * field of view (degrees) and aspect of the part of the view below `covered` pixels. */
  framed(prepared: Prepared, width: number, height: number, covered: number) {
    const aspect = width / (height - covered);
    const { target, distance } = this.framingFor(prepared, aspect);
    return { target: target.toArray(), distance, direction: VIEW_DIRECTION.toArray(),
      fov: FIELD_OF_VIEW, aspect, covered };
  }

  /** Where the camera stands for a model moved by `prepared` in a view of this aspect: the
   * model whole at rest and in the song's loudest poses. */
  private framingFor(prepared: Prepared, aspect: number): Framing {
    const key = Math.round(aspect * 50) / 50;
    let byAspect = this.framings.get(prepared);
    if (!byAspect) {
      byAspect = new Map();
      this.framings.set(prepared, byAspect);
    }
    let found = byAspect.get(key);
    if (!found) {
      found = framing([this.shape!, this.posesOf(prepared)], VIEW_DIRECTION, FIELD_OF_VIEW, key);
      byAspect.set(key, found);
    }
    return found;
  }

  /** The rim of the model in the song's loudest poses under this mapping (CPU, rim only). */
  private posesOf(prepared: Prepared): Silhouette {
    let found = this.poses.get(prepared);
    if (!found) {
      const basis = this.deformer!.basis, rimVertices = this.rim!;
      const weights = this.motion.framingWeights?.(prepared)
        ?? this.motion.loudestTimes(POSES).map((t) => this.motion.weights(prepared, t));
      const points = new Float32Array(3 * rimVertices.length * weights.length);
      weights.forEach((w, i) => {
        deformCPU(basis, w,
          points.subarray(3 * rimVertices.length * i, 3 * rimVertices.length * (i + 1)),
          rimVertices);
      });
      found = silhouette(points, VIEW_DIRECTION);
      this.poses.set(prepared, found);
    }
    return found;
  }

  /** Fit the canvas's drawing buffer to the window. */
  private resize(): void {
    const width = window.innerWidth, height = window.innerHeight;
    const size = this.renderer.getSize(new THREE.Vector2());
    if (size.x !== width || size.y !== height) this.renderer.setSize(width, height, false);
  }
}
