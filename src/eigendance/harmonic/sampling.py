"""Samples of a large mesh for its reduced harmonic basis (docs/design.md#reduced-basis).

The samples are spread evenly over the surface by a voxel grid: one sample per occupied cell,
the vertex nearest the cell's centroid, with the cell size chosen so that about the requested
number of cells is occupied. Cells are kept apart per connected component of the Laplacian's
graph, so every part (and every part the operator couples, docs/design.md#laplacian) has a
sample of its own. Each vertex then belongs to its nearest sample along the graph's edges
(multi-source Dijkstra): those clusters give the neighbourhoods the interpolation weights use
(`eigendance.harmonic.interpolation`).
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp
from scipy.sparse.csgraph import connected_components, dijkstra

from eigendance.errors import InternalError

# Cell size is adjusted until the occupied cells are within this share of the requested count.
COUNT_TOLERANCE = 0.05
ATTEMPTS = 8


def operator_graph(stiffness, vertices: np.ndarray) -> sp.csr_matrix:
    """The graph of L's off-diagonal non-zeros (mesh edges, and any coupling the operator
    adds), each edge weighted by its Euclidean length.

    Parameters
    ----------
    stiffness : L (n, n) sparse.
    vertices : (n, 3) positions.

    Returns
    -------
    (n, n) symmetric CSR of edge lengths.

    Example
    -------
    >>> L = sp.csr_matrix([[1.0, -1.0, 0], [-1.0, 2.0, -1.0], [0, -1.0, 1.0]])
    >>> operator_graph(L, np.array([[0.0, 0, 0], [3, 0, 0], [3, 4, 0]])).toarray().tolist()
    [[0.0, 3.0, 0.0], [3.0, 0.0, 4.0], [0.0, 4.0, 0.0]]
    """
    structure = sp.csr_matrix(stiffness)
    n = structure.shape[0]
    rows = np.repeat(np.arange(n), np.diff(structure.indptr))
    columns = structure.indices
    off = rows != columns
    rows, columns = rows[off], columns[off]
    lengths = np.linalg.norm(vertices[rows] - vertices[columns], axis=1)
    # Coincident vertices joined by an edge still count as joined (a zero would drop the edge).
    lengths = np.maximum(lengths, 1e-12 * max(float(lengths.max(initial=0.0)), 1e-300))
    graph = sp.csr_matrix((lengths, (rows, columns)), shape=(n, n))
    return graph.maximum(graph.T).tocsr()


def component_labels(graph: sp.csr_matrix) -> np.ndarray:
    """The connected component of each vertex.

    Parameters
    ----------
    graph : (n, n) sparse.

    Returns
    -------
    (n,) int labels.
    """
    return connected_components(graph, directed=False)[1]


def spread_samples(vertices: np.ndarray, components: np.ndarray, count: int,
                   area: float) -> tuple[np.ndarray, float]:
    """About `count` vertices spread evenly over the surface, at least one per component.

    Parameters
    ----------
    vertices : (n, 3) positions.
    components : (n,) connected component of each vertex.
    count : the number of samples wanted (more if there are more components).
    area : the surface's area (sets the first cell size).

    Returns
    -------
    samples : (m,) ascending vertex indices, one per occupied cell.
    cell : the cell size, in the units of `vertices`.
    """
    lower = vertices.min(axis=0)
    cell = float(np.sqrt(area / (1.7 * count)))  # an occupied cell holds ≈ 1.7 cell² of area
    for _ in range(ATTEMPTS):
        cells = _cell_keys(vertices, lower, cell, components)
        occupied, inverse = np.unique(cells, return_inverse=True)
        if abs(len(occupied) - count) <= COUNT_TOLERANCE * count:
            break
        cell *= float(np.sqrt(len(occupied) / count))
    inverse = inverse.reshape(-1)
    totals = np.bincount(inverse).astype(np.float64)
    centroids = np.column_stack([np.bincount(inverse, vertices[:, axis]) for axis in range(3)])
    centroids /= totals[:, None]
    distance = np.linalg.norm(vertices - centroids[inverse], axis=1)
    order = np.lexsort((distance, inverse))
    firsts = np.flatnonzero(np.diff(inverse[order], prepend=-1))
    return np.sort(order[firsts]), cell


def _cell_keys(vertices, lower, cell, components):
    """One int64 per (component, voxel) pair."""
    cells = np.floor((vertices - lower) / cell).astype(np.int64)
    sizes = cells.max(axis=0) + 1
    if float(np.prod(sizes, dtype=np.float64)) * (float(components.max()) + 1) < 2.0**62:
        return ((components.astype(np.int64) * sizes[0] + cells[:, 0]) * sizes[1]
                + cells[:, 1]) * sizes[2] + cells[:, 2]
    # a huge grid with many components: rows instead of one number (slower, same result)
    rows = np.column_stack([components, cells])
    return np.unique(rows, axis=0, return_inverse=True)[1].reshape(-1)


def nearest_samples(graph: sp.csr_matrix, samples: np.ndarray) -> np.ndarray:
    """Each vertex's nearest sample along the graph (multi-source Dijkstra).

    Every vertex must share a component with a sample (`spread_samples` makes sure of it).

    Parameters
    ----------
    graph : (n, n) edge lengths (`operator_graph`).
    samples : (m,) vertex indices.

    Returns
    -------
    (n,) int64, the slot (index into `samples`) of each vertex's nearest sample.
    """
    _, _, sources = dijkstra(graph, directed=False, indices=samples, min_only=True,
                             return_predecessors=True)
    if np.any(sources < 0):
        raise InternalError("reduced basis: a vertex is not connected to any sample")
    slot = np.full(graph.shape[0], -1, dtype=np.int64)
    slot[samples] = np.arange(len(samples))
    return slot[sources]
