"""Shared fixtures of the web tests: small library files, a live `eigendance serve`, Chromium."""

from __future__ import annotations

import functools
import http.server
import os
import shutil
import sys
import threading

import pytest

sys.path.insert(0, os.path.dirname(__file__))

from web_helpers import (
    CAT,
    E2E_K,
    REAL_SONG,
    running_server,
    write_icosphere,
    write_song,
)

from helpers import fixture_path

HERE = os.path.dirname(__file__)
WEB_MODULES = os.path.join(HERE, "..", "..", "web", "node_modules")


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
    with running_server([CAT, web_files["song"], REAL_SONG, "-k", str(E2E_K)],
                        web_files["folder"], web_files["cache"]) as server:
        yield server


@pytest.fixture(scope="session")
def gltf_reference(tmp_path_factory):
    """A static server of gltf_reference.html (three.js's GLTFLoader drawing a file), the
    textured models (model.gltf: MorphStressTest; astronaut.glb: the Draco astronaut) and three
    from web/node_modules: its URL."""
    if not os.path.isdir(os.path.join(WEB_MODULES, "three")):
        pytest.skip("web/node_modules is not installed (scripts/web.sh install)")
    folder = tmp_path_factory.mktemp("gltf-reference")
    shutil.copy(os.path.join(HERE, "gltf_reference.html"),
                folder / "index.html")
    shutil.copy(fixture_path("textured", "MorphStressTest.gltf"), folder / "model.gltf")
    shutil.copy(fixture_path("rigged", "quaternius_Astronaut_FinnTheFrog.glb"),
                folder / "astronaut.glb")
    os.symlink(os.path.abspath(os.path.join(WEB_MODULES, "three")), folder / "three")
    handler = functools.partial(Quiet, directory=str(folder))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    yield f"http://127.0.0.1:{server.server_address[1]}/"
    server.shutdown()
    server.server_close()


class Quiet(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass
