"""Modal analysis (docs/design.md#modal-model): the thesis's Table 4.1, hand-derived physics."""

import math

import numpy as np
import pytest

from eigendance.errors import EigendanceError
from eigendance.modal.bodies import Body, Joint
from eigendance.modal.model import ModalModel
from eigendance.modal.motion import (
    band_mapping,
    body_poses,
    body_transforms,
    mode_coefficients,
    mode_drive,
)
from eigendance.modal.rotations import rotation_exp
from eigendance.modal.sample_rigs import open_chain, planar_loop, sample_rig
from eigendance.modal.skeleton import Skeleton


@pytest.mark.parametrize("n_bodies, symmetric, shape, dimension", [
    (4, True, (20, 24), 7), (16, True, (80, 96), 19), (8, False, (40, 48), 11)])
def test_thesis_table_4_1_planar_loops(n_bodies, symmetric, shape, dimension):
    model = ModalModel.from_skeleton(planar_loop(n_bodies, symmetric), keep_matrices=True)
    assert model.matrices["G"].shape == shape
    assert model.constraint_rows == shape[0]
    assert model.nullspace_dim == dimension
    assert model.constraint_rank == shape[1] - dimension  # 3 rows dependent (the loop)
    assert model.rigid_modes == 6
    assert model.n_modes == dimension - 6


def check_modes(model):
    G, modes, mass = model.matrices["G"], model.modes, model.mass
    scale = np.abs(G).max()
    assert np.abs(G @ modes).max() < 1e-10 * scale
    gram = modes.T @ (mass[:, None] * modes)
    np.testing.assert_allclose(gram, np.eye(model.n_modes), atol=1e-9)
    assert np.all(np.isfinite(model.frequencies)) and np.all(model.frequencies > 0)
    assert np.all(np.diff(model.frequencies) >= -1e-12)


@pytest.mark.parametrize("name", ["loop4", "loop8", "loop16", "chain"])
def test_modes_are_admissible_and_mass_orthonormal(name):
    check_modes(ModalModel.from_skeleton(sample_rig(name), keep_matrices=True))


def test_free_tree_has_six_rigid_modes():
    # A branching tree: a trunk with two branches at its top, all spherical and revolute mixed.
    bodies = [Body("trunk", np.zeros(3), np.array([0, 0, 1.0]), 0.1),
              Body("left", np.array([0, 0, 1.0]), np.array([-0.7, 0, 1.6]), 0.05),
              Body("right", np.array([0, 0, 1.0]), np.array([0.7, 0.1, 1.5]), 0.05),
              Body("hand", np.array([0.7, 0.1, 1.5]), np.array([1.2, 0.3, 1.5]), 0.04)]
    document = {"format": "eigendance.skeleton", "version": 1,
                "bodies": [{"name": b.name, "start": b.start.tolist(), "end": b.end.tolist(),
                            "radius": b.radius} for b in bodies],
                "joints": [{"name": "top", "type": "spherical",
                            "bodies": ["trunk", "left", "right"], "stiffness": 50},
                           {"name": "wrist", "type": "revolute", "bodies": ["right", "hand"],
                            "stiffness": "auto"}]}
    skeleton = Skeleton.from_dict(document)
    assert len(skeleton.joints) == 4  # 3 pairs at the top + the wrist
    model = ModalModel.from_skeleton(skeleton, keep_matrices=True)
    assert model.rigid_modes == 6
    check_modes(model)


@pytest.mark.parametrize("n_bodies", [2, 3, 6])
def test_free_spherical_chain_vibrates_in_each_joint_dof(n_bodies):
    model = ModalModel.from_skeleton(open_chain(n_bodies, "spherical", skin=False),
                                     keep_matrices=True)
    assert model.nullspace_dim == 6 + 3 * (n_bodies - 1)
    assert model.rigid_modes == 6
    assert model.n_modes == 3 * (n_bodies - 1)
    check_modes(model)


def test_two_bodies_one_revolute_joint_frequency_by_hand():
    """Two identical rods (mass m, length ℓ, radius r) lie end to end along x and meet at the
    origin, where a revolute joint with axis z and stiffness k joins them. Free in space.

    Planar bending: the joint keeps the meeting point common, so with body angles θ₁, θ₂ about z
    and zero total momentum, symmetry gives θ₁ = θ, θ₂ = −θ and both centres of mass at rest
    (each rod turns about its own centre: the joint point moves by θℓ/2 along y on both rods).
    Kinetic energy T = 2 · ½ J θ̇² = J θ̇², with J = m(3r² + ℓ²)/12 the transverse inertia
    about the centre. The joint's deflection is the relative angle θ₁ − θ₂ = 2θ, so the
    potential is V = ½ k (2θ)² = 2kθ². Lagrange: 2J θ̈ + 4k θ = 0, so ω² = 2k/J and
    ν = √(2k/J) / 2π = √(24k / (m(3r² + ℓ²))) / 2π. Every other motion is rigid (6 modes) or
    twisting/bending the joint forbids, so this is the only vibration mode.
    """
    length, radius, density, k = 1.3, 0.07, 900.0, 42.0
    bodies = [Body("a", np.array([-length, 0, 0]), np.zeros(3), radius, density),
              Body("b", np.zeros(3), np.array([length, 0, 0]), radius, density)]
    joint = Joint("hinge", "revolute", (0, 1), np.zeros(3), np.array([k]),
                  axis=np.array([0, 0, 1.0]))
    model = ModalModel.from_skeleton(Skeleton(bodies, [joint]), keep_matrices=True)
    mass = density * math.pi * radius**2 * length
    inertia = mass * (3 * radius**2 + length**2) / 12
    assert model.rigid_modes == 6 and model.n_modes == 1
    assert model.frequencies[0] == pytest.approx(math.sqrt(2 * k / inertia) / (2 * math.pi),
                                                 rel=1e-10)
    twist = model.modes[:, 0].reshape(2, 6)
    # Opposite rotations about z (body frames share orientation here), centres at rest.
    assert np.allclose(twist[:, 3:], 0, atol=1e-12)
    assert twist[0, 2] == pytest.approx(-twist[1, 2])


def test_stiffness_and_density_scale_frequencies():
    skeleton = sample_rig("loop8")
    base = ModalModel.from_skeleton(skeleton).frequencies
    stiffer = ModalModel.from_skeleton(skeleton.scaled(stiffness=2.0)).frequencies
    heavier = ModalModel.from_skeleton(skeleton.scaled(density=2.0)).frequencies
    np.testing.assert_allclose(stiffer, base * math.sqrt(2), rtol=1e-9)
    np.testing.assert_allclose(heavier, base / math.sqrt(2), rtol=1e-9)
    np.testing.assert_allclose(ModalModel.from_skeleton(skeleton, stiffness=2.0).frequencies,
                               stiffer, rtol=1e-12)


def test_joint_frames_follow_design():
    skeleton = planar_loop(4, skin=False)
    for joint in skeleton.joints:
        rotation = skeleton.joint_rotation(joint)
        np.testing.assert_allclose(rotation.T @ rotation, np.eye(3), atol=1e-12)
        assert np.linalg.det(rotation) == pytest.approx(1.0)
        assert abs(abs(rotation[2, 2]) - 1) < 1e-12  # z = the plane's normal
        d_i = skeleton.bodies[joint.bodies[0]].direction
        assert rotation[:, 0] @ d_i == pytest.approx(1.0)  # x = d_i (already ⟂ z)


def test_body_poses_are_exact_rigid_motions_of_the_rest_pose():
    skeleton = sample_rig("chain")
    model = ModalModel.from_skeleton(skeleton)
    times = np.linspace(0, 2, 7)
    coefficients = mode_coefficients(model, times, time_scale=0.5)
    rotations, centers = body_poses(model, coefficients)
    assert rotations.shape == (7, skeleton.n_bodies, 3, 3)
    gram = np.swapaxes(rotations, -1, -2) @ rotations
    np.testing.assert_allclose(gram, np.broadcast_to(np.eye(3), gram.shape), atol=1e-12)
    np.testing.assert_allclose(np.linalg.det(rotations), 1.0, atol=1e-12)
    np.testing.assert_allclose(rotations[0], model.body_rotations, atol=1e-12)  # sin(0) = 0
    transforms = body_transforms(model, coefficients)
    moved = transforms[..., :3, :3] @ model.body_centers[None, :, :, None]
    np.testing.assert_allclose(moved[..., 0] + transforms[..., :3, 3], centers, atol=1e-12)


def test_rotation_exp_matches_small_angle_and_is_orthogonal(rng):
    vectors = rng.normal(size=(5, 3))
    rotations = rotation_exp(vectors)
    np.testing.assert_allclose(rotations @ np.swapaxes(rotations, 1, 2),
                               np.broadcast_to(np.eye(3), (5, 3, 3)), atol=1e-12)
    np.testing.assert_allclose(rotations @ vectors[..., None], vectors[..., None], atol=1e-12)


def test_drive_and_coefficients():
    model = ModalModel.from_skeleton(sample_rig("loop8"))
    times = np.linspace(0, 1, 11)
    silence = np.zeros((11, model.n_modes))
    assert np.all(mode_coefficients(model, times, drive=silence) == 0)
    only = mode_coefficients(model, times, modes=[1], drive=np.ones((11, 1)))
    assert np.all(only[:, [0, 2, 3, 4]] == 0) and np.any(only[:, 1] != 0)
    with pytest.raises(EigendanceError, match="out of range"):
        mode_coefficients(model, times, modes=[99])


class Bands:
    """A stand-in spectrogram: band values held constant in time."""

    def __init__(self, values):
        self.values = np.asarray(values, dtype=float)
        self.bands = self.values.shape[-1]

    def at(self, times):
        return np.broadcast_to(self.values, (*np.shape(times), self.values.shape[-1]))

    def smoothed(self, smoothing):
        return self


def unshaped(mapping):
    """The mapping without its envelope (its swell needs a spectrogram's frame rate)."""
    from dataclasses import replace

    from eigendance.music.envelope import Envelope

    return replace(mapping, envelope=Envelope())


def test_the_mode_drive_is_the_mapping_filter_over_the_modes():
    values = np.linspace(0, 1, 8)
    mapping = unshaped(band_mapping(8, 5))  # 8 bands over 5 modes, in order, a = 5/8
    phi = mode_drive(mapping, Bands(values), np.zeros(11), 5)
    assert phi.shape == (11, 5)
    # band ξ → mode ⌊(ξ + ½)·5/8⌋: modes 0 ← {0, 1}, 1 ← {2}, 2 ← {3, 4}, 3 ← {5}, 4 ← {6, 7}
    expected = 5 / 8 * np.array([values[0] + values[1], values[2], values[3] + values[4],
                                 values[5], values[6] + values[7]])
    np.testing.assert_allclose(phi[0], expected)
    np.testing.assert_allclose(mode_drive(unshaped(band_mapping(8, 4)), Bands(np.ones(8)), [0],
                                          4), 1.0)
    np.testing.assert_allclose(mode_drive(mapping, Bands(np.zeros(8)), [0], 5, offset=1.0),
                               1.0)  # thesis (6-2): silence keeps the base amplitude


def test_modal_file_round_trip(tmp_path):
    model = ModalModel.from_skeleton(sample_rig("loop8"))
    path = tmp_path / "loop.npz"
    model.save(path)
    with np.load(path) as data:
        for key in ("frequencies", "modes", "rigid_modes", "nullspace_dim", "constraint_rows",
                    "constraint_rank", "body_names"):
            assert key in data.files
    loaded = ModalModel.load(path)
    np.testing.assert_array_equal(loaded.frequencies, model.frequencies)
    np.testing.assert_array_equal(loaded.modes, model.modes)
    assert loaded.body_names == model.body_names
    assert (loaded.rigid_modes, loaded.nullspace_dim, loaded.constraint_rank) == (6, 11, 37)
    with pytest.raises(EigendanceError, match="no such file"):
        ModalModel.load(tmp_path / "missing.npz")


def test_null_space_of_many_rows_needs_no_square_of_them():
    """20,000 joints between two bodies: 100,000 constraint rows of 12 columns. The null space
    is that of AᵀA (eigenvectors of eigenvalue 0, computed independently here), and no LAPACK
    call sees a 100,000 × 100,000 matrix (it would overflow its 32-bit indices)."""
    from eigendance.modal.model import null_space

    rng = np.random.default_rng(0)
    rows = rng.standard_normal((5, 12))
    matrix = np.tile(rows, (20000, 1)) * rng.uniform(0.5, 2, (100000, 1))
    basis = null_space(matrix, 12)
    values, vectors = np.linalg.eigh(matrix.T @ matrix)
    expected = vectors[:, values < 1e-9 * values.max()]
    assert basis.shape == (12, 7) == expected.shape
    assert np.allclose(basis @ basis.T, expected @ expected.T, atol=1e-10)  # same subspace


def test_stiffness_beyond_the_range_of_numbers_is_one_clear_error():
    from eigendance.errors import InputError
    from eigendance.modal.model import ModalModel
    from eigendance.modal.sample_rigs import load_rig

    skeleton = load_rig("chain")
    with pytest.raises(InputError, match="beyond the range of numbers"):
        ModalModel.from_skeleton(skeleton, stiffness=1e300)
    finite = ModalModel.from_skeleton(skeleton, stiffness=1e60)  # about 1e30 Hz
    assert np.isfinite(finite.frequencies).all()
