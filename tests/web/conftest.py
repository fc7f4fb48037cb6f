"""Shared fixtures of the web tests: small library files, a live `eigendance serve`, Chromium."""

from __future__ import annotations

import os
import sys

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

