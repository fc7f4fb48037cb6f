// The motion being shown: the current mesh's basis and song's spectrum, and from them the band
// values and per-mapping filter weights at any time t (docs/design.md#mapping). Shared by the views and
// the viewer, so the gain and the extra smoothing apply to the gallery and the player alike.
import type { Basis, Spectrum } from "./bundle";
import { filterValues, prepare, shaderWeights, smoothed, spectrumAt } from "./filter";
import type { Mapping, Prepared } from "./filter";

export class Motion {
  basis: Basis | null = null;
  spectrum: Spectrum | null = null;
  /** Scales every amplification (the header's *gain*). */
  gain = 1;
  private smoothing = 0;
  /** the spectrogram after the extra smoothing */
  private values: Float32Array | null = null;
  /** reused every frame: band values at the time being drawn */
  private bands = new Float32Array(1024);

  /** Whether there is something to draw. */
  get ready(): boolean { return this.basis !== null && this.spectrum !== null; }

  get duration(): number { return this.spectrum?.duration ?? 0; }

  setSpectrum(spectrum: Spectrum): void {
    this.spectrum = spectrum;
    this.values = smoothed(spectrum, this.smoothing);
  }

  /** Extra exponential smoothing of the spectrogram (time constant, s; 0: none). */
  setSmoothing(seconds: number): void {
    this.smoothing = seconds;
    if (this.spectrum) this.values = smoothed(this.spectrum, seconds);
  }

  /** Band values at time t; the array is reused by the next call. */
  bandValuesAt(t: number): Float32Array {
    const spectrum = this.spectrum!;
    if (this.bands.length < spectrum.bands) this.bands = new Float32Array(spectrum.bands);
    return spectrumAt(spectrum, t, this.bands.subarray(0, spectrum.bands),
      this.values ?? spectrum.values);
  }

  /** A mapping made ready for the current basis. */
  prepare(mapping: Mapping): Prepared { return prepare(mapping, this.basis!.k); }

  /** The deformation shader's weights (φ − 1) ⊙ X̃ of one mapping for these band values. */
  weights(prepared: Prepared, bandValues: Float32Array): Float32Array {
    return shaderWeights(this.basis!, filterValues(prepared, bandValues, this.gain));
  }
}
