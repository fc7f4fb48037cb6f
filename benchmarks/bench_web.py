"""Web player benchmark: where a frame of the gallery goes in headless Chromium without a GPU.

For each case — the demo (built-in cat, k = 150, the demo music), the Stanford bunny (shared
data, k = 300, the demo music) and, with a reduced basis (docs/design.md#reduced-basis), scans
of 0.2, 0.5 and 1 M vertices at k = 300 (benchmarks/big_meshes.py) — serves it with `eigendance
serve`, opens the gallery with S tiles in headless Chromium (SwiftShader WebGL2) and measures
the load (the page opened until its gallery is ready, with the basis bundle's size) and, per
frame:
  - deformation: the positions of every tile (GPU positions pass, or the JS CPU path), waited
    for on the GPU;
  - drawing: the surfaces of every tile (studio backdrop, shadow, model), waited for;
  - the live page at full resolution (`?scale=1`): frames it really draws per second while the
    music plays (counted from the frames drawn over a few seconds of wall time), our code's
    share of each frame (issuing the deformation and drawing, not waiting for the GPU), and the
    rest — compositing and presenting the canvas, waiting for the rasteriser, the browser's
    other work;
  - the live page as a person gets it, with dynamic resolution (docs/design.md#rendering):
    after it settles, the frames drawn per second and the resolution reached;
beside the numpy reference for the same deformation (`HarmonicBasis.filter_positions` of S
filters, one matrix product), measured in the same run. Not run by CI.

    python benchmarks/bench_web.py [--case demo|bunny|0.2M|0.5M|1M|all] [-S 8] [--frames 5]
                                   [--seconds 4] [--settle 14]
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import time
import urllib.request

import numpy as np
from playwright.sync_api import sync_playwright

from big_meshes import detailed_obj
from eigendance.harmonic.basis import HarmonicBasis
from eigendance.music.filter import filters
from eigendance.music.mapping import Mapping
from eigendance.music.spectrogram import Spectrogram
from eigendance.server.serve import demo_paths
from shared_data import shared_path

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "tests", "web"))
from chromium import AUTOPLAY, launch  # noqa: E402 - the tests' Chromium, found above

# name: (mesh file, or a benchmarks/big_meshes.py name; k; construction)
CASES = {"demo": (None, 150, "exact"),
         "bunny": (shared_path("meshes", "bunny_stanford.obj"), 300, "exact"),
         "0.2M": ("armadillo-173k", 300, "reduced"), "0.5M": ("cat-508k", 300, "reduced"),
         "1M": ("fertility-1.15M", 300, "reduced")}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--case", choices=[*CASES, "all"], default="all")
    parser.add_argument("-S", "--size", type=int, default=8)
    parser.add_argument("--frames", type=int, default=5, help="frames per timed part")
    parser.add_argument("--seconds", type=float, default=4.0, help="of live playback")
    parser.add_argument("--settle", type=float, default=14.0,
                        help="seconds of playback before the dynamic resolution is measured")
    parser.add_argument("--port", type=int, default=8791)
    args = parser.parse_args()
    cat, song = demo_paths()
    print(f"S = {args.size} tiles, headless Chromium without a GPU, viewport 1280x800; load "
          f"{', '.join(f'{x:.1f}' for x in os.getloadavg())}")
    for name in (CASES if args.case == "all" else [args.case]):
        mesh, k, construction = CASES[name]
        if mesh is not None and not os.path.exists(mesh):
            mesh = detailed_obj(mesh)
        run_case(name, mesh or cat, k, construction, song, args)


def run_case(name: str, mesh: str, k: int, construction: str, song: str, args) -> None:
    start = time.perf_counter()
    basis = HarmonicBasis.from_mesh(mesh, k, construction=construction)  # cached after a run
    solved = time.perf_counter() - start
    spectrogram = Spectrogram.from_file(song)
    server = subprocess.Popen(
        [sys.executable, "-m", "eigendance.cli", "serve", mesh, song, "-k", str(k),
         "--port", str(args.port), f"--{construction}", "--max-memory-mb", "16384"],
        stdout=subprocess.PIPE, text=True)
    try:
        url = server.stdout.readline().split()[-1]
        while True:  # the server's own basis job hits the same cache
            library = json.load(urllib.request.urlopen(url + "api/library"))
            if library["meshes"][0]["ready"]:
                break
            time.sleep(0.5)
        mesh_id = library["meshes"][0]["id"]
        bundle = len(urllib.request.urlopen(url + f"api/meshes/{mesh_id}/basis.bin").read())
        results = browser_timings(url, args)
    finally:
        server.terminate()
        server.wait(10)

    mappings = [Mapping.from_json(m) for m in results["mappings"]]
    times = 1.0 + 0.1 * np.arange(args.frames)
    values = spectrogram.at(times)
    basis.filter_positions(filters(mappings, values[:1], basis.k)[:, 0])  # warm-up
    start = time.perf_counter()
    for frame in range(args.frames):
        basis.filter_positions(filters(mappings, values[frame:frame + 1], basis.k)[:, 0])
    numpy_ms = (time.perf_counter() - start) / args.frames * 1000

    chosen = results["path"]
    interval = 1000 / results["fps"] if results["fps"] > 0 else float("nan")
    how = "exact" if basis.reduced is None else f"reduced, {basis.reduced.count} samples"
    print(f"\n{name}: {os.path.basename(mesh)}, n = {basis.n}, k = {basis.k} ({how}; basis "
          f"{solved:.1f} s, cached after the first run); {results['renderer']}; load "
          f"{os.getloadavg()[0]:.1f}")
    print(f"  load: basis bundle {bundle / 1e6:.1f} MB, page opened → gallery ready "
          f"{results['load']:.1f} s")
    print(f"  numpy reference, S filters, one product    {numpy_ms:8.1f} ms/frame")
    for path in ("gpu", "cpu"):
        mark = "  ← the page's choice" if path == chosen else ""
        print(f"  {path.upper()} path: deformation {results[path]['deformation']:8.1f} ms "
              f"({results[path]['deformation'] / numpy_ms:5.1f}× numpy), drawing "
              f"{results[path]['drawing']:8.1f} ms{mark}")
    print(f"  live page at full resolution ({chosen.upper()}): {results['fps']:.1f} frames/s "
          f"drawn = {interval:.0f} ms a frame: our code {results['ours']:.0f} ms, compositing "
          f"and the rest {interval - results['ours']:.0f} ms")
    dynamic = results["dynamic"]
    print(f"  live page with dynamic resolution: {dynamic['fps']:.1f} frames/s drawn at "
          f"{100 * dynamic['scale']:.0f}% resolution ({dynamic['fps'] / results['fps']:.1f}× "
          f"full resolution; the page says \"{dynamic['readout']}\""
          f"{' and offers fewer tiles' if dynamic['offer'] else ''})")


def browser_timings(url: str, args) -> dict:
    with sync_playwright() as playwright:
        browser = launch(playwright.chromium, *AUTOPLAY)
        page = browser.new_page(viewport={"width": 1280, "height": 800})
        start = time.perf_counter()
        page.goto(f"{url}?test&size={args.size}&scale=1")
        page.wait_for_function("window.eigendance && window.eigendance.ready", timeout=600_000)
        page.evaluate("window.eigendance.ready")
        out = {"load": time.perf_counter() - start,
               "path": page.evaluate("window.eigendance.info().path"),
               "mappings": page.evaluate("window.eigendance.mappings()"),
               "renderer": page.evaluate("""() => {
                   const gl = document.createElement('canvas').getContext('webgl2');
                   const info = gl.getExtension('WEBGL_debug_renderer_info');
                   return info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : 'WebGL2';
               }""")}
        for path in ("gpu", "cpu"):
            page.evaluate(f"window.eigendance.setPath('{path}')")
            out[path] = page.evaluate(f"window.eigendance.profileFrames({args.frames})")
        page.evaluate(f"window.eigendance.setPath('{out['path']}')")
        out.update(live_rate(page, 1.0, args.seconds))
        page.close()
        page = browser.new_page(viewport={"width": 1280, "height": 800})
        page.goto(f"{url}?test&size={args.size}&path={out['path']}")
        page.wait_for_function("window.eigendance && window.eigendance.ready", timeout=600_000)
        page.evaluate("window.eigendance.ready")
        out["dynamic"] = live_rate(page, args.settle, args.seconds)
        out["dynamic"]["scale"] = page.evaluate("window.eigendance.resolution().scale")
        browser.close()
    return out


def live_rate(page, settle: float, seconds: float) -> dict:
    """Play: after `settle` s, the frames drawn per second over `seconds` s of wall time (the
    song restarts at its end), our code's time per frame, and what the page says."""
    page.click("#play")
    page.wait_for_timeout(int(1000 * settle))
    first = page.evaluate("[performance.now(), window.eigendance.info().frames]")
    page.wait_for_timeout(int(1000 * seconds))
    last = page.evaluate("[performance.now(), window.eigendance.info().frames]")
    result = {"fps": 1000 * (last[1] - first[1]) / (last[0] - first[0]),
              "ours": page.evaluate("window.eigendance.info().frameMs"),
              "readout": page.inner_text("#fps"), "offer": page.is_visible("#notice")}
    page.click("#play")
    return result


if __name__ == "__main__":
    main()
