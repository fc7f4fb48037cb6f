// The frame rate the person sees, said truthfully: the header's readout (frames drawn per second
// while the music plays, and the resolution the page draws at to hold it: resolution.ts), and,
// when even the lowest resolution cannot hold the target, a notice over the gallery offering
// fewer tiles (docs/design.md#rendering).
import { $ } from "./dom";
import { fewerTiles } from "./options";
import type { Viewer } from "./viewer";

/** The notice comes after this long (ms) below the target at the lowest resolution. */
const SLOW_FOR_MS = 3000;

/** What the watch reads from and asks of the page. */
export interface FrameRateEvents {
  /** the viewer drawing now (the harmonics', or a rig's) */
  viewer(): Viewer;
  /** tiles of the gallery on screen; null when no harmonics gallery shows (player, rigs) */
  galleryTiles(): number | null;
  playing(): boolean;
  /** the smallest gallery the rule allows */
  smallest(): number;
  /** make a gallery of `size` tiles (resolves once it is on screen or failed) */
  newGallery(size: number): Promise<unknown>;
}

export class FrameRateWatch {
  private slowSince: number | null = null;
  /** the tile count the measurements belong to: a new gallery starts them over */
  private tiles: number | null = null;
  /** gallery sizes whose low frame rate the person already dismissed */
  private readonly dismissed = new Set<number>();
  /** a smaller gallery is on its way: no notice until it is on screen */
  private pending = false;
  /** what the notice shown is about (its rate follows the readout's), or null */
  private said: { tiles: number; floor: string; target: number } | null = null;

  constructor(private readonly events: FrameRateEvents) {
    $("notice-close").addEventListener("click", () => {
      this.hideNotice();
      const tiles = this.events.galleryTiles();
      if (tiles !== null) this.dismissed.add(tiles);
    });
  }

  /** The notice is about the gallery's tiles: it goes when they do (player, a rig). */
  hideNotice(): void {
    $("notice").hidden = true;
    this.slowSince = null;
  }

  /** Playback started or stopped: the measurements start over. */
  restart(): void { this.slowSince = null; }

  /** Refresh the readout and check the frame rate (called a few times a second). */
  update(now: number): void {
    const viewer = this.events.viewer();
    const { fps } = viewer;
    const readout = $("fps");
    const scale = viewer.resolution.scale;
    const detail = viewer.resolution.detail;
    // Short enough to read whole in the header's one row ("6.4 fps · 65% · 25% △"); the
    // tooltip says it in words.
    readout.textContent = fps > 0 ? `${fps.toFixed(fps < 10 ? 1 : 0)} fps`
      + (scale < 1 ? ` · ${Math.round(100 * scale)}%` : "")
      + (detail < 1 ? ` · ${Math.round(100 * detail)}% △` : "") : "";
    const lowered = viewer.resolution.describe();
    readout.title = "frames the page draws per second while the song plays"
      + (lowered ? `; now ${lowered}` : "") + (detail < 1 ? " (△: of the triangles)" : "");
    readout.classList.toggle("slow", fps > 0 && fps < viewer.resolution.rule.target);
    this.check(viewer, fps, now);
    if (!$("notice").hidden && fps > 0) this.sayRate(fps); // one number: the readout's
  }

  /** The notice's sentence at frame rate `fps`, formatted as the readout formats it. */
  private sayRate(fps: number): void {
    if (!this.said) return;
    const { tiles, floor, target } = this.said;
    $("notice-text").textContent = `This page draws only ${fps.toFixed(fps < 10 ? 1 : 0)} `
      + `frames per second with ${tiles} tiles${floor} (it aims at ${target}).`;
  }

  /** Below the target at the lowest resolution for SLOW_FOR_MS in the gallery: say so and offer
   * fewer tiles. */
  private check(viewer: Viewer, fps: number, now: number): void {
    const tiles = this.events.galleryTiles();
    if (tiles !== this.tiles) { // another gallery (or none): its own measurements
      this.tiles = tiles;
      this.slowSince = null;
      if (!$("notice").hidden) this.hideNotice();
    }
    const { target } = viewer.resolution.rule;
    const slow = tiles !== null && !this.pending && this.events.playing() && fps > 0
      && fps < target && (viewer.resolution.exhausted || !viewer.dynamic)
      && !this.dismissed.has(tiles);
    if (!slow) { this.slowSince = null; return; }
    this.slowSince ??= now;
    if (now - this.slowSince < SLOW_FOR_MS || !$("notice").hidden) return;
    const offer = fewerTiles(tiles, fps, target, this.events.smallest());
    const said = viewer.resolution.describe();
    this.said = { tiles, target, floor: said ? `, even ${said.replace(/ to keep .*/, "")}` : "" };
    this.sayRate(fps);
    const button = $<HTMLButtonElement>("notice-fewer");
    button.hidden = offer === null;
    button.textContent = `show ${offer} tiles`;
    button.onclick = () => {
      this.hideNotice();
      if (offer === null) return;
      this.pending = true;
      void this.events.newGallery(offer).finally(() => {
        this.pending = false;
        this.slowSince = null;
      });
    };
    $("notice").hidden = false;
  }
}
