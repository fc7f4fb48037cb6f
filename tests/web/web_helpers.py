"""Helpers of the web tests: small library files, Chromium settings, opening the app."""

from __future__ import annotations

import contextlib
import io
import json
import os
import socket
import subprocess
import sys
import time
import urllib.request
import zipfile

from helpers import start

CAT = os.path.join(os.path.dirname(__file__), "..", "..", "src", "eigendance", "data",
                   "cat_lowres.obj")
E2E_K = 24
# A real recording (tests/fixtures/audio/LICENSES.md), served beside the generated song.
REAL_SONG = os.path.join(os.path.dirname(__file__), "..", "fixtures", "audio",
                         "kevin_macleod_vibe_ace_20s-24s.ogg")


def free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


@contextlib.contextmanager
def running_server(arguments, folder, cache, command="serve", ready="serving on", port=None):
    """`eigendance serve ARGUMENTS --port P` (or another COMMAND announcing READY) as a
    subprocess on PORT of 127.0.0.1 (a free one by default: the same PORT again is the same
    origin, the page's storage with it), its log in FOLDER/server.log and its basis cache in
    CACHE, its presets in FOLDER/presets unless ARGUMENTS say --presets (never the user's: a
    session's server starts before a test's own folders are set): {url, port, process,
    announce}."""
    port = port or free_port()
    env = dict(os.environ, EIGENDANCE_CACHE_DIR=str(cache),
               EIGENDANCE_PRESETS_DIR=os.path.join(folder, "presets"))
    command = [sys.executable, "-m", "eigendance.cli", command, *arguments, "--port", str(port)]
    log_path = os.path.join(folder, "server.log")
    with open(log_path, "w") as log:
        process = start(command, env=env, stdout=subprocess.PIPE, stderr=log,
                        text=True)
        line = process.stdout.readline()
        if ready not in line:
            process.kill()
            with open(log_path) as written:
                raise RuntimeError(f"server did not start: {line} {written.read()}")
        try:
            url = next(word for word in line.split() if word.startswith("http")).rstrip(",")
            yield {"url": url, "port": port, "process": process,
                   "announce": line}
        finally:
            process.terminate()
            try:
                process.wait(10)
            except subprocess.TimeoutExpired:
                process.kill()


def write_icosphere(path, subdivisions=2) -> str:
    import trimesh

    trimesh.creation.icosphere(subdivisions).export(path)
    return str(path)


def zipped(members: dict, method=zipfile.ZIP_DEFLATED) -> bytes:
    """A zip of {name or ZipInfo: bytes}."""
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", method) as archive:
        for name, data in members.items():
            archive.writestr(name, data)
    return buffer.getvalue()


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


@contextlib.contextmanager
def pinned_gpu_app(browser, url):
    """The app at ?test&path=gpu (760×520) with the hooks' times pinned (`live()`: nothing
    plays), for a test module's page; no page error when the module is done."""
    page = open_app(browser, url, "?test&path=gpu", 760, 520)
    page.evaluate("window.eigendance.live()")
    yield page
    assert not page.errors, page.errors
    page.close()


def library_at(url) -> dict:
    """GET api/library of the server at url."""
    with urllib.request.urlopen(url + "api/library") as answer:
        return json.load(answer)


def rig_ids_at(url) -> dict:
    """{rig name: id} of the library of the server at url."""
    return {rig["name"]: rig["id"] for rig in library_at(url)["rigs"]}


def fake_clip(folder, source, rate=44100, seconds=None):
    """A real clip (the first `seconds` of `source`) as a 16-bit WAV at `rate` (Chromium's
    capture rate: 44.1 kHz, so it reaches the page unresampled), the file the fake microphone
    plays; it starts with
    half a second of silence, as a room does before the music (the capture starts a few
    chunks into the file, so the clip itself starts whole)."""
    import numpy as np
    import soundfile
    from scipy.signal import resample_poly

    from eigendance.music.decode import mono, read_audio

    samples, sample_rate = read_audio(source)
    samples = mono(samples)
    if seconds:
        samples = samples[:int(seconds * sample_rate)]
    samples = np.concatenate([np.zeros(sample_rate // 2), samples])
    samples = resample_poly(samples, rate, sample_rate)
    path = os.path.join(folder, f"{os.path.basename(source)}-{rate}.wav")
    soundfile.write(path, samples, rate, subtype="PCM_16")
    return path
