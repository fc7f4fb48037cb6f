"""Several files given to the page at once (issue 23 item 5), through the *add* input as a person
chooses them: a .gltf with its .bin, an OBJ with its MTL — each arrives as one model in its
materials, listed once; a file the reader cannot read (FBX) shows the reader's one line on how to
convert it."""

from __future__ import annotations

import json
import shutil
import urllib.request

import pytest
from web_helpers import CAT, open_app, running_server

from helpers import fixture_path

pytestmark = pytest.mark.web


@pytest.fixture(scope="module")
def page(browser, web_files, tmp_path_factory):
    folder = tmp_path_factory.mktemp("upload-page")
    with running_server([CAT, web_files["song"], "-k", "12"], folder,
                        web_files["cache"]) as server:
        page = open_app(browser, server["url"], "?test", 900, 640)
        page.url_of_server = server["url"]
        yield page
        page.close()


def library(page) -> dict:
    with urllib.request.urlopen(page.url_of_server + "api/library") as answer:
        return json.load(answer)


def add(page, *paths) -> dict:
    """Choose files in the *add* input; wait until the model they make is on screen."""
    before = page.evaluate("window.eigendance.info().meshId")
    page.set_input_files("#upload", list(paths))
    page.wait_for_function(f"(() => {{ const i = window.eigendance.info(); return i.error || "
                           f"(i.meshId !== '{before}' && i.look); }})()", timeout=120_000)
    return page.evaluate("window.eigendance.info()")


@pytest.mark.parametrize("files, name, materials", [
    (("craft_speederD.gltf", "craft_speederD_data.bin"), "craft_speederD.gltf", 4),
    (("robot.obj", "robot.mtl"), "robot.obj", 3),
])
def test_a_model_in_several_files_arrives_whole(page, files, name, materials):
    info = add(page, *(fixture_path("textured", file) for file in files))
    assert info["error"] is None, info["error"]
    assert len(info["look"]["materials"]) == materials
    listed = [mesh for mesh in library(page)["meshes"] if mesh["name"] == name]
    assert len(listed) == 1 and listed[0]["id"] == info["meshId"]


def test_an_fbx_shows_how_to_convert_it(page, tmp_path):
    fbx = tmp_path / "Stag.fbx"
    fbx.write_bytes(b"Kaydara FBX Binary  \x00\x1a\x00" + bytes(64))
    page.set_input_files("#upload", str(fbx))
    page.wait_for_function("window.eigendance.info().error", timeout=30_000)
    error = page.evaluate("window.eigendance.info().error")
    assert error.startswith("Stag.fbx could not be added") and "glTF" in error
    assert "Blender" in error and "\n" not in error


def test_a_model_in_several_files_is_ready_under_its_own_name(page, tmp_path):
    """Found using the page (issue 30): the status named the .zip the page made of the files
    ("craft_speederD.zip ready") while the menu named the model."""
    shutil.copy(fixture_path("textured", "robot.obj"), tmp_path / "walker.obj")
    shutil.copy(fixture_path("textured", "robot.mtl"), tmp_path / "robot.mtl")
    if page.locator("#error").is_visible():  # an earlier test's
        page.click("#error-close")
    info = add(page, tmp_path / "walker.obj", tmp_path / "robot.mtl")
    assert info["error"] is None, info["error"]
    page.wait_for_function("document.getElementById('status').textContent.includes('ready')",
                           timeout=30_000)
    assert page.text_content("#status") == "walker.obj ready"
