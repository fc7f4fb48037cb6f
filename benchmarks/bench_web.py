"""Web player benchmark: per-frame deformation of S gallery tiles in headless Chromium.

Serves MESH with the demo music through `eigendance serve`, opens the gallery with S tiles in
headless Chromium (SwiftShader WebGL2 where there is no GPU) and times, per frame:
  - the GPU deformation alone (weights upload + positions pass of every tile, synchronised),
  - the CPU (JS) deformation alone,
  - the whole frame (deformation + drawing every tile) on each path,
beside the numpy reference for the same work (`HarmonicBasis.filter_positions` of S filters, one
matrix product), and prints the ratios. Not run by CI.

    python benchmarks/bench_web.py [--mesh bunny_stanford.obj] [-k 1000] [-S 12] [--frames 5]
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
import urllib.request

import numpy as np

from shared_data import shared_path

HERE = os.path.dirname(os.path.abspath(__file__))
BUNNY = shared_path("meshes", "bunny_stanford.obj")
CHROMIUM_ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
                 "--disable-component-update", "--disable-sync", "--no-first-run"]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mesh", default=BUNNY)
    parser.add_argument("-k", type=int, default=1000)
    parser.add_argument("-S", "--size", type=int, default=12)
    parser.add_argument("--frames", type=int, default=5)
    parser.add_argument("--port", type=int, default=8791)
    args = parser.parse_args()

    from eigendance.harmonic.basis import HarmonicBasis
    from eigendance.music.demo_music import write_demo_wav
    from eigendance.music.mapping import Mapping
    from eigendance.music.spectrogram import Spectrogram

    folder = tempfile.mkdtemp(prefix="bench-web-")
    song = os.path.join(folder, "demo.wav")
    write_demo_wav(song, duration=10.0)
    start = time.perf_counter()
    basis = HarmonicBasis.from_mesh(args.mesh, args.k)  # cached after the first run
    print(f"mesh {os.path.basename(args.mesh)}: n = {basis.n}, k = {basis.k} "
          f"(basis {time.perf_counter() - start:.1f} s, cached after the first run)")
    spectrogram = Spectrogram.from_file(song)

    server = subprocess.Popen(
        [sys.executable, "-m", "eigendance.cli", "serve", args.mesh, song, "-k", str(args.k),
         "--port", str(args.port)], stdout=subprocess.PIPE, text=True)
    try:
        url = server.stdout.readline().split()[-1]
        while True:  # the server's own basis job hits the same cache
            library = json.load(urllib.request.urlopen(url + "api/library"))
            if library["meshes"][0]["ready"]:
                break
            time.sleep(0.5)
        results = browser_timings(url, args)
    finally:
        server.terminate()
        server.wait(10)

    mappings = [Mapping.from_json(m) for m in results.pop("mappings")]
    times = 1.0 + 0.1 * np.arange(args.frames)
    values = spectrogram.at(times)
    from eigendance.music.mapping import filters

    phi = filters(mappings, values[:1], basis.k)  # warm-up
    basis.filter_positions(phi[:, 0])
    start = time.perf_counter()
    for frame in range(args.frames):
        phi = filters(mappings, values[frame:frame + 1], basis.k)[:, 0]
        basis.filter_positions(phi)
    numpy_ms = (time.perf_counter() - start) / args.frames * 1000

    print(f"S = {args.size} tiles, {args.frames} frames each, headless Chromium "
          f"({results['renderer']}), viewport 1280x800")
    rows = [("numpy reference (S filters, one product)", numpy_ms),
            ("GPU deformation (positions pass)", results["gpu_deform"]),
            ("JS CPU deformation", results["cpu_deform"]),
            ("whole frame, GPU path", results["gpu_frame"]),
            ("whole frame, CPU path", results["cpu_frame"])]
    for name, ms in rows:
        print(f"  {name:42s} {ms:9.1f} ms/frame   ratio to numpy {ms / numpy_ms:7.2f}")
    print(f"  start-up choice of the app: {results['path'].upper()} path")


def browser_timings(url: str, args) -> dict:
    from playwright.sync_api import sync_playwright

    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path="/usr/bin/chromium",
                                             args=CHROMIUM_ARGS)
        page = browser.new_page(viewport={"width": 1280, "height": 800})
        page.goto(f"{url}?render&size={args.size}")
        page.wait_for_function("window.eigendance && window.eigendance.ready", timeout=600_000)
        page.evaluate("window.eigendance.ready", )
        out = {"path": page.evaluate("window.eigendance.info().path"),
               "mappings": page.evaluate("window.eigendance.mappings()"),
               "renderer": page.evaluate("""() => {
                   const gl = document.getElementById('gl').getContext('webgl2');
                   const info = gl.getExtension('WEBGL_debug_renderer_info');
                   return info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : 'WebGL2';
               }""")}
        for path in ("gpu", "cpu"):
            page.evaluate(f"window.eigendance.setPath('{path}')")
            out[f"{path}_deform"] = page.evaluate(
                f"window.eigendance.timeDeformation({args.frames}).frame")
            out[f"{path}_frame"] = page.evaluate(
                f"window.eigendance.timeFrames({args.frames}).frame")
        browser.close()
    return out


if __name__ == "__main__":
    main()
