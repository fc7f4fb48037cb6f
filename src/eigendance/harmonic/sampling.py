"""Samples of a large mesh for its reduced harmonic basis (docs/design.md#reduced-basis).

The samples are spread evenly over the surface by a voxel grid: one sample per occupied cell,
the vertex nearest the cell's centroid, with the cell size chosen so that about the requested
number of cells is occupied. Cells are kept apart per connected component of the Laplacian's
graph, so every part (and every part the operator couples, docs/design.md#laplacian) has a
sample of its own, and split into the pieces of surface connected inside them, so two sheets
that pass through one cell (a fold, a lip) have a sample each. Each vertex then belongs to its
nearest sample along the graph's edges (multi-source Dijkstra): those clusters give the
neighbourhoods the interpolation weights use (`eigendance.harmonic.interpolation`).
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
                   area: float, graph: sp.csr_matrix | None = None) -> tuple[np.ndarray, float]:
    """About `count` vertices spread evenly over the surface, at least one per component.

    Parameters
    ----------
    vertices : (n, 3) positions.
    components : (n,) connected component of each vertex.
    count : the number of samples wanted (more if there are more components).
    area : the surface's area (sets the first cell size).
    graph : the operator's graph (`operator_graph`): when given, a cell that two sheets of the
        surface cross (a fold, a lip) gives each its sample (`cell_pieces`).

    Returns
    -------
    samples : (m,) ascending vertex indices, one per occupied cell.
    cell : the cell size, in the units of `vertices`.
    """
    lower = vertices.min(axis=0)
    cell = float(np.sqrt(area / (1.7 * count)))  # an occupied cell holds ≈ 1.7 cell² of area
    for _ in range(ATTEMPTS):
        cells = _cell_keys(vertices, lower, cell, components)
        inverse = np.unique(cells, return_inverse=True)[1].reshape(-1)
        if graph is not None:
            inverse = cell_pieces(inverse, graph)
        occupied = int(inverse.max()) + 1
        if abs(occupied - count) <= COUNT_TOLERANCE * count:
            break
        cell *= float(np.sqrt(occupied / count))
    totals = np.bincount(inverse).astype(np.float64)
    centroids = np.column_stack([np.bincount(inverse, vertices[:, axis]) for axis in range(3)])
    centroids /= totals[:, None]
    distance = np.linalg.norm(vertices - centroids[inverse], axis=1)
    order = np.lexsort((distance, inverse))
    firsts = np.flatnonzero(np.diff(inverse[order], prepend=-1))
    return np.sort(order[firsts]), cell


def cell_pieces(cells: np.ndarray, graph: sp.csr_matrix) -> np.ndarray:
    """Cells split into their pieces: the parts of a cell's vertices connected by edges inside it.

    Two sheets of one surface that pass through a cell (a fold, a lip, both sides of a thin
    part) would otherwise share one sample, and span P could not tell them apart. A piece with
    fewer than a quarter of the median cell's vertices (a corner the surface grazes) stays with
    the largest piece of its cell.

    Parameters
    ----------
    cells : (n,) each vertex's cell, 0 … C − 1.
    graph : (n, n) the operator's graph (`operator_graph`).

    Returns
    -------
    (n,) each vertex's piece, 0 … P − 1 (P ≥ C).

    Example
    -------
    >>> path = sp.csr_matrix(np.eye(4, k=1) + np.eye(4, k=-1))   # 0 - 1 - 2 - 3
    >>> cell_pieces(np.array([0, 1, 1, 0]), path).tolist()       # cell 0 holds 0 and 3, apart
    [0, 1, 1, 2]
    """
    edges = sp.coo_matrix(graph)
    inside = cells[edges.row] == cells[edges.col]
    within = sp.csr_matrix((np.ones(int(inside.sum())), (edges.row[inside], edges.col[inside])),
                           shape=graph.shape)
    pieces = connected_components(within, directed=False)[1]
    size = np.bincount(pieces)
    order = np.lexsort((-size[pieces], cells))  # by cell, the largest piece first
    firsts = order[np.flatnonzero(np.diff(cells[order], prepend=-1))]
    largest = np.empty(int(cells.max()) + 1, dtype=np.int64)
    largest[cells[firsts]] = pieces[firsts]
    kept = size[pieces] >= 0.25 * float(np.median(np.bincount(cells)))
    return np.unique(np.where(kept, pieces, largest[cells]), return_inverse=True)[1].reshape(-1)


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
