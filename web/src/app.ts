// The App owns the page: the header's controls, the library menus, the status line, errors,
// the loading indicator, the help, the keyboard, files (drop and upload), the tabs and the URL
// options; it wires the transport, the motion, the viewer and the two views together (after
// three-gltf-viewer's app.js / viewer.js split).
import * as api from "./api";
import { $, messageOf } from "./dom";
import type { Mapping } from "./filter";
import { GalleryView } from "./gallery-view";
import { Library } from "./library";
import { Motion } from "./motion";
import { fewerTiles, galleryRule, gallerySize, sizeChoices } from "./options";
import type { GalleryRule, Options } from "./options";
import { PlayerView } from "./player-view";
import { drawBeat, drawSpectrum } from "./plots";
import { Recorder } from "./recorder";
import { RigStage } from "./rigs";
import { AudioTransport } from "./transport";
import { SMOOTH_FPS, Viewer, softwareRenderer } from "./viewer";
import type { Stage, View } from "./viewer";

/** How often the frame-rate readout and the player's info line are refreshed (ms). */
const READOUT_EVERY_MS = 500;
/** The gallery offers fewer tiles after this long below SMOOTH_FPS while playing (ms). */
const SLOW_FOR_MS = 3000;
/** The frame rate the offer of fewer tiles aims at. */
const AIMED_FPS = 24;
const HELP_SEEN = "eigendance-help-seen";

export class App {
  readonly motion = new Motion();
  readonly transport = new AudioTransport();
  readonly viewer: Viewer;
  readonly gallery: GalleryView;
  readonly player: PlayerView;
  readonly library: Library;
  readonly recorder: Recorder;
  /** articulated models: their galleries and player, on their own canvas */
  readonly rigs: RigStage;
  view: View = "gallery";
  /** the server's gallery-size rule; null when `api/config` could not be read */
  rule: GalleryRule | null = null;
  /** the library had a mesh and a song, and the first gallery was asked for */
  private started = false;
  /** a problem with the options (bad `?size=`), kept in front of the first "ready" */
  private notice = "";
  private readoutAt = 0;
  private slowSince: number | null = null;
  /** gallery sizes whose low frame rate the person already dismissed */
  private slowDismissed = new Set<number>();

  constructor(readonly options: Options) {
    const antialias = options.aa ?? (options.render || !softwareRenderer());
    this.viewer = new Viewer($<HTMLCanvasElement>("gl"), $("player-area"), this.motion,
      this.transport, () => this.stage(), antialias);
    this.viewer.onFrame = (t) => {
      if (this.rigs?.active) this.rigs.viewer.requestDraw(); // a seek or a rewind moves rigs too
      this.showFrame(t);
      drawSpectrum($("spectrum"), this.motion.bandValuesAt(t));
      drawBeat($("spectrum"), this.motion.spectrum, t);
    };
    const requestDraw = () => this.viewer.requestDraw();
    const status = (text: string) => this.status(text);
    this.gallery = new GalleryView(this.motion, { status, requestDraw,
      open: (mapping) => this.open(mapping, `tile of generation ${this.gallery.generation + 1}`),
      guard: (what, task) => this.guard(what, task) }, null);
    this.player = new PlayerView(this.motion, { requestDraw,
      upload: (file) => void this.handleFiles([file]),
      harmonicScale: (index) => this.viewer.deformer?.harmonicScale(index) ?? 1 });
    this.recorder = new Recorder($<HTMLCanvasElement>("gl"), this.transport,
      $<HTMLButtonElement>("record"), () => this.play());
    this.library = new Library(options, this.motion, this.viewer, this.transport,
      (text, fraction) => this.loading(text, fraction), (text) => this.error(text));
    this.library.onBasis = () => { this.gallery.refresh(); this.player.basisChanged(); };
    this.rigs = new RigStage(this.motion, this.transport, antialias, {
      status, loading: (text) => this.loading(text), guard: (what, task) => this.guard(what, task),
      songId: () => this.library.songId }, options.path, options.batch, !options.render);
    this.transport.onChange = (playing) => {
      $("play").textContent = playing ? "❚❚" : "▶";
      this.slowSince = null;
    };
    this.wireHeader();
    this.wireKeys();
    this.wireFiles();
    this.wireOverlays();
  }

  /** Start: the render loop (not in `?render` mode), the server's rules, the library, and the
   * first gallery. Never rejects: a failure is shown as an error. */
  async start(): Promise<void> {
    document.body.classList.toggle("bare", this.options.bare);
    if (!this.options.render) this.viewer.start();
    const hooks = this.options.render || this.options.test || this.options.bare;
    if (!hooks && !localStorage.getItem(HELP_SEEN)) this.showHelp(true);
    try {
      await this.readConfig();
      await this.loadFirst(await this.library.refresh());
    } catch (error) {
      this.error(`The page could not start: ${messageOf(error)}`);
    }
  }

  /** A short line in the header (progress, "ready"). */
  status(text: string): void {
    const line = $("status");
    line.textContent = text;
    line.title = text;
  }

  /** An error, shown in full (wrapped) until closed or replaced; Esc closes it. */
  error(text: string): void {
    $("error-text").textContent = text;
    $("error").hidden = false;
  }

  clearError(): void { $("error").hidden = true; }

  /** The loading indicator: `text` with a progress bar (fraction, or null: indeterminate);
   * null hides it. */
  loading(text: string | null, fraction: number | null = null): void {
    $("loading").hidden = text === null;
    if (text === null) return;
    $("loading-text").textContent = text;
    const bar = $<HTMLProgressElement>("loading-progress");
    if (fraction === null) bar.removeAttribute("value"); else bar.value = fraction;
  }

  /** Run `task`; a failure (a server error, a file the browser cannot read) is shown as the
   * error `what: message` and returned, so the page stays usable and no promise is left
   * rejected. */
  async guard(what: string, task: () => Promise<void>): Promise<string | null> {
    try {
      await task();
      return null;
    } catch (error) {
      const message = `${what}: ${messageOf(error)}`;
      this.error(message);
      this.status("");
      return message;
    }
  }

  setView(view: View): void {
    this.view = view;
    if (this.rigs.active) { this.rigs.setView(view); return; }
    if (view !== "gallery") $("notice").hidden = true; // it is about the tiles
    $("gallery-view").hidden = view !== "gallery";
    $("player-view").hidden = view !== "player";
    $("tab-gallery").classList.toggle("active", view === "gallery");
    $("tab-player").classList.toggle("active", view === "player");
    const first = this.gallery.mappings()[0];
    if (view === "player" && !this.player.mapping && first) this.open(first, "tile 1");
    if (view === "gallery") this.gallery.refresh(); // the player may have changed a tile
    this.player.refreshInfo(this.viewer.path);
    this.viewer.requestDraw();
  }

  /** Show rig `rigId` (an articulated model of the library) in its gallery of modes. */
  openRig(rigId: string): Promise<string | null> {
    return this.guard("Could not show this rig", async () => {
      await this.rigs.open(rigId, this.rule?.max ?? 16);
      $<HTMLSelectElement>("mesh").value = `rig:${rigId}`;
      this.view = "gallery";
    });
  }

  /** Play `mapping` in the player; `source` says where it comes from. */
  open(mapping: Mapping, source = ""): void {
    this.player.show(mapping, source);
    if (this.view !== "player") this.setView("player");
    this.viewer.requestDraw();
  }

  /** Play the song, drawing by its clock again if a time was pinned. */
  play(): void {
    this.transport.play();
    if (this.transport.playing) this.viewer.unpin();
  }

  /** A new first generation of `size` tiles (default: the size on screen; null: the server's
   * default) for the current mesh and song, calibrated on the song; earlier generations stay in
   * the history. */
  newGallery(size?: number | null): Promise<string | null> {
    const { meshId, songId } = this.library;
    const note = `${this.library.meshName}, ${this.library.songName}`;
    return this.guard("Could not make the gallery",
      () => this.gallery.create(meshId, songId, note, size === undefined ? this.gallery.size
        : size));
  }

  /** Upload files one by one; each becomes the current mesh, song or player mapping. */
  async handleFiles(files: FileList | File[]): Promise<void> {
    for (const file of Array.from(files)) {
      try {
        this.status(`adding ${file.name}…`);
        this.loading(`${file.name}: uploading…`);
        const result = await api.upload(file).finally(() => this.loading(null));
        const library = await this.library.refresh();
        if (!this.started) { // the library was incomplete: this file may complete it
          if (await this.loadFirst(library)) this.status(`${file.name} ready`);
          continue;
        }
        if (result.kind === "rig" || result.rig) { // a skeleton, or a glTF with a skin
          if (await this.openRig(result.kind === "rig" ? result.item.id : result.rig.id)) continue;
        } else if (result.kind === "mesh") {
          if (await this.showMesh(result.item.id)) continue; // failed: said why
        } else if (result.kind === "song") {
          await this.changeSong(result.item.id);
        } else if (result.kind === "mapping") {
          $<HTMLSelectElement>("mapping-menu").value = result.item.id;
          this.open(await api.getJSON<Mapping>(`api/mappings/${result.item.id}`), file.name);
        }
        this.status(`${file.name} ready`);
        this.viewer.requestDraw();
      } catch (error) {
        this.status("");
        this.error(`${file.name} could not be added: ${withoutName(messageOf(error), file.name)}`);
      }
    }
  }

  /** What the viewer draws now. */
  private stage(): Stage {
    if (this.rigs.active) { // the rig's viewer draws
      return { view: this.view, tiles: [], player: null, explorer: this.player.explorer };
    }
    return { view: this.view, tiles: this.gallery.shots(),
      player: this.player.shot($("player-area")), explorer: this.player.explorer };
  }

  /** Before each frame: the seek bar and clock, now and then the frame-rate readout, the
   * player's info line and the offer of fewer tiles. */
  private showFrame(t: number): void {
    const seekBar = $<HTMLInputElement>("seek");
    if (document.activeElement !== seekBar) seekBar.value = String(t);
    const seconds = Math.floor(t);
    $("clock").textContent = `${Math.floor(seconds / 60)}:${String(seconds % 60).padStart(2, "0")}`;
    const now = performance.now();
    if (now - this.readoutAt < READOUT_EVERY_MS) return;
    this.readoutAt = now;
    const { fps } = this.rigs.active ? this.rigs.viewer : this.viewer;
    const readout = $("fps");
    readout.textContent = fps > 0 ? `${fps.toFixed(fps < 10 ? 1 : 0)} fps` : "";
    readout.classList.toggle("slow", fps > 0 && fps < SMOOTH_FPS);
    if (this.view === "player") this.player.refreshInfo(this.viewer.path);
    this.checkFrameRate(fps, now);
  }

  /** After SLOW_FOR_MS below SMOOTH_FPS in the gallery, say so and offer fewer tiles. */
  private checkFrameRate(fps: number, now: number): void {
    const tiles = this.gallery.tileCount;
    const slow = this.view === "gallery" && !this.rigs.active && this.transport.playing && fps > 0
      && fps < SMOOTH_FPS && !this.slowDismissed.has(tiles);
    if (!slow) { this.slowSince = null; return; }
    this.slowSince ??= now;
    if (now - this.slowSince < SLOW_FOR_MS || !$("notice").hidden) return;
    const offer = fewerTiles(tiles, fps, AIMED_FPS, this.rule?.min ?? 2);
    const rate = fps.toFixed(fps < 10 ? 1 : 0);
    $("notice-text").textContent = `This page draws only ${rate} frames per second with `
      + `${tiles} tiles (smooth needs ${SMOOTH_FPS}).`;
    const button = $<HTMLButtonElement>("notice-fewer");
    button.hidden = offer === null;
    button.textContent = `show ${offer} tiles`;
    button.onclick = () => {
      $("notice").hidden = true;
      if (offer !== null) void this.newGallery(offer);
    };
    $("notice").hidden = false;
  }

  /** The gallery-size rule from the server: the *tiles* menu, and `?size=` checked against it
   * (a bad one falls back to the default, with a notice). Without it the server checks. */
  private async readConfig(): Promise<void> {
    const notices: string[] = [];
    try {
      this.rule = galleryRule(await api.config());
    } catch (error) {
      this.rule = null;
      this.error(`Could not read the gallery sizes from the server (${messageOf(error)}); `
        + "the server will check the size asked for");
    }
    const { size, problem } = gallerySize(this.options.size, this.rule);
    if (problem) notices.push(problem);
    this.notice = notices.join(" · ");
    if (this.notice) this.status(this.notice);
    this.gallery.size = size;
    this.fillSizeMenu(size);
  }

  private fillSizeMenu(size: number | null): void {
    const menu = $<HTMLSelectElement>("size");
    menu.innerHTML = "";
    if (size === null) return;
    for (const choice of sizeChoices(this.rule, size)) menu.add(new Option(String(choice)));
    menu.value = String(size);
  }

  /** Load the first mesh and song and show the gallery (at start, or once uploads complete the
   * library); a mapping given to the server (or `?mapping=`) opens in the player. Returns false
   * while the library lacks a mesh or a song. */
  private async loadFirst(library: api.Library): Promise<boolean> {
    if (!library.meshes.length || !library.songs.length) {
      const missing = library.meshes.length ? "a song" : "a model";
      this.status(`the library needs ${missing}: drop a file here`);
      return false;
    }
    const { options } = this;
    await this.library.loadSong(options.song ?? library.songs[0].id);
    await this.library.loadMesh(options.mesh ?? library.meshes[0].id);
    this.started = true;
    let failure = await this.newGallery();
    if (failure && this.gallery.size !== null && this.rule === null) {
      failure = await this.newGallery(null); // the size asked for was refused: the default
    }
    if (this.gallery.size !== null) this.fillSizeMenu(this.gallery.size);
    const served = options.mapping ?? library.mappings[0]?.id ?? null;
    if (served) {
      const name = library.mappings.find((m) => m.id === served)?.name ?? "mapping";
      $<HTMLSelectElement>("mapping-menu").value = served;
      this.player.show(await api.getJSON<Mapping>(`api/mappings/${served}`), name);
    }
    this.setView(options.view ?? (served ? "player" : "gallery"));
    this.viewer.choosePath(options.path);
    this.viewer.draw(this.viewer.time());
    this.player.refreshInfo(this.viewer.path);
    const ready = options.render ? "render mode" : "ready: press ▶ or space";
    this.status(failure ? "" : this.notice ? `${this.notice} · ${ready}` : ready);
    this.notice = "";
    return true;
  }

  /** A new current mesh with its own history (a first gallery when it has none), and the
   * faster deformation path for it. Returns the gallery's failure (already shown), or null. */
  private async showMesh(meshId: string): Promise<string | null> {
    await this.library.loadMesh(meshId);
    if (this.rigs.active) { this.rigs.leave(); this.setView(this.view); }
    const failure = this.gallery.showMesh(meshId) ? null : await this.newGallery();
    this.viewer.choosePath(this.options.path);
    return failure;
  }

  /** A new current song, from 0:00, with a first gallery calibrated on it. */
  private async changeSong(songId: string): Promise<void> {
    await this.library.loadSong(songId);
    await this.newGallery();
    await this.rigs.songChanged();
    this.viewer.requestDraw();
  }

  /** The header: library menus, transport, volume, tabs and the tiles menu. */
  private wireHeader(): void {
    const valueOf = (event: Event) => (event.target as HTMLInputElement | HTMLSelectElement).value;
    $("mesh").addEventListener("change", (e) => {
      const meshId = valueOf(e);
      if (meshId.startsWith("rig:")) { void this.openRig(meshId.slice(4)); return; }
      void this.guard("Could not show this model", async () => {
        if (!(await this.showMesh(meshId))) this.status("");
      });
    });
    $("song").addEventListener("change", (e) => {
      const songId = valueOf(e);
      void this.guard("Could not play this song", () => this.changeSong(songId));
    });
    $("mapping-menu").addEventListener("change", (e) => {
      const id = valueOf(e);
      const name = this.library.mappings.find((m) => m.id === id)?.name ?? "mapping";
      void this.guard(`Could not open ${name}`, async () => {
        this.open(await api.getJSON<Mapping>(`api/mappings/${id}`), name);
      });
    });
    for (const kind of ["mesh", "song", "mapping"] as const) {
      $(`remove-${kind}`).addEventListener("click", () => void this.remove(kind));
    }
    $("play").addEventListener("click", () => this.togglePlay());
    $("seek").addEventListener("input", (e) => {
      this.transport.seek(Number(valueOf(e)));
      this.viewer.requestDraw();
    });
    const volume = $<HTMLInputElement>("volume");
    volume.addEventListener("input", () => {
      this.transport.volume = Number(volume.value);
      if (this.transport.muted) this.toggleMute();
    });
    $("mute").addEventListener("click", () => this.toggleMute());
    $("tab-gallery").addEventListener("click", () => this.setView("gallery"));
    $("tab-player").addEventListener("click", () => this.setView("player"));
    const sizes = $<HTMLSelectElement>("size");
    sizes.addEventListener("change", async () => {
      // On failure the menu goes back to the size on screen; the error says why.
      if (await this.newGallery(Number(sizes.value))) sizes.value = String(this.gallery.size);
    });
    window.addEventListener("resize", () => {
      this.viewer.resetPlayerCamera();
      this.viewer.requestDraw();
    });
    // A banner or a wrapped header moves the views: draw again where they are now.
    new ResizeObserver(() => this.viewer.requestDraw()).observe($("tiles"));
    new ResizeObserver(() => this.viewer.requestDraw()).observe($("player-area"));
  }

  /** Remove the item chosen in `kind`'s menu from the server's library (not from the disk);
   * a removed model or song on screen gives way to the first one left. */
  private async remove(kind: "mesh" | "song" | "mapping"): Promise<void> {
    const menu = $<HTMLSelectElement>(kind === "mapping" ? "mapping-menu" : kind);
    const rig = kind === "mesh" && menu.value.startsWith("rig:"); // the model menu lists rigs too
    const id = rig ? menu.value.slice(4) : menu.value;
    const name = menu.selectedOptions[0]?.textContent ?? `the ${kind}`;
    await this.guard(`Could not remove ${name}`, async () => {
      await api.remove(rig ? "rig" : kind, id);
      const library = await this.library.refresh();
      if (rig || (kind === "mesh" && id === this.library.meshId)) {
        const next = library.meshes.find((m) => m.id === this.library.meshId) ?? library.meshes[0];
        if (next) await this.showMesh(next.id); // leaves the rig's views
      } else if (kind === "song" && id === this.library.songId && library.songs.length) {
        this.transport.pause();
        await this.changeSong(library.songs[0].id);
      }
      this.status(`${name} removed from the library`);
    });
  }

  private togglePlay(): void {
    if (this.transport.playing) this.transport.pause(); else this.play();
  }

  private toggleMute(): void {
    this.transport.muted = !this.transport.muted;
    $("mute").classList.toggle("muted", this.transport.muted);
  }

  /** Keys (the help lists them). They work whatever has the focus — a slider, a button, a
   * menu just used — except where one types (a number or text field). */
  private wireKeys(): void {
    // A menu keeps the focus after a choice and would take the next letters for itself.
    document.querySelectorAll("select").forEach((menu) => {
      menu.addEventListener("change", () => menu.blur());
    });
    window.addEventListener("keydown", (e) => {
      if (e.ctrlKey || e.metaKey || e.altKey) return;
      const target = e.target as HTMLElement;
      const typing = target instanceof HTMLTextAreaElement || (target instanceof HTMLInputElement
        && !["range", "checkbox", "button", "file", "radio"].includes(target.type));
      const slider = target instanceof HTMLInputElement && target.type === "range";
      if (typing) return;
      const actions: Record<string, () => void> = {
        " ": () => this.togglePlay(),
        g: () => this.setView("gallery"),
        p: () => this.setView("player"),
        b: () => {
          void this.guard("Breeding failed",
            () => (this.rigs.active ? this.rigs.gallery.breed() : this.gallery.breed()));
        },
        "[": () => this.gallery.step(-1),
        "]": () => this.gallery.step(1),
        m: () => this.toggleMute(),
        "?": () => this.showHelp($("help").hidden),
        h: () => this.showHelp($("help").hidden),
        Escape: () => { this.showHelp(false); this.clearError(); },
      };
      if (!slider) {
        actions.Home = () => { this.transport.seek(0); this.viewer.requestDraw(); };
      }
      const action = actions[e.key.length === 1 ? e.key.toLowerCase() : e.key]
        ?? actions[e.key];
      if (!action) return;
      e.preventDefault(); // a focused button would also be clicked by space
      action();
    });
  }

  /** Help, errors and notices: their close buttons. */
  private wireOverlays(): void {
    $("help-button").addEventListener("click", () => this.showHelp(true));
    $("help-close").addEventListener("click", () => this.showHelp(false));
    $("help").addEventListener("click", (e) => {
      if (e.target === $("help")) this.showHelp(false);
    });
    $("error-close").addEventListener("click", () => this.clearError());
    $("notice-close").addEventListener("click", () => {
      $("notice").hidden = true;
      this.slowDismissed.add(this.gallery.tileCount);
    });
  }

  private showHelp(shown: boolean): void {
    $("help").hidden = !shown;
    if (!shown) {
      try { localStorage.setItem(HELP_SEEN, "1"); } catch { /* private mode: ask again */ }
    }
  }

  /** Files: the *add file* input, and dropping anywhere on the page. */
  private wireFiles(): void {
    $("upload").addEventListener("change", (e) => {
      const input = e.target as HTMLInputElement;
      if (input.files) void this.handleFiles(Array.from(input.files));
      input.value = "";
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

/** A server message without the file name it starts with (the page names the file itself). */
function withoutName(message: string, name: string): string {
  return message.startsWith(`${name}: `) ? message.slice(name.length + 2) : message;
}
