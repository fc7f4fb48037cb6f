"""Geometry shared by both pipelines: vertex welding, vertex normals, bounding-box diagonal."""

from __future__ import annotations

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components
from scipy.spatial import cKDTree

# Largest coordinate magnitude a model may have, in any unit. Outputs hold positions as float32
# (largest value ≈ 3.4·10³⁸): this leaves 23 decades for the motion, and squares of
# coordinates (areas, lengths) stay far from overflow in float64.
MAX_COORDINATE = 1e15


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
    """Length of the diagonal of the axis-aligned bounding box of (n, 3) points."""
    vertices = np.asarray(vertices, dtype=np.float64)
    return float(np.linalg.norm(vertices.max(axis=0) - vertices.min(axis=0)))


def face_normals(vertices: np.ndarray, faces: np.ndarray) -> np.ndarray:
    """(m, 3) normals of the triangles, of length twice their area (not unit)."""
    vertices = np.asarray(vertices, dtype=np.float64)
    faces = np.asarray(faces, dtype=np.int64)
    first = vertices[faces[:, 0]]
    b, c = vertices[faces[:, 1]] - first, vertices[faces[:, 2]] - first
    # the cross product by components: np.cross on millions of rows is 3× slower
    return np.column_stack([b[:, 1] * c[:, 2] - b[:, 2] * c[:, 1],
                            b[:, 2] * c[:, 0] - b[:, 0] * c[:, 2],
                            b[:, 0] * c[:, 1] - b[:, 1] * c[:, 0]])


def vertex_normals(vertices: np.ndarray, faces: np.ndarray) -> np.ndarray:
    """Area-weighted unit vertex normals (n, 3); zero for unreferenced vertices."""
    vertices = np.asarray(vertices, dtype=np.float64)
    faces = np.asarray(faces, dtype=np.int64)
    weighted = face_normals(vertices, faces)
    normals = np.stack([np.bincount(faces.ravel(), np.repeat(weighted[:, axis], 3),
                                    minlength=len(vertices)) for axis in range(3)], axis=1)
    length = np.linalg.norm(normals, axis=1, keepdims=True)
    return normals / np.where(length > 0, length, 1)
