"""The server and the page the browser benchmarks share: `eigendance serve` on a port, waited for
until the meshes' bases are ready, and headless Chromium's page of it, ready."""

from __future__ import annotations

import contextlib
import json
import os
import subprocess
import sys
import time
import urllib.request

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "tests", "web"))
from chromium import launch  # noqa: E402 - the tests' Chromium, found above

RENDERER = """() => {
    const gl = document.createElement('canvas').getContext('webgl2');
    const info = gl.getExtension('WEBGL_debug_renderer_info');
    return info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : 'WebGL2'; }"""


def library_of(url: str) -> dict:
    """GET api/library of the server at url."""
    with urllib.request.urlopen(url + "api/library") as answer:
        return json.load(answer)


@contextlib.contextmanager
def served(files, port: int, options=("-k", "8"), launcher=("-m", "eigendance.cli"), **popen):
    """`eigendance serve FILES OPTIONS --port PORT` as a subprocess (Python's LAUNCHER
    arguments start the command line), until the block ends: (url, process, library), once
    every mesh's basis is ready (the page starts on them)."""
    server = subprocess.Popen([sys.executable, *launcher, "serve", *files, *options,
                               "--port", str(port)], stdout=subprocess.PIPE, text=True, **popen)
    try:
        url = server.stdout.readline().split()[-1]
        while not all(mesh["ready"] for mesh in library_of(url)["meshes"]):
            time.sleep(0.5)
        yield url, server, library_of(url)
    finally:
        server.terminate()
        server.wait(10)


@contextlib.contextmanager
def gpu_page(url: str, width: int = 1024, height: int = 768):
    """Headless Chromium's page at url?test&path=gpu, its app ready: (page, its renderer's
    name)."""
    from playwright.sync_api import sync_playwright  # the browser benchmarks' alone

    with sync_playwright() as playwright:
        browser = launch(playwright.chromium)
        try:
            page = browser.new_page(viewport={"width": width, "height": height})
            page.goto(f"{url}?test&path=gpu")
            page.wait_for_function("window.eigendance && window.eigendance.ready",
                                   timeout=600_000)
            page.evaluate("window.eigendance.ready")
            yield page, page.evaluate(RENDERER)
        finally:
            browser.close()
