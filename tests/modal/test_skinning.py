"""Modal skinning against linear blend skinning of exact body transforms (design.md#skinning)."""

import numpy as np
import pytest

from eigendance.errors import EigendanceError
from eigendance.geometry import vertex_normals
from eigendance.modal.model import ModalModel
from eigendance.modal.motion import body_transforms, mode_coefficients
from eigendance.modal.sample_rigs import load_rig, sample_rig
from eigendance.modal.skinning import ModalSkin, linear_blend_skinning
from helpers import fixture_path


def skinned_difference(skeleton, model, scale):
    times = np.linspace(0, 3, 9)
    coefficients = scale * mode_coefficients(model, times, phases=np.linspace(0, 2, model.n_modes))
    skin = ModalSkin(model, skeleton.vertices, skeleton.weights)
    modal = skin.positions(coefficients)
    exact = linear_blend_skinning(skeleton.vertices, skeleton.weights,
                                  body_transforms(model, coefficients))
    return np.abs(modal - exact).max(), np.abs(exact - skeleton.vertices).max()


@pytest.mark.parametrize("rig", ["loop8", "chain", "Fox.glb"])
def test_modal_and_linear_blend_skinning_agree_to_first_order(rig):
    skeleton = sample_rig(rig) if "." not in rig else load_rig(fixture_path("rigged", rig))
    model = ModalModel.from_skeleton(skeleton)
    big, motion_big = skinned_difference(skeleton, model, 0.1)
    small, motion_small = skinned_difference(skeleton, model, 0.05)
    assert motion_big > 0 and small < 0.1 * motion_small  # the motion itself is first order
    assert 3.2 < big / small < 4.8  # halving the amplitude quarters the difference


def test_zero_coefficients_give_the_rest_pose_and_normals():
    skeleton = sample_rig("loop4")
    model = ModalModel.from_skeleton(skeleton)
    skin = ModalSkin(model, skeleton.vertices, skeleton.weights, dtype=np.float32)
    still = np.zeros((2, model.n_modes))
    np.testing.assert_allclose(skin.positions(still), np.broadcast_to(
        skeleton.vertices, (2,) + skeleton.vertices.shape), atol=1e-6)
    normals = vertex_normals(skeleton.vertices, skeleton.faces)
    np.testing.assert_allclose(skin.normals(still, normals)[0], normals, atol=1e-6)
    moving = mode_coefficients(model, np.array([0.3]))
    turned = skin.normals(moving, normals)
    np.testing.assert_allclose(np.linalg.norm(turned, axis=-1), 1.0, atol=1e-5)
    exact_positions, exact_normals = linear_blend_skinning(
        skeleton.vertices, skeleton.weights, body_transforms(model, moving), normals)
    assert np.abs(exact_normals - turned).max() < 0.2  # same turn, to first order
    with pytest.raises(EigendanceError, match="modes"):
        skin.positions(np.zeros((1, model.n_modes + 1)))


def test_rigidly_bound_vertices_follow_their_body_exactly():
    skeleton = sample_rig("chain")
    model = ModalModel.from_skeleton(skeleton)
    weights = np.zeros_like(skeleton.weights)
    weights[np.arange(len(weights)), skeleton.weights.argmax(axis=1)] = 1.0
    coefficients = mode_coefficients(model, np.linspace(0, 1, 4))
    transforms = body_transforms(model, coefficients)
    positions = linear_blend_skinning(skeleton.vertices, weights, transforms)
    owner = weights.argmax(axis=1)
    rest = skeleton.vertices - model.body_centers[owner]
    for frame in range(4):
        moved = positions[frame] - transforms[frame, owner, :3, 3] - np.einsum(
            "nij,nj->ni", transforms[frame, owner, :3, :3], model.body_centers[owner])
        # distances to the body's centre are kept: a rigid motion
        np.testing.assert_allclose(np.linalg.norm(moved, axis=1), np.linalg.norm(rest, axis=1),
                                   atol=1e-12)
