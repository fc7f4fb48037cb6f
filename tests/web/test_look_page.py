"""What a person sees of a textured model (issue 23 items 1 and 8): the page draws a model in its
own materials and textures, whose colours are those of three.js's own GLTFLoader render of the
same file (tests/web/gltf_reference.html, lit as three.js's glTF viewer lights it) — not the
clay's — and the clay stays one switch away.

Colours are compared where the model is (pixels brighter or more saturated than the studio's
dark backdrop): their hue histograms (saturated pixels) and their mean colour. Each colour of
the model's swatch texture (read here with Pillow) shows in the page's picture.
"""

from __future__ import annotations

import colorsys
import io
import json
import urllib.request

import numpy as np
import pytest
from PIL import Image
from test_look_server import gltf_json_and_buffer, image_bytes
from web_helpers import open_app, running_server

from eigendance.music.mapping import Mapping
from helpers import fixture_path

pytestmark = pytest.mark.web
MODEL = fixture_path("textured", "MorphStressTest.gltf")
WIDTH, HEIGHT = 640, 400
HUE_BINS = 18  # 20° each


@pytest.fixture(scope="module")
def served(web_files, tmp_path_factory):
    """`eigendance serve MorphStressTest.gltf SONG still.json`: a mapping that holds the model
    at rest (amplification 0), so the page shows what GLTFLoader shows."""
    folder = tmp_path_factory.mktemp("look-page")
    Mapping(np.linspace(0, 1, 64), np.zeros(24), name="still.json").save(folder / "still.json")
    with running_server([MODEL, web_files["song"], str(folder / "still.json"), "-k", "24"],
                        folder, web_files["cache"]) as server:
        yield server


def picture(png: bytes) -> np.ndarray:
    return np.asarray(Image.open(io.BytesIO(png)).convert("RGB"), dtype=float) / 255


def model_pixels(image: np.ndarray) -> np.ndarray:
    """(N, 3) the pixels of the model: brighter or more saturated than the dark backdrop
    (#121418 … #2b303b) and its shadow."""
    value = image.max(axis=2)
    saturation = (value - image.min(axis=2)) / np.maximum(value, 1e-6)
    return image[(value > 0.3) | ((saturation > 0.35) & (value > 0.15))]


def hues(pixels: np.ndarray) -> np.ndarray:
    """Hues in degrees of the saturated pixels (saturation > 0.3)."""
    value, low = pixels.max(axis=1), pixels.min(axis=1)
    saturated = pixels[(value - low) / np.maximum(value, 1e-6) > 0.3]
    return np.array([colorsys.rgb_to_hsv(*p)[0] * 360 for p in saturated])


def histogram(angles: np.ndarray) -> np.ndarray:
    counts, _ = np.histogram(angles, bins=HUE_BINS, range=(0, 360))
    return counts / max(counts.sum(), 1)


def page_picture(browser, url: str, mapping_id: str, materials: bool, path: str = "cpu",
                 t: float = 0.0, tile: int | None = None) -> np.ndarray:
    """The player's picture at time t: the still mapping, or gallery tile `tile` opened."""
    page = open_app(browser, url, f"?render&bare&view=player&path={path}&mapping={mapping_id}",
                    WIDTH, HEIGHT)
    try:
        page.wait_for_function("window.eigendance.info().k > 0", timeout=120_000)
        assert page.evaluate("window.eigendance.look()")["images"] == 3
        if tile is not None:
            page.evaluate(f"window.eigendance.open({tile})")
        page.evaluate(f"window.eigendance.setMaterials({'true' if materials else 'false'})")
        page.evaluate(f"window.eigendance.renderAt({t})")
        return picture(page.screenshot())
    finally:
        assert not page.errors, page.errors
        page.close()


def reference_picture(browser, url: str, model: str) -> np.ndarray:
    """three.js GLTFLoader's picture of `model` (a file the reference server holds)."""
    page = browser.new_page(viewport={"width": WIDTH, "height": HEIGHT})
    try:
        page.goto(url)
        page.wait_for_function("window.ready === true", timeout=30_000)
        page.evaluate(f"window.draw('{model}', {WIDTH}, {HEIGHT})")
        return picture(page.screenshot())
    finally:
        page.close()


def swatch_hues() -> list[float]:
    """The hues of the swatch texture's saturated colours (the file's own image)."""
    document, buffer = gltf_json_and_buffer(MODEL)
    index = next(i for i, image in enumerate(document["images"])
                 if image.get("name") == "ColorSwatches")
    data = image_bytes(document, buffer, index)
    colors = np.asarray(Image.open(io.BytesIO(data)).convert("RGB"), dtype=float).reshape(-1, 3)
    return sorted({round(float(h)) for h in hues(np.unique(colors, axis=0) / 255)})


def test_a_textured_model_shows_its_texture_colours_as_three_js_draws_them(
        browser, served, gltf_reference):
    with urllib.request.urlopen(served["url"] + "api/library") as answer:
        mapping_id = json.load(answer)["mappings"][0]["id"]
    ours = page_picture(browser, served["url"], mapping_id, True)
    clay = page_picture(browser, served["url"], mapping_id, False)
    theirs = reference_picture(browser, gltf_reference, "model.gltf")
    regions = {name: model_pixels(image) for name, image in
               (("ours", ours), ("clay", clay), ("three.js", theirs))}
    for name, pixels in regions.items():
        assert len(pixels) > 0.03 * WIDTH * HEIGHT, f"{name}: the model fills its view"
    shown = {name: histogram(hues(pixels)) for name, pixels in regions.items()}
    overlap = np.minimum(shown["ours"], shown["three.js"]).sum()
    clay_overlap = np.minimum(shown["clay"], shown["three.js"]).sum()
    means = {name: pixels.mean(axis=0) for name, pixels in regions.items()}
    ours_gap = np.abs(means["ours"] - means["three.js"]).max() * 255
    clay_gap = np.abs(means["clay"] - means["three.js"]).max() * 255
    print(f"hue histogram overlap with three.js: ours {overlap:.2f}, clay {clay_overlap:.2f}; "
          f"mean colour (0-255) ours {np.round(means['ours'] * 255)}, three.js "
          f"{np.round(means['three.js'] * 255)}, clay {np.round(means['clay'] * 255)}: largest "
          f"channel gap ours {ours_gap:.0f}, clay {clay_gap:.0f}")
    assert overlap > 0.7 and clay_overlap < 0.3
    assert ours_gap < 0.5 * clay_gap
    found = hues(regions["ours"])
    print(f"swatch hues {swatch_hues()}: each within 10° of ≥ 0.5% of the page's colours")
    for hue in swatch_hues():  # every swatch colour is on screen (±10°, ≥ 0.5% of the colours)
        near = np.abs((found - hue + 180) % 360 - 180) < 10
        assert near.mean() > 0.005, f"the swatch of hue {hue}° is missing"


def test_the_gpu_and_cpu_paths_draw_the_materials_alike(browser, served):
    """The drawn vertices read their welded vertex's position from the positions pass's float
    target (GPU) or gather it from the CPU positions: the same picture, a dancing one (the
    gallery's first tile in the player, not the still mapping)."""
    with urllib.request.urlopen(served["url"] + "api/library") as answer:
        mapping_id = json.load(answer)["mappings"][0]["id"]
    gpu = page_picture(browser, served["url"], mapping_id, True, "gpu", 1.5, tile=1)
    cpu = page_picture(browser, served["url"], mapping_id, True, "cpu", 1.5, tile=1)
    still = page_picture(browser, served["url"], mapping_id, True, "cpu", 1.5)
    assert np.mean(np.abs(cpu - still).max(axis=2) * 255 > 24) > 0.01  # it dances
    difference = np.abs(gpu - cpu).max(axis=2) * 255
    print(f"GPU against CPU path: {np.mean(difference > 2):.4%} of the pixels differ by > 2")
    assert np.mean(difference > 2) < 0.002
