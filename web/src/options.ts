// The page's URL options (docs/web.md) and the gallery-size rule announced by the server.
// Pure functions of their inputs, so Vitest checks them without a browser.

/** The one gallery-size rule; the server sends it as `GET api/config` → `{gallery: …}`. */
export interface GalleryRule { min: number; max: number; default: number; }

/** The smallest size the *tiles* menu offers: fewer tiles than 4 leave little to compare. */
export const MENU_MIN = 4;

export interface Options {
  /** `?size=` as written; checked against the server's rule by `gallerySize`. */
  size: string | null;
  mesh: string | null;
  song: string | null;
  mapping: string | null;
  /** `?view=`; null: the player when the server was given mappings, else the gallery */
  view: "gallery" | "player" | null;
  /** `?aa=0|1`: antialiasing off / on; null: on unless WebGL runs in software (or `?render`) */
  aa: boolean | null;
  /** `?half`: float16 harmonics; `?half=0`: never; null: automatic (above 128 MB). */
  half: boolean | null;
  /** `?render`: no clock, frames drawn by `window.eigendance.renderAt(t)`. */
  render: boolean;
  /** `?test`: the live page with the test hooks on `window.eigendance`. */
  test: boolean;
  /** `?bare`: only the canvas (offline video frames). */
  bare: boolean;
  /** `?path=gpu|cpu`: force a deformation path instead of timing both. */
  path: "gpu" | "cpu" | null;
  /** `?batch=N`: tiles per GPU positions pass. */
  batch: number;
  /** `?scale=S`: draw at this fixed render scale (0.1 … 1) instead of dynamic resolution. */
  scale: number | null;
  /** `?fps=N`: the frame rate the page aims at (1 … 120; RESOLUTION.target when absent) */
  fps: number | null;
  /** `?source=mic`: start on the default live input (docs/design.md#live); `tab`: tab audio */
  source: "mic" | "tab" | null;
  /** a `?source=` that names no live input (said, not ignored), or null */
  badSource: string | null;
}

/** The render scale `?scale=` asks for, or null (dynamic resolution) when absent or not a
 * number in [0.1, 1]. */
export function fixedScale(raw: string | null): number | null {
  return numberIn(raw, 0.1, 1);
}

/** `raw` as a number in [low, high], or null when absent, empty or outside. */
function numberIn(raw: string | null, low: number, high: number): number | null {
  const value = raw === null || raw.trim() === "" ? NaN : Number(raw);
  return Number.isFinite(value) && value >= low && value <= high ? value : null;
}

/** The frame rates `?fps=` may ask for. */
export const MIN_FPS = 1, MAX_FPS = 120;

/** The frame rate `?fps=` asks the page to aim at (a projector's 30 or 60), or null (the
 * default target) when absent or not a number in [MIN_FPS, MAX_FPS]. */
export function targetFps(raw: string | null): number | null {
  return numberIn(raw, MIN_FPS, MAX_FPS);
}

export function readOptions(search: string): Options {
  const params = new URLSearchParams(search);
  const path = params.get("path");
  return {
    size: params.get("size"),
    mesh: params.get("mesh"),
    song: params.get("song"),
    mapping: params.get("mapping"),
    view: params.get("view") === "player" ? "player"
      : params.get("view") === "gallery" ? "gallery" : null,
    aa: params.has("aa") ? params.get("aa") !== "0" : null,
    half: params.has("half") ? params.get("half") !== "0" : null,
    render: params.has("render"),
    test: params.has("test"),
    bare: params.has("bare"),
    path: path === "gpu" || path === "cpu" ? path : null,
    batch: Number(params.get("batch") ?? 8),
    scale: fixedScale(params.get("scale")),
    fps: targetFps(params.get("fps")),
    source: params.get("source") === "mic" ? "mic" : params.get("source") === "tab" ? "tab" : null,
    badSource: params.has("source") && !["mic", "tab"].includes(params.get("source")!)
      ? params.get("source") : null,
  };
}

/** Whether `window.eigendance` is installed: only for offline rendering and tests. */
export const wantsHooks = (options: Options): boolean => options.render || options.test;

/** Check the server's `api/config` answer, so a malformed one fails here with a clear message
 * instead of as a hung gallery later. */
export function galleryRule(config: unknown): GalleryRule {
  const rule = (config as { gallery?: Partial<GalleryRule> } | null)?.gallery;
  const { min, max, default: chosen } = rule ?? {};
  const integer = (value: unknown): value is number => Number.isInteger(value);
  if (!integer(min) || !integer(max) || !integer(chosen) || min < 1 || min > chosen
      || chosen > max) {
    throw new Error("api/config: expected {gallery: {min, max, default}}, got "
      + JSON.stringify(config));
  }
  return { min, max, default: chosen };
}

/** The gallery size asked for by `?size=`: any integer of the rule; otherwise the default and
 * a message saying why, for the status line. Without the rule (`api/config` failed), the size
 * as written, or null for the server's default: the server then checks it (one rule). */
export function gallerySize(raw: string | null, rule: GalleryRule | null):
    { size: number | null; problem: string | null } {
  const written = raw !== null && /^\s*\d+\s*$/.test(raw) ? Number(raw) : NaN;
  if (rule === null) return { size: Number.isInteger(written) ? written : null, problem: null };
  if (raw === null) return { size: rule.default, problem: null };
  if (Number.isInteger(written) && written >= rule.min && written <= rule.max) {
    return { size: written, problem: null };
  }
  return {
    size: rule.default,
    problem: `?size=${raw} is not a gallery size (an integer from ${rule.min} to ${rule.max}): `
      + `showing ${rule.default} tiles`,
  };
}

/** The *tiles* menu: every size from 4 (or the rule's minimum, if larger) to the maximum, plus
 * the current size when `?size=` chose a smaller one, so the menu shows what is on screen.
 * Without the rule, only the current size. */
export function sizeChoices(rule: GalleryRule | null, current: number): number[] {
  if (rule === null) return [current];
  const sizes: number[] = [];
  for (let size = Math.max(MENU_MIN, rule.min); size <= rule.max; size++) sizes.push(size);
  if (!sizes.includes(current)) sizes.push(current);
  return sizes.sort((a, b) => a - b);
}

/** How many tiles to offer when the page draws `fps` frames per second with `tiles` tiles and
 * should reach `wanted`: the cost of a frame is about proportional to the tiles. At least
 * `least`; null when fewer would not help. */
export function fewerTiles(tiles: number, fps: number, wanted: number, least: number):
    number | null {
  const fit = Math.floor((tiles * fps) / wanted);
  const offer = Math.max(least, Math.min(tiles - 1, fit));
  return offer < tiles ? offer : null;
}
