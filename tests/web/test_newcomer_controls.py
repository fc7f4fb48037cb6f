"""What a newcomer reaches for (issue 30 item 10), from the user's side: loop, full screen, a
camera reset, download names that say what they hold, the rig's *save mapping* tooltip, and a
library with a song and no model. Each test failed on the build before its fix.

Select with `pytest -m web`; skipped where /usr/bin/chromium is missing.
"""

from __future__ import annotations

import json

import numpy as np
import pytest
from test_newcomer_page import open_rig_from_menu
from web_helpers import open_app, running_server

pytestmark = pytest.mark.web


def test_loop_plays_the_song_again_at_its_end(browser, live_server):
    page = open_app(browser, live_server["url"], "?test&size=4&path=cpu")
    try:
        page.click("#loop")
        assert page.get_attribute("#loop", "aria-pressed") == "true"
        duration = page.evaluate("window.eigendance.info().duration")
        page.eval_on_selector("#seek", "(seek, t) => { seek.value = t; "
                                       "seek.dispatchEvent(new Event('input')); }", duration - 0.6)
        page.click("#play")
        # Past the end it plays on from the start: the clock goes back and ❚❚ stays.
        page.wait_for_function("Number(document.getElementById('seek').value) < 0.5 && "
                               "Number(document.getElementById('seek').value) > 0",
                               timeout=20_000)
        assert page.text_content("#play") == "❚❚"
        page.keyboard.press("l")  # off again: the song stops at its end
        assert page.get_attribute("#loop", "aria-pressed") == "false"
        assert not page.errors, page.errors
    finally:
        page.close()


def test_f_goes_full_screen_and_reset_view_brings_the_camera_back(browser, live_server):
    page = open_app(browser, live_server["url"], "?render&size=4&view=player")
    try:
        page.keyboard.press("f")
        page.wait_for_function("document.fullscreenElement !== null", timeout=5_000)
        page.keyboard.press("f")
        page.wait_for_function("document.fullscreenElement === null", timeout=5_000)
        page.evaluate("window.eigendance.renderAt(1)")
        framed = np.array(page.evaluate("window.eigendance.playerPixels(4)"))
        box = page.locator("#player-area").bounding_box()
        x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
        page.mouse.move(x, y)
        page.mouse.down()
        page.mouse.move(x + 200, y + 60, steps=8)
        page.mouse.up()
        page.mouse.wheel(0, 600)
        page.evaluate("window.eigendance.renderAt(1)")
        turned = np.array(page.evaluate("window.eigendance.playerPixels(4)"))
        assert np.mean(np.abs(turned - framed) > 24) > 0.01, "the drag turned the camera"
        page.click("#reset-view")
        page.evaluate("window.eigendance.renderAt(1)")
        again = np.array(page.evaluate("window.eigendance.playerPixels(4)"))
        assert np.mean(np.abs(again - framed) > 24) < 0.002
        assert not page.errors, page.errors
    finally:
        page.close()


def test_downloads_are_named_after_the_model(browser, live_server):
    page = open_app(browser, live_server["url"], "?test&size=4&path=cpu")
    try:
        with page.expect_download() as tile:
            page.locator("#tiles .save").nth(1).click()
        assert tile.value.suggested_filename == "cat_lowres-g1-2.json"
        page.locator("#tiles .open").nth(1).click()
        with page.expect_download() as player:
            page.click("#save-mapping")
        name = player.value.suggested_filename
        assert name.startswith("cat_lowres-") and name.endswith(".json"), name
        open_rig_from_menu(page, live_server["url"], "hand")
        assert "version 3" in page.get_attribute("#rig-save", "title")
        page.locator("#rig-tiles .rig-tile .caption").nth(1).click()
        page.click("#rig-combine")
        with page.expect_download() as rig:
            page.click("#rig-save")
        assert rig.value.suggested_filename == "hand-modes-2.json"
        assert json.load(open(rig.value.path()))["version"] == 3
        assert not page.errors, page.errors
    finally:
        page.close()


def test_a_song_without_a_model_does_not_show_a_rig_s_name(browser, web_files, tmp_path):
    """`serve song.wav`: the model menu says there is no model, not "loop4" over an empty page;
    choosing a rig there still opens it."""
    with running_server([web_files["song"], "-k", "12"], tmp_path, web_files["cache"]) as server:
        page = open_app(browser, server["url"], "?test")
        try:
            assert "needs a model" in page.text_content("#status")
            shown = page.locator("#mesh option:checked").text_content()
            assert "no model" in shown, shown
            open_rig_from_menu(page, server["url"], "loop4")
            assert page.locator("#rig-tiles .rig-tile").count() > 0
            assert not page.errors, page.errors
        finally:
            page.close()


def test_a_rig_chosen_with_no_song_says_it_needs_one_and_opens_once_one_comes(browser,
                                                                            web_files,
                                                                            tmp_path):
    """`eigendance serve` with no file, a built-in rig chosen in the model menu: the page said
    "Could not show this rig: no song with id ''" in red. It says the rig needs a song, and the
    song then added opens the rig chosen (before: "the library needs a model")."""
    with running_server(["-k", "12"], tmp_path, web_files["cache"]) as server:
        page = open_app(browser, server["url"], "?test")
        try:
            page.select_option("#mesh", label="loop4")
            page.wait_for_function("document.getElementById('status').textContent"
                                   ".includes('needs a song')", timeout=20_000)
            assert page.text_content("#status").startswith("loop4 needs a song to dance to")
            assert page.is_hidden("#error"), page.text_content("#error-text")
            page.set_input_files("#upload", web_files["song"])
            page.wait_for_function("document.querySelectorAll('#rig-tiles .rig-tile').length > 0"
                                   " && window.eigendance.rig.info().name === 'loop4'",
                                   timeout=60_000)
            assert page.is_hidden("#error"), page.text_content("#error-text")
            assert not page.errors, page.errors
        finally:
            page.close()


def test_the_slow_page_notice_agrees_with_the_readout_and_moves_no_tile(browser, live_server):
    """Item 8: without a GPU, 16 tiles at full resolution are slow: the notice's frame rate is
    the readout's, and its coming moves neither the tiles nor the help button. `?fps=60`: a
    target software drawing never reaches (at 12 a 2-core machine skipped this test)."""
    page = open_app(browser, live_server["url"], "?test&size=16&path=cpu&scale=1&fps=60")
    try:
        def places():
            return [page.locator(selector).bounding_box() for selector in
                    ("#tiles > *:first-child", "#tiles > *:last-child", "#help-button")]
        page.click("#play")
        page.wait_for_function("document.getElementById('fps').textContent.includes('fps')",
                               timeout=20_000)
        before = places()
        try:
            page.wait_for_function("!document.getElementById('notice').hidden",
                                   timeout=25_000)
        except Exception:  # noqa: BLE001 - a fast machine has nothing to say
            pytest.skip("this machine draws 16 tiles fast enough: no notice")
        assert places() == before
        compared = 0
        for _ in range(40):  # a loaded machine's readout and notice come and go
            readout, notice, shown = page.evaluate(
                "[document.getElementById('fps').textContent, "
                "document.getElementById('notice-text').textContent, "
                "!document.getElementById('notice').hidden]")
            if readout.split() and shown:  # the readout is blank between its refreshes
                assert f"only {readout.split()[0]} frames per second" in notice, \
                    (readout, notice)
                compared += 1
                if compared == 3:
                    break
            page.wait_for_timeout(400)
        assert compared >= 1  # the notice may go once the rate recovers
    finally:
        page.close()


def test_the_session_survives_a_reload_and_a_file(browser, live_server, tmp_path):
    """Item 10 / the session: bred generations and the selection come back after a reload; a
    saved session file, opened in a fresh browser, brings the generations back."""
    page = open_app(browser, live_server["url"], "?test&size=4&path=cpu")
    try:
        for tile in (0, 2):
            page.locator("#tiles > *").nth(tile).click(position={"x": 5, "y": 5})
        page.click("#breed")
        page.wait_for_function("document.getElementById('generation').options.length === 2",
                               timeout=60_000)
        page.locator("#tiles > *").nth(1).click(position={"x": 5, "y": 5})
        bred = page.evaluate("window.eigendance.mappings()")
        page.reload()
        page.wait_for_function("window.eigendance && window.eigendance.ready", timeout=60_000)
        page.evaluate("window.eigendance.ready")
        assert page.locator("#generation option").count() == 2
        assert page.evaluate("window.eigendance.mappings()") == bred
        assert page.locator("#tiles > .selected").count() == 1
        with page.expect_download() as saved:
            page.click("#save-session")
        session = tmp_path / saved.value.suggested_filename
        saved.value.save_as(session)
        assert saved.value.suggested_filename == "cat_lowres-session.json"
    finally:
        page.close()
    fresh = open_app(browser, live_server["url"], "?test&size=4&path=cpu")  # empty storage
    try:
        assert fresh.locator("#generation option").count() == 1
        fresh.set_input_files("#open-session", str(session))
        fresh.wait_for_function("document.getElementById('generation').options.length === 2",
                                timeout=30_000)
        assert fresh.evaluate("window.eigendance.mappings()") == bred
        assert not fresh.errors, fresh.errors
    finally:
        fresh.close()


def rig_state(page) -> dict:
    """What the rig's galleries and player show: the generations in the menu, the dance tiles'
    labels and which are selected, and the player's amplitude sliders."""
    page.click("#tab-gallery")
    page.click("#rig-show-dances")
    return {"generations": page.locator("#rig-generation option").all_text_contents(),
            "shown": page.locator("#rig-generation").input_value(),
            "labels": page.locator("#rig-tiles .caption").all_text_contents(),
            "selected": page.locator("#rig-tiles .rig-tile.selected").count(),
            "amplitudes": page.locator("#rig-palette input.amplitude").evaluate_all(
                "(all) => all.map((el) => el.value)"),
            "mapping": page.evaluate("window.eigendance.rig.playerMapping()")}


def test_a_rigs_palette_and_dances_survive_a_reload_and_a_file(browser, live_server, tmp_path):
    """The session holds the rigs too: a palette set in the built-in hand's player and a bred
    generation of its dances come back after a reload, and from a saved session file in a
    fresh browser."""
    url = live_server["url"]
    page = open_app(browser, url, "?test&size=4&path=cpu")
    try:
        open_rig_from_menu(page, url, "hand")
        page.click("#tab-player")
        page.locator("#rig-palette input.amplitude").first.evaluate(
            "(el) => { el.value = 12.5; el.dispatchEvent(new Event('input')); }")
        page.click("#tab-gallery")
        page.click("#rig-show-dances")
        tiles = page.locator("#rig-tiles .rig-tile .caption")
        tiles.nth(0).click()
        tiles.nth(2).click()
        page.click("#rig-breed")
        page.wait_for_function("document.getElementById('rig-generation').options.length === 2",
                               timeout=60_000)
        page.locator("#rig-tiles .rig-tile .caption").nth(1).click()
        before = rig_state(page)
        assert len(before["generations"]) == 2 and before["selected"] == 1
        assert before["amplitudes"][0] == "12.5"
        page.reload()
        page.wait_for_function("window.eigendance && window.eigendance.ready", timeout=60_000)
        page.evaluate("window.eigendance.ready")
        open_rig_from_menu(page, url, "hand")
        assert page.locator("#rig-show-modes.active").is_visible()  # the modes' bar
        with page.expect_download() as saved:
            page.click("#rig-save-session")  # there too, not only in the dances' bar
        assert rig_state(page) == before
        session = tmp_path / saved.value.suggested_filename
        saved.value.save_as(session)
        assert saved.value.suggested_filename == "hand-session.json"
        rigs = json.loads(session.read_text())["rigs"]
        assert [len(rig["generations"]) for rig in rigs.values()] == [2]
        assert not page.errors, page.errors
    finally:
        page.close()
    fresh = open_app(browser, url, "?test&size=4&path=cpu")  # empty storage
    try:
        open_rig_from_menu(fresh, url, "hand")
        assert len(rig_state(fresh)["generations"]) == 1
        fresh.set_input_files("#rig-open-session", str(session))
        fresh.wait_for_function("document.getElementById('rig-generation').options.length === 2",
                                timeout=30_000)
        assert rig_state(fresh) == before
        assert not fresh.errors, fresh.errors
    finally:
        fresh.close()
