// Show mode in the page (docs/design.md#show): /show starts the output page, any other path
// the studio with the show panel, the presets panel and MIDI learn.
import { App } from "./app";
import * as api from "./api";
import type { Options } from "./options";
import { PresetsPanel } from "./presets-panel";
import { ShowPanel, addShowKeysToHelp } from "./show-control";
import { MidiLearn } from "./show-midi";
import { ShowOutput, readOutputOptions } from "./show-output";
import type { ShowState } from "./show-timing";

declare global {
  interface Window { eigendanceShow?: { output?: ShowOutput; presets?: PresetsPanel;
    panel?: ShowPanel; midi?: MidiLearn }; }
}

export const isOutputPage = (pathname: string): boolean => /\/show\/?$/.test(pathname);

/** The output page: the App in the player, the current cue's model and song, no controls. */
export async function startOutput(options: Options,
                                  hooks: ((app: App, ready: Promise<void>) => void) | null) {
  const state = await api.getJSON<ShowState>("api/show/state");
  const cue = state.cue === null ? null : state.cues[state.cue];
  const app = new App({ ...options, size: null, view: "player", bare: true,
    scale: options.scale ?? 1, mesh: cue?.model.kind === "mesh" ? cue.model.id : options.mesh,
    song: cue?.song ?? options.song, source: cue?.live ?? options.source });
  const output = new ShowOutput(app, readOutputOptions(location.search));
  window.eigendanceShow = { output };
  const ready = app.start().then(async () => {
    if (cue?.model.kind === "rig") { await app.openRig(cue.model.id); app.setView("player"); }
    output.start(state);
  });
  if (hooks) hooks(app, ready);
}

/** The studio page's show parts. */
export function startControl(app: App): void {
  const panel = new ShowPanel();
  const presets = new PresetsPanel(app);
  const midi = new MidiLearn();
  window.eigendanceShow = { panel, presets, midi };
  addShowKeysToHelp();
  // the studio previews what the show plays: a new preset (a slot key, OSC) in its player
  panel.onPreset = (name) => { if (name) void presets.play(name).catch(() => {}); };
  void panel.start();
  void midi.start();
}
