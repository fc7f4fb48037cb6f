// MIDI learn (Web MIDI; docs/design.md#show): right-click (or long-press) a slider, switch or
// button, then move a knob or hit a pad: that control follows it from then on. Mappings are
// kept in localStorage; right-clicking a mapped control clears its mapping. A MIDI message
// that does not parse is ignored with one line on the console.

const STORAGE = "eigendance.midi";
const LONG_PRESS_MS = 600;

/** What a MIDI message is, or null for one we do not use (clock, sysex …); throws for one
 * that is malformed. */
export function parseMidi(data: ArrayLike<number>): { key: string; value: number } | null {
  if (!data || data.length < 1) throw new Error("an empty MIDI message");
  const status = data[0];
  if (status < 0x80) throw new Error(`a MIDI message without a status byte (${status})`);
  const kind = status & 0xf0;
  const channel = status & 0x0f;
  if (kind !== 0xb0 && kind !== 0x90 && kind !== 0x80) return null;
  if (data.length < 3 || data[1] > 127 || data[2] > 127) {
    throw new Error(`a malformed MIDI message (${Array.from(data).join(" ")})`);
  }
  if (kind === 0xb0) return { key: `cc:${channel}:${data[1]}`, value: data[2] / 127 };
  // a note on with velocity 0 is a note off: buttons act on the press only
  return { key: `note:${channel}:${data[1]}`, value: kind === 0x90 && data[2] > 0 ? 1 : 0 };
}

export class MidiLearn {
  map: Record<string, string> = {};
  learning: HTMLElement | null = null;
  private pressed = new Set<string>();

  constructor() {
    try { this.map = JSON.parse(localStorage.getItem(STORAGE) ?? "{}"); } catch { this.map = {}; }
    document.addEventListener("contextmenu", (e) => {
      const control = learnable(e.target);
      if (!control) return;
      e.preventDefault();
      this.learn(control);
    });
    let timer = 0;
    document.addEventListener("pointerdown", (e) => {
      const control = learnable(e.target);
      if (control && e.pointerType === "touch") timer = window.setTimeout(() => this.learn(control), LONG_PRESS_MS);
    });
    document.addEventListener("pointerup", () => window.clearTimeout(timer));
    this.mark();
  }

  /** Ask the browser for MIDI inputs (none: MIDI learn waits, the rest works). */
  async start(): Promise<boolean> {
    const request = (navigator as Navigator & { requestMIDIAccess?: () => Promise<any> })
      .requestMIDIAccess;
    if (!request) return false;
    try {
      const access = await request.call(navigator);
      const bind = () => access.inputs.forEach((input: any) => {
        input.onmidimessage = (e: { data: Uint8Array }) => this.message(e.data);
      });
      bind();
      access.onstatechange = bind;
      return true;
    } catch (error) {
      console.warn(`eigendance: MIDI: ${String(error)}`);
      return false;
    }
  }

  /** Right-click on a control: learn it, or clear its mapping when it has one. */
  learn(control: HTMLElement): void {
    const mapped = Object.keys(this.map).filter((key) => this.map[key] === control.id);
    this.learning?.classList.remove("midi-learning");
    if (mapped.length || this.learning === control) {
      for (const key of mapped) delete this.map[key];
      this.learning = null;
      this.save();
      return;
    }
    this.learning = control;
    control.classList.add("midi-learning");
  }

  message(data: ArrayLike<number>): void {
    let parsed;
    try { parsed = parseMidi(data); } catch (error) {
      console.warn(`eigendance: MIDI: ${(error as Error).message}, ignored`);
      return;
    }
    if (!parsed) return;
    if (this.learning) {
      if (parsed.key.startsWith("note:") && parsed.value === 0) return; // the release of a pad
      this.map[parsed.key] = this.learning.id;
      this.learning.classList.remove("midi-learning");
      this.learning = null;
      this.save();
      return;
    }
    const id = this.map[parsed.key];
    const element = id ? document.getElementById(id) : null;
    if (element) this.apply(element, parsed.key, parsed.value);
  }

  private apply(element: HTMLElement, key: string, value: number): void {
    const press = value >= 0.5;
    const rising = press && !this.pressed.has(key);
    if (press) this.pressed.add(key); else this.pressed.delete(key);
    if (element instanceof HTMLInputElement && element.type === "range") {
      const low = Number(element.min || 0);
      const high = Number(element.max || 100);
      element.value = String(low + value * (high - low));
      element.dispatchEvent(new Event("input", { bubbles: true }));
    } else if (element instanceof HTMLInputElement && element.type === "checkbox") {
      if (rising) { element.checked = !element.checked; element.dispatchEvent(new Event("change")); }
    } else if (rising) {
      element.click();
    }
  }

  private save(): void {
    try { localStorage.setItem(STORAGE, JSON.stringify(this.map)); } catch { /* private mode */ }
    this.mark();
  }

  private mark(): void {
    const mapped = new Set(Object.values(this.map));
    document.querySelectorAll(".midi-mapped").forEach((e) => e.classList.remove("midi-mapped"));
    mapped.forEach((id) => document.getElementById(id)?.classList.add("midi-mapped"));
  }
}

function learnable(target: EventTarget | null): HTMLElement | null {
  const element = (target as HTMLElement | null)?.closest?.(
    "input[type=range], input[type=checkbox], button") as HTMLElement | null;
  return element && element.id ? element : null;
}
