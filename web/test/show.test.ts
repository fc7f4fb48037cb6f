// Show mode's timing (show-timing.ts: changes on the next bar, a cue's length in bars, the
// crossfade) and MIDI parsing (show-midi.ts), without a browser.
import { describe, expect, it } from "vitest";
import type { Spectrum } from "../src/bundle";
import { barStarts, boundaryAfter, cueEnd, fadeWeight, timesOf } from "../src/show-timing";
import { parseMidi } from "../src/show-midi";

// 120 BPM from 0.5 s: beats every 0.5 s
const beats = Float32Array.from({ length: 16 }, (_, i) => 0.5 + 0.5 * i);
const song = { beats } as unknown as Spectrum;
const withBars = { beats, downbeats: Float32Array.from([0.5, 2.5, 4.5, 6.5]),
  sections: Float32Array.from([4.5]) } as unknown as Spectrum;

describe("show timing", () => {
  it("changes on the next downbeat, else the next beat, else at once", () => {
    expect(boundaryAfter(withBars, 0.7)).toBeCloseTo(2.5);
    expect(boundaryAfter(song, 0.7)).toBeCloseTo(1.0);
    expect(boundaryAfter(song, 1.0)).toBeCloseTo(1.5); // on a beat: the next one
    expect(boundaryAfter({ beats: new Float32Array(0) } as unknown as Spectrum, 3.3)).toBe(3.3);
    expect(boundaryAfter(song, 99)).toBe(99);
    expect(boundaryAfter(null, 2)).toBe(2);
  });

  it("counts a cue's bars from its first bar start (4 beats without downbeats)", () => {
    expect(barStarts(song)).toEqual([0.5, 2.5, 4.5, 6.5]);
    expect(cueEnd(song, { until: "bars", bars: 1 }, 0)).toBeCloseTo(2.5);
    expect(cueEnd(song, { until: "bars", bars: 2 }, 2.5)).toBeCloseTo(6.5);
    expect(cueEnd(song, { until: "bars", bars: 9 }, 0)).toBeNull(); // past the song's bars
    expect(cueEnd(withBars, { until: "section", bars: 0 }, 1)).toBeCloseTo(4.5);
    expect(cueEnd(song, { until: "section", bars: 0 }, 1)).toBeNull(); // no sections yet
    expect(cueEnd(song, { until: "told", bars: 0 }, 1)).toBeNull();
  });

  it("reads downbeats and sections whatever holds them", () => {
    expect(timesOf({ downbeats: [1, 2] } as unknown as Spectrum, "downbeats")).toEqual([1, 2]);
    expect(timesOf({} as Spectrum, "sections")).toEqual([]);
    expect(timesOf({ sections: 3 } as unknown as Spectrum, "sections")).toEqual([]);
  });

  it("crossfades linearly over its length", () => {
    expect(fadeWeight(2, 1, 1.5)).toBe(0);
    expect(fadeWeight(2, 1, 2.25)).toBeCloseTo(0.25);
    expect(fadeWeight(2, 1, 9)).toBe(1);
    expect(fadeWeight(2, 0, 2)).toBe(1);
  });
});

describe("MIDI", () => {
  it("reads control changes and notes by channel", () => {
    expect(parseMidi([0xb0, 21, 127])).toEqual({ key: "cc:0:21", value: 1 });
    expect(parseMidi([0xb3, 7, 0])).toEqual({ key: "cc:3:7", value: 0 });
    expect(parseMidi([0x90, 60, 100])).toEqual({ key: "note:0:60", value: 1 });
    expect(parseMidi([0x90, 60, 0])).toEqual({ key: "note:0:60", value: 0 }); // note off
    expect(parseMidi([0x80, 60, 64])).toEqual({ key: "note:0:60", value: 0 });
    expect(parseMidi([0xf8])).toBeNull(); // clock
  });

  it("throws on a malformed message", () => {
    expect(() => parseMidi([])).toThrow();
    expect(() => parseMidi([21, 64])).toThrow(/status/);
    expect(() => parseMidi([0xb0, 21])).toThrow(/malformed/);
    expect(() => parseMidi([0xb0, 200, 3])).toThrow(/malformed/);
  });
});
