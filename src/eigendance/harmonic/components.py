"""L u = λ M u on an operator whose graph falls apart into components (docs/design.md#eigensolver).

When no entry of L or M joins two sets of vertices, the problem is block diagonal: each
component c has its own pairs (λ, u_c), and u_c extended by zero is a pair of the whole mesh,
M-orthogonal to every pair of another component (their supports do not meet). The k smallest
pairs of the mesh are the k smallest of the union of each component's own k smallest, so each
component is solved on its own, with at most k pairs — and a group of m components that are
copies of each other (the same blocks of L and M up to rounding: translated copies stored with
the same vertex order) is solved once for ⌈k/m⌉ pairs, its eigenvectors reused for every copy.

That is also what a solver working on the whole mesh cannot do: m identical pieces give every
eigenvalue multiplicity m (2m for a piece with a symmetric pair of its own), a single-vector
Krylov space sees one vector per eigenvalue, and spectrum slicing never closes its bands.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
from scipy.sparse.csgraph import connected_components

from eigendance.harmonic.mass import as_mass

# Blocks of two components are copies when every entry agrees within SAME_TOLERANCE times the
# largest entry of the block: the rounding of a Laplacian built from translated coordinates
# (≈ 1e-13 on a normalised mesh), far below the eigensolver's residual tolerance of 1e-7.
SAME_TOLERANCE = 1e-10


@dataclass(eq=False)
class Group:
    """Components whose blocks of L and M are copies of the first one's.

    Parameters
    ----------
    members : list of (n_c,) ascending vertex indices, one array per component (all the same
        length; the i-th vertex of each corresponds).
    stiffness : L restricted to the first member (n_c, n_c) csc.
    mass : M restricted to the first member: (n_c,) areas or (n_c, n_c) sparse.
    """

    members: list[np.ndarray]
    stiffness: sp.csc_matrix
    mass: np.ndarray | sp.csc_matrix


def groups(stiffness: sp.spmatrix, mass) -> list[Group]:
    """The connected components of the graph of L's (and a sparse M's) non-zero entries,
    grouped into copies.

    Parameters
    ----------
    stiffness : L (n, n) sparse.
    mass : (n,) areas, a sparse (n, n) SPD matrix, or a `Mass`.

    Returns
    -------
    list of Group, in the order of their first vertex; one group of one member when the graph
    is connected.

    Example
    -------
    >>> L = sp.csc_matrix(np.kron(np.eye(3), [[1.0, -1.0], [-1.0, 1.0]]))
    >>> [len(group.members) for group in groups(L, np.ones(6))]
    [3]
    """
    mass = as_mass(mass)
    graph = sp.csr_matrix(abs(stiffness) + abs(mass.sparse()))
    graph.eliminate_zeros()
    count, labels = connected_components(graph, directed=False)
    if count == 1:
        whole = mass.diagonal if mass.diagonal is not None else mass.matrix
        return [Group([np.arange(mass.n)], sp.csc_matrix(stiffness), whole)]
    # Permuted so that each component is one diagonal block, its vertices ascending.
    order = np.argsort(labels, kind="stable")
    ends = np.cumsum(np.bincount(labels, minlength=count))
    starts = ends - np.bincount(labels, minlength=count)
    stiffness = sp.csr_matrix(stiffness)[order][:, order]
    areas = (mass.diagonal[order] if mass.diagonal is not None
             else sp.csr_matrix(mass.matrix)[order][:, order])
    found: dict[tuple, list[Group]] = {}
    result = []
    for label in np.argsort(order[starts], kind="stable"):  # by first vertex
        block = _block(stiffness, starts[label], ends[label])
        weights = _block(areas, starts[label], ends[label])
        key = (block.shape[0], block.nnz, hash(block.indptr.tobytes()),
               hash(block.indices.tobytes()))
        twin = next((group for group in found.get(key, []) if _same(group, block, weights)),
                    None)
        if twin is None:
            twin = Group([], block, weights)
            found.setdefault(key, []).append(twin)
            result.append(twin)
        twin.members.append(order[starts[label]:ends[label]])
    return result


def _block(matrix, start: int, end: int):
    """Rows and columns start:end of a CSR matrix (as csc, sorted indices) or of a vector."""
    if not sp.issparse(matrix):
        return matrix[start:end]
    block = sp.csc_matrix(matrix[start:end, start:end])
    block.sort_indices()
    return block


def _same(group: Group, block: sp.csc_matrix, areas) -> bool:
    """Whether `block` and `areas` equal the group's blocks within SAME_TOLERANCE (same pattern)."""
    def close(a, b):
        scale = max(float(np.abs(a).max(initial=0)), 1e-300)
        return np.allclose(a, b, rtol=0, atol=SAME_TOLERANCE * scale)

    if not (np.array_equal(group.stiffness.indptr, block.indptr)
            and np.array_equal(group.stiffness.indices, block.indices)
            and close(group.stiffness.data, block.data)):
        return False
    if sp.issparse(areas):
        return (np.array_equal(group.mass.indptr, areas.indptr)
                and np.array_equal(group.mass.indices, areas.indices)
                and close(group.mass.data, areas.data))
    return close(group.mass, areas)


def solve_components(stiffness: sp.spmatrix, mass, k: int,
                     solve_one: Callable, progress=None) -> tuple[np.ndarray, np.ndarray]:
    """The k smallest pairs of L u = λ M u, solving each group of identical components once.

    A group of m copies of an n_c-vertex component needs min(n_c, ⌈k/m⌉) pairs: its j-th
    eigenvalue appears m times, so only j < k/m can be among the k smallest. The pairs of all
    groups are merged by eigenvalue (stable: ties in the order of the groups, then of their
    members).

    Parameters
    ----------
    stiffness : L (n, n) sparse, symmetric positive semi-definite.
    mass : (n,) areas, a sparse (n, n) SPD matrix, or a `Mass`.
    k : pairs, 1 ≤ k < n.
    solve_one : callable(L_c, M_c, k_c, progress) → (eigenvalues (k_c,) ascending, eigenvectors
        (n_c, k_c) M_c-orthonormal), k_c ≤ n_c: the solver of one component (called once, on
        the whole operator, when the graph is connected).
    progress : optional callable(done), told about how many of the k pairs are solved.

    Returns
    -------
    (eigenvalues (k,) ascending, eigenvectors (n, k) with Uᵀ M U = I); the eigenvectors of a
    component are zero outside it.
    """
    mass = as_mass(mass)
    found = groups(stiffness, mass)
    if len(found) == 1 and len(found[0].members) == 1:
        return solve_one(stiffness, mass, k, progress)
    wanted = [min(len(group.members[0]), -(-k // len(group.members))) for group in found]
    work = np.array([len(group.members[0]) * count for group, count in zip(found, wanted,
                                                                            strict=True)])
    start = np.concatenate([[0], np.cumsum(work)]) / work.sum() * k
    solved = []
    for index, (group, count) in enumerate(zip(found, wanted, strict=True)):
        share = (start[index + 1] - start[index]) / count
        report = None if progress is None else (
            lambda done, index=index, share=share: progress(int(start[index] + done * share)))
        solved.append(solve_one(group.stiffness, group.mass, count, report))
    return _merge(found, solved, k, mass)


def _merge(found: list[Group], solved: list[tuple], k: int, mass):
    """The k smallest of every member's pairs, as (eigenvalues (k,), eigenvectors (n, k))."""
    values, owners = [], []
    for number, (group, (eigenvalues, _)) in enumerate(zip(found, solved, strict=True)):
        for member in range(len(group.members)):
            values.append(eigenvalues)
            owners.append(np.column_stack([np.full(len(eigenvalues), number),
                                           np.full(len(eigenvalues), member),
                                           np.arange(len(eigenvalues))]))
    values, owners = np.concatenate(values), np.concatenate(owners)
    chosen = np.argsort(values, kind="stable")[:k]
    rows = np.zeros((k, mass.n))  # each eigenvector contiguous, as the band solver returns
    for row, (number, member, pair) in enumerate(owners[chosen]):
        rows[row, found[number].members[member]] = solved[number][1][:, pair]
    # A copy's mass differs from its group's by rounding: normalise in the mesh's own M.
    rows /= np.sqrt(mass.norms(rows.T))[:, None]
    return values[chosen], rows.T
