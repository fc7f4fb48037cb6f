// The page completes a rig's palette as Python does (`resolve_palette`): every partial palette
// of tests/web/web_fixture_writer.py (PALETTES) against the palette Python resolved for the
// same rig (fixtures/palette.json) — the 40° cap on the selected modes' amplitudes and the time
// scale of the selected modes included.
import { readFileSync } from "node:fs";
import { join } from "node:path";
import { describe, expect, it } from "vitest";
import { defaultTimeScale, paletteOf } from "../src/palette";
import { rigFromBundle } from "../src/rig-bundle";

const folder = join(__dirname, "fixtures");
const data = readFileSync(join(folder, "rig.bin"));
const rig = rigFromBundle(data.buffer.slice(data.byteOffset, data.byteOffset + data.byteLength),
  "chain3");
const reference = JSON.parse(readFileSync(join(folder, "palette.json"), "utf8"));

describe("palette", () => {
  reference.cases.forEach((item: any) => {
    it(`completes ${JSON.stringify(item.modes)} as Python does`, () => {
      const palette = paletteOf(rig, item.modes);
      const expected = item.resolved;
      expect(palette.selected).toEqual(expected.selected);
      // float32 bundle arrays against float64 Python
      palette.amplitudes!.forEach((a, i) => expect(a).toBeCloseTo(expected.amplitudes[i], 6));
      palette.phases!.forEach((p, i) => expect(p).toBeCloseTo(expected.phases[i], 6));
      expect(palette.time_scale!).toBeCloseTo(expected.time_scale, 6);
    });
  });

  it("keeps a time scale of 1 that already fits, and centres modes spread too wide", () => {
    expect(defaultTimeScale([1, 2])).toBe(1);
    expect(defaultTimeScale([0.2, 0.4])).toBeCloseTo(4, 12); // 0.8 / 0.2
    expect(defaultTimeScale([0.1, 10])).toBeCloseTo(Math.sqrt((0.8 / 0.1) * (3.5 / 10)), 12);
  });
});
