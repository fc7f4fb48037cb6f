"""Geometry shared by both pipelines: vectors and frames (unit, cross, perpendicular,
frame_from_xz), vertex welding, vertex normals, bounding-box diagonal."""

from __future__ import annotations

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components
from scipy.spatial import cKDTree

from eigendance.errors import InputError

# Largest coordinate magnitude a model may have, in any unit. Outputs hold positions as float32
# (largest value ≈ 3.4·10³⁸): this leaves 23 decades for the motion, and squares of
# coordinates (areas, lengths) stay far from overflow in float64.
MAX_COORDINATE = 1e15


def unit(vector, name: str = "vector") -> np.ndarray:
    """The vector divided by its length.

    Parameters
    ----------
    vector : (3,) (any length of vector).
    name : how the message calls it when it has zero length.

    Returns
    -------
    (3,) float64 of length 1; InputError for a zero (or non-finite) length.

    Example
    -------
    >>> unit([3.0, 0, 4]).tolist()
    [0.6, 0.0, 0.8]
    """
    vector = np.asarray(vector, dtype=float)
    norm = np.linalg.norm(vector)
    if not norm > 0:
        raise InputError(f"{name} has zero length")
    return vector / norm


def cross(a, b) -> np.ndarray:
    """a × b along the last axis, broadcast: of two 3-vectors, or of stacks of them.

    np.cross costs ~20 µs of set-up for a single pair and is slower on large stacks.

    Parameters
    ----------
    a, b : (…, 3) arrays that broadcast against each other.

    Returns
    -------
    (…, 3) float64 cross products.

    Example
    -------
    >>> cross([1.0, 0, 0], [0.0, 1, 0]).tolist()
    [0.0, 0.0, 1.0]
    """
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    a0, a1, a2 = a[..., 0], a[..., 1], a[..., 2]
    b0, b1, b2 = b[..., 0], b[..., 1], b[..., 2]
    return np.stack([a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0], axis=-1)


def perpendicular(direction) -> np.ndarray:
    """A deterministic unit vector perpendicular to the unit vector `direction`.

    Parameters
    ----------
    direction : (3,) unit vector.

    Returns
    -------
    (3,) unit vector: direction × e_a normalised, e_a the axis along which `direction` is
    smallest.
    """
    direction = np.asarray(direction, dtype=float)
    helper = np.zeros(3)
    helper[int(np.argmin(np.abs(direction)))] = 1.0
    return unit(cross(direction, helper))


def frame_from_xz(x_hint, z) -> np.ndarray:
    """A rotation with the given z axis and its x axis as close as possible to `x_hint`.

    Parameters
    ----------
    x_hint : (3,) the wanted x direction, made orthogonal to z (a deterministic perpendicular
        of z when it is parallel to z).
    z : (3,) the z axis (any length but 0).

    Returns
    -------
    (3, 3) rotation, columns x, y = z × x, z.
    """
    z = unit(z)
    x = np.asarray(x_hint, dtype=float) - np.dot(x_hint, z) * z
    norm = np.linalg.norm(x)
    x = x / norm if norm > 1e-9 * max(1.0, np.linalg.norm(x_hint)) else perpendicular(z)
    return np.column_stack([x, cross(z, x), z])


def weld(vertices: np.ndarray, tolerance: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """Merge coincident vertices, keeping the order of their first occurrence.

    Parameters
    ----------
    vertices : (n, 3) float array.
    tolerance : 0 merges exactly equal vertices; t > 0 merges vertices closer than
        t·(bounding-box diagonal), and whatever such pairs chain together (UV seams and hard
        edges that exporters split, docs/design.md#appearance).

    Returns
    -------
    first : (u,) int64, the input index of each kept vertex, ascending: kept = vertices[first].
    inverse : (n,) int64, the kept index of each input vertex: vertices ≈ kept[inverse].

    Example
    -------
    >>> first, inverse = weld(np.array([[0., 0, 0], [1, 0, 0], [0, 0, 0]]))
    >>> first.tolist(), inverse.tolist()
    ([0, 1], [0, 1, 0])
    >>> weld(np.array([[0., 0, 0], [1, 0, 0], [1e-9, 0, 0]]), 1e-7)[1].tolist()
    [0, 1, 0]
    """
    vertices = np.asarray(vertices, dtype=np.float64)
    first, inverse = unique_rows(vertices)
    if tolerance > 0 and len(first) > 1:  # exact copies first, then pairs within the distance
        unique = vertices[first]
        pairs = cKDTree(unique).query_pairs(tolerance * (bounding_box_diagonal(vertices) or 1.0),
                                            output_type="ndarray")
        if len(pairs):
            graph = coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])),
                               shape=(len(unique),) * 2)
            _, label = connected_components(graph, directed=False)
            lowest = np.full(label.max() + 1, len(vertices))
            np.minimum.at(lowest, label, first)  # each group's first input vertex
            _, first, merged = np.unique(lowest[label], return_index=True, return_inverse=True)
            first, inverse = lowest[label][first], merged.reshape(-1)[inverse]
    order = np.argsort(first)  # groups come sorted by value: put them in input order
    rank = np.empty_like(order)
    rank[order] = np.arange(len(order))
    return first[order].astype(np.int64), rank[inverse].astype(np.int64)


def unique_rows(rows: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The distinct rows of a 2-D array, as np.unique(rows, axis=0, return_index=True,
    return_inverse=True) finds them (rows in lexicographic order), several times faster on
    millions of rows: one lexsort of the columns instead of a sort of row records.

    Parameters
    ----------
    rows : (r, c) array.

    Returns
    -------
    first : (u,) int64, the index of each distinct row's first occurrence.
    inverse : (r,) int64, the distinct row of each row: rows == rows[first][inverse].

    Example
    -------
    >>> first, inverse = unique_rows(np.array([[2, 1], [0, 5], [2, 1]]))
    >>> first.tolist(), inverse.tolist()
    ([1, 0], [1, 0, 1])
    """
    rows = np.asarray(rows)
    if len(rows) == 0:
        return np.zeros(0, np.int64), np.zeros(0, np.int64)
    order = np.lexsort(rows.T[::-1])  # stable: equal rows keep their input order
    ordered = rows[order]
    starts = np.ones(len(rows), dtype=bool)
    starts[1:] = np.any(ordered[1:] != ordered[:-1], axis=1)
    inverse = np.empty(len(rows), dtype=np.int64)
    inverse[order] = np.cumsum(starts) - 1
    return order[starts].astype(np.int64), inverse


def bounding_box_diagonal(vertices: np.ndarray) -> float:
    """Length of the diagonal of the axis-aligned bounding box of (n, 3) points.

    Parameters
    ----------
    vertices : (n, 3).

    Returns
    -------
    float, in the vertices' unit.
    """
    vertices = np.asarray(vertices, dtype=np.float64)
    return float(np.linalg.norm(vertices.max(axis=0) - vertices.min(axis=0)))


def face_edges(faces: np.ndarray) -> np.ndarray:
    """The edges of the triangles as they run round each one (i→j, j→k, k→i): an edge shared
    by two triangles comes twice, once each way on a consistently oriented surface.

    Parameters
    ----------
    faces : (m, 3).

    Returns
    -------
    (3m, 2) vertex indices.

    Example
    -------
    >>> face_edges(np.array([[0, 1, 2]])).tolist()
    [[0, 1], [1, 2], [2, 0]]
    """
    return np.asarray(faces)[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2)


def face_normals(vertices: np.ndarray, faces: np.ndarray) -> np.ndarray:
    """(m, 3) normals of the triangles, of length twice their area (not unit).

    Parameters
    ----------
    vertices : (n, 3).
    faces : (m, 3).

    Returns
    -------
    (m, 3) float64.
    """
    vertices = np.asarray(vertices, dtype=np.float64)
    faces = np.asarray(faces, dtype=np.int64)
    first = vertices[faces[:, 0]]  # three gathers: faster than one (m, 3, 3) gather at 2 M faces
    return cross(vertices[faces[:, 1]] - first, vertices[faces[:, 2]] - first)


def vertex_normals(vertices: np.ndarray, faces: np.ndarray, default=None) -> np.ndarray:
    """Area-weighted unit vertex normals, as three.js computeVertexNormals.

    Parameters
    ----------
    vertices : (n, 3).
    faces : (m, 3) triangles.
    default : (3,) the normal of a vertex whose triangles' normals cancel or that no triangle
        uses (where a unit vector is needed: +z), or None for zero.

    Returns
    -------
    (n, 3) float64.

    Example
    -------
    >>> vertex_normals([[0.0, 0, 0], [1, 0, 0], [0, 1, 0], [5, 5, 5]], [[0, 1, 2]],
    ...                default=(0, 0, 1)).tolist()
    [[0.0, 0.0, 1.0], [0.0, 0.0, 1.0], [0.0, 0.0, 1.0], [0.0, 0.0, 1.0]]
    """
    vertices = np.asarray(vertices, dtype=np.float64)
    faces = np.asarray(faces, dtype=np.int64)
    weighted = face_normals(vertices, faces)
    normals = np.stack([np.bincount(faces.ravel(), np.repeat(weighted[:, axis], 3),
                                    minlength=len(vertices)) for axis in range(3)], axis=1)
    length = np.linalg.norm(normals, axis=1, keepdims=True)
    normals = normals / np.where(length > 0, length, 1)
    if default is not None:
        normals[length[:, 0] <= 0] = default
    return normals
