// Dynamic resolution (docs/design.md#rendering), as games hold a frame rate: the page measures
// the frames it really draws per second while the music plays and draws into a smaller buffer
// (a lower pixel ratio; the browser scales it up) when it cannot keep the target, larger again
// when it has room to spare. Pure logic, so Vitest drives it with a fake clock.

/** How the render scale follows the frame rate. */
export interface ResolutionRule {
  /** the frame rate held (frames per second) */
  target: number;
  /** the smallest render scale (fraction of the CSS pixel size per side) */
  floor: number;
  /** below the target this long (ms), the scale goes down */
  lowerAfterMs: number;
  /** above `raiseAbove × target` this long (ms), it goes up one step */
  raiseAfterMs: number;
  /** hysteresis: the frame rate must exceed the target this many times to go up */
  raiseAbove: number;
  /** one step up multiplies the scale by this */
  raiseStep: number;
  /** after a change, measurements are ignored this long (ms): the readout's window still holds
   * frames drawn at the old scale */
  settleMs: number;
}

/** Without a GPU (SwiftShader, llvmpipe) 12 fps reads as motion, not as a slide show: the demo's
 * 8 tiles reach it at about half the resolution on two cores. 35% per side is the floor: below
 * it a 1280 × 800 gallery's tiles are about 110 pixels wide and a model's features blur away. */
export const RESOLUTION: ResolutionRule = {
  target: 12, floor: 0.35, lowerAfterMs: 1000, raiseAfterMs: 3000, raiseAbove: 1.6,
  raiseStep: 1.15, settleMs: 1200,
};

/** Scales are multiples of this (the page says "drawing at 55% resolution"). */
const QUANTUM = 0.05;

const quantised = (scale: number) => Math.round(scale / QUANTUM) * QUANTUM;

export class ResolutionGovernor {
  /** the render scale now: 1 is the full resolution */
  scale = 1;
  private lowSince: number | null = null;
  private highSince: number | null = null;
  private settledAt = -Infinity;

  constructor(readonly rule: ResolutionRule = RESOLUTION) {}

  /** Whether the scale is as low as it goes. */
  get atFloor(): boolean { return this.scale <= this.rule.floor + 1e-9; }

  /** Feed the frame rate measured at time `now` (ms) while `playing`; returns whether the
   * scale changed. The drawing cost of a frame grows about with its pixels (scale²), so a step
   * down aims at the target directly — scale × √(fps / target) — and never moves more than
   * from 1 to 0.6 at once; a step up is small, after a longer wait, with room to spare. */
  update(fps: number, now: number, playing: boolean): boolean {
    const { rule } = this;
    if (!playing || !(fps > 0) || now < this.settledAt) {
      this.lowSince = this.highSince = null;
      return false;
    }
    if (fps < rule.target && !this.atFloor) {
      this.highSince = null;
      this.lowSince ??= now;
      if (now - this.lowSince < rule.lowerAfterMs) return false;
      const aimed = this.scale * Math.min(0.9, Math.max(0.6, 0.95 * Math.sqrt(fps / rule.target)));
      return this.set(Math.max(rule.floor, Math.min(this.scale - QUANTUM, quantised(aimed))), now);
    }
    this.lowSince = null;
    if (fps > rule.raiseAbove * rule.target && this.scale < 1) {
      this.highSince ??= now;
      if (now - this.highSince < rule.raiseAfterMs) return false;
      return this.set(Math.min(1, Math.max(this.scale + QUANTUM,
        quantised(this.scale * rule.raiseStep))), now);
    }
    this.highSince = null;
    return false;
  }

  /** Back to full resolution (a new model or view: its cost is another). */
  reset(): void {
    this.scale = 1;
    this.lowSince = this.highSince = null;
    this.settledAt = -Infinity;
  }

  /** What the page says: null at full resolution. */
  describe(): string | null {
    if (this.scale >= 1) return null;
    return `drawing at ${Math.round(100 * this.scale)}% resolution to keep ${this.rule.target} fps`;
  }

  private set(scale: number, now: number): boolean {
    const next = Math.max(this.rule.floor, Math.min(1, scale));
    this.lowSince = this.highSince = null;
    this.settledAt = now + this.rule.settleMs;
    if (Math.abs(next - this.scale) < 1e-9) return false;
    this.scale = next;
    return true;
  }
}
