"""Presets (docs/design.md#presets): the folder, the HTTP routes, fitting to another model, and
`--preset` on the command line."""

from __future__ import annotations

import base64
import json
import os

import numpy as np
import pytest
from starlette.testclient import TestClient

from eigendance.cli.main import main
from eigendance.errors import InputError
from eigendance.music.mapping import Mapping
from eigendance.music.mode_settings import ModeSettings
from eigendance.presets.resample import (
    fit_mapping,
    relative_frequencies,
    resample_mapping,
    resample_palette,
)
from eigendance.presets.store import Preset, PresetStore, check_name
from eigendance.server.app import create_app
from eigendance.server.serve import library_session
from helpers import fixture_path

PNG = base64.b64decode(  # a 1×1 PNG
    "iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mNk+M9QDwADhgGAWjR9awAAAABJRU5ErkJggg==")
MAPPING = Mapping([0.05, 0.3, 0.62, 0.99], [1.0, -2.0, 0.5, 3.0], gain=1.5, shading="flat")


def test_a_preset_survives_a_new_store_on_the_same_folder(tmp_path):
    preset = Preset("Kick pulse (slow)", MAPPING, ["kick", "slow"], True, [0.0, 2.0, 6.0], PNG)
    PresetStore(tmp_path).save(preset)
    again = PresetStore(tmp_path).load("Kick pulse (slow)")  # as after a restart
    assert again.mapping.to_json() == MAPPING.to_json()
    assert (again.tags, again.favourite, again.eigenvalues, again.thumbnail) == \
        (["kick", "slow"], True, [0.0, 2.0, 6.0], PNG)
    assert sorted(os.listdir(tmp_path)) == ["Kick pulse (slow).json", "Kick pulse (slow).png"]


@pytest.mark.parametrize("name", ["", "../up", "a/b", ".hidden", "trailing.", "x" * 65, "tab\t",
                                  7, None])
def test_names_that_are_not_plain_file_names_are_refused(name):
    with pytest.raises(InputError, match="preset name"):
        check_name(name)


def test_search_by_name_or_tag_and_favourites(tmp_path):
    store = PresetStore(tmp_path)
    store.save(Preset("Drift", MAPPING, ["ambient"]))
    store.save(Preset("Kick", MAPPING, ["drums"], favourite=True))
    assert [p["name"] for p in store.listing("AMB")] == ["Drift"]
    assert [p["name"] for p in store.listing("kic")] == ["Kick"]
    assert [p["name"] for p in store.listing(favourites=True)] == ["Kick"]
    store.rename("Drift", "Drift 2")
    assert store.names() == ["Drift 2", "Kick"]
    with pytest.raises(InputError) as taken:
        store.rename("Kick", "Drift 2")
    assert taken.value.status == 409
    store.delete("Kick")
    assert store.names() == ["Drift 2"]


def test_relative_frequencies_of_the_sphere():
    # unit sphere: λ = l(l+1), l = 0, 1, 2 (multiplicities 1, 3, 5): ω/ω₁ = √(l(l+1)/2)
    eigenvalues = [0, 2, 2, 2, 6, 6, 6, 6, 6]
    expected = [0, 1, 1, 1, *[np.sqrt(3)] * 5]
    assert np.allclose(relative_frequencies(eigenvalues), expected)


def test_a_mapping_fits_a_scaled_copy_of_its_model_unchanged():
    # a model s times larger has eigenvalues λ/s²: the same relative frequencies, so the same
    # harmonics take the same amplification and the bands drive the same harmonics
    eigenvalues = np.array([0.0, 1.0, 1.5, 4.0, 4.2, 9.0, 9.5, 16.0])
    mapping = Mapping([0.0, 0.3, 0.55, 0.9], np.arange(8.0))
    fitted = resample_mapping(mapping, eigenvalues, eigenvalues / 9.0)
    assert fitted.amplification.tolist() == list(range(8))
    assert fitted.harmonic_indices(8).tolist() == mapping.harmonic_indices(8).tolist()


def test_a_mapping_moves_to_the_harmonics_of_the_same_frequency():
    # old: r = 0, 1, 2, 3, 4 (λ = 0, 1, 4, 9, 16); new: r = 0, 1, 1.9, 4.1 (λ = 0, 1, 3.61,
    # 16.81). New harmonic j takes old harmonic: 0 → 0, 1 → 1, 1.9 → 2, 4.1 → 4.
    old = [0.0, 1.0, 4.0, 9.0, 16.0]
    new = [0.0, 1.0, 3.61, 16.81]
    mapping = Mapping([0.1, 0.5, 0.9], [10.0, 11.0, 12.0, 13.0, 14.0])
    fitted = resample_mapping(mapping, old, new)
    assert fitted.amplification.tolist() == [10.0, 11.0, 12.0, 14.0]
    # bands drove old harmonics 0, 2, 4 (⌊t·5⌋) → new 0, 2, 3
    assert fitted.harmonic_indices(4).tolist() == [0, 2, 3]


def test_a_palette_keeps_the_modes_the_new_rig_has_by_rank():
    palette = ModeSettings(np.array([0, 3, 7]), np.array([0.1, 0.2, 0.3]), np.array([0, 1, 2.0]))
    kept = resample_palette(palette, 5)
    assert kept.selected.tolist() == [0, 3]
    assert kept.amplitudes.tolist() == [0.1, 0.2] and kept.phases.tolist() == [0, 1]
    low = resample_palette(ModeSettings(np.array([8, 9]), np.array([0.4, 0.5]), None), 3)
    assert low.selected.tolist() == [0, 1] and low.amplitudes.tolist() == [0.4, 0.5]
    mapping = Mapping([0.5], [1.0], modes=palette)
    assert fit_mapping(mapping, None, None, mode_count=4).modes.selected.tolist() == [0, 3]


@pytest.fixture
def client(tmp_path):
    with library_session(k=12) as library:
        app = create_app(library, presets=PresetStore(tmp_path / "presets"))
        yield TestClient(app, base_url="http://127.0.0.1:8765")


def test_the_api_saves_lists_exports_imports_and_deletes(client, tmp_path):
    body = {"name": "Wide", "mapping": MAPPING.to_json(), "tags": ["big"],
            "thumbnail": "data:image/png;base64," + base64.b64encode(PNG).decode()}
    assert client.post("/api/presets", json=body).status_code == 201
    assert client.post("/api/presets", json=body).status_code == 409
    assert client.post("/api/presets", json={**body, "replace": True}).status_code == 201
    listed = client.get("/api/presets").json()
    assert listed == [{"name": "Wide", "tags": ["big"], "favourite": False, "kind": "mesh",
                       "thumbnail": True}]
    assert client.get("/api/presets/Wide/thumbnail.png").content == PNG
    exported = client.get("/api/presets/Wide/file")
    assert "attachment" in exported.headers["content-disposition"]
    document = exported.json()
    assert client.delete("/api/presets/Wide").json() == {"deleted": "Wide"}
    assert client.get("/api/presets").json() == []
    assert client.post("/api/presets", json=document).status_code == 201  # import
    assert client.get("/api/presets/Wide").json()["mapping"] == MAPPING.to_json()
    changed = client.patch("/api/presets/Wide", json={"name": "Wider", "favourite": True})
    assert changed.json()["name"] == "Wider" and changed.json()["favourite"] is True
    assert client.get("/api/presets?favourites=1").json()[0]["name"] == "Wider"


@pytest.mark.parametrize("body, status", [
    ({"name": "../x", "mapping": MAPPING.to_json()}, 400),
    ({"name": "ok"}, 400),
    ({"name": "ok", "mapping": {"format": "eigendance.mapping"}}, 400),
    ({"name": "ok", "mapping": MAPPING.to_json(), "thumbnail": "bm90IGEgcG5n"}, 400),
    ({"name": "ok", "mapping": MAPPING.to_json(), "tags": "one"}, 400),
])
def test_bad_presets_are_one_line_errors(client, body, status):
    answer = client.post("/api/presets", json=body)
    assert answer.status_code == status
    assert "\n" not in answer.json()["error"]


def test_a_palette_alone_is_a_rig_preset(client):
    body = {"name": "Sway", "palette": {"selected": [0, 2], "amplitudes": [0.2, 0.3]}}
    assert client.post("/api/presets", json=body).json()["kind"] == "rig"


def test_the_routes_keep_the_host_and_origin_checks(client):
    body = {"name": "Wide", "mapping": MAPPING.to_json()}
    foreign = client.post("/api/presets", json=body, headers={"Origin": "http://evil.example"})
    assert foreign.status_code == 403
    assert client.delete("/api/presets/Wide", headers={"Origin": "http://evil.example"}) \
        .status_code == 403
    assert client.get("/api/presets", headers={"Host": "evil.example"}).status_code == 400


def test_animate_plays_a_preset_as_its_mapping_file(tmp_path, capsys):
    mesh = fixture_path("meshes", "teapot.obj")
    song = fixture_path("audio", "kevin_macleod_vibe_ace_20s-24s.ogg")
    mapping = Mapping(np.linspace(0, 0.9, 64), np.linspace(-1, 1, 12), gain=0.5)
    mapping.save(tmp_path / "m.json")
    PresetStore(tmp_path / "presets").save(Preset("Teapot", mapping))
    common = [mesh, song, "-k", "12", "--duration", "1", "--fps", "10"]
    assert main(["animate", *common, "--mapping", str(tmp_path / "m.json"),
                 "-o", str(tmp_path / "a.npz")]) == 0
    assert main(["animate", *common, "--preset", "Teapot", "--presets", str(tmp_path / "presets"),
                 "-o", str(tmp_path / "b.npz")]) == 0
    a, b = np.load(tmp_path / "a.npz"), np.load(tmp_path / "b.npz")
    assert np.array_equal(a["positions"], b["positions"])
    assert main(["animate", *common, "--preset", "Nope", "--presets", str(tmp_path / "presets"),
                 "-o", str(tmp_path / "c.npz")]) == 1
    assert 'no preset named "Nope"' in capsys.readouterr().err
    assert json.loads((tmp_path / "presets" / "Teapot.json").read_text())["name"] == "Teapot"


def test_batch_plays_a_preset_instead_of_the_plans_gallery(tmp_path, capsys):
    song = tmp_path / "a.ogg"
    song.write_bytes(open(fixture_path("audio", "kevin_macleod_vibe_ace_20s-24s.ogg"), "rb").read())
    plan = tmp_path / "plan.toml"
    plan.write_text('models = ["loop4"]\nsongs = ["a.ogg"]\noutputs = ["npz"]\ngallery = 2\n'
                    'out = "out"\n')
    PresetStore(tmp_path / "presets").save(Preset("Kick pulse", MAPPING))
    assert main(["batch", str(plan), "--dry-run", "--preset", "Kick pulse",
                 "--presets", str(tmp_path / "presets")]) == 0
    assert capsys.readouterr().out.splitlines() == ["loop4-a-Kick_pulse: npz",
                                                    "1 of 1 jobs to make"]
