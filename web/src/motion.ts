// The motion being shown: the current mesh's basis and song's spectrum, and from them the band
// values and per-mapping filter weights at any time t (docs/design.md#mapping). Every setting
// that changes the motion (gain, extra smoothing) belongs to the mapping (`Prepared`), so what a
// tile or the player shows is what its saved mapping gives `eigendance animate`.
import type { Basis, Spectrum } from "./bundle";
import { filterValues, prepare, shaderWeights, smoothed, spectrumAt } from "./filter";
import type { Mapping, Prepared } from "./filter";

/** Smoothed spectrograms kept (each is frames × bands floats): the slider visits many τ. */
const SMOOTHED_KEPT = 4;

export class Motion {
  basis: Basis | null = null;
  spectrum: Spectrum | null = null;
  /** the spectrogram after extra smoothing τ (s), most recently used last */
  private smoothedValues = new Map<number, Float32Array>();
  /** reused every frame: band values at the time being drawn, one buffer per τ */
  private buffers = new Map<number, Float32Array>();
  private loudest: { spectrum: Spectrum; count: number; times: number[] } | null = null;

  /** Whether there is something to draw. */
  get ready(): boolean { return this.basis !== null && this.spectrum !== null; }

  get songLoaded(): boolean { return this.spectrum !== null; }

  get duration(): number { return this.spectrum?.duration ?? 0; }

  setSpectrum(spectrum: Spectrum): void {
    this.spectrum = spectrum;
    this.smoothedValues.clear();
  }

  /** Band values at time t after extra smoothing τ (s; 0: none); the array is reused by the
   * next call with the same τ. */
  bandValuesAt(t: number, smoothing = 0): Float32Array {
    const spectrum = this.spectrum!;
    let buffer = this.buffers.get(smoothing);
    if (!buffer || buffer.length !== spectrum.bands) {
      buffer = new Float32Array(spectrum.bands);
      this.buffers.set(smoothing, buffer);
      if (this.buffers.size > SMOOTHED_KEPT + 1) {
        this.buffers.delete(this.buffers.keys().next().value!);
      }
    }
    return spectrumAt(spectrum, t, buffer, this.valuesFor(smoothing));
  }

  /** The times (s) of the song's `count` loudest frames (sum over the bands), at least a
   * quarter of a second apart: the poses a model is framed in. */
  loudestTimes(count: number): number[] {
    const spectrum = this.spectrum!;
    if (this.loudest?.spectrum === spectrum && this.loudest.count === count) {
      return this.loudest.times;
    }
    const { frames, bands, values, rate } = spectrum;
    const total = new Float64Array(frames);
    for (let j = 0; j < frames; j++) {
      for (let b = 0; b < bands; b++) total[j] += values[j * bands + b];
    }
    const order = Array.from({ length: frames }, (_, j) => j).sort((a, b) => total[b] - total[a]);
    const times: number[] = [];
    for (const j of order) {
      if (times.length === count) break;
      if (times.every((t) => Math.abs(t - j / rate) >= 0.25)) times.push(j / rate);
    }
    this.loudest = { spectrum, count, times };
    return times;
  }

  /** A mapping made ready for the current basis. */
  prepare(mapping: Mapping): Prepared { return prepare(mapping, this.basis!.k); }

  /** The deformation shader's weights (φ − 1) ⊙ X̃ of one mapping at time t. */
  weights(prepared: Prepared, t: number): Float32Array {
    const phi = filterValues(prepared, this.bandValuesAt(t, prepared.smoothing));
    return shaderWeights(this.basis!, phi);
  }

  private valuesFor(smoothing: number): Float32Array {
    const spectrum = this.spectrum!;
    if (!(smoothing > 0)) return spectrum.values;
    let values = this.smoothedValues.get(smoothing);
    if (values) {
      this.smoothedValues.delete(smoothing); // most recently used goes last
    } else {
      values = smoothed(spectrum, smoothing);
      if (this.smoothedValues.size >= SMOOTHED_KEPT) {
        this.smoothedValues.delete(this.smoothedValues.keys().next().value!);
      }
    }
    this.smoothedValues.set(smoothing, values);
    return values;
  }
}
