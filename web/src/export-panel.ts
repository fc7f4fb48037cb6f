// The player's export (docs/web.md#export): the dance the player shows, from a start for a
// duration — by default from where the song is now for 15 s, the clip people post — as an MP4
// video with the song or a glTF (.glb). The server renders it (`POST api/export`, a job with
// progress like a basis solve); the page follows the job and offers the file.
import * as api from "./api";
import { $, fileName } from "./dom";
import type { Mapping } from "./filter";
import type { Messages } from "./messages";

/** The clip's default length (s): what people post. */
export const CLIP_SECONDS = 15;

/** What the panel exports: a mesh by a mapping, or a rig by a mode mapping, on a song. */
export interface ExportedDance {
  kind: "mesh" | "rig";
  id: string;
  song: string;
  mapping: Mapping;
  /** the model's name, for the file's */
  name: string;
}

export interface ExportEvents {
  /** the dance the player shows; null when none (the gallery) */
  dance(): ExportedDance | null;
  /** the song's position now (s) */
  now(): number;
  /** the song's length (s) */
  duration(): number;
  /** a live input plays instead of a song: nothing the server could render with its sound */
  live(): boolean;
}

/** What the panel says while a live input plays (the server has no recording of it). */
export const LIVE_EXPORT = "a live input plays, not a song: “save take” keeps what was heard as "
  + "one; choose it in the song menu to export its dance";

/** The request body of `POST api/export` (docs/web.md#http-api). */
export interface ExportRequest {
  mesh?: string;
  rig?: string;
  song: string;
  mapping: Mapping;
  format: "mp4" | "glb";
  start: number;
  duration: number;
  size?: string;
  fps?: number;
}

/** The window [start, start + duration] of a song of `length` seconds that a clip of `wanted`
 * seconds from `start` can have: the start clamped into the song, the duration cut at its end
 * (at least a tenth of a second). */
export function clipWindow(start: number, wanted: number, length: number):
    { start: number; duration: number } {
  const from = Number.isFinite(start) ? start : 0;
  const begin = Math.max(0, Math.min(from, Math.max(0, length - 0.1)));
  const span = Number.isFinite(wanted) && wanted > 0 ? wanted : CLIP_SECONDS;
  return { start: Math.round(begin * 100) / 100,
    duration: Math.round(Math.max(0.1, Math.min(span, length - begin)) * 100) / 100 };
}

/** A file name for the clip: `cat-0m12s-15s.mp4`. */
export function clipName(model: string, start: number, duration: number, format: string): string {
  const at = `${Math.floor(start / 60)}m${String(Math.floor(start % 60)).padStart(2, "0")}s`;
  return fileName(model, `${at}-${+duration.toFixed(1)}s`, format);
}

export class ExportPanel {
  private running = false;
  /** the dance (model, song, mapping) whose file the download link offers */
  private made = "";

  constructor(private readonly messages: Messages, private readonly events: ExportEvents) {
    for (const id of ["export-open", "rig-export-open"]) {
      $(id).addEventListener("click", () => this.toggle());
    }
    $("export-close").addEventListener("click", () => { $("export-panel").hidden = true; });
    $("export-start-now").addEventListener("click", () => this.fill());
    $("export-go").addEventListener("click", () => void this.run());
    $<HTMLSelectElement>("export-format").addEventListener("change", () => this.refresh());
  }

  /** Show the panel with the current position and 15 s, or hide it. */
  toggle(): void {
    const panel = $("export-panel");
    if (panel.hidden && this.events.dance() === null) {
      this.messages.status("open a tile in the player to export it");
      return;
    }
    panel.hidden = !panel.hidden;
    if (!panel.hidden) this.fill();
  }

  /** Start at the song's position now, for CLIP_SECONDS (cut at the song's end). */
  fill(): void {
    const { start, duration } = clipWindow(this.events.now(), CLIP_SECONDS,
      this.events.duration());
    $<HTMLInputElement>("export-start").value = start.toFixed(1);
    $<HTMLInputElement>("export-duration").value = duration.toFixed(1);
    this.refresh();
  }

  /** Something changed (the view, the model): the panel says whether it can export. */
  refresh(): void {
    const dance = this.events.dance(), live = this.events.live();
    const button = $<HTMLButtonElement>("export-go");
    button.disabled = this.running || dance === null || live;
    $("export-what").textContent = live ? LIVE_EXPORT : dance
      ? `${dance.name}, the player's mapping` : "open a tile in the player to export it";
    // The link and its "done" belong to the dance exported: another one (a model, a tile, a
    // palette changed) does not offer that file as its own.
    if (!this.running && this.made !== keyOf(dance)) {
      $("export-download").hidden = true;
      $("export-state").textContent = "";
    }
    $("export-size-label").hidden = $<HTMLSelectElement>("export-format").value !== "mp4";
    if (dance === null && !this.running) $("export-panel").hidden = true;
  }

  /** The request for the window in the fields (checked again by the server). */
  request(): ExportRequest | null {
    const dance = this.events.dance();
    if (!dance) return null;
    const { start, duration } = clipWindow(Number($<HTMLInputElement>("export-start").value),
      Number($<HTMLInputElement>("export-duration").value), this.events.duration());
    const format = $<HTMLSelectElement>("export-format").value as "mp4" | "glb";
    return { [dance.kind]: dance.id, song: dance.song, mapping: dance.mapping, format, start,
      duration, ...(format === "mp4" ? { size: $<HTMLSelectElement>("export-size").value } : {}) };
  }

  /** Ask the server for the file, follow its job, offer the download. */
  private async run(): Promise<void> {
    const request = this.request();
    const dance = this.events.dance();
    if (!request || !dance || this.running || this.events.live()) { this.refresh(); return; }
    this.running = true;
    this.refresh();
    const bar = $<HTMLProgressElement>("export-progress");
    const link = $<HTMLAnchorElement>("export-download");
    link.hidden = true;
    this.made = "";
    bar.hidden = false;
    bar.removeAttribute("value");
    const say = (text: string) => { $("export-state").textContent = text; };
    say("starting…");
    const failure = await this.messages.guard("The export failed", async () => {
      const { job } = await api.postJSON<{ job: api.Job }>("api/export", request);
      await api.followJob(job.id, (state) => {
        if (state.total) bar.value = state.done / state.total;
        say(state.state === "queued" ? "waiting for the renderer…"
          : `${state.done} of ${state.total} frames`);
      });
      // The file as a blob: the download keeps the page's name (the model, where, how long)
      const file = await (await api.checked(await fetch(`api/exports/${job.id}`))).blob();
      if (link.href.startsWith("blob:")) URL.revokeObjectURL(link.href);
      link.href = URL.createObjectURL(file);
      link.download = clipName(dance.name, request.start, request.duration, request.format);
      link.textContent = `download ${link.download}`;
      link.hidden = false;
      this.made = keyOf(dance);
      say("done");
      link.click();
    });
    if (failure) say("failed (see the message above)");
    bar.hidden = true;
    this.running = false;
    this.refresh();
  }
}

/** What identifies a dance's file: the model, the song and the mapping ("" for none). */
function keyOf(dance: ExportedDance | null): string {
  return dance ? JSON.stringify([dance.kind, dance.id, dance.song, dance.mapping]) : "";
}
