// The rig player's *surface* section (docs/design.md#surface-of-a-rig): off by default; on, the
// skin ripples in its harmonics while the bones sway — a gallery of surface dances calibrated on
// the song to choose from (or the surface genes of the dance the player opened), and its gain.
import { $ } from "./dom";
import type { Mapping } from "./filter";
import type { Rig } from "./rig-bundle";
import { SurfacePlay, rigSurface, surfaceGallery } from "./rig-surface";
import type { RigSurface } from "./rig-surface";

/** The share is measured this long after the last change (ms). */
const SHARE_DELAY_MS = 150;

export interface RigSurfaceEvents {
  rig(): Rig | null;
  songId(): string;
  /** draw the rig with this surface (null: the modal skin alone) */
  play(surface: SurfacePlay | null): void;
  guard(what: string, task: () => Promise<void>): Promise<unknown>;
  /** the surface's share of the player's motion (null: off) */
  share(): number | null;
  /** the surface dances calibrated on the song, or null when off (the dance gallery's genes) */
  dances(dances: Mapping[] | null): void;
}

export class RigSurfaceView {
  private surface: RigSurface | null = null;
  private dances: Mapping[] = [];
  /** the menu: the surface dances, then the genes of dances the player opened */
  private menu: Mapping[] = [];
  private song = "";
  private current: SurfacePlay | null = null;
  private pending: ReturnType<typeof setTimeout> | undefined;

  constructor(private readonly events: RigSurfaceEvents) {
    const toggle = $<HTMLInputElement>("rig-surface");
    toggle.addEventListener("change", () => {
      void this.events.guard("Could not ripple the skin", () => this.switchTo(toggle.checked));
    });
    $<HTMLSelectElement>("rig-surface-dance").addEventListener("change", () => this.choose());
    const gain = $<HTMLInputElement>("rig-surface-gain");
    gain.addEventListener("input", () => {
      $("rig-surface-gain-out").textContent = `${Number(gain.value).toFixed(2)}×`;
      if (this.current) this.current.gain = Number(gain.value);
      this.refreshShare();
    });
  }

  /** The surface as played (a rig mapping's `surface` genes), or null when off. */
  get genes(): Mapping | null { return this.current?.genes() ?? null; }

  /** A new rig (opened or edited: its skin's harmonics change with its rest pose): off. */
  reset(): void {
    this.surface = null;
    this.current = null;
    this.dances = this.menu = []; // calibrated on the skin's harmonics: on again, anew
    this.events.dances(null);
    $<HTMLInputElement>("rig-surface").checked = false;
    this.enable(false);
    $("rig-surface-share").textContent = "";
  }

  /** A new song: the surface dances are calibrated on it again. */
  async songChanged(): Promise<void> {
    if (this.current) await this.switchTo(true);
  }

  private async switchTo(on: boolean): Promise<void> {
    const rig = this.events.rig();
    if (!on || !rig) {
      this.current = null;
      this.enable(false);
      this.events.play(null);
      this.events.dances(null);
      this.showShare();
      return;
    }
    this.surface ??= await rigSurface(rig.id);
    if (this.song !== this.events.songId() || !this.dances.length) {
      this.song = this.events.songId();
      this.dances = await surfaceGallery(rig.id, this.song);
      this.menu = [...this.dances];
      const select = $<HTMLSelectElement>("rig-surface-dance");
      select.replaceChildren(...this.dances.map((_, i) => new Option(`dance ${i + 1}`, String(i))));
    }
    this.enable(true);
    this.choose();
    this.events.dances(this.dances);
  }

  /** The player opened a dance: the skin ripples by its surface genes, the surface turned on
   * for them (a bred one joins the menu); without genes the surface is turned off. */
  async follow(genes: Mapping | null): Promise<void> {
    if ((genes !== null) !== (this.current !== null)) {
      $<HTMLInputElement>("rig-surface").checked = genes !== null;
      await this.switchTo(genes !== null);
    }
    if (genes) this.playGenes(genes);
  }

  private playGenes(genes: Mapping): void {
    if (!this.current) return;
    let index = this.menu.indexOf(genes);
    if (index < 0) {
      index = this.menu.push(genes) - 1;
      $<HTMLSelectElement>("rig-surface-dance").add(new Option(
        `a dance's own ${index - this.dances.length + 1}`, String(index)));
    }
    $<HTMLSelectElement>("rig-surface-dance").value = String(index);
    this.choose();
  }

  private choose(): void {
    if (!this.surface || !this.menu.length) return;
    const index = Number($<HTMLSelectElement>("rig-surface-dance").value) || 0;
    this.current = new SurfacePlay(this.surface, this.menu[index],
      Number($<HTMLInputElement>("rig-surface-gain").value));
    this.events.play(this.current);
    this.showShare();
  }

  /** The share again once the gain or the player's dance stops changing (a slider's drag). */
  refreshShare(): void {
    if (!this.current) return;
    clearTimeout(this.pending);
    this.pending = setTimeout(() => this.showShare(), SHARE_DELAY_MS);
  }

  /** The surface's share of the motion beside its gain (`modal.surface.surface_share`). */
  showShare(): void {
    const share = this.current ? this.events.share() : null;
    $("rig-surface-share").textContent = share === null ? ""
      : `${Math.round(100 * share)}% of the motion`;
  }

  private enable(on: boolean): void {
    $<HTMLSelectElement>("rig-surface-dance").disabled = !on;
    $<HTMLInputElement>("rig-surface-gain").disabled = !on;
  }
}
