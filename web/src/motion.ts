// The motion being shown: the current mesh's basis and song's spectrum, and from them the band
// values and per-mapping filter weights at any time t (docs/design.md#mapping). Every setting
// that changes the motion (gain, extra smoothing) belongs to the mapping (`Prepared`), so what a
// tile or the player shows is what its saved mapping gives `eigendance animate`.
import type { Basis, Spectrum } from "./bundle";
import {
  filterValues, kickAt, prepare, pulseAccents, pulseEvents, sectionGain, shapeValues,
  shaderWeights, smoothed, spectrumAt,
} from "./filter";
import type { Envelope, Mapping, Prepared } from "./filter";
import { StreamShaper } from "./live-shaping";
import type { LiveSpectrum } from "./live-take";

/** Smoothed spectrograms kept (each is frames × bands floats): the slider visits many τ. */
const SMOOTHED_KEPT = 4;

interface Heard {
  spectrum: Spectrum;
  values: Float32Array;
  buffer: Float32Array;
  events: Float32Array;
  /** each event's kick strength (a bar's first beat is accented: `pulseAccents`) */
  accents: Float32Array;
  /** a live take's: the shaping carried on frame by frame, and the revision heard */
  shaper?: StreamShaper;
  revision?: number;
}

const isLive = (spectrum: Spectrum): spectrum is LiveSpectrum =>
  (spectrum as LiveSpectrum).live === true;

export class Motion {
  basis: Basis | null = null;
  spectrum: Spectrum | null = null;
  /** the spectrogram as mappings hear it (smoothing τ, envelope), by `Envelope.key`, most
   * recently used last */
  private smoothedValues = new Map<string, Float32Array>();
  /** reused every frame: the raw band values at the time being drawn */
  private buffer = new Float32Array(0);
  /** per prepared mapping (one lookup a frame): the values it hears, its band-values buffer
   * and the events its pulse kicks on, with their strengths */
  private heard = new WeakMap<Prepared, Heard>();
  private loudest: { spectrum: Spectrum; count: number; times: number[] } | null = null;

  /** Whether there is something to draw. */
  get ready(): boolean { return this.basis !== null && this.spectrum !== null; }

  get songLoaded(): boolean { return this.spectrum !== null; }

  get duration(): number { return this.spectrum?.duration ?? 0; }

  setSpectrum(spectrum: Spectrum): void {
    this.spectrum = spectrum;
    this.smoothedValues.clear();
  }

  /** Band values at time t as a mapping hears them (its smoothing and envelope; none: the
   * spectrogram itself); the array is reused by the next call with the same shaping. */
  bandValuesAt(t: number, prepared?: Prepared): Float32Array {
    const spectrum = this.spectrum!;
    if (prepared) {
      const heard = this.heardBy(prepared);
      return spectrumAt(spectrum, t, heard.buffer, heard.values);
    }
    if (this.buffer.length !== spectrum.bands) this.buffer = new Float32Array(spectrum.bands);
    return spectrumAt(spectrum, t, this.buffer, spectrum.values);
  }

  /** The mapping's section gene's gain factor at time t (1 without; `sectionGain`). */
  sectionGain(prepared: Prepared, t: number): number {
    return this.spectrum ? sectionGain(prepared, this.spectrum.sections, t) : 1;
  }

  /** amount·p(t) of a mapping's pulse on the song's beats or onsets (0 without). */
  kick(prepared: Prepared, t: number): number {
    if (!(prepared.pulse.amount > 0) || !this.spectrum) return 0;
    const heard = this.heardBy(prepared);
    return kickAt(prepared.pulse, heard.events, t, heard.accents);
  }

  private heardBy(prepared: Prepared): Heard {
    const spectrum = this.spectrum!;
    let heard = this.heard.get(prepared);
    if (!heard || heard.spectrum !== spectrum) {
      const live = isLive(spectrum);
      const events = pulseEvents(spectrum, prepared.pulse);
      heard = { spectrum, values: live ? spectrum.values : this.valuesFor(prepared),
        buffer: new Float32Array(spectrum.bands), events,
        accents: pulseAccents(spectrum, prepared.pulse, events) };
      if (live && (prepared.smoothing > 0 || !prepared.envelope.identity)) {
        heard.shaper = new StreamShaper(spectrum.bands, spectrum.rate, prepared.smoothing,
          prepared.envelope);
      }
      this.heard.set(prepared, heard);
    }
    if (isLive(spectrum) && heard.revision !== spectrum.revision) {
      // a live take grows: what it heard since, shaped from where it stopped
      heard.revision = spectrum.revision;
      heard.values = heard.shaper ? heard.shaper.extend(spectrum.values, spectrum.frames)
        : spectrum.values;
      heard.events = pulseEvents(spectrum, prepared.pulse);
      heard.accents = pulseAccents(spectrum, prepared.pulse, heard.events);
    }
    return heard;
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
    const phi = filterValues(prepared, this.bandValuesAt(t, prepared),
      prepared.gain * this.sectionGain(prepared, t), undefined,
      this.kick(prepared, t));
    return shaderWeights(this.basis!, phi);
  }

  private valuesFor(prepared: Prepared): Float32Array {
    const spectrum = this.spectrum!;
    const envelope: Envelope = prepared.envelope;
    if (!(prepared.smoothing > 0) && envelope.identity) return spectrum.values;
    let values = this.smoothedValues.get(envelope.key);
    if (values) {
      this.smoothedValues.delete(envelope.key); // most recently used goes last
    } else {
      values = shapeValues(smoothed(spectrum, prepared.smoothing), spectrum.frames,
        spectrum.bands, spectrum.rate, envelope);
      if (this.smoothedValues.size >= SMOOTHED_KEPT) {
        this.smoothedValues.delete(this.smoothedValues.keys().next().value!);
      }
    }
    this.smoothedValues.set(envelope.key, values);
    return values;
  }
}
