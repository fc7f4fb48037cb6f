"""The page's chrome as a newcomer finds it (issue 30 items 5 and 8), from the user's side: the
FBX advice on one line, a header whose height does not change as the page goes from loading to
ready to playing, one row wide enough to read its frame-rate readout whole (with a song and
with a live input), a textured model at 25% of its triangles that looks as at 100%. Each test
failed on the build before its fix.

Select with `pytest -m web`; skipped where /usr/bin/chromium is missing.
"""

from __future__ import annotations

import io
import time

import numpy as np
import pytest
from chromium import FAKE, GRANT, launch
from PIL import Image
from web_helpers import fake_clip, open_app, running_server

from helpers import fixture_path

pytestmark = pytest.mark.web
CLIP = fixture_path("audio", "kevin_macleod_vibe_ace_0s-21s.ogg")

LINES = """id => { const text = document.getElementById(id);
  const line = parseFloat(getComputedStyle(text).lineHeight);
  return text.getBoundingClientRect().height / line; }"""


@pytest.mark.parametrize("width", [1100, 1280])
def test_the_fbx_advice_is_one_line(browser, live_server, tmp_path, width):
    """Item 5: an FBX dropped without Blender gets its advice on one line of the error banner."""
    page = open_app(browser, live_server["url"], "?test&size=2", width=width)
    try:
        fbx = tmp_path / "Stag.fbx"
        fbx.write_bytes(b"Kaydara FBX Binary  \x00\x1a\x00" + bytes(64))
        page.set_input_files("#upload", str(fbx))
        page.wait_for_selector("#error:not([hidden])", timeout=30_000)
        said = page.text_content("#error-text")
        assert "Blender" in said and "glTF" in said, said
        assert page.evaluate(LINES, "error-text") < 1.5, said
    finally:
        page.close()


# The header's height at every change of its box or of what it says, from the first layout on.
HEIGHTS = """() => { window.heights = []; const bar = document.getElementById('bar');
  const note = () => window.heights.push([bar.getBoundingClientRect().height,
    document.getElementById('status').textContent, document.getElementById('fps').textContent]);
  new ResizeObserver(note).observe(bar);
  new MutationObserver(note).observe(bar, {childList: true, characterData: true,
                                           subtree: true}); }"""


@pytest.mark.parametrize("width", [1100, 1280, 1440])
def test_the_header_keeps_its_height_from_loading_to_playing(browser, live_server, width):
    """Item 8: the header's height, measured at every change of its box from the page's first
    layout through "making the gallery…", "ready", playing (the frame-rate readout shows),
    paused, the player and back, is one height (within a pixel)."""
    page = browser.new_page(viewport={"width": width, "height": 760})
    page.add_init_script("localStorage.setItem('eigendance-help-seen', '1')")
    page.add_init_script("addEventListener('DOMContentLoaded', " + HEIGHTS + ")")
    try:
        page.goto(live_server["url"] + "?test&size=4")
        page.wait_for_function("document.getElementById('status').textContent.includes('ready')",
                               timeout=60_000)
        page.click("#play")
        page.wait_for_function("document.getElementById('fps').textContent.includes('fps')",
                               timeout=60_000)
        page.click("#play")
        page.click("#tab-player")
        page.click("#tab-gallery")
        page.evaluate("new Promise((done) => requestAnimationFrame(() => setTimeout(done, 300)))")
        heights = page.evaluate("window.heights")
        said = {(status, fps) for _, status, fps in heights}
        assert any("ready" in status for status, _ in said), said
        assert max(h for h, *_ in heights) - min(h for h, *_ in heights) <= 1, heights
    finally:
        page.close()


# Whether the header is one row that holds everything it shows: every control's middle within
# 3 px of the others', every control inside the page's width, and each readout's text whole (not cut
# by its ellipsis); and the header's height.
ONE_ROW = """() => { const bar = document.getElementById('bar');
  const shown = [...bar.children].filter((e) => e.id !== 'status' && e.offsetParent !== null
    && e.getBoundingClientRect().width > 0);
  const boxes = shown.map((e) => e.getBoundingClientRect());
  const cut = ['fps', 'live-info'].map((id) => document.getElementById(id))
    .filter((e) => e.offsetParent !== null && e.scrollWidth > e.clientWidth + 1)
    .map((e) => e.textContent);
  return {height: bar.getBoundingClientRect().height,
          middles: boxes.map((b) => Math.round(b.top + b.height / 2)),
          outside: shown.filter((e, i) => boxes[i].right > innerWidth)
            .map((e) => e.id || e.tagName),
          cut, fps: document.getElementById('fps').textContent}; }"""


@pytest.mark.parametrize("width", [1100, 1280, 1440])
def test_the_header_is_one_row_with_its_frame_rate_readable(browser, live_server, width):
    """Item 8 (round 3): at 1100, 1280 and 1440 px, a page drawing at 65% of its resolution and
    a quarter of the triangles while it plays says both in its frame-rate readout, whole (it
    once read "6.4 fps at 65% resoluti…" on a second row at 1280 px), on one header row."""
    page = open_app(browser, live_server["url"], "?test&size=4&scale=0.65", width=width)
    try:
        page.evaluate("window.eigendance.setDetail(0.25)")
        page.click("#play")
        page.wait_for_function("document.getElementById('fps').textContent.includes('25%')",
                               timeout=60_000)
        row = page.evaluate(ONE_ROW)
        page.click("#play")
        assert "65%" in row["fps"] and not row["cut"], row
        assert max(row["middles"]) - min(row["middles"]) <= 3, row
        assert not row["outside"], row
    finally:
        page.close()


@pytest.mark.parametrize("width", [1280, 1440])
def test_the_live_input_header_is_one_row(browser, live_server, tmp_path, width):
    """Use (round 3): with `?source=mic` the header took three rows (94 px) at 1100 px and two
    at 1280; now it is one row, as high as the song's header at the same width, with the live
    readout (tempo, latency) whole and the input's name in the song menu."""
    song = open_app(browser, live_server["url"], "?test&size=2", width=width)
    song_height = song.evaluate(ONE_ROW)["height"]
    song.close()
    clip = fake_clip(str(tmp_path), CLIP, seconds=8)
    launched = launch(browser.browser_type, *FAKE, GRANT,
                      f"--use-file-for-fake-audio-capture={clip}")
    try:
        page = launched.new_page(viewport={"width": width, "height": 760})
        page.goto(live_server["url"] + "?test&size=2&source=mic")
        page.wait_for_function("window.eigendance && window.eigendance.ready", timeout=60_000)
        page.evaluate("window.eigendance.ready")
        page.wait_for_function("document.getElementById('live-info').textContent.includes("
                               "'latency')", timeout=60_000)
        row = page.evaluate(ONE_ROW)
        menu = page.eval_on_selector("#song", "menu => menu.selectedOptions[0].textContent")
        assert max(row["middles"]) - min(row["middles"]) <= 3 and not row["outside"], row
        assert not row["cut"], row
        assert abs(row["height"] - song_height) <= 1, (row, song_height)
        assert "Fake" in menu, menu  # Chromium's fake device's name
    finally:
        launched.close()


def test_a_textured_model_at_a_quarter_of_its_triangles_looks_as_it_does_whole(
        browser, web_files, tmp_path):
    """Item 8: MorphStressTest's first tile (paused, so the same pose) at 25% of the triangles
    (what a slow page draws) against 100%: the mean grey-level difference stays under 0.45
    (0.65 when the simplifier weighed positions alone and slid vertices across the texture;
    0.33 with the UVs and normals in its error)."""
    model = fixture_path("textured", "MorphStressTest.gltf")
    with running_server([model, web_files["song"], "-k", "24"], tmp_path,
                        tmp_path / "cache") as server:
        page = open_app(browser, server["url"], "?test&size=2&scale=1", 1000, 600)
        try:
            assert page.evaluate("window.eigendance.info().look")
            shots = []
            for fraction in (1, 0.25):
                page.evaluate(f"window.eigendance.setDetail({fraction})")
                page.wait_for_function(f"window.eigendance.resolution().detail === {fraction}")
                time.sleep(1)  # a few frames drawn at that detail
                png = page.locator("#tiles > *:first-child").screenshot()
                shots.append(np.asarray(Image.open(io.BytesIO(png)).convert("L"), float))
            difference = float(np.abs(shots[0] - shots[1]).mean())
            assert 0 < difference < 0.45, difference
        finally:
            page.close()


# The rows of a bar: its visible children's vertical centres, those within 10 px of one
# another one row (a label's text sits a few pixels below a button's).
ROWS = """id => { const rows = [];
  for (const child of document.getElementById(id).querySelectorAll(':scope > *')) {
    const box = child.getBoundingClientRect(), middle = box.top + box.height / 2;
    if (box.width > 0 && !rows.some(row => Math.abs(row - middle) < 10)) rows.push(middle); }
  return rows.length; }"""
# Each file input's own box as drawn: the browser's "Choose File · No file chosen" is unseen,
# its label drawn as a button (a border), and clicking the label reaches the input.
FILE_BUTTONS = """() => [...document.querySelectorAll('label.upload')]
  .filter(label => label.offsetParent !== null).map(label => {
  const input = label.querySelector('input[type=file]');
  const style = getComputedStyle(label);
  return [input.id, getComputedStyle(input).opacity, style.borderTopStyle,
          label.getBoundingClientRect().height]; })"""


def test_the_bars_are_one_row_with_buttons_for_files(browser, live_server):
    """Seen at the last stop: the gallery's bar wrapped onto a second row at 1280 px, its
    *open session* and *add* the browser's bare file inputs ("Choose File · No file chosen");
    the rig bar as well. Both are one row of buttons now (this failed before: 2 rows)."""
    page = open_app(browser, live_server["url"], "?test&size=8", width=1280)
    try:
        assert page.evaluate(ROWS, "gallery-controls") == 1
        shown = page.evaluate(FILE_BUTTONS)
        assert {"open-session", "upload"} <= {name for name, *_ in shown}
        with page.expect_file_chooser() as chooser:  # the label opens the file picker
            page.click("label.upload:has(#upload)")
        assert chooser.value.is_multiple()
        page.click("#tab-player")
        shown += page.evaluate(FILE_BUTTONS)
        assert "load-mapping" in {name for name, *_ in shown}
        for name, opacity, border, height in shown:
            assert opacity == "0" and border == "solid" and 15 < height < 40, name
        rigs = page.evaluate("fetch('api/library').then(r => r.json()).then(l => l.rigs)")
        page.evaluate(f"window.eigendance.rig.open('{rigs[0]['id']}')")
        page.evaluate("window.eigendance.rig.setView('gallery')")
        page.wait_for_selector("#rig-gallery-view:not([hidden])")
        assert page.evaluate(ROWS, "rig-gallery-controls") == 1
        assert [name for name, *_ in page.evaluate(FILE_BUTTONS)] == ["rig-open-session"]
    finally:
        page.close()
