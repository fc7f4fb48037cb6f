// The rig's galleries (docs/web.md#rigs-in-the-page): the gallery of modes — one tile per
// vibration mode, lowest first, each oscillating alone at its time-scaled frequency, printed
// under it; a page of at most the gallery rule's largest size, and "more modes" for the rest —
// and the gallery of dances: mode mappings calibrated on the song (`POST api/rig-gallery`) bred
// like the harmonic gallery's (`POST api/breed`). With the surface on, each dance carries its
// surface genes (docs/design.md#surface-of-a-rig): its tile ripples by them, and breeding
// crosses them as Python's `breed` does.
import * as api from "./api";
import type { CloseUp, CloseUpShot } from "./close-up";
import { $, fileName, saveJSON } from "./dom";
import { fittedColumns } from "./grid";
import { drivenHarmonics } from "./filter";
import type { Mapping, Prepared } from "./filter";
import { modeTile, prepareRig } from "./modal-skin";
import type { RigPrepared } from "./modal-skin";
import { SHOWN_HZ, modesLabel, playedFrequency, shownMode } from "./rig-bundle";
import type { Rig } from "./rig-bundle";
import type { RigDance } from "./rig-surface";
import { VIEW_DIRECTION, silhouette } from "./studio";
import type { Shot, Look } from "./viewer";

export type RigGalleryMode = "modes" | "dances";

/** What a dance drives: the modes its bands reach with a non-zero amplification, and its time
 * scale ("modes 1–2 · ×1.15 time scale"; one mode: its frequency as played). */
export function danceLabel(rig: Rig, prepared: RigPrepared): string {
  const driven = drivenHarmonics(prepared).map((target) => prepared.selected[target]);
  if (driven.length === 1) {
    return `${modesLabel(driven)} · ${playedFrequency(rig.frequencies[driven[0]],
      prepared.timeScale)}`;
  }
  return `${modesLabel(driven)} · ×${prepared.timeScale.toFixed(2)} time scale`;
}

/** Rigs are shaded by the normals of their deformed faces (thesis §6.3), in their materials
 * unless the rig player's switch says clay (one switch for the rig's tiles and player). */
export const RIG_LOOK: Look = { shading: "smooth", deformedNormalWeight: 1, materials: true };

interface Tile { element: HTMLElement; view: HTMLElement; label: HTMLElement; closeUp?: CloseUpShot; }

export interface RigGalleryEvents {
  status(text: string): void;
  requestDraw(): void;
  guard(what: string, task: () => Promise<void>): Promise<unknown>;
  /** the song the dances are calibrated on (children are bounded on it) */
  songId(): string;
  /** play the selected modes (mode gallery) or this dance in the player */
  combine(modes: number[]): void;
  open(mapping: Mapping, source: string): void;
  /** the time scale the mode tiles play at (the player's palette's) */
  timeScale(): number;
  /** the dances' generations or selection changed (the session keeps them) */
  changed?(): void;
  /** a mode tile's close-up of the part that moves, or null: the mode is not localised */
  closeUp?(prepared: RigPrepared): CloseUp | null;
}

export class RigGalleryView {
  mode: RigGalleryMode = "modes";
  /** modes per page */
  pageSize = 16;
  page = 0;
  /** the dances: generations of mode mappings (the last one shown unless chosen) */
  generations: Mapping[][] = [];
  generation = -1;
  private rig: Rig | null = null;
  private prepared: RigPrepared[] = [];
  private tiles: Tile[] = [];
  private readonly selectedModes = new Set<number>();
  private readonly selectedDances = new Set<number>();
  /** the surface section's dances while it is on (null: off, the dances are the bones' alone) */
  private surfaces: Mapping[] | null = null;
  private shape: { rig: Rig; aspect: number } | null = null;
  /** the close-ups of the rig's modes (null: none), computed once per mode */
  private readonly closeUps = new Map<number, CloseUp | null>();

  constructor(private readonly events: RigGalleryEvents) {
    $("rig-show-modes").addEventListener("click", () => this.setMode("modes"));
    $("rig-show-dances").addEventListener("click", () => this.setMode("dances"));
    $("rig-prev-modes").addEventListener("click", () => this.setPage(this.page - 1));
    $("rig-more-modes").addEventListener("click", () => this.setPage(this.page + 1));
    $("rig-combine").addEventListener("click", () => {
      this.events.combine([...this.selectedModes].sort((a, b) => a - b));
    });
    $("rig-breed").addEventListener("click", () => {
      void this.events.guard("Breeding failed", () => this.breed());
    });
    $<HTMLSelectElement>("rig-generation").addEventListener("change", (event) => {
      this.showGeneration(Number((event.target as HTMLSelectElement).value));
    });
  }

  get pages(): number { return this.rig ? Math.max(1, Math.ceil(this.rig.k / this.pageSize)) : 1; }

  /** The modes on this page, lowest first. */
  get modes(): number[] {
    if (!this.rig) return [];
    const first = this.page * this.pageSize;
    return Array.from({ length: Math.max(0, Math.min(this.pageSize, this.rig.k - first)) },
      (_, i) => first + i);
  }

  get selection(): number[] {
    const chosen = this.mode === "modes" ? this.selectedModes : this.selectedDances;
    return [...chosen].sort((a, b) => a - b);
  }

  dances(): Mapping[] { return this.generations[this.generation] ?? []; }

  /** Dance `index` as it plays, opens, saves and breeds: while the surface is on, with its
   * surface genes (its own, else the surface section's dance index mod m); while it is off,
   * without them. */
  dance(index: number): RigDance {
    const { surface, ...bones } = this.dances()[index] as RigDance;
    const surfaces = this.surfaces;
    return surfaces?.length
      ? { ...bones, surface: surface ?? surfaces[index % surfaces.length] } : bones;
  }

  /** The surface section's dances (null: the surface is off); the dance tiles follow. */
  setSurfaces(surfaces: Mapping[] | null): void {
    this.surfaces = surfaces;
    if (this.mode === "dances") this.build();
  }

  /** The surface genes of the dance tile drawn with `prepared` (null: none, or a mode tile). */
  surfaceGenes(prepared: Prepared): Mapping | null {
    const index = this.mode === "dances" ? this.prepared.indexOf(prepared as RigPrepared) : -1;
    return index < 0 ? null : this.dance(index).surface ?? null;
  }

  shots(): Shot[] {
    return this.tiles.map((tile, i) => ({ element: tile.view, prepared: this.prepared[i],
      look: RIG_LOOK, closeUp: tile.closeUp }));
  }

  views(): HTMLElement[] { return this.tiles.map((tile) => tile.view); }

  labels(): string[] { return this.tiles.map((tile) => tile.label.textContent ?? ""); }

  /** Each tile's close-up (its corner, the moving part's vertices, share of the model and box
   * in it, its turn from the tile's view and its tag), or null. */
  closeUpsShown(): ({ corner: string; count: number; share: number; box: number[];
    turn: number; tag: string } | null)[] {
    return this.tiles.map(({ closeUp }) => closeUp ? { corner: closeUp.closeUp.corner,
      count: closeUp.closeUp.count, share: closeUp.closeUp.share, box: closeUp.closeUp.box,
      turn: closeUp.closeUp.turn, tag: closeUp.element.textContent ?? "" } : null);
  }

  /** A new rig (or the same one edited: same modes kept selected when they still exist). */
  setRig(rig: Rig, fresh: boolean): void {
    this.rig = rig;
    this.closeUps.clear(); // a new rest pose or stiffness: new modes
    if (fresh) {
      this.page = 0;
      this.selectedModes.clear();
      this.selectedDances.clear();
      this.generations = [];
      this.generation = -1;
    }
    for (const mode of this.selectedModes) if (mode >= rig.k) this.selectedModes.delete(mode);
    this.setPage(Math.min(this.page, this.pages - 1));
  }

  /** The first generation of dances: the rig gallery calibrated on the song. */
  setDances(mappings: Mapping[]): void {
    this.generations = [mappings];
    this.showGeneration(0);
  }

  setMode(mode: RigGalleryMode): void {
    this.mode = mode;
    $("rig-show-modes").classList.toggle("active", mode === "modes");
    $("rig-show-dances").classList.toggle("active", mode === "dances");
    $("rig-modes-controls").hidden = mode !== "modes";
    $("rig-dances-controls").hidden = mode !== "dances";
    this.build();
  }

  setPage(page: number): void {
    this.page = Math.max(0, Math.min(page, this.pages - 1));
    if (this.mode === "modes") this.build();
  }

  showGeneration(index: number, selected: number[] = []): void {
    this.generation = Math.max(0, Math.min(index, this.generations.length - 1));
    this.selectedDances.clear();
    for (const dance of selected) if (dance < this.dances().length) this.selectedDances.add(dance);
    const menu = $<HTMLSelectElement>("rig-generation");
    menu.innerHTML = "";
    this.generations.forEach((_, i) => menu.add(new Option(`generation ${i + 1}`, String(i),
      false, i === this.generation)));
    if (this.mode === "dances") this.build();
    this.events.changed?.();
  }

  /** Generations of a saved session (session.ts), the one shown and its dances selected. */
  restoreDances(generations: Mapping[][], generation: number, selected: number[]): void {
    if (!generations.length) return;
    this.generations = generations;
    this.showGeneration(generation, selected);
  }

  /** The dances selected (whichever gallery is shown). */
  get selectedDanceList(): number[] { return [...this.selectedDances].sort((a, b) => a - b); }

  /** The grid's columns for the rig's shape and the area the tiles have (`fittedColumns`):
   * the rig fills its tiles (again when the window or the view changes). */
  layout(): void {
    const container = $("rig-tiles");
    const area = container.getBoundingClientRect();
    const gap = 6, padding = 20; // #rig-tiles: gap and side padding (style.css)
    container.style.setProperty("--columns", String(fittedColumns(this.tiles.length
      || this.prepared.length, area.width - padding, area.height - 10, this.aspect, gap)));
  }

  /** The rig's width over its height as the tiles' camera sees it at rest. */
  private get aspect(): number {
    if (!this.rig) return 1;
    if (this.shape?.rig !== this.rig) {
      const { x, y } = silhouette(this.rig.vertices, VIEW_DIRECTION);
      const span = (values: Float32Array) => values.reduce((a, b) => Math.max(a, b), -Infinity)
        - values.reduce((a, b) => Math.min(a, b), Infinity);
      this.shape = { rig: this.rig, aspect: span(x) / Math.max(span(y), 1e-9) };
    }
    return this.shape.aspect;
  }

  /** The time scale changed (the player's palette): the mode tiles follow. */
  refresh(): void { this.build(); }

  toggle(index: number): void {
    const chosen = this.mode === "modes" ? this.selectedModes : this.selectedDances;
    const key = this.mode === "modes" ? this.modes[index] : index;
    if (key === undefined) return;
    if (chosen.has(key)) chosen.delete(key); else chosen.add(key);
    this.tiles[index]?.element.classList.toggle("selected", chosen.has(key));
    this.updateButtons();
    if (this.mode === "dances") this.events.changed?.();
  }

  /** The next generation of dances from the selected ones (`eigendance.music.breeding.breed`). */
  async breed(seed = Math.floor(Math.random() * 2 ** 31)): Promise<void> {
    const parents = [...this.selectedDances].sort((a, b) => a - b).map((i) => this.dance(i));
    if (!parents.length) return;
    this.events.status("breeding…");
    const children = await api.breed(parents, this.dances().length, seed,
      { rig: this.rig!.id, song: this.events.songId() });
    this.generations.push(children);
    this.showGeneration(this.generations.length - 1);
    this.events.status("");
  }

  private updateButtons(): void {
    const combine = $<HTMLButtonElement>("rig-combine");
    combine.disabled = this.selectedModes.size === 0;
    combine.textContent = this.selectedModes.size
      ? `combine ${this.selectedModes.size} selected` : "combine selected";
    const breed = $<HTMLButtonElement>("rig-breed");
    breed.disabled = this.selectedDances.size === 0;
    breed.textContent = this.selectedDances.size
      ? `breed ${this.selectedDances.size} selected` : "breed selected";
    $<HTMLButtonElement>("rig-prev-modes").disabled = this.page === 0;
    $<HTMLButtonElement>("rig-more-modes").disabled = this.page >= this.pages - 1;
    const modes = this.modes;
    $("rig-modes-page").textContent = this.rig && modes.length
      ? `modes ${modes[0] + 1}–${modes[modes.length - 1] + 1} of ${this.rig.k}` : "";
  }

  /** One tile per mode of the page, or per dance, in the gallery's grid (grid.ts). */
  private build(): void {
    const rig = this.rig;
    const container = $("rig-tiles");
    container.innerHTML = "";
    this.tiles = [];
    this.prepared = [];
    if (rig) {
      const s = this.events.timeScale();
      if (this.mode === "modes") {
        this.prepared = this.modes.map((mode) => modeTile(rig, mode,
          shownMode(rig.frequencies[mode], s).timeScale));
      } else {
        this.prepared = this.dances().map((mapping) => prepareRig(rig, mapping));
      }
      this.layout();
      this.tiles = this.prepared.map((prepared, index) => {
        const tile = this.makeTile(index, prepared);
        container.appendChild(tile.element);
        return tile;
      });
    }
    this.updateButtons();
    this.events.requestDraw();
  }

  private makeTile(index: number, prepared: RigPrepared): Tile {
    const rig = this.rig!;
    const element = document.createElement("div");
    element.className = "rig-tile";
    element.innerHTML = `<div class="view"></div><div class="caption"></div>`;
    const label = element.querySelector(".caption") as HTMLElement;
    if (this.mode === "modes") {
      const mode = prepared.selected[0];
      const natural = rig.frequencies[mode];
      const palette = this.events.timeScale();
      label.textContent = `mode ${mode + 1} · ${shownMode(natural, palette).label}`;
      label.title = `natural frequency ${natural.toFixed(3)} Hz; played at the palette's time `
        + `scale ×${palette.toFixed(2)}: ${(natural * palette).toFixed(3)} Hz; this tile shows it `
        + `× ${prepared.timeScale.toFixed(3)} (a page shows ${SHOWN_HZ.low}–${SHOWN_HZ.high} Hz); `
        + "click to select, then combine";
      element.classList.toggle("selected", this.selectedModes.has(mode));
    } else {
      label.textContent = `#${index + 1} · ${danceLabel(rig, prepared)}`
        + (this.dance(index).surface ? " · rippling skin" : "");
      label.title = "the modes this dance's mapping drives (a band reaches them with a non-zero "
        + "amplification), at its time scale";
      element.classList.toggle("selected", this.selectedDances.has(index));
      const actions = document.createElement("div");
      actions.className = "actions";
      actions.innerHTML = `<button class="open" title="play this dance in the player">open</button>
        <button class="save" title="download this mapping (JSON)">save</button>`;
      element.appendChild(actions);
    }
    element.addEventListener("click", (event) => {
      const target = event.target as HTMLElement;
      const mapping = this.dance(index);
      if (target.closest(".open")) { this.events.open(mapping, `dance ${index + 1}`); return; }
      if (target.closest(".save")) {
        saveJSON(mapping, fileName(rig.name, `g${this.generation + 1}-${index + 1}`, "json"));
        return;
      }
      this.toggle(index);
    });
    const view = element.querySelector(".view") as HTMLElement;
    const closeUp = this.mode === "modes" ? this.closeUpOf(prepared) : null;
    return { element, view, label, closeUp: closeUp ? closeUpFrame(view, closeUp) : undefined };
  }

  /** Mode `prepared`'s close-up (computed once per mode of the rig). */
  private closeUpOf(prepared: RigPrepared): CloseUp | null {
    const mode = prepared.selected[0];
    if (!this.closeUps.has(mode)) this.closeUps.set(mode, this.events.closeUp?.(prepared) ?? null);
    return this.closeUps.get(mode)!;
  }
}

/** The close-up's frame in its corner of a mode tile's view, tagged (close-up.ts draws it). */
function closeUpFrame(view: HTMLElement, closeUp: CloseUp): CloseUpShot {
  const element = document.createElement("div");
  element.className = `close-up ${closeUp.corner}`;
  const side = ["", "side", "behind", "side"][closeUp.turn];
  element.title = "close-up of the part this mode moves (it spans "
    + `${Math.round(100 * closeUp.share)}% of the model): the same skin, seen nearer`
    + (side ? `, from ${side === "side" ? "the side" : "the far side"} (where its motion `
      + "shows), cut away before it" : "");
  element.innerHTML = `<span class="tag">close-up${side ? `: ${side}` : ""}</span>`;
  view.appendChild(element);
  return { element, closeUp };
}
