// The show's beat clock laid on the song time (show-grid.ts), without a browser.
import { describe, expect, it } from "vitest";
import type { Spectrum } from "../src/bundle";
import { beatLock, hasBeats } from "../src/beat-lock";
import { GridClock, gridOrigin, gridTimes } from "../src/show-grid";
import { boundaryAfter, cueEnd } from "../src/show-timing";

// 120 BPM, a downbeat at wall time 10 000 ms
const grid = { bpm: 120, beats_per_bar: 4, source: "tap" as const, downbeat: 10_000 };

describe("the show's beat clock", () => {
  it("lays the grid on the song time drawn", () => {
    // song time 3 s drawn at wall 11 200 ms: the downbeat was 1.2 s before, at song time 1.8
    const origin = gridOrigin(grid, 3, 11_200);
    expect(origin).toBeCloseTo(1.8);
    const { beats, downbeats } = gridTimes(grid, origin, 0, 4);
    expect(Array.from(beats)).toEqual([0.3, 0.8, 1.3, 1.8, 2.3, 2.8, 3.3, 3.8].map(Math.fround));
    expect(Array.from(downbeats)).toEqual([1.8, 3.8].map(Math.fround)); // (-0.2 is before 0)
  });

  it("gives the song's parts the grid's beats, tempo and bars, the rest the song's", () => {
    const song = { name: "kick", duration: 10, beats: Float32Array.from([0.1, 0.6]),
      downbeats: new Float32Array(0), tempo: 99, meter: 0, rate: 50 } as unknown as Spectrum;
    const clock = new GridClock();
    expect(clock.wrap(song)).toBe(song); // no grid: the song's own
    clock.set(grid);
    clock.frame(3, 11_200);
    const heard = clock.wrap(song)!;
    expect(clock.wrap(song)).toBe(heard); // the same object while nothing changes
    expect([heard.tempo, heard.meter, heard.rate, heard.name]).toEqual([120, 4, 50, "kick"]);
    expect(boundaryAfter(heard, 2.0)).toBeCloseTo(3.8); // the next downbeat: 1.8 + 2 s
    expect(cueEnd(heard, { until: "bars", bars: 1 }, 1.9)).toBeCloseTo(5.8);
    // the rigs' beat lock counts the grid's beats: whole at its beats, half way between
    expect(hasBeats(heard)).toBe(true);
    const onBeat = beatLock(heard, 3.8);
    expect(onBeat.tempo).toBe(120);
    expect(onBeat.phase - Math.round(onBeat.phase)).toBeCloseTo(0, 4);
    expect(beatLock(heard, 4.05).phase - onBeat.phase).toBeCloseTo(0.5, 4);
    clock.frame(3.001, 11_201); // the clock runs on: the same grid
    expect(clock.wrap(song)).toBe(heard);
    clock.frame(5, 11_300); // a seek: laid again
    expect(boundaryAfter(clock.wrap(song), 5.0)).toBeCloseTo(5.7);
    clock.set(null);
    expect(clock.wrap(song)).toBe(song);
  });
});
