"""The skeleton JSON file and the joint stiffness file (docs/design.md#skeleton-file).

`skeleton_parts` reads a parsed skeleton document into bodies and pairwise joints, checking each
item and naming it in its message; `skeleton_document` writes one. In the JSON, a joint's
"stiffness" is a number (every free row), a list (one per free row of [ωx ωy ωz vx vy vz], in
that order), or "auto" (`modal.stiffness.automatic_stiffness`); "position" defaults to where
the two bodies meet (a shared end, else the closest points of their axes); "density" defaults
to DEFAULT_DENSITY; "damping" is kept but the modes are undamped. A joint declared with three or
more bodies becomes one joint per pair of them (thesis §5.2).
"""

from __future__ import annotations

import itertools
import os

import numpy as np

from eigendance.checks import number, shown, vector
from eigendance.errors import InputError
from eigendance.files import read_json
from eigendance.geometry import MAX_COORDINATE
from eigendance.modal.bodies import (
    CONSTRAINED_ROWS,
    DEFAULT_DENSITY,
    JOINT_TYPES,
    Body,
    Joint,
    check_bodies,
    check_rig_size,
    meeting_point,
)
from eigendance.modal.stiffness import set_automatic_stiffness

FORMAT = "eigendance.skeleton"


def skeleton_parts(document, name: str = "skeleton") -> tuple[list[Body], list[Joint]]:
    """The bodies and pairwise joints of a parsed skeleton document, every item checked.

    Parameters
    ----------
    document : the parsed JSON (docs/design.md#skeleton-file).
    name : how messages call it (a file name).

    Returns
    -------
    (bodies, joints): joints given "auto" stiffness have their default stiffness
    (`set_automatic_stiffness`), computed once every body is known good.
    """
    if not isinstance(document, dict) or document.get("format") != FORMAT:
        raise InputError(f"{name}: not an eigendance skeleton (expected \"format\": \"{FORMAT}\")")
    if document.get("version") != 1:
        raise InputError(f"{name}: unsupported skeleton version "
                         f"{shown(document.get('version'))} (expected 1)")
    raw_bodies = document.get("bodies")
    raw_joints = document.get("joints", [])
    if not isinstance(raw_bodies, list) or not raw_bodies:
        raise InputError(f"{name}: \"bodies\" must be a non-empty list")
    if not isinstance(raw_joints, list):
        raise InputError(f"{name}: \"joints\" must be a list")
    check_rig_size(len(raw_bodies), len(raw_joints), name)
    bodies = [_body(item, index, name) for index, item in enumerate(raw_bodies)]
    check_bodies(bodies, name)  # before "auto" stiffness computes with their masses
    joints, automatic, joint_names = [], [], set()
    for index, item in enumerate(raw_joints):
        for joint, auto in _joints(item, index, bodies, joint_names, name):
            if auto:
                automatic.append(len(joints))
            joints.append(joint)
    set_automatic_stiffness(bodies, joints, automatic)
    return bodies, joints


def _body(item, index: int, name: str) -> Body:
    """Body `index` of the document, checked."""
    label = f"{name}: body {index}"
    if not isinstance(item, dict):
        raise InputError(f"{label} is not an object")
    body_name = item.get("name")
    if not isinstance(body_name, str) or not body_name:
        raise InputError(f"{label} needs a \"name\" string")
    label = f"{name}: body {body_name!r}"
    start = _vector(item.get("start"), f"{label}: \"start\"")
    end = _vector(item.get("end"), f"{label}: \"end\"")
    radius = number(item.get("radius"), f"{label}: \"radius\"", 0, above=True)
    density = number(item.get("density", DEFAULT_DENSITY), f"{label}: \"density\"", 0,
                     above=True)
    if not np.linalg.norm(end - start) > 0:
        raise InputError(f"{label} has zero length (start = end)")
    return Body(body_name, start, end, radius, density)


def _joints(item, index: int, bodies: list[Body], joint_names: set, name: str):
    """The pairwise joints of joint item `index`, each with whether its stiffness is "auto";
    `joint_names` collects the names seen (a name twice is an error)."""
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
        raise InputError(f"{label} has unknown type {shown(kind)} (use {', '.join(JOINT_TYPES)})")
    members = _members(item.get("bodies"), bodies, label)
    position = item.get("position")
    position = None if position is None else _vector(position, f"{label}: \"position\"")
    axis = item.get("axis")
    if axis is not None:
        axis = _vector(axis, f"{label}: \"axis\"")
        if not np.linalg.norm(axis) > 0:
            raise InputError(f"{label}: \"axis\" has zero length")
    stiffness = item.get("stiffness")
    if stiffness is None:
        raise InputError(f"{label} needs a \"stiffness\" (a number, a list, or \"auto\")")
    damping = number(item.get("damping", 0.0), f"{label}: \"damping\"", 0.0)
    pairs = list(itertools.combinations(members, 2))
    for i, l in pairs:
        pair_name = joint_name if len(pairs) == 1 else \
            f"{joint_name}[{bodies[i].name},{bodies[l].name}]"
        where = position if position is not None else meeting_point(bodies[i], bodies[l])
        joint = Joint(pair_name, kind, (i, l), where, np.zeros(len(free_rows(kind))), axis,
                      damping)
        if stiffness != "auto":
            joint.stiffness = stiffness_values(stiffness, joint, label)
        yield joint, stiffness == "auto"


def _members(members, bodies: list[Body], label: str) -> list[int]:
    """The body indices a joint item lists, checked: at least two known names, none twice."""
    index_of = {body.name: i for i, body in enumerate(bodies)}
    if not isinstance(members, list) or len(members) < 2:
        raise InputError(f"{label}: \"bodies\" must list at least 2 body names")
    for member in members:
        if not isinstance(member, str) or member not in index_of:
            raise InputError(f"{label} names unknown body {shown(member)}")
    if len(set(members)) != len(members):
        raise InputError(f"{label} lists a body twice")
    return [index_of[member] for member in members]


def skeleton_document(bodies: list[Body], joints: list[Joint]) -> dict:
    """The skeleton JSON document of bodies and pairwise joints (explicit positions).

    Parameters
    ----------
    bodies : the bodies.
    joints : the pairwise joints (bodies by index).

    Returns
    -------
    dict, ready for json.dump (docs/design.md#skeleton-file).
    """
    return {
        "format": FORMAT, "version": 1,
        "bodies": [{"name": b.name, "start": b.start.tolist(), "end": b.end.tolist(),
                    "radius": b.radius, "density": b.density} for b in bodies],
        "joints": [{"name": j.name, "type": j.type,
                    "bodies": [bodies[j.bodies[0]].name, bodies[j.bodies[1]].name],
                    "position": j.position.tolist(),
                    **({"axis": j.axis.tolist()} if j.axis is not None else {}),
                    "stiffness": j.stiffness.tolist(), "damping": j.damping}
                   for j in joints],
    }


def read_joint_stiffness(path: str | os.PathLike) -> dict:
    """A joint stiffness file (`--joints`, the server's stiffness edits).

    Parameters
    ----------
    path : a JSON object {joint name: number | [one per free row] | "auto"}.

    Returns
    -------
    dict as read (`Skeleton.with_stiffness` checks the values against the rig's joints).
    """
    name = os.path.basename(os.fspath(path))
    values = read_json(path, name)
    if not isinstance(values, dict):
        raise InputError(f"{name}: expected a JSON object {{joint name: stiffness}}")
    return values


def free_rows(kind: str) -> tuple[int, ...]:
    """The free rows of [ωx ωy ωz vx vy vz] of a joint type (those it does not constrain).

    Parameters
    ----------
    kind : a joint type (`JOINT_TYPES`).

    Returns
    -------
    tuple of row indices, ascending.
    """
    return tuple(row for row in range(6) if row not in CONSTRAINED_ROWS[kind])


def stiffness_values(value, joint: Joint, label: str) -> np.ndarray:
    """A stiffness given as a number (every free row) or a list (one per free row), checked.

    Parameters
    ----------
    value : the number or list as given.
    joint : the joint it is for (its type says how many free rows).
    label : how messages name the joint.

    Returns
    -------
    (free rows,) float64, each ≥ 0.
    """
    free = len(joint.free_rows)
    if isinstance(value, bool):
        raise InputError(f"{label}: \"stiffness\" must be a number, a list or \"auto\"")
    if isinstance(value, int | float):
        values = [value] * free
    elif isinstance(value, list) and len(value) == free:
        values = value
    else:
        raise InputError(f"{label}: \"stiffness\" must be a number, a list of {free} "
                         f"numbers (one per free row of a {joint.type} joint) or \"auto\"")
    return np.array([number(v, f"{label}: \"stiffness\"", 0.0) for v in values])


def _vector(value, label: str) -> np.ndarray:
    return vector(value, label, 3, MAX_COORDINATE)
