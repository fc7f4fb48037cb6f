// Dynamic resolution (resolution.ts) on a fake clock: down in steps aimed at the target, to the
// floor, then fewer triangles; back up with hysteresis, the triangles first; nothing while the
// song is paused. And the level of detail (detail.ts): fewer triangles over the same vertices.
import * as THREE from "three";
import { mergeVertices } from "three/examples/jsm/utils/BufferGeometryUtils.js";
import { describe, expect, it } from "vitest";
import { detailReady, simplifiedFaces } from "../src/detail";
import { RESOLUTION, ResolutionGovernor } from "../src/resolution";

/** Feed `fps` every 250 ms for `seconds`, from `start` (ms); the time reached. */
function run(governor: ResolutionGovernor, fps: number, seconds: number, start = 0): number {
  let now = start;
  for (; now < start + 1000 * seconds; now += 250) governor.update(fps, now, true);
  return now;
}

describe("dynamic resolution", () => {
  it("goes down to the floor, then draws fewer triangles, and says so", () => {
    const governor = new ResolutionGovernor();
    let now = run(governor, 2, 1.1);
    // the first step straight to the aim (it was 0.6 at most): 0.95 √(2 / 12) = 0.39, in 5% steps
    expect(governor.scale).toBe(0.4);
    expect(governor.describe()).toBe("drawing at 40% resolution to keep 12 fps");
    now = run(governor, 3, 2.3, now); // then 0.4 × 0.6 = 0.24: the floor
    expect(governor.scale).toBeCloseTo(RESOLUTION.floor, 12);
    now = run(governor, 3, 10, now);
    expect(governor.scale).toBeCloseTo(RESOLUTION.floor, 12);
    expect(governor.detail).toBe(0.25);
    expect(governor.exhausted).toBe(true);
    expect(governor.describe()).toBe(
      "drawing at 35% resolution and 25% of the triangles to keep 12 fps");
  });

  it("aims at the target: a page just below it loses a step, not half its pixels", () => {
    const governor = new ResolutionGovernor();
    run(governor, 11, 1.1);
    expect(governor.scale).toBe(0.9);
  });

  it("holds a frame rate between the target and the hysteresis", () => {
    const governor = new ResolutionGovernor();
    let now = run(governor, 6, 1.1);
    const scale = governor.scale;
    now = run(governor, 15, 20, now); // above 12, below 1.6 × 12
    expect(governor.scale).toBe(scale);
  });

  it("goes back up with room to spare, the triangles first", () => {
    const governor = new ResolutionGovernor();
    let now = run(governor, 3, 12);
    expect(governor.exhausted).toBe(true);
    now = run(governor, 20, 4, now); // 1.6 × 12 < 20 < 2.2 × 12: the triangles stay
    expect([governor.detail, governor.scale]).toEqual([0.25, RESOLUTION.floor]);
    now = run(governor, 30, 4.5, now);
    expect(governor.detail).toBe(0.5);
    now = run(governor, 60, 60, now);
    expect([governor.detail, governor.scale]).toEqual([1, 1]);
    expect(governor.describe()).toBeNull();
  });

  it("does nothing while paused or without a measurement", () => {
    const governor = new ResolutionGovernor();
    for (let now = 0; now < 5000; now += 250) {
      governor.update(2, now, false);
      governor.update(0, now + 1, true);
    }
    expect(governor.scale).toBe(1);
  });
});

describe("level of detail", () => {
  it("draws fewer triangles over the same vertices", async () => {
    const geometry = mergeVertices(new THREE.IcosahedronGeometry(1, 12).deleteAttribute("normal")
      .deleteAttribute("uv"));
    const vertices = geometry.getAttribute("position").array as Float32Array;
    const faces = Uint32Array.from(geometry.index!.array);
    await detailReady();
    for (const fraction of [0.5, 0.25]) {
      const coarse = simplifiedFaces(faces, vertices, fraction)!;
      expect(coarse.length % 3).toBe(0);
      expect(coarse.length).toBeLessThanOrEqual(fraction * faces.length + 3);
      expect(coarse.length).toBeGreaterThan(0.1 * fraction * faces.length);
      expect(Math.max(...coarse)).toBeLessThan(vertices.length / 3);
    }
    expect(simplifiedFaces(faces, vertices, 1)).toBe(faces);
  });
});
