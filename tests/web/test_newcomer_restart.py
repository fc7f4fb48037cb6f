"""The page's session across a restart of `serve` (issue 30: "a session survives a reload"):
`serve` run again on the same files gives its models and songs new ids, and a reload found
none of them in the session kept in the browser — every bred generation was gone. The kept
session now names what it holds and a reload finds each by its name, as *open session* does
with a file; what is not served any more is said in one line. Failed before the fix.

Select with `pytest -m web`; skipped where /usr/bin/chromium is missing.
"""

from __future__ import annotations

import pytest
from web_helpers import CAT, free_port, open_app, running_server, write_song

pytestmark = pytest.mark.web


def ready(page) -> None:
    page.wait_for_function("window.eigendance && window.eigendance.ready", timeout=60_000)
    page.evaluate("window.eigendance.ready")


def shown(page) -> dict:
    """What the gallery shows: the generations, the one chosen, the tiles selected, the song."""
    tiles = page.locator("#tiles > *")
    return {"generations": page.locator("#generation option").all_text_contents(),
            "chosen": page.locator("#generation option:checked").text_content(),
            "selected": [i for i in range(tiles.count())
                         if "selected" in (tiles.nth(i).get_attribute("class") or "")],
            "song": page.locator("#song option:checked").text_content()}


def test_bred_generations_survive_a_restart_of_serve_and_a_reload(browser, web_files, tmp_path):
    """Breed on the second song, select a child, stop `serve`, start it again on the same files
    and port, reload: the generations, the selection and the song are there. Then `serve`
    without that song: a reload says so in one line."""
    other = write_song(tmp_path / "other.wav", seconds=5.0)
    both = [CAT, web_files["song"], other, "-k", "12"]
    port = free_port()  # the same origin: the same storage in the browser
    with running_server(both, tmp_path, web_files["cache"], port=port) as first:
        page = open_app(browser, first["url"], "?test&size=4")
        page.select_option("#song", label="other.wav")  # a first generation calibrated on it
        count = "document.querySelectorAll('#generation option').length == "
        page.wait_for_function(count + "2", timeout=60_000)  # song.wav's first, other.wav's
        tiles = page.locator("#tiles > *")
        tiles.nth(0).click()
        tiles.nth(1).click()
        page.click("#breed")
        page.wait_for_function(count + "3", timeout=60_000)
        tiles.nth(2).click()
        before = shown(page)
        assert "bred from 2" in before["chosen"] and before["selected"] == [2], before
    try:
        with running_server(both, tmp_path, web_files["cache"], port=port):
            page.reload()
            ready(page)
            after = shown(page)
            assert after == before, (before, after)
            assert page.locator("#error").is_hidden(), page.text_content("#error")
        with running_server([CAT, web_files["song"], "-k", "12"], tmp_path, web_files["cache"],
                            port=port):
            page.reload()
            ready(page)
            banner = page.text_content("#error")
            assert page.locator("#error").is_visible() and "not served any more: other.wav" \
                in banner, banner
            assert len(page.locator("#generation option").all_text_contents()) == 3
        assert not page.errors, page.errors
    finally:
        page.close()
