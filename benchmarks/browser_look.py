"""Frames per second of the page with a model's materials against the clay (bench_look.py), in
headless Chromium (SwiftShader): `eigendance serve MODEL SONG`, the page at 1280×800 at full
resolution (`?scale=1`: dynamic resolution would trade pixels for the frame rate being
measured), frames timed by the `?test` hooks `timeFrames` / `rig.timeFrames` (the deformation of
every view and its drawing, waited for on the GPU), with `setMaterials(true)` and `(false)`.
"""

from __future__ import annotations

import subprocess
import sys

from playwright.sync_api import sync_playwright

from browser_server import launch

FRAMES, ROUNDS = 10, 3  # frames per timing; timings per look, alternating (the best is kept)


def look_fps(model: str, song: str, rig: bool, k: int, port: int = 8798) -> dict:
    """{"gallery": (fps with materials, fps in clay), "player": (…)} of the page showing
    `model` (a mesh's gallery of 8 tiles, or a rig's gallery of 16 modes) and its player."""
    server = subprocess.Popen([sys.executable, "-m", "eigendance.cli", "serve", model, song,
                               "-k", str(k), "--port", str(port)], stdout=subprocess.PIPE,
                              stderr=subprocess.DEVNULL, text=True)
    hooks = "window.eigendance.rig" if rig else "window.eigendance"
    try:
        url = server.stdout.readline().split()[-1]
        with sync_playwright() as playwright:
            browser = launch(playwright.chromium)
            page = browser.new_page(viewport={"width": 1280, "height": 800})
            page.goto(f"{url}?test&scale=1")
            page.wait_for_function("window.eigendance && window.eigendance.ready",
                                   timeout=600_000)
            page.evaluate("window.eigendance.ready")
            if rig:
                page.wait_for_function(f"{hooks}.info().active", timeout=600_000)
            results = {"gallery": measure(page, hooks)}
            if rig:
                page.evaluate(f"{hooks}.select(0)")
                page.evaluate(f"{hooks}.combine()")
            else:
                page.evaluate("window.eigendance.open(0)")
            results["player"] = measure(page, hooks)
            browser.close()
    finally:
        server.terminate()
        server.wait(10)
    return results


def measure(page, hooks: str) -> tuple[float, float]:
    """(fps in the model's materials, fps in clay) of the view on screen: the best of ROUNDS
    timings of each, alternating, so that a busy moment of the shared host hits both."""
    best = {"true": float("inf"), "false": float("inf")}
    for _ in range(ROUNDS):
        for materials in best:
            page.evaluate(f"{hooks}.setMaterials({materials})")
            frame = page.evaluate(f"{hooks}.timeFrames({FRAMES})")["frame"]
            best[materials] = min(best[materials], frame)
    page.evaluate(f"{hooks}.setMaterials(true)")
    return round(1000 / best["true"], 1), round(1000 / best["false"], 1)
