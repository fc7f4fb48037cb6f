"""Rigs from files in the page (issue 23 items 4 and 7): `eigendance serve RIG.glb SONG` opens
the rig's gallery of modes, and in the gallery of modes of every rig — the fixtures
(tests/fixtures/rigged: skinned, with props on bones, Draco, textured) and the shared rigs
where the checkout has them (../shared/data/rigged) — every tile moves at least 0.1% of its
pixels, and each rig wears every material its file's meshes name; the Draco astronaut shows the
colours three.js's GLTFLoader draws (tests/web/test_look_page.py's reference).
"""

from __future__ import annotations

import base64
import glob
import json
import os
import urllib.request

import numpy as np
import pytest
from test_look_page import histogram, hues, model_pixels, reference_picture
from test_look_server import gltf_json_and_buffer
from web_helpers import open_app, running_server

from helpers import fixture_path

pytestmark = pytest.mark.web
REPO = os.path.join(os.path.dirname(__file__), "..", "..")
SHARED = next((path for path in (os.path.join(REPO, "..", "shared", "data", "rigged"),
                                 os.path.join(REPO, "..", "..", "shared", "data", "rigged"))
               if os.path.isdir(path)), "")  # the shared rigs, where the checkout has them
PATHS = {os.path.basename(path): path for path in
         [*(glob.glob(os.path.join(SHARED, "*.gl*")) if SHARED else ()),
          *glob.glob(fixture_path("rigged", "*.gl*"))]}
RIGS = sorted(PATHS)
# The tile test's motion: each tile's largest share of pixels changing by more than 24 levels
# between two of these times, at laptop size (1280×800) where a finger's mode moves ~30 px.
TIMES = (0.2, 0.45, 0.7, 0.95)


def tile_motion(page, rig: str = "rig") -> list[float]:
    """Per mode tile of the rig on screen, the share of its pixels that change over TIMES
    (hooks `rig.renderAt`, `rig.tileBytes`); at 1280×800."""
    hooks = f"window.eigendance.{rig}"
    viewport = page.viewport_size
    page.set_viewport_size({"width": 1280, "height": 800})
    try:
        frames = []
        for t in TIMES:
            page.evaluate(f"{hooks}.renderAt({t})")
            frames.append([np.frombuffer(base64.b64decode(p), np.uint8).astype(float)
                           for p in page.evaluate(f"{hooks}.tileBytes(2)")])
    finally:
        page.set_viewport_size(viewport)
    return [max(np.mean(np.abs(frames[a][tile] - frames[b][tile]) > 24)
                for a in range(len(TIMES)) for b in range(a))
            for tile in range(len(frames[0]))]


def file_materials(path: str) -> set[str]:
    """The names of the materials the file's mesh primitives use, from the glTF JSON (unnamed:
    "material i", as the reader names them)."""
    document, _ = gltf_json_and_buffer(path)
    used = {primitive["material"] for mesh in document.get("meshes", [])
            for primitive in mesh["primitives"] if "material" in primitive}
    return {document["materials"][i].get("name") or f"material {i}" for i in used}


@pytest.fixture(scope="module")
def served(web_files, tmp_path_factory):
    """`eigendance serve` of a rig with a gun on its hand first, every other rig and a song."""
    folder = tmp_path_factory.mktemp("rig-files")
    first = "quaternius_Character_Gun.glb"
    paths = [PATHS[first], *(PATHS[name] for name in RIGS if name != first)]
    with running_server([*paths, web_files["song"]], folder, web_files["cache"]) as server:
        with urllib.request.urlopen(server["url"] + "api/library") as answer:
            library = json.load(answer)
        server["library"] = library
        yield server


@pytest.fixture(scope="module")
def page(browser, served):
    page = open_app(browser, served["url"], "?test&path=gpu", 760, 520)
    yield page
    assert not page.errors, page.errors
    page.close()


def test_a_skinned_gltf_given_first_opens_as_a_rig_listed_once(served, page):
    library = served["library"]
    first = library["first"]
    rig_names = {rig["id"]: rig["name"] for rig in library["rigs"]}
    assert first["kind"] == "rig" and rig_names[first["id"]] == "quaternius_Character_Gun.glb"
    assert not library["meshes"]  # each skinned glTF is a rig, listed once
    assert sorted(name for name in rig_names.values() if name.endswith((".glb", ".gltf"))) \
        == RIGS
    info = page.evaluate("window.eigendance.rig.info()")
    assert info["active"] and info["name"] == "quaternius_Character_Gun.glb"
    assert info["error"] is None and info["tiles"] == 16
    assert page.evaluate("window.eigendance.rig.look()")["materials"]  # its own materials
    assert page.evaluate("document.getElementById('status').textContent").startswith("ready")


@pytest.mark.parametrize("name", RIGS)
def test_every_mode_tile_of_every_rig_moves(served, page, name):
    rig_id = next(rig["id"] for rig in served["library"]["rigs"] if rig["name"] == name)
    assert page.evaluate(f"window.eigendance.rig.open('{rig_id}')") is None
    motion = tile_motion(page)
    look = page.evaluate("window.eigendance.rig.look()")
    print(f"{name}: least moving tile {min(motion):.4f} of its pixels "
          f"({len(motion)} tiles), materials {look and look['materials']}")
    named = file_materials(PATHS[name])
    if named:  # the file's own materials, read here from its JSON
        assert look is not None and named <= set(look["materials"]), (named, look)
    for tile, changed in enumerate(motion):
        assert changed > 0.001, f"{name}: tile {tile + 1} does not move ({changed:.4f})"


def test_the_lbs_skin_wears_the_rigs_materials_too(served, page):
    """Linear blend skinning (three.js SkinnedMesh) of the character with a gun: in its blue
    materials, and in clay when the switch says so."""
    rig_id = next(rig["id"] for rig in served["library"]["rigs"]
                  if rig["name"] == "quaternius_Character_Gun.glb")
    assert page.evaluate(f"window.eigendance.rig.open('{rig_id}')") is None
    page.evaluate("window.eigendance.rig.select(0)")
    page.evaluate("window.eigendance.rig.combine()")
    page.evaluate("window.eigendance.rig.setSkinning('lbs')")
    means = {}
    try:
        for materials in (True, False):
            page.evaluate(f"window.eigendance.rig.setMaterials({str(materials).lower()})")
            page.evaluate("window.eigendance.rig.renderAt(0.5)")
            pixels = np.array(page.evaluate("window.eigendance.rig.playerPixels(3)"),
                              dtype=float).reshape(-1, 3)
            model = pixels[pixels.max(axis=1) > 90]  # brighter than the backdrop
            means[materials] = model.mean(axis=0)
    finally:
        page.evaluate("window.eigendance.rig.setSkinning('modal')")
        page.evaluate("window.eigendance.rig.setMaterials(true)")
        page.evaluate("window.eigendance.setView('gallery')")
    print(f"LBS skin, mean colour: materials {means[True].round()}, clay {means[False].round()}")
    assert means[True][2] > means[True][0] + 20  # blue
    assert means[False][0] > means[False][2] + 20  # clay


def test_the_draco_astronaut_shows_the_colours_three_js_draws(browser, served, page,
                                                              gltf_reference):
    """The textured, Draco-compressed astronaut in the rig player (at laptop size): the hues of
    its texture as three.js's GLTFLoader draws the file (the reference page), not the clay's.
    The hue histograms are spread over their neighbouring bins (±20°) before they are compared:
    the frog's green lies on a bin's edge, and the page's posed, faceted model sways across it."""
    rig_id = next(rig["id"] for rig in served["library"]["rigs"]
                  if rig["name"] == "quaternius_Astronaut_FinnTheFrog.glb")
    assert page.evaluate(f"window.eigendance.rig.open('{rig_id}')") is None
    page.evaluate("window.eigendance.rig.select(0)")
    page.evaluate("window.eigendance.rig.combine()")
    shown = {}
    viewport = page.viewport_size
    page.set_viewport_size({"width": 1280, "height": 800})
    try:
        for materials in (True, False):
            page.evaluate(f"window.eigendance.rig.setMaterials({str(materials).lower()})")
            page.evaluate("window.eigendance.rig.renderAt(0.5)")
            pixels = np.array(page.evaluate("window.eigendance.rig.playerPixels(2)"),
                              dtype=float).reshape(1, -1, 3) / 255
            shown["ours" if materials else "clay"] = model_pixels(pixels)
    finally:
        page.set_viewport_size(viewport)
        page.evaluate("window.eigendance.rig.setMaterials(true)")
        page.evaluate("window.eigendance.setView('gallery')")
    shown["three.js"] = model_pixels(reference_picture(browser, gltf_reference, "astronaut.glb"))
    counts = {name: sum(np.roll(histogram(hues(pixels)), shift) for shift in (-1, 0, 1)) / 3
              for name, pixels in shown.items()}
    overlap = np.minimum(counts["ours"], counts["three.js"]).sum()
    clay_overlap = np.minimum(counts["clay"], counts["three.js"]).sum()
    means = {name: (pixels.mean(axis=0) * 255).round() for name, pixels in shown.items()}
    print(f"astronaut: hue histogram overlap with three.js: ours {overlap:.2f}, clay "
          f"{clay_overlap:.2f}; mean colours {means}; saturated pixels "
          f"{ {name: len(hues(pixels)) for name, pixels in shown.items()} }")
    assert min(len(hues(pixels)) for pixels in shown.values()) > 200
    assert overlap > 0.75 and clay_overlap < 0.3


def test_the_lbs_skin_ripples_in_its_materials(served, page):
    """The surface on the LBS skin of the character with a gun, in its materials: the drawn
    vertices carry the skin's morph targets (gathered from the welded ones), so the picture
    changes with the surface; no shader error is logged."""
    logged = []
    page.on("console", lambda message: logged.append(message.text)
            if message.type == "error" else None)
    rig_id = next(rig["id"] for rig in served["library"]["rigs"]
                  if rig["name"] == "quaternius_Character_Gun.glb")
    assert page.evaluate(f"window.eigendance.rig.open('{rig_id}')") is None
    page.evaluate("window.eigendance.rig.setView('player'); "
                  "window.eigendance.rig.setSkinning('lbs')")
    switch = """(on) => { const box = document.getElementById('rig-surface');
      box.checked = on; box.dispatchEvent(new Event('change')); }"""
    pictures = {}
    try:
        for on in (False, True):
            page.evaluate(switch, on)
            page.wait_for_function(f"document.getElementById('rig-surface-dance').disabled "
                                   f"=== {str(not on).lower()}", timeout=120_000)
            page.evaluate("window.eigendance.rig.renderAt(1.3)")
            pictures[on] = np.array(page.evaluate("window.eigendance.rig.playerPixels(3)"),
                                    dtype=float)
    finally:
        page.evaluate(switch, False)
        page.evaluate("window.eigendance.rig.setSkinning('modal')")
        page.evaluate("window.eigendance.setView('gallery')")
    changed = np.mean(np.abs(pictures[True] - pictures[False]) > 40)
    print(f"gun rig, LBS in materials: {changed:.4f} of the pixels change with the surface")
    assert changed > 0.002 and not logged, (changed, logged)
