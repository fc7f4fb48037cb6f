// Which deformation path is faster on this machine (docs/design.md#rendering): a few frames
// timed on each, the deformation only (the drawing costs the same on both, and timed with it the
// choice followed the rasteriser's noise). The frames are drawn at the lowest render scale: the
// deformation does not depend on it, and without a GPU a big model's eight full-size frames
// held the page for 8.9 s (a live input opened then started at 2 fps).
import type { FrameParts } from "./viewer";

/** Frames timed per path after one warm-up frame (shader compile, uploads), at most … */
const FRAMES = 3;
/** … and no more once this much (ms) was spent on a path's timed frames. */
const BUDGET_MS = 300;

/** What the timing needs of the viewer. */
export interface Timed {
  /** draw a frame at time t on a path, waiting for the GPU (null: nothing to draw) */
  draw(t: number, useCPU: boolean): FrameParts | null;
  /** draw at this render scale from now on */
  scale(scale: number): void;
  /** the lowest render scale, and the one drawn at now (restored after) */
  floor: number;
  scaleNow: number;
}

/** Mean deformation time (ms) of a path's timed frames. */
function deformationMs(timed: Timed, useCPU: boolean): number {
  timed.draw(1, useCPU);
  let total = 0;
  let frames = 0;
  const started = performance.now();
  while (frames < FRAMES && (frames === 0 || performance.now() - started < BUDGET_MS)) {
    total += timed.draw(1.5 + frames, useCPU)?.deformation ?? 0;
    frames++;
  }
  return total / frames;
}

/** Whether the CPU path deforms faster than the GPU's (both timed at the lowest scale). */
export function fasterOnCPU(timed: Timed): boolean {
  timed.scale(timed.floor);
  try {
    const gpu = deformationMs(timed, false);
    const cpu = deformationMs(timed, true);
    console.info(`eigendance: deformation ${gpu.toFixed(1)} ms on the GPU, ${cpu.toFixed(1)} ms `
      + "on the CPU per frame");
    return cpu < gpu;
  } finally {
    timed.scale(timed.scaleNow);
  }
}
