"""The page says what is true (issue 22 item 2): each stumble a newcomer met, as a person meets
it in headless Chromium — the status line while the song plays, the gallery's grid, the rig
labels, the dances, the help on a phone, what a reload shows, the export panel's defaults.
(The slow-page notice and its offer: test_web_browser.py; the recording's size:
test_web_recording.py.)"""

from __future__ import annotations

import json

import numpy as np
import pytest
from web_helpers import CAT, E2E_K, open_app, rig_ids_at, running_server

from eigendance.modal.rig import Rig
from eigendance.modal.sample_rigs import sample_rig
from eigendance.music.mapping import Mapping

pytestmark = pytest.mark.web


def test_the_status_line_stops_saying_press_play_once_the_song_plays(browser, live_server):
    page = open_app(browser, live_server["url"], "?test&size=2&path=cpu")
    assert "press ▶" in page.inner_text("#status")
    page.click("#play")
    page.wait_for_function("window.eigendance.info().playing")
    page.wait_for_timeout(300)
    assert "press ▶" not in page.inner_text("#status")
    page.click("#play")
    assert not page.errors, page.errors
    page.close()


def rows_of(page, selector: str) -> list[int]:
    """Tiles per row of the grid, top to bottom (by their top edges)."""
    tops = page.eval_on_selector_all(selector, "tiles => tiles.map(t => "
                                               "Math.round(t.getBoundingClientRect().top))")
    return [tops.count(top) for top in sorted(set(tops))]


def test_no_gallery_leaves_a_tile_alone_on_a_row(browser, live_server):
    """Every size of the tiles menu: the last row at least half full (16: 4 × 4, not
    5 + 5 + 5 + 1), the columns those of the video renderer's grid; on a phone (two columns)
    an odd last tile spans the row."""
    page = open_app(browser, live_server["url"], "?render&size=16", 1280, 800)
    grids = {}
    for size in (16, 9, 11, 4, 12, 5):
        if size != 16:  # the page opened with 16
            made = page.evaluate("window.eigendance.info().generations")
            page.select_option("#size", str(size))
            page.wait_for_function(f"window.eigendance.info().generations === {made + 1}")
        assert page.evaluate("window.eigendance.info().tiles") == size
        rows = rows_of(page, ".tile")
        assert sum(rows) == size and 2 * rows[-1] >= rows[0], f"{size} tiles: rows {rows}"
        assert page.input_value("#size") == str(size)
        grids[size] = rows[0]
    from eigendance.export.renderer import gallery_columns

    assert grids == {size: gallery_columns(size) for size in grids}
    # A phone shows two columns: the odd last tile (5 tiles on screen) takes the whole row.
    page.set_viewport_size({"width": 390, "height": 844})
    page.wait_for_timeout(200)
    widths = page.eval_on_selector_all(".tile", "tiles => tiles.map(t => "
                                                "t.getBoundingClientRect().width)")
    assert rows_of(page, ".tile") == [2, 2, 1] and widths[-1] > 1.8 * widths[0], widths
    assert not page.errors, page.errors
    page.close()


def test_the_help_title_wraps_before_the_close_button_on_a_phone(browser, live_server):
    page = open_app(browser, live_server["url"], "?render", 390, 844)
    page.click("#help-button")
    overlap = page.evaluate("""() => {
        const close = document.getElementById('help-close').getBoundingClientRect();
        const range = document.createRange();
        range.selectNodeContents(document.getElementById('help-title'));
        return [...range.getClientRects()].some(r => r.right > close.left
            && r.left < close.right && r.bottom > close.top && r.top < close.bottom);
    }""")
    assert not overlap, "the help title runs under the ✕"
    page.close()


def test_rig_frequencies_are_shown_as_played_everywhere(browser, live_server):
    """One convention: a mode's frequency as played (natural × time scale), labelled with the
    time scale, on its tile, in the palette and in the rig's line (loop16: s = 1.77)."""
    url = live_server["url"]
    page = open_app(browser, url, "?test&path=cpu", 1100, 760)
    page.evaluate(f"window.eigendance.rig.open('{rig_ids_at(url)['loop16']}')")
    mapping = page.evaluate("window.eigendance.rig.playerMapping()")
    scale = mapping["modes"]["time_scale"]
    rig = Rig.from_skeleton(sample_rig("loop16"))
    played = rig.model.frequencies * scale
    suffix = f" ({f'×{scale:.2f}'} time scale)"
    labels = page.evaluate("window.eigendance.rig.labels()")
    assert labels[0] == f"mode 1 · {played[0]:.2f} Hz{suffix}"
    page.evaluate("window.eigendance.rig.select(1); window.eigendance.rig.combine()")
    rows = page.eval_on_selector_all("#rig-palette .name", "names => names.map(n => "
                                                           "n.textContent)")
    assert rows == [f"mode 2 · {played[1]:.2f} Hz{suffix}"]
    assert f"lowest mode {played[0]:.2f} Hz{suffix}" in page.inner_text("#rig-info")
    assert not page.errors, page.errors
    page.close()


def test_each_dance_says_what_it_drives_and_loop4s_dances_differ(browser, live_server):
    url = live_server["url"]
    page = open_app(browser, url, "?test&path=cpu", 1100, 760)
    page.evaluate(f"window.eigendance.rig.open('{rig_ids_at(url)['loop8']}')")
    page.evaluate("window.eigendance.rig.setMode('dances')")
    labels = page.evaluate("window.eigendance.rig.labels()")
    dances = page.evaluate("window.eigendance.rig.info().tiles")
    mappings = [Mapping.from_json(page.evaluate(
        f"window.eigendance.rig.openDance({i}).then(() => window.eigendance.rig.playerMapping())"))
        for i in range(dances)]
    for label, mapping in zip(labels, mappings, strict=True):
        k = len(mapping.modes.selected)
        targets = np.unique(mapping.harmonic_indices(k))
        driven = sorted(int(mapping.modes.selected[t]) + 1
                        for t in targets if mapping.amplification_for(k)[t] != 0)
        shown = label.split(" · ")[1]
        numbers = [int(n) for part in shown.split(" ", 1)[1].split(", ")
                   for n in (range(int(part.split("–")[0]), int(part.split("–")[1]) + 1)
                             if "–" in part else [part])]
        assert numbers == driven, (label, driven)
    assert len(set(labels)) > 1, labels  # not every dance "modes 1–5"
    # loop4 has one mode: its dances must still differ (their own tempo and phase).
    page.evaluate(f"window.eigendance.rig.open('{rig_ids_at(url)['loop4']}')")
    page.evaluate("window.eigendance.rig.setMode('dances')")
    # (the ring stands on its floor, which holds its sway small: docs/design.md#the-floor)
    times = [[np.array(p) for p in page.evaluate(f"window.eigendance.rig.readTiles({t})")]
             for t in (1.3, 2.7)]
    for i in range(len(times[0])):
        for j in range(i):
            apart = max(np.abs(tiles[i] - tiles[j]).max() for tiles in times)
            assert apart > 5e-4, f"dances {j + 1} and {i + 1}"
    assert not page.errors, page.errors
    page.close()


def test_the_export_panel_starts_where_the_song_is_for_15_seconds(browser, live_server):
    """Defaults of the player's export: the current position and 15 s, cut at the song's end;
    in the gallery there is nothing to export."""
    page = open_app(browser, live_server["url"], "?test&size=2&path=cpu")
    page.eval_on_selector("#seek", "(seek) => { seek.value = 1.5; "
                                   "seek.dispatchEvent(new Event('input')); }")
    page.click("#tab-player")
    page.click("#export-open")
    assert page.is_visible("#export-panel")
    request = page.evaluate("window.eigendance.exportRequest()")
    duration = page.evaluate("window.eigendance.info().duration")
    assert request["start"] == pytest.approx(1.5, abs=0.01)
    assert request["duration"] == pytest.approx(min(15.0, duration - 1.5), abs=0.01)
    assert request["format"] == "mp4" and request["mapping"] == page.evaluate(
        "window.eigendance.playerMapping()")
    page.click("#tab-gallery")
    assert page.is_hidden("#export-panel")
    page.close()


@pytest.fixture(scope="module")
def own_server(web_files, tmp_path_factory):
    """A server of its own: these tests change its library (a dropped mapping, a rig's
    pose)."""
    folder = tmp_path_factory.mktemp("truth")
    with running_server([CAT, web_files["song"], "-k", str(E2E_K)], folder,
                        web_files["cache"]) as server:
        yield server


def test_a_reload_starts_in_the_gallery_after_a_mapping_was_dropped(browser, own_server,
                                                                    tmp_path):
    """What a reload restores: the library (the mapping stays in the menu), not the view — a
    mapping dropped in the page opened the player then, a reload shows the gallery."""
    page = open_app(browser, own_server["url"], "?test&size=2&path=cpu")
    mapping = page.evaluate("window.eigendance.mappings()")[1]
    path = tmp_path / "dropped.json"
    path.write_text(json.dumps(mapping))
    page.set_input_files("#upload", str(path))
    page.wait_for_function("window.eigendance.info().view === 'player'")
    page.reload()
    page.wait_for_function("window.eigendance && window.eigendance.ready")
    page.evaluate("window.eigendance.ready")
    assert page.evaluate("window.eigendance.info().view") == "gallery"
    assert "dropped.json" in page.eval_on_selector_all("#mapping-menu option",
                                                       "o => o.map(x => x.textContent)")
    page.close()


def test_a_reload_says_that_a_rigs_pose_edits_were_kept(browser, own_server):
    url = own_server["url"]
    chain = rig_ids_at(url)["chain"]
    page = open_app(browser, url, "?test&size=2&path=cpu")
    page.evaluate(f"window.eigendance.rig.open('{chain}')")
    assert page.evaluate("window.eigendance.rig.pose(0, [0, 0, 0.5])") is None
    page.reload()
    page.wait_for_function("window.eigendance && window.eigendance.ready")
    page.evaluate("window.eigendance.ready")
    page.evaluate(f"window.eigendance.rig.open('{chain}')")
    assert "edited" in page.inner_text("#status")
    assert "edited" in page.evaluate("window.eigendance.rig.info().info")
    assert page.evaluate("window.eigendance.rig.reset()") is None
    page.evaluate(f"window.eigendance.rig.open('{chain}')")
    assert "edited" not in page.inner_text("#status")
    page.close()

