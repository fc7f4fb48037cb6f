"""glTF exports (docs/design.md#exports): read back by the glTF 2.0 rules, not by our writer.

Morph targets: rest + Σ w·D at every sample equals `positions_at`; skins: the joint matrices
(animated TRS × inverse bind matrix) applied with the file's JOINTS/WEIGHTS equal linear blend
skinning of the body transforms. The Khronos validator and three.js are in test_viewers.py.
"""

from __future__ import annotations

import os

import numpy as np
import pygltflib
import pytest
import scipy.sparse as sp
from export_helpers import SONG, check_positions, file_times
from scipy.spatial.transform import Rotation

from eigendance.export.dance import HarmonicDance
from eigendance.export.files import export_dance
from eigendance.export.gltf import glb_bytes, glb_size
from eigendance.export.pointcache import pc2_size
from eigendance.harmonic.basis import HarmonicBasis
from eigendance.harmonic.mesh import Mesh
from eigendance.harmonic.motion import positions_at
from eigendance.modal.skinning import linear_blend_skinning
from eigendance.music.mapping import Mapping
from eigendance.music.spectrogram import Spectrogram

COMPONENTS = {pygltflib.FLOAT: "<f4", pygltflib.UNSIGNED_INT: "<u4",
              pygltflib.UNSIGNED_SHORT: "<u2", pygltflib.UNSIGNED_BYTE: "u1"}
WIDTHS = {"SCALAR": 1, "VEC3": 3, "VEC4": 4, "MAT4": 16}


def load(path):
    gltf = pygltflib.GLTF2().load(str(path))
    blob = gltf.binary_blob()

    def read(index):
        accessor = gltf.accessors[index]
        view = gltf.bufferViews[accessor.bufferView]
        start = view.byteOffset + (accessor.byteOffset or 0)
        width = WIDTHS[accessor.type]
        data = np.frombuffer(blob, COMPONENTS[accessor.componentType],
                             accessor.count * width, start)
        if accessor.normalized:  # glTF 2.0 §3.11: an unsigned integer c means c / its largest
            data = data / np.iinfo(data.dtype).max
        return data.reshape(accessor.count, width) if width > 1 else data

    return gltf, read


def test_morph_targets_replay_the_reference_positions_at_every_sample(harmonic, tmp_path):
    report = export_dance(harmonic, tmp_path / "sphere.glb")
    gltf, read = load(tmp_path / "sphere.glb")
    primitive = gltf.meshes[0].primitives[0]
    rest = read(primitive.attributes.POSITION)
    targets = np.stack([read(target["POSITION"]) for target in primitive.targets])
    channel = gltf.animations[0].channels[0]
    sampler = gltf.animations[0].samplers[channel.sampler]
    assert channel.target.path == "weights" and sampler.interpolation == "LINEAR"
    times = read(sampler.input)
    weights = read(sampler.output).reshape(len(times), len(targets))
    expected_times = file_times(harmonic.duration, 30.0)
    assert report["frames"] == len(times) == len(expected_times)
    np.testing.assert_allclose(times, expected_times, rtol=1e-6)
    played = rest[None] + np.einsum("tj,jnc->tnc", weights, targets)
    reference = positions_at(harmonic.basis, harmonic.spectrogram, harmonic.mapping,
                             expected_times)
    check_positions(played, reference, harmonic.diagonal, 1e-6)
    faces = read(primitive.indices).reshape(-1, 3)
    np.testing.assert_array_equal(faces, harmonic.basis.faces)
    # one target per driven harmonic, named; the mapping drives at most B of them
    names = gltf.meshes[0].extras["targetNames"]
    assert len(names) == len(targets) <= harmonic.mapping.bands
    assert names == [f"harmonic {nu}" for nu in harmonic.driven()]


def test_the_song_is_written_beside_and_named_in_the_extras(harmonic, tmp_path):
    report = export_dance(harmonic, tmp_path / "dance.glb", fps=24)
    song = tmp_path / "dance.ogg"
    assert report["files"] == [str(tmp_path / "dance.glb"), str(song)]
    assert song.read_bytes() == open(SONG, "rb").read()
    gltf, _ = load(tmp_path / "dance.glb")
    extras = gltf.extras["eigendance"]
    assert extras["audio"] == "dance.ogg" and extras["fps"] == 24
    assert extras["mapping"]["gain"] == 1.5 and extras["kind"] == "harmonics"
    assert sorted(os.listdir(tmp_path)) == ["dance.glb", "dance.ogg"]  # no temporaries left


def test_a_skin_plays_linear_blend_skinning_of_the_body_transforms(chain_lbs, tmp_path):
    export_dance(chain_lbs, tmp_path / "chain.glb")
    played, times = play_skin(tmp_path / "chain.glb")
    transforms, _ = chain_lbs.pose(times.astype(np.float64))
    reference = linear_blend_skinning(chain_lbs.rest, chain_lbs.weights, transforms)
    check_positions(played, reference, chain_lbs.diagonal, 1e-5)
    # the dance really moves (0.8% of the diagonal: a chain lying on its floor sways little,
    # docs/design.md#the-floor), 800 times the comparison's tolerance
    assert np.abs(reference - reference[:1]).max() > 0.005 * chain_lbs.diagonal


def test_a_modal_skinned_rig_reports_its_difference_from_the_skin(figure_modal, tmp_path):
    report = export_dance(figure_modal, tmp_path / "figure.glb", fps=10)
    played, times = play_skin(tmp_path / "figure.glb")
    modal = figure_modal.drawn(figure_modal.positions(times))  # the glb's drawn vertices
    largest = np.linalg.norm(played - modal, axis=-1).max()
    assert report["skinning_difference"] == pytest.approx(largest, rel=1e-3, abs=1e-6)
    assert 0 < report["skinning_difference"] < 0.1 * report["diagonal"]


def play_skin(path):
    """Positions of a skinned glb at its samples, by the glTF rules: joint matrix = world(joint)
    · inverse bind matrix, x′ = Σ_j w_j J_j x (joints are children of an identity root)."""
    gltf, read = load(path)
    primitive = gltf.meshes[0].primitives[0]
    skin = gltf.skins[0]
    rest = read(primitive.attributes.POSITION).astype(np.float64)
    inverse = read(skin.inverseBindMatrices).reshape(-1, 4, 4).transpose(0, 2, 1)
    animation = gltf.animations[0]
    tracks = {}
    for channel in animation.channels:
        sampler = animation.samplers[channel.sampler]
        tracks[(channel.target.node, channel.target.path)] = read(sampler.output)
        times = read(sampler.input)
    world = np.zeros((len(times), len(skin.joints), 4, 4))
    for index, node in enumerate(skin.joints):
        world[:, index, :3, :3] = Rotation.from_quat(tracks[(node, "rotation")]).as_matrix()
        world[:, index, :3, 3] = tracks[(node, "translation")]
        world[:, index, 3, 3] = 1
    matrices = world @ inverse[None]
    played = np.zeros((len(times), len(rest), 3))
    sets = 0
    while getattr(primitive.attributes, f"JOINTS_{sets}", None) is not None:
        joints = read(getattr(primitive.attributes, f"JOINTS_{sets}")).astype(np.int64)
        weights = read(getattr(primitive.attributes, f"WEIGHTS_{sets}")).astype(np.float64)
        for column in range(4):
            matrix = matrices[:, joints[:, column]]  # (T, n, 4, 4)
            moved = np.einsum("tnij,nj->tni", matrix[..., :3, :3], rest) + matrix[..., :3, 3]
            played += weights[None, :, column, None] * moved
        sets += 1
    assert sets >= 1
    return played, times


def test_a_still_mapping_exports_a_mesh_without_targets(basis, song, tmp_path):
    still = Mapping(np.full(song.bands, 0.5), np.zeros(8))
    dance = HarmonicDance(basis, song, still)
    gltf, read = load_bytes(glb_bytes(dance, [0.0, 1.0], {}), tmp_path)
    assert not gltf.meshes[0].primitives[0].targets and not gltf.animations
    check_positions(read(gltf.meshes[0].primitives[0].attributes.POSITION)[None],
                    dance.rest[None], dance.diagonal, 1e-6)


def load_bytes(data: bytes, folder):
    path = folder / "bytes.glb"
    path.write_bytes(data)
    return load(path)


def test_a_three_minute_song_on_a_fine_mesh_is_20_times_smaller_than_a_point_cache(tmp_path):
    """The glb grows with (targets × vertices + frames × targets), the cache with frames ×
    vertices; 3 minutes at 30 fps on 2562 vertices (the bunny's ratio is in
    benchmarks/bench_render.py)."""
    import trimesh

    sphere = trimesh.creation.icosphere(4)
    basis = HarmonicBasis.from_mesh(Mesh.from_arrays(sphere.vertices, sphere.faces), 100,
                                    cache=False)
    rng = np.random.default_rng(3)
    song = Spectrogram.from_samples(rng.uniform(-0.5, 0.5, 180 * 8000), 8000)
    mapping = Mapping(rng.uniform(0, 1, 64), rng.uniform(-0.05, 0.05, 100))
    dance = HarmonicDance(basis, song, mapping)
    report = export_dance(dance, tmp_path / "long.glb")
    assert report["frames"] == 5401 and len(dance.driven()) <= 64
    assert report["point_cache_bytes"] == pc2_size(basis.n, 5401)
    assert report["point_cache_bytes"] >= 20 * report["bytes"], report


def test_a_reduced_basis_is_a_skin_on_its_samples_that_replays_the_reference(
        reduced_harmonic, tmp_path):
    """Read by the glTF rules: joint matrix = (animated translation of the joint node) × its
    inverse bind matrix, applied with JOINTS_0/1 and WEIGHTS_0/1 (8 influences)."""
    dance = reduced_harmonic
    export_dance(dance, tmp_path / "reduced.glb", fps=15)
    gltf, read = load(tmp_path / "reduced.glb")
    skin = gltf.skins[0]
    samples = dance.basis.reduced.samples
    assert len(skin.joints) == len(samples) == dance.basis.reduced.count
    primitive = gltf.meshes[0].primitives[0]
    rest = read(primitive.attributes.POSITION).astype(np.float64)
    joints = np.hstack([read(primitive.attributes.JOINTS_0), read(primitive.attributes.JOINTS_1)])
    weights = np.hstack([read(primitive.attributes.WEIGHTS_0),
                         read(primitive.attributes.WEIGHTS_1)]).astype(np.float64)
    check_weight_shares(gltf, primitive, joints, weights, dance.basis.reduced)
    inverse = read(skin.inverseBindMatrices).reshape(-1, 4, 4).transpose(0, 2, 1)
    animation = gltf.animations[0]
    times = read(animation.samplers[0].input)
    translations = np.zeros((len(times), len(skin.joints), 3))
    for channel in animation.channels:
        assert channel.target.path == "translation"  # translation-only joints
        joint = skin.joints.index(channel.target.node)
        translations[:, joint] = read(animation.samplers[channel.sampler].output)
    matrices = np.tile(np.eye(4), (len(times), len(skin.joints), 1, 1))
    matrices[..., :3, 3] = translations
    matrices = matrices @ inverse[None]  # the joint matrices
    homogeneous = np.hstack([rest, np.ones((len(rest), 1))])
    chosen = matrices[:, joints, :3]  # (T, n, 8, 3, 4): each vertex's joints
    played = np.einsum("is,tisab,ib->tia", weights, chosen, homogeneous)
    expected = dance.positions(times)
    check_positions(played, expected, dance.diagonal, 1e-4)
    # The bound of the rounded weights: Σ_j |w'_j − w_j| |D_j(t)| < 8/65535 · max_j |D_j(t)|.
    moved = np.linalg.norm(translations + inverse[None, :, :3, 3], axis=-1)  # |D_j(t)|
    error = np.linalg.norm(played - expected, axis=-1).max(axis=1)
    assert np.all(error <= 8 / 65535 * moved.max(axis=1) + 1e-6 * dance.diagonal), error
    assert np.abs(expected[len(times) // 2] - expected[0]).max() > 1e-3 * dance.diagonal


def check_weight_shares(gltf, primitive, joints, weights, reduced):
    """WEIGHTS_0/1 are normalised unsigned shorts whose whole numbers sum to exactly 65535 per
    vertex, each within one unit of 65535 × the basis's own interpolation weight of that
    sample (P, from the basis file's arrays, not from the exporter)."""
    for name in ("WEIGHTS_0", "WEIGHTS_1"):
        accessor = gltf.accessors[getattr(primitive.attributes, name)]
        assert accessor.normalized and accessor.componentType == pygltflib.UNSIGNED_SHORT
    units = np.rint(weights * 65535).astype(np.int64)
    assert np.allclose(units, weights * 65535, rtol=0, atol=1e-6)  # whole numbers
    assert np.array_equal(units.sum(axis=1), np.full(len(weights), 65535))
    rows = np.repeat(np.arange(len(weights)), joints.shape[1])
    found = sp.csr_matrix((units.ravel(), (rows, joints.ravel())),
                          shape=(len(weights), reduced.count)).toarray()  # duplicates add up
    interpolation = reduced.interpolation
    exact = sp.csr_matrix((interpolation.weights.ravel(), (rows, interpolation.indices.ravel())),
                          shape=found.shape).toarray() * 65535
    assert np.abs(found - exact).max() < 1
    assert np.count_nonzero(units) > 2 * len(units)  # vertices blend several samples


@pytest.mark.parametrize("name, form", [("harmonic", "morph targets"),
                                        ("reduced_harmonic", "skin")])
def test_the_planned_glb_size_is_the_binary_chunk_written(request, tmp_path, name, form):
    """`glb_size` plans the binary chunk to the byte (the GLB header's chunk length)."""
    dance = request.getfixturevalue(name)
    report = export_dance(dance, tmp_path / "dance.glb", fps=15)
    data = (tmp_path / "dance.glb").read_bytes()
    json_length = int.from_bytes(data[12:16], "little")
    binary_length = int.from_bytes(data[20 + json_length:24 + json_length], "little")
    assert data[24 + json_length:28 + json_length] == b"BIN\0"
    assert len(data) == 28 + json_length + binary_length == report["bytes"]
    frames = len(file_times(dance.duration, 15))
    assert report["frames"] == frames
    assert glb_size(dance, frames)[form] == binary_length
