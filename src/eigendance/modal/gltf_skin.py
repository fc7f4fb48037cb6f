"""glTF 2.0 skins as skeletons: joint hierarchy, rest pose, skinned mesh (docs/design.md#skeleton).

pygltflib parses the file (.glb or .gltf with embedded, external or binary-chunk buffers); this
module decodes accessors into numpy arrays, walks the node tree (`read_skins`) and turns the
joints into bodies and elastic joints (`skeleton_from_gltf`).
"""

from __future__ import annotations

import base64
import os
from dataclasses import dataclass, field

import numpy as np
import pygltflib

from eigendance.errors import InputError, one_line
from eigendance.geometry import weld
from eigendance.modal.bodies import Body, Joint
from eigendance.modal.skeleton import Skeleton
from eigendance.modal.stiffness import DEFAULT_JOINT_FREQUENCY, set_automatic_stiffness

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


def skeleton_from_gltf(path: str | os.PathLike,
                       stiffness_frequency: float = DEFAULT_JOINT_FREQUENCY,
                       name: str | None = None) -> Skeleton:
    """Read the skins of a glTF 2.0 file (.glb, .gltf) as a skeleton with a skinned mesh; messages
    call it `name` (default: the file's name).

    - Rest pose: the file's node pose. Joint j sits at the origin of its world matrix W_j;
      skinned vertices are placed at Σ_j w_j W_j·IBM_j·x (the bind pose, x itself when the
      inverse bind matrices match the nodes, as they do in exported rigs).
    - Bodies: one per joint node, from the node to its child joint (the child with the most
      descendant joints, then the farthest), or, for a leaf, along the node's own +y axis
      (the bone axis of Blender and most exporters) as far as the vertices it weighs reach.
      Radius: the median distance from the axis of the vertices the body dominates, clamped
      to [0.02, 1]·length. Density DEFAULT_DENSITY (the size unit is taken to be metres;
      frequencies do not depend on it with the default stiffness).
    - Joints: one spherical joint (free ω, natural for characters) between each joint node
      and its parent joint node, at the child's position; stiffness per rotation row from
      `skeleton.automatic_stiffness`: each of the two parts a joint joins (for a limb: the
      limb from that joint outward, and the rest) swings about it like a pendulum of its own
      length under one gravity, at `stiffness_frequency` Hz (1 Hz) when its centre lies a
      quarter of the rig's size from the joint. Other choices: `Skeleton.with_stiffness`, or
      change `joints` (type, stiffness) of the returned skeleton in code; the skin stays valid.
    - Skin: every triangle primitive of every skinned mesh node (several skins sharing one
      skeleton are merged by joint node); JOINTS_n/WEIGHTS_n read, renormalised to sum 1
      (vertices with no weight go to the nearest body); seam vertices (same position)
      welded.
    """
    rig = read_skins(path)
    return _skeleton_from_rig(rig, os.path.basename(os.fspath(path)), stiffness_frequency)


def has_skin(path: str | os.PathLike) -> bool:
    """Whether a glTF file (.glb, .gltf) has a skin; False for anything unreadable."""
    try:
        document = pygltflib.GLTF2().load(os.fspath(path))
    except Exception:  # noqa: BLE001 - pygltflib raises many kinds; the mesh reader says why
        return False
    return bool(document is not None and document.skins)


def read_skins(path: str | os.PathLike) -> SkinnedRig:
    """Every skin of the file merged by joint node (several skins may share one skeleton)."""

    path = os.fspath(path)
    label = os.path.basename(path)
    if not os.path.exists(path):
        raise InputError(f"{path}: no such file")
    try:
        document = pygltflib.GLTF2().load(path)
    except Exception as error:  # pygltflib raises many kinds on a corrupt file
        raise InputError(f"{label}: not a readable glTF file ({one_line(error, 150)})") from None
    if document is None:
        raise InputError(f"{label}: not a readable glTF file")
    try:
        return _read(document, label)
    except InputError:
        raise
    except (IndexError, KeyError, ValueError, TypeError, AttributeError) as error:
        raise InputError(f"{label}: malformed glTF ({one_line(error, 150)})") from None


def _read(document, label: str) -> SkinnedRig:
    if not document.skins:
        raise InputError(f"{label}: the file has no skin (no skeleton to analyse)")
    buffers = {}

    def buffer(index):
        if index not in buffers:
            uri = document.buffers[index].uri
            if uri and uri.startswith("data:"):  # any media type (pygltflib knows only one)
                if ";base64," not in uri:
                    raise InputError(f"{label}: buffer {index} is not base64 data")
                data = base64.b64decode(uri.split(";base64,", 1)[1])
            else:
                data = document.get_data_from_buffer_uri(uri)
            if data is None:
                raise InputError(f"{label}: buffer {index} cannot be read")
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
                raise InputError(f"{label}: accessor {index} runs past its buffer")
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
                    raise InputError(f"{label}: JOINTS_{set_index} without "
                                          f"WEIGHTS_{set_index}")
                values = accessor(weight_index).astype(float)
                if joints.min(initial=0) < 0 or joints.max(initial=0) >= len(skin.joints):
                    raise InputError(f"{label}: a vertex names joint "
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
                raise InputError(f"{label}: a primitive has bad triangle indices")
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
        raise InputError(f"{label}: non-finite vertex positions or weights")
    vertices, faces, weights, welded = weld_seams(vertices, faces, weights)
    if welded:
        notes.append(f"welded {welded} seam vertices")
    return SkinnedRig(names, parents, joint_matrices, vertices, faces, weights, notes)


def weld_seams(vertices, faces, weights, tolerance: float = 1e-7):
    """Merge vertices closer than tolerance·(bounding-box diagonal) (seams split by exporters);
    weights of merged vertices are averaged; faces that collapse are dropped."""
    first, inverse = weld(vertices, tolerance)
    counts = np.bincount(inverse, minlength=len(first)).astype(float)
    merged_weights = np.zeros((len(first), weights.shape[1]))
    np.add.at(merged_weights, inverse, weights)
    merged_weights /= counts[:, None]
    faces = inverse[faces]
    keep = (faces[:, 0] != faces[:, 1]) & (faces[:, 1] != faces[:, 2]) & \
        (faces[:, 0] != faces[:, 2])
    return vertices[first], faces[keep], merged_weights, len(vertices) - len(first)


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
            raise InputError("the node hierarchy has a cycle")
        parent = parent_node[index]
        local = _local_matrix(nodes[index])
        world[index] = local if parent < 0 else resolve(parent, depth + 1) @ local
        return world[index]

    for index in range(len(nodes)):
        resolve(index)
    return world


def _skeleton_from_rig(rig, name: str, stiffness_frequency: float) -> Skeleton:
    """Bodies and spherical joints from a `gltf_skin.SkinnedRig` (see Skeleton.from_gltf)."""
    positions = rig.joint_matrices[:, :3, 3]
    n_joints = len(positions)
    vertices, weights = rig.vertices, rig.weights
    extent = np.concatenate([positions, vertices]) if len(vertices) else positions
    size = float(np.linalg.norm(extent.max(axis=0) - extent.min(axis=0))) or 1.0
    tiny = 1e-4 * size
    children = [[] for _ in range(n_joints)]
    for child, parent in enumerate(rig.parents):
        if parent >= 0:
            children[parent].append(child)
    descendants = np.zeros(n_joints, dtype=int)
    for joint in _postorder(children, rig.parents):
        descendants[joint] = sum(1 + descendants[c] for c in children[joint])
    dominant = weights.argmax(axis=1) if len(vertices) else np.zeros(0, dtype=int)
    starts, ends = positions.copy(), np.zeros_like(positions)
    lengths = np.zeros(n_joints)
    order = _preorder(children, rig.parents)
    for joint in order:  # parents before children, so a leaf can fall back on its parent
        start = positions[joint]
        candidates = [c for c in children[joint]
                      if np.linalg.norm(positions[c] - start) > tiny]
        if candidates:
            child = max(candidates, key=lambda c: (descendants[c],
                                                   np.linalg.norm(positions[c] - start)))
            ends[joint] = positions[child]
            lengths[joint] = np.linalg.norm(positions[child] - start)
            continue
        owned = vertices[dominant == joint] - start
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
    bodies = []
    for joint in range(n_joints):
        axis = (ends[joint] - starts[joint]) / lengths[joint]
        owned = vertices[dominant == joint] - starts[joint]
        if len(owned):
            along = np.clip(owned @ axis, 0, lengths[joint])
            radial = np.linalg.norm(owned - along[:, None] * axis, axis=1)
            radius = float(np.median(radial))
        else:
            radius = 0.15 * lengths[joint]
        radius = float(np.clip(radius, 0.02 * lengths[joint], lengths[joint]))
        bodies.append(Body(rig.names[joint], starts[joint], ends[joint], radius))
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


def _attach_separate_trees(bodies, joints, rig, descendants, weights) -> int:
    """Join the roots of separate joint trees (IK targets, flat hierarchies such as the WebXR
    hand) into one tree, Prim-style: repeatedly attach the free root nearest to a body already
    in the tree with a spherical joint at the root's position. Returns how many were attached."""
    roots = [j for j, p in enumerate(rig.parents) if p < 0]
    if len(roots) < 2:
        return 0
    load = weights.sum(axis=0) if len(weights) else np.zeros(len(bodies))
    main = max(roots, key=lambda r: (descendants[r], load[r]))
    children = [[] for _ in bodies]
    for child, parent in enumerate(rig.parents):
        if parent >= 0:
            children[parent].append(child)
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
