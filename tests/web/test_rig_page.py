"""Rigs in the page (docs/web.md#rigs-in-the-page), end to end in headless Chromium: GPU modal
skinning read back equals the Python `ModalSkin.positions` of `rig_coefficients`, every tile of
the gallery of modes moves, a pose edit changes the frequencies shown, and three.js linear blend
skinning differs from modal skinning only to second order.

Select with `pytest -m web`; skipped where /usr/bin/chromium is missing.
"""

from __future__ import annotations

import base64
import math

import numpy as np
import pytest
from web_helpers import pinned_gpu_app, rig_ids_at

from eigendance.modal.floor import tile_amplitudes
from eigendance.modal.motion import rig_coefficients
from eigendance.modal.palette import default_phases, mode_reach, single_mode_amplitudes
from eigendance.modal.rig import Rig
from eigendance.modal.sample_rigs import sample_rig
from eigendance.music.mapping import Mapping
from eigendance.music.spectrogram import Spectrogram

pytestmark = pytest.mark.web
TIMES = (0.4, 1.3, 2.9)


@pytest.fixture(scope="module")
def page(browser, live_server):
    with pinned_gpu_app(browser, live_server["url"]) as page:
        yield page


@pytest.fixture(scope="module")
def rig_ids(live_server):
    return rig_ids_at(live_server["url"])


@pytest.fixture(scope="module")
def song(web_files):
    return Spectrogram.from_file(web_files["song"])


# A mode tile plays its mode time-scaled into what a page can show (issue 30 item 7).
SHOWN_LOW, SHOWN_HIGH = 0.4, 1.5


def shown_hz(natural, scale):
    """The frequency a mode tile shows: natural × the palette's scale, clamped to the range."""
    return np.clip(np.asarray(natural) * scale, SHOWN_LOW, SHOWN_HIGH)


def label(mode: int, natural: float, scale: float) -> str:
    shown = float(shown_hz(natural, scale))
    if abs(shown - natural * scale) < 1e-9:
        said = f"{natural * scale:.2f} Hz" + ("" if abs(scale - 1) < 5e-3
                                              else f" (×{scale:.2f} time scale)")
    else:
        said = f"{natural * scale:.2f} Hz, shown at {shown:.2f} Hz"  # as played, and shown
    return f"mode {mode + 1} · {said}"


def open_rig(page, rig_ids, name):
    assert page.evaluate(f"window.eigendance.rig.open('{rig_ids[name]}')") is None
    info = page.evaluate("window.eigendance.rig.info()")
    assert info["error"] is None and info["active"] and info["name"] == name
    return info


@pytest.mark.parametrize("name", ["hand", "loop8"])
def test_gpu_modal_skinning_equals_python(page, rig_ids, song, name):
    """Every mode tile (batched passes, as drawn) and the player (the song-calibrated default
    mapping, music on) at three times: positions read back from the float targets equal
    `ModalSkin.positions(rig_coefficients(…))` within 1e-4 of the bounding-box diagonal."""
    info = open_rig(page, rig_ids, name)
    rig = Rig.from_skeleton(sample_rig(name), dtype=np.float64)
    model, diagonal = rig.model, info["diagonal"]
    modes = info["modes"]
    assert modes == list(range(min(model.n_modes, 16)))
    mapping = Mapping.from_json(page.evaluate("window.eigendance.rig.playerMapping()"))
    scale = mapping.modes.time_scale
    # the tiles' amplitudes, made to be seen (docs/design.md#the-floor)
    mu = tile_amplitudes(model, rig.skin, single_mode_amplitudes(model)) / mode_reach(model)
    gamma = default_phases(np.arange(model.n_modes))
    player = rig.skin.positions(rig_coefficients(model, song, mapping, TIMES))
    worst, moved = 0.0, np.zeros(len(modes))
    for i, t in enumerate(TIMES):
        tiles = np.array(page.evaluate(f"window.eigendance.rig.readTiles({t})"))
        tiles = tiles.reshape(len(modes), -1, 3)
        assert tiles.shape == (len(modes), len(rig.skin.vertices), 3)
        c = np.zeros((len(modes), model.n_modes))
        c[modes, modes] = mu[modes] * np.sin(
            2 * math.pi * shown_hz(model.frequencies[modes], scale) * t + gamma[modes])
        shown = page.evaluate(f"[...Array({len(modes)}).keys()].map("
                              f"(j) => window.eigendance.rig.coefficients(j, {t}))")
        np.testing.assert_allclose(shown, c, atol=1e-6 * np.abs(mu).max())
        expected = rig.skin.positions(c)
        moved = np.maximum(moved, np.abs(expected - rig.skin.vertices).max(axis=(1, 2)))
        worst = max(worst, np.abs(tiles - expected).max() / diagonal)
        gpu = np.array(page.evaluate(f"window.eigendance.rig.readPositions('player', {t})"))
        worst = max(worst, np.abs(gpu.reshape(-1, 3) - player[i]).max() / diagonal)
        cpu = np.array(page.evaluate(f"window.eigendance.rig.cpuPositions('player', {t})"))
        worst = max(worst, np.abs(cpu.reshape(-1, 3) - player[i]).max() / diagonal)
    assert np.all(moved > 1e-3 * diagonal), "every mode tile moves"
    print(f"{name}: largest GPU/CPU − Python error {worst:.2e} of the diagonal")
    assert worst < 1e-4


def test_every_mode_tile_moves_and_shows_its_frequency(page, rig_ids):
    """One tile per mode (a page of 16 for the hand's 72, then 'more modes'), each labelled with
    its natural frequency and the one shown (time-scaled into what a page shows), and every
    tile's pixels change over playback."""
    info = open_rig(page, rig_ids, "hand")
    assert info["pages"] == math.ceil(info["k"] / 16)
    scale = page.evaluate("window.eigendance.rig.playerMapping()")["modes"]["time_scale"]
    labels = page.evaluate("window.eigendance.rig.labels()")
    assert labels == [label(m, info["frequencies"][m], scale) for m in range(16)]
    page.evaluate(f"window.eigendance.rig.page({info['pages'] - 1})")
    last = page.evaluate("window.eigendance.rig.info()")
    assert last["modes"] == list(range(16 * (info["pages"] - 1), info["k"]))
    assert last["tiles"] == len(last["modes"])
    page.evaluate("window.eigendance.rig.page(0)")
    # Tiles as large as on a laptop screen: a finger's mode moves a few pixels of a small tile.
    viewport = page.viewport_size
    page.set_viewport_size({"width": 1280, "height": 800})
    frames = []
    times = (0.2, 0.45, 0.7, 0.95)
    try:
        for t in times:
            page.evaluate(f"window.eigendance.rig.renderAt({t})")
            frames.append([np.frombuffer(base64.b64decode(p), np.uint8).astype(float)
                           for p in page.evaluate("window.eigendance.rig.tileBytes(2)")])
    finally:
        page.set_viewport_size(viewport)
    assert len(frames[0]) == 16
    for tile in range(16):
        changed = max(np.mean(np.abs(frames[a][tile] - frames[b][tile]) > 24)
                      for a in range(len(times)) for b in range(a))
        print(f"tile {tile + 1}: {changed:.4f} of its pixels change")
        # A still tile changes no pixel (drawing is deterministic); 0.1% of a 1280×800 tile is
        # ~30 screen pixels, a fingertip's swing.
        assert changed > 0.001, f"tile {tile + 1} does not move ({changed:.4f})"


def test_a_pose_edit_changes_the_frequencies_shown_and_reset_restores_them(page, rig_ids):
    open_rig(page, rig_ids, "hand")
    before = page.evaluate("window.eigendance.rig.labels()")
    frequencies = page.evaluate("window.eigendance.rig.info().frequencies")
    assert page.evaluate("window.eigendance.rig.pose(1, [0, 0, 0.8])") is None
    edited = page.evaluate("window.eigendance.rig.info()")
    assert edited["revision"] >= 1 and edited["error"] is None
    assert page.evaluate("window.eigendance.rig.labels()") != before
    assert not np.allclose(edited["frequencies"], frequencies, rtol=1e-4)
    stiff = page.evaluate("window.eigendance.rig.stiffness(1, 1.0).then(() => "
                          "window.eigendance.rig.info().frequencies)")
    assert not np.allclose(stiff, edited["frequencies"], rtol=1e-4)
    assert page.evaluate("window.eigendance.rig.reset()") is None
    np.testing.assert_allclose(page.evaluate("window.eigendance.rig.info().frequencies"),
                               frequencies, rtol=1e-5)
    assert page.evaluate("window.eigendance.rig.labels()") == before
    # The hand is a tree: every joint turns. In a loop no joint can turn one side alone: the
    # menu says so and the sliders are off, the stiffness stays editable.
    page.evaluate("window.eigendance.rig.pick(1)")
    assert not page.is_disabled("#rig-turn-x")
    open_rig(page, rig_ids, "loop8")
    page.evaluate("window.eigendance.rig.pick(2)")
    assert "in a loop" in page.eval_on_selector("#rig-joint",
                                                 "menu => menu.selectedOptions[0].text")
    assert "closes a loop" in page.get_attribute("#rig-joint", "title")
    assert page.is_disabled("#rig-turn-x") and page.is_disabled("#rig-turn-z")
    assert not page.is_disabled("#rig-stiffness")


def test_linear_blend_skinning_differs_only_to_second_order(page, rig_ids, song):
    """three.js's SkinnedMesh on the same body poses: close to modal skinning, and the gap
    shrinks like the square of the amplitude (halving it quarters the gap)."""
    info = open_rig(page, rig_ids, "loop8")
    page.evaluate("window.eigendance.rig.setMusic(false)")
    # Music off saves as gain 0, offset 1 (φ ≡ 1): Python plays the page's motion.
    saved = page.evaluate("window.eigendance.rig.playerMapping()")
    assert saved["gain"] == 0 and saved["offset"] == 1
    model = Rig.from_skeleton(sample_rig("loop8"), dtype=np.float64).model
    expected = rig_coefficients(model, song, Mapping.from_json(saved), TIMES)
    shown = [page.evaluate(f"window.eigendance.rig.coefficients('player', {t})") for t in TIMES]
    np.testing.assert_allclose(shown, expected, atol=1e-5 * np.abs(expected).max())
    gaps = []
    for _ in range(2):
        gap = 0.0
        for t in TIMES:
            modal = np.array(page.evaluate(f"window.eigendance.rig.cpuPositions('player', {t})"))
            lbs = np.array(page.evaluate(f"window.eigendance.rig.lbsPositions({t})"))
            gap = max(gap, np.abs(modal - lbs).max() / info["diagonal"])
        gaps.append(gap)
        page.evaluate("window.eigendance.rig.scaleAmplitudes(0.5)")
    assert gaps[0] < 0.05
    assert 2.8 < gaps[0] / gaps[1] < 5.0, gaps
    page.evaluate("window.eigendance.rig.setSkinning('lbs'); window.eigendance.rig.setBones(true)")
    page.evaluate("window.eigendance.rig.setView('player')")
    page.evaluate("window.eigendance.rig.renderAt(1.3)")
    lbs = np.array(page.evaluate("window.eigendance.rig.playerPixels(3)"), dtype=float)
    page.evaluate("window.eigendance.rig.setSkinning('modal')")
    page.evaluate("window.eigendance.rig.renderAt(1.3)")
    modal = np.array(page.evaluate("window.eigendance.rig.playerPixels(3)"), dtype=float)
    assert np.mean(np.abs(lbs - modal) > 40) < 0.01


def test_combined_modes_save_a_mapping_python_plays_the_same_and_dances_breed(page, rig_ids,
                                                                              song):
    """Modes 1 and 3 combined: the saved mapping (version 3, `modes` and `offset`) gives
    `rig_coefficients` the page's coefficients, locked to the beats and, switched off,
    free-running; the dances breed a new generation."""
    info = open_rig(page, rig_ids, "loop8")
    page.evaluate("window.eigendance.rig.setMusic(true)")  # an earlier test turned it off
    page.evaluate("window.eigendance.rig.select(0); window.eigendance.rig.select(2); "
                  "window.eigendance.rig.combine()")
    saved = page.evaluate("window.eigendance.rig.playerMapping()")
    assert saved["version"] == 3 and saved["offset"] == 0 and saved["modes"]["selected"] == [0, 2]
    mapping = Mapping.from_json(saved)
    model = Rig.from_skeleton(sample_rig("loop8"), dtype=np.float64).model
    expected = rig_coefficients(model, song, mapping, TIMES)
    shown = [page.evaluate(f"window.eigendance.rig.coefficients('player', {t})") for t in TIMES]
    np.testing.assert_allclose(shown, expected, atol=1e-5 * np.abs(expected).max())
    assert np.abs(expected[:, [1, 3, 4]]).max() == 0 and np.abs(expected).max() > 0
    # The palette's "on the beat" switch off: the thesis's free-running motion, saved as such.
    assert song.rhythm.has_beats and saved["modes"].get("tempo") is None
    page.evaluate("const box = document.getElementById('rig-beat'); box.checked = false; "
                  "box.dispatchEvent(new Event('change'))")
    free = page.evaluate("window.eigendance.rig.playerMapping()")
    assert free["modes"]["tempo"] == "free"
    expected_free = rig_coefficients(model, song, Mapping.from_json(free), TIMES)
    shown = [page.evaluate(f"window.eigendance.rig.coefficients('player', {t})") for t in TIMES]
    np.testing.assert_allclose(shown, expected_free, atol=1e-5 * np.abs(expected_free).max())
    assert np.abs(expected_free - expected).max() > 1e-3  # the lock changed the motion
    page.evaluate("window.eigendance.rig.setView('gallery'); "
                  "window.eigendance.rig.setMode('dances')")
    count = page.evaluate("window.eigendance.rig.info().tiles")
    page.evaluate("window.eigendance.rig.select(0); window.eigendance.rig.select(1)")
    assert page.evaluate("window.eigendance.rig.breed(5)") is None
    bred = page.evaluate("window.eigendance.rig.info()")
    assert bred["generations"] == 2 and bred["tiles"] == count and bred["error"] is None
    assert info["k"] == 5
