"""One glTF primitive as arrays: a `Piece` (docs/design.md#appearance).

A primitive's attributes (from accessors, or decoded from Draco) with its triangles: triangle
strips and fans become triangles, points and lines cannot be kept (counted for the scene's
notes), the positions are those of the mesh's default morph weights, and only the vertices the
primitive draws are kept (primitives often share one accessor). Coordinates are the mesh's own;
`assets.scene` places the piece in the world.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from eigendance.assets.gltf import DRACO, GltfFile

TRIANGLES, STRIP, FAN = 4, 5, 6
MODE_NAMES = {0: "point", 1: "line", 2: "line loop", 3: "line strip"}


@dataclass
class Piece:
    """One primitive of one mesh node, in world coordinates at rest.

    positions (n, 3); triangles (m, 3) into positions; normals (n, 3) or None; tangents (n, 4)
    or None; uvs one (n, 2) per TEXCOORD set; colors (n, 4) or None; material: the document's
    material index or -1; weights (n, n_joints) over `SkinTree` columns (skinned) or None;
    bone: the joint column a rigid mesh hangs from, or -1.

    Parameters
    ----------
    positions, triangles, normals, tangents, uvs, colors, material, weights, bone : as above.
    attributes : the primitive's other attributes by name.
    """

    positions: np.ndarray
    triangles: np.ndarray
    normals: np.ndarray | None
    tangents: np.ndarray | None
    uvs: list
    colors: np.ndarray | None
    material: int
    weights: np.ndarray | None = None
    bone: int = -1
    attributes: dict = field(default_factory=dict, repr=False)  # as read (joints, weights)


def read_piece(gltf: GltfFile, primitive, what: str, counter: dict, node,
               mesh) -> Piece | None:
    """A primitive's arrays in its mesh's coordinates, or None (counted in `counter`).

    Parameters
    ----------
    gltf : the file.
    primitive : the glTF primitive.
    what : how messages name it ("mesh 0 primitive 1").
    counter : {what was not kept: count}, added to.
    node, mesh : the node and mesh it belongs to (their default morph weights).

    Returns
    -------
    Piece in the mesh's coordinates (weights None, bone -1), or None.
    """
    mode = TRIANGLES if primitive.mode is None else primitive.mode
    if mode not in (TRIANGLES, STRIP, FAN):
        name = MODE_NAMES.get(mode, f"mode-{mode}")
        counter[name] = counter.get(name, 0) + 1
        return None
    attributes, indices = _attributes(gltf, primitive, what)
    if "POSITION" not in attributes:
        counter["primitives without positions"] = counter.get(
            "primitives without positions", 0) + 1
        return None
    positions = attributes["POSITION"][:, :3].astype(float)
    count = len(positions)
    indices = np.arange(count) if indices is None else indices
    if len(indices) and (indices.min() < 0 or indices.max() >= count):
        raise gltf.message(f"{what} has vertex indices outside 0..{count - 1}")
    triangles = _triangles(indices, mode)
    if primitive.targets:
        positions = _default_shape(gltf, primitive, node, mesh, positions, what)
        counter["morph targets of the file's own"] = counter.get(
            "morph targets of the file's own", 0) + len(primitive.targets)
    used = np.unique(triangles)
    if len(used) < count:  # primitives often share one accessor: keep what this one draws
        attributes = {name: values[used] for name, values in attributes.items()}
        positions, count = positions[used], len(used)
        triangles = np.searchsorted(used, triangles)
    uvs = []
    while f"TEXCOORD_{len(uvs)}" in attributes:
        uvs.append(attributes[f"TEXCOORD_{len(uvs)}"][:, :2].astype(float))
    colors = attributes.get("COLOR_0")
    if colors is not None:
        colors = colors.astype(float)
        colors = np.column_stack([colors, np.ones(count)]) if colors.shape[1] == 3 else colors
    piece = Piece(positions, triangles, _rows(attributes.get("NORMAL"), 3),
                  _rows(attributes.get("TANGENT"), 4), uvs, colors,
                  primitive.material if isinstance(primitive.material, int) else -1,
                  attributes=attributes)
    return piece


def _rows(values, width):
    return None if values is None or values.shape[1] < width else values[:, :width].astype(float)


def _attributes(gltf: GltfFile, primitive, what: str):
    """({name: array}, indices or None) of a primitive, decoded from Draco when compressed."""
    extension = (primitive.extensions or {}).get(DRACO)
    if extension is not None:
        attributes, faces = gltf.draco(extension, what)
        return attributes, faces.reshape(-1)
    attributes = {name: gltf.accessor(index) for name, index in
                  vars(primitive.attributes).items() if isinstance(index, int)}
    counts = {len(values) for values in attributes.values()}
    if len(counts) > 1:
        raise gltf.message(f"{what}: its attributes have different counts {sorted(counts)}")
    indices = None
    if primitive.indices is not None:
        indices = gltf.accessor(primitive.indices).reshape(-1).astype(np.int64)
    return attributes, indices


def _triangles(indices: np.ndarray, mode: int) -> np.ndarray:
    if mode == TRIANGLES:
        usable = len(indices) - len(indices) % 3
        return indices[:usable].reshape(-1, 3)
    if len(indices) < 3:
        return np.zeros((0, 3), dtype=np.int64)
    i = np.arange(len(indices) - 2)
    if mode == STRIP:  # every other triangle reversed, so all keep the first one's winding
        even = i % 2 == 0
        return np.column_stack([indices[i], np.where(even, indices[i + 1], indices[i + 2]),
                                np.where(even, indices[i + 2], indices[i + 1])])
    return np.column_stack([np.full(len(i), indices[0]), indices[i + 1], indices[i + 2]])


def _default_shape(gltf, primitive, node, mesh, positions, what) -> np.ndarray:
    """The positions at the node's (else the mesh's) default morph weights."""
    weights = getattr(node, "weights", None)
    weights = weights if weights is not None else mesh.weights
    weights = list(weights or [])
    for index, target in enumerate(primitive.targets):
        weight = float(weights[index]) if index < len(weights) else 0.0
        accessor = target.get("POSITION") if isinstance(target, dict) else \
            getattr(target, "POSITION", None)
        if weight and isinstance(accessor, int):
            delta = gltf.accessor(accessor)[:, :3]
            if len(delta) != len(positions):
                raise gltf.message(f"{what}: morph target {index} has {len(delta)} positions "
                                   f"for {len(positions)} vertices")
            positions = positions + weight * delta
    return positions
