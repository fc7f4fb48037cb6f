"""Live tempo against offline on real recordings (docs/design.md#live): each shared song (its
first --seconds, 30 by default) played through Chromium's fake microphone into the page; the
tempo the page's live tracker shows at the end beside the offline tempo of the same samples
(`Spectrogram.from_file`, librosa's default call), their ratio, and whether it is within 4%.

    EIGENDANCE_SHARED_DATA=/path/to/shared/data python benchmarks/bench_live_tempo.py
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
from shared_data import shared_path

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "tests", "web"))
from chromium import FAKE, GRANT, launch  # noqa: E402 - the tests' Chromium, found above


def clip_of(path: str, folder: str, seconds: float) -> str:
    """The song's first `seconds` as a 44.1 kHz WAV after half a second of silence."""
    samples, rate = read_audio(path)
    samples = mono(samples)[:int(seconds * rate)]
    samples = resample_poly(np.concatenate([np.zeros(rate // 2), samples]), 44100, rate)
    out = os.path.join(folder, os.path.basename(path) + ".wav")
    soundfile.write(out, samples, 44100, subtype="PCM_16")
    return out


def live_tempo(playwright, url: str, clip: str, heard: float) -> float:
    browser = launch(playwright.chromium, *FAKE, GRANT,
                     f"--use-file-for-fake-audio-capture={clip}%noloop")
    try:
        page = browser.new_page(viewport={"width": 800, "height": 600})
        page.goto(f"{url}?test&source=mic&size=1&scale=0.3")
        page.wait_for_function("window.eigendance && window.eigendance.ready", timeout=600_000)
        deadline = time.time() + heard + 60
        while time.time() < deadline:
            state = page.evaluate("window.eigendance.liveInput.state()")
            if state["seconds"] >= heard:
                break
            time.sleep(0.5)
        return float(state["tempo"])
    finally:
        browser.close()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=30.0)
    parser.add_argument("--port", type=int, default=8794)
    args = parser.parse_args()
    folder = shared_path("audio")
    names = sorted(n for n in os.listdir(folder) if n.endswith((".ogg", ".mp3")))
    work = tempfile.mkdtemp(prefix="bench-live-tempo-")
    cat, song = demo_paths()
    server = subprocess.Popen([sys.executable, "-m", "eigendance.cli", "serve", cat, song,
                               "--port", str(args.port)], stdout=subprocess.PIPE, text=True)
    print(f"{'recording':34s} {'s':>5s} {'offline':>8s} {'live':>7s} {'ratio':>6s} within 4%")
    try:
        url = server.stdout.readline().split()[-1]
        with sync_playwright() as playwright:
            for name in names:
                clip = clip_of(os.path.join(folder, name), work, args.seconds)
                duration = soundfile.info(clip).duration
                offline = Spectrogram.from_file(clip, bands=16).rhythm.tempo
                live = live_tempo(playwright, url, clip, duration - 0.7)
                ratio = live / offline if offline else float("nan")
                print(f"{name[:34]:34s} {duration:5.1f} {offline:8.1f} {live:7.1f} "
                      f"{ratio:6.3f} {'yes' if abs(ratio - 1) <= 0.04 else 'NO'}", flush=True)
    finally:
        server.terminate()
        server.wait(10)


if __name__ == "__main__":
    main()
