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
