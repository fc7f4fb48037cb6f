// The gallery (docs/design.md#gallery): S tiles dancing to the same song, selection, breeding, and the
// generations one can go back and forth through (◀ ▶), with each tile's two plots.
import * as api from "./api";
import { TILE_COLORS } from "./deform";
import { $, saveJSON } from "./dom";
import type { Mapping, Prepared } from "./filter";
import type { Motion } from "./motion";
import { drawAmplification, drawTransfer } from "./plots";
import type { Shot } from "./viewer";

/** One tile's elements: the view the mesh is drawn into and its two plots. */
interface Tile { element: HTMLElement; view: HTMLElement; transfer: HTMLCanvasElement;
  amplification: HTMLCanvasElement; }

/** What the gallery asks of the rest of the page. */
export interface GalleryEvents {
  status(text: string): void;
  /** play this mapping in the player */
  open(mapping: Mapping): void;
  requestDraw(): void;
  /** Run a request; a failure shows in the status line as `what: message` (never thrown). */
  guard(what: string, task: () => Promise<void>): Promise<unknown>;
}

export class GalleryView {
  /** every generation so far; breeding from an earlier one drops those after it */
  private generations: Mapping[][] = [];
  private index = 0;
  private prepared: Prepared[] = [];
  private readonly selected = new Set<number>();
  private tiles: Tile[] = [];

  /** `size`: tiles per generation, already checked against the gallery rule. */
  constructor(private readonly motion: Motion, private readonly events: GalleryEvents,
              public size: number) {
    $("back").addEventListener("click", () => this.setGeneration(this.index - 1));
    $("forward").addEventListener("click", () => this.setGeneration(this.index + 1));
    $("breed").addEventListener("click", () => {
      void this.events.guard("breeding", () => this.breed());
    });
  }

  /** The mappings of the generation on screen. */
  mappings(): Mapping[] { return this.generations[this.index] ?? []; }

  get generation(): number { return this.index; }
  get generationCount(): number { return this.generations.length; }
  get tileCount(): number { return this.tiles.length; }
  get selection(): number[] { return [...this.selected]; }

  /** The tiles as the viewer draws them. */
  shots(): Shot[] {
    return this.tiles.map((tile, index) => ({ element: tile.view, prepared: this.prepared[index],
      colorIndex: index }));
  }

  /** Each tile's drawing area (for reading its pixels back). */
  views(): HTMLElement[] { return this.tiles.map((tile) => tile.view); }

  /** A first generation from the server (`eigendance.mapping.initial_gallery`) of `size` tiles.
   * Throws the server's error; the gallery on screen then stays as it was. */
  async create(meshId: string, songId: string, size = this.size): Promise<void> {
    this.events.status("making the gallery…");
    const mappings = await api.gallery(meshId, songId, size);
    this.size = size;
    this.generations = [mappings];
    this.setGeneration(0);
    this.events.status("");
  }

  /** The next generation, bred by the server (`eigendance.mapping.breed`) from the selected
   * tiles; it replaces any generations after the one on screen. */
  async breed(seed = Math.floor(Math.random() * 2 ** 31)): Promise<void> {
    const parents = [...this.selected].sort((a, b) => a - b).map((i) => this.mappings()[i]);
    if (!parents.length) return;
    this.events.status("breeding…");
    const children = await api.breed(parents, this.size, seed);
    this.generations = this.generations.slice(0, this.index + 1);
    this.generations.push(children);
    this.setGeneration(this.generations.length - 1);
    this.events.status("");
  }

  /** A new mesh: the generation on screen prepared for its k (until its own gallery comes). */
  basisChanged(): void {
    this.prepared = this.mappings().map((mapping) => this.motion.prepare(mapping));
  }

  /** Show generation `index` (clamped), with nothing selected. */
  setGeneration(index: number): void {
    this.index = Math.max(0, Math.min(index, this.generations.length - 1));
    this.selected.clear();
    this.prepared = this.mappings().map((mapping) => this.motion.prepare(mapping));
    this.buildTiles();
    $("generation").textContent = `generation ${this.index + 1} of ${this.generations.length}`;
    $<HTMLButtonElement>("back").disabled = this.index === 0;
    $<HTMLButtonElement>("forward").disabled = this.index >= this.generations.length - 1;
    this.updateBreedButton();
    this.events.requestDraw();
  }

  toggle(index: number): void {
    if (this.selected.has(index)) this.selected.delete(index); else this.selected.add(index);
    this.tiles[index]?.element.classList.toggle("selected", this.selected.has(index));
    this.updateBreedButton();
  }

  private updateBreedButton(): void {
    $<HTMLButtonElement>("breed").disabled = this.selected.size === 0;
  }

  /** One tile per mapping, in a grid about 1.5 times wider than tall. */
  private buildTiles(): void {
    const container = $("tiles");
    container.innerHTML = "";
    const mappings = this.mappings();
    container.style.setProperty("--columns", String(Math.ceil(Math.sqrt(mappings.length * 1.5))));
    let largest = 1e-12;
    for (const m of mappings) {
      for (const a of m.amplification) largest = Math.max(largest, Math.abs(a));
    }
    this.tiles = mappings.map((mapping, index) => {
      const tile = this.makeTile(mapping, index);
      container.appendChild(tile.element);
      const color = TILE_COLORS[index % TILE_COLORS.length];
      drawTransfer(tile.transfer, mapping, color);
      drawAmplification(tile.amplification, mapping, largest, color);
      return tile;
    });
  }

  private makeTile(mapping: Mapping, index: number): Tile {
    const element = document.createElement("div");
    element.className = "tile";
    element.dataset.index = String(index);
    element.innerHTML = `<span class="label">#${index + 1}</span>
      <div class="actions"><button class="open" title="open in the player">open</button>
      <button class="save" title="download this mapping (JSON)">save</button></div>
      <div class="view"></div>
      <div class="plots"><canvas class="transfer" width="160" height="34" title="transfer: band → harmonic"></canvas>
      <canvas class="amplification" width="160" height="34" title="amplification per harmonic"></canvas></div>`;
    element.addEventListener("click", (event) => {
      const target = event.target as HTMLElement;
      if (target.closest(".open")) { this.events.open(mapping); return; }
      if (target.closest(".save")) {
        saveJSON(mapping, `mapping-g${this.index + 1}-${index + 1}.json`);
        return;
      }
      this.toggle(index);
    });
    return { element, view: element.querySelector(".view") as HTMLElement,
      transfer: element.querySelector(".transfer") as HTMLCanvasElement,
      amplification: element.querySelector(".amplification") as HTMLCanvasElement };
  }
}
