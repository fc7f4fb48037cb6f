"""Helpers of the show's browser tests and benchmark: a set on the shared kick track, an
`eigendance show` server with OSC in and out, a Chromium that may play sound."""

from __future__ import annotations

import contextlib
import json
import os
import threading
import time
import urllib.request

from chromium import AUTOPLAY, launch
from pythonosc.dispatcher import Dispatcher
from pythonosc.osc_server import ThreadingOSCUDPServer
from web_helpers import CAT, free_port, running_server

from helpers import fixture_path

KICK = fixture_path("audio", "beatnet_808kick120bpm.mp3")  # 120 BPM, 10 s


def write_set(folder) -> str:
    """Two cues on the cat and the kick track: 1 bar of the first gallery tile, then the
    preset "Wide" until told."""
    path = os.path.join(folder, "set.toml")
    with open(path, "w") as file:
        file.write(f"""[set]
name = "test set"
fade_beats = 2

[[cue]]
name = "one"
model = {json.dumps(os.path.abspath(CAT))}
song = {json.dumps(KICK)}
bars = 1

[[cue]]
name = "two"
model = {json.dumps(os.path.abspath(CAT))}
song = {json.dumps(KICK)}
preset = "Wide"
""")
    return path


@contextlib.contextmanager
def osc_listener(addresses=("/eigendance/beat",)):
    """A python-osc server on a free port of 127.0.0.1: (port, [(time.time(), address, *args)])."""
    received = []
    dispatcher = Dispatcher()
    for address in addresses:
        dispatcher.map(address, lambda a, *args: received.append((time.time(), a, *args)))
    server = ThreadingOSCUDPServer(("127.0.0.1", 0), dispatcher)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    try:
        yield server.server_address[1], received
    finally:
        server.shutdown()
        server.server_close()


@contextlib.contextmanager
def show_server(set_path, folder, presets, osc_out_port=None, k=24):
    """`eigendance show SET -k K --osc PORT [--osc-out …] --presets DIR` on free ports:
    {url, osc, process}."""
    osc = free_port()
    arguments = [set_path, "-k", str(k), "--osc", str(osc), "--presets", str(presets)]
    if osc_out_port:
        arguments += ["--osc-out", f"127.0.0.1:{osc_out_port}"]
    with running_server(arguments, folder, os.path.join(folder, "cache"), command="show",
                        ready="control page") as server:
        yield {**server, "osc": osc}


def control(url, action, value=None):
    """POST api/show/control; the new state."""
    request = urllib.request.Request(url + "api/show/control",
                                     data=json.dumps({"action": action, "value": value}).encode(),
                                     headers={"Content-Type": "application/json"})
    with urllib.request.urlopen(request) as answer:
        return json.load(answer)


def state(url):
    with urllib.request.urlopen(url + "api/show/state") as answer:
        return json.load(answer)


@contextlib.contextmanager
def sound_chromium(playwright_browser):
    """A Chromium of the session's Playwright that may play sound without a click."""
    launched = launch(playwright_browser.browser_type, *AUTOPLAY)
    try:
        yield launched
    finally:
        launched.close()


def open_output(chromium, url, query="?test", width=800, height=450):
    """The output page, ready (its App started and following the show)."""
    page = chromium.new_page(viewport={"width": width, "height": height})
    page.errors = []
    page.on("pageerror", lambda error: page.errors.append(str(error)))
    page.goto(url + "show" + query)
    page.wait_for_function("window.eigendance && window.eigendance.ready", timeout=120_000)
    page.evaluate("window.eigendance.ready")
    page.wait_for_function("window.eigendanceShow.output.state !== null", timeout=30_000)
    return page
