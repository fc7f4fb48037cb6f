"""The parts of a skeleton: rigid cylindrical bodies and the elastic joints between them, their
frames, and the ranges the modal analysis handles (docs/design.md#skeleton, #joints).

- body frame: origin at the centre of mass, x along the axis (y, z a deterministic completion);
  mass m = ρπr²ℓ, principal inertia J = (½mr², m(3r²+ℓ²)/12, m(3r²+ℓ²)/12); spatial inertia
  diag(J, m·I₃) in [ω; v] ordering.
- joint frame: origin at the joint position P; z = the joint's `axis` if given, else
  unit(d_i × d_l), else a deterministic unit vector perpendicular to d_i; x = d_i made orthogonal
  to z (a deterministic perpendicular of z when d_i ∥ z); y = z × x.

`check_skeleton` is the one check of a skeleton's bodies and joints (`Skeleton` runs it when
made, the skeleton JSON reader on the bodies before it computes with their masses).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from eigendance.errors import InputError
from eigendance.geometry import (
    MAX_COORDINATE,
    bounding_box_diagonal,
    cross,
    frame_from_xz,
    perpendicular,
    unit,
)

# Constrained rows of [ωx ωy ωz vx vy vz] in the joint frame (thesis Table 3.1).
CONSTRAINED_ROWS = {
    "revolute": (0, 1, 3, 4, 5),
    "prismatic": (0, 1, 2, 3, 4),
    "cylindrical": (0, 1, 3, 4),
    "spherical": (3, 4, 5),
}
JOINT_TYPES = tuple(CONSTRAINED_ROWS)

DEFAULT_DENSITY = 1000.0  # kg/m³, about that of water and of living tissue


# What a skeleton may hold: the range in which the modal analysis works, measured by
# tests/fuzz/test_parsers.py. The analysis mixes rotations (no unit) and translations (the rig's
# length unit) in one matrix, so its rank tolerance and the Cholesky factor of M̃ fail on rigs
# far from unit size; K̃/M̃ overflows beyond the physical range.
PHYSICAL_RANGE = (1e-100, 1e100)  # each body's mass and moments, each joint stiffness (or 0)
SIZE_RANGE = (1e-4, 1e6)  # bounding-box diagonal of the body ends, in the rig's unit
ASPECT_RANGE = (1e-6, 1e3)  # radius / length of a body
MAX_LENGTH_RATIO = 1e3  # longest body / shortest body
MAX_DENSITY_RATIO = 1e12  # densest body / lightest body


def body_rotation(direction) -> np.ndarray:
    """World-from-body rotation with x = direction and a deterministic y, z.

    Parameters
    ----------
    direction : (3,) the body's axis (any length but 0).

    Returns
    -------
    (3, 3) rotation, columns x = direction/|direction|, y, z.
    """
    x = unit(direction)
    y = perpendicular(x)
    return np.column_stack([x, y, cross(x, y)])


@dataclass
class Body:
    """A solid cylinder from `start` to `end`.

    Parameters
    ----------
    name : how joints and messages call it.
    start, end : (3,) the axis's ends, the rig's length unit.
    radius : the cylinder's radius, same unit.
    density : kg per unit³ (DEFAULT_DENSITY, water).
    """

    name: str
    start: np.ndarray
    end: np.ndarray
    radius: float
    density: float = DEFAULT_DENSITY

    @property
    def length(self) -> float:
        """|end − start|, the rig's unit."""
        return float(np.linalg.norm(self.end - self.start))

    @property
    def direction(self) -> np.ndarray:
        """(3,) unit vector from start to end."""
        return unit(self.end - self.start, f"body {self.name!r}")

    @property
    def center(self) -> np.ndarray:
        """(3,) the centre of mass, half-way along the axis."""
        return (self.start + self.end) / 2

    @property
    def rotation(self) -> np.ndarray:
        """World-from-body rotation (3, 3): x along the axis (`body_rotation`)."""
        return body_rotation(self.end - self.start)

    @property
    def mass(self) -> float:
        """m = ρπr²ℓ."""
        return self.density * math.pi * self.radius**2 * self.length

    @property
    def inertia(self) -> np.ndarray:
        """Principal moments (Jx, Jy, Jz) about the centre of mass, x along the axis."""
        m, r, l = self.mass, self.radius, self.length
        transverse = m * (3 * r**2 + l**2) / 12
        return np.array([m * r**2 / 2, transverse, transverse])


@dataclass
class Joint:
    """An elastic joint between two bodies at `position`.

    Parameters
    ----------
    name : how edits and messages call it.
    type : "revolute", "prismatic", "cylindrical" or "spherical" (`JOINT_TYPES`).
    bodies : (i, l) the indices of its two bodies.
    position : (3,) where it is, P.
    stiffness : one value per free row of the joint type, in the order of the free rows of
        [ωx ωy ωz vx vy vz] in the joint frame.
    axis : (3,) its rotation or sliding axis, or None (the normal of the bodies' plane).
    damping : read and kept; the modes are undamped.
    """

    name: str
    type: str
    bodies: tuple[int, int]
    position: np.ndarray
    stiffness: np.ndarray
    axis: np.ndarray | None = None
    damping: float = 0.0

    @property
    def constrained_rows(self) -> tuple[int, ...]:
        """The rows of [ωx ωy ωz vx vy vz] the joint type constrains."""
        return CONSTRAINED_ROWS[self.type]

    @property
    def free_rows(self) -> tuple[int, ...]:
        """The rows it leaves free (one stiffness each)."""
        return tuple(row for row in range(6) if row not in CONSTRAINED_ROWS[self.type])




# The largest rig analysed (docs/design.md#rig-size): the modal analysis is dense in the 6 n_b
# rigid-body coordinates, its time grows as n_b³ and the modal skin's memory as n_b × vertices.
# Measured (benchmarks/bench_limits.py, 2 loaded cores): a glTF chain of 250 joints takes 11 s
# and 0.25 GB, of 500 joints 49 s; a skeleton JSON of 200 bodies (its tube skin of 19,200
# vertices) 31 s and 1.4 GB, of 300 bodies 75 s and 3.1 GB.
MAX_BODIES, MAX_JOINTS = 256, 512


def check_rig_size(bodies: int, joints: int, name: str) -> None:
    """InputError when a rig has more than MAX_BODIES bodies or MAX_JOINTS joints (checked
    before anything is computed from them).

    Parameters
    ----------
    bodies : how many bodies (or glTF joints that become bodies).
    joints : how many joints.
    name : how messages call the rig.

    Example
    -------
    >>> check_rig_size(100, 99, "snake.json")   # within the limits: nothing to say
    >>> try:
    ...     check_rig_size(1000, 999, "snake.json")
    ... except InputError as error:
    ...     print(str(error)[:38])
    snake.json: 1000 bodies and 999 joints
    """
    if bodies > MAX_BODIES or joints > MAX_JOINTS:
        raise InputError(f"{name}: {bodies} bodies and {joints} joints; eigendance analyses "
                         f"rigs of at most {MAX_BODIES} bodies and {MAX_JOINTS} joints")


def check_skeleton(bodies: list[Body], joints: list[Joint], name: str) -> None:
    """InputError, naming the skeleton and the first part at fault, unless the bodies and joints
    make a skeleton the modal analysis handles (`check_bodies`, `check_joints`).

    Parameters
    ----------
    bodies : the skeleton's bodies.
    joints : its pairwise joints (bodies given by index).
    name : how messages call the skeleton (a file name).
    """
    check_rig_size(len(bodies), len(joints), name)
    check_bodies(bodies, name)
    check_joints(joints, len(bodies), name)


def check_bodies(bodies: list[Body], name: str) -> None:
    """InputError, naming the first body at fault, unless the bodies are valid and keep to the
    ranges the modal analysis handles: at least one body, unique names, finite values, positive
    length, radius and density; then coordinates, SIZE_RANGE, ASPECT_RANGE, PHYSICAL_RANGE for
    masses and moments, MAX_LENGTH_RATIO and MAX_DENSITY_RATIO (in that order: each check keeps
    the numbers of the next one finite).

    Parameters
    ----------
    bodies : the bodies.
    name : how messages call the skeleton.
    """
    names = [body.name for body in bodies]
    if not bodies:
        raise InputError(f"{name}: the skeleton has no bodies")
    duplicates = sorted({n for n in names if names.count(n) > 1})
    if duplicates:
        raise InputError(f"{name}: duplicate body name {duplicates[0]!r}")
    for body in bodies:
        if not (np.all(np.isfinite(body.start)) and np.all(np.isfinite(body.end))
                and math.isfinite(body.radius) and math.isfinite(body.density)):
            raise InputError(f"{name}: body {body.name!r} has a non-finite value")
        if not body.length > 0:
            raise InputError(f"{name}: body {body.name!r} has zero length")
        if not body.radius > 0 or not body.density > 0:
            raise InputError(f"{name}: body {body.name!r} needs a positive radius and density")
    _check_body_ranges(bodies, name)


def _check_body_ranges(bodies: list[Body], name: str) -> None:
    """The ranges of `check_bodies`, on bodies already known finite and of positive sizes."""
    ends = np.array([end for body in bodies for end in (body.start, body.end)], dtype=float)
    if not (np.all(np.isfinite(ends)) and np.abs(ends).max() <= MAX_COORDINATE):
        raise InputError(f"{name}: coordinates must lie within ±{MAX_COORDINATE:.0e}")
    size = bounding_box_diagonal(ends)
    if not SIZE_RANGE[0] <= size <= SIZE_RANGE[1]:
        raise InputError(f"{name}: the rig spans {size:.3g}; rigs from {SIZE_RANGE[0]:g} to "
                         f"{SIZE_RANGE[1]:g} units across can be analysed (rescale it)")
    low, high = PHYSICAL_RANGE
    for body in bodies:
        aspect = body.radius / body.length
        if not ASPECT_RANGE[0] <= aspect <= ASPECT_RANGE[1]:
            raise InputError(f"{name}: body {body.name!r} has radius / length = {aspect:.3g}, "
                             f"outside {ASPECT_RANGE[0]:g} … {ASPECT_RANGE[1]:g}")
        values = np.array([body.mass, *body.inertia])
        if not np.all((values >= low) & (values <= high)):
            raise InputError(f"{name}: body {body.name!r} has a mass or moment of inertia "
                             f"outside {low:g} … {high:g} (check its density {body.density:g} "
                             f"and radius {body.radius:g})")
    lengths = np.array([body.length for body in bodies])
    densities = np.array([body.density for body in bodies])
    if lengths.max() > MAX_LENGTH_RATIO * lengths.min():
        raise InputError(f"{name}: body lengths range from {lengths.min():.3g} to "
                         f"{lengths.max():.3g}, more than {MAX_LENGTH_RATIO:g} times apart")
    if densities.max() > MAX_DENSITY_RATIO * densities.min():
        raise InputError(f"{name}: densities range from {densities.min():.3g} to "
                         f"{densities.max():.3g}, more than {MAX_DENSITY_RATIO:g} times apart")


def check_joints(joints: list[Joint], n_bodies: int, name: str) -> None:
    """InputError, naming the first joint at fault, unless every joint lies within
    ±MAX_COORDINATE, has stiffnesses 0 or within PHYSICAL_RANGE, joins two different bodies of
    the `n_bodies`, has a known type and one finite stiffness ≥ 0 per free row.

    Parameters
    ----------
    joints : the joints.
    n_bodies : how many bodies the skeleton has.
    name : how messages call the skeleton.
    """
    low, high = PHYSICAL_RANGE
    for joint in joints:
        position = np.asarray(joint.position, dtype=float)
        if not (np.all(np.isfinite(position)) and np.abs(position).max() <= MAX_COORDINATE):
            raise InputError(f"{name}: joint {joint.name!r} lies beyond ±{MAX_COORDINATE:.0e}")
        stiffness = np.asarray(joint.stiffness, dtype=float)
        bad = stiffness[(stiffness > high) | ((stiffness > 0) & (stiffness < low))]
        if len(bad):
            raise InputError(f"{name}: joint {joint.name!r} has stiffness {bad[0]:g}; "
                             f"it must be 0 or from {low:g} to {high:g}")
    for joint in joints:
        i, l = joint.bodies
        if i == l:
            raise InputError(f"{name}: joint {joint.name!r} joins a body to itself")
        if not (0 <= i < n_bodies and 0 <= l < n_bodies):
            raise InputError(f"{name}: joint {joint.name!r} joins a body that does not exist")
        if joint.type not in CONSTRAINED_ROWS:
            raise InputError(f"{name}: joint {joint.name!r} has unknown type {joint.type!r} "
                             f"(use {', '.join(JOINT_TYPES)})")
        if joint.stiffness.shape != (len(joint.free_rows),):
            raise InputError(f"{name}: joint {joint.name!r} needs 1 or {len(joint.free_rows)} "
                             f"stiffness values for a {joint.type} joint")
        if not (np.all(np.isfinite(joint.position)) and np.all(np.isfinite(joint.stiffness))
                and np.all(joint.stiffness >= 0)):
            raise InputError(f"{name}: joint {joint.name!r} has a non-finite or negative value")


def meeting_point(a: Body, b: Body) -> np.ndarray:
    """Where two bodies meet: a shared end if they have one, else the midpoint of the closest
    points of their axes (thesis §3.2.1: the joint sits where the axes intersect).

    Parameters
    ----------
    a, b : two bodies.

    Returns
    -------
    (3,) the point.
    """
    ends_a, ends_b = (a.start, a.end), (b.start, b.end)
    scale = max(a.length, b.length)
    for p in ends_a:
        for q in ends_b:
            if np.linalg.norm(p - q) <= 1e-9 * scale:
                return (p + q) / 2
    d1, d2, r = a.end - a.start, b.end - b.start, a.start - b.start
    aa, bb, ab, ar, br = d1 @ d1, d2 @ d2, d1 @ d2, d1 @ r, d2 @ r
    denominator = aa * bb - ab * ab
    if denominator <= 1e-12 * aa * bb:  # parallel: nearest pair of ends
        pairs = [(p, q) for p in ends_a for q in ends_b]
        p, q = min(pairs, key=lambda pq: np.linalg.norm(pq[0] - pq[1]))
        return (p + q) / 2
    s = (ab * br - bb * ar) / denominator
    t = (aa * br - ab * ar) / denominator
    return (a.start + s * d1 + b.start + t * d2) / 2


def joint_frame(joint: Joint, bodies: list[Body]) -> np.ndarray:
    """World-from-joint rotation (columns x, y, z) of a joint (docs/design.md#joints).

    Parameters
    ----------
    joint : the joint.
    bodies : the skeleton's bodies (the joint's two by index).

    Returns
    -------
    (3, 3) rotation.
    """
    d_i = bodies[joint.bodies[0]].direction
    d_l = bodies[joint.bodies[1]].direction
    if joint.axis is not None:
        z = unit(joint.axis, f"axis of joint {joint.name!r}")
    else:
        normal = cross(d_i, d_l)
        z = normal / np.linalg.norm(normal) if np.linalg.norm(normal) > 1e-9 \
            else perpendicular(d_i)
    return frame_from_xz(d_i, z)

