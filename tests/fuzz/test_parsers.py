"""Property tests of every reader of user input (docs/design.md#errors): meshes, audio,
mappings, skeletons and the .npz files. Whatever the input, a reader gives a result whose
numbers are finite, or an `InputError`: never another exception, never NaN. And a reader that
refused everything would fail: the inputs that are valid by construction (drawn unspoiled, or
written by a real tool) must give a result.

Hypothesis draws the inputs from a fixed seed (derandomize) so CI runs the same bounded set of
examples every time; EIGENDANCE_FUZZ_EXAMPLES=2000 searches deeper.
"""

import json
import math
import os

import numpy as np
import pytest
import soundfile
import trimesh
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st

from eigendance.errors import InputError
from eigendance.harmonic.basis import HarmonicBasis
from eigendance.harmonic.laplacian import laplacian
from eigendance.harmonic.mesh import Mesh, load_mesh
from eigendance.modal.bodies import JOINT_TYPES
from eigendance.modal.model import ModalModel
from eigendance.modal.sample_rigs import load_rig
from eigendance.modal.skeleton import Skeleton
from eigendance.music.mapping import Mapping
from eigendance.music.spectrogram import Spectrogram

FUZZ = settings(max_examples=int(os.environ.get("EIGENDANCE_FUZZ_EXAMPLES", 50)), deadline=None,
                derandomize=True, database=None,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                       HealthCheck.function_scoped_fixture])

# Numbers as a hostile file holds them: ordinary, huge, tiny, signed zero, NaN, infinities.
wild_floats = st.one_of(
    st.floats(-10, 10), st.floats(allow_nan=True, allow_infinity=True),
    st.sampled_from([0.0, -0.0, 1e-300, -1e-300, 1e300, -1e300, 1e15, 1e-15, 5e-324]))
json_numbers = st.one_of(wild_floats.filter(math.isfinite), st.integers(-10, 10),
                         st.integers(), st.sampled_from([10**40, -(10**39), 2**64, 2**63]))
json_values = st.recursive(
    st.none() | st.booleans() | json_numbers | st.text(max_size=8),
    lambda inner: st.lists(inner, max_size=4) | st.dictionaries(st.text(max_size=6), inner,
                                                                max_size=4),
    max_leaves=12)


def outcome(read):
    """read()'s result, or None for an InputError; any other exception fails the test."""
    try:
        result = read()
    except InputError as error:
        assert "\n" not in str(error)
        event("input error")
        return None
    event("result")
    return result


def all_finite(*arrays) -> bool:
    return all(np.all(np.isfinite(np.asarray(array, dtype=np.float64))) for array in arrays)


# --- meshes -----------------------------------------------------------------------------------

ICOSAHEDRON = trimesh.creation.icosphere(0)  # 12 vertices, 20 triangles: the base to spoil


@st.composite
def mesh_arrays(draw):
    """An icosahedron moved, scaled and spoiled a little, or arrays of anything; and whether
    the arrays are a valid mesh by construction (the icosahedron unspoiled at a usable scale)."""
    if draw(st.booleans()):
        vertices = draw(st.lists(st.lists(wild_floats, min_size=3, max_size=3), max_size=9))
        faces = draw(st.lists(st.lists(st.integers(-3, 12), min_size=3, max_size=3),
                              max_size=12))
        return np.array(vertices, dtype=np.float64).reshape(-1, 3), \
            np.array(faces, dtype=np.int64).reshape(-1, 3), False
    scale = draw(st.sampled_from([1.0, 1e-20, 1e-31, 1e12, 1e16, 1e300]))
    with np.errstate(all="ignore"):
        vertices = ICOSAHEDRON.vertices * scale + draw(st.floats(-1e3, 1e3)) * scale
    faces = ICOSAHEDRON.faces.copy()
    spoils = draw(st.integers(0, 3))
    for _ in range(spoils):
        if draw(st.booleans()):
            vertices[draw(st.integers(0, 11)), draw(st.integers(0, 2))] = draw(wild_floats)
        else:
            faces[draw(st.integers(0, 19)), draw(st.integers(0, 2))] = draw(st.integers(-2, 13))
    return vertices, faces, spoils == 0 and scale in (1.0, 1e-20)


@FUZZ
@given(arrays=mesh_arrays())
def test_mesh_arrays_give_a_clean_mesh_or_an_input_error(arrays):
    vertices, faces, valid = arrays
    mesh = outcome(lambda: Mesh.from_arrays(vertices, faces))
    assert mesh is not None or not valid, "a valid mesh was refused"
    if mesh is None:
        return
    assert all_finite(mesh.vertices, mesh.center, mesh.scale) and mesh.scale > 0
    assert np.abs(mesh.vertices).max() <= 1 + 1e-12
    assert mesh.faces.min() >= 0 and mesh.faces.max() < mesh.n
    operators = outcome(lambda: laplacian(mesh.vertices, mesh.faces))
    if operators is not None:
        stiffness, mass = operators
        assert all_finite(stiffness.data, mass) and np.all(mass > 0)


obj_lines = st.one_of(
    st.builds(lambda xyz: "v " + " ".join(repr(float(c)) for c in xyz),
              st.lists(wild_floats, min_size=3, max_size=3)),
    st.builds(lambda ids: "f " + " ".join(ids),
              st.lists(st.sampled_from(["1", "2", "3", "4", "0", "-1", "9", "1/1", "2//2",
                                        "3/0/1", "x"]), min_size=3, max_size=4)),
    st.sampled_from(["# comment", "# caf\u00e9", "vn 0 0 1", "g part", "", "o x", "f", "v 1"]))


TETRAHEDRON_OBJ = ["v 0 0 0", "v 1 0 0", "v 0 1 0", "v 0 0 1", "f 1 3 2", "f 1 2 4", "f 1 4 3",
                   "f 2 3 4"]


@FUZZ
@given(inserted=st.lists(st.tuples(st.integers(0, 8), obj_lines), max_size=4),
       dropped=st.sets(st.integers(0, 7), max_size=2), latin1=st.booleans())
def test_obj_text_gives_a_mesh_or_an_input_error(tmp_path_factory, inserted, dropped, latin1):
    lines = [line for i, line in enumerate(TETRAHEDRON_OBJ) if i not in dropped]
    for index, line in inserted:
        lines.insert(index, line)
    path = tmp_path_factory.mktemp("obj") / "fuzz.obj"
    path.write_bytes("\n".join(lines).encode("latin-1" if latin1 else "utf-8"))
    mesh = outcome(lambda: load_mesh(path))
    harmless = {"# comment", "vn 0 0 1", "g part", "", "o x"}
    if not dropped and all(line in harmless for _, line in inserted):
        assert mesh is not None and (mesh.n, len(mesh.faces)) == (4, 4), "a valid OBJ refused"
    if mesh is not None:
        assert all_finite(mesh.vertices) and mesh.faces.max() < mesh.n


@pytest.mark.parametrize("suffix", [".stl", ".ply", ".off", ".obj", ".glb"])
def test_mesh_files_written_by_trimesh_give_a_mesh(tmp_path, suffix):
    path = tmp_path / f"sphere{suffix}"
    trimesh.creation.icosphere(1).export(path)
    mesh = load_mesh(path)
    assert (mesh.n, len(mesh.faces)) == (42, 80) and all_finite(mesh.vertices)


@FUZZ
@given(data=st.binary(max_size=600), suffix=st.sampled_from([".stl", ".ply", ".off", ".obj",
                                                              ".glb"]),
       prefix=st.sampled_from([b"", b"solid x\n", b"ply\nformat ascii 1.0\n", b"OFF\n",
                               b"glTF"]))
def test_mesh_bytes_give_a_mesh_or_an_input_error(tmp_path_factory, data, suffix, prefix):
    path = tmp_path_factory.mktemp("bytes") / f"fuzz{suffix}"
    path.write_bytes(prefix + data)
    mesh = outcome(lambda: load_mesh(path))
    if mesh is not None:
        assert all_finite(mesh.vertices) and mesh.faces.max() < mesh.n


# --- audio ------------------------------------------------------------------------------------

sample_lists = st.one_of(st.lists(st.floats(-2, 2), max_size=300),
                        st.lists(wild_floats, max_size=300))


@FUZZ
@given(samples=sample_lists,
       sample_rate=st.one_of(st.integers(-5, 50), st.sampled_from([8000, 44100, 10**7])),
       rate=st.sampled_from([1e-3, 1.0, 100.0, 1000.0]), bands=st.integers(1, 64))
def test_samples_give_a_spectrogram_or_an_input_error(samples, sample_rate, rate, bands):
    spectrogram = outcome(lambda: Spectrogram.from_samples(np.array(samples, dtype=np.float64),
                                                           sample_rate, rate=rate, bands=bands))
    valid = sample_rate in (8000, 44100) and samples and all_finite(samples)
    assert spectrogram is not None or not valid, "valid samples were refused"
    if spectrogram is not None:
        values = spectrogram.values
        assert all_finite(values) and values.min() >= 0 and values.max() <= 1
        assert values.shape == (len(spectrogram.times), bands) and len(samples) > 0


@FUZZ
@given(samples=sample_lists, sample_rate=st.one_of(st.integers(1, 200000),
                                                 st.sampled_from([8000, 44100, 96000])),
       subtype=st.sampled_from(["FLOAT", "DOUBLE", "PCM_16"]),
       cut=st.one_of(st.just(0), st.integers(1, 300)),
       suffix=st.sampled_from([".wav", ".flac", ".mp3", ".ogg"]))
def test_audio_files_give_a_spectrogram_or_an_input_error(tmp_path_factory, samples, sample_rate,
                                                          subtype, cut, suffix):
    path = tmp_path_factory.mktemp("audio") / f"fuzz{suffix}"
    samples = np.array(samples, dtype=np.float64)
    if subtype == "PCM_16":
        samples = np.clip(np.nan_to_num(samples), -1, 1)
    soundfile.write(path, samples, sample_rate, subtype=subtype, format="WAV")
    path.write_bytes(path.read_bytes()[:max(0, path.stat().st_size - cut)])  # maybe truncated
    spectrogram = outcome(lambda: Spectrogram.from_file(path))
    valid = cut == 0 and len(samples) and sample_rate > 2 * 20 and all_finite(samples) \
        and np.abs(samples).max() < 1e30  # finite as float32 too
    assert spectrogram is not None or not valid, "a valid audio file was refused"
    if spectrogram is not None:
        assert all_finite(spectrogram.values) and 0 <= spectrogram.values.min()


@FUZZ
@given(data=st.binary(max_size=400), suffix=st.sampled_from([".wav", ".mp3", ".ogg", ".flac",
                                                              ".m4a"]),
       prefix=st.sampled_from([b"", b"RIFF", b"ID3\x03\x00", b"OggS", b"fLaC", b"\xff\xfb"]))
def test_audio_bytes_give_a_spectrogram_or_an_input_error(tmp_path_factory, data, suffix,
                                                          prefix):
    path = tmp_path_factory.mktemp("noise") / f"fuzz{suffix}"
    path.write_bytes(prefix + data)
    spectrogram = outcome(lambda: Spectrogram.from_file(path))
    if spectrogram is not None:
        assert all_finite(spectrogram.values)


# --- mappings ---------------------------------------------------------------------------------

@st.composite
def valid_mapping(draw, spoil=True):
    """A well-formed mapping document of version 1 or 2 with one field perhaps spoiled."""
    bands = draw(st.integers(1, 6))
    document = {"format": "eigendance.mapping", "version": draw(st.sampled_from([1, 2])),
                "bands": bands,
                "transfer": draw(st.lists(st.floats(0, 1), min_size=bands, max_size=bands)),
                "amplification": draw(st.lists(st.floats(-1e3, 1e3), min_size=1, max_size=5)),
                "seed": draw(st.one_of(st.none(), st.integers(0, 2**64 - 1))),
                "gain": draw(st.floats(0, 10)), "smoothing": draw(st.floats(0, 1)),
                "look": {"shading": "flat"}}
    if spoil and draw(st.booleans()):
        document[draw(st.sampled_from(sorted(document)))] = draw(json_values)
    return document


@FUZZ
@given(document=valid_mapping(spoil=False))
def test_well_formed_mapping_documents_give_a_mapping(document):
    mapping = outcome(lambda: Mapping.from_json(document, "fuzz.json"))
    assert mapping is not None, "a well-formed mapping was refused"
    assert mapping.bands == document["bands"]


def mapping_documents():
    """Mapping documents: well-formed ones spoiled a little, loose ones, or anything JSON."""
    fields = st.fixed_dictionaries({
        "format": st.sampled_from(["eigendance.mapping", "other"]),
        "version": st.sampled_from([1, 2, 3, True, "2"]),
        "bands": st.one_of(st.integers(0, 4), json_values),
        "transfer": st.one_of(st.lists(st.one_of(st.floats(0, 1), json_numbers), max_size=4),
                              json_values),
        "amplification": st.one_of(st.lists(json_numbers, max_size=4), json_values),
        "seed": st.one_of(st.none(), json_numbers, json_values),
    }, optional={"gain": json_values | json_numbers, "smoothing": json_numbers,
                 "offset": json_numbers, "modes": json_values,
                 "look": st.fixed_dictionaries({}, optional={
                     "shading": json_values, "deformed_normal_weight": json_numbers})})
    return st.one_of(valid_mapping(), fields, json_values)


@FUZZ
@given(document=mapping_documents())
def test_mapping_documents_give_a_mapping_or_an_input_error(document):
    mapping = outcome(lambda: Mapping.from_json(document, "fuzz.json"))
    if mapping is not None:
        assert all_finite(mapping.transfer, mapping.amplification, mapping.gain)
        assert all_finite(mapping.filter(np.ones(mapping.bands), 7))


@FUZZ
@given(text=st.one_of(st.text(max_size=60), st.builds(json.dumps, mapping_documents()),
                      st.sampled_from(["[" * 5000 + "]" * 5000, '{"bands": ' + "9" * 5000 + "}",
                                       '{"seed": 1e999}', "NaN", "\ufeff{}"])))
def test_mapping_files_give_a_mapping_or_an_input_error(tmp_path_factory, text):
    path = tmp_path_factory.mktemp("mapping") / "fuzz.json"
    path.write_text(text, encoding="utf-8")
    mapping = outcome(lambda: Mapping.load(path))
    if mapping is not None:
        assert all_finite(mapping.transfer, mapping.amplification)


# --- skeletons --------------------------------------------------------------------------------

lengths = st.one_of(st.floats(0.05, 5), st.sampled_from([1e-300, 1e-9, 1e-5, 1e3, 1e12, 1e300]))
points = st.lists(st.one_of(st.floats(-3, 3), json_numbers), min_size=3, max_size=3)


@st.composite
def skeleton_documents(draw):
    """A chain of bodies with joints between neighbours: numbers drawn wild, some fields
    replaced by any JSON value."""
    count = draw(st.integers(1, 4))
    scale = draw(st.sampled_from([1.0, 1e-6, 1e-3, 1e4, 1e9]))
    corners = np.cumsum(np.array(draw(st.lists(
        st.lists(st.floats(-1, 1), min_size=3, max_size=3), min_size=count + 1,
        max_size=count + 1))), axis=0) * scale
    bodies = [{"name": f"b{i}", "start": corners[i].tolist(), "end": corners[i + 1].tolist(),
               "radius": draw(lengths) * scale, "density": draw(st.one_of(
                   st.just(1000.0), st.floats(1e-3, 1e6), json_numbers))}
              for i in range(count)]
    joints = [{"name": f"j{i}", "type": draw(st.sampled_from(JOINT_TYPES)),
               "bodies": [f"b{i}", f"b{i + 1}"],
               "stiffness": draw(st.one_of(st.just("auto"), st.floats(0, 1e4), json_numbers,
                                           st.lists(json_numbers, max_size=3)))}
              for i in range(count - 1)]
    document = {"format": "eigendance.skeleton", "version": 1, "bodies": bodies,
                "joints": joints}
    if draw(st.booleans()):  # one field of one item replaced by anything
        items = bodies + joints
        item = items[draw(st.integers(0, len(items) - 1))]
        item[draw(st.sampled_from(sorted(item)))] = draw(json_values)
    return document


@st.composite
def sound_skeleton_documents(draw):
    """A chain of 1 to 4 bodies of sensible sizes, each 0.2 to 2 long and a tenth as thick,
    joints between neighbours with stiffness "auto" or a number: always a valid skeleton."""
    count = draw(st.integers(1, 4))
    steps = draw(st.lists(st.tuples(st.floats(0.2, 2), st.floats(0, 2 * math.pi),
                                    st.floats(-1, 1)), min_size=count, max_size=count))
    corners = np.cumsum([[0.0, 0.0, 0.0]] + [
        [length * math.cos(angle) * math.sqrt(1 - z * z),
         length * math.sin(angle) * math.sqrt(1 - z * z), length * z]
        for length, angle, z in steps], axis=0)
    bodies = [{"name": f"b{i}", "start": corners[i].tolist(), "end": corners[i + 1].tolist(),
               "radius": steps[i][0] / 10} for i in range(count)]
    joints = [{"name": f"j{i}", "type": draw(st.sampled_from(JOINT_TYPES)),
               "bodies": [f"b{i}", f"b{i + 1}"],
               "stiffness": draw(st.one_of(st.just("auto"), st.floats(1, 1e4)))}
              for i in range(count - 1)]
    return {"format": "eigendance.skeleton", "version": 1, "bodies": bodies, "joints": joints}


@FUZZ
@given(document=sound_skeleton_documents())
def test_sound_skeleton_documents_give_a_skeleton_and_finite_modes(document):
    skeleton = outcome(lambda: Skeleton.from_dict(document, "fuzz.json"))
    assert skeleton is not None, "a valid skeleton was refused"
    model = ModalModel.from_skeleton(skeleton)
    assert all_finite(model.frequencies, model.modes) and np.all(model.frequencies >= 0)


@FUZZ
@given(document=skeleton_documents())
def test_skeleton_documents_give_finite_modes_or_an_input_error(document):
    skeleton = outcome(lambda: Skeleton.from_dict(document, "fuzz.json"))
    if skeleton is None:
        return
    model = ModalModel.from_skeleton(skeleton)
    assert all_finite(model.frequencies, model.modes) and np.all(model.frequencies >= 0)


# --- .npz files -------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def real_files(tmp_path_factory):
    """A basis and a spectrogram written by eigendance, whose fields the tests below spoil."""
    folder = tmp_path_factory.mktemp("npz")
    sphere = trimesh.creation.icosphere(1)
    basis = HarmonicBasis.from_mesh(Mesh.from_arrays(sphere.vertices, sphere.faces), 6,
                                    cache=False)
    basis.save(folder / "basis.npz")
    tone = np.sin(np.arange(4000) / 3.0)
    Spectrogram.from_samples(tone, 8000, bands=8).save(folder / "spectrogram.npz")
    return {name: dict(np.load(folder / f"{name}.npz")) for name in ("basis", "spectrogram")}


def test_unspoiled_npz_files_load(tmp_path, real_files):
    for kind, loader in (("basis", HarmonicBasis.load), ("spectrogram", Spectrogram.load)):
        np.savez(tmp_path / f"{kind}.npz", **real_files[kind])
        loaded = loader(tmp_path / f"{kind}.npz")
        assert all_finite(loaded.values if kind == "spectrogram" else loaded.eigenvectors)


spoilers = st.sampled_from([
    lambda a: a * np.nan, lambda a: a * np.inf, lambda a: a * 1e300, lambda a: -a, lambda a: a[:1],
    lambda a: a.reshape(-1), lambda a: a.astype(np.float32), lambda a: a.astype(np.int64),
    lambda a: a.astype(str), lambda a: np.array(3.0), lambda a: np.zeros((0,) + a.shape[1:]),
    lambda a: a.astype(bool), lambda a: a + 1, lambda a: a * 2, lambda a: np.zeros_like(a),
    lambda a: np.array("cotan"), lambda a: a.astype(np.complex128)])


@FUZZ
@given(kind=st.sampled_from(["basis", "spectrogram"]), changes=st.lists(
    st.tuples(st.integers(0, 9), spoilers), min_size=1, max_size=3))
def test_spoiled_npz_files_give_a_result_or_an_input_error(tmp_path_factory, real_files, kind,
                                                           changes):
    arrays = dict(real_files[kind])
    names = sorted(arrays)
    for index, spoil in changes:
        name = names[index % len(names)]
        try:
            with np.errstate(all="ignore"):  # spoiling may overflow: that is the point
                arrays[name] = spoil(np.asarray(arrays[name]))
        except (ValueError, TypeError, IndexError):
            continue
    path = tmp_path_factory.mktemp("spoiled") / f"{kind}.npz"
    np.savez(path, **arrays)
    loader = HarmonicBasis.load if kind == "basis" else Spectrogram.load
    loaded = outcome(lambda: loader(path))
    if loaded is None:
        return
    if kind == "basis":
        assert all_finite(loaded.eigenvectors, loaded.to_original(loaded.vertices))
        assert loaded.faces.min() >= 0 and loaded.faces.max() < loaded.n
    else:
        assert all_finite(loaded.values, loaded.at(np.linspace(0, loaded.duration, 5)))


RIGGED = os.path.join(os.path.dirname(__file__), "..", "fixtures", "rigged")


@FUZZ
@given(name=st.sampled_from(["RiggedSimple.glb", "SimpleSkin.gltf"]), at=st.integers(0, 10**6),
       patch=st.binary(min_size=1, max_size=24), cut=st.booleans())
def test_spoiled_gltf_skins_give_a_rig_or_an_input_error(tmp_path_factory, name, at, patch, cut):
    with open(os.path.join(RIGGED, name), "rb") as file:
        data = file.read()
    at %= len(data)
    data = data[:at] if cut else data[:at] + patch + data[at + len(patch):]
    path = tmp_path_factory.mktemp("gltf") / name
    path.write_bytes(data)
    rig = outcome(lambda: load_rig(str(path)))
    if rig is not None:
        assert all_finite(rig.vertices, rig.weights, rig.centers)


@pytest.mark.parametrize("name", ["RiggedSimple.glb", "SimpleSkin.gltf"])
def test_unspoiled_gltf_skins_give_a_rig(name):
    rig = load_rig(os.path.join(RIGGED, name))
    assert rig.n_bodies >= 2 and all_finite(rig.vertices, rig.weights, rig.centers)
