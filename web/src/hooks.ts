// `window.eigendance`: the handle for offline rendering (`?render`) and tests (`?test`), and
// only there; installed explicitly by main.ts and announced on the console.
import type { App } from "./app";
import { deformCPU } from "./filter";
import type { Prepared } from "./filter";
import { liveHooks } from "./live-hooks";
import { lookInfo, pixelsOf, rigHooks } from "./rig-hooks";
import type { DeformationPath, View } from "./viewer";

export type Hooks = ReturnType<typeof makeHooks>;

declare global {
  interface Window { eigendance?: Hooks; }
}

/** Put the hooks on `window.eigendance`; `ready` resolves once the app has started. */
export function installHooks(app: App, ready: Promise<void>): void {
  window.eigendance = makeHooks(app, ready);
  console.info("eigendance: test hooks on window.eigendance");
}

function makeHooks(app: App, ready: Promise<void>) {
  return {
    ready,
    ...pixelHooks(app),
    ...galleryHooks(app),
    /** Rigs (docs/web.md#rigs-in-the-page); positions are in the rig file's units. */
    rig: rigHooks(app),
    /** Live input (docs/web.md#live-input). */
    liveInput: liveHooks(app),
    ...timingHooks(app),
  };
}

/** every tile's shader weights at time t */
const allWeights = (app: App, t: number) =>
  app.gallery.shots().map((shot) => app.motion.weights(shot.prepared, t));

/** Drawing at a time, and reading back what was drawn (positions, pixels). */
function pixelHooks(app: App) {
  const { gallery, motion, player, viewer } = app;
  const prepared = (tile: number | "player"): Prepared =>
    tile === "player" ? player.prepared! : gallery.shots()[tile].prepared;
  return {
    /** Draw the frame at time t (s) and resolve when it is on the canvas. */
    async renderAt(t: number): Promise<void> {
      viewer.pin(t);
      viewer.draw(t);
      viewer.finish();
    },
    /** Back to the audio clock. */
    live(): void { viewer.unpin(); },
    /** Deformed positions (normalised, n*3) of a tile or the player at time t, computed by the
     * GPU shader and read back from its float render target: the batched pass over every
     * gallery tile, as drawn, or with `single` (and for the player) the one-model pass. */
    readPositions(tile: number | "player", t: number, single = false): number[] {
      const deformer = viewer.deformer!;
      if (tile === "player" || single) {
        return Array.from(deformer.readPositions([motion.weights(prepared(tile), t)]));
      }
      return Array.from(deformer.readPositions(allWeights(app, t), tile));
    },
    /** The same positions from the CPU path. */
    cpuPositions(tile: number | "player", t: number): number[] {
      return Array.from(deformCPU(motion.basis!, motion.weights(prepared(tile), t)));
    },
    /** Where the camera of a tile (or the player, at its framing) stands: what it shows. */
    framingOf(tile: number | "player") {
      const element = tile === "player" ? document.getElementById("player-area")!
        : gallery.views()[tile];
      const { width, height } = element.getBoundingClientRect();
      return viewer.framed(prepared(tile), width, height,
        Math.min(Number(element.dataset.covered ?? 0), height / 3));
    },
    /** Downsampled RGB pixels of each tile's view, read from the canvas. */
    tilePixels: (step = 4): number[][] => pixelsOf(viewer, gallery.views(), step),
    /** The same for the player's view. */
    playerPixels: (step = 4): number[] => pixelsOf(viewer, [document.getElementById(
      "player-area")!], step)[0],
  };
}

/** The gallery, the player and the page's state. */
function galleryHooks(app: App) {
  const { gallery, motion, player, viewer } = app;
  return {
    mappings: () => gallery.mappings(),
    /** The player's mapping as "save mapping" writes it. */
    playerMapping: () => player.saved(),
    select: (index: number) => gallery.toggle(index),
    breed: async (seed?: number): Promise<void> => {
      await app.messages.guard("Breeding failed", () => gallery.breed(seed));
    },
    back: () => gallery.step(-1),
    /** Show generation `index` (in creation order). */
    generation: (index: number) => gallery.setGeneration(index),
    /** The generations menu: index (creation order), depth in the tree, label. */
    generations: () => gallery.history.entries(),
    setView: (view: View) => app.setView(view),
    open: (index: number) => app.open(gallery.mappings()[index], `tile ${index + 1}`),
    upload: (file: File) => app.files.handle([file]),
    info: () => ({
      meshId: app.library.meshId, songId: app.library.songId, n: motion.basis?.n,
      k: motion.basis?.k, path: viewer.path, batch: viewer.deformer?.batch,
      generation: gallery.generation, generations: gallery.generationCount,
      tiles: gallery.tileCount, view: app.view, frameMs: viewer.frameMs, fps: viewer.fps,
      frames: viewer.playedFrames,
      duration: motion.duration, selected: gallery.selection, playing: app.transport.playing,
      time: app.transport.now(), volume: app.transport.volume, muted: app.transport.muted,
      error: app.messages.shownError(), scale: viewer.resolution.scale,
      status: document.getElementById("status")!.textContent,
      recording: app.recorder.size, look: lookInfo(viewer),
    }),
    setPath: (path: DeformationPath) => viewer.setPath(path),
    /** Draw every tile and the player in the model's materials (true) or in clay (false), as
     * the player's switch does for its mapping. */
    setMaterials(on: boolean): void {
      for (const mapping of [...gallery.mappings(), player.mapping]) {
        if (mapping) mapping.look = { ...mapping.look, materials: on };
      }
      (document.getElementById("materials") as HTMLInputElement).checked = on;
      viewer.requestDraw();
    },
    /** The model's own look as loaded: materials, drawn vertices (null: clay). */
    look: () => lookInfo(viewer),
    /** The render scale (dynamic resolution) of the harmonics' viewer. */
    resolution: () => ({ scale: viewer.resolution.scale, atFloor: viewer.resolution.atFloor,
      detail: viewer.resolution.detail, exhausted: viewer.resolution.exhausted,
      said: viewer.resolution.describe(), pixelRatio: viewer.renderer.getPixelRatio() }),
    /** Draw the tiles with about `fraction` of the triangles (a level of detail.ts), as a slow
     * page does; with `?scale=` fixed, the page keeps it. */
    setDetail(fraction: number): void {
      viewer.resolution.detail = fraction;
      viewer.requestDraw();
    },
    /** The export panel's request for the window in its fields (what `export` would send). */
    exportRequest: () => app.exporter.request(),
  };
}

/** Timings of the deformation and the drawing (benchmarks). */
function timingHooks(app: App) {
  const { motion, viewer } = app;
  return {
    /** Time the deformation alone of every tile (ms per frame), GPU or CPU path. */
    timeDeformation(count: number, t0 = 1): { frame: number } {
      const run = (t: number) => {
        const weights = allWeights(app, t);
        const deformer = viewer.deformer!;
        if (!deformer.useCPU) deformer.computePositions(weights);
        else weights.forEach((w, i) => deformCPU(motion.basis!, w, viewer.cpuBuffer(i)));
        viewer.finish();
      };
      run(t0);
      const start = performance.now();
      for (let i = 0; i < count; i++) run(t0 + 0.1 * i);
      return { frame: (performance.now() - start) / count };
    },
    /** Time one frame's deformation + draw of every tile (ms). */
    timeFrames(count: number, t0 = 1): { frame: number } {
      viewer.draw(t0); viewer.finish();
      const start = performance.now();
      for (let i = 0; i < count; i++) { viewer.draw(t0 + 0.1 * i); viewer.finish(); }
      return { frame: (performance.now() - start) / count };
    },
    /** Where a frame goes (ms, mean over `count` frames): the deformation of every model, then
     * drawing them, each waited for on the GPU. */
    profileFrames(count: number, t0 = 1): { deformation: number; drawing: number } {
      viewer.draw(t0, true);
      let deformation = 0, drawing = 0;
      for (let i = 0; i < count; i++) {
        const parts = viewer.draw(t0 + 0.1 * i, true)!;
        deformation += parts.deformation;
        drawing += parts.drawing;
      }
      return { deformation: deformation / count, drawing: drawing / count };
    },
  };
}
