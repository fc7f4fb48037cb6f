// A live take as the motion hears it: a `Spectrum` that grows as the worklet's frames come
// (docs/design.md#live), its onsets, beats and tempo from `LiveRhythm`, and the stream's clock.
// Every view reads it as it reads a song's spectrogram, so meshes and rigs, the gallery and the
// player, the pulse and the tempo lock follow live input unchanged.
import type { Spectrum } from "./bundle";
import { BANDS, RATE, bandEdges } from "./live-analysis";
import type { Frame } from "./live-analysis";
import { LiveRhythm } from "./live-rhythm";

/** The longest take kept: beyond it a new take starts (30 min: 46 MB of band values). */
export const MAX_TAKE_SECONDS = 1800;
const FIRST_CAPACITY = 60 * RATE;

/** A spectrum that grows: `revision` changes with every new frame or event. */
export interface LiveSpectrum extends Spectrum {
  live: true;
  revision: number;
  /** the onset strength e_j of every frame (dB per frame, docs/design.md#rhythm) */
  onsetStrength: Float32Array;
}

export class LiveTake {
  readonly spectrum: LiveSpectrum;
  readonly rhythm = new LiveRhythm();

  constructor(readonly name: string, sampleRate: number) {
    this.spectrum = { name, rate: RATE, frames: 1, bands: BANDS, duration: 0,
      times: new Float32Array(FIRST_CAPACITY), values: new Float32Array(FIRST_CAPACITY * BANDS),
      bandEdges: Float32Array.from(bandEdges(sampleRate)), beats: new Float32Array(0),
      onsets: new Float32Array(0), downbeats: new Float32Array(0), sections: new Float32Array(0),
      tempo: 0, meter: 0, live: true, revision: 0,
      onsetStrength: new Float32Array(FIRST_CAPACITY) };
  }

  /** Seconds of audio analysed (the newest frame's time). */
  get seconds(): number { return this.spectrum.duration; }

  /** Whether the take is full (MAX_TAKE_SECONDS). */
  get full(): boolean { return this.spectrum.frames >= MAX_TAKE_SECONDS * RATE; }

  /** Add the worklet's frames (in order); frame j lands at j/RATE s. */
  add(frames: Frame[]): void {
    const s = this.spectrum;
    let events = false;
    for (const frame of frames) {
      const j = frame.index;
      if (j >= MAX_TAKE_SECONDS * RATE) break;
      if (j >= s.times.length) this.grow(2 * s.times.length);
      s.values.set(frame.values, j * s.bands);
      s.times[j] = j / RATE;
      s.onsetStrength[j] = frame.onset;
      s.frames = Math.max(s.frames, j + 1);
      events = this.rhythm.push(frame.onset, frame.beat) || events;
    }
    s.duration = (s.frames - 1) / RATE;
    if (events) {
      s.onsets = Float32Array.from(this.rhythm.onsets);
      s.beats = Float32Array.from(this.rhythm.beats);
    }
    s.tempo = this.rhythm.beats.length >= 4 ? this.rhythm.tempo : 0;
    s.revision++;
  }

  private grow(capacity: number): void {
    const s = this.spectrum;
    const times = new Float32Array(capacity);
    times.set(s.times);
    const strength = new Float32Array(capacity);
    strength.set(s.onsetStrength);
    s.onsetStrength = strength;
    const values = new Float32Array(capacity * s.bands);
    values.set(s.values);
    s.times = times;
    s.values = values;
  }
}
