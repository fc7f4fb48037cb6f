// The close-up of a mode tile (close-up.ts): which modes get one — the part that moves spans
// less than LOCALISED of the model — and in which corner, on hand-made figures seen straight on
// (direction +z: the view's x and y are the points' x and y).
import * as THREE from "three";
import { describe, expect, it } from "vitest";
import { trianglesTouching } from "../src/detail";
import { CORNERS, INSET, LOCALISED, MOVING, PARTS_GRID, closeUpOf, freeCorner, lookingAt,
  movingRegion } from "../src/close-up";

const FRONT = new THREE.Vector3(0, 0, 1);

/** A 1 × 2 slab of points (x 0–1, y 0–2, every 0.05) and, apart, a "finger": 3 × 3 points
 * over x 0.9–1.0 and y `low`–`low` + 0.1 (its indices: `finger`), and with `other`, another
 * over x 0–0.1 (`other`). */
function figure(low: number, other = false): { rest: Float32Array; finger: number[]; other: number[] } {
  const points: number[] = [];
  for (let i = 0; i <= 20; i++) for (let j = 0; j <= 40; j++) points.push(0.05 * i, 0.05 * j, 0);
  const fingers = (other ? [0.9, 0] : [0.9]).map((left) => {
    const first = points.length / 3;
    for (let i = 0; i < 3; i++) for (let j = 0; j < 3; j++) points.push(left + 0.05 * i, low + 0.05 * j, 0.1);
    return Array.from({ length: 9 }, (_, o) => first + o);
  });
  return { rest: Float32Array.from(points), finger: fingers[0], other: fingers[1] ?? [] };
}

/** `rest` with the points `moving` moved by dx across. */
function moved(rest: Float32Array, moving: number[], dx: number): Float32Array {
  const pose = rest.slice();
  for (const i of moving) pose[3 * i] += dx;
  return pose;
}

describe("close-up", () => {
  it("frames a finger: its box, its share of the model, a corner it does not reach", () => {
    const { rest, finger } = figure(0.9);
    const poses = [moved(rest, finger, 0.02), moved(rest, finger, -0.02)];
    const region = movingRegion(rest, poses, FRONT)!;
    expect(region.count).toBe(9);
    // Across: 0.88–1.02 (0.14; up 0.1) of the slab's 2 up: 0.07; its box in the slab's 1 × 2.
    expect(region.share).toBeCloseTo(0.07, 5);
    const expected = [0.88, 0.45, 1.02, 0.5];
    region.box.forEach((value, i) => expect(value).toBeCloseTo(expected[i], 5));
    expect(region.depth).toBeCloseTo(0.1, 6); // the finger's z; it moves across, not nearer
    expect(region.front).toBeCloseTo(0, 6);
    const close = closeUpOf(rest, poses, FRONT)!;
    expect(close).not.toBeNull();
    expect(close.corner).toBe("top-right"); // every corner as full: the first, not reached
    // It draws the triangles within 1.6 framed spans (1.7 × 0.14 across) of the finger's middle
    // (0.95, 0.95): the slab's corner (0, 0) is out, the finger in.
    expect(close.visible[0]).toBe(0);
    for (const i of finger) expect(close.visible[i]).toBe(1);
    const reach = 1.6 * 1.7 * 0.14;
    const inside = Array.from({ length: rest.length / 3 }, (_, i) => i).filter((i) =>
      Math.abs(rest[3 * i] - 0.95) < reach - 1e-6 && Math.abs(rest[3 * i + 1] - 0.95) < reach - 1e-6);
    expect(close.visible.reduce((a, b) => a + b, 0)).toBeGreaterThanOrEqual(inside.length);
    expect(trianglesTouching(Uint32Array.of(0, 1, 2, finger[0], 1, 2), close.visible))
      .toEqual(Uint32Array.of(finger[0], 1, 2));
    // The close-up frames the finger 1.7 times larger than it spans (context around it).
    const xs = Array.from(close.shapes[0].x);
    expect(Math.max(...xs) - Math.min(...xs)).toBeCloseTo(1.7 * 0.1, 4);
  });

  it("frames one of two fingers apart, the one that moves most", () => {
    const { rest, finger, other } = figure(0.9, true);
    const pose = moved(moved(rest, finger, 0.02), other, -0.018);
    const region = movingRegion(rest, [pose], FRONT)!;
    expect(region.count).toBe(9);
    // Across: 0.9–1.02 of the slab's 2 up.
    expect(region.share).toBeCloseTo(0.06, 5);
    expect(region.box[0]).toBeCloseTo(0.9, 5);
    expect(closeUpOf(rest, [pose], FRONT)).not.toBeNull();
  });

  it("joins a sparse mesh's part through its faces", () => {
    // A ladder: rungs (0, y) – (1, y) for y = 0 … 10, each joined to the next by two triangles;
    // the grid's cells (10 / PARTS_GRID = 0.31) do not touch from one rung to the next. A sway
    // (0.1·(y + 0.5) across) moves the rungs with y + 0.5 > 0.3 · 10.5 (MOVING of the top's):
    // y = 3 … 10, 8 rungs, 16 vertices.
    const points: number[] = [], faces: number[] = [];
    for (let y = 0; y <= 10; y++) points.push(0, y, 0, 1, y, 0);
    for (let y = 0; y < 10; y++) faces.push(2 * y, 2 * y + 1, 2 * y + 2, 2 * y + 1, 2 * y + 3, 2 * y + 2);
    const rest = Float32Array.from(points), pose = rest.slice();
    for (let i = 0; i < 22; i++) pose[3 * i] += 0.1 * (rest[3 * i + 1] + 0.5);
    expect(10 / PARTS_GRID).toBeLessThan(1 / 2);
    expect(movingRegion(rest, [pose], FRONT)!.count).toBe(1); // one end of the top rung alone
    const region = movingRegion(rest, [pose], FRONT, Uint32Array.from(faces))!;
    expect(region.count).toBe(16);
    expect(region.share).toBeCloseTo(7 / 10, 5); // up: y 3–10 of 0–10
    expect(closeUpOf(rest, [pose], FRONT, Uint32Array.from(faces))).toBeNull();
  });

  it("looks at a part from where its surface faces the camera", () => {
    // A plate of two triangles at z = 0.1 over the slab: wound to face −z (away from a camera
    // on +z: the far side of a body), then +z; it moves across (x). Seen from +z turned by
    // 180° (−z), the away-facing plate shows its motion; the facing one, from +z itself.
    const { rest: slab } = figure(0.9);
    const first = slab.length / 3;
    const rest = Float32Array.from([...slab, 0.4, 1, 0.1, 0.4, 1.2, 0.1, 0.6, 1, 0.1, 0.6, 1.2, 0.1]);
    const plate = Int32Array.from([0, 1, 2, 3], (o) => first + o);
    const pose = moved(rest, [...plate], 0.05);
    const away = Uint32Array.from([0, 1, 2, 1, 3, 2], (o) => first + o); // (b − a) × (c − a) = −z
    const facing = Uint32Array.from([0, 2, 1, 1, 2, 3], (o) => first + o);
    expect(lookingAt(rest, [pose], plate, away, FRONT)).toBe(2);
    expect(lookingAt(rest, [pose], plate, facing, FRONT)).toBe(0);
    const region = movingRegion(rest, [pose], FRONT, away)!;
    expect(region.turn).toBe(2);
    [0, 0, -1].forEach((value, d) => expect(region.direction.getComponent(d)).toBeCloseTo(value, 6));
  });

  it("puts the close-up in a corner the moving part does not reach", () => {
    const { rest, finger } = figure(1.6); // y 1.6–1.7 of 0–2: 0.80–0.85, in the top right corner
    const close = closeUpOf(rest, [moved(rest, finger, 0.02)], FRONT)!;
    expect(close.box[1]).toBeGreaterThan(1 - INSET);
    expect(close.corner).toBe("top-left");
  });

  it("picks the corner the model leaves free", () => {
    // An L: the slab's points but those with x < 0.5 and y < 1 (the bottom left corner empty).
    const points: number[] = [];
    for (let i = 0; i <= 20; i++) {
      for (let j = 0; j <= 40; j++) if (!(0.05 * i < 0.5 && 0.05 * j < 1)) points.push(0.05 * i, 0.05 * j, 0);
    }
    points.push(0, 0, 0); // the box still from (0, 0)
    expect(freeCorner(Float32Array.from(points), [0.9, 0.9, 1, 1], FRONT)).toBe("bottom-left");
    expect(CORNERS).toContain("bottom-left");
  });

  it("gives a whole-body motion none: what moves spans most of the model", () => {
    // A sway: each point moves across by 0.05·(y + 0.025); those above MOVING (0.3) of the
    // top's, y + 0.025 > 0.6075, move: the slab's rows from y = 0.6 to 2 (29 of 21 points) and the
    // finger's 9.
    const { rest } = figure(1.0);
    const pose = rest.slice();
    for (let i = 0; i < pose.length / 3; i++) pose[3 * i] += 0.05 * (rest[3 * i + 1] + 0.025);
    const region = movingRegion(rest, [pose], FRONT)!;
    expect(MOVING).toBe(0.3);
    expect(region.count).toBe(29 * 21 + 9);
    expect(region.share).toBeCloseTo(1.4 / 2, 5); // up: y 0.6–2 of the slab's 2
    expect(region.share).toBeGreaterThan(LOCALISED);
    expect(closeUpOf(rest, [pose], FRONT)).toBeNull();
  });

  it("gives a still mode none", () => {
    const { rest } = figure(1.0);
    expect(movingRegion(rest, [rest.slice()], FRONT)).toBeNull();
    expect(closeUpOf(rest, [rest.slice()], FRONT)).toBeNull();
  });
});
