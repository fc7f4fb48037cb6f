// The live source in the page (docs/web.md#live-input): the song menu's *live input* entries
// (each microphone or line in, tab or system audio), starting and stopping a `LiveInput` so that
// one runs at a time and a song takes over cleanly, the live bar (what is heard, the tempo, the
// latency, the latency-offset slider remembered per device), the take's recording and *save
// take* (a song of the library).
import * as api from "./api";
import { $, fileName, messageOf, saveBlob } from "./dom";
import { LiveInput, audioInputs, offersTabAudio } from "./live-input";
import type { LiveChoice } from "./live-input";
import type { Motion } from "./motion";
import type { AudioTransport } from "./transport";

/** The song menu's values for live entries: `live:mic`, `live:mic:DEVICE`, `live:tab`. */
export const LIVE_PREFIX = "live:";
const OFFSET_KEY = "eigendance.latency-offset.";

/** What the live source needs of the page. */
export interface LiveHost {
  transport: AudioTransport;
  motion: Motion;
  /** show an error (one line) / a status line */
  error: (text: string) => void;
  status: (text: string) => void;
  /** back to the library's current song (its spectrogram and sound) */
  restoreSong: () => Promise<void>;
  /** a take saved as a song: refresh the menus */
  songAdded: (id: string) => Promise<void>;
  requestDraw: () => void;
  /** the frame rate drawn now (for the latency shown) */
  fps: () => number;
}

/** The choice a song-menu value names, or null for a song. */
export function choiceOf(value: string): LiveChoice | null {
  if (!value.startsWith(LIVE_PREFIX)) return null;
  const [kind, ...device] = value.slice(LIVE_PREFIX.length).split(":");
  if (kind === "tab") return { kind: "tab" };
  return device.length ? { kind: "mic", deviceId: device.join(":") } : { kind: "mic" };
}

export class LiveSource {
  input: LiveInput | null = null;
  /** inputs opened and let go, for the tests' "nothing left running" */
  readonly history: LiveInput[] = [];
  private recorder: MediaRecorder | null = null;
  private chunks: Blob[] = [];
  private devices: MediaDeviceInfo[] = [];
  /** whether the input was heard playing at the last refresh (▶ / ❚❚ follows it) */
  private wasPlaying = false;

  constructor(private readonly host: LiveHost) {
    const slider = $<HTMLInputElement>("live-offset");
    slider.addEventListener("input", () => this.setOffset(Number(slider.value) / 1000));
    $("live-save").addEventListener("click", () => void this.saveTake());
    navigator.mediaDevices?.addEventListener?.("devicechange", () => void this.listDevices());
  }

  get active(): boolean { return this.input?.running ?? false; }

  /** The song menu's *live input* group: every audio input (labels once allowed), tab audio
   * where the browser offers it. */
  fillMenu(menu: HTMLSelectElement): void {
    menu.querySelector("optgroup.live")?.remove();
    const group = document.createElement("optgroup");
    group.label = "live input";
    group.className = "live";
    const named = this.devices.filter((d) => d.label && d.deviceId && d.deviceId !== "default");
    group.appendChild(new Option("microphone or line in (default input)", `${LIVE_PREFIX}mic`));
    for (const device of named) {
      group.appendChild(new Option(`input: ${device.label}`,
        `${LIVE_PREFIX}mic:${device.deviceId}`));
    }
    if (offersTabAudio()) group.appendChild(new Option("tab or system audio", `${LIVE_PREFIX}tab`));
    menu.appendChild(group);
    if (!this.input) return;
    menu.value = this.menuValue(this.input.choice);
    // the menu names what plays, as it names a song (the live bar beside it: tempo, latency)
    const chosen = menu.selectedOptions[0];
    if (chosen) chosen.textContent = `● ${this.input.name}`;
  }

  async listDevices(): Promise<void> {
    try { this.devices = await audioInputs(); } catch { this.devices = []; }
    this.fillMenu($<HTMLSelectElement>("song"));
  }

  /** Start `choice` (stopping any input first). False, with one clear message, when it could
   * not be opened: the page goes on with the song. */
  async start(choice: LiveChoice): Promise<boolean> {
    this.stop();
    const { transport, motion } = this.host;
    let input: LiveInput;
    try {
      input = await LiveInput.open(transport.audioContext, transport.input, choice);
    } catch (error) {
      this.host.error(messageOf(error));
      await this.host.restoreSong();
      return false;
    }
    this.input = input;
    this.history.push(input);
    input.offset = this.rememberedOffset(input.deviceKey);
    input.onEnded = (message) => {
      this.host.error(message);
      void this.leave();
    };
    input.onFrames = () => this.host.requestDraw();
    motion.setSpectrum(input.take.spectrum);
    transport.follow(input);
    this.record(input);
    const slider = $<HTMLInputElement>("live-offset");
    slider.value = String(Math.round(input.offset * 1000));
    $("live-bar").hidden = false;
    $<HTMLInputElement>("seek").disabled = true;
    document.body.classList.add("live");
    void this.awaitGesture();
    await this.listDevices(); // labels come with the permission
    this.host.status(`live: ${input.name}`);
    this.host.requestDraw();
    return true;
  }

  /** Let the input go (nothing keeps running) and hide the live bar; the caller loads a song. */
  stop(): void {
    if (this.recorder && this.recorder.state !== "inactive") this.recorder.stop();
    this.recorder = null;
    if (!this.input) return;
    this.input.stop();
    this.input = null;
    this.wasPlaying = false;
    this.host.transport.follow(null);
    $("live-bar").hidden = true;
    $<HTMLInputElement>("seek").disabled = false;
    document.body.classList.remove("live");
  }

  /** Stop, and play the library's song again. */
  async leave(): Promise<void> {
    this.stop();
    await this.host.restoreSong();
  }

  /** The live bar's line: what is heard, the tempo ("NNN BPM"), the latency (input to motion:
   * the input's own, the analysis, the offset and one drawn frame). */
  refresh(): void {
    const input = this.input;
    if (!input) return;
    if (input.playing !== this.wasPlaying) { // the context started (or was suspended)
      this.wasPlaying = input.playing;
      this.host.transport.onChange(input.playing);
    }
    const take = input.take.spectrum;
    const tempo = take.tempo > 0 ? `${take.tempo.toFixed(0)} BPM` : "no beat";
    const frame = this.host.fps() > 0 ? 1 / this.host.fps() : 0;
    const latency = input.latency + frame;
    const silent = input.stats.firstSound < 0 && input.stats.samples > input.take.spectrum.rate;
    const dropouts = input.stats.dropouts ? `; ${input.stats.dropouts} dropouts: the input fell `
      + "behind and gave silence (a busy machine or device)" : "";
    // one width in the header's row (style.css): the input's name is in the song menu, the
    // breakdown and any dropouts in the tooltip (dropouts underline the readout)
    const info = $("live-info");
    info.textContent = `● ${silent ? "silent" : tempo} · latency ${(latency * 1000)
      .toFixed(0)} ms`;
    info.classList.toggle("warn", silent);
    info.classList.toggle("dropouts", dropouts !== "");
    info.title = `${input.name}: input ${(input.inputLatency * 1000).toFixed(0)} ms + analysis `
      + `${(input.analysisDelay * 1000).toFixed(0)} ms + offset ${(input.offset * 1000)
        .toFixed(0)} ms + one frame ${(frame * 1000).toFixed(0)} ms; ${take.duration.toFixed(1)} s `
      + `heard${silent ? " (no sound yet)" : ""}${dropouts}`;
    $("live-offset-out").textContent = `${(input.offset * 1000).toFixed(0)} ms`;
  }

  /** The latency offset (s ≥ 0), remembered for this device. */
  setOffset(seconds: number): void {
    const input = this.input;
    if (!input) return;
    input.offset = Math.max(0, Math.min(0.5, seconds));
    try { localStorage.setItem(OFFSET_KEY + input.deviceKey, String(input.offset)); } catch { /* private mode */ }
    this.refresh();
  }

  /** The take so far: downloaded at once (`live-take-DATE-TIME.webm`), and kept as a song of
   * the library (the server checks and analyses it as any upload: about a tenth of the take's
   * length on two busy cores, so the status counts the seconds). */
  async saveTake(): Promise<string | null> {
    const input = this.input;
    if (!input || !this.recorder) {
      this.host.error("Live input: there is no take to save (choose a live input first)");
      return null;
    }
    let ticker = 0;
    try {
      await new Promise<void>((resolve) => {
        this.recorder!.addEventListener("dataavailable", () => resolve(), { once: true });
        this.recorder!.requestData();
      });
      const type = this.recorder.mimeType || "audio/webm";
      const stamp = new Date().toISOString().slice(0, 19).replace("T", " ").replace(/:/g, "-");
      const suffix = type.includes("ogg") ? "ogg" : "webm";
      const name = `live take ${stamp}.${suffix}`;
      const file = fileName("live take", stamp, suffix);
      const audio = new Blob(this.chunks, { type });
      saveBlob(audio, file);
      const started = performance.now();
      const say = () => this.host.status(`${file} downloaded; analysing it for the song menu… `
        + `${((performance.now() - started) / 1000).toFixed(0)} s`);
      say();
      ticker = window.setInterval(say, 1000);
      const reply = await api.saveTake(audio, name);
      window.clearInterval(ticker);
      await this.host.songAdded(reply.item.id);
      this.host.status(`${file} downloaded; “${name}” is in the song menu`);
      return reply.item.id;
    } catch (error) {
      this.host.error(`Live input: the take could not be saved (${messageOf(error)})`);
      return null;
    } finally {
      window.clearInterval(ticker);
    }
  }

  /** A browser that starts sound only after a gesture (`?source=mic` at load) keeps the
   * AudioContext suspended: say so, and start listening at the first click or key. */
  private async awaitGesture(): Promise<void> {
    const context = this.host.transport.audioContext;
    await Promise.race([context.resume(), new Promise((done) => setTimeout(done, 300))]);
    if (context.state === "running" || !this.input) return;
    this.host.status("live: click the page or press a key to start listening");
    const resume = () => {
      void context.resume().then(() => { if (this.input) this.host.status(`live: ${this.input.name}`); });
    };
    document.addEventListener("pointerdown", resume, { once: true });
    document.addEventListener("keydown", resume, { once: true });
  }

  private record(input: LiveInput): void {
    this.chunks = [];
    if (typeof MediaRecorder === "undefined") return;
    const type = ["audio/webm;codecs=opus", "audio/ogg;codecs=opus", "audio/webm"]
      .find((t) => MediaRecorder.isTypeSupported(t));
    try {
      this.recorder = new MediaRecorder(input.mediaStream, type ? { mimeType: type } : undefined);
      this.recorder.addEventListener("dataavailable", (e) => { if (e.data.size) this.chunks.push(e.data); });
      this.recorder.start(1000);
    } catch {
      this.recorder = null; // the take is still analysed; *save take* says there is none
    }
  }

  private rememberedOffset(device: string): number {
    try {
      const value = Number(localStorage.getItem(OFFSET_KEY + device));
      return Number.isFinite(value) ? Math.max(0, Math.min(0.5, value)) : 0;
    } catch {
      return 0;
    }
  }

  private menuValue(choice: LiveChoice): string {
    return choice.kind === "tab" ? `${LIVE_PREFIX}tab`
      : `${LIVE_PREFIX}mic${choice.deviceId ? `:${choice.deviceId}` : ""}`;
  }
}
