// The player: one mapping on a large orbitable view, with its controls — smoothing, normal
// blend, shading, the harmonics explorer, and saving / loading the mapping.
import { $, messageOf, saveJSON } from "./dom";
import type { Mapping, Prepared } from "./filter";
import type { Motion } from "./motion";
import type { Look } from "./viewer";

/** What the player asks of the rest of the page. */
export interface PlayerEvents {
  status(text: string): void;
  /** show the player with this mapping */
  open(mapping: Mapping): void;
  requestDraw(): void;
  /** the deformation path and smoothed frame time, for the info line */
  rendering(): { path: string; frameMs: number };
  /** 1 / max |U[:, ν]|: the explorer's colour scale for harmonic ν */
  harmonicScale(index: number): number;
}

export class PlayerView {
  mapping: Mapping | null = null;
  prepared: Prepared | null = null;
  /** shading of every view; `harmonic` only colours the player */
  readonly look: Look = { shading: "smooth", normalBlend: 0.4, harmonic: -1, harmonicScale: 1 };

  constructor(private readonly motion: Motion, private readonly events: PlayerEvents) {
    this.wireControls();
  }

  /** Play `mapping` (the caller switches to the player view). */
  show(mapping: Mapping): void {
    this.mapping = mapping;
    this.prepared = this.motion.prepare(mapping);
  }

  /** A new mesh: the mapping prepared for its k, and the harmonics explorer off. */
  basisChanged(): void {
    const k = this.motion.basis!.k;
    if (this.mapping) this.prepared = this.motion.prepare(this.mapping);
    this.look.harmonic = -1;
    this.look.harmonicScale = 1;
    const harmonic = $<HTMLInputElement>("harmonic");
    harmonic.value = "-1";
    harmonic.max = String(k - 1);
  }

  /** The line under the controls: mesh, k, deformation path, frame time, explored harmonic. */
  refreshInfo(): void {
    const basis = this.motion.basis;
    if (!basis) return;
    const { path, frameMs } = this.events.rendering();
    const h = this.look.harmonic;
    const harmonic = h >= 0 ? ` · harmonic ${h}: λ = ${basis.eigenvalues[h].toPrecision(4)}` : "";
    $("player-info").textContent = `${basis.name}: ${basis.n} vertices, k = ${basis.k}, `
      + `${path.toUpperCase()} deformation, ${frameMs.toFixed(0)} ms/frame${harmonic}`;
  }

  private wireControls(): void {
    const slider = (id: string, apply: (v: number) => string) => {
      const input = $<HTMLInputElement>(id);
      input.addEventListener("input", () => {
        $(`${id}-out`).textContent = apply(Number(input.value));
        this.events.requestDraw();
      });
    };
    slider("smoothing", (v) => { this.motion.setSmoothing(v); return `${v.toFixed(2)} s`; });
    slider("blend", (v) => { this.look.normalBlend = v; return v.toFixed(2); });
    $("shading").addEventListener("change", (e) => {
      this.look.shading = (e.target as HTMLSelectElement).value as Look["shading"];
      this.events.requestDraw();
    });
    const harmonic = $<HTMLInputElement>("harmonic");
    harmonic.addEventListener("input", () => this.explore(harmonic.value));
    $("save-mapping").addEventListener("click", () => {
      if (this.mapping) saveJSON(this.mapping, "mapping.json");
    });
    $("load-mapping").addEventListener("change", (e) => {
      const file = (e.target as HTMLInputElement).files?.[0];
      if (file) void this.loadMapping(file);
    });
  }

  /** The harmonics explorer: colour the mesh by eigenvector ν (−1 or nonsense: off). */
  private explore(text: string): void {
    const k = this.motion.basis?.k ?? 1;
    const value = Math.min(k - 1, Math.max(-1, Math.floor(Number(text))));
    this.look.harmonic = Number.isFinite(value) ? value : -1;
    this.look.harmonicScale = this.look.harmonic >= 0
      ? this.events.harmonicScale(this.look.harmonic) : 1;
    this.refreshInfo();
    this.events.requestDraw();
  }

  private async loadMapping(file: File): Promise<void> {
    try {
      const mapping = JSON.parse(await file.text()) as Mapping;
      if (mapping.format !== "eigendance.mapping") throw new Error("not an eigendance mapping");
      this.events.open(mapping);
    } catch (error) {
      this.events.status(`${file.name}: ${messageOf(error)}`);
    }
  }
}
