"""Articulated skeletons: rigid cylindrical bodies joined by elastic joints
(docs/design.md#skeleton).

A `Skeleton` holds bodies (solid cylinders from `start` to `end`, radius r, density ρ) and joints
between pairs of bodies. A joint declared with three or more bodies becomes one joint per pair of
them (thesis §5.2). Frames:

- body frame: origin at the centre of mass, x along the axis (y, z a deterministic completion);
  mass m = ρπr²ℓ, principal inertia J = (½mr², m(3r²+ℓ²)/12, m(3r²+ℓ²)/12); spatial inertia
  diag(J, m·I₃) in [ω; v] ordering.
- joint frame: origin at the joint position P; z = the joint's `axis` if given, else
  unit(d_i × d_l), else a deterministic unit vector perpendicular to d_i; x = d_i made orthogonal
  to z (a deterministic perpendicular of z when d_i ∥ z); y = z × x.

Sources: the skeleton JSON (`Skeleton.from_json`, docs/design.md#skeleton-file) and glTF 2.0
skins (`eigendance.modal.gltf_skin.skeleton_from_gltf`).
In the JSON, a joint's "stiffness" is a number (every free row), a list (one per free row of
[ωx ωy ωz vx vy vz], in that order), or "auto" (`automatic_stiffness`); "position"
defaults to where the two bodies meet (a shared end, else the closest points of their axes);
"density" defaults to DEFAULT_DENSITY; "damping" is kept but the modes are undamped.

Editing (copies, the original is kept): `with_stiffness` sets joints' stiffness by name,
`rotate_joint` changes the rest pose by turning one side of a joint about it (thesis §4.5.6).
"""

from __future__ import annotations

import itertools
import json
import math
import os
from dataclasses import dataclass, field

import numpy as np

from eigendance.errors import InputError
from eigendance.files import finite_number, read_json
from eigendance.geometry import MAX_COORDINATE
from eigendance.modal.rotations import rotation_exp

# Constrained rows of [ωx ωy ωz vx vy vz] in the joint frame (thesis Table 3.1).
CONSTRAINED_ROWS = {
    "revolute": (0, 1, 3, 4, 5),
    "prismatic": (0, 1, 2, 3, 4),
    "cylindrical": (0, 1, 3, 4),
    "spherical": (3, 4, 5),
}
JOINT_TYPES = tuple(CONSTRAINED_ROWS)

DEFAULT_DENSITY = 1000.0  # kg/m³, about that of water and of living tissue
# Default joint stiffness (glTF rigs, built-in rigs, JSON joints with "stiffness": "auto"): each
# side of a joint (the parts the skeleton falls into without it; the joint's own two bodies when
# it closes a loop) swings about the joint like a pendulum of its own length under one gravity:
# a side whose centre of mass lies PENDULUM_LENGTH·size from the joint at this frequency, a
# side 4 times closer twice as fast (`automatic_stiffness`). Scale-free: a rig in centimetres
# moves like the same rig in metres.
DEFAULT_JOINT_FREQUENCY = 1.0  # Hz
PENDULUM_LENGTH = 0.25  # ℓ / size: a limb-sized length

# What a skeleton may hold: the range in which the modal analysis works, measured by
# tests/fuzz/test_parsers.py. The analysis mixes rotations (no unit) and translations (the rig's
# length unit) in one matrix, so its rank tolerance and the Cholesky factor of M̃ fail on rigs
# far from unit size; K̃/M̃ overflows beyond the physical range.
PHYSICAL_RANGE = (1e-100, 1e100)  # each body's mass and moments, each joint stiffness (or 0)
SIZE_RANGE = (1e-4, 1e6)  # bounding-box diagonal of the body ends, in the rig's unit
ASPECT_RANGE = (1e-6, 1e3)  # radius / length of a body
MAX_LENGTH_RATIO = 1e3  # longest body / shortest body
MAX_DENSITY_RATIO = 1e12  # densest body / lightest body


def unit(vector, name: str = "vector") -> np.ndarray:
    vector = np.asarray(vector, dtype=float)
    norm = np.linalg.norm(vector)
    if not norm > 0:
        raise InputError(f"{name} has zero length")
    return vector / norm


def cross(a, b) -> np.ndarray:
    """a × b of two 3-vectors (np.cross costs ~20 µs of set-up for a single pair)."""
    return np.array([a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                     a[0] * b[1] - a[1] * b[0]])


def perpendicular(direction) -> np.ndarray:
    """A deterministic unit vector perpendicular to the unit vector `direction`."""
    direction = np.asarray(direction, dtype=float)
    helper = np.zeros(3)
    helper[int(np.argmin(np.abs(direction)))] = 1.0
    return unit(cross(direction, helper))


def frame_from_xz(x_hint, z) -> np.ndarray:
    """Rotation (columns x, y, z) with the given z, x = x_hint made orthogonal to z."""
    z = unit(z)
    x = np.asarray(x_hint, dtype=float) - np.dot(x_hint, z) * z
    norm = np.linalg.norm(x)
    x = x / norm if norm > 1e-9 * max(1.0, np.linalg.norm(x_hint)) else perpendicular(z)
    return np.column_stack([x, cross(z, x), z])


def body_rotation(direction) -> np.ndarray:
    """World-from-body rotation with x = direction and a deterministic y, z."""
    x = unit(direction)
    y = perpendicular(x)
    return np.column_stack([x, y, cross(x, y)])


@dataclass
class Body:
    """A solid cylinder from `start` to `end`."""

    name: str
    start: np.ndarray
    end: np.ndarray
    radius: float
    density: float = DEFAULT_DENSITY

    @property
    def length(self) -> float:
        return float(np.linalg.norm(self.end - self.start))

    @property
    def direction(self) -> np.ndarray:
        return unit(self.end - self.start, f"body {self.name!r}")

    @property
    def center(self) -> np.ndarray:
        return (self.start + self.end) / 2

    @property
    def rotation(self) -> np.ndarray:
        """World-from-body rotation (3, 3): x along the axis (`body_rotation`)."""
        return body_rotation(self.end - self.start)

    @property
    def mass(self) -> float:
        return self.density * math.pi * self.radius**2 * self.length

    @property
    def inertia(self) -> np.ndarray:
        """Principal moments (Jx, Jy, Jz) about the centre of mass, x along the axis."""
        m, r, l = self.mass, self.radius, self.length
        transverse = m * (3 * r**2 + l**2) / 12
        return np.array([m * r**2 / 2, transverse, transverse])


@dataclass
class Joint:
    """An elastic joint between two bodies (indices `bodies` = (i, l)) at `position`.

    stiffness: one value per free row of the joint type, in the order of the free rows of
    [ωx ωy ωz vx vy vz] in the joint frame.
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
        return CONSTRAINED_ROWS[self.type]

    @property
    def free_rows(self) -> tuple[int, ...]:
        return tuple(row for row in range(6) if row not in CONSTRAINED_ROWS[self.type])


@dataclass
class Skeleton:
    """Bodies and pairwise joints, optionally with a skinned mesh.

    vertices (n, 3), faces (m, 3) and weights (n, n_bodies, rows summing to 1) describe the skin
    in the same coordinates as the bodies; all three are None for a bare skeleton. appearance:
    how the skin is drawn (materials, drawn vertices on these vertices), or None (clay). After
    rest-pose edits (`rotate_joint`), bind_vertices are the skin as loaded and pose
    (n_bodies, 4, 4) each body's rigid transform since then:
    vertices = Σ_b w_b pose_b · bind_vertices.

    Parameters
    ----------
    bodies : solid cylinders (lengths in any unit, densities in kg per unit³).
    joints : pairwise elastic joints, stiffness per free row.
    name : how messages call it (a file name).

    Example
    -------
    >>> arm = Body("arm", np.zeros(3), np.array([1.0, 0, 0]), radius=0.1)
    >>> hand = Body("hand", np.array([1.0, 0, 0]), np.array([1.0, 1, 0]), radius=0.1)
    >>> elbow = Joint("elbow", "revolute", (0, 1), np.array([1.0, 0, 0]), np.array([50.0]))
    >>> skeleton = Skeleton([arm, hand], [elbow])
    >>> skeleton.n_bodies, round(arm.mass, 2)        # ρπr²ℓ with ρ = 1000
    (2, 31.42)
    """

    bodies: list[Body]
    joints: list[Joint]
    name: str = "skeleton"
    vertices: np.ndarray | None = None
    faces: np.ndarray | None = None
    weights: np.ndarray | None = None
    notes: list[str] = field(default_factory=list)
    bind_vertices: np.ndarray | None = None
    pose: np.ndarray | None = None
    appearance: object = None  # assets.Appearance of the skin (docs/design.md#appearance)

    def __post_init__(self):
        names = [body.name for body in self.bodies]
        if not self.bodies:
            raise InputError(f"{self.name}: the skeleton has no bodies")
        duplicates = sorted({n for n in names if names.count(n) > 1})
        if duplicates:
            raise InputError(f"{self.name}: duplicate body name {duplicates[0]!r}")
        for body in self.bodies:
            if not (np.all(np.isfinite(body.start)) and np.all(np.isfinite(body.end))
                    and math.isfinite(body.radius) and math.isfinite(body.density)):
                raise InputError(f"{self.name}: body {body.name!r} has a non-finite value")
            if not body.length > 0:
                raise InputError(f"{self.name}: body {body.name!r} has zero length")
            if not body.radius > 0 or not body.density > 0:
                raise InputError(
                    f"{self.name}: body {body.name!r} needs a positive radius and density")
        self._check_ranges()
        for joint in self.joints:
            i, l = joint.bodies
            if i == l:
                raise InputError(f"{self.name}: joint {joint.name!r} joins a body to itself")
            if joint.type not in CONSTRAINED_ROWS:
                raise InputError(f"{self.name}: joint {joint.name!r} has unknown type "
                                      f"{joint.type!r} (use {', '.join(JOINT_TYPES)})")
            if joint.stiffness.shape != (len(joint.free_rows),):
                raise InputError(
                    f"{self.name}: joint {joint.name!r} needs 1 or {len(joint.free_rows)} "
                    f"stiffness values for a {joint.type} joint")
            if not (np.all(np.isfinite(joint.position)) and np.all(np.isfinite(joint.stiffness))
                    and np.all(joint.stiffness >= 0)):
                raise InputError(f"{self.name}: joint {joint.name!r} has a non-finite or "
                                      "negative value")

    def _check_ranges(self) -> None:
        """InputError for a skeleton outside the range the modal analysis handles: its bodies
        (`check_bodies`), joint positions and stiffnesses (PHYSICAL_RANGE)."""
        check_bodies(self.bodies, self.name)
        low, high = PHYSICAL_RANGE
        for joint in self.joints:
            position = np.asarray(joint.position, dtype=float)
            if not (np.all(np.isfinite(position)) and np.abs(position).max() <= MAX_COORDINATE):
                raise InputError(f"{self.name}: joint {joint.name!r} lies beyond "
                                 f"±{MAX_COORDINATE:.0e}")
            stiffness = np.asarray(joint.stiffness, dtype=float)
            bad = stiffness[(stiffness > high) | ((stiffness > 0) & (stiffness < low))]
            if len(bad):
                raise InputError(f"{self.name}: joint {joint.name!r} has stiffness {bad[0]:g}; "
                                 f"it must be 0 or from {low:g} to {high:g}")

    # ----------------------------------------------------------------- derived arrays
    @property
    def n_bodies(self) -> int:
        return len(self.bodies)

    @property
    def body_names(self) -> list[str]:
        return [body.name for body in self.bodies]

    @property
    def centers(self) -> np.ndarray:
        """Centres of mass, (n_bodies, 3)."""
        return np.array([body.center for body in self.bodies])

    @property
    def rotations(self) -> np.ndarray:
        """World-from-body rotations, (n_bodies, 3, 3)."""
        return np.array([body.rotation for body in self.bodies])

    @property
    def spatial_inertia(self) -> np.ndarray:
        """Diagonal of M, (6·n_bodies,): per body (Jx, Jy, Jz, m, m, m) in its body frame."""
        return np.concatenate([np.concatenate([b.inertia, [b.mass] * 3]) for b in self.bodies])

    def joint_rotation(self, joint: Joint) -> np.ndarray:
        """World-from-joint rotation (columns x, y, z) (docs/design.md#joints)."""
        return joint_frame(joint, self.bodies)

    @property
    def joint_pairs(self) -> np.ndarray:
        """(n_joints, 2) int64: the two bodies (i, l) of every joint."""
        return np.array([joint.bodies for joint in self.joints], dtype=np.int64).reshape(-1, 2)

    def joint_index(self, key) -> int:
        """The index of a joint given by name or by index; InputError naming the joint."""
        if isinstance(key, int | np.integer) and not isinstance(key, bool):
            if not 0 <= key < len(self.joints):
                raise InputError(f"{self.name}: no joint {key} (the rig has "
                                 f"{len(self.joints)} joints)")
            return int(key)
        found = [index for index, joint in enumerate(self.joints) if joint.name == key]
        if not found:
            raise InputError(f"{self.name}: no joint named {key!r}")
        return found[0]

    def joint_sides(self, index: int) -> tuple[np.ndarray, np.ndarray] | None:
        """The bodies on each side of joint `index` (body i's side, body l's side) as index
        arrays: the parts the skeleton falls into without this joint. None when the joint closes
        a loop (its two bodies stay connected without it)."""
        return _sides(self.n_bodies, self.joint_pairs, index)

    def automatic_stiffness(self, index: int,
                            frequency: float = DEFAULT_JOINT_FREQUENCY) -> np.ndarray:
        """The default stiffness of joint `index` ("auto"; `automatic_stiffness`)."""
        return automatic_stiffness(self.joints[index], self.bodies, frequency,
                                   self.joint_sides(index))

    def automatic_stiffnesses(self, frequency: float = DEFAULT_JOINT_FREQUENCY) -> list:
        """The default stiffness of every joint (the bodies' inertias computed once)."""
        inertias, pairs = body_inertias(self.bodies), self.joint_pairs
        return [automatic_stiffness(joint, self.bodies, frequency,
                                    _sides(self.n_bodies, pairs, index), inertias)
                for index, joint in enumerate(self.joints)]

    # ----------------------------------------------------------------- editing
    def with_stiffness(self, values: dict, scale: float = 1.0) -> Skeleton:
        """A copy with new stiffness for the joints named in `values`.

        Parameters
        ----------
        values : {joint name (or index): stiffness}, a stiffness being a number (every free row),
            a list with one number per free row of the joint, or "auto" (the default rule,
            `automatic_stiffness`).
        scale : then multiplies every joint's stiffness (1: unchanged).

        Example
        -------
        >>> from eigendance.modal.sample_rigs import open_chain
        >>> chain = open_chain(3, "revolute", skin=False)
        >>> chain.with_stiffness({"j0": 5.0}).joints[0].stiffness.tolist()
        [5.0]
        """
        if not isinstance(values, dict):
            raise InputError(f"{self.name}: joint stiffness must be given as "
                             "{joint name: stiffness}")
        if not (isinstance(scale, int | float) and math.isfinite(scale) and scale >= 0):
            raise InputError(f"{self.name}: the stiffness scale must be a finite number ≥ 0, "
                             f"not {scale!r}")
        edited = self.copy()
        for key, value in values.items():
            index = edited.joint_index(key)
            joint = edited.joints[index]
            label = f"{self.name}: joint {joint.name!r}"
            joint.stiffness = edited.automatic_stiffness(index) if value == "auto" else \
                _stiffness(value, joint, label)
        for joint in edited.joints:
            joint.stiffness = joint.stiffness * float(scale)
        return edited

    def rotate_joint(self, key, rotation) -> Skeleton:
        """A copy in a new rest pose: the side of joint `key` holding its second body turns
        about the joint (thesis §4.5.6, Fig. 4.17).

        Parameters
        ----------
        key : the joint's name or index.
        rotation : (3,) rotation vector in world coordinates, radians: the side turns by
            exp([rotation]×) about the joint's position P.

        Every body of that side moves rigidly, x ↦ P + Q(x − P) with Q = exp([rotation]×), and
        the joints inside it (positions, axes) with it; the skin follows by linear blend
        skinning from the skin as loaded, x = Σ_b w_b pose_b x_bind, where pose_b composes the
        edits of body b (so turning a joint back restores the mesh exactly). Stiffnesses are
        kept. A joint that closes a loop cannot turn one side alone: InputError.

        Example
        -------
        >>> from eigendance.modal.sample_rigs import open_chain
        >>> chain = open_chain(2, skin=False)         # b0 from (0, 0, 0) to (1, 0, 0), then b1
        >>> bent = chain.rotate_joint("j0", [0, 0, np.pi / 2])   # a quarter turn about z
        >>> x, y, z = chain.bodies[1].end - chain.bodies[1].start
        >>> bool(np.allclose(bent.bodies[1].end - bent.bodies[1].start, [-y, x, z]))
        True
        """
        index = self.joint_index(key)
        joint = self.joints[index]
        try:
            vector = np.asarray(rotation, dtype=float)
        except (TypeError, ValueError):
            vector = np.zeros(0)
        if vector.shape != (3,) or not np.all(np.isfinite(vector)):
            raise InputError(f"{self.name}: a joint rotation is 3 finite numbers (a rotation "
                             f"vector in radians), not {rotation!r}")
        sides = self.joint_sides(index)
        if sides is None:
            raise InputError(f"{self.name}: joint {joint.name!r} closes a loop; one side of it "
                             "cannot turn alone")
        moving = np.zeros(self.n_bodies, dtype=bool)
        moving[sides[1]] = True
        turn = rotation_exp(vector)
        pivot = joint.position

        def move(point):
            return pivot + turn @ (np.asarray(point, dtype=float) - pivot)

        edited = self.copy()
        for body_index in np.flatnonzero(moving):
            body = edited.bodies[body_index]
            body.start, body.end = move(body.start), move(body.end)
        for other in edited.joints:
            if moving[other.bodies[0]] and moving[other.bodies[1]]:
                other.position = move(other.position)
                if other.axis is not None:
                    other.axis = turn @ other.axis
        if edited.vertices is not None:
            if edited.bind_vertices is None:
                edited.bind_vertices = edited.vertices
                edited.pose = np.tile(np.eye(4), (self.n_bodies, 1, 1))
            step = np.eye(4)
            step[:3, :3], step[:3, 3] = turn, pivot - turn @ pivot
            edited.pose[moving] = step @ edited.pose[moving]
            blended = (edited.weights @ edited.pose[:, :3].reshape(self.n_bodies, 12))
            blended = blended.reshape(-1, 3, 4)
            edited.vertices = np.einsum("nij,nj->ni", blended[:, :, :3],
                                        edited.bind_vertices) + blended[:, :, 3]
        return edited

    def copy(self) -> Skeleton:
        """A deep copy (bodies, joints and skin arrays)."""
        bodies = [Body(b.name, b.start.copy(), b.end.copy(), b.radius, b.density)
                  for b in self.bodies]
        joints = [Joint(j.name, j.type, tuple(j.bodies), j.position.copy(), j.stiffness.copy(),
                        None if j.axis is None else j.axis.copy(), j.damping)
                  for j in self.joints]
        skin = [None if a is None else a.copy() for a in (self.vertices, self.faces,
                                                         self.weights)]
        posed = [None if a is None else a.copy() for a in (self.bind_vertices, self.pose)]
        return Skeleton(bodies, joints, self.name, *skin, list(self.notes), *posed,
                        self.appearance)

    @property
    def size(self) -> float:
        """Diagonal of the bounding box of all body ends (a length scale)."""
        ends = np.concatenate([[b.start for b in self.bodies], [b.end for b in self.bodies]])
        return float(np.linalg.norm(ends.max(axis=0) - ends.min(axis=0)))

    # ----------------------------------------------------------------- loading
    @classmethod
    def from_json(cls, path: str | os.PathLike, name: str | None = None) -> Skeleton:
        """Read a skeleton JSON file (docs/design.md#skeleton-file), checked like `from_dict`;
        messages call it `name` (default: the file's name)."""
        name = name or os.path.basename(os.fspath(path))
        return cls.from_dict(read_json(path, name), name=name)

    @classmethod
    def from_dict(cls, document, name: str = "skeleton") -> Skeleton:
        """Build from a parsed skeleton JSON (docs/design.md#skeleton-file), checking each item."""
        if not isinstance(document, dict) or document.get("format") != "eigendance.skeleton":
            raise InputError(f"{name}: not an eigendance skeleton "
                                  "(expected \"format\": \"eigendance.skeleton\")")
        if document.get("version") != 1:
            raise InputError(f"{name}: unsupported skeleton version "
                                  f"{_shown(document.get('version'))} (expected 1)")
        raw_bodies = document.get("bodies")
        raw_joints = document.get("joints", [])
        if not isinstance(raw_bodies, list) or not raw_bodies:
            raise InputError(f"{name}: \"bodies\" must be a non-empty list")
        if not isinstance(raw_joints, list):
            raise InputError(f"{name}: \"joints\" must be a list")
        bodies = []
        for index, item in enumerate(raw_bodies):
            label = f"{name}: body {index}"
            if not isinstance(item, dict):
                raise InputError(f"{label} is not an object")
            body_name = item.get("name")
            if not isinstance(body_name, str) or not body_name:
                raise InputError(f"{label} needs a \"name\" string")
            label = f"{name}: body {body_name!r}"
            start = _vector(item.get("start"), f"{label}: \"start\"")
            end = _vector(item.get("end"), f"{label}: \"end\"")
            radius = _number(item.get("radius"), f"{label}: \"radius\"", positive=True)
            density = _number(item.get("density", DEFAULT_DENSITY), f"{label}: \"density\"",
                              positive=True)
            if not np.linalg.norm(end - start) > 0:
                raise InputError(f"{label} has zero length (start = end)")
            bodies.append(Body(body_name, start, end, radius, density))
        names = [body.name for body in bodies]
        for body_name in names:
            if names.count(body_name) > 1:
                raise InputError(f"{name}: duplicate body name {body_name!r}")
        check_bodies(bodies, name)  # before "auto" stiffness computes with their masses
        index_of = {body_name: i for i, body_name in enumerate(names)}
        joints, automatic = [], []
        joint_names = set()
        for index, item in enumerate(raw_joints):
            label = f"{name}: joint {index}"
            if not isinstance(item, dict):
                raise InputError(f"{label} is not an object")
            joint_name = item.get("name", f"joint{index}")
            if not isinstance(joint_name, str):
                raise InputError(f"{label}: \"name\" must be a string")
            label = f"{name}: joint {joint_name!r}"
            if joint_name in joint_names:
                raise InputError(f"{name}: duplicate joint name {joint_name!r}")
            joint_names.add(joint_name)
            kind = item.get("type")
            if not isinstance(kind, str) or kind not in CONSTRAINED_ROWS:
                raise InputError(f"{label} has unknown type {_shown(kind)} "
                                      f"(use {', '.join(JOINT_TYPES)})")
            members = item.get("bodies")
            if not isinstance(members, list) or len(members) < 2:
                raise InputError(f"{label}: \"bodies\" must list at least 2 body names")
            for member in members:
                if not isinstance(member, str) or member not in index_of:
                    raise InputError(f"{label} names unknown body {_shown(member)}")
            if len(set(members)) != len(members):
                raise InputError(f"{label} lists a body twice")
            position = item.get("position")
            position = None if position is None else _vector(position, f"{label}: \"position\"")
            axis = item.get("axis")
            if axis is not None:
                axis = _vector(axis, f"{label}: \"axis\"")
                if not np.linalg.norm(axis) > 0:
                    raise InputError(f"{label}: \"axis\" has zero length")
            stiffness = item.get("stiffness")
            if stiffness is None:
                raise InputError(f"{label} needs a \"stiffness\" (a number, a list, "
                                      "or \"auto\")")
            damping = _number(item.get("damping", 0.0), f"{label}: \"damping\"", minimum=0.0)
            pairs = list(itertools.combinations([index_of[m] for m in members], 2))
            for i, l in pairs:
                pair_name = joint_name if len(pairs) == 1 else \
                    f"{joint_name}[{names[i]},{names[l]}]"
                where = position if position is not None else \
                    meeting_point(bodies[i], bodies[l])
                joint = Joint(pair_name, kind, (i, l), where,
                              np.zeros(len(_free_rows(kind))), axis, damping)
                if stiffness == "auto":
                    automatic.append(len(joints))
                else:
                    joint.stiffness = _stiffness(stiffness, joint, label)
                joints.append(joint)
        set_automatic_stiffness(bodies, joints, automatic)
        return cls(bodies, joints, name=name)

    def to_dict(self) -> dict:
        """The skeleton JSON document (pairwise joints, explicit positions)."""
        return {
            "format": "eigendance.skeleton", "version": 1,
            "bodies": [{"name": b.name, "start": b.start.tolist(), "end": b.end.tolist(),
                        "radius": b.radius, "density": b.density} for b in self.bodies],
            "joints": [{"name": j.name, "type": j.type,
                        "bodies": [self.bodies[j.bodies[0]].name, self.bodies[j.bodies[1]].name],
                        "position": j.position.tolist(),
                        **({"axis": j.axis.tolist()} if j.axis is not None else {}),
                        "stiffness": j.stiffness.tolist(), "damping": j.damping}
                       for j in self.joints],
        }

    def scaled(self, stiffness: float = 1.0, density: float = 1.0) -> Skeleton:
        """A copy with every stiffness and density multiplied by the given factors."""
        bodies = [Body(b.name, b.start, b.end, b.radius, b.density * density)
                  for b in self.bodies]
        joints = [Joint(j.name, j.type, j.bodies, j.position, j.stiffness * stiffness, j.axis,
                        j.damping) for j in self.joints]
        return Skeleton(bodies, joints, self.name, self.vertices, self.faces, self.weights,
                        list(self.notes), self.bind_vertices, self.pose, self.appearance)


def is_skeleton_json(path: str | os.PathLike) -> bool:
    """Whether a file is a skeleton JSON (its "format" says so); False for anything else."""
    try:
        with open(path, encoding="utf-8") as file:
            document = json.load(file)
    except (OSError, ValueError, RecursionError):
        return False
    return isinstance(document, dict) and document.get("format") == "eigendance.skeleton"


def read_joint_stiffness(path: str | os.PathLike) -> dict:
    """A joint stiffness file: a JSON object {joint name: number | [one per free row] |
    "auto"} (`Skeleton.with_stiffness` checks the values against the rig's joints)."""
    name = os.path.basename(os.fspath(path))
    values = read_json(path, name)
    if not isinstance(values, dict):
        raise InputError(f"{name}: expected a JSON object {{joint name: stiffness}}")
    return values


def check_bodies(bodies: list[Body], name: str) -> None:
    """InputError, naming the first body beyond them, unless the bodies keep to the ranges the
    modal analysis handles: coordinates, SIZE_RANGE, ASPECT_RANGE, PHYSICAL_RANGE for masses
    and moments, MAX_LENGTH_RATIO and MAX_DENSITY_RATIO (in that order: each check keeps the
    numbers of the next one finite)."""
    ends = np.array([end for body in bodies for end in (body.start, body.end)], dtype=float)
    if not (np.all(np.isfinite(ends)) and np.abs(ends).max() <= MAX_COORDINATE):
        raise InputError(f"{name}: coordinates must lie within ±{MAX_COORDINATE:.0e}")
    size = float(np.linalg.norm(ends.max(axis=0) - ends.min(axis=0)))
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


def meeting_point(a: Body, b: Body) -> np.ndarray:
    """Where two bodies meet: a shared end if they have one, else the midpoint of the closest
    points of their axes (thesis §3.2.1: the joint sits where the axes intersect)."""
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
    """World-from-joint rotation (columns x, y, z) of a joint (docs/design.md#joints)."""
    d_i = bodies[joint.bodies[0]].direction
    d_l = bodies[joint.bodies[1]].direction
    if joint.axis is not None:
        z = unit(joint.axis, f"axis of joint {joint.name!r}")
    else:
        normal = cross(d_i, d_l)
        z = normal / np.linalg.norm(normal) if np.linalg.norm(normal) > 1e-9 \
            else perpendicular(d_i)
    return frame_from_xz(d_i, z)


def body_inertias(bodies: list[Body]) -> tuple:
    """World inertia tensors about the centres (n, 3, 3), masses (n,), centres (n, 3) and the
    skeleton's extent (the diagonal of the bounding box of the body ends)."""
    rotations = np.array([body.rotation for body in bodies])
    moments = np.array([body.inertia for body in bodies])
    tensors = np.einsum("bij,bj,bkj->bik", rotations, moments, rotations)  # R diag(J) Rᵀ
    ends = np.array([[body.start, body.end] for body in bodies]).reshape(-1, 3)
    return (tensors, np.array([body.mass for body in bodies]),
            np.array([body.center for body in bodies]),
            float(np.linalg.norm(ends.max(axis=0) - ends.min(axis=0))))


def inertia_about(inertias, members, point) -> tuple[np.ndarray, float]:
    """World inertia tensor (3, 3) about `point` and total mass of the bodies `members`:
    Σ_b R_b diag(J_b) R_bᵀ + m_b (|d_b|² I − d_b d_bᵀ), d_b = c_b − point (parallel axes).
    `inertias` = `body_inertias(bodies)`."""
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
    """Give the joints at `indices` (default all) their `automatic_stiffness`, in place."""
    pairs = np.array([joint.bodies for joint in joints], dtype=np.int64).reshape(-1, 2)
    inertias = body_inertias(bodies)
    for index in range(len(joints)) if indices is None else indices:
        joints[index].stiffness = automatic_stiffness(
            joints[index], bodies, frequency, _sides(len(bodies), pairs, index), inertias)


def _sides(n_bodies: int, pairs: np.ndarray, index: int):
    """Bodies reachable from each body of joint `index` without it, or None (a loop)."""
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


def _free_rows(kind: str) -> tuple[int, ...]:
    return tuple(row for row in range(6) if row not in CONSTRAINED_ROWS[kind])


def _stiffness(value, joint: Joint, label: str) -> np.ndarray:
    """A stiffness given as a number or a list (one per free row), checked."""
    free = len(joint.free_rows)
    if isinstance(value, bool):
        raise InputError(f"{label}: \"stiffness\" must be a number, a list or \"auto\"")
    if isinstance(value, (int, float)):
        values = [value] * free
    elif isinstance(value, list) and len(value) == free:
        values = value
    else:
        raise InputError(f"{label}: \"stiffness\" must be a number, a list of {free} "
                              f"numbers (one per free row of a {joint.type} joint) or \"auto\"")
    return np.array([_number(v, f"{label}: \"stiffness\"", minimum=0.0) for v in values])


def _number(value, label: str, positive: bool = False, minimum: float | None = None) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise InputError(f"{label} must be a number, not {_shown(value)}")
    if not finite_number(value):
        raise InputError(f"{label} is not finite ({_shown(value)})")
    if positive and not value > 0:
        raise InputError(f"{label} must be positive, not {_shown(value)}")
    if minimum is not None and value < minimum:
        raise InputError(f"{label} must be at least {minimum}, not {_shown(value)}")
    return float(value)


def _shown(value) -> str:
    """A JSON value in a message: short, whatever it is."""
    try:
        text = repr(value) if isinstance(value, str) else json.dumps(value)
    except (TypeError, ValueError, RecursionError):
        text = type(value).__name__
    return text if len(text) <= 40 else text[:39] + "…"


def _vector(value, label: str) -> np.ndarray:
    if not isinstance(value, list) or len(value) != 3:
        raise InputError(f"{label} must be a list of 3 numbers, not {_shown(value)}")
    vector = np.array([_number(v, label) for v in value])
    if np.abs(vector).max() > MAX_COORDINATE:
        raise InputError(f"{label} must lie within ±{MAX_COORDINATE:.0e}")
    return vector
