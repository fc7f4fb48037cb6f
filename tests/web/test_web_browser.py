"""End to end in headless Chromium (SwiftShader WebGL2) on the app served by `eigendance serve`.

Select with `pytest -m web`; skipped where /usr/bin/chromium is missing.
"""

from __future__ import annotations

import base64
import io
import json
import os
import subprocess
import sys
import urllib.request

import numpy as np
import pytest
from PIL import Image
from web_helpers import CAT, E2E_K, REAL_SONG, free_port, open_app, write_song

from eigendance.cli import main
from eigendance.harmonic.basis import HarmonicBasis
from eigendance.harmonic.motion import load_animation, positions_at
from eigendance.music.breeding import breed
from eigendance.music.dancer import gallery_motion
from eigendance.music.mapping import Mapping
from eigendance.music.spectrogram import Spectrogram, frame_times
from helpers import start

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
    """The Python side: the same basis (from the shared cache) and spectrograms."""
    os.environ["EIGENDANCE_CACHE_DIR"] = web_files["cache"]
    basis = HarmonicBasis.from_mesh(CAT, E2E_K)
    return basis, Spectrogram.from_file(web_files["song"])


def songs_of(live_server) -> dict[str, str]:
    """Song name → id in the server's library."""
    with urllib.request.urlopen(live_server["url"] + "api/library") as answer:
        return {song["name"]: song["id"] for song in json.load(answer)["songs"]}


def tiles_at(page, t):
    page.evaluate(f"window.eigendance.renderAt({t})")
    return [np.array(p, dtype=np.float64).reshape(-1, 3)
            for p in page.evaluate("window.eigendance.tilePixels(3)")]


def clay(pixels):
    """The model's pixels: warm clay (red well above blue); the studio backdrop and the
    shadow are grey-blue or dark."""
    return (pixels[..., 0] - pixels[..., 2]) > 30


def tile_images(page, step=2):
    """Each tile's pixels as an image (rows, columns, 3), as drawn."""
    sizes = page.eval_on_selector_all(".tile .view", "views => views.map(v => { "
                                      "const r = v.getBoundingClientRect(); "
                                      "return [Math.floor(r.width), Math.floor(r.height)]; })")
    flat = page.evaluate(f"window.eigendance.tilePixels({step})")
    return [np.array(p, dtype=np.float64).reshape(-(-h // step), -(-w // step), 3)
            for p, (w, h) in zip(flat, sizes, strict=True)]


def whole(mask) -> bool:
    """The model is drawn and touches no edge of its view: it shows whole."""
    return mask.mean() > 0.02 and not (mask[0].any() or mask[-1].any() or mask[:, 0].any()
                                       or mask[:, -1].any())


def test_server_announces_a_localhost_url(live_server):
    assert live_server["url"].startswith("http://127.0.0.1:")


def test_every_tile_shows_the_whole_model_filling_it(page):
    info = page.evaluate("window.eigendance.info()")
    assert info["tiles"] == 6 and info["k"] == E2E_K and info["n"] == 7949
    page.evaluate("window.eigendance.renderAt(2.0)")
    for number, image in enumerate(tile_images(page)):
        mask = clay(image)
        assert whole(mask), f"tile {number + 1}: the model is cut or missing"
        rows, columns = np.flatnonzero(mask.any(axis=1)), np.flatnonzero(mask.any(axis=0))
        fill = max((rows[-1] - rows[0]) / len(mask), (columns[-1] - columns[0]) / len(mask[0]))
        assert fill > 0.6, f"tile {number + 1}: the model fills only {fill:.0%} of it"


def test_every_tile_of_the_initial_gallery_moves_and_differently(page, reference):
    """Positions read back per tile over the song: each tile moves by 1–8% of the diagonal
    (as the Python gallery promises, on the song that plays) and no two alike."""
    basis, spectrogram = reference
    mappings = [Mapping.from_json(m) for m in page.evaluate("window.eigendance.mappings()")]
    for measured in gallery_motion(basis, spectrogram, mappings):
        assert 0.01 <= measured.motion <= 0.08
    times = np.linspace(0.2, spectrogram.duration - 0.2, 12).tolist()
    # In the page: each tile's RMS displacement at each time, and every 5th vertex's displacement.
    measured = page.evaluate("""([rest, times, tiles]) => {
        const e = window.eigendance;
        return [...Array(tiles).keys()].map((tile) => times.map((t) => {
            const p = e.readPositions(tile, t);
            let sum = 0;
            const some = [];
            for (let i = 0; i < p.length; i++) {
                const d = p[i] - rest[i];
                sum += d * d;
                if (Math.floor(i / 3) % 5 === 0) some.push(d);
            }
            return [Math.sqrt(sum / (p.length / 3)), some];
        }));
    }""", [basis.vertices.ravel().tolist(), times, len(mappings)])
    fields = []
    for tile, series in enumerate(measured):
        rms = np.array([value for value, _ in series]) / basis.diagonal
        assert rms.max() > 0.008, f"tile {tile + 1} barely moves: {rms.max():.4f}"
        fields.append(np.concatenate([some for _, some in series]))
    fields = np.array(fields)
    norms = np.linalg.norm(fields, axis=1)
    correlations = np.abs(fields @ fields.T / np.outer(norms, norms))
    np.fill_diagonal(correlations, 0)
    assert correlations.max() <= 0.9


def screen_tiles(page):
    """Each tile's view as the person sees it (a screenshot of the page, cut per tile): the
    views' boxes [left, top, right, bottom] and their pictures."""
    image = np.asarray(Image.open(io.BytesIO(page.screenshot())).convert("RGB"), dtype=float)
    boxes = page.eval_on_selector_all(".tile .view", "views => views.map(v => { "
                                      "const r = v.getBoundingClientRect(); "
                                      "return [r.left, r.top, r.right, r.bottom]; })")
    return boxes, [image[int(top):int(bottom), int(left):int(right)]
                   for left, top, right, bottom in boxes]


# The bars that sit over the tiles while they show: the slow-page notice is fixed over the
# page's foot (it covers the lowest tiles' last rows, its shadow some more), the status under
# the bar's right end. A picture with the notice and one without differed in 2.7% of the
# lowest tiles' pixels: more than the cat's highest harmonic moves them.
OVERLAYS = "#notice, #status, #error"
OVERLAY_SHADOW = 24  # px around a bar (the notice's box-shadow: 0 4px 18px)


def overlay_boxes(page) -> list:
    """[left, top, right, bottom] of each bar of OVERLAYS shown now, its shadow included."""
    return page.eval_on_selector_all(OVERLAYS, f"""bars => bars
        .filter(b => b.getClientRects().length && getComputedStyle(b).visibility !== "hidden")
        .map(b => {{ const r = b.getBoundingClientRect(), s = {OVERLAY_SHADOW};
                     return [r.left - s, r.top - s, r.right + s, r.bottom + s]; }})""")


def uncovered(box, shape, overlays) -> np.ndarray:
    """(h, w) bool: the pixels of a tile's picture (its box on the page, its shape) that no
    overlay box covers."""
    left, top = int(box[0]), int(box[1])
    rows = top + np.arange(shape[0])[:, None]
    columns = left + np.arange(shape[1])[None, :]
    free = np.ones(shape[:2], dtype=bool)
    for x0, y0, x1, y1 in overlays:
        free &= ~((rows >= y0) & (rows < y1) & (columns >= x0) & (columns < x1))
    return free


def assert_no_band_cut_out(page):
    """No tile shows a full-width band of the bare page (#15171c) where its backdrop belongs:
    what an opaque bar over the WebGL canvas did (docs/web.md#rendering)."""
    for view in screen_tiles(page)[1]:
        if min(view.shape[:2]) < 8:  # off screen
            continue
        bare = (np.abs(view - [21, 23, 28]).max(axis=-1) <= 2).mean(axis=1) > 0.9
        assert not bare[2:-2].any(), f"rows {np.flatnonzero(bare)} of a tile are not drawn"


def test_every_tile_moves_on_screen_while_a_real_song_plays(browser, live_server):
    """Every tile's pixels over 5 s of playback of a real recording: each one changes."""
    song = songs_of(live_server)[os.path.basename(REAL_SONG)]
    # at full resolution (scale=1): a page slowed by the session's earlier tests lowers its
    # resolution, and the fourth tile's ripple (below) is then under a pixel
    page = open_app(browser, live_server["url"], f"?test&size=4&song={song}&path=cpu&scale=1")
    page.click("#play")
    snapshots, times, played, layout, overlays = [], [], 0.0, None, []
    # at least 5 s of song time, 12 pictures (a loaded machine draws few: the ripple's most
    # different pair may be missed in fewer)
    while len(times) < 12 or played < 5.0:
        page.wait_for_timeout(250)
        info = page.evaluate("window.eigendance.info()")
        if not info["playing"]:  # the end of the recording (4 s): play it again
            page.click("#play")
            continue
        overlays += overlay_boxes(page)
        boxes, tiles = screen_tiles(page)
        overlays += overlay_boxes(page)  # what showed before or after the picture: covered
        after = page.evaluate("window.eigendance.info()")
        if not after["playing"] or after["time"] < info["time"]:
            continue  # the song ended during the picture: it may show the rest pose, paused
        if boxes != layout:  # the slow-page notice moved the tiles: pictures of the new layout
            snapshots, times, played, layout = [], [], 0.0, boxes  # once it has settled
            continue
        if times and info["time"] > times[-1]:
            played += info["time"] - times[-1]
        snapshots.append(tiles)
        times.append(info["time"])
    assert_no_band_cut_out(page)
    page.click("#play")
    for tile in range(4):
        images = [shot[tile] for shot in snapshots]
        free = uncovered(layout[tile], images[0].shape, overlays)
        # The most different pair of pictures (where no bar ever covered the tile): poses far
        # apart in the song.
        changed = max((np.abs(a - b).sum(axis=-1) > 30)[free].mean()
                      for i, a in enumerate(images) for b in images[:i])
        print(f"tile {tile + 1}: {changed:.4f} of its pixels change over {played:.1f} s "
              f"({1 - free.mean():.3f} of it under a bar)")
        # A still tile changes no pixel (0.0000). The test's fourth item is the cat's highest
        # harmonic (k = 24) alone, a ripple, its silhouette's edge moving: 0.01–0.11% of a
        # 350×260 tile between two pictures while the song plays (its loudness swell barely
        # changes on this song, whose three beats are too few for a pulse). The 2% it measured
        # in some runs and not others was a picture of the rest pose (the song ended during
        # the picture), or the notice over a part of its pictures.
        assert changed > 0.0003, f"tile {tile + 1} does not move on screen ({changed:.4f})"
    assert not page.errors, page.errors
    page.close()


def test_gpu_positions_equal_the_python_reference(page, reference):
    """Read back from the float render targets the tiles are drawn from (batched pass)."""
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


def test_breeding_from_an_earlier_generation_keeps_the_later_ones(page):
    first = page.evaluate("window.eigendance.mappings()")
    page.click(".tile[data-index='1'] .view")
    page.click(".tile[data-index='4'] .view")
    assert page.evaluate("window.eigendance.info().selected") == [1, 4]
    assert page.is_enabled("#breed")
    page.evaluate("window.eigendance.breed(1234)")
    info = page.evaluate("window.eigendance.info()")
    assert info["generation"] == 1 and info["generations"] == 2 and info["tiles"] == 6
    second = page.evaluate("window.eigendance.mappings()")
    expected = breed([Mapping.from_json(first[1]), Mapping.from_json(first[4])], 6, 1234)
    assert second == [m.to_json() for m in expected]
    page.click(".tile[data-index='0'] .view")
    page.evaluate("window.eigendance.breed(7)")  # generation 3, from 2
    third = page.evaluate("window.eigendance.mappings()")
    page.click("#back")  # back to 2: breed again there, a branch
    assert page.evaluate("window.eigendance.mappings()") == second
    page.click(".tile[data-index='2'] .view")
    page.click(".tile[data-index='3'] .view")
    page.evaluate("window.eigendance.breed(8)")
    info = page.evaluate("window.eigendance.info()")
    assert info["generations"] == 4 and info["generation"] == 3
    tree = page.evaluate("window.eigendance.generations()")
    assert [(entry["index"], entry["depth"]) for entry in tree] == [(0, 0), (1, 1), (2, 2),
                                                                     (3, 2)]
    assert "bred from 2" in tree[3]["label"]
    assert page.eval_on_selector_all("#generation option", "o => o.length") == 4
    page.select_option("#generation", "2")  # generation 3 is still there
    assert page.evaluate("window.eigendance.mappings()") == third
    page.select_option("#generation", "0")
    assert page.evaluate("window.eigendance.mappings()") == first
    assert len(tiles_at(page, 1.0)) == 6


def test_what_the_player_shows_is_what_animate_writes(page, reference, tmp_path, web_files):
    """The player's gain, smoothing, facet weight and shading are the mapping's: saved from the
    player, `eigendance animate` gives the positions the player showed."""
    basis, spectrogram = reference
    diagonal = np.linalg.norm(np.ptp(basis.to_original(basis.vertices), axis=0))
    page.evaluate("window.eigendance.open(2)")
    saved = page.evaluate("window.eigendance.playerMapping()")
    assert saved["version"] == 3 and saved["look"]["deformed_normal_weight"] == 0.4  # Fig. 6.4(d)
    for selector, value in (("#gain", "1.7"), ("#smoothing", "0.2"), ("#facets", "0.7")):
        page.eval_on_selector(selector, "(e, v) => { e.value = v; "
                                        "e.dispatchEvent(new Event('input')); }", value)
    page.select_option("#shading", "flat")
    assert page.evaluate("window.eigendance.mappings()[2].gain") == 1.7  # the tile's own
    with page.expect_download() as download:
        page.click("#save-mapping")
    path = tmp_path / "from-player.json"
    download.value.save_as(path)
    mapping = Mapping.load(path)
    assert (mapping.gain, mapping.smoothing, mapping.deformed_normal_weight, mapping.shading) \
        == (1.7, 0.2, 0.7, "flat")
    for t in TIMES:
        shown = np.array(page.evaluate(f"window.eigendance.readPositions('player', {t})"))
        error = np.abs(basis.to_original(shown.reshape(-1, 3))
                       - positions_at(basis, spectrogram, mapping, t)).max() / diagonal
        assert error < 1e-4, f"t={t}: {error:.2e} of the diagonal"
    os.environ["EIGENDANCE_CACHE_DIR"] = web_files["cache"]
    assert main(["animate", CAT, web_files["song"], "--mapping", str(path), "-k", str(E2E_K),
                 "--fps", "5", "-o", str(tmp_path / "dance.npz")]) == 0
    animation = load_animation(tmp_path / "dance.npz")
    np.testing.assert_allclose(animation["times"], frame_times(spectrogram.duration, 5))
    for frame in (3, 11, 24):
        t = float(animation["times"][frame])
        shown = np.array(page.evaluate(f"window.eigendance.readPositions('player', {t})"))
        error = np.abs(basis.to_original(shown.reshape(-1, 3))
                       - animation["positions"][frame]).max() / diagonal
        assert error < 1e-4, f"frame {frame}: {error:.2e} of the diagonal"


def test_player_view_and_harmonics_explorer(page):
    page.evaluate("window.eigendance.open(2)")
    assert page.evaluate("window.eigendance.info().view") == "player"
    page.evaluate("window.eigendance.renderAt(1.0)")
    plain = page.screenshot(clip={"x": 300, "y": 150, "width": 500, "height": 400})
    page.fill("#harmonic", "5")
    page.dispatch_event("#harmonic", "input")
    page.evaluate("window.eigendance.renderAt(1.0)")
    coloured = page.screenshot(clip={"x": 300, "y": 150, "width": 500, "height": 400})
    assert plain != coloured
    page.evaluate("window.eigendance.setView('player')")
    assert "harmonic 5" in page.inner_text("#player-info")
    page.fill("#harmonic", "-1")
    page.dispatch_event("#harmonic", "input")
    page.click("#tab-gallery")
    assert page.evaluate("window.eigendance.info().view") == "gallery"


def test_a_narrow_screen_shows_every_model_whole_and_the_player_uncovered(browser,
                                                                           live_server):
    page = open_app(browser, live_server["url"], "?render&size=8", width=390, height=844)
    page.evaluate("window.eigendance.renderAt(1.5)")
    for number, image in enumerate(tile_images(page)):
        assert whole(clay(image)), f"tile {number + 1} is cut at 390 px"
    page.evaluate("window.eigendance.open(0)")
    page.evaluate("window.eigendance.renderAt(1.5)")
    area, controls = (page.eval_on_selector(s, "e => { const r = e.getBoundingClientRect(); "
                                               "return [r.top, r.bottom, r.width]; }")
                      for s in ("#player-area", "#player-controls"))
    assert area[1] <= controls[0] + 0.5 and area[1] - area[0] > 300
    player = np.array(page.evaluate("window.eigendance.playerPixels(2)"), dtype=np.float64)
    width = -(-int(area[2]) // 2)
    assert whole(clay(player.reshape(-1, width, 3)))
    assert not page.errors, page.errors
    page.close()


def test_keys_work_after_a_slider_and_a_new_song_starts_at_zero(browser, live_server):
    page = open_app(browser, live_server["url"], "?test&size=4&path=cpu")
    before = page.evaluate("window.eigendance.info().generations")
    page.click("#volume")  # a slider has the focus now
    page.keyboard.press("Space")
    page.wait_for_function("window.eigendance.info().playing")
    page.wait_for_timeout(600)
    page.keyboard.press("Space")
    assert not page.evaluate("window.eigendance.info().playing")
    assert page.evaluate("window.eigendance.info().time") > 0.3
    page.keyboard.press("p")
    assert page.evaluate("window.eigendance.info().view") == "player"
    page.keyboard.press("g")
    assert page.evaluate("window.eigendance.info().view") == "gallery"
    page.keyboard.press("?")
    assert page.is_visible("#help") and "breed" in page.inner_text("#help")
    page.keyboard.press("Escape")
    assert page.is_hidden("#help")
    page.keyboard.press("m")
    assert page.evaluate("window.eigendance.info().muted")
    page.keyboard.press("m")
    page.eval_on_selector("#seek", "e => { e.value = 2.5; e.dispatchEvent(new Event('input')); }")
    assert page.evaluate("window.eigendance.info().time") == pytest.approx(2.5)
    page.select_option("#song", songs_of(live_server)[os.path.basename(REAL_SONG)])
    page.wait_for_function(f"window.eigendance.info().generations === {before + 1}")
    info = page.evaluate("window.eigendance.info()")
    assert info["time"] == 0 and not info["playing"]  # a new song starts at 0:00
    assert page.input_value("#seek") == "0"
    page.keyboard.press("[")  # the first gallery (of the other song) is still there
    assert page.evaluate("window.eigendance.info().generation") == 0
    assert not page.errors, page.errors
    page.close()


def test_volume_and_mute_leave_the_motion_alone(browser, live_server):
    page = open_app(browser, live_server["url"], "?test&size=4&path=cpu")
    before = page.evaluate("window.eigendance.cpuPositions(1, 1.3)")
    page.eval_on_selector("#volume", "e => { e.value = 0.3; e.dispatchEvent(new Event('input')); }")
    page.click("#mute")
    info = page.evaluate("window.eigendance.info()")
    assert info["volume"] == pytest.approx(0.3) and info["muted"]
    assert page.evaluate("window.eigendance.cpuPositions(1, 1.3)") == before
    page.close()


def test_uploaded_mesh_shows_loading_then_gets_its_gallery(browser, live_server, web_files):
    page = open_app(browser, live_server["url"], "?render&size=4")
    first = page.evaluate("window.eigendance.info().meshId")

    def slow(route):  # the harmonics take a moment to arrive: the indicator shows meanwhile
        page.wait_for_timeout(1500)
        route.continue_()

    page.route("**/basis.bin*", slow)
    page.set_input_files("#upload", web_files["sphere"])
    page.wait_for_selector("#loading", state="visible", timeout=30_000)
    assert "sphere.obj" in page.inner_text("#loading")
    page.wait_for_function(f"window.eigendance.info().meshId !== '{first}' && "
                           "document.getElementById('status').textContent.includes('ready')",
                           timeout=60_000)
    assert page.is_hidden("#loading")
    info = page.evaluate("window.eigendance.info()")
    assert info["n"] == 162 and info["tiles"] == 4
    options = page.eval_on_selector_all("#mesh option", "o => o.map(x => x.textContent)")
    assert "sphere.obj" in options
    page.evaluate("window.eigendance.renderAt(1.0)")
    for image in tile_images(page):
        assert whole(clay(image))
    assert not page.errors, page.errors
    page.close()


def test_a_bad_file_gives_a_full_error_naming_it(browser, live_server, tmp_path):
    page = open_app(browser, live_server["url"], "?render&size=4")
    broken = tmp_path / "my model.obj"
    broken.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\n")  # no triangles
    page.set_input_files("#upload", str(broken))
    page.wait_for_selector("#error", state="visible", timeout=30_000)
    text = page.inner_text("#error-text")
    assert text.startswith("my model.obj could not be added: ") and "triangles" in text
    assert "upload-" not in text
    assert page.get_attribute("#error", "role") == "alert"
    colours = page.eval_on_selector("#error", "e => getComputedStyle(e).backgroundColor")
    assert colours != page.eval_on_selector("#bar", "e => getComputedStyle(e).backgroundColor")
    page.click("#error-close")
    assert page.is_hidden("#error")
    assert page.evaluate("window.eigendance.info().tiles") == 4  # still usable
    page.close()


def test_a_mapping_given_to_serve_shows_in_the_player(browser, web_files, tmp_path, page):
    mapping = Mapping.from_json(page.evaluate("window.eigendance.mappings()")[1])
    mapping.gain = 1.3
    mapping.save(tmp_path / "favourite.json")
    port = free_port()
    env = dict(os.environ, EIGENDANCE_CACHE_DIR=web_files["cache"])
    process = start([sys.executable, "-m", "eigendance.cli", "serve", CAT,
                                web_files["song"], str(tmp_path / "favourite.json"), "-k",
                                str(E2E_K), "--port", str(port)], env=env,
                    stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    try:
        url = process.stdout.readline().split()[-1]
        served = open_app(browser, url, "?render&size=4")
        assert served.evaluate("window.eigendance.info().view") == "player"
        assert served.inner_text("#player-source") == "favourite.json"
        assert served.evaluate("window.eigendance.playerMapping()") == mapping.to_json()
        assert served.input_value("#gain") == "1.3"
        assert not served.errors, served.errors
        served.close()
    finally:
        process.terminate()
        process.wait(10)


def test_the_resolution_follows_the_frame_rate_and_the_page_says_so(browser, live_server):
    """Below the target the page draws at a lower resolution, then fewer triangles, and says
    so beside the frame rate (dynamic resolution)."""
    page = open_app(browser, live_server["url"], "?test&size=16&path=cpu")
    page.click("#play")
    page.wait_for_function("document.getElementById('fps').textContent.includes('fps')",
                           timeout=20_000)
    if not keep_playing(page, "window.eigendance.resolution().scale < 1", 15):
        fps = page.evaluate("window.eigendance.info().fps")
        page.close()
        pytest.skip(f"this machine draws 16 tiles at {fps:.0f} fps: nothing to lower")
    page.wait_for_function("document.getElementById('fps').textContent.includes('%')")
    assert "resolution to keep 12 fps" in page.get_attribute("#fps", "title")
    assert_no_band_cut_out(page)
    page.close()


def test_fewer_tiles_are_offered_when_slow_and_the_page_says_the_new_size(browser,
                                                                          live_server):
    """The readout is the page's real frame rate (frames drawn per second, counted here
    independently). At full resolution (`?scale=1`: nothing left to lower) and below the
    target, the gallery says so and offers fewer tiles. The offer taken, the *tiles* menu and
    the notice say the new size, and a rig's player never has the notice over it.

    `?fps=60` aims at 60 frames per second, which 16 tiles drawn in software never reach: at
    the default 12 this test depended on the machine's speed (CI drew them at 12–13 fps, the
    notice came once and not again after the rig)."""
    page = open_app(browser, live_server["url"], "?test&size=16&path=cpu&scale=1&fps=60")
    page.click("#play")
    page.wait_for_function("document.getElementById('fps').textContent.includes('fps')",
                           timeout=20_000)
    start = page.evaluate("[performance.now(), window.eigendance.info().frames]")
    page.wait_for_timeout(2500)
    end = page.evaluate("[performance.now(), window.eigendance.info().frames]")
    counted = 1000 * (end[1] - start[1]) / (end[0] - start[0])
    shown = float(page.inner_text("#fps").split()[0])
    assert counted > 0 and abs(shown - counted) <= max(1.5, 0.35 * counted), (shown, counted)
    if not keep_playing(page, "!document.getElementById('notice').hidden", 20):
        fps = page.evaluate("window.eigendance.info().fps")
        page.close()
        pytest.skip(f"this machine draws 16 tiles at {fps:.0f} fps: nothing to offer")
    assert "frames per second with 16 tiles" in page.inner_text("#notice-text")
    assert "(it aims at 60)" in page.inner_text("#notice-text")
    page.wait_for_timeout(500)
    assert_no_band_cut_out(page)
    # A rig opens: the notice is about the tiles, it goes (and stays gone in its player).
    mesh = page.evaluate("window.eigendance.info().meshId")
    rigs = page.evaluate("fetch('api/library').then(r => r.json()).then(l => l.rigs)")
    page.evaluate(f"window.eigendance.rig.open('{rigs[0]['id']}')")
    page.evaluate("window.eigendance.rig.setView('player')")
    keep_playing(page, "false", 3.5)
    assert page.is_hidden("#notice")
    page.select_option("#mesh", mesh)  # back to the model's gallery of 16: slow again
    page.wait_for_function("!window.eigendance.rig.info().active")
    page.click("#tab-gallery")
    assert keep_playing(page, "!document.getElementById('notice').hidden", 20)
    offer = int(page.inner_text("#notice-fewer").split()[1])
    assert 2 <= offer < 16
    page.click("#notice-fewer")
    keep_playing(page, f"window.eigendance.info().tiles === {offer}", 30)
    assert page.input_value("#size") == str(offer)  # the menu says what is on screen
    for _ in range(8):  # never again "16 tiles" about the smaller gallery
        keep_playing(page, "false", 0.5)
        assert page.is_hidden("#notice") or f"with {offer} tiles" in page.inner_text(
            "#notice-text")
    page.close()


def keep_playing(page, condition: str, seconds: float) -> bool:
    """Play (again at the song's end: the test song lasts 6 s) until `condition` holds in the
    page; whether it did within `seconds`."""
    for _ in range(int(seconds * 4)):
        if page.evaluate(condition):
            return True
        if not page.evaluate("window.eigendance.info().playing"):
            page.click("#play")
        page.wait_for_timeout(250)
    return bool(page.evaluate(condition))


def test_live_playback_follows_the_audio_clock_and_records_webm_with_audio(browser,
                                                                           live_server):
    page = browser.new_page(viewport={"width": 900, "height": 700}, accept_downloads=True)
    page.goto(live_server["url"] + "?test&size=4&path=cpu")
    page.wait_for_function("window.eigendance && window.eigendance.ready", timeout=60_000)
    page.evaluate("window.eigendance.ready")
    page.click("#tab-player")
    page.click("#record")  # starts playback too
    page.wait_for_function("document.getElementById('clock').textContent === '0:01'",
                           timeout=20_000)
    with page.expect_download() as download:
        page.click("#record")
    assert download.value.suggested_filename == "cat_lowres-dance.webm"
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
    assert info["generations"] == before["generations"] + 1  # calibrated on the new song
    assert page.is_hidden("#drop")
    assert "dropped.wav" in page.eval_on_selector_all("#song option",
                                                      "o => o.map(x => x.textContent)")
    page.close()


def test_playback_stops_at_the_end_of_the_song_and_rewinds(browser, live_server):
    page = open_app(browser, live_server["url"], "?test&size=4&path=cpu")
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
    port = free_port()
    env = dict(os.environ, EIGENDANCE_CACHE_DIR=web_files["cache"])
    process = start([sys.executable, "-m", "eigendance.cli", "serve", "-k", "12",
                                "--port", str(port)], env=env, stdout=subprocess.PIPE,
                    stderr=subprocess.DEVNULL, text=True)
    try:
        url = process.stdout.readline().split()[-1]
        page = open_app(browser, url, "?render&size=4")
        assert "needs a model" in page.inner_text("#status")
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
