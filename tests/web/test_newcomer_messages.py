"""What the page says to a newcomer (issue 30 items 4, 5 and 6), from the user's side: the
loading box above the first-visit help with honest progress, files that are not a model, a song
or a mapping said in those words, and a live input asked for in the address that cannot start.
Each test failed on the build before its fix.

Select with `pytest -m web`; skipped where /usr/bin/chromium is missing.
"""

from __future__ import annotations

import os
import time

import pytest
from web_helpers import CAT, open_app, running_server

from helpers import fixture_path

pytestmark = pytest.mark.web


def test_a_file_that_is_not_a_model_song_or_mapping_is_said_so(browser, live_server, tmp_path):
    page = open_app(browser, live_server["url"], "?test&size=2")
    try:
        notes = tmp_path / "notes.txt"
        notes.write_text("shopping list\n")
        page.set_input_files("#upload", str(notes))
        page.wait_for_selector("#error:not([hidden])", timeout=30_000)
        said = page.text_content("#error-text")
        assert "not a model, a song or a mapping" in said and "models: .obj" in said, said
        assert "content type" not in said and "application/" not in said, said
        page.click("#error-close")
        fake = tmp_path / "song.mp3"
        fake.write_bytes(b"these bytes are no sound at all")
        page.set_input_files("#upload", str(fake))
        page.wait_for_selector("#error:not([hidden])", timeout=30_000)
        assert "not an MP3 file" in page.text_content("#error-text")
    finally:
        page.close()


@pytest.mark.parametrize("query, words", [
    ("?test&source=microphone", "?source=microphone is not a live input"),
    ("?test&source=mic", "Live input:"),  # no audio device in this Chromium
])
def test_a_live_input_asked_in_the_address_that_cannot_start_is_said(browser, live_server,
                                                                      query, words):
    page = open_app(browser, live_server["url"], query)
    try:
        page.wait_for_selector("#error:not([hidden])", timeout=30_000)
        assert words in page.text_content("#error-text")
        assert "the song plays instead" in (page.text_content("#error-text")
                                            + page.text_content("#status"))
    finally:
        page.close()


def test_the_loading_box_shows_above_the_first_visit_help_without_a_false_count(
        browser, web_files, tmp_path):
    model = "/work/shared/data/meshes/bunny_stanford.obj"
    if not os.path.exists(model):
        model = fixture_path("meshes", "fertility.off")
    with running_server([CAT, web_files["song"], "-k", "200"], tmp_path,
                        tmp_path / "cache") as server:
        page = browser.new_page(viewport={"width": 1100, "height": 760})  # a first visit
        try:
            page.goto(server["url"])
            page.wait_for_function("document.getElementById('status').textContent"
                                   ".includes('ready')", timeout=60_000)
            assert page.locator("#help").is_visible()
            page.set_input_files("#upload", model)
            page.wait_for_function("document.getElementById('loading-text').textContent"
                                   ".includes('harmonics')", timeout=60_000)
            shown = []
            end = time.monotonic() + 4
            while time.monotonic() < end and page.locator("#loading").is_visible():
                shown.append(page.text_content("#loading-text"))
                box = page.locator("#loading").bounding_box()
                if box is None:  # hidden since: the solve is done
                    break
                on_top = page.evaluate(
                    "([x, y]) => document.getElementById('loading')"
                    ".contains(document.elementFromPoint(x, y))",
                    [box["x"] + box["width"] / 2, box["y"] + box["height"] / 2])
                assert on_top, "the help covers the loading box"
                time.sleep(0.1)
            assert not any("(0 of" in text for text in shown), shown
        finally:
            page.close()
