"""The default joint stiffness: each side of a joint swings like a pendulum under one gravity
(docs/design.md#joints).

A joint's *sides* are the parts the skeleton falls into without it (`joint_sides`; a joint that
closes a loop has none, and its own two bodies stand in). `automatic_stiffness` gives a joint
the stiffness of the rule, `set_automatic_stiffness` gives it to many joints at once.
"""

from __future__ import annotations

import math

import numpy as np

from eigendance.geometry import bounding_box_diagonal
from eigendance.modal.bodies import Body, Joint, joint_frame

# Default joint stiffness (glTF rigs, built-in rigs, JSON joints with "stiffness": "auto"): each
# side of a joint (the parts the skeleton falls into without it; the joint's own two bodies when
# it closes a loop) swings about the joint like a pendulum of its own length under one gravity:
# a side whose centre of mass lies PENDULUM_LENGTH·size from the joint at this frequency, a
# side 4 times closer twice as fast (`automatic_stiffness`). Scale-free: a rig in centimetres
# moves like the same rig in metres.
DEFAULT_JOINT_FREQUENCY = 1.0  # Hz
PENDULUM_LENGTH = 0.25  # ℓ / size: a limb-sized length


def body_inertias(bodies: list[Body]) -> tuple:
    """World inertia tensors about the centres (n, 3, 3), masses (n,), centres (n, 3) and the
    skeleton's extent (the diagonal of the bounding box of the body ends).

    Parameters
    ----------
    bodies : the skeleton's bodies.

    Returns
    -------
    (tensors (n, 3, 3), masses (n,), centres (n, 3), extent).
    """
    rotations = np.array([body.rotation for body in bodies])
    moments = np.array([body.inertia for body in bodies])
    tensors = np.einsum("bij,bj,bkj->bik", rotations, moments, rotations)  # R diag(J) Rᵀ
    ends = np.array([[body.start, body.end] for body in bodies]).reshape(-1, 3)
    return (tensors, np.array([body.mass for body in bodies]),
            np.array([body.center for body in bodies]),
            bounding_box_diagonal(ends))


def inertia_about(inertias, members, point) -> tuple[np.ndarray, float]:
    """World inertia tensor (3, 3) about `point` and total mass of the bodies `members`:
    Σ_b R_b diag(J_b) R_bᵀ + m_b (|d_b|² I − d_b d_bᵀ), d_b = c_b − point (parallel axes).
    `inertias` = `body_inertias(bodies)`.

    Parameters
    ----------
    inertias : `body_inertias(bodies)`.
    members : indices of the bodies.
    point : (3,).

    Returns
    -------
    (tensor (3, 3), mass).
    """
    members = np.asarray(members, dtype=np.int64)
    tensors, masses, centres = (array[members] for array in inertias[:3])
    offsets = centres - point
    parallel = masses[:, None, None] * (np.einsum("bi,bi->b", offsets, offsets)[:, None, None]
                                        * np.eye(3) - np.einsum("bi,bj->bij", offsets, offsets))
    return (tensors + parallel).sum(axis=0), float(masses.sum())


def automatic_stiffness(joint: Joint, bodies: list[Body],
                        frequency: float = DEFAULT_JOINT_FREQUENCY,
                        sides: tuple | None = None, inertias=None) -> np.ndarray:
    """The default stiffness of a joint, one value per free row (docs/design.md#joints).

    Each side of the joint swings like a pendulum of its own length under one gravity for the
    whole rig: side s, held at the joint position P while the other side stays still, vibrates
    at ω_s² = g/d_s with g = (2πf)²·ℓ, ℓ = PENDULUM_LENGTH·size, d_s the distance from P to the
    side's centre of mass (at least 5% of ℓ). So k_row = min_s ω_s²·I_row(s), where I_row(s) is
    the side's moment of inertia about the joint frame's axis of that row through P (rotation
    rows ωx, ωy, ωz) or its mass (translation rows). A side whose centre lies ℓ from the joint
    swings at f Hz, one 4 times closer at 2f: big limbs slower than fingers.
    `sides`: the two lists of bodies (`Skeleton.joint_sides`); None (a joint closing a loop)
    takes the joint's own two bodies. `inertias`: `body_inertias(bodies)`, if already computed.

    Parameters
    ----------
    joint : the joint.
    bodies : the skeleton's bodies.
    frequency : f, Hz.
    sides : the joint's sides, or None.
    inertias : `body_inertias(bodies)`, or None.

    Returns
    -------
    (free rows,) stiffness: torque per radian for rotation rows, force per unit for translation
    rows.
    """
    inertias = inertias if inertias is not None else body_inertias(bodies)
    length = PENDULUM_LENGTH * inertias[3]
    gravity = (2 * math.pi * frequency) ** 2 * length
    frame = joint_frame(joint, bodies)
    groups = sides if sides is not None else ([joint.bodies[0]], [joint.bodies[1]])
    candidates = []
    for members in groups:
        tensor, mass = inertia_about(inertias, members, joint.position)
        moments = np.einsum("ia,ij,ja->a", frame, tensor, frame)  # e_aᵀ I e_a, joint axes
        centre = inertias[1][members] @ inertias[2][members] / mass
        distance = max(float(np.linalg.norm(centre - joint.position)), 0.05 * length)
        candidates.append(gravity / distance * np.concatenate([moments, [mass] * 3]))
    return np.minimum(*candidates)[list(joint.free_rows)]


def set_automatic_stiffness(bodies: list[Body], joints: list[Joint], indices=None,
                            frequency: float = DEFAULT_JOINT_FREQUENCY) -> None:
    """Give the joints at `indices` (default all) their `automatic_stiffness`, in place.

    Parameters
    ----------
    bodies : the skeleton's bodies.
    joints : its joints (changed in place).
    indices : the joints to set (None: all).
    frequency : f, Hz.
    """
    pairs = np.array([joint.bodies for joint in joints], dtype=np.int64).reshape(-1, 2)
    inertias = body_inertias(bodies)
    for index in range(len(joints)) if indices is None else indices:
        joints[index].stiffness = automatic_stiffness(
            joints[index], bodies, frequency, joint_sides(len(bodies), pairs, index), inertias)


def joint_sides(n_bodies: int, pairs: np.ndarray, index: int):
    """The bodies on each side of joint `index`: those reachable from each of its bodies
    without it.

    Parameters
    ----------
    n_bodies : the skeleton's number of bodies.
    pairs : (n_joints, 2) the two bodies of every joint.
    index : the joint.

    Returns
    -------
    (body i's side, body l's side), sorted int arrays; None when the joint closes a loop (its
    two bodies stay connected without it).
    """
    neighbours = [[] for _ in range(n_bodies)]
    for position, (i, l) in enumerate(pairs):
        if position != index:
            neighbours[i].append(l)
            neighbours[l].append(i)

    def reach(start):
        seen, stack = {start}, [start]
        while stack:
            for other in neighbours[stack.pop()]:
                if other not in seen:
                    seen.add(other)
                    stack.append(other)
        return seen

    first, second = pairs[index]
    side = reach(first)
    if second in side:
        return None
    return np.array(sorted(side)), np.array(sorted(reach(second)))


