"""The page's remove buttons (issue 12): each sends DELETE for the item in its menu; the menus
lose it, the page moves on to a model or song that is left, and the last one cannot be removed."""

from __future__ import annotations

import numpy as np
import pytest
from web_helpers import CAT, E2E_K, library_at, open_app, running_server

from eigendance.music.mapping import Mapping

pytestmark = pytest.mark.web


@pytest.fixture
def own_server(web_files, tmp_path):
    """A server of its own (the session's `live_server` must keep its library)."""
    mapping = tmp_path / "calm.json"
    Mapping(np.linspace(0, 1, 8), np.full(E2E_K, 0.01), name="calm.json").save(mapping)
    with running_server([CAT, web_files["sphere"], web_files["song"], str(mapping), "-k",
                         str(E2E_K)], tmp_path, web_files["cache"]) as server:
        yield server


def menu(page, select_id: str) -> list[str]:
    """The names in a menu; for the model menu only the meshes (its group of rigs follows)."""
    return page.evaluate(f"[...document.getElementById('{select_id}').options]"
                         ".filter((o) => !o.value.startsWith('rig:')).map((o) => o.textContent)")


def test_remove_buttons_take_items_out_of_the_library_and_the_menus(browser, own_server):
    url = own_server["url"]
    page = open_app(browser, url, "?test&path=cpu&size=2&view=gallery")
    try:
        assert menu(page, "mesh") == ["cat_lowres.obj", "sphere.obj"]
        first = page.evaluate("window.eigendance.info().meshId")
        # The model on screen goes: the other one is shown, with a gallery of its own.
        page.click("#remove-mesh")
        page.wait_for_function("document.getElementById('status').textContent"
                               ".includes('removed from the library')", timeout=60_000)
        assert page.evaluate("window.eigendance.info().meshId") != first
        assert menu(page, "mesh") == ["sphere.obj"]
        assert [m["name"] for m in library_at(url)["meshes"]] == ["sphere.obj"]
        assert page.evaluate("window.eigendance.info().tiles") == 2
        # The last model and the only song stay: their buttons are disabled and say why.
        for kind in ("mesh", "song"):
            button = page.locator(f"#remove-{kind}")
            assert button.is_disabled() and "add another" in button.get_attribute("title")
        # The mapping menu disappears with its last mapping.
        assert menu(page, "mapping-menu") == ["calm.json"]
        page.evaluate("window.eigendance.setView('player')")
        page.click("#remove-mapping")
        page.wait_for_function("document.getElementById('remove-mapping').hidden",
                               timeout=10_000)
        assert library_at(url)["mappings"] == []
        assert page.evaluate("window.eigendance.info().error") is None
        # Removed on purpose, the model is not missed by a reload (the session forgot it).
        page.reload()
        page.wait_for_function("window.eigendance && window.eigendance.ready", timeout=60_000)
        page.evaluate("window.eigendance.ready")
        assert page.locator("#error").is_hidden(), page.text_content("#error")
        assert menu(page, "mesh") == ["sphere.obj"]
        assert page.errors == []
    finally:
        page.close()
