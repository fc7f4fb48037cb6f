// What the page tells the person: the status line, errors (a red banner until closed), the
// loading indicator and the help. One place, so every part of the page says things the same
// way, and so a hint like "ready: press ▶" never stays on screen once the song plays.
import { $, messageOf } from "./dom";

const HELP_SEEN = "eigendance-help-seen";

export class Messages {
  /** a status shown only while the song is paused ("ready: press ▶ or space") */
  private pausedHint: string | null = null;

  /** A short line in the header (progress, "… ready"). */
  status(text: string): void {
    this.pausedHint = null;
    this.show(text);
  }

  /** A status that only makes sense while nothing plays: it goes when the song starts. */
  hint(text: string, playing: boolean): void {
    this.status(playing ? "" : text);
    this.pausedHint = playing ? null : text;
  }

  /** Playback started or stopped: a hint about pressing ▶ goes. */
  playing(on: boolean): void {
    if (on && this.pausedHint !== null && $("status").textContent === this.pausedHint) {
      this.status("");
    }
  }

  /** An error, shown in full (wrapped) until closed or replaced; Esc closes it. */
  error(text: string): void {
    $("error-text").textContent = text;
    $("error").hidden = false;
  }

  clearError(): void { $("error").hidden = true; }

  /** The error shown, or null. */
  shownError(): string | null {
    return $("error").hidden ? null : $("error-text").textContent;
  }

  /** The loading indicator: `text` with a progress bar (fraction, or null: indeterminate);
   * null hides it. */
  loading(text: string | null, fraction: number | null = null): void {
    $("loading").hidden = text === null;
    if (text === null) return;
    $("loading-text").textContent = text;
    const bar = $<HTMLProgressElement>("loading-progress");
    if (fraction === null) bar.removeAttribute("value"); else bar.value = fraction;
  }

  /** Run `task`; a failure (a server error, a file the browser cannot read) is shown as the
   * error `what: message` and returned, so the page stays usable and no promise is left
   * rejected. */
  async guard(what: string, task: () => Promise<void>): Promise<string | null> {
    try {
      await task();
      return null;
    } catch (error) {
      const message = `${what}: ${messageOf(error)}`;
      this.error(message);
      this.status("");
      return message;
    }
  }

  /** Show or hide the help; once closed it is not shown by itself again. */
  help(shown: boolean): void {
    $("help").hidden = !shown;
    if (!shown) {
      try { localStorage.setItem(HELP_SEEN, "1"); } catch { /* private mode: ask again */ }
    }
  }

  /** The help on a first visit (never in offline rendering or tests). */
  helpOnFirstVisit(): void {
    let seen: string | null = null;
    try { seen = localStorage.getItem(HELP_SEEN); } catch { /* private mode */ }
    if (!seen) this.help(true);
  }

  /** The close buttons of the help and the error banner. */
  wire(): void {
    $("help-button").addEventListener("click", () => this.help(true));
    $("help-close").addEventListener("click", () => this.help(false));
    $("help").addEventListener("click", (e) => {
      if (e.target === $("help")) this.help(false);
    });
    $("error-close").addEventListener("click", () => this.clearError());
  }

  private show(text: string): void {
    const line = $("status");
    line.textContent = text;
    line.title = text;
  }
}
