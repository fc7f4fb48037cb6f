"""The page's chrome as a newcomer finds it (issue 30 items 5 and 8), from the user's side: the
FBX advice on one line, a header whose height does not change as the page goes from loading to
ready to playing. Each test failed on the build before its fix.

Select with `pytest -m web`; skipped where /usr/bin/chromium is missing.
"""

from __future__ import annotations

import pytest
from web_helpers import open_app

pytestmark = pytest.mark.web

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
