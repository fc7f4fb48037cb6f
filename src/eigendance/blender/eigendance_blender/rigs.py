"""A rig's dance on an armature: the body transforms `eigendance animate-rig` writes, put on the
bones of the same name as an Action; the skinned meshes follow.

The command's transforms D_b(t) move the rig file's model space (glTF: Y up). The armature's own
space is that space as Blender's importer placed it, found from the skinned meshes: the rig's
rest vertices, turned Z up or not, scaled and moved onto the meshes' vertices (nearest), then
an affine map A fitted to the pairs. A bone b of parent p (D of a bone the command leaves out:
its parent's) gets the pose basis R_b⁻¹·D_p⁻¹·D_b·R_b, with D = A·D·A⁻¹ and R a bone's rest
matrix in armature space: its pose matrix is then D_b·R_b and it deforms by D_b, as the command.
"""

import mathutils
import numpy as np
from mathutils.kdtree import KDTree

from . import keys

Z_UP = np.array([[1.0, 0, 0], [0, 0, -1], [0, 1, 0]])  # glTF Y up → Blender Z up
FIT_SAMPLES = 400


def skinned_positions(armature) -> np.ndarray:
    """The rest vertices of the meshes the armature deforms, in armature space.

    Parameters
    ----------
    armature : the armature object.

    Returns
    -------
    (n, 3).
    """
    found = []
    inverse = np.array(armature.matrix_world.inverted())
    for obj in armature.users_scene[0].objects if armature.users_scene else ():
        if obj.type != "MESH" or not any(m.type == "ARMATURE" and m.object == armature
                                         for m in obj.modifiers):
            continue
        points = np.empty(3 * len(obj.data.vertices))
        obj.data.vertices.foreach_get("co", points)
        matrix = inverse @ np.array(obj.matrix_world)
        found.append(points.reshape(-1, 3) @ matrix[:3, :3].T + matrix[:3, 3])
    return np.concatenate(found) if found else np.empty((0, 3))


def fit_space(rest: np.ndarray, skinned: np.ndarray):
    """The affine map A (4, 4) from the rig file's space to the armature's, and its error.

    Parameters
    ----------
    rest : (m, 3) the command's rest vertices.
    skinned : (n, 3) the armature's skinned vertices.

    Returns
    -------
    (A, largest distance / diagonal).
    """
    tree = KDTree(len(skinned))
    for index, point in enumerate(skinned):
        tree.insert(point, index)
    tree.balance()
    diagonal = float(np.linalg.norm(np.ptp(skinned, axis=0))) or 1.0
    picks = rest[np.linspace(0, len(rest) - 1, min(FIT_SAMPLES, len(rest))).astype(int)]
    best = (None, np.inf)
    for turn in (Z_UP, np.eye(3)):
        turned = rest @ turn.T
        size = float(np.linalg.norm(np.ptp(turned, axis=0))) or 1.0
        scale = diagonal / size
        moved = (turned - turned.mean(axis=0)) * scale + skinned.mean(axis=0)
        chosen = moved[np.linspace(0, len(rest) - 1, len(picks)).astype(int)]
        pairs = np.array([tree.find(point)[0] for point in chosen])
        ones = np.hstack([picks, np.ones((len(picks), 1))])
        solution = np.linalg.lstsq(ones, pairs, rcond=None)[0]  # (4, 3)
        error = np.abs(ones @ solution - pairs).max() / diagonal
        if error < best[1]:
            matrix = np.eye(4)
            matrix[:3, :] = solution.T
            best = (matrix, error)
    return best


def bone_order(armature) -> list:
    """The armature's bones, every parent before its children.

    Parameters
    ----------
    armature : the armature object.

    Returns
    -------
    list of bones.
    """
    ordered, stack = [], [bone for bone in armature.data.bones if bone.parent is None]
    while stack:
        bone = stack.pop()
        ordered.append(bone)
        stack.extend(bone.children)
    return ordered


def pose_bases(armature, names, transforms, space) -> dict:
    """Each moving bone's pose basis at every sample (see the module docstring).

    Parameters
    ----------
    armature : the armature object.
    names : (nb,) the command's body names.
    transforms : (T, nb, 4, 4) D_b(t), the rig file's space.
    space : (4, 4) A.

    Returns
    -------
    {bone name: (T, 4, 4)}.
    """
    inverse = np.linalg.inv(space)
    moved = {str(name): space @ transforms[:, index].astype(np.float64) @ inverse
             for index, name in enumerate(names)}
    count = len(transforms)
    world = {}
    bases = {}
    for bone in bone_order(armature):
        parent = world.get(bone.parent.name) if bone.parent else None
        parent = parent if parent is not None else np.broadcast_to(np.eye(4), (count, 4, 4))
        own = moved.get(bone.name, parent)
        world[bone.name] = own
        if bone.name in moved:
            rest = np.array(bone.matrix_local)
            bases[bone.name] = np.linalg.inv(rest) @ np.linalg.inv(parent) @ own @ rest
    return bases


def key_bones(armature, bases: dict, first: int, name: str) -> None:
    """Keyframe each bone's location and rotation (quaternion) at every sample, in a new Action.

    Parameters
    ----------
    armature : the armature object.
    bases : {bone name: (T, 4, 4)} pose bases.
    first : the frame of sample 0.
    name : the action's name.
    """
    keys.fresh_action(armature, name)
    for bone_name, basis in bases.items():
        bone = armature.pose.bones[bone_name]
        bone.rotation_mode = "QUATERNION"
        turns = np.array([tuple(mathutils.Matrix(m[:3, :3].tolist()).to_quaternion())
                          for m in basis])
        flips = np.cumprod(np.where(np.sum(turns[1:] * turns[:-1], axis=1) < 0, -1.0, 1.0))
        turns[1:] *= flips[:, None]  # each next to the last: no spin the long way round
        frames = first + np.arange(len(basis))
        for index in range(3):
            keys.key_samples(armature, bone, "location", index, frames, basis[:, index, 3])
        for index in range(4):
            keys.key_samples(armature, bone, "rotation_quaternion", index, frames,
                             turns[:, index])
    keys.name_action(armature)


def clear_pose(armature) -> None:
    """Put every bone back at rest (what the new Action does not key stays there).

    Parameters
    ----------
    armature : the armature object.
    """
    for bone in armature.pose.bones:
        bone.location = (0, 0, 0)
        bone.rotation_quaternion = (1, 0, 0, 0)
        bone.rotation_euler = (0, 0, 0)
        bone.scale = (1, 1, 1)
