// The live input's test hooks (`window.eigendance.liveInput`, with `?test` or `?render` only):
// start and stop a source, what it heard (frames, onsets, beats, tempo), its bookkeeping and
// whether anything it opened is still running.
import type { App } from "./app";
import { LiveAnalyser } from "./live-analysis";
import type { LiveKind } from "./live-input";

export function liveHooks(app: App) {
  const live = app.live;
  return {
    /** Start a live input (resolves to false when it could not be opened: the error shown). */
    start: (kind: LiveKind = "mic", deviceId?: string) => app.startLive({ kind, deviceId }),
    /** Stop it and go back to the song. */
    stop: () => live.leave(),
    /** Save the take so far as a song (its id, or null with the error shown). */
    save: () => live.saveTake(),
    setOffset: (seconds: number) => live.setOffset(seconds),
    /** What the browser does when the input device goes away: its tracks fire "ended". */
    unplug: () => live.input?.mediaStream.getAudioTracks()
      .forEach((track) => track.dispatchEvent(new Event("ended"))),
    state: () => {
      const input = live.input;
      const take = input?.take.spectrum;
      return {
        active: live.active, name: input?.name ?? null, frames: take?.frames ?? 0,
        seconds: take?.duration ?? 0, tempo: take?.tempo ?? 0, estimate: input?.take.rhythm.tempo ?? 0,
        onsets: input ? [...input.take.rhythm.onsets] : [],
        beats: input ? [...input.take.rhythm.beats] : [],
        sampleRate: app.transport.audioContext.sampleRate,
        window: input ? new LiveAnalyser(app.transport.audioContext.sampleRate).N : 0,
        latency: input?.latency ?? 0, offset: input?.offset ?? 0, stats: input?.stats ?? null,
        info: document.getElementById("live-info")!.textContent,
        menu: (document.getElementById("song") as HTMLSelectElement).value,
        following: app.transport.following,
        /** inputs opened so far that still run, and tracks not ended */
        running: live.history.filter((i) => i.running).length,
        liveTracks: live.history.flatMap((i) => i.mediaStream.getTracks())
          .filter((t) => t.readyState !== "ended").length,
        opened: live.history.length,
        /** ms of the page's thread spent taking frames in */
        receiveMs: input?.receiveMs ?? 0,
      };
    },
    /** Band values of frames [from, to) (frames × bands). */
    values: (from = 0, to?: number): number[][] => {
      const take = live.input?.take.spectrum;
      if (!take) return [];
      const stop = Math.min(to ?? take.frames, take.frames);
      const out: number[][] = [];
      for (let j = from; j < stop; j++) {
        out.push(Array.from(take.values.subarray(j * take.bands, (j + 1) * take.bands)));
      }
      return out;
    },
    /** The onset strength of every frame so far (dB per frame). */
    onsetStrength: (): number[] => {
      const take = live.input?.take.spectrum;
      return take ? Array.from(take.onsetStrength.subarray(0, take.frames)) : [];
    },
    /** The live analysis's cost on this thread: ms per 128-sample block of `seconds` of noise
     * (the worklet runs the same code; `stats.busyMs` is its own measure where it has a clock). */
    timeAnalysis: (seconds = 10, sampleRate = 48000): number => {
      const analyser = new LiveAnalyser(sampleRate);
      const block = new Float32Array(128);
      const blocks = Math.round((seconds * sampleRate) / 128);
      let seed = 1;
      const start = performance.now();
      for (let i = 0; i < blocks; i++) {
        for (let n = 0; n < 128; n++) { seed = (seed * 16807) % 2147483647; block[n] = seed / 2147483647 - 0.5; }
        analyser.push(block);
      }
      return (performance.now() - start) / blocks;
    },
  };
}
