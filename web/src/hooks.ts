// `window.eigendance`: the handle for offline rendering (`?render`) and tests (`?test`), and
// only there; installed explicitly by main.ts and announced on the console.
import type { App } from "./app";
import { deformCPU } from "./filter";
import type { Prepared } from "./filter";
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
  const { gallery, motion, player, viewer } = app;
  const prepared = (tile: number | "player"): Prepared =>
    tile === "player" ? player.prepared! : gallery.shots()[tile].prepared;
  /** every tile's shader weights at time t */
  const allWeights = (t: number) => {
    const values = motion.bandValuesAt(t);
    return gallery.shots().map((shot) => motion.weights(shot.prepared, values));
  };
  return {
    ready,
    /** Draw the frame at time t (s) and resolve when it is on the canvas. */
    async renderAt(t: number): Promise<void> {
      viewer.pin(t);
      viewer.draw(t);
      viewer.finish();
    },
    /** Back to the audio clock. */
    live(): void { viewer.unpin(); },
    /** Deformed positions (normalised, n*3) of a tile at time t, computed by the GPU shader and
     * read back from its float render target: the batched pass over every gallery tile, as
     * drawn, or with `single` the one-tile pass (the player's). */
    readPositions(tile: number | "player", t: number, single = false): number[] {
      const deformer = viewer.deformer!;
      if (tile === "player" || single) {
        const weights = motion.weights(prepared(tile), motion.bandValuesAt(t));
        return Array.from(deformer.readPositions([weights]));
      }
      return Array.from(deformer.readPositions(allWeights(t), tile));
    },
    /** The same positions from the CPU path. */
    cpuPositions(tile: number | "player", t: number): number[] {
      const weights = motion.weights(prepared(tile), motion.bandValuesAt(t));
      return Array.from(deformCPU(motion.basis!, weights));
    },
    /** Downsampled RGB pixels of each tile's view, read from the canvas. */
    tilePixels: (step = 4): number[][] => viewer.pixelsOf(gallery.views(), step),
    mappings: () => gallery.mappings(),
    select: (index: number) => gallery.toggle(index),
    breed: async (seed?: number): Promise<void> => {
      await app.guard("breeding", () => gallery.breed(seed));
    },
    back: () => gallery.setGeneration(gallery.generation - 1),
    setView: (view: View) => app.setView(view),
    open: (index: number) => app.open(gallery.mappings()[index]),
    upload: (file: File) => app.handleFiles([file]),
    info: () => ({
      meshId: app.library.meshId, songId: app.library.songId, n: motion.basis?.n, k: motion.basis?.k,
      path: viewer.path, batch: viewer.deformer?.batch, generation: gallery.generation,
      generations: gallery.generationCount, tiles: gallery.tileCount, view: app.view,
      frameMs: viewer.frameMs, duration: motion.duration,
      selected: gallery.selection,
    }),
    setPath: (path: DeformationPath) => viewer.setPath(path),
    /** Time the deformation alone of every tile (ms per frame), GPU or CPU path. */
    timeDeformation(count: number, t0 = 1): { frame: number } {
      const run = (t: number) => {
        const weights = allWeights(t);
        const deformer = viewer.deformer!;
        if (!deformer.useCPU) deformer.computePositions(weights);
        else weights.forEach((w) => deformCPU(motion.basis!, w, viewer.cpuBuffer()));
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
  };
}
