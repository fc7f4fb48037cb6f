// The gallery (docs/design.md#gallery): S tiles dancing to the same song, selection, breeding,
// and the history of generations as a tree (each mesh keeps its own), with each tile's label
// (the harmonics it drives) and its two plots.
import * as api from "./api";
import { $, fileName, saveJSON } from "./dom";
import { gridColumns } from "./grid";
import { drivenHarmonics, settingsOf, withBasis } from "./filter";
import type { Mapping, Prepared } from "./filter";
import { History } from "./history";
import { keepInSession } from "./session";
import type { SavedHistory } from "./session";
import type { Motion } from "./motion";
import { drawAmplification, drawTransfer, effectiveAmplification } from "./plots";
import type { Shot } from "./viewer";

/** Pixels at the top of a tile's view under its number and its open / save buttons: the model
 * is framed below them, so nothing of it (a label on its top) hides there. */
const TILE_CAPTION = 24;

/** One tile's elements: the view the model is drawn into, its label and its two plots. */
interface Tile { element: HTMLElement; view: HTMLElement; label: HTMLElement;
  transfer: HTMLCanvasElement; amplification: HTMLCanvasElement; }

/** What the gallery asks of the rest of the page. */
export interface GalleryEvents {
  status(text: string): void;
  /** play this mapping in the player */
  open(mapping: Mapping): void;
  requestDraw(): void;
  /** Run a request; a failure is shown as an error `what: message` (never thrown). */
  guard(what: string, task: () => Promise<void>): Promise<unknown>;
  /** the song the tiles dance to (children are bounded on it) */
  songId(): string;
  /** the model's name (download names) */
  modelName(): string;
}

/** "harmonics 4–7", "harmonic 1", or "still" for the tile label. */
export function harmonicsLabel(driven: number[]): string {
  if (!driven.length) return "still";
  const [low, high] = [driven[0], driven[driven.length - 1]];
  return low === high ? `harmonic ${low}` : `harmonics ${low}–${high}`;
}

export class GalleryView {
  /** tiles per generation; null: the server's default (its rule could not be read) */
  size: number | null;
  private histories = new Map<string, History<Mapping>>();
  private meshId = "";
  private prepared: Prepared[] = [];
  private readonly selected = new Set<number>();
  private tiles: Tile[] = [];
  /** tiles selected when a session was restored, applied once its model shows */
  private readonly restoredSelection = new Map<string, number[]>();

  constructor(private readonly motion: Motion, private readonly events: GalleryEvents,
              size: number | null) {
    this.size = size;
    $("back").addEventListener("click", () => this.step(-1));
    $("forward").addEventListener("click", () => this.step(1));
    $<HTMLSelectElement>("generation").addEventListener("change", (event) => {
      this.setGeneration(Number((event.target as HTMLSelectElement).value));
    });
    $("breed").addEventListener("click", () => {
      void this.events.guard("Breeding failed", () => this.breed());
    });
  }

  /** The history of the current mesh. */
  get history(): History<Mapping> {
    let history = this.histories.get(this.meshId);
    if (!history) {
      history = new History<Mapping>();
      this.histories.set(this.meshId, history);
    }
    return history;
  }

  /** The mappings of the generation on screen. */
  mappings(): Mapping[] { return this.history.shown?.mappings ?? []; }

  get generation(): number { return this.history.current; }
  get generationCount(): number { return this.history.size; }
  get tileCount(): number { return this.tiles.length; }
  get selection(): number[] { return [...this.selected].sort((a, b) => a - b); }

  /** The tiles as the viewer draws them: each moved by its mapping, in its mapping's look. */
  shots(): Shot[] {
    const mappings = this.mappings();
    return this.tiles.map((tile, index) => {
      const { shading, deformedNormalWeight, materials } = settingsOf(mappings[index]);
      return { element: tile.view, prepared: this.prepared[index],
        look: { shading, deformedNormalWeight, materials } };
    });
  }

  /** Each tile's drawing area (for reading its pixels back). */
  views(): HTMLElement[] { return this.tiles.map((tile) => tile.view); }

  /** A first generation from the server (`eigendance.music.gallery.initial_gallery`, calibrated on the
   * song) of `size` tiles, added to the mesh's history. Throws the server's error; the gallery
   * on screen then stays as it was. */
  async create(meshId: string, songId: string, note: string, size = this.size): Promise<void> {
    this.events.status("making the gallery…");
    const mappings = await api.gallery(meshId, songId, size);
    this.meshId = meshId;
    this.size = mappings.length;
    this.history.add(mappings, null, note);
    this.setGeneration(this.history.current);
    this.events.status("");
  }

  /** The next generation, bred by the server (`eigendance.music.breeding.breed`) from the selected
   * tiles: a child of the generation on screen (a new branch if it already has children). */
  async breed(seed = Math.floor(Math.random() * 2 ** 31)): Promise<void> {
    const parents = this.selection.map((i) => this.mappings()[i]);
    if (!parents.length) return;
    this.events.status("breeding…");
    const from = this.history.current;
    const children = await api.breed(parents, this.size ?? parents.length, seed,
      { mesh: this.meshId, song: this.events.songId() });
    this.history.add(children, from);
    this.setGeneration(this.history.current);
    this.events.status("");
  }

  /** The mesh whose history is shown; false when it has none yet (a first gallery is due). */
  showMesh(meshId: string): boolean {
    this.meshId = meshId;
    this.setGeneration(this.history.current);
    for (const index of this.restoredSelection.get(meshId) ?? []) this.toggle(index);
    this.restoredSelection.delete(meshId);
    if (this.history.size) this.size = this.tileCount || this.size;
    return this.history.size > 0;
  }

  /** Every model's history as a session saves it (session.ts). */
  snapshot(): Record<string, SavedHistory> {
    const out: Record<string, SavedHistory> = {};
    for (const [id, history] of this.histories) {
      if (!history.size) continue;
      out[id] = { generations: history.generations, current: history.current,
        selected: id === this.meshId ? this.selection : [] };
    }
    return out;
  }

  /** Histories of a saved session, in place of these models' (others stay). */
  restore(histories: Record<string, SavedHistory>): void {
    for (const [id, saved] of Object.entries(histories)) {
      const history = new History<Mapping>();
      for (const g of saved.generations) history.add(g.mappings, g.parent, g.note);
      history.current = Math.max(0, Math.min(saved.current, history.size - 1));
      this.histories.set(id, history);
      this.restoredSelection.set(id, saved.selected ?? []);
    }
  }

  /** Forget model `id`'s history (removed from the library on purpose). */
  forget(id: string): void {
    this.histories.delete(id);
    this.restoredSelection.delete(id);
  }

  /** Keep the session in the browser after every change. */
  private persist(): void { keepInSession({ histories: this.snapshot() }); }

  /** A new basis or edited mappings: prepare the generation on screen again, redraw plots. */
  refresh(): void {
    this.prepared = this.mappings().map((mapping) => this.motion.prepare(mapping));
    this.tiles.forEach((tile, index) => this.drawPlots(tile, index));
    this.events.requestDraw();
  }

  /** Show generation `index` (clamped), with nothing selected. */
  setGeneration(index: number): void {
    const history = this.history;
    history.current = Math.max(0, Math.min(index, history.size - 1));
    if (!history.size) history.current = -1;
    this.selected.clear();
    this.prepared = this.motion.basis
      ? this.mappings().map((mapping) => this.motion.prepare(mapping)) : [];
    this.buildTiles();
    const menu = $<HTMLSelectElement>("generation");
    menu.innerHTML = "";
    for (const entry of history.entries()) {
      menu.add(new Option(entry.label, String(entry.index), false,
        entry.index === history.current));
    }
    menu.disabled = history.size < 2;
    $<HTMLButtonElement>("back").disabled = history.neighbour(-1) === history.current;
    $<HTMLButtonElement>("forward").disabled = history.neighbour(1) === history.current;
    this.updateBreedButton();
    this.events.requestDraw();
    this.persist();
  }

  /** Select or unselect tile `index`. */
  toggle(index: number): void {
    if (this.selected.has(index)) this.selected.delete(index); else this.selected.add(index);
    this.tiles[index]?.element.classList.toggle("selected", this.selected.has(index));
    this.updateBreedButton();
    this.persist();
  }

  /** The generation before (−1) or after (+1) this one in the history's tree order. */
  step(direction: -1 | 1): void { this.setGeneration(this.history.neighbour(direction)); }

  private updateBreedButton(): void {
    const button = $<HTMLButtonElement>("breed");
    button.disabled = this.selected.size === 0;
    button.textContent = this.selected.size ? `breed ${this.selected.size} selected`
      : "breed selected";
  }

  /** One tile per mapping, in the gallery's grid (grid.ts; 2 columns on a narrow screen:
   * style.css). */
  private buildTiles(): void {
    const container = $("tiles");
    container.innerHTML = "";
    const mappings = this.mappings();
    container.style.setProperty("--columns",
      String(gridColumns(mappings.length)));
    this.tiles = mappings.map((mapping, index) => {
      const tile = this.makeTile(mapping, index);
      container.appendChild(tile.element);
      this.drawPlots(tile, index);
      return tile;
    });
  }

  private drawPlots(tile: Tile, index: number): void {
    const prepared = this.prepared[index];
    const basis = this.motion.basis;
    if (!prepared || !basis) return;
    tile.label.textContent = `#${index + 1} · ${harmonicsLabel(drivenHarmonics(prepared))}`;
    drawTransfer(tile.transfer, prepared);
    drawAmplification(tile.amplification, prepared,
      effectiveAmplification(prepared, basis.coefficients));
  }

  private makeTile(mapping: Mapping, index: number): Tile {
    const element = document.createElement("div");
    element.className = "tile";
    element.dataset.index = String(index);
    element.innerHTML = `<span class="label">#${index + 1}</span>
      <div class="actions"><button class="open" title="play this tile in the player"><span
        class="long">open</span><span class="short">▶</span></button>
      <button class="save" title="download this tile's mapping (JSON)"><span
        class="long">save</span><span class="short">↓</span></button></div>
      <div class="view" data-covered="${TILE_CAPTION}"></div>
      <div class="plots"><canvas class="transfer" width="160" height="34"
        title="transfer: which harmonic of the shape each sound band drives (left: low sounds, bottom: low harmonics)"></canvas>
      <canvas class="amplification" width="160" height="34"
        title="amplification: how strongly each harmonic moves with the music (up: grows, down: shrinks; coloured: reached by the music)"></canvas></div>`;
    element.addEventListener("click", (event) => {
      const target = event.target as HTMLElement;
      if (target.closest(".open")) { this.events.open(mapping); return; }
      if (target.closest(".save")) {
        saveJSON(withBasis(mapping, this.motion.basis), fileName(this.events.modelName(),
          `g${this.history.current + 1}-${index + 1}`, "json"));
        return;
      }
      this.toggle(index);
    });
    return { element, view: element.querySelector(".view") as HTMLElement,
      label: element.querySelector(".label") as HTMLElement,
      transfer: element.querySelector(".transfer") as HTMLCanvasElement,
      amplification: element.querySelector(".amplification") as HTMLCanvasElement };
  }
}
