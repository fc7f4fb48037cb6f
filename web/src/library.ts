// The server's library as the page sees it: the model, song and mapping menus, and the current
// model and song, downloaded into the motion, the viewer and the audio transport (with a loading
// indicator while they come).
import * as api from "./api";
import { $, messageOf } from "./dom";
import { loadAppearance } from "./look";
import type { Motion } from "./motion";
import type { Options } from "./options";
import { rememberNames } from "./session";
import type { AudioTransport } from "./transport";
import type { Viewer } from "./viewer";

/** Above this many bytes of float32 harmonics the basis comes as float16 unless `?half=0`. */
const HALF_ABOVE_BYTES = 128 * 2 ** 20;

export class Library {
  meshId = "";
  songId = "";
  /** the model being computed or loaded (the menu names it meanwhile), or null */
  loading: string | null = null;
  /** the model being loaded was removed on purpose (✕): its load ends quietly */
  private dropped: string | null = null;
  private items: api.Library | null = null;
  /** Called once a new basis is in the motion and the viewer (the views re-prepare mappings). */
  onBasis: () => void = () => {};
  /** Called when the menus were refilled (the song menu's live entries go back in). */
  onMenus: () => void = () => {};

  /** `busy(text, fraction)` shows the loading indicator (fraction in [0, 1] or null when
   * unknown); `busy(null)` hides it. `problem(text)` shows an error that is not fatal. */
  constructor(private readonly options: Options, private readonly motion: Motion,
              private readonly viewer: Viewer, private readonly transport: AudioTransport,
              private readonly busy: (text: string | null, fraction?: number | null) => void,
              private readonly problem: (text: string) => void) {}

  get meshName(): string { return this.items?.meshes.find((m) => m.id === this.meshId)?.name ?? ""; }
  /** The name of rig `id` as the library lists it ("" when it does not). */
  rigName(id: string): string { return this.items?.rigs?.find((r) => r.id === id)?.name ?? ""; }
  get songName(): string { return this.items?.songs.find((s) => s.id === this.songId)?.name ?? ""; }
  get mappings(): { id: string; name: string }[] { return this.items?.mappings ?? []; }

  /** Ask the server what it holds and refill the menus. */
  async refresh(): Promise<api.Library> {
    const items = await api.library();
    this.items = items;
    rememberNames(items); // the session names what it holds (session.ts)
    const models = $<HTMLSelectElement>("mesh");
    const shown = models.value; // a rig, while one is on screen
    fillSelect(models, items.meshes, this.loading ?? this.meshId);
    addRigs(models, items.rigs ?? []);
    if ([...models.options].some((option) => option.value === shown)) models.value = shown;
    else if (!items.meshes.length) { // nothing on screen: the menu says so (not a rig's name)
      models.prepend(new Option("no model: drop one, or choose a rig", "", true, true));
      models.options[0].disabled = true;
    }
    fillSelect($<HTMLSelectElement>("song"), items.songs, this.songId);
    const mappings = $<HTMLSelectElement>("mapping-menu");
    const chosen = mappings.value;
    fillSelect(mappings, items.mappings, chosen);
    (mappings.closest("label") ?? mappings).hidden = !items.mappings.length;
    $("remove-mapping").hidden = !items.mappings.length;
    // The page always shows a model and a song: the last one stays until another comes.
    for (const [kind, count] of [["mesh", items.meshes.length], ["song", items.songs.length]]) {
      const button = $<HTMLButtonElement>(`remove-${kind}`);
      button.disabled = Number(count) < 2;
      button.title = button.disabled ? `the only ${kind === "mesh" ? "model" : "song"}: add `
        + "another before removing it" : `remove this ${kind === "mesh" ? "model" : "song"} from `
        + "the library (its file on disk stays)";
    }
    this.onMenus();
    return items;
  }

  /** The model being loaded is removed (✕ while it computes): its load ends without error. */
  drop(meshId: string): void { if (meshId === this.loading) this.dropped = meshId; }

  /** Make `meshId` current: wait for its basis job, download the basis, hand it over. False
   * when it was removed (`drop`) while it loaded: the model on screen stays. */
  async loadMesh(meshId: string): Promise<boolean> {
    const mesh = this.items?.meshes.find((m) => m.id === meshId);
    if (!mesh) throw new Error(`the server has no model with id ${meshId}`);
    this.loading = meshId;
    $<HTMLSelectElement>("mesh").value = meshId; // the menu (and its ✕) names what computes
    try {
      if (!mesh.ready && mesh.job) await this.followSolve(mesh.name, mesh.job);
      this.busy(`${mesh.name}: loading its harmonics…`, null);
      const bytes = 16 * Math.ceil(mesh.k / 4) * mesh.vertices;
      const [basis, appearance] = await Promise.all([
        api.basis(meshId, this.options.half ?? bytes > HALF_ABOVE_BYTES),
        mesh.look ? loadAppearance("meshes", meshId).catch((error) => {
          this.problem(`${mesh.name}: its materials cannot be shown (${messageOf(error)}); `
            + "it is drawn in clay");
          return null;
        }) : null]);
      this.viewer.setBasis(basis, this.options.batch, appearance);
      $("materials-switch").hidden = !appearance;
      this.motion.basis = basis;
      this.meshId = meshId;
      $<HTMLSelectElement>("mesh").value = meshId;
      this.onBasis();
      return true;
    } catch (error) {
      if (this.dropped === meshId) return false;
      throw error;
    } finally {
      this.loading = this.dropped = null;
      $<HTMLSelectElement>("mesh").value = this.meshId; // the model on screen, if this one failed
      this.busy(null);
    }
  }

  /** Follow a model's basis job in the loading box: what the server does (waits its turn,
   * reads the cache, sets up, the pairs found as each band of the solver ends) and the seconds
   * since, ticking, so the box never sits still while the server works. */
  private async followSolve(name: string, first: api.Job): Promise<void> {
    let job = first;
    const since = performance.now();
    const say = (): void => {
      const seconds = ` · ${Math.floor((performance.now() - since) / 1000)} s`;
      // No count before the solver reports one: reading the cache or setting up says none.
      // A cache entry found stale is solved after all: then the count shows.
      const counting = job.done > 0 && (!job.cached || job.done < job.total);
      const what = job.state === "queued" ? "waiting for the model before it"
        : counting ? `computing its harmonics (${job.done} of ${job.total})`
          : job.cached ? "reading its harmonics from the cache"
            : "preparing its harmonics (the Laplacian, the first band)";
      this.busy(`${name}: ${what}${seconds}`, counting ? job.done / job.total : null);
    };
    say();
    const ticking = setInterval(say, 1000);
    try {
      await api.followJob(first.id, (next) => { job = next; say(); });
    } finally {
      clearInterval(ticking);
    }
  }

  /** Make `songId` current, from 0:00: its spectrogram, and its audio (none in `?render`
   * mode). */
  async loadSong(songId: string): Promise<void> {
    const name = this.items?.songs.find((s) => s.id === songId)?.name ?? "the song";
    try {
      this.busy(`${name}: loading…`, null);
      const spectrum = await api.spectrum(songId);
      this.motion.setSpectrum(spectrum);
      this.songId = songId;
      $<HTMLSelectElement>("song").value = songId;
      $<HTMLInputElement>("seek").max = String(spectrum.duration);
      if (this.options.render) {
        await this.transport.load(null, spectrum.duration);
        return;
      }
      try {
        await this.transport.load(await api.audioBytes(songId), spectrum.duration);
      } catch (error) {
        await this.transport.load(null, spectrum.duration);
        this.problem(`${name}: this browser cannot play its sound (${messageOf(error)})`);
      }
    } finally {
      this.onMenus(); // shows the song, or the live input still playing
      if (!document.body.classList.contains("live")) {
        $<HTMLSelectElement>("song").value = this.songId;
      }
      this.busy(null);
    }
  }
}

/** Replace a menu's options by the library's items, keeping `chosen` selected. */
function fillSelect(select: HTMLSelectElement, items: { id: string; name: string }[],
                    chosen: string): void {
  select.innerHTML = "";
  for (const item of items) select.add(new Option(item.name, item.id, false, item.id === chosen));
}

/** The library's rigs (articulated models) as a group of the model menu, values `rig:ID`. */
function addRigs(select: HTMLSelectElement, rigs: { id: string; name: string }[]): void {
  if (!rigs.length) return;
  const group = document.createElement("optgroup");
  group.label = "rigs (vibration modes)";
  for (const rig of rigs) group.appendChild(new Option(rig.name, `rig:${rig.id}`));
  select.appendChild(group);
}
