// What the player applies is the mapping's (docs/design.md#mapping-file): version-1 files read
// with the defaults, the page writes version 2; tile labels; framing fills the view.
import { describe, expect, it } from "vitest";
import * as THREE from "three";
import { DEFAULT_SETTINGS, drivenHarmonics, prepare, settingsOf, withSettings } from "../src/filter";
import type { Mapping } from "../src/filter";
import { harmonicsLabel } from "../src/gallery-view";
import { VIEW_DIRECTION, framing, rim, silhouette } from "../src/studio";

const v1: Mapping = { format: "eigendance.mapping", version: 1, bands: 4,
  transfer: [0.1, 0.1, 0.6, 0.9], amplification: [0, 2, 0, -1, 0], seed: null };

describe("mapping settings", () => {
  it("reads a version-1 file with the defaults (facet weight 0.4, thesis Fig. 6.4(d))", () => {
    expect(settingsOf(v1)).toEqual(DEFAULT_SETTINGS);
    expect(DEFAULT_SETTINGS.deformedNormalWeight).toBe(0.4);
    expect(DEFAULT_SETTINGS.materials).toBe(true); // a model with materials shows them
  });

  it("writes every setting into a version-3 file and reads it back", () => {
    const settings = { gain: 1.7, smoothing: 0.25, deformedNormalWeight: 0.8,
      shading: "flat" as const, materials: false };
    const saved = withSettings(v1, settings);
    expect(saved).toMatchObject({ version: 3, gain: 1.7, smoothing: 0.25, offset: 0,
      look: { deformed_normal_weight: 0.8, shading: "flat", materials: false } });
    expect(settingsOf(saved)).toEqual(settings);
    expect(saved.transfer).toEqual(v1.transfer);
    expect(v1.version).toBe(1); // the original is not changed
    const prepared = prepare(saved, 5);
    expect([prepared.gain, prepared.smoothing]).toEqual([1.7, 0.25]);
  });

  it("labels a tile by the harmonics its music reaches and amplifies", () => {
    expect(drivenHarmonics(prepare(v1, 5))).toEqual([3]); // ν 0 and 4 are not amplified
    expect(harmonicsLabel([3])).toBe("harmonic 3");
    expect(harmonicsLabel([2, 3, 7])).toBe("harmonics 2–7");
    expect(harmonicsLabel([])).toBe("still");
  });
});

describe("framing", () => {
  it("makes a model fill its view, whatever the view's shape", () => {
    // A box 4 wide, 1 tall and 1 deep, seen from the default direction.
    const corners: number[] = [];
    for (const x of [-2, 2]) for (const y of [-0.5, 0.5]) for (const z of [-0.5, 0.5]) {
      corners.push(x, y + 3, z); // off centre: the target follows the model
    }
    const vertices = new Float32Array(corners);
    const shape = silhouette(vertices, VIEW_DIRECTION);
    for (const aspect of [0.5, 1, 2.5]) {
      const { target, distance } = framing([shape], VIEW_DIRECTION, 30, aspect);
      const camera = new THREE.PerspectiveCamera(30, aspect, 0.01, 100);
      camera.position.copy(VIEW_DIRECTION).multiplyScalar(distance).add(target);
      camera.lookAt(target);
      camera.updateMatrixWorld();
      let x0 = 1, x1 = -1, y0 = 1, y1 = -1;
      for (let i = 0; i < vertices.length; i += 3) {
        const p = new THREE.Vector3(vertices[i], vertices[i + 1], vertices[i + 2]).project(camera);
        x0 = Math.min(x0, p.x); x1 = Math.max(x1, p.x); y0 = Math.min(y0, p.y); y1 = Math.max(y1, p.y);
      }
      expect(Math.max(-x0, x1, -y0, y1)).toBeLessThanOrEqual(1); // all inside
      expect(Math.max(x1 - x0, y1 - y0)).toBeGreaterThan(1.45); // and fills ≥ 72% of it
    }
  });
});

describe("rim", () => {
  it("keeps the vertices that reach farthest from the middle of the view", () => {
    const points = new Float32Array([0, 0, 0, 0.1, 0, 0, 3, 0, 0, -3, 0, 0, 0, 0.2, 0]);
    const shape = silhouette(points, new THREE.Vector3(0, 0, 1));
    expect(Array.from(rim(shape, 0.4)).sort()).toEqual([2, 3]);
  });
});
