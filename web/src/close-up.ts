// The close-up of a mode tile (docs/web.md#rigs-in-the-page): a finger, ear or toe mode moves a
// few pixels of a tile that frames the whole rig, so the tile also draws, in a corner, the same
// deformed skin from a camera that frames just the part that moves. The one rule of which modes
// get one (`closeUp`), where the close-up goes, and its drawing (`CloseUpDrawer`).
import * as THREE from "three";
import type { Basis } from "./bundle";
import type { Deformer } from "./deform";
import { deformCPU } from "./filter";
import { VIEW_DIRECTION, framing, silhouette } from "./studio";
import type { Silhouette, Studio } from "./studio";

/** A vertex moves when its largest displacement exceeds this share of the mode's largest. */
export const MOVING = 0.3;
/** The part that moves: the moving vertices joined to the one that moves most by the mesh's
 * faces or by touching cells of a grid this many cells across the model's silhouette (both
 * hands' fingers are two parts, each its own close-up's worth; one hand's fingers, one). */
export const PARTS_GRID = 32;
/** A mode is localised — its tile gets a close-up — when the part that moves (at rest and in its
 * poses) spans less than this share of the model's silhouette (the larger spans, across or up
 * the view, of each)… */
export const LOCALISED = 0.25;
/** …or, when the tiles' view does not see it move (`lookingAt` turns), less than this share. */
export const HIDDEN = 0.5;
/** The close-up's share of its tile's width and height (style.css `.close-up`). */
export const INSET = 0.45;
/** The close-up shows the part that moves this many times larger than its own span (context
 * around it), and at least this share of the model's span (a few vertices are not a view). */
const CONTEXT = 1.7;
const SMALLEST = 0.08;
/** The grid over the model's silhouette on which corners are compared. */
const CELLS = 20;
const CUTAWAY = 0.8;
/** The close-up draws the triangles within this many framed spans of the part's middle (a
 * close-up 1:3 as wide as tall shows 1.5 of them up). */
const WINDOW = 1.6;
/** The close-up turns from the tiles' view when another sees the part move this many times more. */
const TURN = 1.5;

export type Corner = "top-right" | "top-left" | "bottom-right" | "bottom-left";
/** In this order when equally free. */
export const CORNERS: Corner[] = ["top-right", "top-left", "bottom-right", "bottom-left"];

/** The part of a model one mode moves, seen along the tiles' view direction. */
export interface Region {
  /** its vertices at rest and in each pose seen from `direction`, enlarged by CONTEXT across
   * and up, their depth from `depth` (the close-up's framing) */
  shapes: Silhouette[];
  /** the middle of its depth along the view direction */
  depth: number;
  /** how far its nearest point (at rest or posed) lies before `depth` toward the camera */
  front: number;
  /** the direction the close-up looks from (`lookingAt`): the tiles' turned by `turn` × 90°
   * about the vertical */
  direction: THREE.Vector3;
  turn: number;
  /** per vertex, 1 where it lies (at rest) within WINDOW framed spans of the part across and up
   * the close-up: the triangles touching these are all it draws */
  visible: Uint8Array;
  /** its span over the model's (the larger of across and up of each) */
  share: number;
  /** its box within the model's silhouette box, 0–1, x right and y up: [x0, y0, x1, y1] */
  box: [number, number, number, number];
  /** vertices that move */
  count: number;
}

/** A localised mode's close-up: its region and the tile's corner it is drawn in. */
export interface CloseUp extends Region { corner: Corner; }

/** Where a mode tile's close-up is drawn (its element: the corner's frame, placed by CSS). */
export interface CloseUpShot { element: HTMLElement; closeUp: CloseUp; }

type Box = [number, number, number, number];

function boxOf(shape: Silhouette, indices?: ArrayLike<number>): Box {
  const box: Box = [Infinity, Infinity, -Infinity, -Infinity];
  const count = indices ? indices.length : shape.x.length;
  for (let o = 0; o < count; o++) {
    const i = indices ? indices[o] : o;
    box[0] = Math.min(box[0], shape.x[i]); box[1] = Math.min(box[1], shape.y[i]);
    box[2] = Math.max(box[2], shape.x[i]); box[3] = Math.max(box[3], shape.y[i]);
  }
  return box;
}

/** Silhouettes of the points `indices` of `shape`, scaled by `factor` across and up the view
 * about (cx, cy), their depth from `depth`. */
function part(shape: Silhouette, indices: Int32Array, cx: number, cy: number, factor: number,
              depth: number): Silhouette {
  const s = new Float32Array(indices.length), x = new Float32Array(indices.length),
    y = new Float32Array(indices.length);
  indices.forEach((i, o) => {
    s[o] = shape.s[i] - depth;
    x[o] = cx + factor * (shape.x[i] - cx);
    y[o] = cy + factor * (shape.y[i] - cy);
  });
  return { s, x, y };
}

/**
 * The part of a model (`rest`, n*3; `faces`, m*3) that a mode moves in its `poses` (each
 * n*3): the vertices whose largest displacement exceeds MOVING of the largest, joined to the one
 * that moves most (`partAround`), with its span over the model's span in the view along
 * `direction`, and its framing seen from where it shows (`lookingAt`); null when nothing moves.
 */
export function movingRegion(rest: Float32Array, poses: Float32Array[],
                             direction = VIEW_DIRECTION, faces: Uint32Array | null = null):
    Region | null {
  const n = rest.length / 3;
  const moved = new Float32Array(n);
  for (const pose of poses) {
    for (let i = 0; i < n; i++) {
      moved[i] = Math.max(moved[i], Math.hypot(pose[3 * i] - rest[3 * i],
        pose[3 * i + 1] - rest[3 * i + 1], pose[3 * i + 2] - rest[3 * i + 2]));
    }
  }
  const largest = moved.reduce((a, b) => Math.max(a, b), 0);
  if (!(largest > 0)) return null;
  const model = silhouette(rest, direction);
  const indices = partAround(model, moved, moved.indexOf(largest), MOVING * largest, faces);
  const [m0, m1, m2, m3] = boxOf(model);
  const box = regionBox([model, ...poses.map((pose) => silhouette(pose, direction))], indices);
  const width = Math.max(m2 - m0, 1e-9), height = Math.max(m3 - m1, 1e-9);
  const turn = lookingAt(rest, poses, indices, faces, direction);
  const look = turned(direction, turn);
  return { ...framed([rest, ...poses].map((points) => silhouette(points, look)), indices,
    SMALLEST * Math.max(width, height)), direction: look, turn, count: indices.length,
    share: Math.max(box[2] - box[0], box[3] - box[1]) / Math.max(width, height),
    box: [(box[0] - m0) / width, (box[1] - m1) / height, (box[2] - m0) / width,
      (box[3] - m1) / height] };
}

/** The box of the points `indices` over the views. */
function regionBox(views: Silhouette[], indices: Int32Array): Box {
  const box: Box = [Infinity, Infinity, -Infinity, -Infinity];
  for (const view of views) {
    const b = boxOf(view, indices);
    box[0] = Math.min(box[0], b[0]); box[1] = Math.min(box[1], b[1]);
    box[2] = Math.max(box[2], b[2]); box[3] = Math.max(box[3], b[3]);
  }
  return box;
}

/** The close-up's framing of the points `indices` in `views` (at rest and posed): enlarged by
 * CONTEXT, to `smallest` across at least, their depth from the middle of theirs; and the
 * vertices it may see (WINDOW). */
function framed(views: Silhouette[], indices: Int32Array, smallest: number):
    { shapes: Silhouette[]; depth: number; front: number; visible: Uint8Array } {
  const box = regionBox(views, indices);
  let near = -Infinity, far = Infinity;
  for (const view of views) {
    for (const i of indices) { near = Math.max(near, view.s[i]); far = Math.min(far, view.s[i]); }
  }
  const depth = (near + far) / 2;
  const cx = (box[0] + box[2]) / 2, cy = (box[1] + box[3]) / 2;
  const span = Math.max(box[2] - box[0], box[3] - box[1], 1e-9);
  const factor = Math.max(CONTEXT, smallest / span);
  const reach = WINDOW * factor * span, [rest] = views;
  const visible = Uint8Array.from(rest.x, (x, i) =>
    Number(Math.abs(x - cx) < reach && Math.abs(rest.y[i] - cy) < reach));
  return { shapes: views.map((view) => part(view, indices, cx, cy, factor, depth)), depth,
    front: near - depth, visible };
}

/** `direction` turned by `turn` × 90° about the vertical. */
function turned(direction: THREE.Vector3, turn: number): THREE.Vector3 {
  return direction.clone().applyAxisAngle(new THREE.Vector3(0, 1, 0), (turn * Math.PI) / 2);
}

/**
 * Where the close-up looks from: of `direction` and it turned about the vertical by 90°, 180°
 * and 270° (turn 0–3), the one that sees the part `indices` move most — Σ over its vertices of
 * how much their surface faces the camera (the normal's cosine, 0 when turned away: a far side,
 * the back of a body) times their largest displacement across the view — `direction` (0) unless
 * another sees TURN times as much (no `faces`: 0).
 */
export function lookingAt(rest: Float32Array, poses: Float32Array[], indices: Int32Array,
                          faces: Uint32Array | null, direction = VIEW_DIRECTION): number {
  if (!faces) return 0;
  const normals = new Float32Array(rest.length);
  const a = new THREE.Vector3(), b = new THREE.Vector3(), c = new THREE.Vector3();
  for (let f = 0; f < faces.length; f += 3) {
    a.fromArray(rest, 3 * faces[f]); b.fromArray(rest, 3 * faces[f + 1]).sub(a);
    c.fromArray(rest, 3 * faces[f + 2]).sub(a);
    b.cross(c); // the face's normal, as long as twice its area
    for (let e = 0; e < 3; e++) for (let d = 0; d < 3; d++) normals[3 * faces[f + e] + d] += b.getComponent(d);
  }
  const normal = new THREE.Vector3(), moved = new THREE.Vector3();
  const seen = (view: THREE.Vector3) => {
    let total = 0;
    for (const i of indices) {
      normal.fromArray(normals, 3 * i).normalize();
      let across = 0;
      for (const pose of poses) {
        moved.fromArray(pose, 3 * i).sub(a.fromArray(rest, 3 * i));
        across = Math.max(across, moved.addScaledVector(view, -moved.dot(view)).length());
      }
      total += Math.max(0, normal.dot(view)) * across;
    }
    return total;
  };
  let best = 0, most = TURN * seen(direction);
  for (const turn of [1, 2, 3]) {
    const score = seen(turned(direction, turn));
    if (score > most) { best = turn; most = score; }
  }
  return best;
}

/** The vertices moved more than `threshold` (`moved`, per vertex) joined to vertex `seed`'s:
 * through the mesh's `faces` (n*3) among them, or through touching cells (8 neighbours) of a
 * grid PARTS_GRID cells across the silhouette `model` (a hand's fingers, a sparse mesh's rings). */
function partAround(model: Silhouette, moved: Float32Array, seed: number, threshold: number,
                    faces: Uint32Array | null): Int32Array {
  const parent = Int32Array.from(moved.keys());
  const root = (i: number): number => {
    while (parent[i] !== i) i = parent[i] = parent[parent[i]];
    return i;
  };
  const join = (a: number, b: number) => { parent[root(a)] = root(b); };
  const moves = (i: number) => moved[i] > threshold;
  if (faces) {
    for (let f = 0; f < faces.length; f += 3) {
      for (let e = 0; e < 3; e++) {
        const a = faces[f + e], b = faces[f + (e + 1) % 3];
        if (moves(a) && moves(b)) join(a, b);
      }
    }
  }
  const [x0, y0, x1, y1] = boxOf(model);
  const size = Math.max(x1 - x0, y1 - y0, 1e-9) / PARTS_GRID;
  const columns = Math.floor((x1 - x0) / size) + 3; // a free column each side
  const cells = new Map<number, number>(); // a cell: one of its moving vertices
  moved.forEach((_, i) => {
    if (!moves(i)) return;
    const cell = (Math.floor((model.y[i] - y0) / size) + 1) * columns
      + Math.floor((model.x[i] - x0) / size) + 1;
    const first = cells.get(cell);
    if (first === undefined) cells.set(cell, i); else join(i, first);
  });
  for (const [cell, first] of cells) {
    for (const next of [cell + 1, cell + columns - 1, cell + columns, cell + columns + 1]) {
      const other = cells.get(next);
      if (other !== undefined) join(first, other);
    }
  }
  const part = root(seed);
  return Int32Array.from(moved.keys()).filter((i) => moves(i) && root(i) === part);
}

const target = new THREE.Vector3();

/** The corner's rectangle in the 0–1 box (x right, y up). */
function cornerBox(corner: Corner): Box {
  const left = corner.endsWith("left"), top = corner.startsWith("top");
  return [left ? 0 : 1 - INSET, top ? 1 - INSET : 0, left ? INSET : 1, top ? 1 : INSET];
}

/** The corner to draw a close-up in: one the moving part does not reach, covering the fewest
 * cells of the model's silhouette (a CELLS × CELLS grid over its box, `rest` n*3). */
export function freeCorner(rest: Float32Array, region: Box, direction = VIEW_DIRECTION): Corner {
  const model = silhouette(rest, direction);
  const [x0, y0, x1, y1] = boxOf(model);
  const filled = new Uint8Array(CELLS * CELLS);
  const cell = (value: number, low: number, high: number) =>
    Math.min(CELLS - 1, Math.floor((CELLS * (value - low)) / Math.max(high - low, 1e-9)));
  for (let i = 0; i < model.x.length; i++) {
    filled[cell(model.y[i], y0, y1) * CELLS + cell(model.x[i], x0, x1)] = 1;
  }
  const cost = (corner: Corner) => {
    const [c0, c1, c2, c3] = cornerBox(corner);
    const reached = region[0] < c2 && region[2] > c0 && region[1] < c3 && region[3] > c1;
    let covered = 0;
    for (let row = 0; row < CELLS; row++) {
      for (let column = 0; column < CELLS; column++) {
        const x = (column + 0.5) / CELLS, y = (row + 0.5) / CELLS;
        if (x > c0 && x < c2 && y > c1 && y < c3) covered += filled[row * CELLS + column];
      }
    }
    return covered + (reached ? CELLS * CELLS : 0);
  };
  return CORNERS.reduce((best, corner) => (cost(corner) < cost(best) ? corner : best));
}

/** The close-up of a mode moving `rest` (n*3; `faces` m*3) into `poses` (each n*3), or null
 * when the mode is not localised: the part that moves spans LOCALISED of the model or more
 * (HIDDEN or more when the close-up looks at it from another side). */
export function closeUpOf(rest: Float32Array, poses: Float32Array[], direction = VIEW_DIRECTION,
                          faces: Uint32Array | null = null): CloseUp | null {
  const region = movingRegion(rest, poses, direction, faces);
  if (!region || region.share >= (region.turn ? HIDDEN : LOCALISED)) return null;
  return { ...region, corner: freeCorner(rest, region.box, direction) };
}

/** A mode tile's close-up (`closeUpOf`): `poses` are the weights of its largest poses (the
 * tile's framing poses), deformed on the CPU from `basis`. */
export function closeUp(basis: Basis, poses: Float32Array[]): CloseUp | null {
  return closeUpOf(basis.vertices, poses.map((weights) => deformCPU(basis, weights)),
    VIEW_DIRECTION, basis.faces);
}

/** Draws close-ups: the scene as deformed for the tile, again, into the close-up's rectangle,
 * from a camera framing the moving part (cached by close-up and aspect), cut away before it
 * (near plane CUTAWAY of the way to its nearest point): what hides it in the tile (a horse's
 * body before its tail) does not hide it here. */
export class CloseUpDrawer {
  private readonly camera: THREE.PerspectiveCamera;
  private framings = new WeakMap<CloseUp, Map<number, { target: THREE.Vector3; distance: number }>>();

  constructor(fieldOfView: number) {
    this.camera = new THREE.PerspectiveCamera(fieldOfView, 1, 0.001, 100);
  }

  /** Draw the deformer's scene into the shot's close-up, its visible triangles only (canvas
   * `height` CSS px; the tile just drawn). */
  draw(renderer: THREE.WebGLRenderer, deformer: Deformer, studio: Studio, shot: CloseUpShot,
       height: number): void {
    const rect = shot.element.getBoundingClientRect();
    if (rect.width < 2 || rect.height < 2) return;
    const x = rect.left, y = height - rect.bottom;
    renderer.setViewport(x, y, rect.width, rect.height);
    renderer.setScissor(x, y, rect.width, rect.height);
    renderer.clearDepth();
    const aspect = Math.round((rect.width / rect.height) * 50) / 50;
    let byAspect = this.framings.get(shot.closeUp);
    if (!byAspect) this.framings.set(shot.closeUp, byAspect = new Map());
    let found = byAspect.get(aspect);
    if (!found) {
      found = framing(shot.closeUp.shapes, shot.closeUp.direction, this.camera.fov, aspect);
      byAspect.set(aspect, found);
    }
    const camera = this.camera;
    camera.aspect = aspect;
    const { depth, front, direction } = shot.closeUp;
    camera.near = Math.max(CUTAWAY * (found.distance - front), found.distance / 100);
    camera.far = found.distance + 10;
    target.copy(direction).multiplyScalar(depth).add(found.target);
    camera.position.copy(direction).multiplyScalar(found.distance).add(target);
    camera.lookAt(target);
    camera.updateProjectionMatrix();
    studio.setAspect(aspect);
    deformer.drawOnly(shot.closeUp.visible);
    renderer.render(deformer.scene, camera);
    deformer.drawOnly(null);
  }
}
