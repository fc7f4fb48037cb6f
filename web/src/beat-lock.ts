// The tempo lock of docs/design.md#rhythm, evaluated per frame in the browser: beats counted
// continuously and the bar's accent, the same numbers as eigendance.music.rhythm.
import ANALYSIS from "../../src/eigendance/music/analysis.json";
import type { Spectrum } from "./bundle";

/** Whether a song has a beat the dances can follow (Rhythm.has_beats: ≥ 4 beats, a tempo). */
export function hasBeats(spectrum: Spectrum): boolean {
  return spectrum.beats.length >= 4 && spectrum.tempo > 0;
}

/** B(t): beats counted continuously, B(b_i) = i, linear between beats and extrapolated with
 * the first and last intervals (eigendance.music.rhythm.beat_phase). */
export function beatPhase(beats: ArrayLike<number>, t: number): number {
  const n = beats.length;
  if (t < beats[0]) return (t - beats[0]) / (beats[1] - beats[0]);
  if (t >= beats[n - 1]) return n - 1 + (t - beats[n - 1]) / (beats[n - 1] - beats[n - 2]);
  let low = 0, high = n - 1;
  while (high - low > 1) {
    const middle = (low + high) >> 1;
    if (beats[middle] <= t) low = middle; else high = middle;
  }
  return low + (t - beats[low]) / (beats[low + 1] - beats[low]);
}

/** How much stronger a bar's first beat is: the tempo-locked sway reaches this much further,
 * a pulse's kick on it is this much stronger (analysis.json, which
 * eigendance.music.rhythm.DOWNBEAT_ACCENT reads too). */
export const DOWNBEAT_ACCENT: number = ANALYSIS.rhythm.downbeat_accent;

/** The tempo lock at time t: B(t), the tempo and the bar's accent 1 + A·cos²(πx/2) for
 * |x| < 1 (else 1), x = B(t) − B(d) for the downbeat d nearest in beats; 1 without bars
 * (eigendance.music.rhythm.Rhythm.downbeat_accent). Needs `hasBeats`. */
export function beatLock(spectrum: Spectrum, t: number): { phase: number; tempo: number;
    accent: number } {
  const { beats, downbeats } = spectrum;
  const phase = beatPhase(beats, t);
  let accent = 1;
  if (spectrum.meter > 0 && downbeats.length >= 2) {
    let after = 0; // the first downbeat after t, clipped to 1 … n − 1
    while (after < downbeats.length && downbeats[after] <= t) after++;
    after = Math.min(Math.max(after, 1), downbeats.length - 1);
    const x = Math.min(Math.abs(phase - beatPhase(beats, downbeats[after - 1])),
      Math.abs(phase - beatPhase(beats, downbeats[after])));
    if (x < 1) accent += DOWNBEAT_ACCENT * Math.cos((Math.PI * x) / 2) ** 2;
  }
  return { phase, tempo: spectrum.tempo, accent };
}
