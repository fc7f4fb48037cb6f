"""glTF 2.0 skins as skeletons: joint hierarchy, rest pose, skinned mesh (docs/design.md#skeleton).

`assets.read_model` reads the file (every mesh node, skins, meshes attached to bones, materials);
this module keeps the joints that move something (`moving_joints`) and turns them into bodies
and elastic joints (`skeleton_from_gltf`).
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field

import numpy as np

from eigendance.assets.appearance import WELD_TOLERANCE
from eigendance.assets.model import Model
from eigendance.assets.reader import read_model
from eigendance.errors import InputError
from eigendance.geometry import bounding_box_diagonal, weld
from eigendance.modal.bodies import Body, Joint, check_rig_size
from eigendance.modal.skeleton import Skeleton
from eigendance.modal.stiffness import DEFAULT_JOINT_FREQUENCY, set_automatic_stiffness

# A joint carries the skin when some vertex gives it at least this weight (or a mesh hangs
# from it); joints that carry nothing and connect nothing that does are left out.
CARRY_WEIGHT = 1e-6


@dataclass
class SkinnedRig:
    """A skin over the joints that move something, welded.

    Parameters
    ----------
    names : (n_j,) joint names.
    parents : (n_j,) index of the parent joint, or -1.
    joint_matrices : (n_j, 4, 4) world matrices in the rest pose.
    vertices : (n, 3) rest-pose skin.
    faces : (m, 3).
    weights : (n, n_j) (rows may not sum to 1 yet).
    notes : what was changed on the way, in words.
    """

    names: list[str]
    parents: np.ndarray
    joint_matrices: np.ndarray
    vertices: np.ndarray
    faces: np.ndarray
    weights: np.ndarray
    notes: list[str] = field(default_factory=list)


def skeleton_from_gltf(path: str | os.PathLike,
                       stiffness_frequency: float = DEFAULT_JOINT_FREQUENCY,
                       name: str | None = None) -> Skeleton:
    """Read the skins of a glTF 2.0 file (.glb, .gltf) as a skeleton with a skinned mesh; messages
    call it `name` (default: the file's name).

    - Rest pose: the file's node pose. Joint j sits at the origin of its world matrix W_j;
      skinned vertices are placed at Σ_j w_j W_j·IBM_j·x (the bind pose, x itself when the
      inverse bind matrices match the nodes, as they do in exported rigs).
    - Skin: every mesh node of the scene (`assets.read_model`): skinned meshes (several skins
      sharing one skeleton are merged by joint node) with their JOINTS_n/WEIGHTS_n, and meshes
      attached to a bone (a mesh node below a joint node: a hat, a gun) with weight 1 on that
      joint; weights renormalised to sum 1 (vertices with no weight go to the nearest body);
      drawn vertices within WELD_TOLERANCE of the diagonal welded (`Skeleton.appearance` maps
      them back, with the file's materials).
    - Joints that move nothing are left out (`moving_joints`): IK and pole targets, roots above
      the skeleton.
    - Bodies: one per joint kept, from the node to its child joint (the child with the most
      descendant joints, then the farthest), or, for a leaf, toward the middle of the vertices
      it carries, else along the node's own +y axis (the bone axis of Blender and most
      exporters). Radius: the median distance from the axis of the vertices the body
      dominates, clamped to [0.02, 1]·length. Density DEFAULT_DENSITY (the size unit is taken
      to be metres; frequencies do not depend on it with the default stiffness).
    - Joints: one spherical joint (free ω, natural for characters) between each joint kept and
      its nearest kept ancestor, at the child's position; stiffness per rotation row from
      `skeleton.automatic_stiffness`: each of the two parts a joint joins swings about it like a
      pendulum of its own length under one gravity, at `stiffness_frequency` Hz (1 Hz) when its
      centre lies a quarter of the rig's size from the joint. Other choices:
      `Skeleton.with_stiffness`, or change `joints` (type, stiffness) of the returned skeleton in
      code; the skin stays valid.

    Parameters
    ----------
    path : the file.
    stiffness_frequency : f of the joints' default stiffness, Hz.
    name : what messages call it (None: the file's name).

    Returns
    -------
    Skeleton, with its skin and the file's appearance.

    Raises
    ------
    InputError
        For a file that cannot be read, has no skin, or a rig too large to analyse.
    """
    model = read_model(path, name)
    label = name or os.path.basename(os.fspath(path))
    if model.skin is None:
        raise InputError(f"{label}: the file has no skin (no skeleton to analyse)")
    rig, welded = skinned_rig(model)
    skeleton = _skeleton_from_rig(rig, label, stiffness_frequency)
    skeleton.appearance = model.appearance(welded)
    return skeleton


def skinned_rig(model: Model) -> tuple[SkinnedRig, np.ndarray]:
    """The welded skin of a model with skins, over the joints that move something.

    Parameters
    ----------
    model : a model read with its skin.

    Returns
    -------
    (SkinnedRig, (n_d,) the welded vertex of each drawn vertex).
    """
    skin = model.skin
    weights = model.weights.copy()
    hanging = np.flatnonzero(model.bones >= 0)
    weights[hanging, model.bones[hanging]] = 1.0
    keep = moving_joints(skin.parents, weights.max(axis=0, initial=0) >= CARRY_WEIGHT)
    check_rig_size(int(keep.sum()), max(int(keep.sum()) - 1, 0), model.name)
    notes = []
    if not keep.all():
        notes.append(f"left out {int((~keep).sum())} joints that move no vertex "
                     f"({', '.join(np.array(skin.names)[~keep][:4])}"
                     f"{', …' if (~keep).sum() > 4 else ''})")
    if len(hanging):
        notes.append(f"{len(hanging)} vertices of meshes attached to bones follow their bone")
    column = np.cumsum(keep) - 1
    parents = np.array([_kept_ancestor(skin.parents, j, keep, column)
                        for j in np.flatnonzero(keep)], dtype=np.int64)
    first, welded = weld(model.positions, WELD_TOLERANCE)
    counts = np.bincount(welded, minlength=len(first)).astype(float)
    merged = np.zeros((len(first), int(keep.sum())))
    np.add.at(merged, welded, weights[:, keep])
    faces = welded[model.triangles]
    faces = faces[(faces[:, 0] != faces[:, 1]) & (faces[:, 1] != faces[:, 2])
                  & (faces[:, 0] != faces[:, 2])]
    if len(first) < len(welded):
        notes.append(f"welded {len(welded) - len(first)} seam vertices")
    rig = SkinnedRig([n for n, k in zip(skin.names, keep, strict=True) if k], parents,
                     skin.matrices[keep], model.positions[first], faces,
                     merged / counts[:, None], notes)
    return rig, welded


def moving_joints(parents: np.ndarray, carrying: np.ndarray) -> np.ndarray:
    """Which joints enter the modal model: (n_j,) bool.

    A joint is kept when it carries the skin (a vertex weight or a mesh attached to it), or
    when it connects joints that do: at least two of its directions — each child's subtree,
    and the rest of its tree above it — hold a carrying joint (a hips joint between spine and
    legs, a twist bone inside an arm). Joints that carry nothing and lie beyond every carrying
    joint (IK and pole targets, a root above the skeleton, an empty tree) are left out. When
    no joint carries anything, all are kept.

    Parameters
    ----------
    parents : (n_j,) index of each joint's parent, or -1.
    carrying : (n_j,) bool, the joints that carry the skin.

    Returns
    -------
    (n_j,) bool.

    Example
    -------
    >>> # root → hips → (spine, leg); the leg → pole target; only spine and leg carry vertices
    >>> moving_joints(np.array([-1, 0, 1, 1, 3]), np.array([0, 0, 1, 1, 0], bool)).tolist()
    [False, True, True, True, False]
    """
    carrying = np.asarray(carrying, dtype=bool)
    if not carrying.any():
        return np.ones(len(parents), dtype=bool)
    children = _children(parents)
    below = carrying.astype(int)  # carrying joints in each subtree
    root = np.arange(len(parents))
    for joint in _postorder(children, parents):
        if parents[joint] >= 0:
            below[parents[joint]] += below[joint]
    for joint in _preorder(children, parents):
        if parents[joint] >= 0:
            root[joint] = root[parents[joint]]
    keep = carrying.copy()
    for joint in np.flatnonzero(~carrying):
        directions = sum(below[child] > 0 for child in children[joint])
        directions += below[root[joint]] - below[joint] > 0
        keep[joint] = directions >= 2
    return keep


def _kept_ancestor(parents, joint, keep, column) -> int:
    joint = parents[joint]
    while joint >= 0 and not keep[joint]:
        joint = parents[joint]
    return int(column[joint]) if joint >= 0 else -1


def _children(parents) -> list[list[int]]:
    children = [[] for _ in parents]
    for child, parent in enumerate(parents):
        if parent >= 0:
            children[parent].append(child)
    return children


def _skeleton_from_rig(rig, name: str, stiffness_frequency: float) -> Skeleton:
    """Bodies and spherical joints from a `gltf_skin.SkinnedRig` (see Skeleton.from_gltf)."""
    positions = rig.joint_matrices[:, :3, 3]
    vertices, weights = rig.vertices, rig.weights
    extent = np.concatenate([positions, vertices]) if len(vertices) else positions
    size = bounding_box_diagonal(extent) or 1.0
    children = _children(rig.parents)
    descendants = np.zeros(len(positions), dtype=int)
    for joint in _postorder(children, rig.parents):
        descendants[joint] = sum(1 + descendants[c] for c in children[joint])
    dominant = weights.argmax(axis=1) if len(vertices) else np.zeros(0, dtype=int)
    ends, lengths = _bone_ends(rig, children, descendants, dominant, size)
    bodies = [_body(rig.names[joint], positions[joint], ends[joint], lengths[joint],
                    vertices[dominant == joint]) for joint in range(len(positions))]
    joints = []
    for child, parent in enumerate(rig.parents):
        if parent < 0:
            continue
        joints.append(Joint(f"{rig.names[parent]}-{rig.names[child]}", "spherical",
                            (parent, child), positions[child].copy(), np.zeros(3)))
    attached = _attach_separate_trees(bodies, joints, rig, descendants, weights)
    set_automatic_stiffness(bodies, joints, frequency=stiffness_frequency)
    notes = list(rig.notes)
    if attached:
        notes.append(f"attached {attached} separate joint trees to their nearest body")
    if len(vertices):
        empty = weights.sum(axis=1) <= 0
        if np.any(empty):
            centers = np.array([b.center for b in bodies])
            nearest = np.linalg.norm(vertices[empty, None] - centers[None], axis=2).argmin(1)
            weights[np.flatnonzero(empty), nearest] = 1.0
        weights = weights / weights.sum(axis=1, keepdims=True)
    skeleton = Skeleton(bodies, joints, name=name,
                        vertices=vertices if len(vertices) else None,
                        faces=rig.faces if len(vertices) else None,
                        weights=weights if len(vertices) else None, notes=notes)
    return skeleton


def _bone_ends(rig, children, descendants, dominant, size: float):
    """(ends (n_j, 3), lengths (n_j,)) of the bones: toward the child that leads the most
    joints (the farthest of those), else along what the joint carries or its bone axis."""
    positions = rig.joint_matrices[:, :3, 3]
    tiny = 1e-4 * size
    ends, lengths = np.zeros_like(positions), np.zeros(len(positions))
    for joint in _preorder(children, rig.parents):  # parents first: a leaf falls back on them
        start = positions[joint]
        candidates = [c for c in children[joint]
                      if np.linalg.norm(positions[c] - start) > tiny]
        if candidates:
            child = max(candidates, key=lambda c: (descendants[c],
                                                   np.linalg.norm(positions[c] - start)))
            ends[joint] = positions[child]
            lengths[joint] = np.linalg.norm(positions[child] - start)
            continue
        owned = rig.vertices[dominant == joint] - start
        centroid = owned.mean(axis=0) if len(owned) else np.zeros(3)
        if np.linalg.norm(centroid) > tiny:  # toward the middle of what it carries
            axis = centroid
        else:  # the bone axis of Blender and most exporters
            axis = rig.joint_matrices[joint, :3, 1]
            if not np.linalg.norm(axis) > 0:
                axis = np.array([0.0, 1.0, 0.0])
        axis = axis / np.linalg.norm(axis)
        reach = np.percentile(owned @ axis, 95) if len(owned) else 0.0
        parent = rig.parents[joint]
        fallback = 0.5 * lengths[parent] if parent >= 0 and lengths[parent] > 0 else 0.05 * size
        length = reach if reach > tiny else fallback
        ends[joint] = start + length * axis
        lengths[joint] = length
    return ends, lengths


def _body(name: str, start, end, length: float, owned) -> Body:
    """A bone's body: its radius the median distance of the vertices it carries (`owned`) from
    its axis, 15% of its length when it carries none, within 2–100% of its length."""
    axis = (end - start) / length
    owned = owned - start
    if len(owned):
        along = np.clip(owned @ axis, 0, length)
        radius = float(np.median(np.linalg.norm(owned - along[:, None] * axis, axis=1)))
    else:
        radius = 0.15 * length
    return Body(name, start.copy(), end, float(np.clip(radius, 0.02 * length, length)))


def _attach_separate_trees(bodies, joints, rig, descendants, weights) -> int:
    """Join the roots of separate joint trees (IK targets, flat hierarchies such as the WebXR
    hand) into one tree, Prim-style: repeatedly attach the free root nearest to a body already
    in the tree with a spherical joint at the root's position. Returns how many were attached."""
    roots = [j for j, p in enumerate(rig.parents) if p < 0]
    if len(roots) < 2:
        return 0
    load = weights.sum(axis=0) if len(weights) else np.zeros(len(bodies))
    main = max(roots, key=lambda r: (descendants[r], load[r]))
    children = _children(rig.parents)
    in_tree = set(_preorder(children, [0 if j != main else -1 for j in range(len(bodies))]))
    waiting = [r for r in roots if r != main]
    starts = np.array([b.start for b in bodies])
    ends = np.array([b.end for b in bodies])
    while waiting:
        members = np.array(sorted(in_tree))
        best = None
        for root in waiting:
            distance = _segment_distance(bodies[root].start, starts[members], ends[members])
            nearest = int(np.argmin(distance))
            if best is None or distance[nearest] < best[0]:
                best = (distance[nearest], root, int(members[nearest]))
        _, root, host = best
        joints.append(Joint(f"{bodies[host].name}-{bodies[root].name}", "spherical",
                            (host, root), bodies[root].start.copy(), np.zeros(3)))
        waiting.remove(root)
        in_tree.update(_preorder(children, [0 if j != root else -1
                                            for j in range(len(bodies))]))
    return len(roots) - 1


def _segment_distance(point, starts, ends) -> np.ndarray:
    """Distance from a point to each segment start→end."""
    direction = ends - starts
    along = np.einsum("ij,ij->i", point - starts, direction) / \
        np.maximum(np.einsum("ij,ij->i", direction, direction), 1e-300)
    closest = starts + np.clip(along, 0, 1)[:, None] * direction
    return np.linalg.norm(closest - point, axis=1)


def _preorder(children, parents):
    order, stack = [], [j for j, p in enumerate(parents) if p < 0][::-1]
    while stack:
        joint = stack.pop()
        order.append(joint)
        stack.extend(children[joint][::-1])
    return order


def _postorder(children, parents):
    return _preorder(children, parents)[::-1]
