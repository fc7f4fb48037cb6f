// The presets panel (docs/design.md#presets): save the player's dance (a mesh's mapping or a
// rig's palette, with its look and a thumbnail of the view) as a named preset; browse, search
// by name and tag, mark favourites, rename, delete, play one, export and import preset files.
// Presets live on the server (`api/presets`), in a folder that survives restarts.
import type { App } from "./app";
import * as api from "./api";
import type { Mapping } from "./filter";

export interface PresetSummary { name: string; tags: string[]; favourite: boolean;
  kind: "mesh" | "rig"; thumbnail: boolean; }

const path = (name: string) => `api/presets/${encodeURIComponent(name)}`;

async function send(method: string, url: string, body?: unknown): Promise<unknown> {
  const response = await api.checked(await fetch(url, { method, headers: body === undefined
    ? {} : { "Content-Type": "application/json" },
  body: body === undefined ? undefined : JSON.stringify(body) }));
  return response.json();
}

export class PresetsPanel {
  readonly element: HTMLElement;
  presets: PresetSummary[] = [];

  constructor(private readonly app: App) {
    this.element = document.createElement("aside");
    this.element.id = "presets-panel";
    this.element.hidden = true;
    this.element.innerHTML = `
      <div class="row"><strong>presets</strong><button id="presets-close" aria-label="close">×</button></div>
      <div class="row"><input id="preset-name" placeholder="name" maxlength="64" size="14">
        <input id="preset-tags" placeholder="tags, comma separated" size="14">
        <button id="preset-save" title="save the player's dance (mapping or palette, look, a picture of it) as a preset">save</button></div>
      <div class="row"><input id="preset-search" type="search" placeholder="search name or tag" size="16">
        <label><input id="preset-favourites" type="checkbox"> ★ only</label>
        <label class="upload" title="import preset files">import <input id="preset-import" type="file" accept=".json" multiple hidden></label></div>
      <div id="preset-list"></div>
      <div id="preset-status" class="tags"></div>`;
    document.body.append(this.element);
    const button = document.createElement("button");
    button.id = "presets-button";
    button.textContent = "presets";
    button.title = "presets: save, browse and play named dances";
    document.querySelector("#bar nav")?.append(button);
    button.addEventListener("click", () => this.toggle());
    this.wire();
  }

  toggle(open = this.element.hidden): void {
    this.element.hidden = !open;
    if (open) void this.refresh();
  }

  async refresh(): Promise<void> {
    const q = (this.input("preset-search").value || "").trim();
    const favourites = this.input("preset-favourites").checked ? "&favourites=1" : "";
    this.presets = await api.getJSON<PresetSummary[]>(`api/presets?q=${encodeURIComponent(q)}${favourites}`);
    const list = this.element.querySelector("#preset-list")!;
    list.replaceChildren(...this.presets.map((preset) => this.row(preset)));
  }

  /** Save what the player shows as preset `name`; resolves to the error, or null. */
  async save(name: string, tags: string[], replace = false): Promise<string | null> {
    const app = this.app;
    const rig = app.rigs.active;
    const mapping: Mapping | null = rig ? app.rigs.player.saved() : app.player.saved();
    if (!mapping) return this.say("open a dance in the player first");
    const canvas = document.getElementById(rig ? "rig-gl" : "gl") as HTMLCanvasElement;
    const thumbnail = thumbnailOf(canvas);
    try {
      await send("POST", "api/presets", { name, mapping, tags, thumbnail, replace,
        mesh: rig ? undefined : app.library.meshId || undefined });
    } catch (error) { return this.say(String((error as Error).message ?? error)); }
    this.say(`saved ${name}`);
    await this.refresh();
    return null;
  }

  /** Play preset `name` in the player, fitted to the model on screen. */
  async play(name: string): Promise<void> {
    const app = this.app;
    const query = app.rigs.active && app.rigs.rig ? `rig=${app.rigs.rig.id}` : `mesh=${app.library.meshId}`;
    const preset = await api.getJSON<{ mapping: Mapping }>(`${path(name)}?${query}`);
    if (app.rigs.active) await app.rigs.openDance(preset.mapping, name); // with its surface
    else app.open(preset.mapping, `preset ${name}`);
  }

  private row(preset: PresetSummary): HTMLElement {
    const row = document.createElement("div");
    row.className = "preset";
    row.dataset.name = preset.name;
    const picture = preset.thumbnail ? `<img alt="" src="${path(preset.name)}/thumbnail.png">` : "<img alt=\"\">";
    row.innerHTML = `${picture}<span class="name"></span>
      <button class="fav" title="favourite (on the keys 1–9)">${preset.favourite ? "★" : "☆"}</button>
      <button class="play" title="play it in the player">▶</button>
      <button class="rename" title="rename">✎</button>
      <a class="export" title="download the preset file" download>⇩</a>
      <button class="delete remove" title="delete" aria-label="delete">✕</button>`;
    row.querySelector(".name")!.textContent = preset.name;
    const tags = document.createElement("div");
    tags.className = "tags";
    tags.textContent = preset.tags.join(", ");
    row.querySelector(".name")!.append(tags);
    (row.querySelector(".export") as HTMLAnchorElement).href = `${path(preset.name)}/file`;
    const on = (cls: string, action: () => Promise<unknown>) =>
      row.querySelector(`.${cls}`)!.addEventListener("click", () => void this.guard(action));
    on("fav", () => send("PATCH", path(preset.name), { favourite: !preset.favourite }));
    on("play", () => this.play(preset.name));
    on("rename", async () => {
      const name = prompt("new name", preset.name);
      if (name && name !== preset.name) await send("PATCH", path(preset.name), { name });
    });
    on("delete", async () => {
      if (confirm(`delete the preset ${preset.name}?`)) await send("DELETE", path(preset.name));
    });
    return row;
  }

  private async guard(action: () => Promise<unknown>): Promise<void> {
    try { await action(); } catch (error) { this.say(String((error as Error).message ?? error)); }
    await this.refresh();
  }

  private say(text: string): string {
    this.element.querySelector("#preset-status")!.textContent = text;
    return text;
  }

  private input(id: string): HTMLInputElement {
    return this.element.querySelector<HTMLInputElement>(`#${id}`)!;
  }

  private wire(): void {
    this.element.querySelector("#presets-close")!.addEventListener("click", () => this.toggle(false));
    this.element.querySelector("#preset-save")!.addEventListener("click", () => {
      const tags = this.input("preset-tags").value.split(",").map((t) => t.trim()).filter(Boolean);
      void this.save(this.input("preset-name").value.trim(), tags);
    });
    this.input("preset-search").addEventListener("input", () => void this.refresh());
    this.input("preset-favourites").addEventListener("change", () => void this.refresh());
    this.input("preset-import").addEventListener("change", async (e) => {
      const input = e.target as HTMLInputElement;
      for (const file of Array.from(input.files ?? [])) {
        await this.guard(async () => send("POST", "api/presets", JSON.parse(await file.text())));
      }
      input.value = "";
    });
  }
}

/** A small PNG of the canvas (the drawing buffer is kept: the viewer preserves it). */
export function thumbnailOf(canvas: HTMLCanvasElement | null, width = 192): string | null {
  if (!canvas || !canvas.width) return null;
  const small = document.createElement("canvas");
  small.width = width;
  small.height = Math.max(1, Math.round((width * canvas.height) / canvas.width));
  small.getContext("2d")?.drawImage(canvas, 0, 0, small.width, small.height);
  return small.toDataURL("image/png");
}
