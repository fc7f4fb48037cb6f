// The show's own beat clock in the page (docs/design.md#show): a grid the server keeps (taps,
// a typed tempo, an Ableton Link session) laid on the song time the page draws, as the beats,
// downbeats, tempo and meter of the spectrum every part reads — cue changes and cue ends
// (show-timing.ts), the crossfade's length, the pulse and the rigs' beat lock — so they follow
// the show's clock instead of the song's own beats (or a live input's) while it is set.
import type { Spectrum } from "./bundle";

/** The server's grid (`GET api/show/state`'s `grid`): a downbeat's wall time, ms since 1970. */
export interface Grid { bpm: number; beats_per_bar: number; source: "tap" | "link";
  downbeat: number; }

/** Song time further than this from where the grid was laid (a seek, a pause, a clock's
 * drift) lays it again. */
export const GRID_SLIP = 0.02;
/** Seconds of grid laid ahead of the time drawn (a live take has no end). */
const AHEAD = 600;

/** The song time of a grid's downbeat when song time t is drawn at wall time `wall` (ms). */
export function gridOrigin(grid: Grid, t: number, wall: number): number {
  return t + (grid.downbeat - wall) / 1000;
}

/** The grid's beats and downbeats in song time from `from` to `to`, its downbeat at song time
 * `origin`. */
export function gridTimes(grid: Grid, origin: number, from: number, to: number):
    { beats: Float32Array; downbeats: Float32Array } {
  const period = 60 / grid.bpm;
  const first = Math.ceil((from - origin) / period);
  const last = Math.floor((to - origin) / period);
  const beats: number[] = [];
  const downbeats: number[] = [];
  for (let k = first; k <= last; k++) {
    const time = origin + k * period;
    beats.push(time);
    if (((k % grid.beats_per_bar) + grid.beats_per_bar) % grid.beats_per_bar === 0) downbeats.push(time);
  }
  return { beats: Float32Array.from(beats), downbeats: Float32Array.from(downbeats) };
}

/** The spectrum as the show hears it: the base (a song's, or a live take that grows) with the
 * grid's beats; the same object while nothing changes, so what the motion caches holds. */
export class GridClock {
  grid: Grid | null = null;
  private origin = 0;
  private end = 0;
  private base: Spectrum | null = null;
  private wrapped: Spectrum | null = null;

  /** A new grid from the server (null: the song's own beats again). */
  set(grid: Grid | null): void {
    const same = grid && this.grid && grid.bpm === this.grid.bpm
      && grid.downbeat === this.grid.downbeat && grid.beats_per_bar === this.grid.beats_per_bar;
    if (same) return;
    this.grid = grid;
    this.wrapped = null;
  }

  /** Each frame while the clock runs: song time t drawn at wall time `wall` (ms). */
  frame(t: number, wall: number): void {
    if (!this.grid) return;
    const origin = gridOrigin(this.grid, t, wall);
    const period = 60 / this.grid.bpm;
    let slip = Math.abs(origin - this.origin) % (period * this.grid.beats_per_bar);
    slip = Math.min(slip, period * this.grid.beats_per_bar - slip);
    if (!this.wrapped || slip > GRID_SLIP || t > this.end - AHEAD / 2) {
      this.origin = origin;
      this.wrapped = null;
    }
  }

  /** The spectrum the show's parts read. */
  wrap(base: Spectrum | null): Spectrum | null {
    const grid = this.grid;
    if (!grid || !base) return base;
    if (this.wrapped && this.base === base) return this.wrapped;
    this.base = base;
    this.end = Math.max(base.duration, 0) + AHEAD;
    const { beats, downbeats } = gridTimes(grid, this.origin, 0, this.end);
    const override: Partial<Spectrum> = { beats, downbeats, tempo: grid.bpm, meter: grid.beats_per_bar };
    this.wrapped = new Proxy(base, {
      get: (target, key, receiver) => key in override
        ? override[key as keyof Spectrum] : Reflect.get(target, key, receiver),
    });
    return this.wrapped;
  }
}
