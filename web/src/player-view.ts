// The player: one mapping on a large orbitable view, with its settings — gain, smoothing, the
// normals' facet weight, the shading and the materials / clay switch — which are the mapping's
// own (saving writes them, so
// `eigendance animate` gives what the player shows), the harmonics explorer, and saving /
// loading mappings.
import { $, fileName, saveJSON } from "./dom";
import { settingsOf, withBasis, withSettings } from "./filter";
import type { Mapping, Prepared, Settings, Shading } from "./filter";
import type { Motion } from "./motion";
import type { Explorer, Shot } from "./viewer";

/** What the player asks of the rest of the page. */
export interface PlayerEvents {
  /** add a mapping file the person chose (the server checks it), then play it */
  upload(file: File): void;
  requestDraw(): void;
  /** 1 / max |U[:, ν]|: the explorer's colour scale for harmonic ν */
  harmonicScale(index: number): number;
  /** the model's name (download names) */
  modelName(): string;
}

/** The sliders and menu of the mapping's settings, by element id. */
const SLIDERS: { id: string; key: "gain" | "smoothing" | "deformedNormalWeight";
  shown: (v: number) => string }[] = [
  { id: "gain", key: "gain", shown: (v) => `${v.toFixed(2)}×` },
  { id: "smoothing", key: "smoothing", shown: (v) => `${v.toFixed(2)} s` },
  { id: "facets", key: "deformedNormalWeight", shown: (v) => v.toFixed(2) },
];

export class PlayerView {
  mapping: Mapping | null = null;
  prepared: Prepared | null = null;
  /** where the mapping came from, for the info line and the saved file's name */
  source = "";
  readonly explorer: Explorer = { harmonic: -1, scale: 1 };

  constructor(private readonly motion: Motion, private readonly events: PlayerEvents) {
    this.wireControls();
  }

  /** Play `mapping` (the caller switches to the player view). Its settings show in the
   * controls; changing them changes the mapping itself (a gallery tile's too). */
  show(mapping: Mapping, source = ""): void {
    this.mapping = mapping;
    this.source = source;
    this.prepared = this.motion.basis ? this.motion.prepare(mapping) : null;
    const settings = settingsOf(mapping);
    for (const { id, key, shown } of SLIDERS) {
      $<HTMLInputElement>(id).value = String(settings[key]);
      $(`${id}-out`).textContent = shown(settings[key]);
    }
    $<HTMLSelectElement>("shading").value = settings.shading;
    $<HTMLInputElement>("materials").checked = settings.materials;
    $("player-source").textContent = source;
  }

  /** The player's model as the viewer draws it. */
  shot(element: HTMLElement): Shot | null {
    if (!this.mapping || !this.prepared) return null;
    const { shading, deformedNormalWeight, materials } = settingsOf(this.mapping);
    return { element, prepared: this.prepared, look: { shading, deformedNormalWeight, materials },
      source: this.mapping };
  }

  /** The mapping as a version-3 file with everything the player applies, and the basis it
   * plays on. */
  saved(): Mapping | null {
    return this.mapping
      ? withBasis(withSettings(this.mapping, this.settings()), this.motion.basis) : null;
  }

  /** A new mesh: the mapping prepared for its k, and the harmonics explorer off. */
  basisChanged(): void {
    const k = this.motion.basis!.k;
    if (this.mapping) this.prepared = this.motion.prepare(this.mapping);
    this.explorer.harmonic = -1;
    this.explorer.scale = 1;
    const harmonic = $<HTMLInputElement>("harmonic");
    harmonic.value = "-1";
    harmonic.max = String(k - 1);
  }

  /** The line under the controls: mesh, k, deformation path, explored harmonic. */
  refreshInfo(path: string): void {
    const basis = this.motion.basis;
    if (!basis) return;
    const h = this.explorer.harmonic;
    const harmonic = h >= 0 ? ` · harmonic ${h}: λ = ${basis.eigenvalues[h].toPrecision(4)}` : "";
    $("player-info").textContent = `${basis.name}: ${basis.n} vertices, k = ${basis.k}, `
      + `${path.toUpperCase()} deformation${harmonic}`;
  }

  /** The settings as the controls show them. */
  settings(): Settings {
    const value = (id: string) => Number($<HTMLInputElement>(id).value);
    return { gain: value("gain"), smoothing: value("smoothing"),
      deformedNormalWeight: value("facets"),
      shading: $<HTMLSelectElement>("shading").value as Shading,
      materials: $<HTMLInputElement>("materials").checked };
  }

  /** Write the controls' settings into the mapping (version 2) and show the change. */
  private apply(): void {
    if (!this.mapping) return;
    Object.assign(this.mapping, withSettings(this.mapping, this.settings()));
    this.prepared = this.motion.prepare(this.mapping);
    this.events.requestDraw();
  }

  private wireControls(): void {
    for (const { id, shown } of SLIDERS) {
      const input = $<HTMLInputElement>(id);
      input.addEventListener("input", () => {
        $(`${id}-out`).textContent = shown(Number(input.value));
        this.apply();
      });
    }
    $("shading").addEventListener("change", () => this.apply());
    $("materials").addEventListener("change", () => this.apply());
    const harmonic = $<HTMLInputElement>("harmonic");
    harmonic.addEventListener("input", () => this.explore(harmonic.value));
    $("save-mapping").addEventListener("click", () => {
      const mapping = this.saved();
      if (mapping) saveJSON(mapping, fileName(this.events.modelName(), this.source, "json"));
    });
    $("load-mapping").addEventListener("change", (e) => {
      const input = e.target as HTMLInputElement;
      const file = input.files?.[0];
      if (file) this.events.upload(file);
      input.value = ""; // the same file again is a new choice
    });
  }

  /** The harmonics explorer: colour the mesh by eigenvector ν (−1 or nonsense: off). */
  private explore(text: string): void {
    const k = this.motion.basis?.k ?? 1;
    const value = Math.min(k - 1, Math.max(-1, Math.floor(Number(text))));
    this.explorer.harmonic = Number.isFinite(value) ? value : -1;
    this.explorer.scale = this.explorer.harmonic >= 0
      ? this.events.harmonicScale(this.explorer.harmonic) : 1;
    this.events.requestDraw();
  }
}
