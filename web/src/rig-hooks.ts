// `window.eigendance.rig`: the hooks of rigs (docs/web.md#rigs-in-the-page) for tests and
// offline rendering, and the pixel helpers every hook shares. Positions are in the rig file's
// units.
import type { App } from "./app";
import { deformCPU } from "./filter";
import type { RigPrepared } from "./modal-skin";
import { toFileUnits } from "./rig-bundle";
import { RIG_LOOK } from "./rig-gallery-view";
import type { Skinning } from "./rig-player-view";
import type { DeformationPath, View, Viewer } from "./viewer";

export function rigHooks(app: App) {
  return { ...rigReadHooks(app), ...rigControlHooks(app), ...rigEditHooks(app) };
}

/** Drawing a rig at a time and reading back what was drawn (positions, coefficients, pixels). */
function rigReadHooks(app: App) {
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
    /** three.js linear blend skinning of the player's body poses at time t, of the bind pose
     * rippled by the surface when it is on (file units). */
    lbsPositions(t: number): number[] {
      rigs.poseFigure(t);
      return Array.from(rigs.figure!.lbsPositions());
    },
    tilePixels: (step = 4): number[][] => pixelsOf(rigs.viewer, rigs.gallery.views(), step),
    /** The same as base64 strings of the RGB bytes (far faster to hand over than numbers). */
    tileBytes: (step = 4): string[] => pixelsOf(rigs.viewer, rigs.gallery.views(), step)
      .map((pixels) => base64(pixels)),
    playerPixels: (step = 4): number[] => pixelsOf(rigs.viewer, [document.getElementById(
      "rig-player-area")!], step)[0],
    labels: () => rigs.gallery.labels(),
    /** Each mode tile's close-up ({corner, share}) or null (close-up.ts). */
    closeUps: () => rigs.gallery.closeUpsShown(),
  };
}

/** A rig's views and switches, as the page's controls set them. */
function rigControlHooks(app: App) {
  const rigs = app.rigs;
  return {
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
      const opened = rigs.openDance(rigs.gallery.dance(index), `dance ${index + 1}`);
      app.setView("player");
      return opened;
    },
    /** Dance `index` as its tile's *save* writes it (with its surface genes while on). */
    dance: (index: number) => rigs.gallery.dance(index),
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
  };
}

/** A rig's palette, edits (pose, stiffness) and state. */
function rigEditHooks(app: App) {
  const rigs = app.rigs;
  return {
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
export function lookInfo(viewer: Viewer) {
  const look = viewer.deformer?.look;
  return look ? { materials: look.appearance.materials.map((m) => m.name),
    drawn: look.appearance.drawn, images: look.appearance.images.length } : null;
}

/** Downsampled RGB pixels of each element's area of the viewer's canvas, as drawn. */
export function pixelsOf(viewer: Viewer, elements: HTMLElement[], step: number): number[][] {
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
