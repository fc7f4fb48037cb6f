"""Frames per second of the page's gallery of modes (GPU modal skinning,
docs/web.md#rigs-in-the-page) in headless Chromium, for bench_rigs.py's Table 7.2.

`eigendance serve` gets the built-in cat, the demo music and the rigged files (each becomes a rig
item; the built-in rigs are always there); the page (1024×768, the thesis's window) opens every
rig, shows NM mode tiles and times frames drawn by the `?test` hook `rig.timeFrames` (modal
skinning of every tile in the positions pass, then drawing them, waited for on the GPU).
"""

from __future__ import annotations

from browser_server import gpu_page, served
from eigendance.server.serve import demo_paths


def browser_fps(rig_files, galleries=(1, 9), frames=10, port=8797) -> dict:
    """{rig name: {"NM": fps}} and the renderer's name under key "renderer"."""
    results: dict = {}
    with served([*demo_paths(), *rig_files], port) as (url, _, library), \
            gpu_page(url) as (page, renderer):
        results["renderer"] = renderer
        for rig in library["rigs"]:
            if page.evaluate(f"window.eigendance.rig.open('{rig['id']}')") is not None:
                continue  # no modes (a rig without elastic joints): said on the page
            fps = {}
            for tiles in galleries:
                page.evaluate(f"window.eigendance.rig.pageSize({tiles})")
                frame = page.evaluate(f"window.eigendance.rig.timeFrames({frames})")["frame"]
                fps[str(tiles)] = round(1000 / frame, 1)
            results[rig["name"]] = fps
    return results
