// The rhythm half of the page against numbers written by the Python reference
// (tests/web/web_fixture_writer.py `rhythm_reference` → test/fixtures/rhythm.*): the spectrogram
// bundle's beats, the version-3 envelope and pulse of the filter, the beat phase and the rig
// motion locked to the beats (docs/design.md#rhythm, #mapping, #tempo-lock).
import { readFileSync } from "node:fs";
import { join } from "node:path";
import { describe, expect, it } from "vitest";
import { parseBundle, spectrumFromBundle } from "../src/bundle";
import { beatLock, beatPhase, DOWNBEAT_ACCENT, hasBeats } from "../src/beat-lock";
import {
  filterValues, kickAt, prepare, pulseAccents, pulseEvents, shapeValues, smoothed, spectrumAt,
} from "../src/filter";
import type { Mapping } from "../src/filter";
import { prepareRig, rigCoefficients, modeDrive } from "../src/modal-skin";
import { rigFromBundle } from "../src/rig-bundle";

const folder = join(__dirname, "fixtures");
const bytes = (name: string) => {
  const data = readFileSync(join(folder, name));
  return data.buffer.slice(data.byteOffset, data.byteOffset + data.byteLength);
};
const reference = JSON.parse(readFileSync(join(folder, "rhythm.json"), "utf8"));
const song = spectrumFromBundle(parseBundle(bytes("rhythm.bin")));
const rig = rigFromBundle(bytes("rig.bin"), "chain");

function worst(actual: ArrayLike<number>, expected: number[]): number {
  expect(actual.length).toBe(expected.length);
  let largest = 0;
  for (let i = 0; i < expected.length; i++) {
    largest = Math.max(largest, Math.abs(actual[i] - expected[i]));
  }
  return largest;
}

describe("rhythm in the spectrogram bundle", () => {
  it("carries the beats and the tempo", () => {
    expect(hasBeats(song)).toBe(true);
    expect(song.tempo).toBeCloseTo(reference.tempo, 9);
    expect(worst(song.beats, reference.beats)).toBeLessThanOrEqual(1e-6);
  });

  it("counts beats continuously like Rhythm.beat_phase", () => {
    const phase = reference.times.map((t: number) => beatPhase(song.beats, t));
    expect(worst(phase, reference.phase)).toBeLessThanOrEqual(1e-5); // float32 beat times
  });

  it("accents the bar's first beat like Rhythm.downbeat_accent", () => {
    const accent = reference.times.map((t: number) => beatLock(song, t).accent);
    expect(worst(accent, reference.accent)).toBeLessThanOrEqual(1e-5);
    expect(Math.max(...accent)).toBeGreaterThan(1.1); // the fixture's times reach near a downbeat
  });
});

describe("version-3 mappings (envelope, auto-range, pulse)", () => {
  reference.cases.forEach((c: { mapping: Mapping; phi: number[][]; shaped: number[][] },
    index: number) => {
    const prepared = prepare(c.mapping, c.phi[0].length);
    const shaped = shapeValues(smoothed(song, prepared.smoothing), song.frames, song.bands,
      song.rate, prepared.envelope);

    it(`shapes the spectrogram like Mapping.shaped (case ${index})`, () => {
      const step = reference.frames_step;
      c.shaped.forEach((row, i) => {
        expect(worst(shaped.subarray(i * step * song.bands, (i * step + 1) * song.bands), row))
          .toBeLessThanOrEqual(1e-6);
      });
    });

    it(`plays φ with the pulse like Mapping.play (case ${index})`, () => {
      const events = pulseEvents(song, prepared.pulse);
      const accents = pulseAccents(song, prepared.pulse, events);
      reference.times.forEach((t: number, i: number) => {
        const values = spectrumAt(song, t, undefined, shaped);
        const phi = filterValues(prepared, values, prepared.gain, undefined,
          kickAt(prepared.pulse, events, t, accents));
        const scale = Math.max(1, ...c.phi[i].map(Math.abs));
        expect(worst(phi, c.phi[i]) / scale).toBeLessThanOrEqual(2e-5); // float32 event times
      });
    });
  });
});

describe("the beat pulse on the bars", () => {
  it("kicks a bar's first beat 1 + DOWNBEAT_ACCENT times harder, like Pulse.signal", () => {
    const prepared = prepare(reference.cases[0].mapping, reference.cases[0].phi[0].length);
    expect(prepared.pulse.source).toBe("beats");
    const events = pulseEvents(song, prepared.pulse);
    const accents = pulseAccents(song, prepared.pulse, events);
    const kicks = reference.kick_times.map((t: number) =>
      kickAt(prepared.pulse, events, t, accents));
    expect(worst(kicks, reference.kicks) / Math.max(...reference.kicks))
      .toBeLessThanOrEqual(1e-5); // float32 beat times
    // 10 ms after every beat: the bars' first beats kick 1.25 times the others
    expect(DOWNBEAT_ACCENT).toBe(0.25);
    expect(Math.max(...kicks) / Math.min(...kicks)).toBeCloseTo(1.25, 4);
  });
});

describe("rig motion locked to the beats", () => {
  reference.rig_cases.forEach((c: { mapping: Mapping; coefficients: number[][] }, index: number) => {
    it(`gives rig_coefficients' numbers (${c.mapping.modes ? (c.mapping.modes as any).tempo ?? "beat" : ""}, case ${index})`, () => {
      const prepared = prepareRig(rig, c.mapping);
      const shaped = shapeValues(smoothed(song, prepared.smoothing), song.frames, song.bands,
        song.rate, prepared.envelope);
      const events = pulseEvents(song, prepared.pulse);
      const accents = pulseAccents(song, prepared.pulse, events);
      const locked = prepared.tempo !== "free" && hasBeats(song);
      reference.times.forEach((t: number, i: number) => {
        const phi = modeDrive(prepared, spectrumAt(song, t, undefined, shaped),
          kickAt(prepared.pulse, events, t, accents));
        const beat = locked ? beatLock(song, t) : undefined;
        const coefficients = rigCoefficients(rig, prepared, phi, t, undefined, beat);
        expect(worst(coefficients, c.coefficients[i])).toBeLessThanOrEqual(2e-5);
      });
    });
  });
});
