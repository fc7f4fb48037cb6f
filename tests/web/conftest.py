"""Shared fixtures of the web tests: small library files, a live `eigendance serve`, Chromium."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest

sys.path.insert(0, os.path.dirname(__file__))

from web_helpers import (
    CAT,
    E2E_K,
    REAL_SONG,
    free_port,
    write_icosphere,
    write_song,
)


@pytest.fixture(scope="session")
def web_files(tmp_path_factory):
    folder = tmp_path_factory.mktemp("web-files")
    return {"song": write_song(folder / "song.wav"),
            "sphere": write_icosphere(folder / "sphere.obj"),
            "cache": str(folder / "cache"), "folder": folder}


@pytest.fixture(scope="session")
def live_server(web_files):
    """`eigendance serve CAT SONG REAL_SONG -k 24` on a free port of 127.0.0.1, as a
    subprocess (SONG, generated, comes first: the page's default)."""
    port = free_port()
    env = dict(os.environ, EIGENDANCE_CACHE_DIR=web_files["cache"])
    command = [sys.executable, "-m", "eigendance.cli", "serve", CAT, web_files["song"],
               REAL_SONG, "-k", str(E2E_K), "--port", str(port)]
    log = open(web_files["folder"] / "server.log", "w")  # noqa: SIM115 - closed below
    process = subprocess.Popen(command, env=env, stdout=subprocess.PIPE, stderr=log, text=True)
    line = process.stdout.readline()
    if "serving on" not in line:
        process.kill()
        log.close()
        raise RuntimeError(f"server did not start: {line} "
                           f"{(web_files['folder'] / 'server.log').read_text()}")
    url = line.strip().split()[-1]
    yield {"url": url, "port": port, "process": process, "announce": line}
    process.terminate()
    try:
        process.wait(10)
    except subprocess.TimeoutExpired:
        process.kill()
    log.close()

