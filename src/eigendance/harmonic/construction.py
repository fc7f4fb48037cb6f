"""How a harmonic basis is computed (docs/design.md#reduced-basis, docs/design.md#cache).

Which construction (`choose_construction`: exact when the solve fits the time and memory
rule, else reduced), the solve planned against the memory available, its eigenpairs fetched
from or stored in the disk cache (`basis_key` names an entry, `eigenpairs_fit` and
`reduced.reduced_pairs_fit` check one before it is used). `HarmonicBasis.from_mesh` builds
the basis from what these return.
"""

from __future__ import annotations

import hashlib
import time

import numpy as np

from eigendance.errors import InputError
from eigendance.harmonic.cache import DiskCache
from eigendance.harmonic.eigensolver import SOLVER_VERSION, residuals, solve
from eigendance.harmonic.laplacian import laplacian as build_laplacian
from eigendance.harmonic.mesh import Mesh
from eigendance.harmonic.reduced import (
    CACHE_TOLERANCE,
    ReducedHarmonics,
    reduced_arrays,
    reduced_from_arrays,
    reduced_harmonics,
    reduced_key,
    reduced_pairs_fit,
    sample_count,
    solve_bytes,
)
from eigendance.limits import check_memory, memory_budget

# Bytes a solve of k harmonics on n vertices holds at its peak, per eigenvector value: the
# eigenvectors, the solver's band blocks and their copies while stitching. Measured peaks: 18
# (armadillo, k = 2376) to 21 (bunny, k = 1070); README's performance table.
SOLVE_BYTES_PER_VALUE = 24
CONSTRUCTIONS = ("auto", "exact", "reduced")
# The exact solve is chosen by "auto" up to this many values n·k: its time grows as n·k
# (≈ 0.5 µs per value on this 2-core machine when it is quiet: bunny k = 300, 1.0·10⁷ values,
# 5.3 s; the armadillo ×4, 5.2·10⁷ values, 55–132 s on the shared host under a load of 4–11),
# so 6·10⁷ (200k vertices at k = 300) keeps it near half a minute on a quiet machine; the
# reduced basis of 1.15 M vertices at k = 300 takes 39 s (benchmarks/bench_reduced.py;
# docs/design.md#reduced-basis).
EXACT_VALUES = 6e7


def choose_construction(n: int, k: int, samples: int | None = None) -> str:
    """Which basis `from_mesh` makes by default (docs/design.md#reduced-basis).

    Parameters
    ----------
    n : vertices.
    k : harmonics.
    samples : the samples a reduced basis would have (default `reduced.sample_count`).

    Returns
    -------
    "exact" when the exact solve fits the time rule (n·k ≤ EXACT_VALUES) and the memory
    available now (or the mesh has too few vertices to reduce), else "reduced".
    """
    if (sample_count(n, k) if samples is None else samples) >= n:  # too few vertices to reduce
        return "exact"
    fits = SOLVE_BYTES_PER_VALUE * n * k <= memory_budget()
    return "exact" if fits and n * k <= EXACT_VALUES else "reduced"


class _Operators:
    """L and M of a mesh, assembled once and only when asked (a cache hit's check, a solve)."""

    def __init__(self, mesh: Mesh, laplacian: str):
        self.mesh, self.laplacian, self.pair = mesh, laplacian, None

    def __call__(self):
        if self.pair is None:
            self.pair = build_laplacian(self.mesh.vertices, self.mesh.faces, self.laplacian)
        return self.pair


def exact_pairs(mesh: Mesh, k: int, laplacian: str, solver: str, cache: bool,
                progress) -> tuple[np.ndarray, np.ndarray, np.ndarray, float]:
    """The first k eigenpairs of L u = λ M u on every vertex, planned against the memory
    available and through the disk cache.

    Parameters
    ----------
    mesh : the normalised mesh.
    k : harmonics.
    laplacian : "cotan" or "robust".
    solver : "bands" or "eigsh".
    cache : read and write the disk cache.
    progress : optional callable(done) told how many eigenpairs are accepted so far.

    Returns
    -------
    (eigenvalues (k,), eigenvectors (n, k) with Uᵀ M U = I, mass (n,), seconds the solve took:
    0 from the cache).
    """
    per_harmonic = SOLVE_BYTES_PER_VALUE * mesh.n
    fits = int(memory_budget() // per_harmonic)
    check_memory(per_harmonic * k, f"{mesh.name}: {k} harmonics of {mesh.n} vertices",
                 remedy={"k": fits} if 1 <= fits < k else None)
    operators, timing = _Operators(mesh, laplacian), {"seconds": 0.0}

    def solved() -> dict[str, np.ndarray]:
        stiffness, mass = operators()
        start = time.perf_counter()
        eigenvalues, eigenvectors = solve(stiffness, mass, k, solver, progress)
        timing["seconds"] = time.perf_counter() - start
        return {"eigenvalues": eigenvalues, "eigenvectors": eigenvectors, "mass": mass}

    if cache:
        arrays = basis_cache().get(basis_key(mesh, k, laplacian, solver), solved,
                                   lambda found: eigenpairs_fit(*operators(), k, found))
    else:
        arrays = solved()
    return arrays["eigenvalues"], arrays["eigenvectors"], arrays["mass"], timing["seconds"]


def reduced_pairs(mesh: Mesh, k: int, laplacian: str, samples: int | None, cache: bool,
                  progress) -> tuple[np.ndarray, np.ndarray, ReducedHarmonics, float]:
    """The first k eigenpairs of the reduced problem on `count` samples
    (docs/design.md#reduced-basis), planned against the memory available and through the disk
    cache.

    Parameters
    ----------
    mesh : the normalised mesh.
    k : harmonics.
    laplacian : "cotan" or "robust".
    samples : samples m (k < m ≤ n; default `reduced.sample_count`).
    cache : read and write the disk cache.
    progress : optional callable(done).

    Returns
    -------
    (eigenvalues (k,), mass (n,), ReducedHarmonics, seconds the solve took: 0 from the cache).
    """
    count = sample_count(mesh.n, k) if samples is None else int(samples)
    if not k < count <= mesh.n:
        raise InputError(f"{mesh.name}: a reduced basis of k = {k} harmonics needs more than k "
                         f"samples and at most one per vertex ({mesh.n}); asked for {count}",
                         remedy={"samples": 4 * k} if 4 * k <= mesh.n else {"exact": True})
    check_memory(solve_bytes(mesh.n, len(mesh.faces), k, count, laplacian),
                 f"{mesh.name}: a reduced basis of {k} harmonics of {mesh.n} vertices")
    operators, timing = _Operators(mesh, laplacian), {"seconds": 0.0}

    def solved() -> dict[str, np.ndarray]:
        stiffness, mass = operators()
        start = time.perf_counter()
        eigenvalues, reduced = reduced_harmonics(stiffness, mass, mesh.vertices, mesh.faces,
                                                 k, count, progress)
        timing["seconds"] = time.perf_counter() - start
        return {"eigenvalues": eigenvalues, "mass": mass, **reduced_arrays(reduced)}

    if cache:
        key = reduced_key(basis_key(mesh, k, laplacian, "bands"), count)
        arrays = basis_cache().get(key, solved, lambda found: reduced_pairs_fit(
            *operators(), k, found))
    else:
        arrays = solved()
    return arrays["eigenvalues"], arrays["mass"], reduced_from_arrays(arrays), timing["seconds"]


def eigenpairs_fit(stiffness, mass: np.ndarray, k: int, arrays: dict) -> bool:
    """Whether stored arrays are k M-orthonormal eigenpairs of L u = λ M u for these L, M.

    Shapes, finite values, the same mass, ascending eigenvalues, uᵀ M u = 1 and every residual
    within CACHE_TOLERANCE, and Uᵀ M U = I probed with one fixed random vector w: ‖Uᵀ M U w − w‖
    is zero for the identity and, for any other matrix, almost surely not. O(nnz(L)·k).

    Parameters
    ----------
    stiffness : L (n, n) sparse.
    mass : (n,) M's diagonal.
    k : harmonics.
    arrays : the stored arrays.

    Returns
    -------
    bool.
    """
    eigenvalues, eigenvectors, stored_mass = (arrays.get(name) for name in
                                              ("eigenvalues", "eigenvectors", "mass"))
    n = len(mass)
    if any(not isinstance(array, np.ndarray) or array.dtype != np.float64 for array in
           (eigenvalues, eigenvectors, stored_mass)):
        return False
    if eigenvalues.shape != (k,) or eigenvectors.shape != (n, k) or stored_mass.shape != (n,):
        return False
    if not (np.isfinite(eigenvalues).all() and np.isfinite(eigenvectors).all()
            and np.allclose(stored_mass, mass, rtol=1e-12, atol=0)):
        return False
    scale = max(1.0, float(np.abs(eigenvalues).max()))
    if np.any(np.diff(eigenvalues) < -CACHE_TOLERANCE * scale):
        return False
    norms = np.einsum("ij,i,ij->j", eigenvectors, mass, eigenvectors)  # uᵀ M u
    if not np.all(np.abs(norms - 1) <= CACHE_TOLERANCE):
        return False
    if not residuals(stiffness, mass, eigenvalues, eigenvectors).max() <= CACHE_TOLERANCE:
        return False
    probe = np.random.default_rng(0).standard_normal(k)
    gram_probe = eigenvectors.T @ (mass * (eigenvectors @ probe))
    return bool(np.linalg.norm(gram_probe - probe) <= CACHE_TOLERANCE * np.linalg.norm(probe))


def basis_cache() -> DiskCache:
    """The disk cache of eigen-solves (folder `bases` of the cache folder).

    Returns
    -------
    DiskCache.
    """
    return DiskCache("bases")


def basis_key(mesh: Mesh, k: int, laplacian: str, solver: str = "bands") -> str:
    """The cache key of a solve: everything its eigenpairs depend on.

    The normalised geometry's SHA-256, k, the Laplacian, the solver and its version.

    Parameters
    ----------
    mesh : the normalised mesh.
    k : harmonics.
    laplacian : "cotan" or "robust".
    solver : "bands" or "eigsh".

    Returns
    -------
    str.
    """
    digest = hashlib.sha256()
    digest.update(np.ascontiguousarray(mesh.vertices, dtype=np.float64).tobytes())
    digest.update(np.ascontiguousarray(mesh.faces, dtype=np.int64).tobytes())
    return (f"eigendance.basis mesh={digest.hexdigest()} k={k} laplacian={laplacian} "
            f"solver={solver} version={SOLVER_VERSION}")
