// Files the person gives the page: the *add* input and dropping anywhere (files or folders).
// Each one is uploaded (the server checks it by its content) and becomes the current model,
// song, rig or player mapping. A model in several files — a .gltf with its .bin and textures, an
// OBJ with its MTL and images — goes as one .zip (docs/web.md#http-api), read by the server like
// a single .glb.
import { zipSync } from "three/examples/jsm/libs/fflate.module.js";
import * as api from "./api";
import { $, messageOf } from "./dom";
import type { Mapping } from "./filter";
import type { Messages } from "./messages";

/** What an upload leads to, by its kind. */
export interface FileEvents {
  /** the library's items after the upload; false while it still lacks a model or a song */
  refresh(): Promise<void>;
  /** whether the page has started (a first gallery was asked for) */
  started(): boolean;
  /** start the page if the library is now complete; false if not */
  startIfComplete(): Promise<boolean>;
  /** each returns the failure already shown, or null */
  openRig(id: string): Promise<string | null>;
  showMesh(id: string): Promise<string | null>;
  changeSong(id: string): Promise<void>;
  openMapping(id: string, mapping: Mapping, name: string): void;
  requestDraw(): void;
}

export class FileIntake {
  /** the server's suffixes (`api/config`), once read; null until then or if it failed */
  suffixes: Suffixes | null = null;

  constructor(private readonly messages: Messages, private readonly events: FileEvents) {}

  /** Upload files one by one; each becomes the current mesh, song or player mapping. A model
   * with the files it names (`paths`: where each file lies in a dropped folder) goes as one
   * zip. */
  async handle(files: FileList | File[], paths?: string[]): Promise<void> {
    for (const file of await together(Array.from(files), this.suffixes, paths)) {
      try {
        await this.add(file);
      } catch (error) {
        this.messages.status("");
        this.messages.error(`${file.name} could not be added: `
          + withoutName(messageOf(error), file.name));
      }
    }
  }

  /** The *add file* input, and dropping anywhere on the page. */
  wire(): void {
    $("upload").addEventListener("change", (e) => {
      const input = e.target as HTMLInputElement;
      if (input.files) void this.handle(Array.from(input.files));
      input.value = "";
    });
    const drop = $("drop");
    window.addEventListener("dragover", (e) => { e.preventDefault(); drop.hidden = false; });
    drop.addEventListener("dragleave", () => { drop.hidden = true; });
    window.addEventListener("drop", (e) => {
      e.preventDefault();
      drop.hidden = true;
      if (!e.dataTransfer?.files.length) return;
      const entries = Array.from(e.dataTransfer.items ?? [], (item) => item.webkitGetAsEntry?.());
      if (entries.some((entry) => entry?.isDirectory)) { // a folder: every file in it
        void filesIn(entries.filter((entry): entry is FileSystemEntry => Boolean(entry)))
          .then((found) => this.handle(found.map((f) => f.file), found.map((f) => f.path)));
      } else {
        void this.handle(e.dataTransfer.files);
      }
    });
  }

  private async add(file: File): Promise<void> {
    const { messages, events } = this;
    messages.status(`adding ${file.name}…`);
    messages.loading(`${file.name}: uploading…`);
    const result = await api.upload(file).finally(() => messages.loading(null));
    await events.refresh();
    if (!events.started()) { // the library was incomplete: this file may complete it
      if (await events.startIfComplete()) messages.status(`${file.name} ready`);
      return;
    }
    if (result.kind === "rig" || result.rig) { // a skeleton, or a glTF with a skin
      if (await events.openRig(result.kind === "rig" ? result.item.id : result.rig.id)) return;
    } else if (result.kind === "mesh") {
      if (await events.showMesh(result.item.id)) return; // failed: said why
    } else if (result.kind === "song") {
      await events.changeSong(result.item.id);
    } else if (result.kind === "mapping") {
      $<HTMLSelectElement>("mapping-menu").value = result.item.id;
      events.openMapping(result.item.id,
        await api.getJSON<Mapping>(`api/mappings/${result.item.id}`), file.name);
    }
    // The model's own name: files given together went as one .zip named after the model file.
    messages.status(`${result.item?.name ?? file.name} ready`);
    events.requestDraw();
  }
}

/** A server message without the file name it starts with (the page names the file itself). */
function withoutName(message: string, name: string): string {
  return message.startsWith(`${name}: `) ? message.slice(name.length + 2) : message;
}

/** The suffixes of each input kind the server accepts, as `GET api/config` announces them
 * (`eigendance.inputs.model.published_suffixes`): the page keeps no copy of its own. */
export interface Suffixes {
  mesh: string[];
  rig: string[];
  audio: string[];
  mapping: string[];
  archive: string[];
  /** the files a model names beside it (glTF buffers and images, an OBJ's MTL and maps) */
  companion: string[];
}

/** The server's suffixes from its `api/config` answer; null when it holds none that fit. */
export function suffixesOf(config: unknown): Suffixes | null {
  const found = (config as { suffixes?: Record<string, unknown> } | null)?.suffixes;
  const kinds = ["mesh", "rig", "audio", "mapping", "archive", "companion"] as const;
  const lists = (value: unknown): value is string[] =>
    Array.isArray(value) && value.every((item) => typeof item === "string");
  return found && kinds.every((kind) => lists(found[kind])) ? found as unknown as Suffixes : null;
}

function suffixOf(name: string): string {
  const dot = name.lastIndexOf(".");
  return dot < 0 ? "" : name.slice(dot).toLowerCase();
}

/** The uploads of some files: a model's files (a model and what it names: buffers, MTLs,
 * images) as one zip named after the model, each other file by itself. Without the server's
 * suffixes (`api/config` failed), each file by itself: the server says what it refuses. */
export async function together(files: File[], suffixes: Suffixes | null,
    paths?: string[]): Promise<File[]> {
  if (suffixes === null) return files;
  const isModel = (file: File) => suffixes.mesh.includes(suffixOf(file.name));
  const isCompanion = (file: File) => suffixes.companion.includes(suffixOf(file.name));
  const models = files.filter(isModel), companions = files.filter(isCompanion);
  if (!models.length || !companions.length) return files; // the server says what it refuses
  const members: Record<string, Uint8Array> = {};
  for (const [index, file] of files.entries()) {
    if (!isModel(file) && !isCompanion(file)) continue;
    const path = (paths?.[index] ?? file.name).replace(/^\/+/, "");
    members[path] = new Uint8Array(await file.arrayBuffer());
  }
  const name = models[0].name.replace(/\.[^.]*$/, "") + ".zip";
  const zipped = zipSync(members, { level: 0 }); // stored: images and buffers barely shrink
  return [new File([zipped], name, { type: "application/zip" }),
    ...files.filter((file) => !isModel(file) && !isCompanion(file))];
}

/** Every file under dropped entries (folders read through), with its path in the drop. */
async function filesIn(entries: FileSystemEntry[]): Promise<{ file: File; path: string }[]> {
  const found: { file: File; path: string }[] = [];
  const visit = async (entry: FileSystemEntry): Promise<void> => {
    if (entry.isFile) {
      const file = await new Promise<File>((resolve, reject) =>
        (entry as FileSystemFileEntry).file(resolve, reject));
      found.push({ file, path: entry.fullPath });
    } else if (entry.isDirectory) {
      const reader = (entry as FileSystemDirectoryEntry).createReader();
      for (;;) { // readEntries answers in batches until an empty one
        const batch = await new Promise<FileSystemEntry[]>((resolve, reject) =>
          reader.readEntries(resolve, reject));
        if (!batch.length) break;
        for (const child of batch) await visit(child);
      }
    }
  };
  for (const entry of entries) await visit(entry);
  return found;
}
