// The live analysis (src/live-analysis.ts, docs/design.md#live) against the offline definition:
// the spectrogram and onset envelope that the Python reference computes for the same signal at
// 44.1, 48 and 96 kHz (tests/web/web_fixture_writer.py `live_reference` → fixtures/live.json),
// fed block by block as the AudioWorklet feeds it; and the live shaping and rhythm.
import { readFileSync } from "node:fs";
import { join } from "node:path";
import { describe, expect, it } from "vitest";
import { envelopeOf, shapeValues, smoothed } from "../src/filter";
import type { Mapping } from "../src/filter";
import { LiveAnalyser } from "../src/live-analysis";
import type { Frame } from "../src/live-analysis";
import { LiveRhythm } from "../src/live-rhythm";
import { StreamShaper } from "../src/live-shaping";

const reference = JSON.parse(readFileSync(join(__dirname, "fixtures", "live.json"), "utf8"));

/** web_fixture_writer.live_signal: the same formula. */
function signal(rate: number, seconds = 1): Float32Array {
  return Float32Array.from({ length: Math.floor(seconds * rate) }, (_, n) => {
    const t = n / rate;
    return 0.4 * Math.sin(2 * Math.PI * 220 * t)
      + (t >= 0.3 ? 0.2 * Math.sin(2 * Math.PI * (300 * t + 2000 * t * t)) : 0)
      + (t >= 0.6 ? 0.1 * Math.sin(2 * Math.PI * 6000 * t) : 0);
  });
}

/** Every frame of `samples` in 128-sample blocks, then zeros until the last frame is out. */
function analyse(rate: number, samples: Float32Array): Frame[] {
  const analyser = new LiveAnalyser(rate);
  const frames: Frame[] = [];
  const padded = new Float32Array(samples.length + analyser.N);
  padded.set(samples);
  for (let i = 0; i < padded.length; i += 128) frames.push(...analyser.push(padded.subarray(i, i + 128)));
  return frames;
}

describe("live analysis = offline spectrogram", () => {
  for (const c of reference.cases) {
    it(`matches at ${c.sample_rate} Hz`, () => {
      const frames = analyse(c.sample_rate, signal(c.sample_rate));
      const analyser = new LiveAnalyser(c.sample_rate);
      analyser.edges.forEach((edge, i) => expect(edge).toBeCloseTo(c.edges[i], 6));
      let values = 0, onset = 0, beat = 0;
      c.frames.forEach((j: number, i: number) => {
        expect(frames[j].index).toBe(j);
        frames[j].values.forEach((v, b) => { values = Math.max(values, Math.abs(v - c.values[i][b])); });
        onset = Math.max(onset, Math.abs(frames[j].onset - c.onset[i]));

      });
      expect(values).toBeLessThan(1e-4); // float32 rounding of the offline analysis
      expect(onset).toBeLessThan(1e-2); // dB per frame, of values up to tens
      // The tempo's envelope: librosa's onset strength (BeatFeatures) of the same signal, which
      // lags it by 2 frames (librosa's centring compensation) and resamples to 22050 Hz first.
      const live = frames.flatMap((f) => f.beat.map(([median]) => median));
      c.beat.forEach((value: number, t: number) => {
        if (t >= 3 && t - 2 < live.length) beat = Math.max(beat, Math.abs(live[t - 2] - value));
      });
      expect(beat).toBeLessThan(1.5); // dB per frame, of values up to ~20 (no resampling here)
    });
  }
});

describe("live shaping", () => {
  it("carries on the offline smoothing and envelope frame by frame", () => {
    const B = 4, frames = 300, rate = 100;
    const values = Float32Array.from({ length: frames * B }, (_, i) => 0.5 + 0.5 * Math.sin(i * 0.37));
    const mapping = { smoothing: 0.05, envelope: { attack: 0.02, release: [0.1, 0.2, 0, 0.3],
      threshold: 0.2 } } as unknown as Mapping;
    const envelope = envelopeOf(mapping, B);
    const spectrum = { rate, frames, bands: B, values } as never;
    const offline = shapeValues(smoothed(spectrum, 0.05), frames, B, rate, envelope);
    const shaper = new StreamShaper(B, rate, 0.05, envelope);
    for (const stop of [1, 50, 51, 200, 300]) shaper.extend(values, stop); // as frames come
    for (let i = 0; i < frames * B; i++) expect(shaper.out[i]).toBeCloseTo(offline[i], 5);
  });
});

describe("live rhythm", () => {
  it("finds the onsets and the tempo of clicks at 120 BPM", () => {
    const rhythm = new LiveRhythm();
    // librosa's onset strength (22050/512 frames per second, placed 2 frames later: its
    // centring) with a click every 0.5 s as well.
    const beatRate = 22050 / 512;
    let k = 0;
    for (let j = 0; j < 1500; j++) {
      const beat: [number, number][] = [];
      for (; k < ((j + 1) * beatRate) / 100; k++) {
        const t = (k + 2) / beatRate;
        const value = Math.abs(((t - 0.1 + 0.25) % 0.5) - 0.25) < 0.5 / beatRate ? 20 : 0.1;
        beat.push([value, value]);
      }
      rhythm.push(j % 50 === 10 ? 20 : j % 50 === 11 ? 5 : 0.1, beat);
    }
    expect(Math.abs(rhythm.tempo - 120)).toBeLessThan(0.04 * 120); // librosa's lag grid: 117.5
    const expected = Array.from({ length: 29 }, (_, i) => 0.1 + 0.5 * i);
    for (const t of expected) expect(Math.min(...rhythm.onsets.map((o) => Math.abs(o - t)))).toBeLessThan(0.024);
    const late = rhythm.beats.filter((b) => b > 5);
    expect(late.length).toBeGreaterThan(15);
    for (const b of late) expect(Math.abs(((b - 0.1 + 0.25) % 0.5) - 0.25)).toBeLessThan(0.021);
  });
});
