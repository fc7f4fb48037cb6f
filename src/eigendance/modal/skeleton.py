"""Articulated skeletons: rigid cylindrical bodies joined by elastic joints
(docs/design.md#skeleton).

A `Skeleton` holds bodies (solid cylinders from `start` to `end`, radius r, density ρ; their
frames and ranges: `modal.bodies`) and joints between pairs of bodies, and optionally the skin
they move. Sources: the skeleton JSON (`Skeleton.from_json`, `modal.skeleton_file`) and glTF
2.0 skins (`eigendance.modal.gltf_skin.skeleton_from_gltf`); the default stiffness of a joint
is `modal.stiffness`'s rule.

Editing (copies, the original is kept): `with_stiffness` sets joints' stiffness by name,
`rotate_joint` changes the rest pose by turning one side of a joint about it (thesis §4.5.6).
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass, field

import numpy as np

from eigendance.errors import InputError
from eigendance.files import read_json
from eigendance.geometry import bounding_box_diagonal
from eigendance.modal.bodies import CONSTRAINED_ROWS, Body, Joint, check_skeleton, joint_frame
from eigendance.modal.rotations import rotation_exp
from eigendance.modal.skeleton_file import skeleton_document, skeleton_parts, stiffness_values
from eigendance.modal.stiffness import (
    DEFAULT_JOINT_FREQUENCY,
    automatic_stiffness,
    body_inertias,
    joint_sides,
    set_automatic_stiffness,
)

# Body, Joint and the stiffness rule live in modal.bodies and modal.stiffness; they are named here
# too for the readers that import them with the skeleton (`modal.gltf_skin`, branches in flight).
__all__ = ["CONSTRAINED_ROWS", "DEFAULT_JOINT_FREQUENCY", "Body", "Joint", "Skeleton",
           "set_automatic_stiffness"]


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
        check_skeleton(self.bodies, self.joints, self.name)

    # ----------------------------------------------------------------- derived arrays
    @property
    def n_bodies(self) -> int:
        """Bodies."""
        return len(self.bodies)

    @property
    def body_names(self) -> list[str]:
        """The bodies' names, in order."""
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
        """World-from-joint rotation (columns x, y, z) (docs/design.md#joints).

        Parameters
        ----------
        joint : one of its joints.

        Returns
        -------
        (3, 3).
        """
        return joint_frame(joint, self.bodies)

    @property
    def joint_pairs(self) -> np.ndarray:
        """(n_joints, 2) int64: the two bodies (i, l) of every joint."""
        return np.array([joint.bodies for joint in self.joints], dtype=np.int64).reshape(-1, 2)

    def joint_index(self, key) -> int:
        """The index of a joint given by name or by index; InputError naming the joint.

        Parameters
        ----------
        key : a joint's name or index.

        Returns
        -------
        int.
        """
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
        a loop (its two bodies stay connected without it).

        Parameters
        ----------
        index : the joint.

        Returns
        -------
        (side of body i, side of body l) int arrays, or None.
        """
        return joint_sides(self.n_bodies, self.joint_pairs, index)

    def automatic_stiffness(self, index: int,
                            frequency: float = DEFAULT_JOINT_FREQUENCY) -> np.ndarray:
        """The default stiffness of joint `index` ("auto"; `automatic_stiffness`).

        Parameters
        ----------
        index : the joint.
        frequency : Hz of a side a quarter of the rig's size long.

        Returns
        -------
        (free rows,).
        """
        return automatic_stiffness(self.joints[index], self.bodies, frequency,
                                   self.joint_sides(index))

    def automatic_stiffnesses(self, frequency: float = DEFAULT_JOINT_FREQUENCY) -> list:
        """The default stiffness of every joint (the bodies' inertias computed once).

        Parameters
        ----------
        frequency : Hz of a side a quarter of the rig's size long.

        Returns
        -------
        list of (free rows,) arrays, one per joint.
        """
        inertias, pairs = body_inertias(self.bodies), self.joint_pairs
        return [automatic_stiffness(joint, self.bodies, frequency,
                                    joint_sides(self.n_bodies, pairs, index), inertias)
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

        Returns
        -------
        Skeleton, a copy; InputError naming a joint or value at fault.

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
                stiffness_values(value, joint, label)
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

        Returns
        -------
        Skeleton, a copy.

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
            step = np.eye(4)
            step[:3, :3], step[:3, 3] = turn, pivot - turn @ pivot
            edited._pose_skin(moving, step)
        return edited

    def _pose_skin(self, moving: np.ndarray, step: np.ndarray) -> None:
        """Compose the rigid `step` (4, 4) into the pose of the `moving` bodies and skin the
        mesh as loaded by linear blend skinning, x = Σ_b w_b pose_b x_bind (in place)."""
        if self.bind_vertices is None:
            self.bind_vertices = self.vertices
            self.pose = np.tile(np.eye(4), (self.n_bodies, 1, 1))
        self.pose[moving] = step @ self.pose[moving]
        blended = (self.weights @ self.pose[:, :3].reshape(self.n_bodies, 12)).reshape(-1, 3, 4)
        self.vertices = np.einsum("nij,nj->ni", blended[:, :, :3], self.bind_vertices) \
            + blended[:, :, 3]

    def copy(self) -> Skeleton:
        """A deep copy (bodies, joints and skin arrays).

        Returns
        -------
        Skeleton.
        """
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
        return bounding_box_diagonal(ends)

    # ----------------------------------------------------------------- loading
    @classmethod
    def from_json(cls, path: str | os.PathLike, name: str | None = None) -> Skeleton:
        """Read a skeleton JSON file (docs/design.md#skeleton-file), checked like `from_dict`;
        messages call it `name` (default: the file's name).

        Parameters
        ----------
        path : the skeleton JSON file.
        name : how messages call it.

        Returns
        -------
        Skeleton.
        """
        name = name or os.path.basename(os.fspath(path))
        return cls.from_dict(read_json(path, name), name=name)

    @classmethod
    def from_dict(cls, document, name: str = "skeleton") -> Skeleton:
        """Build from a parsed skeleton JSON (docs/design.md#skeleton-file), checking each item.

        Parameters
        ----------
        document : the parsed JSON document.
        name : how messages call it (a file name).

        Returns
        -------
        Skeleton without a skin; InputError naming the first item at fault.
        """
        bodies, joints = skeleton_parts(document, name)
        return cls(bodies, joints, name=name)

    def to_dict(self) -> dict:
        """The skeleton JSON document (pairwise joints, explicit positions).

        Returns
        -------
        dict (docs/design.md#skeleton-file), ready for json.dump.
        """
        return skeleton_document(self.bodies, self.joints)

    def scaled(self, stiffness: float = 1.0, density: float = 1.0) -> Skeleton:
        """A copy with every stiffness and density multiplied by the given factors.

        Parameters
        ----------
        stiffness : multiplies every joint stiffness.
        density : multiplies every body's density.

        Returns
        -------
        Skeleton, a copy.
        """
        bodies = [Body(b.name, b.start, b.end, b.radius, b.density * density)
                  for b in self.bodies]
        joints = [Joint(j.name, j.type, j.bodies, j.position, j.stiffness * stiffness, j.axis,
                        j.damping) for j in self.joints]
        return Skeleton(bodies, joints, self.name, self.vertices, self.faces, self.weights,
                        list(self.notes), self.bind_vertices, self.pose, self.appearance)

