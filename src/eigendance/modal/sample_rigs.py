"""Rigs by name or file: built-in rigs, skeleton JSON and glTF skins (docs/design.md#skeleton).

The built-in rigs are the thesis's planar loops ("laços", Fig. 4.10: symmetric loops of 4 and
16 bodies, the non-symmetric loop of 8), a small chain, all made by code with a tube skin mesh
(rings of vertices around each body, weights blending into the neighbouring body near each
joint), and a hand (the WebXR generic left hand, a glTF skin in the package's data folder,
MIT licence).
"""

from __future__ import annotations

import math
import os
from importlib import resources

import numpy as np

from eigendance.errors import InputError
from eigendance.files import check_readable, suffix_of
from eigendance.modal.bodies import Body, Joint
from eigendance.modal.gltf_skin import skeleton_from_gltf
from eigendance.modal.skeleton import Skeleton
from eigendance.modal.stiffness import set_automatic_stiffness

SAMPLE_RIGS = ("loop4", "loop8", "loop16", "chain", "hand")
HAND_FILE = "generic-hand_left.glb"  # in the package's data folder


def loop_points(n_bodies: int, symmetric: bool = True) -> np.ndarray:
    """Corners of a planar loop in the xy-plane: a regular polygon of radius 1, or (not
    symmetric) corners on an ellipse at uneven angles.

    Parameters
    ----------
    n_bodies : corners.
    symmetric : a regular polygon, or the uneven ellipse.

    Returns
    -------
    (n_bodies, 3).
    """
    angles = 2 * math.pi * np.arange(n_bodies) / n_bodies
    if symmetric:
        return np.column_stack([np.cos(angles), np.sin(angles), np.zeros(n_bodies)])
    angles = angles + 0.35 * np.sin(3 * angles) / n_bodies * 4
    return np.column_stack([1.4 * np.cos(angles), 0.8 * np.sin(angles), np.zeros(n_bodies)])


def planar_loop(n_bodies: int, symmetric: bool = True, radius: float = 0.05,
                density: float = 1000.0, stiffness: float | None = None,
                skin: bool = True) -> Skeleton:
    """A closed loop of n_bodies bodies joined by revolute joints (axes normal to the plane).

    Parameters
    ----------
    n_bodies : bodies (and joints).
    symmetric : regular, or the thesis's non-symmetric shape.
    radius, density : of every body.
    stiffness : of every joint (None: the default rule).
    skin : give it a tube skin.

    Returns
    -------
    Skeleton.
    """
    if n_bodies < 3:
        raise InputError("a loop needs at least 3 bodies")
    corners = loop_points(n_bodies, symmetric)
    bodies = [Body(f"b{index}", corners[index], corners[(index + 1) % n_bodies], radius, density)
              for index in range(n_bodies)]
    joints = []
    for index in range(n_bodies):
        i, l = index, (index + 1) % n_bodies
        joints.append(Joint(f"j{index}", "revolute", (i, l), corners[l].copy(),
                            np.array([float(stiffness or 0.0)])))
    if stiffness is None:
        set_automatic_stiffness(bodies, joints)
    name = f"loop{n_bodies}" + ("" if symmetric else "-asymmetric")
    skeleton = Skeleton(bodies, joints, name=name)
    if skin:
        add_tube_skin(skeleton)
    return skeleton


def open_chain(n_bodies: int = 3, joint_type: str = "spherical", radius: float = 0.05,
               density: float = 1000.0, stiffness: float | None = None,
               skin: bool = True) -> Skeleton:
    """A free zig-zag chain of bodies in 3D joined end to end (a small open tree).

    Parameters
    ----------
    n_bodies : bodies.
    joint_type : of every joint.
    radius, density : of every body.
    stiffness : of every joint (None: the default rule).
    skin : give it a tube skin.

    Returns
    -------
    Skeleton.
    """
    points = [np.zeros(3)]
    for index in range(n_bodies):
        turn = 0.6 * index
        points.append(points[-1] + np.array([math.cos(turn), math.sin(turn), 0.3 * (index % 2)]))
    bodies = [Body(f"b{index}", points[index], points[index + 1], radius, density)
              for index in range(n_bodies)]
    joints = []
    for index in range(n_bodies - 1):
        joint = Joint(f"j{index}", joint_type, (index, index + 1), points[index + 1].copy(),
                      np.zeros(0))
        joint.stiffness = np.full(len(joint.free_rows), float(stiffness or 0.0))
        joints.append(joint)
    if stiffness is None:
        set_automatic_stiffness(bodies, joints)
    skeleton = Skeleton(bodies, joints, name=f"chain{n_bodies}")
    if skin:
        add_tube_skin(skeleton)
    return skeleton


def sample_rig(name: str) -> Skeleton:
    """One of SAMPLE_RIGS by name (the 8-body loop is the thesis's non-symmetric one).

    Parameters
    ----------
    name : loop4, loop8, loop16, chain or hand.

    Returns
    -------
    Skeleton with a skin.
    """
    if name == "loop4":
        return planar_loop(4)
    if name == "loop8":
        return planar_loop(8, symmetric=False)
    if name == "loop16":
        return planar_loop(16)
    if name == "chain":
        return open_chain(3)
    if name == "hand":
        with resources.as_file(resources.files("eigendance") / "data" / HAND_FILE) as path:
            return skeleton_from_gltf(path, name="hand")
    raise InputError(f"unknown sample rig {name!r} (use {', '.join(SAMPLE_RIGS)})")


def add_tube_skin(skeleton: Skeleton, rings: int = 8, around: int = 12,
                  blend: float = 0.25) -> None:
    """Give `skeleton` a tube mesh: `rings` rings of `around` vertices along each body, at 1.2
    times its radius, weighted to the body and, within `blend` of an end, half-way into the
    body that shares that joint.

    Parameters
    ----------
    skeleton : the skeleton (its vertices, faces and weights are set).
    rings : rings per body.
    around : vertices per ring.
    blend : the share of a body, at each end, blended with its neighbour.
    """
    vertices, faces, weights = [], [], []
    n_bodies = skeleton.n_bodies
    neighbours = {(b, end): None for b in range(n_bodies) for end in (0, 1)}
    for joint in skeleton.joints:
        i, l = joint.bodies
        for body, other in ((i, l), (l, i)):
            ends = (skeleton.bodies[body].start, skeleton.bodies[body].end)
            end = int(np.linalg.norm(ends[1] - joint.position)
                      < np.linalg.norm(ends[0] - joint.position))
            if neighbours[(body, end)] is None:
                neighbours[(body, end)] = other
    circle = 2 * math.pi * np.arange(around) / around
    for index, body in enumerate(skeleton.bodies):
        rotation = skeleton.rotations[index]
        offsets = 1.2 * body.radius * (np.outer(np.cos(circle), rotation[:, 1])
                                       + np.outer(np.sin(circle), rotation[:, 2]))
        base = sum(len(v) for v in vertices)
        for ring, s in enumerate(np.linspace(0.02, 0.98, rings)):
            vertices.append(body.start + s * (body.end - body.start) + offsets)
            row = np.zeros((around, n_bodies))
            start_share = 0.5 * max(0.0, (blend - s) / blend)
            end_share = 0.5 * max(0.0, (s - 1 + blend) / blend)
            row[:, index] = 1.0
            for share, end in ((start_share, 0), (end_share, 1)):
                other = neighbours[(index, end)]
                if other is not None and share > 0:
                    row[:, index] -= share
                    row[:, other] += share
            weights.append(row)
            if ring:
                a = base + (ring - 1) * around + np.arange(around)
                b = base + (ring - 1) * around + (np.arange(around) + 1) % around
                faces.append(np.column_stack([a, b, b + around]))
                faces.append(np.column_stack([a, b + around, a + around]))
    skeleton.vertices = np.concatenate(vertices)
    skeleton.faces = np.concatenate(faces).astype(np.int64)
    skeleton.weights = np.concatenate(weights)


def load_rig(rig: str | os.PathLike, name: str | None = None, document=None) -> Skeleton:
    """A rig with its skin, from a file or by name.

    Parameters
    ----------
    rig : a skeleton JSON (.json), a glTF 2.0 skin (.glb, .gltf), or the name of a built-in
        rig (SAMPLE_RIGS), unless a file of that name exists.
    name : what messages and the skeleton call a file (default: the file's name).
    document : a skeleton JSON's document, already parsed (`inputs.model.classify`).

    Returns
    -------
    Skeleton with vertices, faces and weights (a skeleton without a mesh gets a tube skin).

    Example
    -------
    >>> loop = load_rig("loop4")
    >>> loop.n_bodies, len(loop.joints), loop.weights.shape[1]
    (4, 4, 4)
    """
    rig = os.fspath(rig)
    if rig in SAMPLE_RIGS and not os.path.exists(rig):
        return sample_rig(rig)
    suffix = suffix_of(rig)
    if suffix not in (".json", ".glb", ".gltf"):
        raise InputError(f"{rig}: unknown rig format {suffix!r} (use .json, .glb or .gltf, or "
                         f"a built-in rig: {', '.join(SAMPLE_RIGS)})")
    check_readable(rig)
    if suffix in (".glb", ".gltf"):
        skeleton = skeleton_from_gltf(rig, name=name)
    elif document is not None:
        skeleton = Skeleton.from_dict(document, name or os.path.basename(rig))
    else:
        skeleton = Skeleton.from_json(rig, name)
    if skeleton.vertices is None:
        add_tube_skin(skeleton)
    return skeleton
