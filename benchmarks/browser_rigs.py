"""Frames per second of the page's gallery of modes (GPU modal skinning,
docs/web.md#rigs-in-the-page) in headless Chromium, for bench_rigs.py's Table 7.2.

`eigendance serve` gets the built-in cat, the demo music and the rigged files (each becomes a rig
item; the built-in rigs are always there); the page (1024×768, the thesis's window) opens every
rig, shows NM mode tiles and times frames drawn by the `?test` hook `rig.timeFrames` (modal
skinning of every tile in the positions pass, then drawing them, waited for on the GPU).
"""

from __future__ import annotations

import json
import subprocess
import sys
import time
import urllib.request

from playwright.sync_api import sync_playwright

from eigendance.server.serve import demo_paths

CHROMIUM_ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
                 "--disable-background-networking", "--disable-component-update",
                 "--disable-sync"]


def browser_fps(rig_files, galleries=(1, 9), frames=10, port=8797) -> dict:
    """{rig name: {"NM": fps}} and the renderer's name under key "renderer"."""
    cat, song = demo_paths()
    server = subprocess.Popen(
        [sys.executable, "-m", "eigendance.cli", "serve", cat, song, *rig_files, "-k", "8",
         "--port", str(port)], stdout=subprocess.PIPE, text=True)
    results: dict = {}
    try:
        url = server.stdout.readline().split()[-1]
        while True:  # the meshes' (small) bases first: the page starts on them
            library = json.load(urllib.request.urlopen(url + "api/library"))
            if all(mesh["ready"] for mesh in library["meshes"]):
                break
            time.sleep(0.5)
        with sync_playwright() as playwright:
            browser = playwright.chromium.launch(executable_path="/usr/bin/chromium",
                                                 args=CHROMIUM_ARGS)
            page = browser.new_page(viewport={"width": 1024, "height": 768})
            page.goto(f"{url}?test&path=gpu")
            page.wait_for_function("window.eigendance && window.eigendance.ready",
                                   timeout=600_000)
            page.evaluate("window.eigendance.ready")
            results["renderer"] = page.evaluate("""() => {
                const gl = document.createElement('canvas').getContext('webgl2');
                const info = gl.getExtension('WEBGL_debug_renderer_info');
                return info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : 'WebGL2'; }""")
            for rig in library["rigs"]:
                if page.evaluate(f"window.eigendance.rig.open('{rig['id']}')") is not None:
                    continue  # no modes (a rig without elastic joints): said on the page
                fps = {}
                for tiles in galleries:
                    page.evaluate(f"window.eigendance.rig.pageSize({tiles})")
                    frame = page.evaluate(f"window.eigendance.rig.timeFrames({frames})")["frame"]
                    fps[str(tiles)] = round(1000 / frame, 1)
                results[rig["name"]] = fps
            browser.close()
    finally:
        server.terminate()
        server.wait(10)
    return results
