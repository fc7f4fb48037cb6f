// The server's library as the page sees it: the mesh and song menus, and the current mesh and
// song, downloaded into the motion, the viewer and the audio transport.
import * as api from "./api";
import { $, messageOf } from "./dom";
import type { Motion } from "./motion";
import type { Options } from "./options";
import type { AudioTransport } from "./transport";
import type { Viewer } from "./viewer";

/** Above this many bytes of float32 harmonics the basis comes as float16 unless `?half=0`. */
const HALF_ABOVE_BYTES = 128 * 2 ** 20;

export class Library {
  meshId = "";
  songId = "";
  private items: api.Library | null = null;
  /** Called once a new basis is in the motion and the viewer (the views re-prepare mappings). */
  onBasis: () => void = () => {};

  constructor(private readonly options: Options, private readonly motion: Motion,
              private readonly viewer: Viewer, private readonly transport: AudioTransport,
              private readonly status: (text: string) => void) {}

  /** Ask the server what it holds and refill the menus. */
  async refresh(): Promise<api.Library> {
    const items = await api.library();
    this.items = items;
    fillSelect($<HTMLSelectElement>("mesh"), items.meshes, this.meshId);
    fillSelect($<HTMLSelectElement>("song"), items.songs, this.songId);
    return items;
  }

  /** Make `meshId` current: wait for its basis job, download the basis, hand it over. */
  async loadMesh(meshId: string): Promise<void> {
    const mesh = this.items?.meshes.find((m) => m.id === meshId);
    if (!mesh) throw new Error(`no mesh ${meshId}`);
    this.meshId = meshId;
    $<HTMLSelectElement>("mesh").value = meshId;
    if (!mesh.ready && mesh.job) {
      await api.followJob(mesh.job.id, (job) => {
        this.status(`${mesh.name}: basis ${job.done}/${job.total} eigenpairs (${job.state})`);
      });
    }
    this.status(`${mesh.name}: loading basis…`);
    const bytes = 16 * Math.ceil(mesh.k / 4) * mesh.vertices;
    const basis = await api.basis(meshId, this.options.half ?? bytes > HALF_ABOVE_BYTES);
    this.viewer.setBasis(basis, this.options.batch);
    this.motion.basis = basis;
    this.onBasis();
  }

  /** Make `songId` current: its spectrogram, and its audio (none in `?render` mode). */
  async loadSong(songId: string): Promise<void> {
    this.songId = songId;
    $<HTMLSelectElement>("song").value = songId;
    const spectrum = await api.spectrum(songId);
    this.motion.setSpectrum(spectrum);
    $<HTMLInputElement>("seek").max = String(spectrum.duration);
    if (this.options.render) {
      await this.transport.load(null, spectrum.duration);
      return;
    }
    try {
      await this.transport.load(await api.audioBytes(songId), spectrum.duration);
    } catch (error) {
      this.status(`audio: ${messageOf(error)}`);
    }
  }
}

/** Replace a menu's options by the library's items, keeping `chosen` selected. */
function fillSelect(select: HTMLSelectElement, items: { id: string; name: string }[],
                    chosen: string): void {
  select.innerHTML = "";
  for (const item of items) select.add(new Option(item.name, item.id, false, item.id === chosen));
}
