"""The inputs layer (docs/design.md#inputs): one rule by content for what a file is, one reading
of each, the basis a mapping records and the one the commands then solve, the harmonic problem
built once."""

from __future__ import annotations

import json
import shutil

import numpy as np
import pytest
import trimesh

from eigendance.cli import main
from eigendance.errors import InputError
from eigendance.export.video import parse_size
from eigendance.files import AUDIO_SUFFIXES, COMPANION_SUFFIXES, MESH_SUFFIXES
from eigendance.harmonic.basis import HarmonicBasis, HarmonicProblem
from eigendance.harmonic.construction import BasisRecord, basis_key
from eigendance.harmonic.mesh import Mesh, load_mesh
from eigendance.harmonic.motion import load_animation
from eigendance.inputs.defaults import DEFAULT_K
from eigendance.inputs.mapping import (
    BasisChoice,
    basis_choice,
    read_mapping,
    record_note,
    shared_choice,
)
from eigendance.inputs.model import classify, model_kind, published_suffixes, read_model
from eigendance.modal.sample_rigs import sample_rig
from eigendance.modal.skeleton_file import skeleton_document
from eigendance.music.mapping import Mapping
from helpers import fixture_path

SONG = fixture_path("audio", "kevin_macleod_vibe_ace_20s-24s.ogg")


def test_one_rule_says_what_a_file_is_by_its_content(tmp_path):
    skeleton = tmp_path / "arm.json"
    chain = sample_rig("chain")
    skeleton.write_text(json.dumps(skeleton_document(chain.bodies, chain.joints)))
    mapping = tmp_path / "calm.json"
    Mapping([0.5], [1.0]).save(mapping)
    assert classify(skeleton)[0] == "rig"
    assert classify(mapping) == ("mapping", json.loads(mapping.read_text()))
    assert classify(fixture_path("rigged", "Fox.glb")) == ("rig", None)  # a skin
    assert classify(fixture_path("rigged", "SimpleSkin.gltf"))[0] == "rig"
    assert classify(fixture_path("textured", "kenney_cakeBirthday.glb"))[0] == "mesh"
    assert classify(fixture_path("meshes", "teapot.obj"))[0] == "mesh"
    assert classify(fixture_path("audio", "beatnet_808kick120bpm.mp3"))[0] == "audio"
    assert classify("loop4") == ("rig", None)  # a built-in rig
    # the commands that take a model: --mesh asks for a skin's harmonics
    assert model_kind(fixture_path("rigged", "Fox.glb")) == "rig"
    assert model_kind(fixture_path("rigged", "Fox.glb"), as_mesh=True) == "mesh"
    with pytest.raises(InputError, match="calm.json: a mapping, not a model"):
        model_kind(mapping)
    with pytest.raises(InputError, match="a skeleton has no mesh"):
        model_kind(skeleton, as_mesh=True)
    with pytest.raises(InputError, match="unknown file type '.xyz'"):
        classify(tmp_path.joinpath("a.xyz").write_text("x") and tmp_path / "a.xyz")


def test_a_model_is_read_once_into_the_value_the_work_takes(tmp_path):
    fox = read_model(fixture_path("rigged", "Fox.glb"))
    assert fox.kind == "rig" and fox.skeleton.n_bodies > 1 and fox.problem is None
    teapot = read_model(fixture_path("meshes", "teapot.obj"), name="pot.obj")
    assert teapot.kind == "mesh" and teapot.problem.mesh.name == "pot.obj"
    assert teapot.problem.laplacian == "cotan"
    beetle = read_model(fixture_path("meshes", "beetle.obj"))  # non-manifold edges
    assert beetle.problem.laplacian == "robust"


def test_the_suffixes_the_page_is_told_are_the_servers():
    suffixes = published_suffixes()
    assert suffixes["mesh"] == list(MESH_SUFFIXES) and suffixes["audio"] == list(AUDIO_SUFFIXES)
    assert suffixes["companion"] == list(COMPANION_SUFFIXES) and suffixes["archive"] == [".zip"]
    assert ".glb" in suffixes["rig"] and suffixes["mapping"] == [".json"]


def test_a_mapping_records_its_basis_and_the_commands_solve_it(tmp_path):
    path = tmp_path / "made.json"
    Mapping([0.2, 0.8], [1.0, 2.0], basis=BasisRecord(24, "reduced", 3000)).save(path)
    mapping = read_mapping(path)
    assert mapping.basis == BasisRecord(24, "reduced", 3000)
    assert json.loads(path.read_text())["basis"] == {"k": 24, "construction": "reduced",
                                                    "samples": 3000, "placed": None}
    assert basis_choice(mapping) == basis_choice(mapping, 24, "reduced")
    assert (basis_choice(mapping).k, basis_choice(mapping).samples) == (24, 3000)
    other = basis_choice(mapping, construction="exact")
    assert (other.k, other.construction, other.samples) == (24, "exact", None)
    assert other.note.startswith("made.json was made on k = 24 harmonics (reduced, 3000 "
                                 "samples asked); on k = 24 harmonics (exact)")
    # a mapping from before the record: the default k, the construction rule, nothing to say
    old = {key: value for key, value in mapping.to_json().items() if key != "basis"}
    path.write_text(json.dumps(old))
    assert basis_choice(read_mapping(path)) == basis_choice(None)
    assert (basis_choice(None).k, basis_choice(None).construction) == (DEFAULT_K, "auto")
    for bad, message in (({"k": 0}, "basis.k must be from 1"),
                         ({"k": 24, "construction": "fast"}, "basis.construction must be"),
                         ({"k": 24, "samples": 10}, "basis.samples must be greater than 24"),
                         ([24], "basis must be an object")):
        path.write_text(json.dumps({**old, "basis": bad}))
        with pytest.raises(InputError, match=message):
            read_mapping(path)


def test_a_reduced_basis_recorded_in_a_mapping_is_solved_again_the_same(tmp_path, monkeypatch,
                                                                        capsys):
    """The grid places about the samples asked (2000 on a 2562-vertex sphere: a few dozen more
    or fewer), so the record keeps the count asked, which places the same samples again."""
    monkeypatch.setenv("EIGENDANCE_CACHE_DIR", str(tmp_path / "cache"))
    mesh = tmp_path / "sphere.obj"
    trimesh.creation.icosphere(4).export(mesh)
    made = HarmonicBasis.from_mesh(mesh, 20, construction="reduced", cache=False)
    record = made.record
    assert (record.construction, record.samples, record.placed) == (
        "reduced", 2000, len(made.reduced.samples))  # 2000: MIN_SAMPLES, k·SAMPLES_PER_HARMONIC
    assert record.placed != record.samples  # the case at stake: asked ≠ placed
    path = tmp_path / "made.json"
    Mapping(np.linspace(0.1, 0.9, 20), np.ones(20), basis=record).save(path)
    choice = basis_choice(read_mapping(path))
    again = HarmonicProblem(mesh, construction=choice.construction, samples=choice.samples,
                            cache=False).basis(choice.k)
    assert np.array_equal(again.reduced.samples, made.reduced.samples)
    np.testing.assert_allclose(again.eigenvalues, made.eigenvalues, rtol=1e-8, atol=1e-10)
    # animate with the mapping alone dances as on the basis it was made on (saved: the page's)
    made.save(tmp_path / "made.npz")
    assert HarmonicBasis.load(tmp_path / "made.npz").record == record  # the file keeps both
    for source, output in ((tmp_path / "made.npz", "page.npz"), (mesh, "cli.npz")):
        assert main(["animate", str(source), SONG, "--mapping", str(path), "--duration", "3",
                     "--fps", "10", "-o", str(tmp_path / output)]) == 0
    assert "note" not in capsys.readouterr().err
    page, cli = (load_animation(tmp_path / name)["positions"] for name in ("page.npz", "cli.npz"))
    diagonal = np.linalg.norm(np.ptp(page[0], axis=0))
    assert np.abs(cli - page).max() < 1e-4 * diagonal
    # an older record kept the samples placed: read as the default asked, those placed checked
    older = BasisRecord.from_json({"k": 20, "construction": "reduced", "samples": record.placed})
    assert older == BasisRecord(20, "reduced", None, record.placed)
    assert record_note(Mapping([0.5], [1.0], basis=older), made.record) is None
    other = BasisRecord(20, "reduced", 2000, record.placed + 1)
    assert f"{record.placed + 1} placed" in record_note(Mapping([0.5], [1.0], basis=other),
                                                        made.record)


def test_one_basis_for_several_mappings_is_the_one_they_record():
    made = [Mapping([0.5], [1.0], name=f"{k}.json", basis=BasisRecord(k)) for k in (24, 24)]
    old = Mapping([0.5], [1.0], name="old.json")
    exact = BasisChoice(24, "exact")
    assert shared_choice([*made, old]) == (exact, [])
    assert shared_choice([old]) == (BasisChoice(DEFAULT_K, "auto"), [])
    assert shared_choice(made, 24) == (exact, [])
    choice, notes = shared_choice(made, 60)
    assert choice == BasisChoice(60, "exact") and len(notes) == 2
    assert notes[0] == basis_choice(made[0], 60).note  # the command line's line, word for word
    assert notes[0].startswith("24.json was made on k = 24 harmonics (exact); on k = 60 "
                               "harmonics (exact)")
    with pytest.raises(InputError, match=r"different k \(24, 40\); set k"):
        shared_choice([*made, Mapping([0.5], [1.0], basis=BasisRecord(40))])
    # the construction recorded is followed too, and asked for another it is said
    reduced = [Mapping([0.5], [1.0], name="r.json", basis=BasisRecord(24, "reduced", 96))]
    assert shared_choice(reduced) == (BasisChoice(24, "reduced", 96), [])
    choice, notes = shared_choice(reduced, construction="exact")
    assert choice == BasisChoice(24, "exact") and notes == [
        "r.json was made on k = 24 harmonics (reduced, 96 samples asked); on k = 24 harmonics "
        "(exact) the same bands drive other harmonics: the dance differs from the one it was "
        "made on"]
    with pytest.raises(InputError, match=r"different constructions \(exact, reduced\); set "
                                         "construction"):
        shared_choice([*made, *reduced])
    # and the samples asked: the first mapping's, the others made on other samples said
    other = Mapping([0.5], [1.0], name="r2000.json", basis=BasisRecord(24, "reduced", 2000))
    choice, notes = shared_choice([*reduced, other])
    assert choice == BasisChoice(24, "reduced", 96) and notes == [
        "r2000.json was made on k = 24 harmonics (reduced, 2000 samples asked); the basis danced "
        "on has k = 24 harmonics (reduced, 96 samples asked), and the dance differs from the one "
        "it was made on"]


def test_the_problem_is_built_once_and_answers_each_k(monkeypatch, tmp_path):
    sphere = trimesh.creation.icosphere(2)
    mesh = Mesh.from_arrays(sphere.vertices, sphere.faces)
    problem = HarmonicProblem(mesh, cache=False)
    assert problem.key(9) == basis_key(mesh, 9, "cotan")
    first = problem.basis(9)
    operators = problem.operators()
    assert problem.operators() is operators  # L and M assembled once
    assert len(problem.contacts) == 0  # one piece: no contact
    problem.save(tmp_path / "parsed.npz")  # as the server's solve worker gets it
    loaded = HarmonicProblem.load(tmp_path / "parsed.npz")
    again = loaded.basis(9)
    np.testing.assert_allclose(np.abs(again.eigenvectors), np.abs(first.eigenvectors),
                               atol=1e-8)
    assert (loaded.key(9), loaded.laplacian, loaded.cache) == (problem.key(9), "cotan", False)
    # the construction "auto" chooses is decided once per k (the server plans with it), and
    # the saved problem keeps the decision (the solve's worker does not decide again)
    calls = []
    monkeypatch.setattr("eigendance.harmonic.basis.choose_construction",
                        lambda *args: calls.append(args) or "reduced")
    fresh = HarmonicProblem(mesh, cache=False)
    assert fresh.construction_for(9) == fresh.construction_for(9) == "reduced"
    fresh.save(tmp_path / "fresh.npz")
    assert HarmonicProblem.load(tmp_path / "fresh.npz").construction_for(9) == "reduced"
    assert len(calls) == 1
    monkeypatch.undo()
    assert HarmonicBasis.from_mesh(mesh, 9, cache=False).record == BasisRecord(9)
    with pytest.raises(InputError, match="unknown construction 'fast'"):
        HarmonicProblem(mesh, construction="fast")


def test_a_materials_number_that_is_not_one_is_an_error_naming_it(tmp_path):
    for name in ("craft_speederD.gltf", "craft_speederD_data.bin"):
        shutil.copy(fixture_path("textured", name), tmp_path / name)
    path = tmp_path / "craft_speederD.gltf"
    document = json.loads(path.read_text())
    assert load_mesh(path).appearance is not None  # as it is, it reads
    material = document["materials"][0]
    material["pbrMetallicRoughness"]["metallicFactor"] = float("nan")  # was read as 1
    path.write_text(json.dumps(document))
    with pytest.raises(InputError, match="material 0 metallicFactor is not finite"):
        load_mesh(path)
    material["pbrMetallicRoughness"]["metallicFactor"] = 1
    material["extensions"] = {"KHR_materials_emissive_strength": {"emissiveStrength": "x"}}
    path.write_text(json.dumps(document))
    with pytest.raises(InputError, match="emissiveStrength must be a number, not 'x'"):
        load_mesh(path)
    del material["extensions"]
    del document["materials"][0]["pbrMetallicRoughness"]["metallicFactor"]  # absent: default
    path.write_text(json.dumps(document))
    assert load_mesh(path).appearance.materials[0].metallic == 1.0


def test_one_grammar_of_a_video_size():
    assert parse_size("1280x720") == parse_size("1280×720") == parse_size(" 1280 X 720 ") \
        == (1280, 720)
    for bad in ("1280x", "+1280x720", "1280x720x2", "big", 1280, "1281x720"):
        with pytest.raises(InputError):
            parse_size(bad)
