// The control page's show panel (docs/design.md#show): the set's cues with the current and the
// next, next / previous, loop, blackout, tap tempo, gain and fade, preset slots 1–9. Every
// control goes to the server (`POST api/show/control`), which the output page (/show, here or
// in another browser) follows; the panel follows the server too.
import * as api from "./api";
import { addKeysToHelp, forThePage, keyName } from "./keys";
import type { KeyRow } from "./keys";
import type { ShowState } from "./show-timing";

/** The performer's keys (as keys.ts's rows) and the control each sends ("slot": the key's
 * number; "output": the output page opens); the help lists them. They leave the page's own
 * keys alone (keys.ts; test/keys.test.ts). */
export const SHOW_KEYS: readonly (readonly [...KeyRow, string])[] = [
  [["PageDown", "."], "next cue", "next"], [["PageUp", ","], "previous cue", "prev"],
  [["1", "2", "3", "4", "5", "6", "7", "8", "9"], "preset slots 1–9", "slot"],
  [["t"], "tap tempo (the show's beats)", "tap"], [["a"], "auto: the song's own beats again", "auto"],
  [["k"], "blackout", "blackout"], [["c"], "loop this cue", "loop_cue"],
  [["o"], "the output page (/show)", "output"],
];

export async function control(action: string, value?: unknown): Promise<ShowState | null> {
  try {
    return await api.postJSON<ShowState>("api/show/control", { action, value });
  } catch (error) {
    console.warn(`eigendance show: ${action}: ${String(error)}`);
    return null;
  }
}

export class ShowPanel {
  readonly element: HTMLElement;
  state: ShowState | null = null;
  /** the show's preset changed (a slot key, OSC, another page) */
  onPreset: (name: string | null) => void = () => {};

  constructor() {
    this.element = document.createElement("aside");
    this.element.id = "show-panel";
    this.element.hidden = true;
    this.element.innerHTML = `
      <div class="row"><strong id="show-set">show</strong>
        <a id="show-output" href="show" target="eigendance-show" title="the output page for the projector (O)">output ↗</a></div>
      <ol id="show-cues"></ol>
      <div class="row">
        <button id="show-prev" title="previous cue (PageUp or ,)">◀ cue</button>
        <button id="show-next" title="next cue, on the next downbeat (PageDown or .)">cue ▶</button>
        <button id="show-loop-cue" title="stay on this cue when it ends (C)">loop cue</button>
        <button id="show-loop-set" title="after the last cue, the first again">loop set</button>
      </div>
      <div class="row">
        <button id="show-play" title="play / stop the show">▶ play</button>
        <button id="show-blackout" title="black output (K)">blackout</button>
        <button id="show-tap" title="tap the tempo: the show's beats, from the first tap's downbeat (T)">tap</button>
        <button id="show-auto" title="the song's own beats again, after tapping (A)">auto</button><span id="show-tempo"></span>
      </div>
      <div class="row"><label title="the show's gain: how far every dance moves">gain
        <input id="show-gain" type="range" min="0" max="4" step="0.01" value="1"></label>
        <label title="crossfade of a change, beats">fade
        <input id="show-fade" type="number" min="0" max="64" step="1" value="4" style="width:4em"></label></div>`;
    document.body.append(this.element);
    this.wire();
  }

  /** Follow the server's state (events), and show the panel when the server has a set. */
  async start(): Promise<void> {
    try {
      this.render(await api.getJSON<ShowState>("api/show/state"));
    } catch { return; /* an older server: no show */ }
    const events = new EventSource("api/show/events");
    events.onmessage = (e) => this.render(JSON.parse(e.data) as ShowState);
    window.addEventListener("keydown", (e) => this.key(e));
  }

  render(state: ShowState): void {
    const before = this.state;
    this.state = state;
    if (before && before.preset !== state.preset) this.onPreset(state.preset);
    this.element.hidden = state.set === null;
    const byId = (id: string) => document.getElementById(id)!;
    byId("show-set").textContent = state.set ?? "show";
    const list = byId("show-cues");
    list.replaceChildren(...state.cues.map((cue, index) => {
      const item = document.createElement("li");
      const length = cue.until === "bars" ? `${cue.bars} bars` : cue.until === "section"
        ? "to the next section" : "until told";
      item.textContent = `${cue.name} · ${cue.preset ?? "first tile"} · ${length}${cue.loop ? " · loop" : ""}`;
      item.classList.toggle("current", index === state.cue);
      item.classList.toggle("next", index === state.next);
      item.addEventListener("click", () => void control("cue", index));
      return item;
    }));
    byId("show-loop-cue").classList.toggle("active", state.loop_cue === true);
    byId("show-loop-set").classList.toggle("active", state.loop_set);
    byId("show-blackout").classList.toggle("active", state.blackout);
    byId("show-play").textContent = state.playing ? "■ stop" : "▶ play";
    byId("show-tempo").textContent = state.tempo
      ? `${state.tempo.toFixed(1)} BPM${state.grid ? ` · ${state.grid.source}` : ""}` : "";
    byId("show-auto").classList.toggle("active", state.grid === null);
    const gain = byId("show-gain") as HTMLInputElement;
    if (document.activeElement !== gain) gain.value = String(state.gain);
    const fade = byId("show-fade") as HTMLInputElement;
    if (document.activeElement !== fade) fade.value = String(state.fade_beats);
  }

  private wire(): void {
    const click = (id: string, action: () => void) =>
      this.element.querySelector(`#${id}`)!.addEventListener("click", action);
    click("show-prev", () => void control("prev"));
    click("show-next", () => void control("next"));
    click("show-loop-cue", () => void control("loop_cue"));
    click("show-loop-set", () => void control("loop_set"));
    click("show-blackout", () => void control("blackout"));
    click("show-tap", () => void control("tap"));
    click("show-auto", () => void control("auto"));
    click("show-play", () => void control(this.state?.playing ? "stop" : "play"));
    const gain = this.element.querySelector<HTMLInputElement>("#show-gain")!;
    gain.addEventListener("input", () => void control("gain", Number(gain.value)));
    const fade = this.element.querySelector<HTMLInputElement>("#show-fade")!;
    fade.addEventListener("change", () => void control("fade", Number(fade.value)));
  }

  /** The performer's keys (not while typing, not with a modifier). */
  private key(e: KeyboardEvent): void {
    if (!forThePage(e)) return;
    const key = keyName(e);
    const action = SHOW_KEYS.find(([keys]) => keys.includes(key))?.[2];
    if (!action) return;
    e.preventDefault();
    if (action === "output") window.open("show", "eigendance-show");
    else void control(action, action === "slot" ? Number(key) : undefined);
  }
}

/** The show's keys as rows of the help's table. */
export function addShowKeysToHelp(): void {
  addKeysToHelp(SHOW_KEYS.map(([keys, what]) => [keys, what] as const));
}
