// `window.eigendance`: the handle for offline rendering (`?render`) and tests (`?test`), and
// only there; installed explicitly by main.ts and announced on the console.
import type { App } from "./app";
import { deformCPU } from "./filter";
import type { Prepared } from "./filter";
import { liveHooks } from "./live-hooks";
import { bodyMatrices } from "./modal-skin";
import type { RigPrepared } from "./modal-skin";
import { toFileUnits } from "./rig-bundle";
import { RIG_LOOK } from "./rig-gallery-view";
import type { Skinning } from "./rig-player-view";
import type { DeformationPath, View, Viewer } from "./viewer";

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
  const allWeights = (t: number) => gallery.shots().map((shot) => motion.weights(shot.prepared, t));
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
    /** Deformed positions (normalised, n*3) of a tile or the player at time t, computed by the
     * GPU shader and read back from its float render target: the batched pass over every
     * gallery tile, as drawn, or with `single` (and for the player) the one-model pass. */
    readPositions(tile: number | "player", t: number, single = false): number[] {
      const deformer = viewer.deformer!;
      if (tile === "player" || single) {
        return Array.from(deformer.readPositions([motion.weights(prepared(tile), t)]));
      }
      return Array.from(deformer.readPositions(allWeights(t), tile));
    },
    /** The same positions from the CPU path. */
    cpuPositions(tile: number | "player", t: number): number[] {
      return Array.from(deformCPU(motion.basis!, motion.weights(prepared(tile), t)));
    },
    /** Downsampled RGB pixels of each tile's view, read from the canvas. */
    tilePixels: (step = 4): number[][] => pixelsOf(viewer, gallery.views(), step),
    /** The same for the player's view. */
    playerPixels: (step = 4): number[] => pixelsOf(viewer, [document.getElementById(
      "player-area")!], step)[0],
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
    /** The export panel's request for the window in its fields (what `export` would send). */
    exportRequest: () => app.exporter.request(),
    /** Rigs (docs/web.md#rigs-in-the-page); positions are in the rig file's units. */
    rig: rigHooks(app),
    /** Live input (docs/web.md#live-input). */
    liveInput: liveHooks(app),
    /** Time the deformation alone of every tile (ms per frame), GPU or CPU path. */
    timeDeformation(count: number, t0 = 1): { frame: number } {
      const run = (t: number) => {
        const weights = allWeights(t);
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

function rigHooks(app: App) {
  const rigs = app.rigs;
  const prepared = (tile: number | "player"): RigPrepared =>
    (tile === "player" ? rigs.player.prepared! : rigs.gallery.shots()[tile].prepared) as RigPrepared;
  const allWeights = (t: number) => rigs.gallery.shots().map((shot) => rigs.motion.weights(shot.prepared, t));
  return {
    /** Open rig `id` in its gallery of modes (resolves once shown; the error shown if any). */
    open: (id: string) => app.openRig(id),
    renderAt(t: number): void {
      rigs.viewer.pin(t);
      rigs.viewer.draw(t);
      rigs.viewer.finish();
    },
    live: () => rigs.viewer.unpin(),
    /** GPU modal skinning read back (a tile of the batched passes as drawn, or the player). */
    readPositions(tile: number | "player", t: number): number[] {
      const deformer = rigs.viewer.deformer!;
      const positions = tile === "player"
        ? deformer.readPositions([rigs.motion.weights(prepared(tile), t)])
        : deformer.readPositions(allWeights(t), tile);
      return Array.from(toFileUnits(rigs.rig!, positions));
    },
    /** Every tile's GPU positions at time t from one batched computation, as drawn. */
    readTiles(t: number): number[][] {
      return rigs.viewer.deformer!.readAll(allWeights(t))
        .map((positions) => Array.from(toFileUnits(rigs.rig!, positions)));
    },
    /** The same from the CPU path. */
    cpuPositions(tile: number | "player", t: number): number[] {
      const basis = rigs.viewer.deformer!.basis;
      return Array.from(toFileUnits(rigs.rig!, deformCPU(basis, rigs.motion.weights(prepared(tile), t))));
    },
    /** Mode coefficients c (k) of a tile or the player at time t. */
    coefficients: (tile: number | "player", t: number) =>
      Array.from(rigs.motion.coefficients(prepared(tile), t)),
    /** three.js linear blend skinning of the player's body poses at time t (file units). */
    lbsPositions(t: number): number[] {
      const figure = rigs.figure!;
      figure.pose(bodyMatrices(rigs.rig!, rigs.motion.coefficients(prepared("player"), t)));
      return Array.from(figure.lbsPositions());
    },
    tilePixels: (step = 4): number[][] => pixelsOf(rigs.viewer, rigs.gallery.views(), step),
    /** The same as base64 strings of the RGB bytes (far faster to hand over than numbers). */
    tileBytes: (step = 4): string[] => pixelsOf(rigs.viewer, rigs.gallery.views(), step)
      .map((pixels) => base64(pixels)),
    playerPixels: (step = 4): number[] => pixelsOf(rigs.viewer, [document.getElementById(
      "rig-player-area")!], step)[0],
    labels: () => rigs.gallery.labels(),
    setView: (view: View) => app.setView(view),
    setMode: (mode: "modes" | "dances") => rigs.gallery.setMode(mode),
    page: (page: number) => rigs.gallery.setPage(page),
    /** Show at most `size` mode tiles a page (the gallery of NM tiles of Table 7.2). */
    pageSize: (size: number) => {
      rigs.gallery.pageSize = size;
      rigs.gallery.setMode("modes");
      rigs.gallery.setPage(0);
    },
    select: (index: number) => rigs.gallery.toggle(index),
    combine: () => rigs.combine(rigs.gallery.selection),
    breed: (seed?: number) => app.messages.guard("Breeding failed", () => rigs.gallery.breed(seed)),
    openDance: (index: number) => {
      rigs.player.show(rigs.gallery.dances()[index], `dance ${index + 1}`);
      app.setView("player");
    },
    setSkinning: (skinning: Skinning) => {
      rigs.player.skinning = skinning;
      (document.getElementById("rig-skinning") as HTMLSelectElement).value = skinning;
      rigs.viewer.requestDraw();
    },
    setMusic: (on: boolean) => {
      rigs.player.music = on;
      (document.getElementById("rig-music") as HTMLInputElement).checked = on;
      rigs.player.update();
    },
    /** The rig's tiles and player in its materials (true) or in clay (false). */
    setMaterials: (on: boolean) => {
      RIG_LOOK.materials = on;
      (document.getElementById("rig-materials") as HTMLInputElement).checked = on;
      rigs.viewer.requestDraw();
    },
    look: () => lookInfo(rigs.viewer),
    setBones: (on: boolean) => {
      rigs.player.bones = on;
      (document.getElementById("rig-bones") as HTMLInputElement).checked = on;
      rigs.viewer.requestDraw();
    },
    pick: (joint: number) => rigs.player.pick(joint),
    /** Scale the player palette's amplitudes by `factor`. */
    scaleAmplitudes: (factor: number) => {
      const amplitudes = rigs.player.palette!.amplitudes!;
      amplitudes.forEach((a, i) => { amplitudes[i] = a * factor; });
      rigs.player.update();
    },
    /** Turn joint `joint` by a rotation vector (radians), as the pose sliders do. */
    pose: (joint: number, rotation: [number, number, number]) =>
      app.messages.guard("Could not turn the joint", () => rigs.poseJoint(joint, rotation)),
    stiffness: (joint: number, value: number | "auto") =>
      app.messages.guard("Could not set the stiffness", () => rigs.stiffness(joint, value)),
    reset: () => app.messages.guard("Could not reset the rig", () => rigs.reset()),
    playerMapping: () => rigs.player.saved(),
    info: () => ({
      id: rigs.rig?.id, name: rigs.rig?.name, n: rigs.rig?.n, k: rigs.rig?.k,
      revision: rigs.rig?.revision, diagonal: rigs.rig?.diagonal, active: rigs.active,
      view: rigs.view, mode: rigs.gallery.mode, page: rigs.gallery.page,
      pages: rigs.gallery.pages, modes: rigs.gallery.modes, tiles: rigs.gallery.views().length,
      path: rigs.viewer.path, batch: rigs.viewer.deformer?.batch, fps: rigs.viewer.fps,
      frequencies: rigs.rig ? Array.from(rigs.rig.frequencies) : [],
      generations: rigs.gallery.generations.length, error: app.messages.shownError(),
      info: document.getElementById("rig-info")!.textContent,
    }),
    setPath: (path: DeformationPath) => rigs.viewer.setPath(path),
    /** Time one frame (modal skinning + drawing of every tile, or the player), ms. */
    timeFrames(count: number, t0 = 1): { frame: number } {
      rigs.viewer.draw(t0); rigs.viewer.finish();
      const start = performance.now();
      for (let i = 0; i < count; i++) { rigs.viewer.draw(t0 + 0.1 * i); rigs.viewer.finish(); }
      return { frame: (performance.now() - start) / count };
    },
  };
}

/** Bytes (0–255 numbers) as base64. */
function base64(bytes: number[]): string {
  let text = "";
  for (let i = 0; i < bytes.length; i += 8192) {
    text += String.fromCharCode(...bytes.slice(i, i + 8192));
  }
  return btoa(text);
}

/** The look a viewer's model is drawn in: its materials and drawn vertices, or null (clay). */
function lookInfo(viewer: Viewer) {
  const look = viewer.deformer?.look;
  return look ? { materials: look.appearance.materials.map((m) => m.name),
    drawn: look.appearance.drawn, images: look.appearance.images.length } : null;
}

/** Downsampled RGB pixels of each element's area of the viewer's canvas, as drawn. */
function pixelsOf(viewer: Viewer, elements: HTMLElement[], step: number): number[][] {
  const gl = viewer.renderer.getContext();
  const height = viewer.renderer.domElement.height;
  const ratio = viewer.renderer.getPixelRatio();
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
