"""The mesh nodes of a glTF scene, in world coordinates (docs/design.md#appearance).

Every node of the default scene (or, without scenes, of every root node) that has a mesh comes
in with its world transform, once per node: several meshes, several primitives (each read by
`assets.primitives`), the same mesh under two nodes (instancing). Skinned meshes come in bind
pose, Σ_j w_j (W_j · IBM_j) x, with their weights over the union of every skin's joints
(several skins may share one skeleton); a mesh node below a joint node (a prop on a bone)
records that joint (`Piece.bone`). Triangle strips and fans become triangles; points and lines
cannot be kept and are listed in `notes`, as are morph targets of the file's own (the rest
shape is the mesh at its default weights).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from eigendance.assets.gltf import GltfFile
from eigendance.assets.primitives import MODE_NAMES, Piece, read_piece

# Joints read from a model's skins: the weights are a dense (vertices, joints) array, and a rig
# keeps at most modal.bodies.MAX_BODIES of them (helper bones that move nothing are dropped).
MAX_SKIN_JOINTS = 1024


@dataclass
class SkinTree:
    """The joints of every skin: names, parents (joint column or -1), matrices (n_j, 4, 4)
    world transforms at rest, nodes (the joint nodes).

    Parameters
    ----------
    names, parents, matrices, nodes : as above.
    """

    names: list[str]
    parents: np.ndarray
    matrices: np.ndarray
    nodes: list[int]


@dataclass
class Scene:
    """Every mesh node of a glTF scene as pieces, and the joints of its skins.

    Parameters
    ----------
    pieces : one `Piece` per primitive of every mesh node.
    skin : the joints of its skins, or None.
    notes : what was not kept.
    """
    pieces: list[Piece]
    skin: SkinTree | None
    notes: list[str] = field(default_factory=list)


def read_scene(gltf: GltfFile) -> Scene:
    """Every mesh node of the default scene as `Piece`s, the joints of its skins, and notes.

    Parameters
    ----------
    gltf : the file.

    Returns
    -------
    Scene.
    """
    document = gltf.document
    nodes = document.nodes or []
    parents = _parents(gltf, nodes)
    roots = _roots(gltf, parents)
    order = _preorder(gltf, nodes, roots)
    world = _world(nodes, parents, order)
    skin = _skin_tree(gltf, nodes, parents, world, set(order))
    column = {node: index for index, node in enumerate(skin.nodes)} if skin else {}
    counter: dict[str, int] = {}
    pieces = []
    for node_index in order:
        node = nodes[node_index]
        if node.mesh is None:
            continue
        meshes = document.meshes or []
        if not isinstance(node.mesh, int) or not 0 <= node.mesh < len(meshes):
            raise gltf.message(f"node {node_index} names mesh {node.mesh!r}, which does not "
                               "exist")
        skinning = _skinning(gltf, node, world, column) if node.skin is not None else None
        bone = -1 if skinning is not None else _bone(node_index, parents, column)
        for index, primitive in enumerate(meshes[node.mesh].primitives or []):
            what = f"mesh {node.mesh} primitive {index}"
            piece = read_piece(gltf, primitive, what, counter, node, meshes[node.mesh])
            if piece is None:
                continue
            if skinning is not None:
                _bind(gltf, piece, primitive, skinning, len(column), what)
            else:
                _place(piece, world[node_index])
                piece.bone = bone
            pieces.append(piece)
    notes = [f"{count} {what} primitive{'s' * (count > 1)} (not triangles)" if what in
             MODE_NAMES.values() else f"{count} {what}" for what, count in counter.items()]
    return Scene(pieces, skin, notes)


def _parents(gltf: GltfFile, nodes) -> np.ndarray:
    parents = np.full(len(nodes), -1)
    for index, node in enumerate(nodes):
        for child in node.children or []:
            if not isinstance(child, int) or not 0 <= child < len(nodes) or child == index:
                raise gltf.message(f"node {index} has an impossible child {child!r}")
            if parents[child] >= 0:
                raise gltf.message(f"node {child} has two parents (the nodes must form trees)")
            parents[child] = index
    return parents


def _roots(gltf: GltfFile, parents) -> list[int]:
    scenes = gltf.document.scenes or []
    if not scenes:
        return [int(i) for i in np.flatnonzero(parents < 0)]
    chosen = gltf.document.scene if isinstance(gltf.document.scene, int) else 0
    if not 0 <= chosen < len(scenes):
        raise gltf.message(f"the default scene {chosen} does not exist")
    roots = list(scenes[chosen].nodes or [])
    for root in roots:
        if not isinstance(root, int) or not 0 <= root < len(parents):
            raise gltf.message(f"scene {chosen} names node {root!r}, which does not exist")
    return roots


def _preorder(gltf: GltfFile, nodes, roots) -> list[int]:
    order, stack, seen = [], list(reversed(roots)), set()
    while stack:
        index = stack.pop()
        if index in seen:
            raise gltf.message(f"node {index} appears twice in the scene (a cycle)")
        seen.add(index)
        order.append(index)
        stack.extend(reversed(nodes[index].children or []))
    return order


def local_matrix(node) -> np.ndarray:
    """A node's local transform (4, 4): its matrix, or T·R·S.

    Parameters
    ----------
    node : a glTF node.

    Returns
    -------
    (4, 4).
    """
    if node.matrix is not None:
        return np.array(node.matrix, dtype=float).reshape(4, 4).T  # column-major
    matrix = np.eye(4)
    if node.rotation is not None:
        x, y, z, w = np.asarray(node.rotation, dtype=float) / np.linalg.norm(node.rotation)
        matrix[:3, :3] = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                          [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                          [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
    if node.scale is not None:
        matrix[:3, :3] = matrix[:3, :3] * np.asarray(node.scale, dtype=float)[None, :]
    if node.translation is not None:
        matrix[:3, 3] = node.translation
    return matrix


def _world(nodes, parents, order) -> np.ndarray:
    """World matrices of every node (parents come before children in `order`; nodes outside
    the scene get their chain resolved too, as skins may name them)."""
    world = np.full((len(nodes), 4, 4), np.nan)

    def resolve(index):
        chain = []
        while index >= 0 and np.isnan(world[index, 0, 0]):
            chain.append(index)
            index = parents[index]
            if len(chain) > len(nodes):
                break
        above = np.eye(4) if index < 0 else world[index]
        for each in reversed(chain):
            above = above @ local_matrix(nodes[each])
            world[each] = above

    for index in [*order, *range(len(nodes))]:
        resolve(index)
    return world


def _skin_tree(gltf: GltfFile, nodes, parents, world, in_scene) -> SkinTree | None:
    skins = gltf.document.skins or []
    used = {node.skin for index, node in enumerate(nodes)
            if index in in_scene and node.skin is not None and node.mesh is not None}
    joint_nodes: list[int] = []
    listed: set[int] = set()
    for skin_index in sorted(s for s in used if isinstance(s, int)):
        if not 0 <= skin_index < len(skins):
            raise gltf.message(f"a node names skin {skin_index}, which does not exist")
        for joint in skins[skin_index].joints or []:
            if not isinstance(joint, int) or not 0 <= joint < len(nodes):
                raise gltf.message(f"skin {skin_index} names joint node {joint!r}")
            if joint not in listed:
                listed.add(joint)
                joint_nodes.append(joint)
    if len(joint_nodes) > MAX_SKIN_JOINTS:  # before the (vertices, joints) weights exist
        raise gltf.message(f"its skins have {len(joint_nodes)} joints; at most "
                           f"{MAX_SKIN_JOINTS} are read")
    if not joint_nodes:
        return None
    column = {node: position for position, node in enumerate(joint_nodes)}
    names, seen = [], set()
    for node in joint_nodes:
        name = str(nodes[node].name or f"joint{node}")
        name = f"{name}#{node}" if name in seen else name
        seen.add(name)
        names.append(name)
    joint_parents = np.array([_nearest(parents[node], parents, column) for node in joint_nodes])
    return SkinTree(names, joint_parents, world[np.array(joint_nodes)], joint_nodes)


def _nearest(node: int, parents, column) -> int:
    """The column of the nearest joint among `node` and its ancestors, or -1."""
    while node >= 0 and node not in column:
        node = parents[node]
    return column[node] if node >= 0 else -1


def _bone(node: int, parents, column) -> int:
    return _nearest(parents[node], parents, column) if column else -1


def _skinning(gltf: GltfFile, node, world, column):
    """(columns of the skin's joints, W_j · IBM_j (n, 4, 4)) of a skinned node."""
    skin = gltf.document.skins[node.skin]
    joints = np.array(skin.joints, dtype=np.int64)
    if skin.inverseBindMatrices is not None:
        inverse = gltf.accessor(skin.inverseBindMatrices)
        if inverse.shape != (len(joints), 16):
            raise gltf.message(f"skin {node.skin} has {len(inverse)} inverse bind matrices for "
                               f"{len(joints)} joints")
        inverse = np.swapaxes(inverse.reshape(-1, 4, 4), 1, 2)  # column-major
        # An inverse bind matrix must be invertible (all zeros would put the skin at a point).
        with np.errstate(all="ignore"):
            scale = np.abs(inverse[:, :3, :3]).max(axis=(1, 2)) ** 3
            singular = ~(np.abs(np.linalg.det(inverse)) > 1e-12 * scale) | \
                ~np.isfinite(inverse).all(axis=(1, 2))
        if singular.any():
            raise gltf.message(f"skin {node.skin}: inverseBindMatrices[{np.argmax(singular)}] "
                               "is not an invertible matrix")
    else:
        inverse = np.tile(np.eye(4), (len(joints), 1, 1))
    return np.array([column[j] for j in joints]), world[joints] @ inverse


def _place(piece: Piece, matrix: np.ndarray) -> None:
    """Move a rigid piece to world coordinates; a mirroring transform keeps the winding."""
    linear = matrix[:3, :3]
    piece.positions = piece.positions @ linear.T + matrix[:3, 3]
    if piece.normals is not None:
        piece.normals = _unit(piece.normals @ np.linalg.pinv(linear))
    if piece.tangents is not None:
        piece.tangents[:, :3] = _unit(piece.tangents[:, :3] @ linear.T)
    if np.linalg.det(linear) < 0:
        piece.triangles = piece.triangles[:, ::-1].copy()


def _bind(gltf: GltfFile, piece: Piece, primitive, skinning, n_joints: int, what: str) -> None:
    """Weights over the joint columns and bind-pose positions of a skinned piece."""
    columns, matrices = skinning
    attributes = piece.attributes
    count = len(piece.positions)
    weights = np.zeros((count, n_joints))
    set_index = 0
    while f"JOINTS_{set_index}" in attributes:
        joints = attributes[f"JOINTS_{set_index}"].astype(np.int64)
        values = attributes.get(f"WEIGHTS_{set_index}")
        if values is None:
            raise gltf.message(f"{what}: JOINTS_{set_index} without WEIGHTS_{set_index}")
        bad = np.flatnonzero(~np.isfinite(values).all(axis=-1))
        if len(bad):  # it would blend the bind pose into NaN positions
            raise gltf.message(f"{what}: WEIGHTS_{set_index} holds NaN or infinite weights "
                               f"({len(bad)} vertices, the first {bad[0]})")
        if joints.min(initial=0) < 0 or joints.max(initial=0) >= len(columns):
            raise gltf.message(f"{what}: a vertex names joint {joints.max()} of a "
                               f"{len(columns)}-joint skin")
        rows = np.repeat(np.arange(count), joints.shape[1])
        np.add.at(weights, (rows, columns[joints.reshape(-1)]),
                  np.clip(values.reshape(-1), 0, None))
        set_index += 1
    local = weights[:, columns]
    total = local.sum(axis=1, keepdims=True)
    blend = (local / np.where(total > 0, total, 1)) @ matrices.reshape(-1, 16)
    blend[total[:, 0] <= 0] = np.eye(4).reshape(-1)
    blend = blend.reshape(-1, 4, 4)
    piece.positions = np.einsum("nij,nj->ni", blend[:, :3, :3], piece.positions) + \
        blend[:, :3, 3]
    if piece.normals is not None:
        piece.normals = _unit(np.einsum("nij,nj->ni", blend[:, :3, :3], piece.normals))
    if piece.tangents is not None:
        piece.tangents[:, :3] = _unit(np.einsum("nij,nj->ni", blend[:, :3, :3],
                                                piece.tangents[:, :3]))
    piece.weights = weights


def _unit(vectors: np.ndarray) -> np.ndarray:
    length = np.linalg.norm(vectors, axis=1, keepdims=True)
    return vectors / np.where(length > 0, length, 1)
