"""The rig player's surface in headless Chromium (docs/design.md#surface-of-a-rig): off by
default; on, the skin's harmonics ripple on the GPU (and the CPU path) as the Python's
`SurfaceDance` says, added to the modal skin; the LBS view carries them too, as
`animate-rig --skinning lbs` does; rig dances carry surface genes and breed them as Python's
`breed` does.

Select with `pytest -m web`; skipped where /usr/bin/chromium is missing.
"""

from __future__ import annotations

import json
import urllib.request
from dataclasses import replace

import numpy as np
import pytest
from web_helpers import pinned_gpu_app, rig_ids_at

from eigendance.cli import main
from eigendance.modal.motion import rig_coefficients
from eigendance.modal.rig import Rig
from eigendance.modal.sample_rigs import sample_rig
from eigendance.modal.surface import SurfaceDance, surface_share
from eigendance.music.breeding import breed
from eigendance.music.gallery import initial_gallery
from eigendance.music.mapping import Mapping
from eigendance.music.spectrogram import Spectrogram

pytestmark = pytest.mark.web
TIMES = (0.4, 1.3, 2.9)
SWITCH = """(on) => { const box = document.getElementById('rig-surface');
  box.checked = on; box.dispatchEvent(new Event('change')); }"""
GAIN = """(gain) => { const slider = document.getElementById('rig-surface-gain');
  slider.value = String(gain); slider.dispatchEvent(new Event('input')); }"""


@pytest.fixture(scope="module")
def page(browser, live_server):
    with pinned_gpu_app(browser, live_server["url"]) as page:
        yield page


def test_the_surface_ripples_the_skin_on_the_gpu_as_python_does(page, live_server, web_files):
    hand = rig_ids_at(live_server["url"])["hand"]
    assert page.evaluate(f"window.eigendance.rig.open('{hand}')") is None
    assert page.evaluate("document.getElementById('rig-surface').checked") is False  # off
    diagonal = page.evaluate("window.eigendance.rig.info()")["diagonal"]
    rig = Rig.from_skeleton(sample_rig("hand"), dtype=np.float64)
    song = Spectrogram.from_file(web_files["song"])
    mapping = Mapping.from_json(page.evaluate("window.eigendance.rig.playerMapping()"))
    bones = rig.skin.positions(rig_coefficients(rig.model, song, mapping, TIMES))
    off = np.array(page.evaluate(f"window.eigendance.rig.readPositions('player', {TIMES[1]})"))
    np.testing.assert_allclose(off.reshape(-1, 3), bones[1], atol=1e-4 * diagonal)
    page.evaluate(SWITCH, True)
    page.wait_for_function("!document.getElementById('rig-surface-dance').disabled")
    ripple = SurfaceDance(rig.surface(), song, initial_gallery(rig.surface().basis, song, 8)[0])
    expected = bones + ripple.displacements(TIMES)  # first order, as the page's modal skin
    for i, t in enumerate(TIMES):
        for path in ("readPositions", "cpuPositions"):
            shown = np.array(page.evaluate(f"window.eigendance.rig.{path}('player', {t})"))
            np.testing.assert_allclose(shown.reshape(-1, 3), expected[i], atol=1e-4 * diagonal)
    assert np.abs(expected - bones).max() > 1e-3 * diagonal  # it ripples
    # The share shown beside the gain: `surface_share` over 16 moments spread over the song.
    moments = (np.arange(16) + 0.5) * song.duration / 16
    still = rig.skin.positions(rig_coefficients(rig.model, song, mapping, moments))
    share = surface_share(still, still + ripple.displacements(moments), rig.skeleton.vertices)
    shown = page.evaluate("document.getElementById('rig-surface-share').textContent")
    assert shown.endswith("% of the motion") and 0 < share < 1, shown
    assert abs(int(shown.split("%")[0]) - 100 * share) <= 1, (shown, share)  # float32, rounding
    # The gain sets the share: at 2× the surface mapping's gain, Python's share, shown anew.
    page.evaluate(GAIN, 2)
    page.wait_for_function(f"document.getElementById('rig-surface-share').textContent "
                           f"!== {json.dumps(shown)}")
    louder = SurfaceDance(rig.surface(), song, replace(ripple.mapping,
                                                       gain=2 * ripple.mapping.gain))
    doubled = surface_share(still, still + louder.displacements(moments), rig.skeleton.vertices)
    shown = page.evaluate("document.getElementById('rig-surface-share').textContent")
    assert doubled > share and abs(int(shown.split("%")[0]) - 100 * doubled) <= 1, (shown, doubled)
    page.evaluate(GAIN, 1)
    page.evaluate(SWITCH, False)
    page.wait_for_function("document.getElementById('rig-surface-dance').disabled")
    back = np.array(page.evaluate(f"window.eigendance.rig.readPositions('player', {TIMES[1]})"))
    np.testing.assert_allclose(back.reshape(-1, 3), bones[1], atol=1e-4 * diagonal)


def lbs_view(page, t):
    """The LBS skin's positions (three.js's morphing and skinning) and the player's pixels."""
    positions = np.array(page.evaluate(f"window.eigendance.rig.lbsPositions({t})"))
    page.evaluate(f"window.eigendance.rig.renderAt({t})")
    return positions.reshape(-1, 3), np.array(
        page.evaluate("window.eigendance.rig.playerPixels(3)"), dtype=float)


def test_the_lbs_view_ripples_as_animate_rig_lbs_does(page, live_server, web_files, tmp_path):
    """The LBS view with the surface on: the skin's harmonics as morph targets before the skin,
    Σ_b w_ib T_b (x_i + d_i), within 1e-4 of the diagonal of `animate-rig --skinning lbs` on
    the page's saved dance (its surface genes); drawn (its pixels change with the surface)."""
    with urllib.request.urlopen(live_server["url"] + "api/library") as answer:
        hand = next(r["id"] for r in json.load(answer)["rigs"] if r["name"] == "hand")
    assert page.evaluate(f"window.eigendance.rig.open('{hand}')") is None
    diagonal = page.evaluate("window.eigendance.rig.info()")["diagonal"]
    page.evaluate("window.eigendance.rig.setView('player'); "
                  "window.eigendance.rig.setSkinning('lbs')")
    fps, frames = 10, (4, 13, 29)
    off = [lbs_view(page, f / fps) for f in frames]
    page.evaluate(SWITCH, True)
    page.wait_for_function("!document.getElementById('rig-surface-dance').disabled")
    on = [lbs_view(page, f / fps) for f in frames]
    saved = page.evaluate("window.eigendance.rig.playerMapping()")
    assert saved["surface"] is not None
    dance = tmp_path / "dance.json"
    dance.write_text(json.dumps(saved))
    out = tmp_path / "lbs.npz"
    assert main(["animate-rig", "hand", web_files["song"], "--mapping", str(dance),
                 "--skinning", "lbs", "--fps", str(fps), "--duration", "3",
                 "-o", str(out)]) == 0
    expected = np.load(out)["positions"]
    for f, (positions, _), (still, _) in zip(frames, on, off, strict=True):
        np.testing.assert_allclose(positions, expected[f], atol=1e-4 * diagonal)
        assert np.abs(positions - still).max() > 1e-3 * diagonal  # the surface moves it
    changed = [np.mean(np.abs(a[1] - b[1]) > 40) for a, b in zip(on, off, strict=True)]
    assert max(changed) > 0.002, changed  # drawn: the rippled skin shows
    page.evaluate(SWITCH, False)
    page.wait_for_function("document.getElementById('rig-surface-dance').disabled")
    back, _ = lbs_view(page, frames[1] / fps)
    np.testing.assert_allclose(back, off[1][0], atol=1e-6 * diagonal)
    page.evaluate("window.eigendance.rig.setSkinning('modal')")


def test_rig_dances_breed_with_their_surface_genes_as_python_does(page, live_server, web_files):
    """With the surface on, each rig dance carries surface genes (the surface section's dance
    i mod m) and its tile ripples by them; breeding two of them gives children whose genes are
    Python's `breed` of the same parents and seed (crossed or copied), and a child opened in the
    player ripples by its own genes, saved in its file's `surface`."""
    with urllib.request.urlopen(live_server["url"] + "api/library") as answer:
        hand = next(r["id"] for r in json.load(answer)["rigs"] if r["name"] == "hand")
    assert page.evaluate(f"window.eigendance.rig.open('{hand}')") is None
    hooks = "window.eigendance.rig"
    page.evaluate(f"{hooks}.setMode('dances')")
    assert page.evaluate(f"{hooks}.dance(0)").get("surface") is None  # off: the bones alone
    page.evaluate(SWITCH, True)
    page.wait_for_function("!document.getElementById('rig-surface-dance').disabled")
    song = Spectrogram.from_file(web_files["song"])
    rig = Rig.from_skeleton(sample_rig("hand"), dtype=np.float64)
    surfaces = initial_gallery(rig.surface().basis, song, 8)
    parents = [page.evaluate(f"{hooks}.dance({i})") for i in (0, 1)]
    for i, parent in enumerate(parents):  # the section's dance i, as the server calibrates it
        np.testing.assert_allclose(parent["surface"]["amplification"],
                                   surfaces[i].amplification, rtol=1e-6)
    assert all("rippling skin" in label for label in page.evaluate(f"{hooks}.labels()"))
    page.evaluate(f"{hooks}.select(0); {hooks}.select(1)")
    seed = 11
    assert page.evaluate(f"{hooks}.breed({seed})") is None
    size = page.evaluate(f"{hooks}.info()")["tiles"]
    children = [page.evaluate(f"{hooks}.dance({i})") for i in range(size)]
    bred = breed([Mapping.from_json(p) for p in parents], size, seed)
    genes = [(c["surface"]["transfer"], c["surface"]["amplification"]) for c in children]
    for child, (transfer, amplification) in zip(bred, genes, strict=True):
        np.testing.assert_allclose(transfer, child.surface.transfer, atol=1e-12)
        np.testing.assert_allclose(amplification, child.surface.amplification, atol=1e-12)
    parent_genes = [p["surface"]["amplification"] for p in parents]
    assert any(not np.allclose(a, p) for _, a in genes for p in parent_genes)  # crossed ones
    # A child's tile ripples by its genes: the modal skin plus its SurfaceDance.
    diagonal = page.evaluate(f"{hooks}.info()")["diagonal"]
    crossed = next(i for i, (_, a) in enumerate(genes)
                   if all(not np.allclose(a, p) for p in parent_genes))
    child = Mapping.from_json(children[crossed])
    ripple = SurfaceDance(rig.surface(), song, child.surface).displacements(TIMES)
    bones = rig.skin.positions(rig_coefficients(rig.model, song, child, TIMES))
    for i, t in enumerate(TIMES):
        shown = np.array(page.evaluate(f"{hooks}.cpuPositions({crossed}, {t})")).reshape(-1, 3)
        np.testing.assert_allclose(shown, bones[i] + ripple[i], atol=1e-4 * diagonal)
    page.evaluate(f"{hooks}.openDance({crossed})")
    saved = page.evaluate(f"{hooks}.playerMapping()")
    assert saved["surface"]["amplification"] == children[crossed]["surface"]["amplification"]
    shown = np.array(page.evaluate(f"{hooks}.cpuPositions('player', {TIMES[1]})"))
    np.testing.assert_allclose(shown.reshape(-1, 3), bones[1] + ripple[1], atol=1e-4 * diagonal)
    # The share shown follows the dance opened (measured again once the player changes).
    moments = (np.arange(16) + 0.5) * song.duration / 16
    still = rig.skin.positions(rig_coefficients(rig.model, song, child, moments))
    moved = still + SurfaceDance(rig.surface(), song, child.surface).displacements(moments)
    share = 100 * surface_share(still, moved, rig.skeleton.vertices)
    page.wait_for_function(f"Math.abs(parseInt(document.getElementById('rig-surface-share')"
                           f".textContent) - {share}) <= 1")
    page.evaluate(SWITCH, False)
    page.wait_for_function("document.getElementById('rig-surface-dance').disabled")
    assert page.evaluate(f"{hooks}.playerMapping()").get("surface") is None
    assert page.evaluate(f"{hooks}.dance({crossed})").get("surface") is None


def test_a_preset_reopens_with_its_rippling_skin(page, live_server):
    """A rig's dance saved as a preset while its skin ripples plays again rippling by the same
    genes, the surface turned on for them (the presets panel's ▶; a show's cue opens its preset
    the same way); a preset of the bones alone plays with the skin still."""
    hooks = "window.eigendance.rig"
    assert page.evaluate(f"{hooks}.open('{rig_ids_at(live_server['url'])['hand']}')") is None
    page.evaluate(f"{hooks}.setView('player')")
    diagonal = page.evaluate(f"{hooks}.info()")["diagonal"]
    surface_on = "document.getElementById('rig-surface').checked"
    enabled = "!document.getElementById('rig-surface-dance').disabled"

    def positions():
        return np.array(page.evaluate(f"{hooks}.readPositions('player', {TIMES[1]})"))

    def save(name):
        page.fill("#preset-name", name)
        page.click("#preset-save")
        page.wait_for_selector(f'#preset-list .preset[data-name="{name}"]')

    page.click("#presets-button")
    save("Still hand")
    still = positions()
    page.evaluate(SWITCH, True)
    page.wait_for_function(enabled)
    page.select_option("#rig-surface-dance", "2")  # the surface's third dance, not the first
    rippling, rippled = page.evaluate(f"{hooks}.playerMapping()"), positions()
    assert np.abs(rippled - still).max() > 1e-3 * diagonal
    save("Rippling hand")
    page.evaluate(SWITCH, False)
    page.wait_for_function(f"!{enabled}")

    page.click('#preset-list .preset[data-name="Rippling hand"] .play')
    page.wait_for_function(f"{surface_on} && {enabled}")
    reopened = page.evaluate(f"{hooks}.playerMapping()")
    assert Mapping.from_json(reopened["surface"]).to_json() == \
        Mapping.from_json(rippling["surface"]).to_json()
    np.testing.assert_allclose(positions(), rippled, atol=1e-5 * diagonal)
    page.click('#preset-list .preset[data-name="Still hand"] .play')
    page.wait_for_function(f"!{surface_on} && !{enabled}")
    assert page.evaluate(f"{hooks}.playerMapping()").get("surface") is None
    np.testing.assert_allclose(positions(), still, atol=1e-5 * diagonal)
    page.click("#presets-button")
