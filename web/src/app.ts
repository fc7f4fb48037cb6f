// The App owns the page: the views, the library, the transport, the viewer and what the page
// says (messages.ts); it starts the page and moves between models, songs, views and galleries.
// The header's controls and keys are wired in header.ts, files in files.ts, the frame-rate
// readout in frame-rate.ts, the export panel in export-panel.ts (three-gltf-viewer's split).
import * as api from "./api";
import { $, messageOf } from "./dom";
import { ExportPanel } from "./export-panel";
import { FileIntake, suffixesOf } from "./files";
import type { Mapping } from "./filter";
import { FrameRateWatch } from "./frame-rate";
import { GalleryView } from "./gallery-view";
import { wireHeader } from "./header";
import { Library } from "./library";
import { LiveSource } from "./live-source";
import type { LiveChoice } from "./live-input";
import { Messages } from "./messages";
import { Motion } from "./motion";
import { galleryRule, gallerySize, sizeChoices } from "./options";
import type { GalleryRule, Options } from "./options";
import { PlayerView } from "./player-view";
import { drawBeat, drawSpectrum } from "./plots";
import { Recorder } from "./recorder";
import { keepInSession, loadStartSong, restoreStored, songOf, startModel } from "./session";
import { RigStage } from "./rigs";
import { AudioTransport } from "./transport";
import { Viewer, softwareRenderer } from "./viewer";
import type { Stage, View } from "./viewer";

/** How often the frame-rate readout and the player's info line are refreshed (ms). */
const READOUT_EVERY_MS = 500;
const READY = "ready: press ▶ or space";

export class App {
  readonly messages = new Messages();
  readonly motion = new Motion();
  readonly transport = new AudioTransport();
  readonly viewer: Viewer;
  readonly gallery: GalleryView;
  readonly player: PlayerView;
  readonly library: Library;
  readonly recorder: Recorder;
  readonly files: FileIntake;
  readonly frameRate: FrameRateWatch;
  readonly exporter: ExportPanel;
  /** articulated models: their galleries and player, on their own canvas */
  readonly rigs: RigStage;
  /** live input (microphone, line in, tab audio) in place of the song */
  readonly live: LiveSource;
  view: View = "gallery";
  /** the server's gallery-size rule; null when `api/config` could not be read */
  rule: GalleryRule | null = null;
  /** the library had a mesh and a song, and the first gallery was asked for */
  private started = false;
  /** a rig chosen in the model menu while the library had no song: opened once one comes */
  private chosenRig: string | null = null;
  /** a problem with the options (bad `?size=`), kept in front of the first "ready" */
  private notice = "";
  private readoutAt = 0;

  constructor(readonly options: Options) {
    const antialias = options.aa ?? (options.render || !softwareRenderer());
    const messages = this.messages;
    this.viewer = new Viewer($<HTMLCanvasElement>("gl"), $("player-area"), this.motion,
      this.transport, () => this.stage(), antialias, options.scale, options.fps);
    this.viewer.onFrame = (t) => {
      if (this.rigs?.active) this.rigs.viewer.requestDraw(); // a seek or a rewind moves rigs too
      this.showFrame(t);
      drawSpectrum($("spectrum"), this.motion.bandValuesAt(t));
      drawBeat($("spectrum"), this.motion.spectrum, t);
    };
    const requestDraw = () => this.viewer.requestDraw();
    const status = (text: string) => messages.status(text);
    const guard = (what: string, task: () => Promise<void>) => messages.guard(what, task);
    this.gallery = new GalleryView(this.motion, { status, requestDraw, guard,
      songId: () => this.library.songId, modelName: () => this.library.meshName,
      open: (mapping) => this.open(mapping, `tile of generation ${this.gallery.generation + 1}`) },
    null);
    this.player = new PlayerView(this.motion, { requestDraw,
      upload: (file) => void this.files.handle([file]), modelName: () => this.library.meshName,
      harmonicScale: (index) => this.viewer.deformer?.harmonicScale(index) ?? 1 });
    this.recorder = new Recorder(this.transport,
      [$<HTMLButtonElement>("record"), $<HTMLButtonElement>("rig-record")], () => this.play(),
      () => ({ viewer: this.shownViewer(), name: this.modelName(),
        element: $(this.rigs.active ? "rig-player-area" : "player-area") }));
    this.library = new Library(options, this.motion, this.viewer, this.transport,
      (text, fraction) => messages.loading(text, fraction), (text) => messages.error(text));
    this.library.onBasis = () => { this.gallery.refresh(); this.player.basisChanged(); };
    this.live = new LiveSource({ transport: this.transport, motion: this.motion,
      error: (text) => messages.error(text), status, requestDraw: () => this.requestDraws(),
      restoreSong: () => this.restoreSong(),
      songAdded: async (id) => { await this.library.refresh(); this.live.fillMenu($<HTMLSelectElement>("song")); },
      fps: () => this.shownViewer().fps });
    this.library.onMenus = () => this.live.fillMenu($<HTMLSelectElement>("song"));
    this.rigs = new RigStage(this.motion, this.transport, antialias, {
      status, loading: (text) => messages.loading(text), guard,
      songId: () => this.library.songId }, options.path, options.batch, !options.render,
    options.scale, options.fps);
    this.files = new FileIntake(messages, {
      refresh: async () => { await this.library.refresh(); },
      started: () => this.started,
      startIfComplete: async () => this.loadFirst(await this.library.refresh()),
      openRig: (id) => this.openRig(id), showMesh: (id) => this.showMesh(id),
      changeSong: (id) => this.changeSong(id),
      openMapping: (_, mapping, name) => this.open(mapping, name),
      requestDraw });
    this.frameRate = new FrameRateWatch({
      viewer: () => this.shownViewer(),
      galleryTiles: () => (this.view === "gallery" && !this.rigs.active
        ? this.gallery.tileCount : null),
      playing: () => this.transport.playing,
      smallest: () => this.rule?.min ?? 2,
      newGallery: (size) => this.newGallery(size) });
    this.exporter = new ExportPanel(messages, {
      dance: () => this.exportedDance(), now: () => this.viewer.time(),
      duration: () => this.motion.duration, live: () => this.transport.following });
    this.transport.onChange = (playing) => {
      $("play").textContent = playing ? "❚❚" : "▶";
      this.frameRate.restart();
      messages.playing(playing);
    };
    wireHeader(this);
    messages.wire();
    this.files.wire();
  }

  /** Start: the render loop (not in `?render` mode), the server's rules, the library, and the
   * first gallery. Never rejects: a failure is shown as an error. */
  async start(): Promise<void> {
    document.body.classList.toggle("bare", this.options.bare);
    if (!this.options.render) this.viewer.start();
    const hooks = this.options.render || this.options.test || this.options.bare;
    if (!hooks) this.messages.helpOnFirstVisit();
    try {
      await this.readConfig();
      await this.loadFirst(restoreStored(this, await this.library.refresh())); // a reload
    } catch (error) {
      this.messages.error(`The page could not start: ${messageOf(error)}`);
    }
  }

  setView(view: View): void {
    this.view = view;
    if (view !== "gallery" || this.rigs.active) this.frameRate.hideNotice(); // about the tiles
    this.exporter.refresh();
    if (this.rigs.active) { this.rigs.setView(view); return; }
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
    this.frameRate.hideNotice(); // the harmonics' gallery leaves the screen
    return this.messages.guard("Could not show this rig", async () => {
      if (!this.started) { // a library with a song and no model: a rig chosen in the menu
        const library = await this.library.refresh();
        if (library.songs.length) await loadStartSong(this, library);
        this.started = library.songs.length > 0;
      }
      if (!this.library.songId) { // `serve` with no file, a rig chosen: say what it needs
        const name = this.library.rigName(rigId) || "a rig";
        this.messages.status(`${name} needs a song to dance to: drop one here, or add one `
          + "with add model / song / mapping");
        this.chosenRig = rigId; // a song added then opens it (loadFirst)
        return;
      }
      await this.rigs.open(rigId, this.rule?.max ?? 16);
      $<HTMLSelectElement>("mesh").value = `rig:${rigId}`;
      this.view = "gallery";
      this.exporter.refresh();
    });
  }

  /** Play `mapping` in the player; `source` says where it comes from. */
  open(mapping: Mapping, source = ""): void {
    this.player.show(mapping, source);
    if (this.view !== "player") this.setView("player");
    this.exporter.refresh();
    this.viewer.requestDraw();
  }

  /** Play the song, drawing by its clock again if a time was pinned. */
  play(): void {
    this.transport.play();
    if (this.transport.playing) this.viewer.unpin();
  }

  togglePlay(): void {
    if (this.transport.playing) this.transport.pause(); else this.play();
  }

  /** A new first generation of `size` tiles (default: the size on screen; null: the server's
   * default) for the current mesh and song, calibrated on the song; earlier generations stay in
   * the history. The *tiles* menu follows; on failure it shows the size on screen. */
  async newGallery(size?: number | null): Promise<string | null> {
    const { meshId, songId } = this.library;
    const note = `${this.library.meshName}, ${this.library.songName}`;
    const failure = await this.messages.guard("Could not make the gallery",
      () => this.gallery.create(meshId, songId, note, size === undefined ? this.gallery.size
        : size));
    if (this.gallery.size !== null) this.fillSizeMenu(this.gallery.size);
    return failure;
  }

  /** A new current mesh with its own history (a first gallery when it has none), and the
   * faster deformation path for it. Returns the gallery's failure (already shown), or null. */
  async showMesh(meshId: string): Promise<string | null> {
    if (!await this.library.loadMesh(meshId)) return "removed while it was computed";
    if (this.rigs.active) { this.rigs.leave(); this.setView(this.view); }
    const failure = this.gallery.showMesh(meshId) ? null : await this.newGallery();
    if (this.gallery.size !== null) this.fillSizeMenu(this.gallery.tileCount || this.gallery.size);
    this.viewer.choosePath(this.options.path);
    this.exporter.refresh();
    return failure;
  }

  /** A new current song, from 0:00, with a first gallery calibrated on it (a live input
   * playing stops). */
  async changeSong(songId: string): Promise<void> {
    this.live.stop();
    await this.library.loadSong(songId);
    keepInSession({ song: songOf(this) }); // the song the galleries are calibrated on
    await this.newGallery();
    await this.rigs.songChanged();
    this.exporter.refresh();
    this.viewer.requestDraw();
  }

  /** Dance to a live input instead of the song (docs/web.md#live-input): the galleries,
   * the player and rigs stay, their mappings hear the input. False when it could not be opened
   * (said in one line; the song plays on). */
  startLive(choice: LiveChoice): Promise<boolean> {
    return this.live.start(choice);
  }

  /** The live input `?source=` asks for; a failure (no device, permission refused, a source
   * that is none) is said in the banner, and the status says the song plays instead. */
  private async startAskedSource(): Promise<void> {
    const { source, badSource } = this.options;
    if (badSource !== null) {
      this.messages.error(`?source=${badSource} is not a live input (?source=mic: a microphone `
        + "or line in; ?source=tab: a tab's audio); the song plays instead");
    } else if (source && !await this.startLive({ kind: source })) {
      this.messages.status("the song plays instead of the live input (see above)");
    }
  }

  /** The library's current song again, after a live input (its spectrogram and sound). */
  private async restoreSong(): Promise<void> {
    if (this.library.songId) await this.library.loadSong(this.library.songId);
    this.requestDraws();
  }

  private requestDraws(): void {
    this.viewer.requestDraw();
    if (this.rigs.active) this.rigs.viewer.requestDraw();
  }

  /** The model on screen's name: a rig's, or the mesh's. */
  modelName(): string { return this.rigs.active ? this.rigs.rig?.name ?? "" : this.library.meshName; }

  /** The viewer drawing now: a rig's, or the harmonics'. */
  shownViewer(): Viewer { return this.rigs.active ? this.rigs.viewer : this.viewer; }

  /** What the export panel exports: the dance the player shows (null in the gallery). */
  private exportedDance() {
    const song = this.library.songId;
    if (this.rigs.active) { // the rig's own views: combine selected and open reach its player
      if (this.rigs.view !== "player") return null;
      const mapping = this.rigs.player.saved();
      return mapping && this.rigs.rig ? { kind: "rig" as const, id: this.rigs.rig.id, song,
        mapping, name: this.rigs.rig.name } : null;
    }
    if (this.view !== "player") return null;
    const mapping = this.player.saved();
    return mapping ? { kind: "mesh" as const, id: this.library.meshId, song, mapping,
      name: this.library.meshName } : null;
  }

  /** What the viewer draws now. */
  private stage(): Stage {
    if (this.rigs.active) { // the rig's viewer draws
      return { view: this.view, tiles: [], player: null, explorer: this.player.explorer };
    }
    return { view: this.view, tiles: this.gallery.shots(),
      player: this.player.shot($("player-area")), explorer: this.player.explorer };
  }

  /** Before each frame: the seek bar and clock, now and then the frame-rate readout and the
   * player's info line. */
  private showFrame(t: number): void {
    const seekBar = $<HTMLInputElement>("seek");
    if (document.activeElement !== seekBar) seekBar.value = String(t);
    const seconds = Math.floor(t);
    $("clock").textContent = `${Math.floor(seconds / 60)}:${String(seconds % 60).padStart(2, "0")}`;
    const now = performance.now();
    if (now - this.readoutAt < READOUT_EVERY_MS) return;
    this.readoutAt = now;
    if (this.view === "player") this.player.refreshInfo(this.viewer.path);
    this.frameRate.update(now);
    this.live.refresh();
  }

  /** The rules from the server: the suffixes of the files it accepts (for the uploads), and
   * the gallery size: the *tiles* menu, and `?size=` checked against it (a bad one falls back
   * to the default, with a notice). Without them the server checks. */
  private async readConfig(): Promise<void> {
    try {
      const config = await api.config();
      this.files.suffixes = suffixesOf(config);
      this.rule = galleryRule(config);
    } catch (error) {
      this.rule = null;
      this.messages.error(`Could not read the gallery sizes from the server (${messageOf(error)}); `
        + "the server will check the size asked for");
    }
    const { size, problem } = gallerySize(this.options.size, this.rule);
    this.notice = problem ?? "";
    if (this.notice) this.messages.status(this.notice);
    this.gallery.size = size;
    this.fillSizeMenu(size);
  }

  /** Start with rig `rigId` in its gallery of modes, on the session's song (or `?song=`). */
  private async loadFirstRig(library: api.Library, rigId: string): Promise<boolean> {
    await loadStartSong(this, library); // the session's song (session.ts), or the first
    this.started = true;
    const failure = await this.openRig(rigId);
    if (this.options.view === "player") this.setView("player");
    if (!failure) {
      this.messages.hint(this.options.render ? "render mode" : READY, this.transport.playing);
    }
    await this.live.listDevices();
    await this.startAskedSource();
    return true;
  }

  /** The *tiles* menu: the sizes the rule allows, the size on screen chosen. */
  private fillSizeMenu(size: number | null): void {
    const menu = $<HTMLSelectElement>("size");
    menu.innerHTML = "";
    if (size === null) return;
    for (const choice of sizeChoices(this.rule, size)) menu.add(new Option(String(choice)));
    menu.value = String(size);
  }

  /** Load the first mesh and song and show the gallery (at start, or once uploads complete the
   * library). What a start (or a reload) shows: the session's model, else the library's first,
   * the session's song or the first (or `?mesh=`, `?song=`), the gallery — or the player with a mapping given to `serve` (or
   * `?mapping=`); mappings added in the page stay in the menu, and do not open by themselves.
   * A rig given first to `serve` (a skinned glTF), or the only kind of model there, opens in
   * its gallery of modes instead. Returns false while the library lacks a model or a song. */
  private async loadFirst(library: api.Library): Promise<boolean> {
    const start = startModel(library, this.options.mesh); // the session's model, or the first
    const chosen = !library.meshes.length && library.rigs?.some((r) => r.id === this.chosenRig)
      ? this.chosenRig : null; // a rig chosen in the menu before there was a song
    const rig = start.rig ?? chosen;
    if (rig && library.songs.length) return this.loadFirstRig(library, rig);
    if (!library.meshes.length || !library.songs.length) {
      const missing = library.meshes.length ? "a song" : "a model";
      this.messages.status(`the library needs ${missing}: drop a file here`);
      return false;
    }
    const { options } = this;
    await loadStartSong(this, library); // the session's song, paused where it was left
    await this.library.loadMesh(options.mesh ?? start.mesh ?? library.meshes[0].id);
    this.started = true;
    // The session kept in the browser (session.ts): the generations come back after a reload.
    let failure = this.gallery.showMesh(this.library.meshId) ? null : await this.newGallery();
    if (failure && this.gallery.size !== null && this.rule === null) {
      failure = await this.newGallery(null); // the size asked for was refused: the default
    }
    const served = options.mapping ?? library.mappings.find((m) => m.origin === "file")?.id ?? null;
    if (served) {
      const name = library.mappings.find((m) => m.id === served)?.name ?? "mapping";
      $<HTMLSelectElement>("mapping-menu").value = served;
      this.player.show(await api.getJSON<Mapping>(`api/mappings/${served}`), name);
    }
    this.setView(options.view ?? (served ? "player" : "gallery"));
    this.viewer.choosePath(options.path);
    this.viewer.draw(this.viewer.time());
    this.player.refreshInfo(this.viewer.path);
    const ready = options.render ? "render mode" : READY;
    if (failure) this.messages.status("");
    else this.messages.hint(this.notice ? `${this.notice} · ${ready}` : ready,
      this.transport.playing);
    this.notice = "";
    await this.live.listDevices();
    await this.startAskedSource();
    return true;
  }
}
