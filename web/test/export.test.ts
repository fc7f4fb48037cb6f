// The export panel's window (export-panel.ts): from where the song is, 15 s by default, cut at
// the song's end; the clip's file name.
import { describe, expect, it } from "vitest";
import { CLIP_SECONDS, clipName, clipWindow } from "../src/export-panel";
import { fixedScale } from "../src/options";

describe("export window", () => {
  it("starts where the song is, for 15 s, cut at its end", () => {
    expect(CLIP_SECONDS).toBe(15);
    expect(clipWindow(12.345, 15, 180)).toEqual({ start: 12.35, duration: 15 });
    expect(clipWindow(170, 15, 180)).toEqual({ start: 170, duration: 10 });
    expect(clipWindow(-3, 15, 6)).toEqual({ start: 0, duration: 6 });
    expect(clipWindow(9, 15, 6)).toEqual({ start: 5.9, duration: 0.1 });
    expect(clipWindow(NaN, NaN, 30)).toEqual({ start: 0, duration: 15 });
  });

  it("names the clip by the model, where it starts and how long it lasts", () => {
    expect(clipName("cat_lowres.obj", 72.5, 15, "mp4")).toBe("cat_lowres-1m12s-15s.mp4");
    expect(clipName("my model (2).glb", 0, 4.25, "glb")).toBe("my-model-2-0m00s-4.3s.glb");
    expect(clipName("", 0, 1, "mp4")).toBe("dance-0m00s-1s.mp4");
  });
});

describe("?scale=", () => {
  it("fixes the render scale only for a number from 0.1 to 1", () => {
    expect(fixedScale("0.5")).toBe(0.5);
    expect(fixedScale("1")).toBe(1);
    for (const raw of [null, "", "0", "2", "x", "0.05"]) expect(fixedScale(raw)).toBeNull();
  });
});
