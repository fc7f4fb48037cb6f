"""End to end in headless Chromium (SwiftShader WebGL2) on the app served by `eigendance serve`.

Select with `pytest -m web`; skipped where /usr/bin/chromium is missing.
"""

from __future__ import annotations

import numpy as np
import pytest
from web_helpers import CAT, E2E_K, open_app

pytestmark = pytest.mark.web
TIMES = (0.5, 1.7, 4.2)


@pytest.fixture(scope="module")
def page(browser, live_server):
    page = open_app(browser, live_server["url"], "?render&size=6")
    yield page
    assert not page.errors, page.errors
    page.close()


@pytest.fixture(scope="module")
def reference(web_files):
    """The Python side: the same basis (from the shared cache) and spectrogram."""
    import os

    from eigendance.harmonic.basis import HarmonicBasis
    from eigendance.music.spectrogram import Spectrogram

    os.environ["EIGENDANCE_CACHE_DIR"] = web_files["cache"]
    basis = HarmonicBasis.from_mesh(CAT, E2E_K)
    return basis, Spectrogram.from_file(web_files["song"])


def tiles_at(page, t):
    page.evaluate(f"window.eigendance.renderAt({t})")
    return [np.array(p, dtype=np.float64).reshape(-1, 3)
            for p in page.evaluate("window.eigendance.tilePixels(3)")]


def test_server_announces_a_localhost_url(live_server):
    assert live_server["url"].startswith("http://127.0.0.1:")


def test_gallery_shows_s_non_blank_mutually_different_tiles(page):
    info = page.evaluate("window.eigendance.info()")
    assert info["tiles"] == 6 and info["k"] == E2E_K and info["n"] == 7949
    tiles = tiles_at(page, 2.0)
    background = tiles[0][0]
    for pixels in tiles:
        drawn = np.abs(pixels - background).sum(axis=1) > 30
        assert drawn.mean() > 0.05, "a tile is blank"
    for i in range(len(tiles)):
        for j in range(i + 1, len(tiles)):
            assert np.abs(tiles[i] - tiles[j]).mean() > 1.0, f"tiles {i} and {j} look the same"


def test_tiles_move_with_the_music(page):
    first, later = page.evaluate("""() => {
        const e = window.eigendance;
        return [e.readPositions(0, 0.05), e.readPositions(0, 3.0)];
    }""")
    moved = np.abs(np.array(first) - np.array(later)).max()
    assert moved > 1e-4


def test_gpu_positions_equal_the_python_reference(page, reference):
    """Read back from the float render targets the tiles are drawn from (batched pass)."""
    from eigendance.harmonic.motion import positions_at
    from eigendance.music.mapping import Mapping

    basis, spectrogram = reference
    diagonal = np.linalg.norm(np.ptp(basis.to_original(basis.vertices), axis=0))
    mappings = page.evaluate("window.eigendance.mappings()")
    for tile in (0, 3, 5):
        mapping = Mapping.from_json(mappings[tile])
        for t in TIMES:
            gpu = np.array(page.evaluate(f"window.eigendance.readPositions({tile}, {t})"))
            gpu = basis.to_original(gpu.reshape(-1, 3))
            expected = positions_at(basis, spectrogram, mapping, t)
            error = np.abs(gpu - expected).max() / diagonal
            assert error < 1e-4, f"tile {tile} at t={t}: error {error:.2e} of the diagonal"
            single = np.array(page.evaluate(
                f"window.eigendance.readPositions({tile}, {t}, true)"))  # one-tile pass
            assert np.abs(basis.to_original(single.reshape(-1, 3)) - expected).max() / diagonal \
                < 1e-4
            cpu = np.array(page.evaluate(f"window.eigendance.cpuPositions({tile}, {t})"))
            assert np.abs(basis.to_original(cpu.reshape(-1, 3)) - expected).max() / diagonal \
                < 1e-4


def test_select_and_breed_make_a_new_generation(page):
    from eigendance.music.breeding import breed
    from eigendance.music.mapping import Mapping

    before = page.evaluate("window.eigendance.mappings()")
    page.click(".tile[data-index='1'] .view")
    page.click(".tile[data-index='4'] .view")
    assert page.evaluate("window.eigendance.info().selected") == [1, 4]
    assert page.is_enabled("#breed")
    page.evaluate("window.eigendance.breed(1234)")
    info = page.evaluate("window.eigendance.info()")
    assert info["generation"] == 1 and info["generations"] == 2 and info["tiles"] == 6
    children = page.evaluate("window.eigendance.mappings()")
    expected = breed([Mapping.from_json(before[1]), Mapping.from_json(before[4])], 6, 1234)
    assert children == [m.to_json() for m in expected]
    assert page.inner_text("#generation") == "generation 2 of 2"
    tiles = tiles_at(page, 1.0)
    assert len(tiles) == 6
    page.click("#back")
    assert page.evaluate("window.eigendance.mappings()") == before
    page.click("#forward")
    assert page.evaluate("window.eigendance.mappings()") == children


def test_player_view_and_harmonics_explorer(page, tmp_path):
    page.evaluate("window.eigendance.open(2)")
    assert page.evaluate("window.eigendance.info().view") == "player"
    page.evaluate("window.eigendance.renderAt(1.0)")
    plain = page.screenshot(clip={"x": 300, "y": 150, "width": 500, "height": 450})
    page.fill("#harmonic", "5")
    page.dispatch_event("#harmonic", "input")
    page.evaluate("window.eigendance.renderAt(1.0)")
    coloured = page.screenshot(clip={"x": 300, "y": 150, "width": 500, "height": 450})
    assert plain != coloured
    assert "harmonic 5" in page.inner_text("#player-info")
    page.fill("#harmonic", "-1")
    page.dispatch_event("#harmonic", "input")
    page.click("#tab-gallery")
    assert page.evaluate("window.eigendance.info().view") == "gallery"


def test_uploaded_mesh_gets_its_basis_and_appears(browser, live_server, web_files):
    page = open_app(browser, live_server["url"], "?render&size=4")
    first = page.evaluate("window.eigendance.info().meshId")
    page.set_input_files("#upload", web_files["sphere"])
    page.wait_for_function(f"window.eigendance.info().meshId !== '{first}' && "
                           "document.getElementById('status').textContent.includes('ready')",
                           timeout=60_000)
    info = page.evaluate("window.eigendance.info()")
    assert info["n"] == 162 and info["tiles"] == 4
    options = page.eval_on_selector_all("#mesh option", "o => o.map(x => x.textContent)")
    assert "sphere.obj" in options
    for pixels in tiles_at(page, 1.0):
        assert (np.abs(pixels - pixels[0]).sum(axis=1) > 30).mean() > 0.02
    assert not page.errors, page.errors
    page.close()


def test_live_playback_follows_the_audio_clock_and_records_webm_with_audio(browser,
                                                                           live_server):
    page = browser.new_page(viewport={"width": 900, "height": 700}, accept_downloads=True)
    page.goto(live_server["url"] + "?test&size=4")
    page.wait_for_function("window.eigendance && window.eigendance.ready", timeout=60_000)
    page.evaluate("window.eigendance.ready")
    page.click("#tab-player")
    page.click("#record")  # starts playback too
    page.wait_for_function("document.getElementById('clock').textContent === '0:01'",
                           timeout=20_000)
    with page.expect_download() as download:
        page.click("#record")
    assert download.value.suggested_filename == "eigendance.webm"
    with open(download.value.path(), "rb") as file:
        video = file.read()
    assert video[:4] == b"\x1a\x45\xdf\xa3"  # EBML: WebM
    assert b"V_VP" in video and b"A_OPUS" in video  # a video and an audio track
    page.click("#play")  # pause
    paused = page.input_value("#seek")
    page.wait_for_timeout(300)
    assert page.input_value("#seek") == paused
    page.close()


def test_dropping_an_audio_file_makes_it_the_current_song(browser, live_server, web_files):
    import base64

    from web_helpers import write_song

    path = write_song(web_files["folder"] / "dropped.wav", 3.0)
    with open(path, "rb") as file:
        data = base64.b64encode(file.read()).decode()
    page = open_app(browser, live_server["url"], "?render&size=4")
    before = page.evaluate("window.eigendance.info()")
    page.evaluate("""(data) => {
        const bytes = Uint8Array.from(atob(data), (c) => c.charCodeAt(0));
        const transfer = new DataTransfer();
        transfer.items.add(new File([bytes], "dropped.wav", { type: "audio/wav" }));
        window.dispatchEvent(new DragEvent("dragover", { dataTransfer: transfer }));
        window.dispatchEvent(new DragEvent("drop", { dataTransfer: transfer }));
    }""", data)
    page.wait_for_function("document.getElementById('status').textContent"
                           ".includes('dropped.wav ready')", timeout=30_000)
    info = page.evaluate("window.eigendance.info()")
    assert info["songId"] != before["songId"]
    assert info["duration"] == pytest.approx(3.0, abs=0.01)
    assert page.is_hidden("#drop")
    assert "dropped.wav" in page.eval_on_selector_all("#song option",
                                                      "o => o.map(x => x.textContent)")
    page.close()


def test_playback_stops_at_the_end_of_the_song_and_rewinds(browser, live_server):
    page = open_app(browser, live_server["url"], "?test&size=4")
    duration = page.evaluate("window.eigendance.info().duration")
    page.eval_on_selector("#seek", "(seek, t) => { seek.value = t; "
                                   "seek.dispatchEvent(new Event('input')); }", duration - 0.6)
    page.click("#play")
    page.wait_for_function("document.getElementById('play').textContent === '▶'",
                           timeout=20_000)
    assert float(page.input_value("#seek")) == 0
    assert not page.errors, page.errors
    page.close()


def test_float16_download_stays_close_to_the_reference(browser, live_server, reference):
    from eigendance.harmonic.motion import positions_at
    from eigendance.music.mapping import Mapping

    basis, spectrogram = reference
    diagonal = np.linalg.norm(np.ptp(basis.to_original(basis.vertices), axis=0))
    page = open_app(browser, live_server["url"], "?render&half&size=4")
    mapping = Mapping.from_json(page.evaluate("window.eigendance.mappings()")[0])
    gpu = np.array(page.evaluate("window.eigendance.readPositions(0, 1.7)"))
    error = np.abs(basis.to_original(gpu.reshape(-1, 3))
                   - positions_at(basis, spectrogram, mapping, 1.7)).max() / diagonal
    assert error < 1e-3, error
    page.close()


def test_empty_library_fills_up_from_uploads(browser, web_files, tmp_path):
    import os
    import subprocess
    import sys

    from web_helpers import free_port

    port = free_port()
    env = dict(os.environ, EIGENDANCE_CACHE_DIR=web_files["cache"])
    process = subprocess.Popen([sys.executable, "-m", "eigendance.cli", "serve", "-k", "12",
                                "--port", str(port)], env=env, stdout=subprocess.PIPE,
                               stderr=subprocess.DEVNULL, text=True)
    try:
        url = process.stdout.readline().split()[-1]
        page = open_app(browser, url, "?render&size=4")
        assert "needs a mesh" in page.inner_text("#status")
        page.set_input_files("#upload", web_files["sphere"])
        page.wait_for_function("document.getElementById('status').textContent"
                               ".includes('needs a song')", timeout=30_000)
        page.set_input_files("#upload", web_files["song"])
        page.wait_for_function("window.eigendance.info().tiles === 4", timeout=60_000)
        info = page.evaluate("window.eigendance.info()")
        assert info["n"] == 162 and info["k"] == 12
        assert not page.errors, page.errors
        page.close()
    finally:
        process.terminate()
        process.wait(10)
