// Dynamic resolution (docs/design.md#rendering), as games hold a frame rate: the page measures
// the frames it really draws per second while the music plays and draws into a smaller buffer
// (a lower pixel ratio; the browser scales it up) when it cannot keep the target, larger again
// when it has room to spare; at the lowest resolution, the gallery's tiles draw fewer triangles
// (detail.ts). Pure logic, so Vitest drives it with a fake clock.

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
  /** the fractions of the triangles the tiles may draw, from all (1) down */
  detail: number[];
  /** hysteresis of the detail: the frame rate must exceed the target this many times to draw
   * twice the triangles again */
  detailAbove: number;
}

/** Without a GPU (SwiftShader, llvmpipe) 12 fps reads as motion, not as a slide show: the demo's
 * 8 tiles reach it at about half the resolution on two cores. 35% per side is the floor: below
 * it a 1280 × 800 gallery's tiles are about 110 pixels wide and a model's features blur away. */
export const RESOLUTION: ResolutionRule = {
  target: 12, floor: 0.35, lowerAfterMs: 1000, raiseAfterMs: 3000, raiseAbove: 1.6,
  raiseStep: 1.15, settleMs: 1200, detail: [1, 0.5, 0.25], detailAbove: 2.2,
};

/** Scales are multiples of this (the page says "drawing at 55% resolution"). */
const QUANTUM = 0.05;

const quantised = (scale: number) => Math.round(scale / QUANTUM) / (1 / QUANTUM);

export class ResolutionGovernor {
  /** the render scale now: 1 is the full resolution */
  scale = 1;
  /** the fraction of the triangles the gallery's tiles draw now (1: all) */
  detail = 1;
  private lowSince: number | null = null;
  private highSince: number | null = null;
  private settledAt = -Infinity;
  /** whether the scale went down before (the first step is not capped) */
  private lowered = false;

  constructor(readonly rule: ResolutionRule = RESOLUTION) {}

  /** Whether the scale is as low as it goes. */
  get atFloor(): boolean { return this.scale <= this.rule.floor + 1e-9; }

  /** Whether nothing is left to lower: the lowest resolution and the fewest triangles. */
  get exhausted(): boolean {
    return this.atFloor && this.detail <= this.rule.detail[this.rule.detail.length - 1];
  }

  /** Feed the frame rate measured at time `now` (ms) while `playing`; returns whether the
   * scale or the detail changed. The drawing cost of a frame grows about with its pixels
   * (scale²), so a step down aims at the target directly — scale × √(fps / target) — and never
   * moves more than from 1 to 0.6 at once; at the floor, the tiles draw half the triangles
   * (down to the last detail level). A step up is small, after a longer wait, with room to
   * spare: the triangles first (twice as many: the frame rate must be `detailAbove` × the
   * target), then the resolution. */
  update(fps: number, now: number, playing: boolean): boolean {
    const { rule } = this;
    if (!playing || !(fps > 0) || now < this.settledAt) {
      this.lowSince = this.highSince = null;
      return false;
    }
    if (fps < rule.target && !this.exhausted) {
      this.highSince = null;
      this.lowSince ??= now;
      if (now - this.lowSince < rule.lowerAfterMs) return false;
      if (this.atFloor) return this.setDetail(+1, now);
      // The page's first step goes straight to the aim (a big model without a GPU drew 1.4 fps
      // for seconds while the steps came); later ones move at most to 0.6×.
      const least = this.lowered ? 0.6 : 0;
      this.lowered = true;
      const aimed = this.scale * Math.min(0.9, Math.max(least, 0.95 * Math.sqrt(fps / rule.target)));
      return this.set(Math.max(rule.floor, Math.min(this.scale - QUANTUM, quantised(aimed))), now);
    }
    this.lowSince = null;
    const room = this.detail < 1 ? rule.detailAbove : rule.raiseAbove;
    if (fps > room * rule.target && (this.scale < 1 || this.detail < 1)) {
      this.highSince ??= now;
      if (now - this.highSince < rule.raiseAfterMs) return false;
      if (this.detail < 1) return this.setDetail(-1, now);
      return this.set(Math.min(1, Math.max(this.scale + QUANTUM,
        quantised(this.scale * rule.raiseStep))), now);
    }
    this.highSince = null;
    return false;
  }

  /** Back to full resolution (a new model or view: its cost is another). */
  reset(): void {
    this.scale = 1;
    this.detail = 1;
    this.lowSince = this.highSince = null;
    this.settledAt = -Infinity;
    this.lowered = false;
  }

  /** What the page says: null at full resolution and detail. */
  describe(): string | null {
    if (this.scale >= 1 && this.detail >= 1) return null;
    const triangles = this.detail < 1 ? ` and ${Math.round(100 * this.detail)}% of the triangles`
      : "";
    return `drawing at ${Math.round(100 * this.scale)}% resolution${triangles} to keep `
      + `${this.rule.target} fps`;
  }

  /** One detail level down (+1) or up (−1). */
  private setDetail(step: 1 | -1, now: number): boolean {
    const levels = this.rule.detail;
    const index = Math.max(0, Math.min(levels.length - 1, levels.indexOf(this.detail) + step));
    this.lowSince = this.highSince = null;
    this.settledAt = now + this.rule.settleMs;
    if (levels[index] === this.detail) return false;
    this.detail = levels[index];
    return true;
  }

  private set(scale: number, now: number): boolean {
    const next = Math.max(this.rule.floor, Math.min(1, quantised(scale)));
    this.lowSince = this.highSince = null;
    this.settledAt = now + this.rule.settleMs;
    if (Math.abs(next - this.scale) < 1e-9) return false;
    this.scale = next;
    return true;
  }
}
