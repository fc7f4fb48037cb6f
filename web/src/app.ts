// The App owns the page: the header's controls, the library menus, the status line, files
// (drop and upload), the tabs and the URL options; it wires the transport, the motion, the
// viewer and the two views together (after three-gltf-viewer's app.js / viewer.js split).
import * as api from "./api";
import { $, messageOf } from "./dom";
import type { Mapping } from "./filter";
import { GalleryView } from "./gallery-view";
import { Library } from "./library";
import { Motion } from "./motion";
import { FALLBACK_RULE, galleryRule, gallerySize, sizeChoices } from "./options";
import type { Options } from "./options";
import { PlayerView } from "./player-view";
import { drawSpectrum } from "./plots";
import { Recorder } from "./recorder";
import { AudioTransport } from "./transport";
import { Viewer } from "./viewer";
import type { Stage, View } from "./viewer";

/** How often the player's info line (frame time) is refreshed while playing (ms). */
const INFO_EVERY_MS = 500;

export class App {
  readonly motion = new Motion();
  readonly transport = new AudioTransport();
  readonly viewer: Viewer;
  readonly gallery: GalleryView;
  readonly player: PlayerView;
  readonly library: Library;
  readonly recorder: Recorder;
  view: View;
  /** the library had a mesh and a song, and the first gallery was asked for */
  private started = false;
  /** a problem with the options (bad `?size=`), kept in front of the first "ready" */
  private notice = "";
  private infoShownAt = 0;

  constructor(readonly options: Options) {
    this.view = options.view;
    this.viewer = new Viewer($<HTMLCanvasElement>("gl"), $("player-area"), this.motion,
      this.transport, () => this.stage());
    this.viewer.onFrame = (t, bandValues) => this.showFrame(t, bandValues);
    const requestDraw = () => this.viewer.requestDraw();
    const status = (text: string) => this.status(text);
    const open = (mapping: Mapping) => this.open(mapping);
    this.gallery = new GalleryView(this.motion, { status, open, requestDraw,
      guard: (what, task) => this.guard(what, task) }, FALLBACK_RULE.default);
    this.player = new PlayerView(this.motion, { status, open, requestDraw,
      rendering: () => ({ path: this.viewer.path, frameMs: this.viewer.frameMs }),
      harmonicScale: (index) => this.viewer.deformer?.harmonicScale(index) ?? 1 });
    this.recorder = new Recorder($<HTMLCanvasElement>("gl"), this.transport, $<HTMLButtonElement>("record"),
      () => this.play());
    this.library = new Library(options, this.motion, this.viewer, this.transport, status);
    this.library.onBasis = () => { this.gallery.basisChanged(); this.player.basisChanged(); };
    this.transport.onChange = (playing) => { $("play").textContent = playing ? "❚❚" : "▶"; };
    this.wireHeader();
    this.wireFiles();
  }

  /** Start: the render loop (not in `?render` mode), the server's rules, the library, and the
   * first gallery. Never rejects: a failure is shown in the status line. */
  async start(): Promise<void> {
    document.body.classList.toggle("bare", this.options.bare);
    if (!this.options.render) this.viewer.start();
    try {
      await this.readConfig();
      await this.loadFirst(await this.library.refresh());
    } catch (error) {
      this.status(`error: ${messageOf(error)}`);
    }
  }

  status(text: string): void {
    const line = $("status");
    line.textContent = text;
    line.title = text; // the line is cut to its width; the whole message on hover
  }

  /** Run `task`; a failure (a server error, a file the browser cannot read) is shown as
   * `what: message` and returned, so the page stays usable and no promise is left rejected. */
  async guard(what: string, task: () => Promise<void>): Promise<string | null> {
    try {
      await task();
      return null;
    } catch (error) {
      const message = `${what}: ${messageOf(error)}`;
      this.status(message);
      return message;
    }
  }

  setView(view: View): void {
    this.view = view;
    $("gallery-view").hidden = view !== "gallery";
    $("player-view").hidden = view !== "player";
    $("tab-gallery").classList.toggle("active", view === "gallery");
    $("tab-player").classList.toggle("active", view === "player");
    const first = this.gallery.mappings()[0];
    if (view === "player" && !this.player.mapping && first) this.player.show(first);
    this.player.refreshInfo();
    this.viewer.requestDraw();
  }

  /** Play `mapping` in the player. */
  open(mapping: Mapping): void {
    this.player.show(mapping);
    this.setView("player");
  }

  /** Play the song, drawing by its clock again if a time was pinned. */
  play(): void {
    this.transport.play();
    if (this.transport.playing) this.viewer.unpin();
  }

  /** A new first generation of `size` tiles for the current mesh and song. */
  newGallery(size?: number): Promise<string | null> {
    const { meshId, songId } = this.library;
    return this.guard("gallery", () => this.gallery.create(meshId, songId, size));
  }

  /** Upload files one by one; each becomes the current mesh, song or player mapping. */
  async handleFiles(files: FileList | File[]): Promise<void> {
    for (const file of Array.from(files)) {
      try {
        this.status(`uploading ${file.name}…`);
        const result = await api.upload(file);
        const library = await this.library.refresh();
        if (!this.started) { // the library was incomplete: this file may complete it
          if (await this.loadFirst(library)) this.status(`${file.name} ready`);
          continue;
        }
        if (result.kind === "mesh") {
          if (await this.showMesh(result.item.id)) continue; // the gallery failed: said why
        } else if (result.kind === "song") {
          await this.library.loadSong(result.item.id);
        } else if (result.kind === "mapping") {
          this.open(await api.getJSON<Mapping>(`api/mappings/${result.item.id}`));
        }
        this.status(`${file.name} ready`);
        this.viewer.requestDraw();
      } catch (error) {
        this.status(`${file.name}: ${messageOf(error)}`);
      }
    }
  }

  /** What the viewer draws now. */
  private stage(): Stage {
    const player = this.player.prepared ? { element: $("player-area"),
      prepared: this.player.prepared,
      colorIndex: Math.max(0, this.gallery.mappings().indexOf(this.player.mapping!)) } : null;
    return { view: this.view, tiles: this.gallery.shots(), player, look: this.player.look };
  }

  /** After each frame: the spectrum strip, the seek bar and clock, now and then the info line. */
  private showFrame(t: number, bandValues: Float32Array): void {
    drawSpectrum($<HTMLCanvasElement>("spectrum"), bandValues);
    const seekBar = $<HTMLInputElement>("seek");
    if (document.activeElement !== seekBar) seekBar.value = String(t);
    const seconds = Math.floor(t);
    $("clock").textContent = `${Math.floor(seconds / 60)}:${String(seconds % 60).padStart(2, "0")}`;
    const now = performance.now();
    if (this.view === "player" && now - this.infoShownAt > INFO_EVERY_MS) {
      this.infoShownAt = now;
      this.player.refreshInfo();
    }
  }

  /** The gallery-size rule from the server: the *tiles* menu, and `?size=` checked against it
   * (a bad one falls back to the default, with a notice). */
  private async readConfig(): Promise<void> {
    let rule = FALLBACK_RULE;
    const notices: string[] = [];
    try {
      rule = galleryRule(await api.config());
    } catch (error) {
      notices.push(`gallery sizes: ${messageOf(error)}`);
    }
    const { size, problem } = gallerySize(this.options.size, rule);
    if (problem) notices.push(problem);
    this.notice = notices.join(" · ");
    if (this.notice) this.status(this.notice);
    this.gallery.size = size;
    const menu = $<HTMLSelectElement>("size");
    menu.innerHTML = "";
    for (const choice of sizeChoices(rule, size)) menu.add(new Option(String(choice)));
    menu.value = String(size);
  }

  /** Load the first mesh and song and show the gallery (at start, or once uploads complete the
   * library). Returns false while the library lacks a mesh or a song. */
  private async loadFirst(library: api.Library): Promise<boolean> {
    if (!library.meshes.length || !library.songs.length) {
      const missing = library.meshes.length ? "a song" : "a mesh";
      this.status(`the library needs ${missing}: drop files here`);
      return false;
    }
    const { options } = this;
    await this.library.loadSong(options.song ?? library.songs[0].id);
    await this.library.loadMesh(options.mesh ?? library.meshes[0].id);
    this.started = true;
    const failure = await this.newGallery();
    if (options.mapping) {
      this.player.show(await api.getJSON<Mapping>(`api/mappings/${options.mapping}`));
    }
    this.setView(this.view);
    this.viewer.choosePath(options.path);
    this.viewer.draw(this.viewer.time());
    this.player.refreshInfo();
    const ready = failure ?? (options.render ? "render mode" : "ready: press ▶ or space");
    this.status(this.notice ? `${this.notice} · ${ready}` : ready);
    this.notice = "";
    return true;
  }

  /** A new current mesh with its own first gallery, and the faster deformation path for it.
   * Returns the gallery's failure (already shown), or null. */
  private async showMesh(meshId: string): Promise<string | null> {
    await this.library.loadMesh(meshId);
    const failure = await this.newGallery();
    this.viewer.choosePath(this.options.path);
    return failure;
  }

  /** The header: library menus, transport, gain, tabs, the tiles menu and the keyboard. */
  private wireHeader(): void {
    const valueOf = (event: Event) => (event.target as HTMLInputElement | HTMLSelectElement).value;
    $("mesh").addEventListener("change", (e) => {
      const meshId = valueOf(e);
      void this.guard("mesh", async () => {
        if (!(await this.showMesh(meshId))) this.status("");
      });
    });
    $("song").addEventListener("change", (e) => {
      const songId = valueOf(e);
      void this.guard("song", async () => {
        await this.library.loadSong(songId);
        this.viewer.requestDraw();
      });
    });
    $("play").addEventListener("click", () => this.togglePlay());
    $("seek").addEventListener("input", (e) => {
      this.transport.seek(Number(valueOf(e)));
      this.viewer.requestDraw();
    });
    const gain = $<HTMLInputElement>("gain");
    gain.addEventListener("input", () => {
      this.motion.gain = Number(gain.value);
      $("gain-out").textContent = this.motion.gain.toFixed(2);
      this.viewer.requestDraw();
    });
    $("tab-gallery").addEventListener("click", () => this.setView("gallery"));
    $("tab-player").addEventListener("click", () => this.setView("player"));
    const sizes = $<HTMLSelectElement>("size");
    sizes.addEventListener("change", async () => {
      // On failure the menu goes back to the size on screen; the status says why.
      if (await this.newGallery(Number(sizes.value))) sizes.value = String(this.gallery.size);
    });
    window.addEventListener("keydown", (e) => {
      if (e.code === "Space" && !(e.target instanceof HTMLInputElement)) {
        e.preventDefault();
        this.togglePlay();
      }
    });
    window.addEventListener("resize", () => this.viewer.requestDraw());
  }

  private togglePlay(): void {
    if (this.transport.playing) this.transport.pause(); else this.play();
  }

  /** Files: the *add file* input, and dropping anywhere on the page. */
  private wireFiles(): void {
    $("upload").addEventListener("change", (e) => {
      const files = (e.target as HTMLInputElement).files;
      if (files) void this.handleFiles(files);
    });
    const drop = $("drop");
    window.addEventListener("dragover", (e) => { e.preventDefault(); drop.hidden = false; });
    drop.addEventListener("dragleave", () => { drop.hidden = true; });
    window.addEventListener("drop", (e) => {
      e.preventDefault();
      drop.hidden = true;
      if (e.dataTransfer?.files.length) void this.handleFiles(e.dataTransfer.files);
    });
  }
}
