"""Joints a user can trust (docs/design.md#joints): hand-derived frequencies of prismatic and
cylindrical joints, the default stiffness rule, per-joint stiffness edits and rest-pose edits."""

import math

import numpy as np
import pytest

from eigendance.errors import EigendanceError
from eigendance.modal.bodies import Body, Joint
from eigendance.modal.model import ModalModel
from eigendance.modal.motion import body_poses
from eigendance.modal.rotations import rotation_exp
from eigendance.modal.sample_rigs import open_chain, planar_loop
from eigendance.modal.skeleton import Skeleton
from eigendance.modal.stiffness import automatic_stiffness


def rods(radii=(0.07, 0.05), densities=(900.0, 1300.0), lengths=(1.3, 0.8)):
    """Two rods along x meeting at the origin: a from (−ℓ_a, 0, 0), b to (ℓ_b, 0, 0)."""
    return [Body("a", np.array([-lengths[0], 0, 0]), np.zeros(3), radii[0], densities[0]),
            Body("b", np.zeros(3), np.array([lengths[1], 0, 0]), radii[1], densities[1])]


def test_prismatic_joint_along_the_rods_frequency_by_hand():
    """A prismatic joint along the rods' common axis x allows only a relative slide s along x.
    With zero total momentum the rods translate along x in opposite directions,
    m_a ẋ_a + m_b ẋ_b = 0 (no angular momentum: the motion is along the line of the centres), so
    with s = x_b − x_a the kinetic energy is ½ m_r ṡ², m_r = m_a m_b / (m_a + m_b), and the
    potential ½ k s²: ω² = k / m_r, the only vibration mode."""
    bodies = rods()
    k = 37.0
    joint = Joint("slide", "prismatic", (0, 1), np.zeros(3), np.array([k]),
                  axis=np.array([1.0, 0, 0]))
    model = ModalModel.from_skeleton(Skeleton(bodies, [joint]))
    reduced = bodies[0].mass * bodies[1].mass / (bodies[0].mass + bodies[1].mass)
    assert model.rigid_modes == 6 and model.n_modes == 1
    assert model.frequencies[0] == pytest.approx(math.sqrt(k / reduced) / (2 * math.pi),
                                                 rel=1e-9)
    twist = model.modes[:, 0].reshape(2, 6)
    assert np.abs(twist[:, :3]).max() < 1e-9 * np.abs(twist).max()  # no rotation at all
    np.testing.assert_allclose(twist[:, 4:], 0, atol=1e-9 * np.abs(twist).max())  # along x


@pytest.mark.parametrize("axis", [[0, 1.0, 0], [0.3, -0.4, 0.866]])
def test_prismatic_joint_across_the_rods_frequency_by_hand(axis):
    """A slide along a unit u off the line of the centres carries angular momentum, so the
    whole turns while the rods slide. Lagrange with the rigid motions eliminated: about the
    centre of mass G, with body b moved by s·u on top of a common velocity Ẋ and spin ω,
    T = ½M|Ẋ|² + ½ωᵀI_Gω + ½m_b ṡ² + m_b ṡ u·Ẋ + m_b ṡ (r_b × u)·ω (r_b = c_b − G). Minimising
    over Ẋ and ω leaves T = ½ m_eff ṡ² with m_eff = m_r − m_b² wᵀ I_G⁻¹ w, w = r_b × u, I_G the
    inertia tensor about G: Σ diag(½mr², m(3r²+ℓ²)/12, m(3r²+ℓ²)/12) (rods along x) + m(|r|²I −
    rrᵀ). Hence ω² = k / m_eff."""
    lengths, radii = (1.3, 0.8), (0.07, 0.05)
    bodies = rods(radii=radii, lengths=lengths)
    k = 37.0
    u = np.asarray(axis) / np.linalg.norm(axis)
    joint = Joint("slide", "prismatic", (0, 1), np.zeros(3), np.array([k]), axis=u)
    model = ModalModel.from_skeleton(Skeleton(bodies, [joint]))
    masses = np.array([b.mass for b in bodies])
    centres = np.array([[-lengths[0] / 2, 0, 0], [lengths[1] / 2, 0, 0]])
    centre = masses @ centres / masses.sum()
    inertia = np.zeros((3, 3))
    for m, r, ell, c in zip(masses, radii, lengths, centres, strict=True):
        offset = c - centre
        inertia += np.diag([m * r**2 / 2, m * (3 * r**2 + ell**2) / 12,
                            m * (3 * r**2 + ell**2) / 12])
        inertia += m * (offset @ offset * np.eye(3) - np.outer(offset, offset))
    w = np.cross(centres[1] - centre, u)
    effective = masses.prod() / masses.sum() - masses[1] ** 2 * w @ np.linalg.solve(inertia, w)
    assert model.rigid_modes == 6 and model.n_modes == 1
    assert model.frequencies[0] == pytest.approx(math.sqrt(k / effective) / (2 * math.pi),
                                                 rel=1e-9)


def test_cylindrical_joint_frequencies_by_hand():
    """A cylindrical joint along the common axis x of two rods frees the relative twist about x
    and the relative slide along x. The two do not couple (the rods are symmetric about x):
    - twist: opposite spins with J_a θ̇_a + J_b θ̇_b = 0, J = ½ m r² (moment about the rod's
      own axis), relative angle φ = θ_b − θ_a: T = ½ J_r φ̇², J_r = J_a J_b / (J_a + J_b),
      V = ½ k_ω φ², so ω² = k_ω / J_r;
    - slide: as for the prismatic joint, ω² = k_v / m_r.
    """
    bodies = rods()
    k_twist, k_slide = 0.9, 55.0
    joint = Joint("sleeve", "cylindrical", (0, 1), np.zeros(3), np.array([k_twist, k_slide]),
                  axis=np.array([1.0, 0, 0]))
    model = ModalModel.from_skeleton(Skeleton(bodies, [joint]))
    spins = [0.5 * b.mass * b.radius**2 for b in bodies]
    reduced_spin = spins[0] * spins[1] / (spins[0] + spins[1])
    reduced_mass = bodies[0].mass * bodies[1].mass / (bodies[0].mass + bodies[1].mass)
    expected = sorted([math.sqrt(k_twist / reduced_spin), math.sqrt(k_slide / reduced_mass)])
    assert model.rigid_modes == 6 and model.n_modes == 2
    np.testing.assert_allclose(model.frequencies, np.array(expected) / (2 * math.pi), rtol=1e-9)


def subtree_rig(base_density=1000.0):
    """A base rod along −x, then a two-rod arm along +x: arm1 (0→1), arm2 (1→2), all r = 0.05;
    revolute joints about z at the origin ("shoulder") and at x = 1 ("elbow")."""
    bodies = [Body("base", np.array([-1.0, 0, 0]), np.zeros(3), 0.05, base_density),
              Body("arm1", np.zeros(3), np.array([1.0, 0, 0]), 0.05),
              Body("arm2", np.array([1.0, 0, 0]), np.array([2.0, 0, 0]), 0.05)]
    joints = [Joint("shoulder", "revolute", (0, 1), np.zeros(3), np.zeros(1),
                    axis=np.array([0, 0, 1.0])),
              Joint("elbow", "revolute", (1, 2), np.array([1.0, 0, 0]), np.zeros(1),
                    axis=np.array([0, 0, 1.0]))]
    return bodies, joints


def test_default_stiffness_by_hand():
    """The rule (docs/design.md#joints): k = min over the two sides of g/d_s · I_s, with one
    gravity g = (2π·1 Hz)²·ℓ, ℓ = size/4 (size = 3, the extent of the body ends: ℓ = 0.75),
    d_s the distance from the joint to side s's centre of mass and I_s its moment of inertia
    about the joint axis. The base is heavy, so the arm's side gives the minimum. Shoulder: the
    arm (arm1 + arm2, centre at x = 1: d = 1), I = Σ m(3r² + ℓ²)/12 + m·c², c = 0.5 and 1.5
    (parallel axes). Elbow: arm2 alone (d = 0.5, c = 0.5) against base + arm1."""
    bodies, joints = subtree_rig(base_density=50_000.0)
    m = bodies[1].mass
    own = m * (3 * 0.05**2 + 1.0) / 12
    gravity = (2 * math.pi) ** 2 * 0.75
    by_hand = [gravity / 1.0 * (2 * own + m * (0.25 + 2.25)), gravity / 0.5 * (own + m * 0.25)]
    shoulder = automatic_stiffness(joints[0], bodies, 1.0, ([0], [1, 2]))
    elbow = automatic_stiffness(joints[1], bodies, 1.0, ([0, 1], [2]))
    assert shoulder[0] == pytest.approx(by_hand[0], rel=1e-12)
    assert elbow[0] == pytest.approx(by_hand[1], rel=1e-12)
    skeleton = Skeleton(bodies, joints)
    # The skeleton finds the sides itself: the same values, against the hand rule.
    np.testing.assert_allclose(skeleton.automatic_stiffness(0), by_hand[:1], rtol=1e-12)
    assert [side.tolist() for side in skeleton.joint_sides(0)] == [[0], [1, 2]]
    for index, values in enumerate(skeleton.automatic_stiffnesses()):
        np.testing.assert_allclose(values, [by_hand[index]], rtol=1e-12)


def test_default_stiffness_swings_an_arm_like_a_pendulum():
    """Dynamics of the rule: with a base 10⁶ times denser (nearly fixed) and a stiff elbow
    (the arm nearly rigid), the lowest mode is the arm swinging about the shoulder as a
    pendulum of length d = 1 under g = (2π)²·0.75: ω² = g/d, i.e. √0.75 Hz."""
    bodies, joints = subtree_rig(base_density=1e9)
    skeleton = Skeleton(bodies, joints)
    stiff = skeleton.automatic_stiffness(1)[0] * 1e6
    skeleton = skeleton.with_stiffness({"shoulder": "auto", "elbow": stiff})
    model = ModalModel.from_skeleton(skeleton)
    assert model.frequencies[0] == pytest.approx(math.sqrt(0.75), rel=1e-4)


def test_a_joint_in_a_loop_takes_its_own_two_bodies():
    """The square loop (corners on the unit circle, sides s = √2, r = 0.05): a joint has no
    sides, so each of its two rods is one, its centre d = s/2 from the joint and its inertia
    about the joint's z axis I = m(3r² + s²)/12 + m·d². The extent is the diagonal 2√2, so
    ℓ = √2/2 = d and k = g/d·I = (2π)²·I."""
    loop = planar_loop(4, skin=False)
    assert loop.joint_sides(0) is None
    joint = loop.joints[0]
    m = loop.bodies[0].mass
    by_hand = (2 * math.pi) ** 2 * (m * (3 * 0.05**2 + 2.0) / 12 + m * 0.5)
    by_bodies = automatic_stiffness(joint, loop.bodies, 1.0, None)
    np.testing.assert_allclose(by_bodies, [by_hand], rtol=1e-12)
    np.testing.assert_allclose(joint.stiffness, by_bodies, rtol=1e-12)


def test_with_stiffness_edits_one_joint_and_keeps_the_original():
    chain = open_chain(4, "spherical", skin=False)
    before = [joint.stiffness.copy() for joint in chain.joints]
    edited = chain.with_stiffness({"j1": [1.0, 2.0, 3.0], "j2": 7.5})
    assert edited.joints[1].stiffness.tolist() == [1.0, 2.0, 3.0]
    assert edited.joints[2].stiffness.tolist() == [7.5] * 3
    np.testing.assert_array_equal(edited.joints[0].stiffness, before[0])
    for joint, old in zip(chain.joints, before, strict=True):  # the original is untouched
        np.testing.assert_array_equal(joint.stiffness, old)
    back = edited.with_stiffness({"j1": "auto", 2: "auto"})
    for joint, old in zip(back.joints, before, strict=True):
        np.testing.assert_allclose(joint.stiffness, old, rtol=1e-12)
    base = ModalModel.from_skeleton(chain).frequencies
    scaled = ModalModel.from_skeleton(chain.with_stiffness({}, scale=4.0)).frequencies
    np.testing.assert_allclose(scaled, 2 * base, rtol=1e-9)


@pytest.mark.parametrize("values, message", [
    ({"elbow": 1.0}, "no joint named 'elbow'"),
    ({"j0": [1.0, 2.0]}, "list of 3 numbers"),
    ({"j0": -1.0}, "must be at least 0"),
    ({"j0": float("nan")}, "not finite"),
    ({"j0": "stiff"}, "must be a number, a list of 3 numbers"),
    ({7: 1.0}, "no joint 7"),
])
def test_bad_stiffness_edits_are_one_line_errors_naming_the_joint(values, message):
    chain = open_chain(3, "spherical", skin=False)
    with pytest.raises(EigendanceError, match=message) as caught:
        chain.with_stiffness(values)
    assert "\n" not in str(caught.value)


def test_rotating_a_joint_turns_its_child_side_rigidly_about_the_joint():
    chain = open_chain(3)  # tube skin, weights blending across joints
    turn = np.array([0.2, -0.4, 0.9])
    bent = chain.rotate_joint("j0", turn)
    pivot = chain.joints[0].position
    q = rotation_exp(turn)
    np.testing.assert_allclose(bent.bodies[0].start, chain.bodies[0].start)
    np.testing.assert_allclose(bent.bodies[0].end, chain.bodies[0].end)
    for index in (1, 2):
        for end in ("start", "end"):
            expected = pivot + q @ (getattr(chain.bodies[index], end) - pivot)
            np.testing.assert_allclose(getattr(bent.bodies[index], end), expected, atol=1e-12)
    np.testing.assert_allclose(bent.joints[1].position,
                               pivot + q @ (chain.joints[1].position - pivot), atol=1e-12)
    np.testing.assert_allclose(bent.joints[0].position, pivot)
    share = chain.weights[:, 1:].sum(axis=1)[:, None]  # weight on the turning side
    expected = chain.vertices + share * (pivot + (chain.vertices - pivot) @ q.T - chain.vertices)
    np.testing.assert_allclose(bent.vertices, expected, atol=1e-12)
    assert np.any(share == 0) and np.any(share == 1) and np.any((share > 0) & (share < 1))
    twice = bent.rotate_joint("j1", [0.0, 0.3, 0.0]).rotate_joint("j1", [0.0, -0.3, 0.0])
    back = twice.rotate_joint("j0", -turn)  # undoing every edit gives the mesh back exactly
    np.testing.assert_allclose(back.vertices, chain.vertices, atol=1e-12)
    np.testing.assert_allclose(chain.bodies[2].end, back.bodies[2].end, atol=1e-12)


def test_a_new_rest_pose_gets_new_modes_that_oscillate_about_it():
    """Fig. 4.17: after a pose edit the modes are those of the new pose (admissible for its
    constraints) and zero coefficients give the new pose."""
    chain = open_chain(4, "revolute", skin=False)
    bent = chain.rotate_joint("j1", [0.0, 0.0, 1.0])
    before = ModalModel.from_skeleton(chain)
    after = ModalModel.from_skeleton(bent, keep_matrices=True)
    assert after.n_modes == before.n_modes
    assert not np.allclose(after.frequencies, before.frequencies, rtol=1e-3)
    G = after.matrices["G"]
    assert np.abs(G @ after.modes).max() < 1e-10 * np.abs(G).max()
    rotations, centers = body_poses(after, np.zeros((1, after.n_modes)))
    np.testing.assert_allclose(centers[0], bent.centers, atol=1e-12)
    np.testing.assert_allclose(rotations[0], bent.rotations, atol=1e-12)


def test_pose_edits_refuse_loops_and_bad_rotations():
    with pytest.raises(EigendanceError, match="closes a loop"):
        planar_loop(8, symmetric=False, skin=False).rotate_joint("j3", [0, 0, 0.5])
    chain = open_chain(3, skin=False)
    for bad in ([0, 1], [0, float("inf"), 0], "up"):
        with pytest.raises(EigendanceError, match="3 finite numbers"):
            chain.rotate_joint("j0", bad)
    with pytest.raises(EigendanceError, match="no joint named 'knee'"):
        chain.rotate_joint("knee", [0, 0, 1])
