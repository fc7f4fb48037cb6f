"""The song as a newcomer meets it (issue 30, the usage report): the session keeps the song chosen
and where it was left (a reload and a saved file come back to it, paused); choosing a rig or
switching its views keeps the song playing; a song that stops at its end says so.

Select with `pytest -m web`; skipped where /usr/bin/chromium is missing.
"""

from __future__ import annotations

import os

import pytest
from test_newcomer_page import open_rig_from_menu
from web_helpers import REAL_SONG, open_app

pytestmark = pytest.mark.web

QUERY = "?test&size=4&path=cpu"


def song_shown(page) -> tuple[str, str]:
    """The song the song menu names, and the transport's clock."""
    return (page.eval_on_selector("#song", "(menu) => menu.selectedOptions[0].textContent"),
            page.text_content("#clock"))


def seek_to(page, seconds: float) -> None:
    """Drag the seek bar to `seconds`, as a person does."""
    page.eval_on_selector("#seek", "(seek, t) => { seek.value = t; "
                                   "seek.dispatchEvent(new Event('input')); }", seconds)


def wait_for_song(page, name: str, clock: str) -> None:
    page.wait_for_function(
        "([name, clock]) => document.getElementById('song').selectedOptions[0]?.textContent "
        "=== name && document.getElementById('clock').textContent === clock",
        arg=[name, clock], timeout=60_000)


def test_the_session_keeps_the_song_and_where_it_was_left(browser, live_server, tmp_path):
    """After a reload the song chosen comes back (not the library's first), paused where it was
    left; a saved session file brings it back in a fresh browser too."""
    real = os.path.basename(REAL_SONG)
    page = open_app(browser, live_server["url"], QUERY)
    try:
        first = song_shown(page)
        assert first == ("song.wav", "0:00")
        page.select_option("#song", label=real)
        page.wait_for_function("document.getElementById('generation').options.length === 2",
                               timeout=60_000)  # a first generation calibrated on the new song
        seek_to(page, 2.5)
        wait_for_song(page, real, "0:02")
        page.reload()
        page.wait_for_function("window.eigendance && window.eigendance.ready", timeout=60_000)
        page.evaluate("window.eigendance.ready")
        wait_for_song(page, real, "0:02")
        assert page.text_content("#play") == "▶"  # paused: a reload does not start the sound
        with page.expect_download() as saved:
            page.click("#save-session")
        session = tmp_path / saved.value.suggested_filename
        saved.value.save_as(session)
        assert not page.errors, page.errors
    finally:
        page.close()
    fresh = open_app(browser, live_server["url"], QUERY)  # empty storage: the first song
    try:
        assert song_shown(fresh) == first
        fresh.set_input_files("#open-session", str(session))
        wait_for_song(fresh, real, "0:02")
        assert fresh.locator("#generation option").count() == 2  # the file's generations
        assert not fresh.errors, fresh.errors
    finally:
        fresh.close()


def assert_playing_on(page) -> None:
    """The transport plays: ❚❚ shows and the seek bar moves on."""
    at = page.eval_on_selector("#seek", "(seek) => seek.value")
    page.wait_for_function("(at) => document.getElementById('seek').value !== at", arg=at,
                           timeout=20_000)
    assert page.text_content("#play") == "❚❚"


def test_choosing_a_rig_and_its_views_keeps_the_song_playing(browser, live_server):
    """The usage report: choosing a rig, its *dances* and *modes*, its player and gallery, while
    the song plays (looping, so its end never falls inside the test): the clock runs on."""
    url = live_server["url"]
    page = open_app(browser, url, QUERY)
    try:
        page.click("#loop")
        page.click("#play")
        assert_playing_on(page)
        open_rig_from_menu(page, url, "hand")
        assert_playing_on(page)
        for control in ("#rig-show-dances", "#rig-show-modes", "#tab-player", "#tab-gallery"):
            page.click(control)
            assert_playing_on(page)
        assert not page.errors, page.errors
    finally:
        page.close()


def test_a_song_that_ends_says_so(browser, live_server):
    """In the report the song reached its end while a rig was chosen and read as "choosing a
    rig stops the song": at its end (no loop) the page says the song ended, until ▶."""
    url = live_server["url"]
    page = open_app(browser, url, QUERY)
    try:
        open_rig_from_menu(page, url, "hand")
        duration = page.evaluate("window.eigendance.info().duration")
        seek_to(page, duration - 0.6)
        page.click("#play")
        page.wait_for_function("document.getElementById('status').textContent"
                               ".includes('the song ended')", timeout=20_000)
        assert page.text_content("#play") == "▶"
        assert page.text_content("#clock") == "0:00"
        page.click("#play")
        page.wait_for_function("!document.getElementById('status').textContent"
                               ".includes('the song ended')", timeout=20_000)
        assert not page.errors, page.errors
    finally:
        page.close()
