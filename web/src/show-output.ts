// The show's output page, /show (docs/design.md#show): one dance large for a projector or a
// capture, no controls. It follows the show's state from the server (server-sent events, so
// the control page may be another browser), changes cue or preset on the next downbeat (beats
// where the song has no bars) with a crossfade of the motion, reports the song time it draws
// (OSC out follows it), and ends a cue after its bars.
import type { App } from "./app";
import * as api from "./api";
import type { Spectrum } from "./bundle";
import type { Mapping, Prepared } from "./filter";
import { GridClock } from "./show-grid";
import { BANDS_PER_SECOND, LiveReporter, isLiveSpectrum } from "./show-live";
import { boundaryAfter, cueEnd, fadeWeight } from "./show-timing";
import type { ShowState } from "./show-timing";
import "./show.css";

/** How often the output page tells the server the song time it draws (ms). */
const CLOCK_EVERY_MS = 250;

/** The output page's own URL options: `?size=WxH` (letterboxed), `?bg=black|studio`,
 * `?offset=MS` (its latency offset). */
export interface OutputOptions { size: [number, number] | null; background: "black" | "studio";
  offset: number; }

export function readOutputOptions(search: string): OutputOptions {
  const params = new URLSearchParams(search);
  const match = /^(\d{2,5})x(\d{2,5})$/.exec(params.get("size") ?? "");
  const offset = Number(params.get("offset") ?? 0);
  return { size: match ? [Number(match[1]), Number(match[2])] : null,
    background: params.get("bg") === "studio" ? "studio" : "black",
    offset: Number.isFinite(offset) ? Math.min(Math.max(offset, 0), 2000) / 1000 : 0 };
}

/** One change of cue as applied, at song time t; `before` the song time of the frame before
 * (the change came on the first frame at or past its boundary): for the tests and the
 * benchmark. */
export interface Applied { cue: number | null; preset: string | null; t: number; at: number;
  frameDt: number; before: number; }

export class ShowOutput {
  state: ShowState | null = null;
  /** the cue and preset on screen */
  shownCue: number | null = null;
  shownPreset: string | null = null;
  /** a change waiting for its downbeat: the song time it starts at */
  private pending: { cue: number | null; preset: string | null; at: number;
    mapping: Mapping | null; sameModel: boolean } | null = null;
  /** the crossfade in progress */
  private fade: { from: Prepared | null; start: number; length: number } | null = null;
  private cueStart = 0;
  private scheduled = 0;
  /** presets fitted to the cues' models, fetched ahead */
  private readonly mappings = new Map<string, Mapping | null>();
  private lastFrame = 0;
  private lastT = 0;
  private clockAt = 0;
  readonly applied: Applied[] = [];
  /** the show's own beat clock (taps, a typed tempo, Link) over the song's beats */
  readonly clock = new GridClock();
  /** a live input's events for OSC out, reported with the clock */
  private readonly live = new LiveReporter();
  /** the spectrum of the song or live take, without the show's beats */
  private base: Spectrum | null = null;
  /** each change of the show's gain: when the page heard it and drew its first frame (ms since
   * 1970; the benchmark's latency from an OSC message to the changed frame) */
  readonly gains: { gain: number; heard: number; drawn: number | null }[] = [];

  constructor(private readonly app: App, private readonly options: OutputOptions) {}

  /** Lay the page out, wrap the motion (gain, crossfade) and the clock (offset), follow. */
  start(first: ShowState): void {
    const { app, options } = this;
    document.body.classList.add("show-output", `show-${options.background}`);
    const area = document.getElementById("player-area")!;
    if (options.size) {
      const [w, h] = options.size;
      area.style.setProperty("--show-aspect", `${w} / ${h}`);
      area.classList.add("letterboxed");
    }
    if (options.background === "black") {
      app.viewer.studio.backdrop.visible = false; // the model alone on black, as a projector
      const renderer = app.viewer.renderer;
      const clear = renderer.setClearColor.bind(renderer);
      renderer.setClearColor = (_color, alpha) => clear(0x000000, alpha);
    }
    const clock = app.transport;
    const now = clock.now.bind(clock);
    clock.now = () => Math.max(0, now() - this.options.offset);
    this.base = app.motion.spectrum; // every part reads the spectrum with the show's beats
    Object.defineProperty(app.motion, "spectrum", { configurable: true,
      get: () => this.clock.wrap(this.base), set: (spectrum) => { this.base = spectrum; } });
    const weights = app.motion.weights.bind(app.motion);
    app.motion.weights = (prepared: Prepared, t: number) => this.weights(weights, prepared, t);
    const onFrame = app.viewer.onFrame;
    app.viewer.onFrame = (t) => { this.frame(t); onFrame(t); };
    const full = () => void document.documentElement.requestFullscreen?.().catch(() => {});
    window.addEventListener("keydown", (e) => { if (e.key === "f" || e.key === "F") full(); });
    area.addEventListener("click", full);
    this.shownCue = first.cue;
    this.shownPreset = first.preset;
    this.follow(first);
    if (first.preset) void this.schedule(first.cue, first.preset, true);
    const events = new EventSource("api/show/events");
    events.onmessage = (e) => this.follow(JSON.parse(e.data) as ShowState);
  }

  /** A new state from the server. */
  follow(state: ShowState): void {
    const before = this.state;
    this.state = state;
    const app = this.app;
    document.body.classList.toggle("show-blackout", state.blackout);
    this.clock.set(state.grid);
    if (before && before.gain !== state.gain) {
      this.gains.push({ gain: state.gain, heard: performance.timeOrigin + performance.now(),
        drawn: null });
    }
    if (state.playing && !app.transport.playing) app.play();
    if (!state.playing && app.transport.playing) app.transport.pause();
    for (const [id, value] of Object.entries(state.controls)) setControl(id, value);
    if (state.cue !== this.shownCue || state.preset !== this.shownPreset) {
      void this.schedule(state.cue, state.preset);
    }
    if (state.next !== null && !this.mappings.has(this.key(state.next, state.cues[state.next].preset))) {
      void this.fetchMapping(state.next, state.cues[state.next].preset);
    }
    app.viewer.requestDraw();
  }

  /** Make ready the change to (cue, preset) and set it for the next boundary (`now`: this
   * frame's time, which is a boundary). */
  private async schedule(cue: number | null, preset: string | null, now = false): Promise<void> {
    const t = this.app.viewer.time();
    const at = now ? t : boundaryAfter(this.app.motion.spectrum, t);
    const token = ++this.scheduled;
    const cached = this.mappings.get(this.key(cue, preset));
    const mapping = cached !== undefined ? cached : await this.fetchMapping(cue, preset);
    if (token !== this.scheduled) return; // a later change replaced it
    this.pending = { cue, preset, at, mapping, sameModel: this.sameModel(cue) };
  }

  /** Whether cue `cue` dances the model and song on screen (a crossfade of the motion). */
  private sameModel(cue: number | null): boolean {
    const state = this.state!;
    const next = cue === null ? null : state.cues[cue];
    const shown = this.shownCue === null ? null : state.cues[this.shownCue];
    return !next || !shown || (shown.model.id === next.model.id && shown.song === next.song);
  }

  private key(cue: number | null, preset: string | null): string {
    const model = cue === null ? null : this.state?.cues[cue]?.model;
    return `${preset}\u0000${model?.kind ?? "mesh"}:${model?.id ?? this.app.library.meshId}`;
  }

  /** Preset `preset` fitted to cue `cue`'s model (null: none, or it failed: said on the
   * console); kept, so that a cue's end can change at once. */
  private async fetchMapping(cue: number | null, preset: string | null): Promise<Mapping | null> {
    if (!preset) return null;
    const model = cue === null ? null : this.state?.cues[cue]?.model;
    const query = model?.kind === "rig" ? `rig=${model.id}` : `mesh=${model?.id ?? this.app.library.meshId}`;
    let mapping: Mapping | null = null;
    try {
      mapping = (await api.getJSON<{ mapping: Mapping }>(
        `api/presets/${encodeURIComponent(preset)}?${query}`)).mapping;
    } catch (error) {
      console.warn(`eigendance show: preset ${preset}: ${String(error)}`);
    }
    this.mappings.set(this.key(cue, preset), mapping);
    return mapping;
  }

  /** Before each frame: apply a change whose boundary came, end a cue after its bars, report
   * the clock now and then. */
  private frame(t: number): void {
    const wall = performance.now();
    const frameDt = this.lastFrame ? (wall - this.lastFrame) / 1000 : 0;
    this.lastFrame = wall;
    if (this.lastT > t + 0.5) this.cueStart = t; // the song started again
    if (this.app.transport.playing) this.clock.frame(t, performance.timeOrigin + wall);
    const before = this.lastT;
    this.lastT = t;
    const last = this.gains[this.gains.length - 1];
    if (last && last.drawn === null) last.drawn = performance.timeOrigin + wall;
    if (!this.pending) this.endCue(t);
    const pending = this.pending;
    if (pending && t >= pending.at) {
      this.pending = null;
      void this.apply(pending, t, frameDt, before);
    }
    const base = this.base;
    const live = isLiveSpectrum(base) && this.app.live.active ? base : null;
    // a live input's report goes as soon as there is a beat or an onset, its bands 30 a second
    const every = live ? 1000 / BANDS_PER_SECOND : CLOCK_EVERY_MS;
    if (wall - this.clockAt > every || (live && this.live.pending(live))) {
      this.clockAt = wall;
      const spectrum = this.app.motion.spectrum;
      void fetch("api/show/clock", { method: "POST", headers: { "Content-Type": "application/json" },
        body: JSON.stringify({ song: live ? null : this.app.library.songId || null, time: t,
          playing: this.app.transport.playing, tempo: spectrum?.tempo || null,
          wall: performance.timeOrigin + wall, live: live ? this.live.report(live) : null }) })
        .catch(() => {});
    }
  }

  /** The cue's bars are over (or its section): on to the next, now (this is its boundary). */
  private endCue(t: number): void {
    const state = this.state;
    if (!state || state.cue === null || this.shownCue !== state.cue) return;
    const cue = state.cues[state.cue];
    const end = cueEnd(this.app.motion.spectrum, cue, this.cueStart);
    if (end === null || t < end || state.loop_cue) return;
    if (state.next === null) return;
    this.cueStart = t;
    this.pending = null;
    void api.postJSON<ShowState>("api/show/control",
      { action: "next", value: { from: state.cue } }).catch(() => {});
    const next = state.next;
    const preset = state.cues[next].preset;
    this.state = { ...state, cue: next, preset };
    const mapping = this.mappings.get(this.key(next, preset));
    if (mapping !== undefined || !preset) {
      this.pending = { cue: next, preset, at: t, mapping: mapping ?? null,
        sameModel: this.sameModel(next) };
    } else {
      void this.schedule(next, preset, true);
    }
  }

  private async apply(change: NonNullable<ShowOutput["pending"]>, t: number, frameDt: number,
                      before = t) {
    const app = this.app;
    const state = this.state!;
    const beats = state.fade_beats;
    const tempo = app.motion.spectrum?.tempo || state.tempo || 120;
    const from = change.sameModel ? app.player.prepared : null;
    this.applied.push({ cue: change.cue, preset: change.preset, t, at: performance.now(), frameDt,
      before });
    if (change.cue !== this.shownCue) this.cueStart = t;
    this.shownCue = change.cue;
    this.shownPreset = change.preset;
    if (!change.sameModel && change.cue !== null) {
      const cue = state.cues[change.cue];
      if (cue.live) {
        await app.startLive({ kind: cue.live });
      } else if (cue.song && (cue.song !== app.library.songId || app.live.active)) {
        app.live.stop();
        await app.library.loadSong(cue.song);
      }
      if (cue.model.kind === "mesh" && cue.model.id !== app.library.meshId) {
        await app.library.loadMesh(cue.model.id);
        app.player.basisChanged();
      } else if (cue.model.kind === "rig") {
        await app.openRig(cue.model.id);
        app.setView("player");
      }
      if (state.playing) app.play();
    }
    if (app.rigs.active) { // a rig: its own player (cut at the bar: no crossfade, no gain)
      if (change.mapping) await app.rigs.openDance(change.mapping, change.preset ?? "");
    } else {
      const mapping = change.mapping ?? app.gallery.mappings()[0] ?? null;
      if (mapping) app.open(mapping, change.preset ?? "");
    }
    this.fade = beats > 0 ? { from, start: t, length: (beats * 60) / tempo } : null;
    app.viewer.requestDraw();
  }

  /** The motion drawn: the show's gain × (the crossfade from the old mapping to the new). */
  private weights(base: (p: Prepared, t: number) => Float32Array, prepared: Prepared,
                  t: number): Float32Array {
    const gain = this.state?.gain ?? 1;
    const out = base(prepared, t);
    const fade = this.fade;
    const w = fade ? fadeWeight(fade.start, fade.length, t) : 1;
    if (fade && w >= 1) this.fade = null;
    const old = fade && w < 1 && fade.from && fade.from.k === prepared.k
      ? base(fade.from, t) : null;
    for (let i = 0; i < out.length; i++) out[i] = gain * (w * out[i] + (old ? (1 - w) * old[i] : 0));
    return out;
  }
}

/** Set a slider, switch or menu of the page as if a person had (OSC /control/ID, MIDI). */
export function setControl(id: string, value: number): void {
  const element = document.getElementById(id);
  if (element instanceof HTMLInputElement) {
    if (element.type === "checkbox") element.checked = value >= 0.5;
    else element.value = String(value);
    element.dispatchEvent(new Event(element.type === "checkbox" ? "change" : "input"));
  } else if (element instanceof HTMLButtonElement && value >= 0.5) {
    element.click();
  }
}
