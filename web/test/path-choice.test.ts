// The deformation path's timing (path-choice.ts): drawn at the lowest render scale (the scale
// back afterwards), a slow machine's frames cut short by the budget, the faster path chosen.
import { describe, expect, it, vi } from "vitest";
import { fasterOnCPU } from "../src/path-choice";

/** A viewer whose frames take `gpuMs` / `cpuMs` of deformation on a fake clock. */
function fake(gpuMs: number, cpuMs: number) {
  let now = 0;
  vi.spyOn(performance, "now").mockImplementation(() => now);
  const scales: number[] = [];
  const frames = { gpu: 0, cpu: 0 };
  const timed = {
    floor: 0.35, scaleNow: 0.8,
    scale: (scale: number) => { scales.push(scale); },
    draw: (_t: number, useCPU: boolean) => {
      const deformation = useCPU ? cpuMs : gpuMs;
      frames[useCPU ? "cpu" : "gpu"]++;
      expect(scales[scales.length - 1]).toBe(0.35); // every timed frame at the floor
      now += deformation + 5;
      return { deformation, drawing: 5 };
    },
  };
  return { timed, scales, frames };
}

describe("choosing the deformation path", () => {
  it("draws at the lowest scale, puts the scale back, and keeps the faster path", () => {
    const { timed, scales, frames } = fake(8, 3);
    expect(fasterOnCPU(timed)).toBe(true);
    expect(scales).toEqual([0.35, 0.8]);
    expect(frames).toEqual({ gpu: 4, cpu: 4 }); // a warm-up and three timed frames each
    expect(fasterOnCPU(fake(2, 3).timed)).toBe(false);
  });

  it("times fewer frames where each is slow", () => {
    const { timed, frames } = fake(400, 200);
    expect(fasterOnCPU(timed)).toBe(true);
    expect(frames).toEqual({ gpu: 2, cpu: 3 }); // 300 ms spent after one 400-ms frame
  });
});
