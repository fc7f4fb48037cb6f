// The browser's filter and binary parsing against numbers written by the Python reference
// (tests/web/web_fixture_writer.py → test/fixtures).
import { readFileSync } from "node:fs";
import { join } from "node:path";
import { describe, expect, it } from "vitest";
import { basisFromBundle, halfToFloat, parseBundle, spectrumFromBundle } from "../src/bundle";
import {
  deformCPU, filterValues, prepare, resampleAmplification, shaderWeights, smoothed, spectrumAt,
} from "../src/filter";
import type { Mapping } from "../src/filter";

const folder = join(__dirname, "fixtures");
const bytes = (name: string) => {
  const data = readFileSync(join(folder, name));
  return data.buffer.slice(data.byteOffset, data.byteOffset + data.byteLength);
};
const reference = JSON.parse(readFileSync(join(folder, "reference.json"), "utf8"));
const basis = basisFromBundle(parseBundle(bytes("basis.bin")));
const spectrum = spectrumFromBundle(parseBundle(bytes("spectrogram.bin")));

function expectClose(actual: ArrayLike<number>, expected: number[], tolerance: number): void {
  expect(actual.length).toBe(expected.length);
  let worst = 0;
  for (let i = 0; i < expected.length; i++) {
    worst = Math.max(worst, Math.abs(actual[i] - expected[i]));
  }
  expect(worst).toBeLessThanOrEqual(tolerance);
}

describe("binary bundles", () => {
  it("parses the basis", () => {
    expect(basis.n).toBe(reference.n);
    expect(basis.k).toBe(reference.k);
    expect(basis.k4).toBe(Math.ceil(reference.k / 4));
    expectClose(basis.vertices, reference.vertices, 1e-6);
    expectClose(basis.coefficients, reference.coefficients, 1e-6);
    expect(basis.faces.length % 3).toBe(0);
    expect(Math.max(...basis.faces)).toBe(basis.n - 1);
  });

  it("packs four harmonics per texel, zero padded", () => {
    const { n, k, k4 } = basis;
    const unpacked: number[] = [];
    for (let i = 0; i < n; i++) {
      for (let v = 0; v < k; v++) unpacked.push(basis.harmonics[i * 4 * k4 + v]);
      for (let v = k; v < 4 * k4; v++) expect(basis.harmonics[i * 4 * k4 + v]).toBe(0);
    }
    expectClose(unpacked, reference.eigenvectors, 1e-6);
  });

  it("parses the spectrogram", () => {
    expect(spectrum.bands).toBe(reference.bands);
    expect(spectrum.frames).toBe(reference.frames);
    expect(spectrum.rate).toBe(100);
    expect(spectrum.bandEdges.length).toBe(reference.bands + 1);
  });

  it("decodes float16 harmonics", () => {
    expect([0x3c00, 0xc000, 0x7bff, 0x0001, 0x0000, 0x8000].map(halfToFloat))
      .toEqual([1, -2, 65504, 2 ** -24, 0, -0]);
    const half = basisFromBundle(parseBundle(bytes("basis16.bin")));
    expect(half.n).toBe(basis.n);
    let worst = 0;
    basis.harmonics.forEach((x, i) => {
      worst = Math.max(worst, Math.abs(half.harmonics[i] - x) / Math.max(Math.abs(x), 2 ** -14));
    });
    expect(worst).toBeLessThanOrEqual(2 ** -11);
    expectClose(half.vertices, reference.vertices, 1e-6);
  });

  it("rejects what is not a bundle", () => {
    expect(() => parseBundle(new TextEncoder().encode("nonsense!").buffer)).toThrow();
  });
});

describe("filter (docs/design.md#mapping)", () => {
  it("interpolates the spectrogram between frames like Spectrogram.at", () => {
    reference.times.forEach((t: number, i: number) => {
      expectClose(spectrumAt(spectrum, t), reference.values[i], 1e-6);
    });
  });

  it("computes φ like Mapping.filter, including amplification resampling", () => {
    for (const c of reference.cases) {
      const prepared = prepare(c.mapping as Mapping, basis.k);
      reference.times.forEach((_: number, i: number) => {
        expectClose(filterValues(prepared, reference.values[i]), c.phi[i], 1e-9);
      });
    }
  });

  it("deforms like HarmonicBasis.filter_positions (CPU path, shader weights)", () => {
    for (const c of reference.cases) {
      const prepared = prepare(c.mapping as Mapping, basis.k);
      reference.times.forEach((t: number, i: number) => {
        const phi = filterValues(prepared, spectrumAt(spectrum, t));
        const positions = deformCPU(basis, shaderWeights(basis, phi));
        expectClose(positions, c.positions[i], 2e-6);
      });
    }
  });

  it("gain scales the motion; a ≡ 0 gives the rest shape", () => {
    const mapping = reference.cases[0].mapping as Mapping;
    const still = prepare({ ...mapping, amplification: mapping.amplification.map(() => 0) },
      basis.k);
    const phi = filterValues(still, reference.values[2]);
    expect(Array.from(phi).every((x) => x === 1)).toBe(true);
    expectClose(deformCPU(basis, shaderWeights(basis, phi)), reference.vertices, 1e-6);
    const prepared = prepare(mapping, basis.k);
    const one = filterValues(prepared, reference.values[2], 1);
    const two = filterValues(prepared, reference.values[2], 2);
    one.forEach((x, v) => expect(two[v] - 1).toBeCloseTo(2 * (x - 1), 12));
  });

  it("extra smoothing: τ = 0 leaves the spectrogram unchanged, τ > 0 lags it", () => {
    expect(smoothed(spectrum, 0)).toBe(spectrum.values);
    const lagged = smoothed(spectrum, 0.2);
    expect(lagged.length).toBe(spectrum.values.length);
    expect(Math.max(...lagged)).toBeLessThanOrEqual(Math.max(...spectrum.values) + 1e-6);
    // A step of loudness 1 in one band (the other silent) at 10 frames/s, τ = 0.1 s: the pole
    // m = exp(−1/(10·0.1)) = 1/e, so frame j reads 1 − e^−(j+1) (by hand: y_j = m·y_(j−1) +
    // (1 − m)·1 from y_(−1) = 0) — 0.632, 0.865, 0.950 — where a pass-through reads 1.
    const step = { ...spectrum, rate: 10, frames: 3, bands: 2,
                   values: Float32Array.from([1, 0, 1, 0, 1, 0]) };
    expectClose(smoothed(step, 0.1), [1 - Math.exp(-1), 0, 1 - Math.exp(-2), 0,
                                      1 - Math.exp(-3), 0], 1e-6);
  });

  it("resamples amplification by normalised index", () => {
    expect(Array.from(resampleAmplification([1, 2, 3], 6))).toEqual([1, 1, 2, 2, 3, 3]);
    expect(Array.from(resampleAmplification([1, 2, 3, 4], 2))).toEqual([2, 4]);
  });
});
