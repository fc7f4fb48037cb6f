"""Skeletons from glTF 2.0 skins: every rig loads and gives finite modes or a one-line error."""

import glob
import json

import numpy as np
import pytest
import trimesh

from eigendance.errors import EigendanceError
from eigendance.modal.model import ModalModel
from eigendance.modal.sample_rigs import load_rig
from helpers import fixture_path

FIXTURE_RIGS = ["RiggedSimple.glb", "SimpleSkin.gltf", "Fox.glb"]


def check_rig(skeleton):
    model = ModalModel.from_skeleton(skeleton, keep_matrices=True)
    assert np.all(np.isfinite(model.frequencies)) and np.all(np.isfinite(model.modes))
    assert model.rigid_modes == 6  # one connected free tree
    assert model.n_modes == 3 * len(skeleton.joints)  # spherical joints: 3 DOF each
    assert np.abs(model.matrices["G"] @ model.modes).max() < 1e-9 * np.abs(
        model.matrices["G"]).max()
    assert skeleton.weights.shape == (len(skeleton.vertices), skeleton.n_bodies)
    np.testing.assert_allclose(skeleton.weights.sum(axis=1), 1.0)
    assert skeleton.weights.min() >= 0
    assert skeleton.faces.min() >= 0 and skeleton.faces.max() < len(skeleton.vertices)
    for body in skeleton.bodies:
        assert body.length > 0 and 0 < body.radius <= body.length
    return model


@pytest.mark.parametrize("name", FIXTURE_RIGS)
def test_fixture_rigs_give_finite_modes(name):
    check_rig(load_rig(fixture_path("rigged", name)))


def test_simple_skin_bodies_follow_the_joint_nodes():
    """SimpleSkin (this revision): both joint nodes sit at (0, 1, 0) (the child has no
    translation), so neither has a child at a distance: each is a leaf body running toward the
    vertices it carries, the first down to y = 0, the second up to y = 2."""
    skeleton = load_rig(fixture_path("rigged", "SimpleSkin.gltf"))
    assert skeleton.n_bodies == 2 and len(skeleton.joints) == 1
    first, second = skeleton.bodies
    np.testing.assert_allclose(first.start, [0, 1, 0])
    np.testing.assert_allclose(second.start, [0, 1, 0])
    np.testing.assert_allclose(first.end, [0, 0, 0], atol=1e-12)
    np.testing.assert_allclose(second.end, [0, 2, 0], atol=1e-12)
    joint = skeleton.joints[0]
    assert joint.type == "spherical" and joint.bodies == (0, 1)
    np.testing.assert_allclose(joint.position, [0, 1, 0])
    assert len(skeleton.vertices) == 10
    np.testing.assert_allclose(skeleton.weights[4], [0.5, 0.5])


def test_fox_seams_are_welded():
    skeleton = load_rig(fixture_path("rigged", "Fox.glb"))
    assert len(skeleton.vertices) < 1728 / 2  # non-indexed triangles: corners shared after
    assert any("welded" in note for note in skeleton.notes)


def test_several_skins_sharing_one_skeleton(tmp_path):
    with open(fixture_path("rigged", "SimpleSkin.gltf")) as file:
        document = json.load(file)
    document["nodes"].append({"skin": 1, "mesh": 0})
    document["skins"].append(dict(document["skins"][0]))
    document["scenes"][0]["nodes"].append(len(document["nodes"]) - 1)
    path = tmp_path / "two-skins.gltf"
    path.write_text(json.dumps(document))
    skeleton = load_rig(path)
    assert skeleton.n_bodies == 2  # joints merged by node
    assert len(skeleton.vertices) == 10  # the two copies weld together
    check_rig(skeleton)


def test_a_file_without_skin_or_a_corrupt_file_gives_one_line(tmp_path):
    box = tmp_path / "box.glb"
    trimesh.creation.box().export(box)
    with pytest.raises(EigendanceError, match="has no skin") as caught:
        load_rig(box)
    assert "\n" not in str(caught.value)
    broken = tmp_path / "broken.glb"
    broken.write_bytes(b"glTF\x02\x00\x00\x00garbage")
    with pytest.raises(EigendanceError) as caught:
        load_rig(broken)
    assert "\n" not in str(caught.value)


FIXTURE_RIGS = sorted(glob.glob(fixture_path("rigged", "*.gl*")))


def test_every_fixture_rig_loads_with_finite_modes_or_says_why():
    assert len(FIXTURE_RIGS) >= 7
    for path in FIXTURE_RIGS:
        try:
            skeleton = load_rig(path)
        except EigendanceError as error:
            assert "\n" not in str(error)
            continue
        check_rig(skeleton)


def chain_gltf(joints: int) -> dict:
    """A glTF of a chain of `joints` joints along y, listed children first (node 0 is the
    deepest), each carrying two vertices of a strip of triangles."""
    import base64

    node = [joints - 1 - j for j in range(joints)]  # joint j (depth j) is node node[j]
    nodes = [None] * joints
    for j in range(joints):
        nodes[node[j]] = {"name": f"j{j}", "translation": [0, 0.1 if j else 0, 0],
                          **({"children": [node[j + 1]]} if j + 1 < joints else {})}
    y = 0.1 * np.repeat(np.arange(joints), 2)
    vertices = np.stack([np.tile([-0.05, 0.05], joints), y, 0 * y], axis=1).astype("<f4")
    a = 2 * np.arange(joints - 1)[:, None]
    faces = np.concatenate([a + [0, 1, 2], a + [1, 3, 2]]).astype("<u4")
    influences = np.zeros((2 * joints, 4), "<u2")
    influences[:, 0] = np.repeat(np.arange(joints), 2)
    weights = np.zeros((2 * joints, 4), "<f4")
    weights[:, 0] = 1
    inverse = np.tile(np.eye(4, dtype="<f4"), (joints, 1, 1))
    inverse[:, 3, 1] = -0.1 * np.arange(joints)  # column-major: the translation's y
    blobs = [vertices.tobytes(), faces.tobytes(), influences.tobytes(), weights.tobytes(),
             inverse.tobytes()]
    offsets = np.cumsum([0] + [len(blob) for blob in blobs])
    kinds = [("VEC3", 5126), ("SCALAR", 5125), ("VEC4", 5123), ("VEC4", 5126), ("MAT4", 5126)]
    counts = [len(vertices), faces.size, len(influences), len(weights), joints]
    accessors = [{"bufferView": i, "componentType": kind, "count": count, "type": shape}
                 for i, ((shape, kind), count) in enumerate(zip(kinds, counts, strict=True))]
    accessors[0].update(min=vertices.min(0).tolist(), max=vertices.max(0).tolist())
    nodes.append({"name": "skin", "mesh": 0, "skin": 0})
    data = b"".join(blobs)
    return {"asset": {"version": "2.0"}, "scene": 0,
            "scenes": [{"nodes": [node[0], joints]}], "nodes": nodes,
            "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "JOINTS_0": 2,
                                                       "WEIGHTS_0": 3}, "indices": 1}]}],
            "skins": [{"joints": node, "inverseBindMatrices": 4}], "accessors": accessors,
            "bufferViews": [{"buffer": 0, "byteOffset": int(offsets[i]),
                             "byteLength": len(blob)} for i, blob in enumerate(blobs)],
            "buffers": [{"byteLength": len(data), "uri": "data:application/octet-stream;"
                         "base64," + base64.b64encode(data).decode()}]}


def test_a_chain_deeper_than_the_recursion_limit_listed_children_first(tmp_path):
    """1,020 joints listed children first (issue 21: once a RecursionError): the tree is walked
    whole — the message counts every body — and the rig size limit refuses it in one line."""
    import sys

    from eigendance.errors import InputError
    from eigendance.modal.gltf_skin import skeleton_from_gltf

    path = tmp_path / "chain.gltf"
    path.write_text(json.dumps(chain_gltf(1020)))  # under the 1,024 joints a skin may have
    assert sys.getrecursionlimit() < 1020
    with pytest.raises(InputError, match="1020 bodies and 1019 joints; .* at most 256 bodies"):
        skeleton_from_gltf(path)
