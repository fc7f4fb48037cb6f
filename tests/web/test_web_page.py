"""The page's options and failures in headless Chromium: the test hooks only in `?render` /
`?test` mode, the gallery-size rule from `api/config` (the server's, the only one), and request
failures shown in full as errors with the page still usable (no unhandled rejection).

Select with `pytest -m web`; skipped where /usr/bin/chromium is missing.
"""

from __future__ import annotations

import json
from collections.abc import Callable

import pytest

pytestmark = pytest.mark.web
READY = "document.getElementById('status').textContent.includes('ready')"
ANNOUNCEMENT = "eigendance: test hooks on window.eigendance"


def answer(code: int, body) -> Callable:
    """A route handler answering `code` with the JSON `body` instead of the server."""
    return lambda route: route.fulfill(status=code, content_type="application/json",
                                       body=json.dumps(body))


def open_page(browser, url, query, routes=()):
    """The app at `url + query`, with (pattern, status, body) answers replacing the server's;
    waits until the status line says ready."""
    page = browser.new_page(viewport={"width": 1000, "height": 700})
    page.errors, page.console = [], []
    page.on("pageerror", lambda error: page.errors.append(str(error)))
    page.on("console", lambda message: page.console.append(message.text))
    for pattern, code, body in routes:
        page.route(pattern, answer(code, body))
    page.goto(url + query)
    page.wait_for_function(READY, timeout=60_000)
    return page


def status(page) -> str:
    return page.inner_text("#status")


def error(page) -> str:
    """The error banner's text ('' when none is shown)."""
    return "" if page.is_hidden("#error") else page.inner_text("#error-text")


def tile_count(page) -> int:
    return page.eval_on_selector_all(".tile", "tiles => tiles.length")


def size_menu(page) -> list[int]:
    return [int(text) for text in
            page.eval_on_selector_all("#size option", "o => o.map(x => x.textContent)")]


def test_hooks_only_in_render_or_test_mode_and_announced(browser, live_server):
    page = open_page(browser, live_server["url"], "?size=4&path=cpu")
    assert tile_count(page) == 4
    assert page.evaluate("window.eigendance === undefined")
    assert ANNOUNCEMENT not in page.console
    assert not page.errors, page.errors
    page.close()
    page = open_page(browser, live_server["url"], "?test&size=4&path=cpu")
    assert page.evaluate("window.eigendance.info().tiles") == 4
    assert page.console.count(ANNOUNCEMENT) == 1
    assert not page.errors, page.errors
    page.close()


def test_tiles_menu_is_built_from_the_servers_rule(browser, live_server):
    rule = {"gallery": {"min": 2, "max": 10, "default": 6}}
    page = open_page(browser, live_server["url"], "?test&path=cpu",
                     [("**/api/config", 200, rule)])
    assert size_menu(page) == [4, 5, 6, 7, 8, 9, 10]
    assert page.input_value("#size") == "6" and tile_count(page) == 6
    page.close()
    page = open_page(browser, live_server["url"], "?test&path=cpu&size=2")
    assert size_menu(page) == [2, *range(4, 17)]  # ?size= may go below the menu's 4
    assert page.input_value("#size") == "2" and tile_count(page) == 2
    assert not page.errors, page.errors
    page.close()


@pytest.mark.parametrize("size", ["abc", "40", "1", "6.5"])
def test_a_size_outside_the_rule_falls_back_to_the_default_with_a_message(browser, live_server,
                                                                          size):
    page = open_page(browser, live_server["url"], f"?test&path=cpu&size={size}")
    assert f"?size={size} is not a gallery size" in status(page)
    assert "from 2 to 16" in page.get_attribute("#status", "title")
    assert tile_count(page) == 8 and page.input_value("#size") == "8"
    assert not page.errors, page.errors
    page.close()


def test_a_failing_config_request_is_shown_and_the_page_still_starts(browser, live_server):
    page = open_page(browser, live_server["url"], "?test&path=cpu&size=5",
                     [("**/api/config", 500, {"error": "config exploded"})])
    assert "config exploded" in error(page)
    assert tile_count(page) == 5 and size_menu(page) == [5]
    assert not page.errors, page.errors
    page.close()
    # Without the rule the server checks ?size= (one rule), and the page shows its default.
    page = browser.new_page(viewport={"width": 1000, "height": 700})
    page.route("**/api/config", answer(500, {"error": "config exploded"}))
    page.goto(live_server["url"] + "?test&path=cpu&size=40")
    page.wait_for_function("window.eigendance && window.eigendance.info().tiles === 8",
                           timeout=60_000)
    assert "2 to 16 items" in error(page)
    page.close()


def test_failing_gallery_and_breed_requests_show_the_servers_message(browser, live_server):
    page = open_page(browser, live_server["url"], "?test&path=cpu&size=4")
    before = page.evaluate("window.eigendance.mappings()")
    # The gallery: the server's error in the status line, the tiles and menu as they were.
    page.route("**/api/gallery", answer(400, {"error": "no gallery of that size today"}))
    page.select_option("#size", "6")
    page.wait_for_function("document.getElementById('error-text').textContent"
                           ".includes('no gallery of that size today')", timeout=20_000)
    assert error(page) == "Could not make the gallery: no gallery of that size today"
    assert page.input_value("#size") == "4" and tile_count(page) == 4
    assert page.evaluate("window.eigendance.mappings()") == before
    # Breeding: the same, then the page is still usable once the server answers again.
    page.route("**/api/breed", answer(400, {"error": "parents do not agree"}))
    page.click(".tile[data-index='1'] .view")
    page.click("#breed")
    page.wait_for_function("document.getElementById('error-text').textContent"
                           ".includes('parents do not agree')", timeout=20_000)
    assert page.evaluate("window.eigendance.info().generations") == 1
    page.unroute("**/api/breed")
    page.click("#breed")
    page.wait_for_function("window.eigendance.info().generations === 2", timeout=20_000)
    assert tile_count(page) == 4
    assert not page.errors, page.errors
    page.close()
