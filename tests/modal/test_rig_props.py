"""Rigs as artists make them (docs/design.md#skeleton): meshes attached to a bone follow it,
joints that move nothing (IK and pole targets) are not bodies, and every mode of the gallery of
modes moves the skin visibly — on every fixture rig and, where the shared data is there, every
shared rig."""

from __future__ import annotations

import glob
import os

import numpy as np
import pytest

from eigendance.geometry import bounding_box_diagonal
from eigendance.modal.gltf_skin import moving_joints
from eigendance.modal.motion import body_transforms
from eigendance.modal.palette import mode_reach, single_mode_amplitudes
from eigendance.modal.rig import Rig
from eigendance.modal.sample_rigs import load_rig
from eigendance.modal.skinning import linear_blend_skinning
from helpers import fixture_path

REPO = os.path.join(os.path.dirname(__file__), "..", "..")
SHARED = next((path for path in (os.path.join(REPO, "..", "shared", "data", "rigged"),
                                 os.path.join(REPO, "..", "..", "shared", "data", "rigged"))
               if os.path.isdir(path)), "")  # the shared rigs, where the checkout has them
RIGS = sorted({os.path.basename(path): path for path in
               [*(glob.glob(os.path.join(SHARED, "*.gl*")) if SHARED else ()),
                *glob.glob(fixture_path("rigged", "*.gl*"))]}.values(), key=os.path.basename)
PROPS = {"quaternius_Character_Gun.glb": "Gun", "quaternius_Astronaut_FinnTheFrog.glb": "Pistol"}


def test_joints_that_move_nothing_are_left_out_by_the_rule():
    # root → hips → (spine → twist → arm, leg → pole); the twist bone carries nothing but
    # connects spine and arm; the root and the pole target carry nothing and connect nothing.
    parents = np.array([-1, 0, 1, 2, 3, 1, 5])
    carrying = np.array([0, 0, 1, 0, 1, 1, 0], dtype=bool)
    assert moving_joints(parents, carrying).tolist() == [False, True, True, True, True, True,
                                                         False]
    # hips carries nothing but joins spine and leg; a separate tree of targets is dropped
    parents = np.array([-1, 0, 0, -1, 3])
    carrying = np.array([0, 1, 1, 0, 0], dtype=bool)
    assert moving_joints(parents, carrying).tolist() == [True, True, True, False, False]


@pytest.mark.parametrize("path", RIGS, ids=os.path.basename)
def test_every_rig_builds_without_helper_bones_and_every_mode_moves_the_skin(path):
    skeleton = load_rig(path)
    assert not [b.name for b in skeleton.bodies if "pole" in b.name.lower()]
    # A body that carries no vertex is kept only to connect bodies that do: ≥ 2 joints.
    carried = skeleton.weights.max(axis=0)
    degree = np.bincount(skeleton.joint_pairs.ravel(), minlength=skeleton.n_bodies)
    assert np.all((carried > 0) | (degree >= 2)), [
        b.name for b, c, d in zip(skeleton.bodies, carried, degree, strict=True)
        if not c and d < 2]
    rig = Rig.from_skeleton(skeleton, dtype=np.float64)
    diagonal = bounding_box_diagonal(skeleton.vertices)
    # The gallery of modes: the first 16 modes, each alone at its tile's amplitude.
    count = min(16, rig.model.n_modes)
    coefficients = np.diag(single_mode_amplitudes(rig.model) / mode_reach(rig.model))[:count]
    moved = np.linalg.norm(rig.skin.positions(coefficients) - skeleton.vertices, axis=-1)
    assert np.all(moved.max(axis=1) >= 1e-3 * diagonal), moved.max(axis=1) / diagonal
    assert carried.max() > 0


@pytest.mark.parametrize("name", sorted(PROPS))
def test_a_mesh_attached_to_a_bone_follows_it(name):
    skeleton = load_rig(fixture_path("rigged", name))
    look = skeleton.appearance
    # The prop's vertices: those weighted wholly to one body whose joint node holds the prop.
    rig = Rig.from_skeleton(skeleton, dtype=np.float64)
    single = np.flatnonzero(skeleton.weights.max(axis=1) > 1 - 1e-9)
    assert len(single) and look is not None
    coefficients = np.zeros((2, rig.model.n_modes))
    coefficients[1, :4] = 0.1 * single_mode_amplitudes(rig.model)[:4] / \
        mode_reach(rig.model)[:4]
    transforms = body_transforms(rig.model, coefficients)
    moved = linear_blend_skinning(skeleton.vertices, skeleton.weights, transforms)
    hand = np.argmax(np.bincount(skeleton.weights[single].argmax(axis=1)))
    prop = single[skeleton.weights[single].argmax(axis=1) == hand]
    # rigid under LBS: the prop's pairwise distances are kept, and it moves
    before, after = skeleton.vertices[prop[:200]], moved[1][prop[:200]]
    np.testing.assert_allclose(np.linalg.norm(after[:, None] - after[None], axis=-1),
                               np.linalg.norm(before[:, None] - before[None], axis=-1),
                               atol=1e-9 * bounding_box_diagonal(skeleton.vertices))
    assert np.abs(after - before).max() > 1e-3 * bounding_box_diagonal(skeleton.vertices)
    # under modal skinning it follows its body to first order
    modal = rig.skin.positions(coefficients)[1][prop]
    assert np.abs(modal - moved[1][prop]).max() < 0.1 * np.abs(moved[1][prop] -
                                                             skeleton.vertices[prop]).max()
    assert any("attached to bones" in note for note in skeleton.notes)
    assert any("left out" in note and "PoleTarget" in note for note in skeleton.notes)
