// What a Viewer draws (viewer.ts): the views, the shots (a model, where, moved how, in which
// look) and what moves them; types only, shared by the views and the viewers.
import type { CloseUpShot } from "./close-up";
import type { Prepared, Shading } from "./filter";

export type View = "gallery" | "player";
export type DeformationPath = "gpu" | "cpu";

/** How one model's surface is shaded: its mapping's look (docs/design.md#mapping-file). */
export interface Look {
  shading: Shading;
  /** weight of the deformed triangle's flat normal against the original vertex normal */
  deformedNormalWeight: number;
  /** in the model's own materials when it has them (false: the clay studio look) */
  materials: boolean;
}

/** One model to draw: where on the page, moved by which (prepared) mapping, with which look;
 * `source` (the mapping) says when the player shows another one; `closeUp`: a mode tile's
 * close-up of the part that moves (close-up.ts). */
export interface Shot {
  element: HTMLElement; prepared: Prepared; look: Look; source?: object; closeUp?: CloseUpShot;
}

/** The harmonics explorer: colour the player's model by eigenvector `harmonic` (−1: off). */
export interface Explorer { harmonic: number; scale: number; }

/** What the current frame shows. */
export interface Stage { view: View; tiles: Shot[]; player: Shot | null; explorer: Explorer; }

/** What moves the models (the harmonics' `Motion`, a rig's `RigMotion`): the deformation
 * shader's weights of a prepared mapping at time t, and the poses a model is framed in — the
 * weights `framingWeights` gives, else those at the song's loudest times. */
export interface MotionSource {
  readonly ready: boolean;
  /** a song is loaded (the page's clock and spectrum follow it even without a model) */
  readonly songLoaded?: boolean;
  weights(prepared: Prepared, t: number): Float32Array;
  loudestTimes(count: number): number[];
  framingWeights?(prepared: Prepared): Float32Array[];
}
