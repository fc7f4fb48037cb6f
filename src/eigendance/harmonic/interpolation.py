"""Sparse interpolation from samples to every vertex (docs/design.md#reduced-basis).

A function given at m samples is carried to the n vertices by P (n × m): vertex i's value is
Σ_j w_ij · value[index_ij] over at most `MOST` = 8 samples, with w_ij ≥ 0 and Σ_j w_ij = 1 —
the shape of linear blend skinning with translation-only joints, so the browser and glTF play
it as they play a skin.

The weights are local maximum-entropy coordinates (Arroyo & Ortiz 2006): among the samples
near vertex x (its cluster's sample and the samples of the clusters two steps away in the
sample graph, the 8 nearest kept), w_j ∝ exp(−β|s_j − x|² + λ·(s_j − x)), with λ found by
Newton's method so that Σ_j w_j (s_j − x) has no tangential part: the weights reproduce the
vertex's position in its tangent plane (linear precision, where x lies among its samples), so
P carries smooth functions with an error of second order in the sample spacing h; β = γ/h²
sets how far a weight reaches (γ = `LOCALITY`). The weights are then rounded to multiples of
2⁻¹¹ that still sum to exactly 1: exact in float16 (the page) and float32 (glTF), so every
consumer uses the very same P.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import scipy.sparse as sp

MOST = 8  # samples per vertex: two sets of four glTF joints; eight gathers in the shader
QUANTUM = 2.0**-11  # weights are multiples of this (exact in float16)
LOCALITY = 2.0  # γ: β = γ / h², the weight of a sample one spacing away is ≈ e^-γ at λ = 0
NEWTON_STEPS = 6  # Newton converges in 3–4 steps (benchmarks/bench_reduced.py)
CHUNK = 1 << 16  # vertices per block of the weight computation (bounds its memory)


@dataclass
class Interpolation:
    """P (n × m) as at most MOST (index, weight) pairs per vertex.

    Parameters
    ----------
    indices : (n, MOST) int32 sample slots in 0 … m − 1 (a slot repeats where a vertex has
        fewer samples; its weight there is 0).
    weights : (n, MOST) float64, ≥ 0, multiples of QUANTUM, each row summing to exactly 1.
    count : m, the number of samples.

    Example
    -------
    >>> P = Interpolation(np.array([[0, 1], [1, 1]], np.int32), np.array([[0.5, 0.5], [1, 0]]), 2)
    >>> P.lift(np.array([[2.0], [4.0]])).ravel().tolist()
    [3.0, 4.0]
    """

    indices: np.ndarray
    weights: np.ndarray
    count: int
    _matrix: sp.csr_matrix | None = field(default=None, repr=False, compare=False)  # P, built once

    @property
    def n(self) -> int:
        """Vertices n."""
        return len(self.indices)

    def matrix(self) -> sp.csr_matrix:
        """P as a sparse matrix (repeated slots summed), built once.

        Returns
        -------
        (n, m) CSR.
        """
        if self._matrix is None:
            n, most = self.indices.shape
            matrix = sp.csr_matrix((self.weights.astype(np.float64).reshape(-1),  # copies:
                                    self.indices.astype(np.int64).reshape(-1),  # P is sorted
                                    np.arange(0, n * most + 1, most)), shape=(n, self.count))
            matrix.sum_duplicates()
            matrix.eliminate_zeros()
            self._matrix = matrix
        return self._matrix

    def lift(self, coarse: np.ndarray) -> np.ndarray:
        """P · coarse.

        Parameters
        ----------
        coarse : (m,) or (m, c) values at the samples.

        Returns
        -------
        (n,) or (n, c) values at the vertices.
        """
        return self.matrix() @ coarse

    def check(self) -> str | None:
        """What is wrong with these arrays as an interpolation.

        Returns
        -------
        str, or None when they are one.
        """
        if self.indices.ndim != 2 or self.weights.shape != self.indices.shape or \
                self.indices.shape[1] > MOST:
            return f"weights and indices must both be (n, ≤ {MOST})"
        if not np.issubdtype(self.indices.dtype, np.integer) or \
                (self.indices.size and (self.indices.min() < 0 or
                                        self.indices.max() >= self.count)):
            return f"sample indices must be integers in 0 … {self.count - 1}"
        if not (np.isfinite(self.weights).all() and (self.weights >= 0).all()):
            return "weights must be finite and non-negative"
        if not np.all(np.abs(self.weights.sum(axis=1) - 1) <= 1e-12):
            return "each vertex's weights must sum to 1"
        return None


def maxent_interpolation(graph: sp.csr_matrix, vertices: np.ndarray, normals: np.ndarray,
                         samples: np.ndarray, slot: np.ndarray, spacing: float,
                         locality: float = LOCALITY) -> Interpolation:
    """Local maximum-entropy weights of every vertex on its nearest samples (module docstring).

    Parameters
    ----------
    graph : the (n, n) operator graph (`sampling.operator_graph`).
    vertices, normals : (n, 3) positions and unit normals (zero where undefined).
    samples : (m,) vertex index of each sample.
    slot : (n,) each vertex's nearest sample (`sampling.nearest_samples`).
    spacing : h, the distance between neighbouring samples, in the units of `vertices`.
    locality : γ of β = γ/h².

    Returns
    -------
    Interpolation with at most MOST weights per vertex.
    """
    candidates = _sample_neighbourhoods(graph, slot, len(samples))
    n = len(vertices)
    indices = np.empty((n, MOST), dtype=np.int32)
    weights = np.empty((n, MOST))
    beta = locality / spacing**2
    for start in range(0, n, CHUNK):
        rows = slice(start, min(n, start + CHUNK))
        chosen, offsets, squared = _nearest_candidates(candidates[slot[rows]], vertices[rows],
                                                       vertices[samples])
        found = _maxent(offsets, squared, normals[rows], beta, spacing)
        indices[rows], weights[rows] = chosen, quantised(found)
    return Interpolation(indices, weights, len(samples))


def _sample_neighbourhoods(graph, slot, count: int) -> np.ndarray:
    """(m, w) for each sample the samples within two steps of the sample graph (itself
    included), padded with −1; samples are neighbours when a graph edge joins their clusters."""
    coo = graph.tocoo()
    a, b = slot[coo.row], slot[coo.col]
    apart = a != b
    adjacency = sp.csr_matrix((np.ones(int(apart.sum())), (a[apart], b[apart])), (count, count))
    adjacency = (adjacency + sp.identity(count, format="csr")).astype(bool).astype(np.float32)
    reach = (adjacency @ adjacency).tocsr()
    degree = np.diff(reach.indptr)
    table = np.full((count, int(degree.max())), -1, dtype=np.int64)
    position = np.arange(reach.nnz) - np.repeat(reach.indptr[:-1], degree)
    table[np.repeat(np.arange(count), degree), position] = reach.indices
    return table


def _nearest_candidates(candidates, points, sample_positions):
    """The MOST nearest of each point's candidates: (slots (c, MOST), offsets s − x
    (c, MOST, 3), squared distances (c, MOST), +inf where a point has fewer candidates)."""
    valid = candidates >= 0
    offsets = sample_positions[np.maximum(candidates, 0)] - points[:, None, :]
    squared = np.einsum("ijk,ijk->ij", offsets, offsets)
    squared[~valid] = np.inf
    if candidates.shape[1] > MOST:
        keep = np.argpartition(squared, MOST - 1, axis=1)[:, :MOST]
    else:
        keep = np.broadcast_to(np.arange(candidates.shape[1]), candidates.shape)
    chosen = np.take_along_axis(candidates, keep, axis=1)
    offsets = np.take_along_axis(offsets, keep[:, :, None], axis=1)
    squared = np.take_along_axis(squared, keep, axis=1)
    if chosen.shape[1] < MOST:  # fewer candidates than MOST anywhere: pad with +inf
        pad = MOST - chosen.shape[1]
        chosen = np.pad(chosen, ((0, 0), (0, pad)), constant_values=-1)
        offsets = np.pad(offsets, ((0, 0), (0, pad), (0, 0)))
        squared = np.pad(squared, ((0, 0), (0, pad)), constant_values=np.inf)
    missing = ~np.isfinite(squared)
    chosen = np.where(missing, chosen[:, :1], chosen)  # the nearest is always a candidate
    return chosen.astype(np.int32), offsets, squared


def _maxent(offsets, squared, normals, beta: float, spacing: float) -> np.ndarray:
    """Weights (c, MOST) ∝ exp(−β|d|² + λ·d), λ such that Σ w d is normal to the surface.

    The offsets are written in a tangent frame (two coordinates), where λ's Newton step is a
    2 × 2 solve in closed form.
    """
    present = np.isfinite(squared)
    first, second = _tangent_frame(normals)
    x = np.einsum("ijk,ik->ij", offsets, first)
    y = np.einsum("ijk,ik->ij", offsets, second)
    prior = np.where(present, -beta * np.where(present, squared, 0.0), -np.inf)
    lam_x = np.zeros((len(offsets), 1))
    lam_y = np.zeros((len(offsets), 1))
    for _ in range(NEWTON_STEPS):
        w = _softmax(prior + lam_x * x + lam_y * y)
        mean_x, mean_y = (w * x).sum(axis=1, keepdims=True), (w * y).sum(axis=1, keepdims=True)
        xx = (w * x * x).sum(axis=1, keepdims=True) - mean_x * mean_x
        xy = (w * x * y).sum(axis=1, keepdims=True) - mean_x * mean_y
        yy = (w * y * y).sum(axis=1, keepdims=True) - mean_y * mean_y
        determinant = xx * yy - xy * xy
        usable = determinant > 1e-12 * (xx + yy) ** 2 + 1e-300  # else the samples are in a line
        determinant = np.where(usable, determinant, 1.0)
        step_x = np.where(usable, -(yy * mean_x - xy * mean_y) / determinant, 0.0)
        step_y = np.where(usable, -(xx * mean_y - xy * mean_x) / determinant, 0.0)
        # A vertex outside its samples' hull (a boundary) has no solution: λ grows slowly.
        size = np.hypot(step_x, step_y) * spacing
        damping = np.minimum(1.0, 4.0 / np.maximum(size, 1e-300))
        lam_x += step_x * damping
        lam_y += step_y * damping
    return _softmax(prior + lam_x * x + lam_y * y)


def _tangent_frame(normals: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Two unit vectors perpendicular to each normal (the x and y axes where it is zero)."""
    helper = np.where(np.abs(normals[:, :1]) < 0.9, [[1.0, 0.0, 0.0]], [[0.0, 1.0, 0.0]])
    first = np.cross(normals, helper)
    length = np.linalg.norm(first, axis=1, keepdims=True)
    undefined = length[:, 0] < 1e-12
    first = np.where(undefined[:, None], [[1.0, 0.0, 0.0]], first / np.maximum(length, 1e-300))
    second = np.where(undefined[:, None], [[0.0, 1.0, 0.0]], np.cross(normals, first))
    return first, second


def _softmax(energy: np.ndarray) -> np.ndarray:
    top = energy.max(axis=1, keepdims=True)
    weights = np.exp(energy - top)
    return weights / weights.sum(axis=1, keepdims=True)


def quantised(weights: np.ndarray) -> np.ndarray:
    """Rows of non-negative weights summing to 1, rounded to multiples of QUANTUM that still
    sum to exactly 1 (largest remainders round up).

    Parameters
    ----------
    weights : (r, c) rows of non-negative weights summing to 1.

    Returns
    -------
    (r, c) float64 multiples of QUANTUM, each row summing to exactly 1.

    Example
    -------
    >>> float(quantised(np.array([[1 / 3, 1 / 3, 1 / 3]])).sum())
    1.0
    """
    return shares(weights, round(1 / QUANTUM)) * QUANTUM


def shares(weights: np.ndarray, units: int) -> np.ndarray:
    """Rows of non-negative weights summing to 1 as whole numbers of 1/units that sum to
    exactly `units` (the largest-remainder method: every weight·units rounded down, then the
    rows' largest remainders up), so each differs from weight·units by less than 1.

    Parameters
    ----------
    weights : (r, c) rows of non-negative weights summing to 1.
    units : the whole each row is shared out of (2¹¹ for P, 65535 for glTF's normalised
        unsigned shorts).

    Returns
    -------
    (r, c) int64, each row summing to `units`.

    Example
    -------
    >>> shares(np.array([[0.5, 0.25, 0.25]]), 65535).tolist()
    [[32767, 16384, 16384]]
    """
    scaled = weights * units
    floor = np.floor(scaled)
    deficit = (units - floor.sum(axis=1)).round().astype(np.int64)
    order = np.argsort(floor - scaled, axis=1, kind="stable")  # largest remainder first
    bump = np.arange(weights.shape[1])[None, :] < deficit[:, None]
    np.put_along_axis(floor, order, np.take_along_axis(floor, order, axis=1) + bump, axis=1)
    return floor.astype(np.int64)
