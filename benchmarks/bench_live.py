"""Live input benchmark (docs/design.md#live): what the live analysis costs and what it does to
the page's frame rate, in headless Chromium without a GPU.

- The analysis per 128-sample block (the AudioWorklet's quantum): the page's own code
  (web/src/live-analysis.ts, the code the worklet runs) timed on the page's thread over 10 s
  of noise at 44.1, 48 and 96 kHz, against the block's real-time budget (128/sr) and beside the
  offline reference (`eigendance.music.spectrogram` with the rhythm's envelope, numpy and scipy,
  per 128 samples of a 60-s analysis) measured in the same run. (Chromium gives an AudioWorklet
  no clock finer than a millisecond, so the worklet's own share is measured through the same
  code on the page's thread.)
- Frames drawn per second in the gallery with the song playing, then with the live input (the
  fake microphone playing a real clip), same page, same tiles, same render scale.

    python benchmarks/bench_live.py [-S 8] [--seconds 6] [--scale 0.5]
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import time

import numpy as np
import soundfile
from playwright.sync_api import sync_playwright
from scipy.signal import resample_poly

from eigendance.music.decode import mono, read_audio
from eigendance.music.spectrogram import Spectrogram
from eigendance.server.serve import demo_paths

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "tests", "web"))
from chromium import FAKE, GRANT, launch  # noqa: E402 - the tests' Chromium, found above

HERE = os.path.dirname(os.path.abspath(__file__))
CLIP = os.path.join(HERE, "..", "tests", "fixtures", "audio", "kevin_macleod_vibe_ace_0s-21s.ogg")
RATES = (44100, 48000, 96000)


def offline_per_block(rate: int, seconds: float = 60.0) -> float:
    """ms of the offline analysis (spectrogram and onset envelope) per 128 samples."""
    noise = np.random.default_rng(0).uniform(-0.5, 0.5, int(seconds * rate))
    Spectrogram.from_samples(noise[:rate], rate)  # warm (librosa's mel bank, numba)
    started = time.perf_counter()
    Spectrogram.from_samples(noise, rate)
    return 1000 * (time.perf_counter() - started) / (len(noise) / 128)


def fake_clip(folder: str) -> str:
    samples, sample_rate = read_audio(CLIP)
    path = os.path.join(folder, "clip.wav")
    soundfile.write(path, resample_poly(mono(samples), 44100, sample_rate), 44100,
                    subtype="PCM_16")
    return path


def fps_for(page, seconds: float) -> float:
    """Frames the page drew per second over `seconds` of wall time."""
    before = page.evaluate("window.eigendance.info().frames")
    started = time.time()
    page.wait_for_timeout(seconds * 1000)
    return (page.evaluate("window.eigendance.info().frames") - before) / (time.time() - started)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("-S", "--size", type=int, default=8)
    parser.add_argument("--seconds", type=float, default=6.0)
    parser.add_argument("--scale", type=float, default=0.5, help="fixed render scale")
    parser.add_argument("--port", type=int, default=8793)
    args = parser.parse_args()
    print(f"load {', '.join(f'{x:.1f}' for x in os.getloadavg())} (2 cores, shared host)")
    cat, song = demo_paths()
    folder = tempfile.mkdtemp(prefix="bench-live-")
    clip = fake_clip(folder)
    server = subprocess.Popen([sys.executable, "-m", "eigendance.cli", "serve", cat, song,
                               "--port", str(args.port)], stdout=subprocess.PIPE, text=True)
    try:
        url = server.stdout.readline().split()[-1]
        with sync_playwright() as playwright:
            browser = launch(playwright.chromium, *FAKE, GRANT,
                             f"--use-file-for-fake-audio-capture={clip}")
            page = browser.new_page(viewport={"width": 1280, "height": 800})
            page.goto(f"{url}?test&size={args.size}&scale={args.scale}")
            page.wait_for_function("window.eigendance && window.eigendance.ready", timeout=600_000)
            page.evaluate("window.eigendance.ready")
            print("analysis per 128-sample block (ms): live (page thread) | offline numpy | "
                  "real-time budget")
            for rate in RATES:
                live = min(page.evaluate(f"window.eigendance.liveInput.timeAnalysis(10, {rate})")
                           for _ in range(3))
                print(f"  {rate / 1000:5.1f} kHz: {live:.4f} | {offline_per_block(rate):.4f} | "
                      f"{1000 * 128 / rate:.2f}  ({100 * live / (1000 * 128 / rate):.1f}% of "
                      "the budget)")
            page.click("#play")
            page.wait_for_timeout(1500)
            song_fps = fps_for(page, args.seconds)
            page.evaluate("window.eigendance.liveInput.start('mic')")
            page.wait_for_timeout(1500)
            live_fps = fps_for(page, args.seconds)
            state = page.evaluate("window.eigendance.liveInput.state()")
            page.evaluate("window.eigendance.liveInput.stop()")
            page.click("#play")
            page.wait_for_timeout(1500)
            after_fps = fps_for(page, args.seconds)
            print(f"gallery of {args.size} tiles at render scale {args.scale}: {song_fps:.1f} fps "
                  f"with the song, {live_fps:.1f} fps with the live input, {after_fps:.1f} fps "
                  "with the song again "
                  f"({state['seconds']:.1f} s heard, {state['stats']['dropouts']} dropouts, "
                  f"taking frames in: {state['receiveMs'] / state['seconds']:.1f} ms per s "
                  "on the page's thread, "
                  f"latency shown {state['info'].split('latency')[-1].split('·')[0].strip()})")
            browser.close()
    finally:
        server.terminate()
        server.wait(10)
    print(f"load {', '.join(f'{x:.1f}' for x in os.getloadavg())}")


if __name__ == "__main__":
    main()
