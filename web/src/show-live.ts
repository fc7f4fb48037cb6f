// A live input's events for OSC out (docs/design.md#show): the output page analyses the live
// input itself (live-*.ts); what is new since its last report — beats, onsets, band values 30
// times a second — goes to the server with its clock (`POST api/show/clock`, `live`), which
// sends them over OSC when the picture reaches them (show.live_out).
import type { Spectrum } from "./bundle";
import type { LiveSpectrum } from "./live-take";

/** Band frames a second reported (OSC out's /bands rate). */
export const BANDS_PER_SECOND = 30;
/** The most events or frames one report carries (the server's bound). */
const MOST = 64;

export interface LiveReport { take: string; beats: [number, number][]; onsets: number[];
  bands: [number, number[]][]; }

export const isLiveSpectrum = (spectrum: Spectrum | null): spectrum is LiveSpectrum =>
  (spectrum as LiveSpectrum | null)?.live === true;

export class LiveReporter {
  private spectrum: LiveSpectrum | null = null;
  private take = "";
  private takes = 0;
  private beats = 0;
  private onsets = 0;
  private bandsAt = -Infinity;

  /** Whether the take has beats or onsets not reported yet (the page reports them at once). */
  pending(spectrum: LiveSpectrum): boolean {
    return spectrum !== this.spectrum || spectrum.beats.length > this.beats
      || spectrum.onsets.length > this.onsets;
  }

  /** What is new in the take since the last report (and mark it reported). */
  report(spectrum: LiveSpectrum): LiveReport {
    if (spectrum !== this.spectrum) { // a new take: from its start
      this.spectrum = spectrum;
      this.take = `${performance.timeOrigin}-${++this.takes}`;
      this.beats = this.onsets = 0;
      this.bandsAt = -Infinity;
    }
    const beats: [number, number][] = [];
    for (; this.beats < spectrum.beats.length && beats.length < MOST; this.beats++) {
      beats.push([this.beats, spectrum.beats[this.beats]]);
    }
    const onsets: number[] = [];
    for (; this.onsets < spectrum.onsets.length && onsets.length < MOST; this.onsets++) {
      onsets.push(spectrum.onsets[this.onsets]);
    }
    const bands: [number, number[]][] = [];
    const step = 1 / BANDS_PER_SECOND;
    const first = Math.max(0, Math.ceil((this.bandsAt + step) * spectrum.rate));
    for (let j = first; j < spectrum.frames && bands.length < MOST; j++) {
      const time = j / spectrum.rate;
      if (time < this.bandsAt + step - 1e-9) continue;
      const row = spectrum.values.subarray(j * spectrum.bands, (j + 1) * spectrum.bands);
      bands.push([time, Array.from(row, (v) => Math.round(v * 1e4) / 1e4)]);
      this.bandsAt = time;
    }
    return { take: this.take, beats, onsets, bands };
  }
}
