// The page's rig motion (modal-skin.ts) against numbers written by the Python reference
// (tests/web/web_fixture_writer.py → test/fixtures/rig.*): the palette, the filter with offset
// b, the mode coefficients of `rig_coefficients`, modal skinning through the positions pass's
// weights (CPU path) and the body poses.
import { readFileSync } from "node:fs";
import { join } from "node:path";
import { describe, expect, it } from "vitest";
import { parseBundle, spectrumFromBundle } from "../src/bundle";
import { beatLock, hasBeats } from "../src/beat-lock";
import { deformCPU, shapeValues, smoothed, spectrumAt } from "../src/filter";
import type { Mapping } from "../src/filter";
import { bodyMatrices, modalWeights, modeDrive, prepareRig, rigCoefficients } from "../src/modal-skin";
import { rigBasis, rigFromBundle, toFileUnits } from "../src/rig-bundle";

const folder = join(__dirname, "fixtures");
const bytes = (name: string) => {
  const data = readFileSync(join(folder, name));
  return data.buffer.slice(data.byteOffset, data.byteOffset + data.byteLength);
};
const reference = JSON.parse(readFileSync(join(folder, "rig.json"), "utf8"));
const rig = rigFromBundle(bytes("rig.bin"), "chain3");
const spectrum = spectrumFromBundle(parseBundle(bytes("spectrogram.bin")));

function worst(actual: ArrayLike<number>, expected: number[]): number {
  expect(actual.length).toBe(expected.length);
  let largest = 0;
  for (let i = 0; i < expected.length; i++) {
    largest = Math.max(largest, Math.abs(actual[i] - expected[i]));
  }
  return largest;
}

describe("rig motion", () => {
  it("reads the rig bundle", () => {
    expect([rig.n, rig.k, rig.G, rig.b]).toEqual([288, 6, 2, 3]);
    expect(rig.tau.length).toBe(rig.n * rig.G * 12);
  });

  reference.cases.forEach((item: any, index: number) => {
    const mapping = item.mapping as Mapping;
    const prepared = prepareRig(rig, mapping);
    const basis = rigBasis(rig);
    const shaped = shapeValues(smoothed(spectrum, prepared.smoothing), spectrum.frames,
      spectrum.bands, spectrum.rate, prepared.envelope); // the default mapping's swell
    reference.times.forEach((t: number, i: number) => {
      it(`case ${index}, t = ${t}: coefficients, modal skinning, body poses`, () => {
        const bands = spectrumAt(spectrum, t, undefined, shaped);
        const beat = prepared.tempo !== "free" && hasBeats(spectrum)
          ? beatLock(spectrum, t) : undefined;
        const c = rigCoefficients(rig, prepared, modeDrive(prepared, bands), t, undefined, beat);
        const scale = Math.max(...item.coefficients.flat().map(Math.abs));
        expect(worst(c, item.coefficients[i])).toBeLessThan(2e-5 * scale);
        const positions = toFileUnits(rig, deformCPU(basis, modalWeights(rig, c)));
        expect(worst(positions, item.positions[i])).toBeLessThan(1e-5 * rig.diagonal);
        const matrices = bodyMatrices(rig, c);
        const rotations: number[] = [], centres: number[] = [];
        for (let b = 0; b < rig.b; b++) {
          for (let r = 0; r < 3; r++) {
            for (let col = 0; col < 3; col++) rotations.push(matrices[16 * b + 4 * col + r]);
            centres.push(matrices[16 * b + 12 + r]);
          }
        }
        expect(worst(rotations, item.rotations[i])).toBeLessThan(1e-5);
        expect(worst(centres, item.centres[i])).toBeLessThan(1e-5 * rig.diagonal);
      });
    });
  });

  it("sorts a palette given out of order, its amplitudes and phases following", () => {
    const prepared = prepareRig(rig, reference.cases[1].mapping);
    expect(Array.from(prepared.selected)).toEqual([1, 4]);
    // the same palette given in order: the same amplitudes (0.2 and 0.3, then kept above the
    // floor: floor.ts)
    const sorted = prepareRig(rig, { ...reference.cases[1].mapping, modes: {
      ...reference.cases[1].mapping.modes, selected: [1, 4], amplitudes: [0.2, 0.3],
      phases: [2.5, 1.0] } });
    expect(Array.from(prepared.amplitudes)).toEqual(Array.from(sorted.amplitudes));
    expect(prepared.amplitudes[0]).toBeLessThanOrEqual(0.2);
    expect(Array.from(prepared.phases)).toEqual([2.5, 1.0]);
    expect(prepared.timeScale).toBe(0.7);
  });

  it("plays φ ≡ 1 with the music off", () => {
    const prepared = prepareRig(rig, reference.cases[0].mapping, false);
    expect(Array.from(modeDrive(prepared, spectrumAt(spectrum, 1)))).toEqual(
      new Array(prepared.k).fill(1));
  });
});
