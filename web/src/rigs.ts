// Rigs in the page (docs/web.md#rigs-in-the-page): an articulated model from the model menu
// opens its gallery of modes; the RigStage owns what the page shows then — a second Viewer (its
// own canvas) drawing the rig's modal skin through the harmonics' deformation machinery, the
// rig's galleries and player, and the edits (pose, stiffness) that answer a new rig bundle.
import * as api from "./api";
import { closeUp } from "./close-up";
import { $, messageOf } from "./dom";
import { loadAppearance } from "./look";
import type { Appearance } from "./look";
import type { Mapping, Prepared } from "./filter";
import { RigFigure } from "./bones";
import { RigMotion, bodyMatrices, modalWeights } from "./modal-skin";
import type { Motion } from "./motion";
import type { Rig } from "./rig-bundle";
import { poseRig, resetRig, rigBasis, rigBundle, rigGallery, stiffenRig } from "./rig-bundle";
import { RIG_LOOK, RigGalleryView } from "./rig-gallery-view";
import { RigPlayerView } from "./rig-player-view";
import { RigSessions } from "./rig-session";
import type { SavedRig } from "./session";
import { SurfacePlay, surfaceBasis, surfaceShare } from "./rig-surface";
import type { RigDance } from "./rig-surface";
import { RigSurfaceView } from "./rig-surface-view";
import type { Clock } from "./transport";
import { Viewer } from "./viewer";
import type { DeformationPath, Stage, View } from "./viewer";

export interface RigEvents {
  status(text: string): void;
  loading(text: string | null): void;
  guard(what: string, task: () => Promise<void>): Promise<string | null>;
  /** the song the dances are calibrated on */
  songId(): string;
}

export class RigStage {
  readonly motion: RigMotion;
  readonly viewer: Viewer;
  readonly gallery: RigGalleryView;
  readonly player: RigPlayerView;
  readonly surface: RigSurfaceView;
  rig: Rig | null = null;
  /** the rig's skin's materials (its drawn vertices follow the skin's), or null: clay */
  appearance: Appearance | null = null;
  figure: RigFigure | null = null;
  active = false;
  view: View = "gallery";
  /** each dance tile's surface genes as played (`surfaceOf`) */
  private tileSurfaces = new WeakMap<Prepared, SurfacePlay>();
  /** every rig's galleries and palette, as the session keeps them (rig-session.ts) */
  readonly sessions = new RigSessions();
  /** the rig gallery's default mapping (calibrated on the song): what combined modes play */
  private defaultMapping: Mapping | null = null;
  /** false while a rig opens (what it shows first is not a change to keep) */
  private keeping = false;

  constructor(music: Motion, clock: Clock, antialias: boolean, private readonly events: RigEvents,
              private readonly path: DeformationPath | null, private readonly batch: number,
              live: boolean, scale: number | null = null, target: number | null = null) {
    this.motion = new RigMotion(music);
    // The page's own loop handles the end of the song (rewind, the seek bar); this one follows.
    const follower: Clock = { get playing() { return clock.playing; }, now: () => clock.now(),
      ended: () => false, rewind: () => {} };
    this.viewer = new Viewer($<HTMLCanvasElement>("rig-gl"), $("rig-player-area"), this.motion,
      follower, () => this.stage(), antialias, scale, target);
    this.viewer.onFrame = (t) => this.beforeFrame(t);
    const requestDraw = () => this.viewer.requestDraw();
    this.gallery = new RigGalleryView({ status: events.status, requestDraw, guard: events.guard,
      songId: () => events.songId(),
      combine: (modes) => this.combine(modes),
      open: (mapping, source) => void events.guard("Could not open the dance",
        () => this.openDance(mapping, source)),
      timeScale: () => this.player.palette?.time_scale ?? this.rig?.palette?.time_scale ?? 1,
      changed: () => this.keep(),
      closeUp: (prepared) => closeUp(this.viewer.deformer!.basis, this.motion.framingWeights(prepared)) });
    this.player = new RigPlayerView({ requestDraw, guard: events.guard,
      timeScaleChanged: () => { if (this.gallery.mode === "modes") this.gallery.refresh(); },
      pose: (joint, rotation) => this.poseJoint(joint, rotation),
      stiffness: (joint, value) => this.stiffness(joint, value),
      reset: () => this.reset(), surface: () => this.surface.genes,
      changed: () => { this.surface?.refreshShare(); this.keep(); } });
    this.motion.surfaceOf = (prepared) => this.surfaceOf(prepared);
    this.surface = new RigSurfaceView({ rig: () => this.rig, songId: events.songId,
      guard: events.guard, play: (surface) => this.playSurface(surface),
      share: () => this.surfaceShare(), dances: (dances) => this.gallery.setSurfaces(dances) });
    $("rig-player-area").addEventListener("click", (event) => this.pickAt(event));
    window.addEventListener("resize", () => { if (this.active) this.gallery.layout(); });
    // A banner or a wrapped header moves the views: draw again where they are now (paused too).
    for (const id of ["rig-tiles", "rig-player-area"]) new ResizeObserver(requestDraw).observe($(id));
    if (live) this.viewer.start(); // not in `?render` mode: the caller draws the frames
  }

  /** Open rig `id` (its bundle; the dances calibrated on the current song) in its gallery of
   * modes. Throws the server's error (a rig without modes, an unreadable file…). */
  async open(id: string, pageSize: number): Promise<void> {
    this.events.loading("loading the rig and its vibration modes…");
    this.keeping = false;
    try {
      const rig = await rigBundle(id);
      if (!rig.k) throw new Error(`${rig.name} has no vibration mode (no elastic joint)`);
      const [gallery, appearance] = await Promise.all([
        rigGallery(id, this.events.songId(), null), this.rigLook(id)]);
      this.appearance = appearance;
      $("rig-materials-switch").hidden = !appearance;
      this.gallery.pageSize = pageSize;
      this.setRig(rig, true);
      this.defaultMapping = gallery.default;
      this.player.show(gallery.default, "default palette");
      this.gallery.setDances(gallery.mappings);
      this.gallery.setMode("modes");
      this.showSaved(this.sessions.get(id));
      this.keeping = true;
      this.enter();
      this.viewer.choosePath(this.path);
      // The server keeps a rig's edits until "reset pose": a reload shows them, and says so.
      const modes = `${rig.k} vibration mode${rig.k === 1 ? "" : "s"}`;
      this.events.status(`${rig.name}: ${modes}` + (rig.edited ? " · its pose or stiffness was "
        + "edited earlier (the server keeps edits; reset pose goes back to the rig as loaded)"
        : ""));
    } finally {
      this.events.loading(null);
    }
  }

  /** Rigs of a saved session (*open session*): the rig open shows its galleries again. */
  restore(rigs: Record<string, SavedRig>): void {
    this.sessions.restore(rigs);
    if (this.active && this.rig && rigs[this.rig.id]) {
      this.keeping = false;
      this.showSaved(rigs[this.rig.id]);
      this.keeping = true;
    }
  }

  /** A rig's galleries and player as a session kept them (a palette that no longer fits the
   * rig, after an edit elsewhere, is left out). */
  private showSaved(saved: SavedRig | undefined): void {
    if (!saved) return;
    this.gallery.restoreDances(saved.generations, saved.generation, saved.selected);
    if (!saved.player) return;
    try {
      this.player.show(saved.player.mapping, saved.player.source);
    } catch {
      this.player.show(this.defaultMapping!, "default palette");
    }
  }

  /** Keep the open rig's galleries and palette in the session (rig-session.ts). */
  private keep(): void {
    const rig = this.rig;
    if (!this.keeping || !rig) return;
    const mapping = this.player.saved();
    this.sessions.set(rig.id, { generations: this.gallery.generations,
      generation: this.gallery.generation, selected: this.gallery.selectedDanceList,
      player: mapping ? { mapping, source: this.player.source } : null });
  }

  /** A new song: the dances and the combined modes' mapping are calibrated on it again. */
  async songChanged(): Promise<void> {
    if (!this.active || !this.rig) return;
    const gallery = await rigGallery(this.rig.id, this.events.songId(), null);
    this.defaultMapping = gallery.default;
    this.gallery.setDances(gallery.mappings);
    await this.surface.songChanged();
  }

  /** Back to the harmonics (another model chosen). */
  leave(): void {
    this.active = false;
    document.body.classList.remove("rig-mode");
    for (const id of ["rig-gallery-view", "rig-player-view"]) $(id).hidden = true;
    $("rig-gl").hidden = true;
  }

  setView(view: View): void {
    this.view = view;
    $("rig-gallery-view").hidden = view !== "gallery";
    $("rig-player-view").hidden = view !== "player";
    $("tab-gallery").classList.toggle("active", view === "gallery");
    $("tab-player").classList.toggle("active", view === "player");
    if (view === "gallery" && this.active) this.gallery.layout();
    this.viewer.requestDraw();
  }

  stage(): Stage {
    if (!this.active) return { view: this.view, tiles: [], player: null, explorer: { harmonic: -1, scale: 1 } };
    const player = this.player.shot($("rig-player-area"));
    return { view: this.view, tiles: this.view === "gallery" ? this.gallery.shots() : [], player,
      explorer: { harmonic: -1, scale: 1 } };
  }

  /** Play a dance in the player (a tile, a preset, a show's cue) as it was made: its bones'
   * mapping, and its skin rippling by its surface genes (the surface turned on for them) or
   * still (the surface off) when it has none. */
  async openDance(mapping: RigDance, source: string): Promise<void> {
    this.player.show(mapping, source);
    this.setView("player");
    await this.surface.follow(mapping.surface ?? null);
  }

  /** What ripples the skin of the player (the surface section's choice) or of a dance tile
   * (its surface genes, at the section's gain); null: nothing, or the surface is off. */
  private surfaceOf(prepared: Prepared): SurfacePlay | null {
    const played = this.motion.surface;
    if (!played || prepared === this.player.prepared) return played;
    const genes = this.gallery.surfaceGenes(prepared);
    if (!genes) return null;
    let play = this.tileSurfaces.get(prepared);
    if (play?.mapping !== genes || play.surface !== played.surface) {
      play = new SurfacePlay(played.surface, genes);
      this.tileSurfaces.set(prepared, play);
    }
    play.gain = played.gain;
    return play;
  }

  /** Combine the selected modes in the player: the song-calibrated default mapping playing
   * them, each at its tile's amplitude over √(number of modes) and its tile's phase. */
  combine(modes: number[]): void {
    const rig = this.rig;
    if (!rig || !modes.length || !this.defaultMapping) return;
    const share = 1 / Math.sqrt(modes.length);
    this.player.show({ ...this.defaultMapping, modes: { selected: modes,
      amplitudes: modes.map((m) => rig.tileAmplitudes[m] * share),
      phases: modes.map((m) => rig.phases[m]),
      time_scale: this.player.palette?.time_scale ?? rig.palette!.time_scale } },
    `modes ${modes.map((m) => m + 1).join(", ")}`);
    this.setView("player");
  }

  /** Equilibrium pose edit (thesis Fig. 4.17): turn `joint`'s far side by the rotation
   * vector (world, radians); the server recomputes the modes. */
  poseJoint(joint: number, rotation: [number, number, number]): Promise<void> {
    return this.edit("turning the joint", () => poseRig(this.rig!.id, joint, rotation));
  }

  /** Stiffness of every free row of `joint`, or "auto" (the default rule). */
  stiffness(joint: number, value: number | "auto"): Promise<void> {
    return this.edit("setting the stiffness",
      () => stiffenRig(this.rig!.id, { [this.rig!.jointList[joint].name]: value }));
  }

  /** The rig as loaded (pose and stiffness). */
  reset(): Promise<void> {
    return this.edit("resetting", async () => {
      const rig = await resetRig(this.rig!.id);
      this.player.pick(this.player.joint); // the sliders back to 0
      return rig;
    });
  }

  private enter(): void {
    this.active = true;
    document.body.classList.add("rig-mode");
    $("gallery-view").hidden = true;
    $("player-view").hidden = true;
    $("rig-gl").hidden = false;
    this.setView("gallery");
  }

  /** Show a rig: its modal skin as a basis for the viewer, its figure (bones, LBS skin). */
  private setRig(rig: Rig, fresh: boolean): void {
    this.motion.surface = null; // a new rest pose: new skin harmonics
    this.surface.reset();
    this.drawRig(rig);
    this.rig = rig;
    this.motion.rig = rig;
    this.player.setRig(rig, fresh);
    this.gallery.setRig(rig, fresh);
    if (!fresh) this.viewer.setPath(this.viewer.path);
  }

  /** The viewer's basis: the modal skin, with the skin's harmonics when the surface is on. */
  private drawRig(rig: Rig): void {
    const surface = this.motion.surface;
    this.viewer.setBasis(surface ? surfaceBasis(rig, surface.surface) : rigBasis(rig), this.batch,
      this.appearance);
    this.figure?.dispose();
    this.figure = new RigFigure(rig, this.viewer.deformer!.look, surface?.surface ?? null);
    this.viewer.deformer!.scene.add(this.figure.group);
  }

  /** The surface section's choice: the skin ripples (or not) in the player. */
  private playSurface(surface: SurfacePlay | null): void {
    const changed = (surface === null) !== (this.motion.surface === null);
    this.motion.surface = surface;
    if (changed && this.rig) {
      this.drawRig(this.rig);
      this.viewer.setPath(this.viewer.path);
    }
    this.viewer.requestDraw();
  }

  /** The surface's share of the player's motion, over 16 moments spread over the song (null:
   * no surface or no song). */
  surfaceShare(): number | null {
    const prepared = this.player.prepared, deformer = this.viewer.deformer;
    const spectrum = this.motion.music.spectrum;
    if (!this.motion.surface || !prepared || !deformer || !spectrum) return null;
    const times = [...Array(16).keys()].map((i) => (i + 0.5) * spectrum.duration / 16);
    const surface = this.motion.surface;
    return surfaceShare(deformer.basis, times, (t, on) => {
      this.motion.surface = on ? surface : null;
      try {
        return on ? this.motion.weights(prepared, t)
          : modalWeights(this.rig!, this.motion.coefficients(prepared, t),
            new Float32Array(12 * deformer.basis.k4));
      } finally {
        this.motion.surface = surface;
      }
    });
  }

  /** An edit answered by a new bundle: the modes are recomputed, gallery and player follow. */
  private async edit(what: string, request: () => Promise<Rig>): Promise<void> {
    this.events.status(`${what}…`);
    const started = performance.now();
    const rig = await request();
    this.setRig(rig, false);
    this.events.status(`${rig.name}: modes recomputed (${Math.round(performance.now() - started)} ms)`);
  }

  /** Before each frame: bones, joints and the LBS skin follow the player's body poses. */
  private beforeFrame(t: number): void {
    const figure = this.figure, deformer = this.viewer.deformer;
    if (!figure || !deformer) return;
    const player = this.view === "player" && this.player.prepared !== null;
    const lbs = player && this.player.skinning === "lbs";
    deformer.shown = !lbs;
    if (player) this.poseFigure(t);
    figure.show({ lbs, bones: player && this.player.bones, joint: player ? this.player.joint : -1,
      materials: RIG_LOOK.materials });
  }

  /** Bones, joints and the LBS skin at the player's time t: its body poses, and the skin's
   * ripple in the bind pose (the surface's φ at t, as the modal skin's) when the surface is on. */
  poseFigure(t: number): void {
    const figure = this.figure!, surface = this.motion.surface;
    figure.pose(bodyMatrices(this.rig!, this.motion.coefficients(this.player.prepared!, t)));
    figure.ripple(surface ? surface.phi(this.motion.music, t) : null);
  }

  /** The rig's skin's look, if the library lists one (null: clay, or it cannot be shown). */
  private async rigLook(id: string): Promise<Appearance | null> {
    const listed = (await api.library()).rigs?.find((rig) => rig.id === id);
    if (!listed?.look) return null;
    try {
      return await loadAppearance("rigs", id);
    } catch (error) {
      this.events.status(`${listed.name}: its materials cannot be shown (${messageOf(error)}); `
        + "drawn in clay");
      return null;
    }
  }

  /** A click in the player picks the joint drawn nearest to it. */
  private pickAt(event: MouseEvent): void {
    if (!this.figure || !this.player.bones) return;
    const area = $("rig-player-area").getBoundingClientRect();
    const x = ((event.clientX - area.left) / area.width) * 2 - 1;
    const y = -((event.clientY - area.top) / area.height) * 2 + 1;
    const joint = this.figure.nearestJoint(x, y, this.viewer.playerCamera);
    if (joint >= 0) this.player.pick(joint);
  }
}
