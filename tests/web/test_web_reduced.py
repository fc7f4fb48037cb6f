"""A reduced basis in the page (docs/design.md#reduced-basis): `eigendance serve --reduced`
sends the coarse basis and the interpolation; the GPU gathers each vertex's samples as skinning
does, the CPU path gives the same numbers, and both equal Python's positions; the gallery,
the player and breeding run on it.

Select with `pytest -m web`; skipped where /usr/bin/chromium is missing.
"""

from __future__ import annotations

import json
import os
import time
import urllib.request

import numpy as np
import pytest
from test_look_page import MODEL as LOOK_MODEL
from test_look_page import page_picture
from test_web_mapping_basis import assert_player_shows
from web_helpers import CAT, E2E_K, library_at, open_app, running_server

from eigendance.cli import main
from eigendance.harmonic.basis import HarmonicBasis
from eigendance.harmonic.construction import BasisRecord
from eigendance.harmonic.motion import load_animation, positions_at
from eigendance.music.mapping import Mapping
from eigendance.music.spectrogram import Spectrogram
from eigendance.server.binary import unpack

pytestmark = pytest.mark.web
SAMPLES = 2000  # the default for k = 24 (at least 2000): the grid places it within 5%


@pytest.fixture(scope="module")
def reduced_server(web_files, tmp_path_factory):
    folder = tmp_path_factory.mktemp("reduced-server")
    with running_server([CAT, web_files["song"], "-k", str(E2E_K), "--reduced"], folder,
                        web_files["cache"]) as server:
        yield server


@pytest.fixture(scope="module")
def reduced_page(browser, reduced_server):
    page = open_app(browser, reduced_server["url"], "?render&size=4")
    yield page
    assert not page.errors, page.errors
    page.close()


def test_the_bundle_holds_the_interpolation_not_the_harmonics(reduced_server, reduced_page):
    with urllib.request.urlopen(reduced_server["url"] + "api/library") as answer:
        mesh = json.load(answer)["meshes"][0]
    assert mesh["construction"] == "reduced"
    with urllib.request.urlopen(reduced_server["url"] + f"api/meshes/{mesh['id']}/basis.bin") \
            as answer:
        meta, arrays = unpack(answer.read())
    n, m = meta["n"], meta["placed"]
    assert meta["samples"] == SAMPLES  # asked; the grid places m, within 5% of it
    assert "harmonics" not in arrays and abs(m - SAMPLES) <= 0.05 * SAMPLES
    assert arrays["coarse"].shape == (m, 4 * ((E2E_K + 3) // 4))
    assert arrays["weights"].dtype == np.float16 and arrays["weights"].shape == (n, 8)
    assert arrays["indices"].dtype == np.uint16 and arrays["indices"].max() < m
    assert np.array_equal(arrays["weights"].astype(np.float64).sum(axis=1), np.ones(n))


def test_gpu_and_cpu_positions_equal_python_on_a_reduced_basis(reduced_page, web_files):
    os.environ["EIGENDANCE_CACHE_DIR"] = web_files["cache"]
    basis = HarmonicBasis.from_mesh(CAT, E2E_K, construction="reduced")  # the server's, cached
    assert abs(basis.reduced.count - SAMPLES) <= 0.05 * SAMPLES
    spectrogram = Spectrogram.from_file(web_files["song"])
    diagonal = np.linalg.norm(np.ptp(basis.to_original(basis.vertices), axis=0))

    def error(positions, expected):
        return np.abs(basis.to_original(np.array(positions).reshape(-1, 3)) - expected).max() \
            / diagonal

    mappings = reduced_page.evaluate("window.eigendance.mappings()")
    for tile in (0, 3):
        mapping = Mapping.from_json(mappings[tile])
        for t in (0.5, 4.2):
            expected = positions_at(basis, spectrogram, mapping, t)
            assert np.abs(expected - basis.to_original(basis.vertices)).max() > 1e-3 * diagonal
            for how in (f"readPositions({tile}, {t})", f"readPositions({tile}, {t}, true)",
                        f"cpuPositions({tile}, {t})"):
                found = reduced_page.evaluate(f"window.eigendance.{how}")
                assert error(found, expected) < 1e-4, (how, error(found, expected))


def test_the_player_and_breeding_work_on_a_reduced_basis(reduced_page, web_files):
    os.environ["EIGENDANCE_CACHE_DIR"] = web_files["cache"]
    basis = HarmonicBasis.from_mesh(CAT, E2E_K, construction="reduced")
    spectrogram = Spectrogram.from_file(web_files["song"])
    diagonal = np.linalg.norm(np.ptp(basis.to_original(basis.vertices), axis=0))
    reduced_page.click(".tile[data-index='0'] .view")
    reduced_page.click(".tile[data-index='2'] .view")
    reduced_page.evaluate("window.eigendance.breed(5)")
    assert reduced_page.evaluate("window.eigendance.info().generation") == 1
    child = Mapping.from_json(reduced_page.evaluate("window.eigendance.mappings()")[1])
    reduced_page.evaluate("window.eigendance.open(1)")
    shown = np.array(reduced_page.evaluate("window.eigendance.readPositions('player', 2.0)"))
    expected = positions_at(basis, spectrogram, child, 2.0)
    assert np.abs(basis.to_original(shown.reshape(-1, 3)) - expected).max() / diagonal < 1e-4
    reduced_page.evaluate("window.eigendance.setView('gallery')")


def test_a_mapping_saved_on_a_reduced_basis_dances_the_same_under_animate(
        reduced_page, web_files, tmp_path, monkeypatch, capsys):
    """The page's record keeps the samples asked (the grid places about as many, and the count
    asked places the same ones again), so `animate` with the mapping alone solves the page's
    basis and dances as the page showed it (issue 29)."""
    monkeypatch.setenv("EIGENDANCE_CACHE_DIR", web_files["cache"])
    reduced_page.evaluate("window.eigendance.open(1)")
    with reduced_page.expect_download() as download:
        reduced_page.click("#save-mapping")
    path = tmp_path / "from-page.json"
    download.value.save_as(path)
    basis = HarmonicBasis.from_mesh(CAT, E2E_K, construction="reduced")  # the server's, cached
    assert Mapping.load(path).basis == BasisRecord(E2E_K, "reduced", SAMPLES,
                                                   basis.reduced.count)
    output = tmp_path / "dance.npz"
    assert main(["animate", CAT, web_files["song"], "--mapping", str(path),
                 "-o", str(output)]) == 0
    assert "note" not in capsys.readouterr().err  # the mapping's own basis, solved the same
    assert_player_shows(reduced_page, load_animation(output), basis)
    reduced_page.evaluate("window.eigendance.setView('gallery')")


def test_serve_solves_on_the_samples_a_mapping_records(web_files, tmp_path):
    """`basis --samples N` → `gallery` → a mapping recording N samples: `serve` with it asks the
    reduced basis for those samples, as it follows the k and the construction it records."""
    recorded = 1500  # not the default for k = 24 (SAMPLES)
    path = tmp_path / "made-on-1500.json"
    Mapping(np.linspace(0, 0.5, 64), np.full(E2E_K, 0.5),
            basis=BasisRecord(E2E_K, "reduced", recorded)).save(path)
    with running_server([CAT, web_files["song"], str(path)], tmp_path, web_files["cache"]) \
            as server:
        while not (mesh := library_at(server["url"])["meshes"][0])["ready"]:
            time.sleep(0.5)
        with urllib.request.urlopen(server["url"] + f"api/meshes/{mesh['id']}/basis.bin") \
                as answer:
            meta, _ = unpack(answer.read())
    assert (meta["k"], meta["construction"], meta["samples"]) == (E2E_K, "reduced", recorded)
    assert abs(meta["placed"] - recorded) <= 0.05 * recorded  # the grid places about as many


@pytest.fixture(scope="module")
def reduced_look_server(web_files, tmp_path_factory):
    """A model with materials (MorphStressTest) served on a reduced basis."""
    folder = tmp_path_factory.mktemp("reduced-look")
    Mapping(np.linspace(0, 1, 64), np.zeros(24), name="still.json").save(folder / "still.json")
    with running_server([LOOK_MODEL, web_files["song"], str(folder / "still.json"), "-k", "24",
                         "--reduced"], folder, web_files["cache"]) as server:
        yield server


def test_a_model_with_materials_dances_alike_on_both_paths_of_a_reduced_basis(
        browser, reduced_look_server):
    """The drawn vertices gather their welded vertex's samples (the REDUCED define of the shared
    surface shader) on the GPU, or take the CPU path's positions: the same dancing picture."""
    url = reduced_look_server["url"]
    with urllib.request.urlopen(url + "api/library") as answer:
        library = json.load(answer)
    assert library["meshes"][0]["construction"] == "reduced"
    mapping_id = library["mappings"][0]["id"]
    gpu = page_picture(browser, url, mapping_id, True, "gpu", 1.5, tile=1)
    cpu = page_picture(browser, url, mapping_id, True, "cpu", 1.5, tile=1)
    still = page_picture(browser, url, mapping_id, True, "cpu", 1.5)
    assert np.mean(np.abs(cpu - still).max(axis=2) * 255 > 24) > 0.01  # it dances
    difference = np.abs(gpu - cpu).max(axis=2) * 255
    assert np.mean(difference > 2) < 0.002
