// The rig's player (docs/web.md#rigs-in-the-page): one mode mapping on the skinned mesh, with
// its palette — the selected modes, each with an amplitude and a phase slider, the time scale s,
// music on or off, gain and offset b — the modal-skinning / LBS switch, the bones, the pose
// editor (thesis Fig. 4.17: pick a joint, turn it about x, y, z; the modes are recomputed) and
// per-joint stiffness. *save mapping* writes a version-2 mapping with `modes` and `offset`.
import { $, fileName, saveJSON } from "./dom";
import type { Mapping } from "./filter";
import { prepareRig } from "./modal-skin";
import { paletteOf } from "./palette";
import { floorCap } from "./floor";
import type { RigPrepared } from "./modal-skin";
import { playedFrequency } from "./rig-bundle";
import type { ModeSettings, Rig } from "./rig-bundle";
import { RIG_LOOK } from "./rig-gallery-view";
import type { RigDance } from "./rig-surface";
import type { Shot } from "./viewer";

export type Skinning = "modal" | "lbs";

export interface RigPlayerEvents {
  requestDraw(): void;
  /** the palette's time scale changed (the mode tiles follow it) */
  timeScaleChanged(): void;
  guard(what: string, task: () => Promise<void>): Promise<unknown>;
  /** Equilibrium pose: turn `joint` by the rotation vector (radians, world). */
  pose(joint: number, rotation: [number, number, number]): Promise<void>;
  stiffness(joint: number, value: number | "auto"): Promise<void>;
  reset(): Promise<void>;
  /** the surface's mapping as played (saved as the mapping's `surface` genes), or null */
  surface?(): Mapping | null;
  /** the dance played changed (its palette, gain, offset, music: the session keeps it, the
   * surface's share follows) */
  changed?(): void;
}

const DEGREES = Math.PI / 180;

export class RigPlayerView {
  mapping: Mapping | null = null;
  palette: ModeSettings | null = null;
  prepared: RigPrepared | null = null;
  source = "";
  music = true;
  skinning: Skinning = "modal";
  bones = false;
  /** the joint the pose editor turns (−1: none) */
  joint = -1;
  private rig: Rig | null = null;
  /** what the rotation sliders of the picked joint have turned so far (degrees) */
  private turned: [number, number, number] = [0, 0, 0];

  constructor(private readonly events: RigPlayerEvents) {
    const range = (id: string, show: (value: number) => string, apply: (value: number) => void) => {
      const input = $<HTMLInputElement>(id);
      input.addEventListener("input", () => {
        $(`${id}-out`).textContent = show(Number(input.value));
        apply(Number(input.value));
      });
    };
    range("rig-scale", (v) => `${v.toFixed(2)}×`, (v) => {
      if (!this.palette) return;
      this.palette.time_scale = v;
      this.buildPalette(); // the frequencies shown are as played
      this.update();
      this.events.timeScaleChanged();
    });
    range("rig-gain", (v) => `${v.toFixed(2)}×`, (v) => {
      if (this.mapping) { this.mapping.gain = v; this.update(); }
    });
    range("rig-offset", (v) => v.toFixed(2), (v) => {
      if (this.mapping) { this.mapping.offset = v; this.update(); }
    });
    $<HTMLInputElement>("rig-beat").addEventListener("change", (e) => {
      if (!this.palette) return;
      this.palette.tempo = (e.target as HTMLInputElement).checked ? "beat" : "free";
      this.update();
    });
    $<HTMLInputElement>("rig-music").addEventListener("change", (e) => {
      this.music = (e.target as HTMLInputElement).checked;
      this.update();
    });
    $<HTMLSelectElement>("rig-skinning").addEventListener("change", (e) => {
      this.skinning = (e.target as HTMLSelectElement).value as Skinning;
      this.events.requestDraw();
    });
    $<HTMLInputElement>("rig-materials").addEventListener("change", (e) => {
      RIG_LOOK.materials = (e.target as HTMLInputElement).checked;
      this.events.requestDraw();
    });
    $<HTMLInputElement>("rig-bones").addEventListener("change", (e) => {
      this.bones = (e.target as HTMLInputElement).checked;
      this.events.requestDraw();
    });
    $<HTMLSelectElement>("rig-joint").addEventListener("change", (e) => {
      this.pick(Number((e.target as HTMLSelectElement).value));
    });
    (["x", "y", "z"] as const).forEach((axis, a) => {
      const input = $<HTMLInputElement>(`rig-turn-${axis}`);
      input.addEventListener("input", () => {
        $(`rig-turn-${axis}-out`).textContent = `${input.value}°`;
      });
      input.addEventListener("change", () => {
        const value = Number(input.value), delta = value - this.turned[a];
        if (this.joint < 0 || delta === 0) return;
        const rotation: [number, number, number] = [0, 0, 0];
        rotation[a] = delta * DEGREES;
        void this.events.guard("Could not turn the joint", async () => {
          await this.events.pose(this.joint, rotation);
          this.turned[a] = value;
        }).then(() => { // a refused turn (a joint closing a loop) puts the slider back
          input.value = String(this.turned[a]);
          $(`rig-turn-${axis}-out`).textContent = `${this.turned[a]}°`;
        });
      });
    });
    $("rig-reset").addEventListener("click", () => {
      void this.events.guard("Could not reset the rig", () => this.events.reset());
    });
    $("rig-stiffness-set").addEventListener("click", () => {
      const value = Number($<HTMLInputElement>("rig-stiffness").value);
      if (this.joint < 0) return;
      void this.events.guard("Could not set the stiffness",
        () => this.events.stiffness(this.joint, value));
    });
    $("rig-stiffness-auto").addEventListener("click", () => {
      if (this.joint < 0) return;
      void this.events.guard("Could not set the stiffness",
        () => this.events.stiffness(this.joint, "auto"));
    });
    $("rig-save").addEventListener("click", () => {
      const saved = this.saved();
      if (saved) saveJSON(saved, fileName(this.rig?.name ?? "", this.source, "json"));
    });
  }

  /** The player's mapping as *save mapping* writes it: version 3 with its palette and offset.
   * Music off (φ ≡ 1) is saved as gain 0 and offset 1: the same motion in every player. */
  saved(): RigDance | null {
    if (!this.mapping || !this.palette) return null;
    const saved: Mapping = { ...this.mapping, version: 3,
      gain: this.music ? this.mapping.gain ?? 1 : 0, smoothing: this.mapping.smoothing ?? 0,
      offset: this.music ? this.mapping.offset ?? 0 : 1, modes: { ...this.palette },
      look: { ...this.mapping.look, materials: RIG_LOOK.materials } };
    // The surface genes as played (docs/design.md#surface-of-a-rig), not an opened dance's.
    const { surface: _opened, ...bones } = saved as RigDance;
    const surface = this.events.surface?.() ?? null;
    return surface ? { ...bones, surface } : bones;
  }

  shot(element: HTMLElement): Shot | null {
    return this.prepared ? { element, prepared: this.prepared, look: RIG_LOOK,
      source: this.mapping ?? undefined } : null;
  }

  /** Play `mapping` (copied: the sliders change the copy). */
  show(mapping: Mapping, source: string): void {
    this.mapping = structuredClone(mapping);
    RIG_LOOK.materials = mapping.look?.materials ?? true;
    $<HTMLInputElement>("rig-materials").checked = RIG_LOOK.materials;
    this.source = source;
    this.palette = this.rig ? paletteOf(this.rig, mapping.modes as Partial<ModeSettings>) : null;
    this.buildPalette();
    this.refreshInfo();
    this.update();
  }

  /** A new rig, or the same one edited (pose, stiffness): the palette stays when it fits. */
  setRig(rig: Rig, fresh: boolean): void {
    this.rig = rig;
    if (fresh) { this.mapping = null; this.palette = null; this.prepared = null; this.joint = -1; }
    if (this.palette && this.palette.selected!.some((m) => m >= rig.k)) this.palette = null;
    if (this.mapping && !this.palette) this.palette = paletteOf(rig, null);
    const menu = $<HTMLSelectElement>("rig-joint");
    menu.innerHTML = "";
    menu.add(new Option("— pick a joint —", "-1"));
    rig.jointList.forEach((joint, j) => menu.add(new Option(`${joint.name} (${joint.type}`
      + `${joint.closes_loop ? ", in a loop" : ""})`, String(j))));
    this.pick(this.joint < rig.j ? this.joint : -1, !fresh);
    this.buildPalette();
    this.update();
    this.refreshInfo();
  }

  /** The line about the rig: its size, its lowest mode as played, and whether it was edited
   * (the server keeps pose and stiffness edits until "reset pose", a reload too). */
  refreshInfo(): void {
    const rig = this.rig;
    if (!rig) return;
    const s = this.palette?.time_scale ?? rig.palette?.time_scale ?? 1;
    const count = (n: number, one: string, many: string) => `${n} ${n === 1 ? one : many}`;
    $("rig-info").textContent = `${rig.name}: ${count(rig.b, "body", "bodies")}, `
      + `${count(rig.j, "joint", "joints")}, ${count(rig.k, "mode", "modes")}, `
      + `${count(rig.n, "vertex", "vertices")} · lowest mode ${rig.k ? playedFrequency(rig.frequencies[0], s) : "–"}`
      + (rig.edited ? " · pose or stiffness edited (kept by the server until reset pose)" : "");
  }

  /** Pick joint j for the pose editor and the stiffness field (−1: none). */
  pick(joint: number, keepTurns = false): void {
    const rig = this.rig;
    if (!rig) return;
    if (joint !== this.joint || !keepTurns) this.turned = [0, 0, 0];
    this.joint = joint;
    $<HTMLSelectElement>("rig-joint").value = String(joint);
    const info = joint >= 0 ? rig.jointList[joint] : null;
    (["x", "y", "z"] as const).forEach((axis, a) => {
      const input = $<HTMLInputElement>(`rig-turn-${axis}`);
      input.value = String(this.turned[a]);
      // A joint closing a loop cannot turn one side alone: the server would refuse it.
      input.disabled = !info || info.closes_loop;
      $(`rig-turn-${axis}-out`).textContent = `${this.turned[a]}°`;
    });
    // Without a title of its own the menu shows its label's.
    if (info?.closes_loop) {
      $("rig-joint").title = `${info.name} closes a loop: it cannot turn one side alone (its `
        + "stiffness can change)";
    } else {
      $("rig-joint").removeAttribute("title");
    }
    const field = $<HTMLInputElement>("rig-stiffness");
    field.disabled = !info;
    field.value = info?.stiffness.length ? String(+info.stiffness[0].toPrecision(4)) : "";
    $("rig-stiffness-default").textContent = info?.default_stiffness.length
      ? `default ${info.default_stiffness.map((v) => +v.toPrecision(3)).join(", ")}` : "";
    this.events.requestDraw();
  }

  /** Rebuild the prepared mapping after a change of the palette or the mapping's settings. */
  update(): void {
    if (this.rig && this.mapping && this.palette) {
      this.prepared = prepareRig(this.rig, { ...this.mapping, modes: this.palette }, this.music);
      // Together the modes would sink a limb below the floor: they play scaled down (floor.ts).
      const asked = this.palette.amplitudes!, played = this.prepared.amplitudes;
      const scale = asked.some((a) => a > 0) ? Math.max(...played.map((p, v) =>
        Math.abs(asked[v]) > 0 ? Math.abs(p / asked[v]) : 0)) : 1;
      $("rig-floor-note").hidden = scale > 0.999;
      $("rig-floor-note").textContent = `together these amplitudes would sink a limb below the `
        + `floor: they play at ×${scale.toFixed(2)}`;
    }
    this.events.changed?.();
    this.events.requestDraw();
  }

  /** Sliders of the palette: per selected mode its amplitude (degrees of reach) and phase. */
  private buildPalette(): void {
    const rig = this.rig, palette = this.palette, mapping = this.mapping;
    $("rig-source").textContent = this.source;
    const list = $("rig-palette");
    list.innerHTML = "";
    if (!rig || !palette || !mapping) return;
    const setRange = (id: string, value: number, text: string) => {
      $<HTMLInputElement>(id).value = String(value);
      $(`${id}-out`).textContent = text;
    };
    setRange("rig-scale", palette.time_scale!, `${palette.time_scale!.toFixed(2)}×`);
    $<HTMLInputElement>("rig-beat").checked = palette.tempo !== "free";
    setRange("rig-gain", mapping.gain ?? 1, `${(mapping.gain ?? 1).toFixed(2)}×`);
    setRange("rig-offset", mapping.offset ?? 0, (mapping.offset ?? 0).toFixed(2));
    palette.selected!.forEach((mode, v) => {
      const row = document.createElement("div");
      row.className = "rig-mode-row";
      const amplitude = palette.amplitudes![v] / DEGREES, phase = palette.phases![v] / DEGREES;
      // At most where the skin would sink below the floor (floor.ts).
      const largest = Math.min(Math.max(90, Math.ceil(2 * amplitude)),
        Math.floor(2 * floorCap(rig, mode) / DEGREES) / 2);
      row.innerHTML = `<span class="name" title="as played: natural frequency ${
        rig.frequencies[mode].toFixed(3)} Hz × the time scale">mode ${mode + 1} · ${
        playedFrequency(rig.frequencies[mode], palette.time_scale!)}</span>
        <label title="reach at φ = 1: the largest body rotation, degrees (at most ${largest}°: \
beyond, the skin would sink below the floor)">amplitude
        <input type="range" class="amplitude" min="0" max="${largest}" step="0.5" value="${amplitude}">
        <output>${amplitude.toFixed(1)}°</output></label>
        <label title="phase γ, degrees">phase <input type="range" class="phase" min="0"
        max="360" step="1" value="${phase % 360}"><output>${(phase % 360).toFixed(0)}°</output></label>`;
      const wire = (selector: string, values: number[], unit: string, digits: number) => {
        const input = row.querySelector(selector) as HTMLInputElement;
        input.addEventListener("input", () => {
          values[v] = Number(input.value) * DEGREES;
          (input.nextElementSibling as HTMLElement).textContent =
            `${Number(input.value).toFixed(digits)}${unit}`;
          this.update();
        });
      };
      wire(".amplitude", palette.amplitudes!, "°", 1);
      wire(".phase", palette.phases!, "°", 0);
      list.appendChild(row);
    });
  }
}
