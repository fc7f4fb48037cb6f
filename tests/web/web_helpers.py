"""Helpers of the web tests: small library files, Chromium settings, opening the app."""

from __future__ import annotations

import os
import socket
import time

CHROMIUM = "/usr/bin/chromium"
CHROMIUM_ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
                 "--disable-component-update", "--disable-sync", "--no-first-run"]
CAT = os.path.join(os.path.dirname(__file__), "..", "..", "src", "eigendance", "data",
                   "cat_lowres.obj")
E2E_K = 24


def free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


def write_icosphere(path, subdivisions=2) -> str:
    import trimesh

    trimesh.creation.icosphere(subdivisions).export(path)
    return str(path)


def write_song(path, seconds=6.0) -> str:
    import soundfile

    from eigendance.music.demo_music import demo_track

    samples, rate = demo_track(seconds)
    soundfile.write(str(path), samples, rate, subtype="PCM_16")
    return str(path)


def open_app(browser, url, query="?render", width=1100, height=760):
    page = browser.new_page(viewport={"width": width, "height": height})
    errors = []
    page.on("pageerror", lambda error: errors.append(str(error)))
    page.goto(url + query)
    page.wait_for_function("window.eigendance && window.eigendance.ready", timeout=60_000)
    started = time.time()
    page.evaluate("window.eigendance.ready")
    page.errors = errors
    page.load_seconds = time.time() - started
    return page
