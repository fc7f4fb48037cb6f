// When a show changes (docs/design.md#show): on the next downbeat — the bars of the song's
// rhythm, or its beats where it has no bars, or at once without beats — and for how long a cue
// lasts (bars, or to the next section). Pure functions of the song's spectrum, for Vitest.
import type { Spectrum } from "./bundle";
import type { Grid } from "./show-grid";

/** The server's show state (`GET api/show/state`). */
export interface ShowCue {
  name: string; model: { kind: "mesh" | "rig"; id: string }; song: string | null;
  live: "mic" | "tab" | null; preset: string | null; until: "bars" | "section" | "told";
  bars: number; loop: boolean; fade_beats: number;
}
export interface ShowState {
  set: string | null; cues: ShowCue[]; cue: number | null; next: number | null;
  preset: string | null; gain: number; playing: boolean; tempo: number | null;
  /** the show's own beat clock (show-grid.ts), or null: the song's beats */
  grid: Grid | null;
  blackout: boolean; loop_set: boolean; loop_cue: boolean | null; fade_beats: number;
  controls: Record<string, number>; version: number;
}

/** Beats per bar where the song has beats but no bars (4/4). */
export const BEATS_PER_BAR = 4;

/** A named array of the spectrum, read whatever the bundle calls it (`downbeats`,
 * `sections`: the rhythm's bars and parts, empty or absent in older bundles). */
export function timesOf(spectrum: Spectrum | null, name: "downbeats" | "sections" | "beats"):
    ArrayLike<number> {
  const value = (spectrum as unknown as Record<string, unknown> | null)?.[name];
  return value && typeof (value as ArrayLike<number>).length === "number"
    ? (value as ArrayLike<number>) : [];
}

/** The first time ≥ t in ascending `times`, or null. */
export function firstAtOrAfter(times: ArrayLike<number>, t: number): number | null {
  let lo = 0;
  let hi = times.length;
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    if (times[mid] < t) lo = mid + 1; else hi = mid;
  }
  return lo < times.length ? times[lo] : null;
}

/** When a change asked for at song time t starts: the next downbeat, else the next beat,
 * else t itself (no rhythm, or past the last one). */
export function boundaryAfter(spectrum: Spectrum | null, t: number): number {
  const downbeats = timesOf(spectrum, "downbeats");
  const grid = downbeats.length ? downbeats : timesOf(spectrum, "beats");
  return firstAtOrAfter(grid, t + 1e-6) ?? t;
}

/** The bar starts: the downbeats, else every BEATS_PER_BAR-th beat. */
export function barStarts(spectrum: Spectrum | null): number[] {
  const downbeats = timesOf(spectrum, "downbeats");
  if (downbeats.length) return Array.from(downbeats);
  const beats = timesOf(spectrum, "beats");
  const bars: number[] = [];
  for (let i = 0; i < beats.length; i += BEATS_PER_BAR) bars.push(beats[i]);
  return bars;
}

/** When a cue that started at `start` ends: after its bars (counted from the first bar start
 * at or after `start`), at the next section, or never (null: until told, or no rhythm). */
export function cueEnd(spectrum: Spectrum | null, cue: Pick<ShowCue, "until" | "bars">,
                       start: number): number | null {
  if (cue.until === "section") return firstAtOrAfter(timesOf(spectrum, "sections"), start + 1e-6);
  if (cue.until !== "bars" || cue.bars < 1) return null;
  const bars = barStarts(spectrum);
  let first = 0;
  while (first < bars.length && bars[first] < start - 1e-6) first++;
  const end = first + cue.bars;
  return end < bars.length ? bars[end] : null;
}

/** The crossfade's weight of the new motion at time t: 0 → 1 over `length` s from `start`. */
export function fadeWeight(start: number, length: number, t: number): number {
  if (!(length > 0)) return 1;
  return Math.min(1, Math.max(0, (t - start) / length));
}
