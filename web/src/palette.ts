// A rig's palette as the page completes it (docs/design.md#modal-motion): the mapping's `modes`
// with every field it leaves empty filled by the default rule, as `eigendance.modal.palette.
// resolve_palette` fills it — the selection (the bundle's default palette's), the amplitudes
// (each mode alone bending its most bent joint by 25°, the bundle's `amplitudes`; then all
// scaled down together if the selected modes in phase would bend a joint beyond 40°), the
// phases (κ·g, the bundle's `phases`) and the time scale (the s closest to 1 that puts the
// selected modes' frequencies in [0.8, 3.5] Hz), any amplitudes then kept above the floor
// (floor.ts, `floor_capped`), and the tempo mode (`modes.tempo`, null: locked
// to the beats of a song that has them). Vitest checks it against numbers Python writes
// (web/test/fixtures/palette.json). The tempo lock's ratios and phases are `lock_ratios` and
// `locked_phases` of the same module (docs/design.md#tempo-lock).
import { floorCapped } from "./floor";
import type { ModeSettings, Rig } from "./rig-bundle";

/** Hz: where the default time scale puts the selected modes (`palette.TEMPO_BAND`). */
export const TEMPO_BAND: [number, number] = [0.8, 3.5];
/** The largest joint bend of the selected modes in phase at φ = 1 (`palette.COMBINED_BEND`). */
export const COMBINED_BEND = (40 * Math.PI) / 180;

/** s closest to 1 with s·[min ν, max ν] inside TEMPO_BAND, else the geometric centring
 * (`default_time_scale`). */
export function defaultTimeScale(frequencies: ArrayLike<number>): number {
  const positive = Array.from(frequencies).filter((f) => f > 0);
  if (!positive.length) return 1;
  const smallest = TEMPO_BAND[0] / Math.min(...positive);
  const largest = TEMPO_BAND[1] / Math.max(...positive);
  if (smallest <= largest) return Math.min(Math.max(1, smallest), largest);
  return Math.sqrt(smallest * largest);
}

/** Reach (radians) of the selected modes: each alone as its mode tile, all capped together
 * at COMBINED_BEND (`default_amplitudes`). */
export function defaultAmplitudes(rig: Rig, selected: number[]): number[] {
  const amplitudes = selected.map((mode) => rig.amplitudes[mode]);
  let together = 0;
  for (let joint = 0; joint < rig.j; joint++) {
    let bend = 0;
    selected.forEach((mode, v) => {
      bend += rig.jointBend[joint * rig.k + mode] * (amplitudes[v] / rig.reach[mode]);
    });
    together = Math.max(together, bend);
  }
  const scale = together > COMBINED_BEND ? COMBINED_BEND / together : 1;
  return amplitudes.map((a) => a * scale);
}

/** A palette with every field set (the mapping's `modes` as the page writes it), the selected
 * modes ascending, their amplitudes and phases following (`resolve_palette`). */
export function paletteOf(rig: Rig, modes: Partial<ModeSettings> | null | undefined):
    ModeSettings {
  const selected = modes?.selected ?? rig.palette!.selected!;
  for (const v of selected) {
    if (!(Number.isInteger(v) && v >= 0 && v < rig.k)) {
      throw new Error(`the mapping selects mode ${v}; the rig has ${rig.k}`);
    }
  }
  const order = selected.map((_, i) => i).sort((a, b) => selected[a] - selected[b]);
  const sorted = order.map((i) => selected[i]);
  const amplitudes = floorCapped(rig, sorted, modes?.amplitudes
    ? order.map((i) => modes.amplitudes![i]) : defaultAmplitudes(rig, sorted));
  const phases = modes?.phases ? order.map((i) => modes.phases![i])
    : sorted.map((mode) => rig.phases[mode]);
  const timeScale = modes?.time_scale
    ?? defaultTimeScale(sorted.map((mode) => rig.frequencies[mode]));
  return { selected: sorted, amplitudes, phases, time_scale: timeScale,
    tempo: modes?.tempo ?? null };
}

/** The cycles per beat in {½, 1, 2} nearest (in log frequency) to a mode's time-scaled natural
 * frequency (eigendance.modal.palette.lock_ratios). */
export function lockRatio(frequency: number, timeScale: number, tempo: number): number {
  let best = 0.5, distance = Infinity;
  for (const r of [0.5, 1, 2]) {
    const d = Math.abs(Math.log(Math.max(frequency * timeScale, 1e-12) / (r * tempo / 60)));
    if (d < distance) { best = r; distance = d; }
  }
  return best;
}

/** γ snapped to the nearest π/2 + nπ (eigendance.modal.palette.locked_phases; numpy rounds
 * halves to even). */
export function lockedPhase(phase: number): number {
  const x = (phase - Math.PI / 2) / Math.PI;
  let n = Math.round(x);
  if (Math.abs(x % 1) === 0.5 && n % 2 !== 0) n -= 1; // round half to even, as numpy
  return Math.PI / 2 + Math.PI * n;
}

