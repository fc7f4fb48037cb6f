"""Read the skins of a glTF 2.0 file: joint hierarchy, rest-pose joint matrices, skinned mesh.

pygltflib parses the file (.glb or .gltf with embedded, external or binary-chunk buffers); this
module only decodes accessors into numpy arrays and walks the node tree. `Skeleton.from_gltf`
turns the result into bodies and joints.
"""

from __future__ import annotations

import base64
import os
from dataclasses import dataclass, field

import numpy as np

from eigendance.errors import EigendanceError

COMPONENT_TYPES = {5120: np.int8, 5121: np.uint8, 5122: np.int16, 5123: np.uint16,
                   5125: np.uint32, 5126: np.float32}
WIDTHS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT2": 4, "MAT3": 9, "MAT4": 16}
TRIANGLES = 4


@dataclass
class SkinnedRig:
    """names (n_j,), parents (n_j,) index of the parent joint or -1, joint_matrices (n_j, 4, 4)
    world matrices in the rest pose, vertices (n, 3) rest-pose skin, faces (m, 3), weights
    (n, n_j) (rows may not sum to 1 yet)."""

    names: list[str]
    parents: np.ndarray
    joint_matrices: np.ndarray
    vertices: np.ndarray
    faces: np.ndarray
    weights: np.ndarray
    notes: list[str] = field(default_factory=list)


def read_skins(path: str | os.PathLike) -> SkinnedRig:
    """Every skin of the file merged by joint node (several skins may share one skeleton)."""
    import pygltflib

    path = os.fspath(path)
    label = os.path.basename(path)
    if not os.path.exists(path):
        raise EigendanceError(f"{path}: no such file")
    try:
        document = pygltflib.GLTF2().load(path)
    except Exception as error:  # pygltflib raises many kinds on a corrupt file
        raise EigendanceError(f"{label}: not a readable glTF file ({_one_line(error)})") from None
    if document is None:
        raise EigendanceError(f"{label}: not a readable glTF file")
    try:
        return _read(document, label)
    except EigendanceError:
        raise
    except (IndexError, KeyError, ValueError, TypeError, AttributeError) as error:
        raise EigendanceError(f"{label}: malformed glTF ({_one_line(error)})") from None


def _read(document, label: str) -> SkinnedRig:
    if not document.skins:
        raise EigendanceError(f"{label}: the file has no skin (no skeleton to analyse)")
    buffers = {}

    def buffer(index):
        if index not in buffers:
            uri = document.buffers[index].uri
            if uri and uri.startswith("data:"):  # any media type (pygltflib knows only one)
                if ";base64," not in uri:
                    raise EigendanceError(f"{label}: buffer {index} is not base64 data")
                data = base64.b64decode(uri.split(";base64,", 1)[1])
            else:
                data = document.get_data_from_buffer_uri(uri)
            if data is None:
                raise EigendanceError(f"{label}: buffer {index} cannot be read")
            buffers[index] = bytes(data)
        return buffers[index]

    def accessor(index) -> np.ndarray:
        item = document.accessors[index]
        dtype = np.dtype(COMPONENT_TYPES[item.componentType]).newbyteorder("<")
        width = WIDTHS[item.type]
        if item.bufferView is None:
            values = np.zeros((item.count, width), dtype=dtype)
        else:
            view = document.bufferViews[item.bufferView]
            data = buffer(view.buffer)
            offset = (view.byteOffset or 0) + (item.byteOffset or 0)
            stride = view.byteStride or dtype.itemsize * width
            needed = offset + stride * (item.count - 1) + dtype.itemsize * width
            if item.count and needed > len(data):
                raise EigendanceError(f"{label}: accessor {index} runs past its buffer")
            values = np.ndarray((item.count, width), dtype=dtype, buffer=data, offset=offset,
                                strides=(stride, dtype.itemsize)).copy()
        if item.sparse is not None and item.sparse.count:
            sparse = item.sparse
            indices = _raw(document, buffer, sparse.indices.bufferView,
                           sparse.indices.byteOffset, sparse.indices.componentType,
                           sparse.count, 1)[:, 0].astype(np.int64)
            values[indices] = _raw(document, buffer, sparse.values.bufferView,
                                   sparse.values.byteOffset, item.componentType,
                                   sparse.count, width)
        if item.normalized and dtype.kind in "iu":
            return np.maximum(values / np.iinfo(dtype).max, -1.0)
        return values

    nodes = document.nodes
    parent_node = np.full(len(nodes), -1)
    for index, node in enumerate(nodes):
        for child in node.children or []:
            parent_node[child] = index
    world = _world_matrices(nodes, parent_node)

    joint_nodes: list[int] = []
    for skin in document.skins:
        for node in skin.joints:
            if node not in joint_nodes:
                joint_nodes.append(node)
    column = {node: position for position, node in enumerate(joint_nodes)}
    names, seen = [], set()
    for node in joint_nodes:
        name = nodes[node].name or f"joint{node}"
        if name in seen:
            name = f"{name}#{node}"
        seen.add(name)
        names.append(name)
    parents = np.full(len(joint_nodes), -1)
    for position, node in enumerate(joint_nodes):
        ancestor = parent_node[node]
        while ancestor >= 0 and ancestor not in column:
            ancestor = parent_node[ancestor]
        parents[position] = column[ancestor] if ancestor >= 0 else -1

    pieces_vertices, pieces_faces, pieces_weights = [], [], []
    offset = 0
    notes = []
    for node in nodes:
        if node.skin is None or node.mesh is None:
            continue
        skin = document.skins[node.skin]
        skin_columns = np.array([column[j] for j in skin.joints])
        if skin.inverseBindMatrices is not None:
            inverse_bind = accessor(skin.inverseBindMatrices).reshape(-1, 4, 4)
            inverse_bind = np.swapaxes(inverse_bind, 1, 2).astype(float)  # column-major
        else:
            inverse_bind = np.tile(np.eye(4), (len(skin.joints), 1, 1))
        skinning = world[np.array(skin.joints)] @ inverse_bind  # (n_skin_joints, 4, 4)
        for primitive in document.meshes[node.mesh].primitives:
            mode = TRIANGLES if primitive.mode is None else primitive.mode
            attributes = primitive.attributes
            if mode != TRIANGLES or attributes.POSITION is None:
                notes.append("skipped a non-triangle primitive")
                continue
            positions = accessor(attributes.POSITION).astype(float)
            count = len(positions)
            weights = np.zeros((count, len(joint_nodes)))
            set_index = 0
            while getattr(attributes, f"JOINTS_{set_index}", None) is not None:
                joints = accessor(getattr(attributes, f"JOINTS_{set_index}")).astype(np.int64)
                weight_index = getattr(attributes, f"WEIGHTS_{set_index}", None)
                if weight_index is None:
                    raise EigendanceError(f"{label}: JOINTS_{set_index} without "
                                          f"WEIGHTS_{set_index}")
                values = accessor(weight_index).astype(float)
                if joints.min(initial=0) < 0 or joints.max(initial=0) >= len(skin.joints):
                    raise EigendanceError(f"{label}: a vertex names joint "
                                          f"{joints.max()} of a {len(skin.joints)}-joint skin")
                rows = np.repeat(np.arange(count), joints.shape[1])
                np.add.at(weights, (rows, skin_columns[joints.reshape(-1)]),
                          np.clip(values.reshape(-1), 0, None))
                set_index += 1
            if set_index == 0:
                notes.append("skipped a primitive without skin weights")
                continue
            # Rest pose: Σ_j w_j (W_j · IBM_j) x, with weights over this skin's joints.
            local = weights[:, skin_columns]
            total = local.sum(axis=1, keepdims=True)
            blend = (local / np.where(total > 0, total, 1)) @ skinning.reshape(-1, 16)
            blend[total[:, 0] <= 0] = np.eye(4).reshape(-1)
            blend = blend.reshape(-1, 4, 4)
            positions = np.einsum("nij,nj->ni", blend[:, :3, :3], positions) + blend[:, :3, 3]
            if primitive.indices is not None:
                indices = accessor(primitive.indices).reshape(-1).astype(np.int64)
            else:
                indices = np.arange(count)
            if len(indices) % 3 or (len(indices) and (indices.max() >= count
                                                       or indices.min() < 0)):
                raise EigendanceError(f"{label}: a primitive has bad triangle indices")
            pieces_vertices.append(positions)
            pieces_weights.append(weights)
            pieces_faces.append(indices.reshape(-1, 3) + offset)
            offset += count
    joint_matrices = world[np.array(joint_nodes)]
    if not pieces_vertices:
        return SkinnedRig(names, parents, joint_matrices, np.zeros((0, 3)),
                          np.zeros((0, 3), dtype=np.int64), np.zeros((0, len(joint_nodes))),
                          notes + ["no skinned triangles"])
    vertices = np.concatenate(pieces_vertices)
    faces = np.concatenate(pieces_faces)
    weights = np.concatenate(pieces_weights)
    if not np.all(np.isfinite(vertices)) or not np.all(np.isfinite(weights)):
        raise EigendanceError(f"{label}: non-finite vertex positions or weights")
    vertices, faces, weights, welded = weld(vertices, faces, weights)
    if welded:
        notes.append(f"welded {welded} seam vertices")
    return SkinnedRig(names, parents, joint_matrices, vertices, faces, weights, notes)


def weld(vertices, faces, weights, tolerance: float = 1e-7):
    """Merge vertices closer than tolerance·(bounding-box diagonal) (seams split by exporters);
    weights of merged vertices are averaged; faces that collapse are dropped."""
    diagonal = float(np.linalg.norm(vertices.max(axis=0) - vertices.min(axis=0))) or 1.0
    keys = np.round(vertices / (tolerance * diagonal)).astype(np.int64)
    _, first, inverse = np.unique(keys, axis=0, return_index=True, return_inverse=True)
    inverse = inverse.reshape(-1)
    order = np.argsort(first)  # keep the original order of first occurrences
    rank = np.empty_like(order)
    rank[order] = np.arange(len(order))
    inverse = rank[inverse]
    merged_vertices = vertices[first[order]]
    counts = np.bincount(inverse, minlength=len(order)).astype(float)
    merged_weights = np.zeros((len(order), weights.shape[1]))
    np.add.at(merged_weights, inverse, weights)
    merged_weights /= counts[:, None]
    faces = inverse[faces]
    keep = (faces[:, 0] != faces[:, 1]) & (faces[:, 1] != faces[:, 2]) & \
        (faces[:, 0] != faces[:, 2])
    return merged_vertices, faces[keep], merged_weights, len(vertices) - len(order)


def _raw(document, buffer, view_index, byte_offset, component_type, count, width):
    dtype = np.dtype(COMPONENT_TYPES[component_type]).newbyteorder("<")
    view = document.bufferViews[view_index]
    offset = (view.byteOffset or 0) + (byte_offset or 0)
    return np.frombuffer(buffer(view.buffer), dtype=dtype, count=count * width,
                         offset=offset).reshape(count, width)


def _local_matrix(node) -> np.ndarray:
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


def _world_matrices(nodes, parent_node) -> np.ndarray:
    world = np.full((len(nodes), 4, 4), np.nan)

    def resolve(index, depth=0):
        if not np.isnan(world[index, 0, 0]):
            return world[index]
        if depth > len(nodes):
            raise EigendanceError("the node hierarchy has a cycle")
        parent = parent_node[index]
        local = _local_matrix(nodes[index])
        world[index] = local if parent < 0 else resolve(parent, depth + 1) @ local
        return world[index]

    for index in range(len(nodes)):
        resolve(index)
    return world


def _one_line(error: Exception) -> str:
    text = " ".join(str(error).split())
    return (text[:150] + "…") if len(text) > 150 else (text or type(error).__name__)
