"""Export benchmark: videos against real time, and the glb against a point cache.

1. `render_video` (offscreen OpenGL on llvmpipe + the imageio-ffmpeg encoder) of the demo (the cat,
   k = 150, the demo music) and of the bunny (k = 300) at 1280×720, 30 fps: seconds of video per
   second of wall time (≥ 1× for the demo and ≥ 0.5× for the bunny are the targets), beside the
   other renderer measured in the same run: the app's own page in headless Chromium (`?render`,
   SwiftShader), drawing each frame with `renderAt(t)` and grabbing it as a screenshot (frames
   only, no encoding: a lower bound of its cost). The machine is shared: the CPU time per frame
   (this process, its render workers and the encoder) also gives the speed two idle cores allow.
2. The bunny's glb (morph targets) with a 3-minute song against the same motion as a point cache
   (.pc2 size: 32 + frames × vertices × 12 bytes); the target is ≥ 20× smaller.

Not run by CI.

    python benchmarks/bench_render.py [--seconds 20] [--chromium-frames 30] [--no-chromium]
"""

from __future__ import annotations

import argparse
import os
import resource
import subprocess
import sys
import tempfile
import time

from shared_data import shared_path

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "tests", "web"))
from chromium import launch  # noqa: E402 - the tests' Chromium, found above

BUNNY = shared_path("meshes", "bunny_stanford.obj")
WIDTH, HEIGHT, FPS = 1280, 720, 30.0


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=20.0, help="song length for videos")
    parser.add_argument("--chromium-frames", type=int, default=30)
    parser.add_argument("--no-chromium", action="store_true")
    parser.add_argument("--port", type=int, default=8793)
    args = parser.parse_args()

    from importlib.resources import files

    from eigendance.export.dance import HarmonicDance
    from eigendance.export.files import export_dance
    from eigendance.export.renderer import Look
    from eigendance.export.video import render_video
    from eigendance.harmonic.basis import HarmonicBasis
    from eigendance.music.demo_music import write_demo_wav
    from eigendance.music.gallery import initial_gallery, strongest_item
    from eigendance.music.spectrogram import Spectrogram

    folder = tempfile.mkdtemp(prefix="bench-render-")
    song = os.path.join(folder, "demo.wav")
    write_demo_wav(song, duration=args.seconds)
    spectrogram = Spectrogram.from_file(song)
    cat = os.fspath(files("eigendance") / "data" / "cat_lowres.obj")
    models = {"demo (cat, k = 150)": (cat, 150), "bunny (k = 300)": (BUNNY, 300)}
    targets = {"demo (cat, k = 150)": 1.0, "bunny (k = 300)": 0.5}

    print(f"videos: {WIDTH}x{HEIGHT}, {FPS:g} fps, {args.seconds:g} s of the demo music "
          f"(cpu count {os.cpu_count()})")
    for name, (mesh, k) in models.items():
        basis = HarmonicBasis.from_mesh(mesh, k)  # cached after the first run
        dance = HarmonicDance(basis, spectrogram, strongest_item(basis, spectrogram), song)
        path = os.path.join(folder, "video.mp4")
        cpu_before = cpu_seconds()
        start = time.perf_counter()
        report = render_video(path, [dance], [Look()], song, FPS, (WIDTH, HEIGHT), force=True)
        seconds = time.perf_counter() - start
        cpu = cpu_seconds() - cpu_before
        speed = report["duration"] / seconds
        idle = report["duration"] / (cpu / 2)  # all of it spread over two free cores
        chromium = "" if args.no_chromium else \
            f"; the page in Chromium: {page_speed(mesh, k, song, args):.2f}× (frames only)"
        print(f"  {name:<20} n = {basis.n:>6}: {report['frames']} frames in {seconds:.1f} s = "
              f"{speed:.2f}× real time (target ≥ {targets[name]:g}×){chromium}")
        print(f"  {'':<20} CPU {cpu / report['frames'] * 1000:.0f} ms per frame (drawing, "
              f"encoding, workers): {idle:.2f}× real time on two idle cores")

    long_song = os.path.join(folder, "three-minutes.wav")
    write_demo_wav(long_song, duration=180.0)
    long = Spectrogram.from_file(long_song)
    basis = HarmonicBasis.from_mesh(BUNNY, 300)
    # The largest glb: the initial-gallery item that drives the most harmonics.
    dances = [HarmonicDance(basis, long, item, long_song) for item in initial_gallery(basis, long)]
    dance = max(dances, key=lambda dance: len(dance.driven()))
    start = time.perf_counter()
    report = export_dance(dance, os.path.join(folder, "bunny.glb"), force=True)
    seconds = time.perf_counter() - start
    glb, cache = report["bytes"], report["point_cache_bytes"]
    print(f"bunny glb, 3-minute song, {report['frames']} frames, {len(dance.driven())} morph "
          f"targets: {glb / 1e6:.1f} MB in {seconds:.1f} s; as a point cache {cache / 1e6:.1f} MB"
          f": {cache / glb:.0f}× smaller (target ≥ 20×)")


def cpu_seconds() -> float:
    """CPU time of this process and of its finished children (workers, ffmpeg)."""
    own, children = (resource.getrusage(who) for who in (resource.RUSAGE_SELF,
                                                          resource.RUSAGE_CHILDREN))
    return own.ru_utime + own.ru_stime + children.ru_utime + children.ru_stime


def page_speed(mesh: str, k: int, song: str, args) -> float:
    """Seconds of video per second for the page (`?render&bare&view=player`): renderAt(t) and a
    screenshot per frame, after one warm-up frame."""
    from playwright.sync_api import sync_playwright

    server = subprocess.Popen([sys.executable, "-m", "eigendance.cli", "serve", mesh, song,
                               "-k", str(k), "--port", str(args.port)], stdout=subprocess.PIPE,
                              stderr=subprocess.DEVNULL, text=True)
    try:
        url = server.stdout.readline().split()[-1]
        with sync_playwright() as playwright:
            browser = launch(playwright.chromium)
            page = browser.new_page(viewport={"width": WIDTH, "height": HEIGHT})
            page.goto(url + "?render&bare&view=player")
            page.wait_for_function("window.eigendance && window.eigendance.ready",
                                   timeout=600_000)
            page.evaluate("window.eigendance.ready")
            page.wait_for_function("window.eigendance.info().k > 0", timeout=600_000)
            page.evaluate("window.eigendance.renderAt(0)")
            page.screenshot()
            start = time.perf_counter()
            for index in range(args.chromium_frames):
                page.evaluate(f"window.eigendance.renderAt({(index + 1) / FPS})")
                page.screenshot()
            per_frame = (time.perf_counter() - start) / args.chromium_frames
            browser.close()
    finally:
        server.terminate()
        server.wait(10)
    return 1.0 / (per_frame * FPS)


if __name__ == "__main__":
    main()
