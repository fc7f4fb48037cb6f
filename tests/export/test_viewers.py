"""Exported glbs in the tools people open them with (docs/design.md#exports): the Khronos
glTF-Validator (npm gltf-validator, from Node) and three.js's GLTFLoader in headless Chromium.

Both need web/node_modules (`scripts/web.sh install`); without it they are skipped, except under
CI, where a missing tool fails.
"""

from __future__ import annotations

import functools
import http.server
import json
import os
import shutil
import subprocess
import threading

import numpy as np
import pytest
from export_helpers import check_positions, file_times, required, spread_frames

from eigendance.export.files import export_dance

ROOT = os.path.join(os.path.dirname(__file__), "..", "..")
WEB_MODULES = os.path.join(ROOT, "web", "node_modules")
HERE = os.path.dirname(__file__)
INSTALL = "scripts/web.sh install"


LONG_FPS = 5  # the 21 s song


@pytest.fixture(scope="module")
def glbs(tmp_path_factory, harmonic, reduced_harmonic, chain_lbs, figure_modal, fox_lbs,
         cake, gun_lbs, gun_surface):
    """Every kind of glb the exporter writes: morph targets, and skins of built-in and glTF
    rigs (linear blend and modal skinning), a reduced basis's skin on its samples; with a
    look: the textured, multi-part cake whose morph weights go below 0 and above 1 on a 21 s
    song, a rig with a gun on its hand."""
    folder = tmp_path_factory.mktemp("glbs")
    dances = {"sphere": harmonic, "reduced": reduced_harmonic, "chain": chain_lbs,
              "figure": figure_modal, "fox": fox_lbs, "cake": cake, "gun": gun_lbs,
              "surface": gun_surface}
    for name, dance in dances.items():
        export_dance(dance, folder / f"{name}.glb", fps=fps_of(dance))
    return folder, dances


def fps_of(dance) -> float:
    return LONG_FPS if dance.duration > 20 else 15


def test_the_khronos_validator_finds_no_error_and_no_warning(glbs):
    folder, dances = glbs
    node = shutil.which("node")
    required("gltf-validator", node is not None and
             os.path.isdir(os.path.join(WEB_MODULES, "gltf-validator")), INSTALL)
    files = [str(folder / f"{name}.glb") for name in dances]
    run = subprocess.run([node, os.path.join(HERE, "validate_gltf.mjs"), *files],
                         capture_output=True, text=True, timeout=120, check=True)
    reports = [json.loads(line) for line in run.stdout.splitlines()]
    assert len(reports) == len(files)
    for report in reports:
        assert report["numErrors"] == 0 and report["numWarnings"] == 0, report


@pytest.fixture(scope="module")
def three_page(glbs):
    """A static server of the glbs, the test page and three from web/node_modules."""
    required("three", os.path.isdir(os.path.join(WEB_MODULES, "three")), INSTALL)
    folder, _ = glbs
    shutil.copy(os.path.join(HERE, "three_positions.html"), folder / "index.html")
    os.symlink(os.path.abspath(os.path.join(WEB_MODULES, "three")), folder / "three")
    handler = functools.partial(Quiet, directory=str(folder))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    yield f"http://127.0.0.1:{server.server_address[1]}/"
    server.shutdown()
    server.server_close()


class Quiet(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


@pytest.mark.web
@pytest.mark.parametrize("name", ["sphere", "reduced", "chain", "figure", "fox", "cake", "gun",
                                  "surface"])
def test_three_js_plays_the_glb_as_the_reference_moves(glbs, three_page, chromium, name):
    """At three sample times (first, middle, last but one: the mixer loops at the end)."""
    _, dances = glbs
    dance = dances[name]
    samples = file_times(dance.duration, fps_of(dance))
    if dance.duration > 20:  # six frames spread over the song (the mixer loops at the end)
        times = [float(samples[i]) for i in spread_frames(len(samples) - 1)]
    else:
        times = [float(samples[0]), float(samples[len(samples) // 2]), float(samples[-2])]
    page = chromium.new_page()
    try:
        page.goto(three_page)
        page.wait_for_function("window.ready === true", timeout=30_000)
        result = page.evaluate("([url, times]) => window.positionsAt(url, times)",
                               [f"{name}.glb", times])
    finally:
        page.close()
    if name in ("sphere", "cake"):
        expected = dance.positions(times)
        assert result["targets"] == len(dance.driven())
    elif name == "reduced":  # three.js's joint matrices, both sets of four influences
        expected = dance.positions(times)
        assert result["skinned"] and result["influences"] == 8
    else:
        expected = dance.blend_positions(np.array(times))  # what a glTF skin plays
        assert result["skinned"]
        if name == "surface":  # the ripple's morph targets under the skin
            assert result["targets"] == len(dance.surface.driven())
    expected = dance.drawn(expected)  # drawn vertices, each on its welded vertex
    played = np.array(result["frames"]).reshape(len(times), len(expected[0]), 3)
    check_positions(played, expected, dance.diagonal, 1e-4, f"three.js r{result['revision']}")
    assert np.abs(expected[1] - expected[0]).max() > 1e-3 * dance.diagonal  # it moves
