// The page's URL options (docs/web.md) and the gallery-size rule announced by the server.
// Pure functions of their inputs, so Vitest checks them without a browser.

/** The one gallery-size rule; the server sends it as `GET api/config` → `{gallery: …}`. */
export interface GalleryRule { min: number; max: number; default: number; }

/** Used only when the server cannot be asked (the error is shown in the status line). */
export const FALLBACK_RULE: GalleryRule = { min: 2, max: 16, default: 8 };

/** The smallest size the *tiles* menu offers: fewer tiles than 4 leave little to compare. */
export const MENU_MIN = 4;

export interface Options {
  /** `?size=` as written; checked against the server's rule by `gallerySize`. */
  size: string | null;
  mesh: string | null;
  song: string | null;
  mapping: string | null;
  view: "gallery" | "player";
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
}

export function readOptions(search: string): Options {
  const params = new URLSearchParams(search);
  const path = params.get("path");
  return {
    size: params.get("size"),
    mesh: params.get("mesh"),
    song: params.get("song"),
    mapping: params.get("mapping"),
    view: params.get("view") === "player" ? "player" : "gallery",
    half: params.has("half") ? params.get("half") !== "0" : null,
    render: params.has("render"),
    test: params.has("test"),
    bare: params.has("bare"),
    path: path === "gpu" || path === "cpu" ? path : null,
    batch: Number(params.get("batch") ?? 8),
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
 * a message saying why, for the status line. */
export function gallerySize(raw: string | null, rule: GalleryRule):
    { size: number; problem: string | null } {
  if (raw === null) return { size: rule.default, problem: null };
  const size = /^\s*\d+\s*$/.test(raw) ? Number(raw) : NaN;
  if (Number.isInteger(size) && size >= rule.min && size <= rule.max) {
    return { size, problem: null };
  }
  return {
    size: rule.default,
    problem: `?size=${raw} is not a gallery size (an integer from ${rule.min} to ${rule.max}): `
      + `showing ${rule.default} tiles`,
  };
}

/** The *tiles* menu: every size from 4 (or the rule's minimum, if larger) to the maximum, plus
 * the current size when `?size=` chose a smaller one, so the menu shows what is on screen. */
export function sizeChoices(rule: GalleryRule, current: number): number[] {
  const sizes: number[] = [];
  for (let size = Math.max(MENU_MIN, rule.min); size <= rule.max; size++) sizes.push(size);
  if (!sizes.includes(current)) sizes.push(current);
  return sizes.sort((a, b) => a - b);
}
