// Files the person gives the page: the *add* input and dropping anywhere. Each one is uploaded
// (the server checks it by its content) and becomes the current model, song, rig or player
// mapping.
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
  constructor(private readonly messages: Messages, private readonly events: FileEvents) {}

  /** Upload files one by one; each becomes the current mesh, song or player mapping. */
  async handle(files: FileList | File[]): Promise<void> {
    for (const file of Array.from(files)) {
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
      if (e.dataTransfer?.files.length) void this.handle(e.dataTransfer.files);
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
    messages.status(`${file.name} ready`);
    events.requestDraw();
  }
}

/** A server message without the file name it starts with (the page names the file itself). */
function withoutName(message: string, name: string): string {
  return message.startsWith(`${name}: `) ? message.slice(name.length + 2) : message;
}
