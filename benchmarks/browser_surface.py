"""Milliseconds per frame of the page's rig player with the surface off and on
(docs/design.md#surface-of-a-rig) in headless Chromium, for bench_surface.py.

`eigendance serve` gets the built-in cat, the demo music and the rigged files; the page
(1024×768) opens each rig in its player and times frames drawn by the `?test` hook
`rig.timeFrames` (the positions pass and drawing, waited for on the GPU), surface off and on
(the skin's first surface dance) in turn, twice: the best of the two turns of each; each in
modal skinning and in the LBS view ("off lbs", "on lbs": the surface as morph targets).
"""

from __future__ import annotations

import json
import subprocess
import sys
import time
import urllib.request

from playwright.sync_api import sync_playwright

from browser_rigs import CHROMIUM_ARGS
from eigendance.server.serve import demo_paths

SWITCH = """(on) => { const box = document.getElementById('rig-surface');
  box.checked = on; box.dispatchEvent(new Event('change')); }"""


def player_ms(rig_files, frames=20, port=8798) -> dict:
    """{rig name: {"off": ms, "on": ms, "off lbs": ms, "on lbs": ms}} and the renderer under
    "renderer"."""
    cat, song = demo_paths()
    server = subprocess.Popen(
        [sys.executable, "-m", "eigendance.cli", "serve", cat, song, *rig_files, "-k", "8",
         "--port", str(port)], stdout=subprocess.PIPE, text=True)
    results: dict = {}
    try:
        url = server.stdout.readline().split()[-1]
        while not all(mesh["ready"] for mesh in
                      json.load(urllib.request.urlopen(url + "api/library"))["meshes"]):
            time.sleep(0.5)
        library = json.load(urllib.request.urlopen(url + "api/library"))
        with sync_playwright() as playwright:
            browser = playwright.chromium.launch(executable_path="/usr/bin/chromium",
                                                 args=CHROMIUM_ARGS)
            page = browser.new_page(viewport={"width": 1024, "height": 768})
            page.goto(f"{url}?test&path=gpu")
            page.wait_for_function("window.eigendance && window.eigendance.ready",
                                   timeout=600_000)
            results["renderer"] = page.evaluate("""() => {
                const gl = document.createElement('canvas').getContext('webgl2');
                const info = gl.getExtension('WEBGL_debug_renderer_info');
                return info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : 'WebGL2'; }""")
            for rig in library["rigs"]:
                if rig.get("origin") == "built-in" or \
                        page.evaluate(f"window.eigendance.rig.open('{rig['id']}')") is not None:
                    continue
                page.evaluate("window.eigendance.rig.setView('player')")
                spent: dict[str, float] = {}
                for on in (False, True, False, True):  # each the best of two turns
                    page.evaluate(SWITCH, on)
                    page.wait_for_function(
                        f"{'!' if on else ''}document.getElementById('rig-surface-dance')"
                        ".disabled", timeout=600_000)
                    for skinning in ("modal", "lbs"):  # the LBS view: morph targets
                        page.evaluate(f"window.eigendance.rig.setSkinning('{skinning}')")
                        frame = page.evaluate(
                            f"window.eigendance.rig.timeFrames({frames})")["frame"]
                        key = ("on" if on else "off") + (" lbs" if skinning == "lbs" else "")
                        spent[key] = round(min(spent.get(key, frame), frame), 2)
                page.evaluate("window.eigendance.rig.setSkinning('modal')")
                results[rig["name"]] = spent
            browser.close()
    finally:
        server.terminate()
        server.wait(10)
    return results
