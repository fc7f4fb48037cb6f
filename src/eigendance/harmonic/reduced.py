"""The reduced harmonic basis of a large mesh (docs/design.md#reduced-basis).

After Nasikun, Brandt & Hildebrandt, "Fast Approximation of Laplace-Beltrami Eigenproblems"
(SGP 2018): the harmonics are sought in the span of P (n × m), the interpolation from m
samples (`sampling`, `interpolation`). Restricting L u = λ M u to u = P c gives the small
generalised problem

    L_r c = λ M_r c,   L_r = PᵀLP,  M_r = PᵀMP   (m × m, sparse),

solved by the band solver (`eigensolver.solve`, sparse mass); the harmonics are
U = P U_r. Since M_r = PᵀMP, Uᵀ M U = U_rᵀ M_r U_r = I holds to rounding. This is the
Rayleigh–Ritz (Galerkin) approximation in span P: every λ̃_ν ≥ λ_ν (min-max), and U is never
formed — P (≤ 8 weights per vertex) and U_r (m × k) are what is stored and sent.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import scipy.sparse as sp

from eigendance.errors import InputError
from eigendance.geometry import vertex_normals
from eigendance.harmonic.eigensolver import RESIDUAL_TOLERANCE, residuals, solve
from eigendance.harmonic.interpolation import Interpolation, maxent_interpolation
from eigendance.harmonic.sampling import (
    component_labels,
    nearest_samples,
    operator_graph,
    spread_samples,
)

REDUCED_VERSION = 2  # part of every reduced cache key: a new construction recomputes
# Default m = 21·k: the glb skin of 1.15 M vertices and a 3-minute song at 30 fps (12 bytes a
# sample and frame) stays under an eighth of all k morph targets even with the sampler's 5%
# more samples; 24·k was 0.138× (median eigenvalue error on the armadillo ×4: 2.34% at m =
# 7,424, 2.71% at 6,429; benchmarks/bench_reduced.py, docs/design.md#reduced-basis).
SAMPLES_PER_HARMONIC = 21
MIN_SAMPLES = 2000
# Peak bytes of a reduced solve (bench_reduced.py): per vertex the Laplacian, the graph, the
# clusters, a block of weights, P and L·P (1.15 M vertices, cotan: 1.22 GB at the peak); the
# robust Laplacian's intrinsic triangulation needs far more (the beetle ×256, 294k vertices:
# 1.19 GB); per face libigl's temporaries; per coarse value the band solver's (as exact).
BYTES_PER_VERTEX = {"cotan": 900, "robust": 4500}
FIXED_BYTES = 300e6  # the interpreter and its libraries (the beetle ×256: 0.51 GB at the peak)
BYTES_PER_FACE = 200
BYTES_PER_COARSE_VALUE = 24
# The arrays of a reduced basis in a basis file and a cache entry (docs/design.md#basis-file).
REDUCED_KEYS = ("samples", "interpolation_indices", "interpolation_weights",
                "coarse_eigenvectors")
# ... and the count the sampler was asked for (absent from files written before it was kept).
ASKED_KEY = "samples_asked"
# A cached solve (exact or reduced) is used only if its pairs pass the solver's own test with
# this slack (‖Lu − λMu‖ ≤ tol·max(λ,1)·‖Mu‖, and Uᵀ M U = I within tol): construction.py.
CACHE_TOLERANCE = 10 * RESIDUAL_TOLERANCE


def solve_bytes(n: int, faces: int, k: int, count: int, laplacian: str = "cotan") -> float:
    """Bytes a reduced solve holds at most (`limits.check_memory` plans with it).

    Parameters
    ----------
    n, faces : vertices and triangles of the mesh.
    k : harmonics.
    count : samples m.
    laplacian : "cotan" or "robust".

    Returns
    -------
    float, bytes.
    """
    return FIXED_BYTES + BYTES_PER_VERTEX[laplacian] * n + BYTES_PER_FACE * faces + \
        BYTES_PER_COARSE_VALUE * count * k


def sample_count(n: int, k: int) -> int:
    """The default number of samples m: SAMPLES_PER_HARMONIC·k, at least MIN_SAMPLES, at most n.

    Parameters
    ----------
    n : vertices.
    k : harmonics.

    Returns
    -------
    int, m.
    """
    return int(min(n, max(MIN_SAMPLES, SAMPLES_PER_HARMONIC * k)))


@dataclass
class ReducedHarmonics:
    """U = P U_r without forming it: the samples, P and the coarse eigenvectors.

    Parameters
    ----------
    samples : (m,) vertex index of each sample.
    interpolation : P (n × m).
    coarse : (m, k) U_r, with U_rᵀ M_r U_r = I.
    asked : the samples asked of `spread_samples`, which placed these m (about as many): with
        the mesh, the asked count gives these samples again; None where unknown (older files).
    """

    samples: np.ndarray
    interpolation: Interpolation
    coarse: np.ndarray
    asked: int | None = None
    _overlap: sp.csr_matrix | None = field(default=None, repr=False, compare=False)  # PᵀP

    @property
    def count(self) -> int:
        """Samples m."""
        return len(self.samples)

    def lift(self, values: np.ndarray) -> np.ndarray:
        """U · values = P (U_r · values).

        Parameters
        ----------
        values : (k,) or (k, c).

        Returns
        -------
        (n,) or (n, c).
        """
        return self.interpolation.lift(self.coarse @ values)

    def columns(self, targets) -> np.ndarray:
        """U[:, targets], formed for these harmonics only.

        Parameters
        ----------
        targets : (t,) harmonic indices.

        Returns
        -------
        (n, t).
        """
        return self.interpolation.lift(self.coarse[:, np.asarray(targets, dtype=np.int64)])

    def gram(self, targets) -> np.ndarray:
        """U[:, t]ᵀ U[:, t] = U_r[:, t]ᵀ (PᵀP) U_r[:, t], without forming U (PᵀP built once).

        Parameters
        ----------
        targets : (t,) harmonic indices.

        Returns
        -------
        (t, t).
        """
        if self._overlap is None:  # built once: the gallery asks for many blocks
            matrix = self.interpolation.matrix()
            self._overlap = (matrix.T @ matrix).tocsr()
        coarse = self.coarse[:, np.asarray(targets, dtype=np.int64)]
        return coarse.T @ (self._overlap @ coarse)

    def transpose_lift(self, fine: np.ndarray) -> np.ndarray:
        """Uᵀ · fine = U_rᵀ (Pᵀ fine).

        Parameters
        ----------
        fine : (n, c) values at the vertices.

        Returns
        -------
        (k, c).
        """
        return self.coarse.T @ (self.interpolation.matrix().T @ fine)


def restricted(stiffness, mass: np.ndarray, matrix: sp.csr_matrix):
    """The operators restricted to span P.

    Parameters
    ----------
    stiffness : L (n, n) sparse.
    mass : (n,) vertex areas.
    matrix : P (n, m) sparse.

    Returns
    -------
    (L_r, M_r) = (PᵀLP, PᵀMP), sparse (m, m) CSC, exactly symmetric.
    """
    transpose = matrix.T.tocsr()
    stiffness_r = (transpose @ (stiffness @ matrix)).tocsc()
    mass_r = (transpose @ sp.diags(mass) @ matrix).tocsc()
    return ((stiffness_r + stiffness_r.T) / 2).tocsc(), ((mass_r + mass_r.T) / 2).tocsc()


def reduced_harmonics(stiffness, mass: np.ndarray, vertices: np.ndarray, faces: np.ndarray,
                      k: int, count: int | None = None, progress=None):
    """The first k reduced harmonics of a mesh (module docstring).

    Parameters
    ----------
    stiffness, mass : L (n, n) sparse and the vertex areas (n,) of `harmonic.laplacian`.
    vertices, faces : the normalised mesh (n, 3), (f, 3).
    k : harmonics wanted.
    count : samples m (default `sample_count(n, k)`); more when the mesh has more parts.
    progress : optional callable(done) told how many eigenpairs are accepted so far.

    Returns
    -------
    eigenvalues (k,) ascending and the `ReducedHarmonics`.
    """
    n = len(vertices)
    count = sample_count(n, k) if count is None else int(count)
    graph = operator_graph(stiffness, vertices)
    samples, _ = spread_samples(vertices, component_labels(graph), count, float(mass.sum()),
                                graph)
    if len(samples) <= k:
        raise InputError(f"k = {k} harmonics need more than {k} samples; {len(samples)} were "
                         f"placed on {n} vertices", remedy={"samples": 4 * k})
    slot = nearest_samples(graph, samples)
    spacing = float(np.sqrt(mass.sum() / len(samples)))
    interpolation = maxent_interpolation(graph, vertices, vertex_normals(vertices, faces),
                                         samples, slot, spacing)
    del graph, slot
    stiffness_r, mass_r = restricted(stiffness, mass, interpolation.matrix())
    eigenvalues, coarse = solve(stiffness_r, mass_r, k, progress=progress)
    return eigenvalues, ReducedHarmonics(samples.astype(np.int64), interpolation,
                                         np.ascontiguousarray(coarse), count)


def reduced_key(exact_key: str, count: int) -> str:
    """The cache key of a reduced solve.

    Parameters
    ----------
    exact_key : the exact solve's key (`construction.basis_key`: geometry, k, Laplacian).
    count : samples m.

    Returns
    -------
    str: the exact key with the construction, its version and the sample count.
    """
    return f"{exact_key} construction=reduced-maxent version={REDUCED_VERSION} samples={count}"


def reduced_arrays(reduced: ReducedHarmonics) -> dict[str, np.ndarray]:
    """The arrays that store a reduced basis.

    Parameters
    ----------
    reduced : the `ReducedHarmonics`.

    Returns
    -------
    {name: array} of REDUCED_KEYS, and ASKED_KEY where the asked count is known.
    """
    arrays = {"samples": reduced.samples,
              "interpolation_indices": reduced.interpolation.indices,
              "interpolation_weights": reduced.interpolation.weights,
              "coarse_eigenvectors": reduced.coarse}
    if reduced.asked is not None:
        arrays[ASKED_KEY] = np.int64(reduced.asked)
    return arrays


def reduced_from_arrays(arrays: dict, asked: int | None = None) -> ReducedHarmonics:
    """A `ReducedHarmonics` from stored arrays.

    Parameters
    ----------
    arrays : REDUCED_KEYS as `reduced_arrays` writes them, checked (`check_reduced`), and
        ASKED_KEY where the file has it.
    asked : the asked count where the arrays do not hold it (a cache entry's key names it).

    Returns
    -------
    ReducedHarmonics.
    """
    samples = np.asarray(arrays["samples"], dtype=np.int64)
    interpolation = Interpolation(np.asarray(arrays["interpolation_indices"], dtype=np.int32),
                                  np.asarray(arrays["interpolation_weights"], dtype=np.float64),
                                  len(samples))
    if ASKED_KEY in arrays:
        asked = int(arrays[ASKED_KEY])
    return ReducedHarmonics(samples, interpolation,
                            np.asarray(arrays["coarse_eigenvectors"], dtype=np.float64), asked)


def check_reduced(arrays: dict, n: int, k: int) -> str | None:
    """What is wrong with stored reduced arrays.

    Parameters
    ----------
    arrays : {name: array} holding REDUCED_KEYS.
    n : vertices.
    k : harmonics.

    Returns
    -------
    str, or None when they are a reduced basis of n vertices and k harmonics.
    """
    samples, indices, weights, coarse = (arrays.get(name) for name in REDUCED_KEYS)
    if any(not isinstance(array, np.ndarray) for array in (samples, indices, weights, coarse)):
        return "missing arrays"
    if samples.ndim != 1 or not np.issubdtype(samples.dtype, np.integer) or len(samples) <= k:
        return "samples must be more than k vertex indices"
    if samples.min() < 0 or samples.max() >= n or np.any(np.diff(samples) <= 0):
        return f"samples must be ascending vertex indices in 0 … {n - 1}"
    if len(indices) != n:
        return f"interpolation must have one row per vertex ({n})"
    problem = Interpolation(indices, weights, len(samples)).check()
    if problem:
        return problem
    if coarse.shape != (len(samples), k) or coarse.dtype.kind != "f" or \
            not np.isfinite(coarse).all():
        return f"coarse eigenvectors must be finite, ({len(samples)}, {k})"
    return None


def reduced_pairs_fit(stiffness, mass: np.ndarray, k: int, arrays: dict) -> bool:
    """Whether a cache entry holds k reduced eigenpairs for these L, M: the same mass, a valid
    P, ascending eigenvalues, and the coarse pairs solving L_r c = λ M_r c with U_rᵀ M_r U_r = I
    (P as stored, L_r and M_r restricted anew). O(nnz(L) + nnz(L_r)·k).

    Parameters
    ----------
    stiffness, mass : L and the vertex areas of the mesh, built anew.
    k : harmonics.
    arrays : the entry: eigenvalues, mass and REDUCED_KEYS.

    Returns
    -------
    bool.
    """
    eigenvalues, stored_mass = arrays.get("eigenvalues"), arrays.get("mass")
    n = len(mass)
    if not (isinstance(eigenvalues, np.ndarray) and isinstance(stored_mass, np.ndarray)) or \
            eigenvalues.shape != (k,) or stored_mass.shape != (n,) or \
            not np.isfinite(eigenvalues).all() or check_reduced(arrays, n, k) is not None:
        return False
    if not np.allclose(stored_mass, mass, rtol=1e-12, atol=0):
        return False
    scale = max(1.0, float(np.abs(eigenvalues).max()))
    if np.any(np.diff(eigenvalues) < -CACHE_TOLERANCE * scale):
        return False
    reduced = reduced_from_arrays(arrays)
    stiffness_r, mass_r = restricted(stiffness, mass, reduced.interpolation.matrix())
    coarse = reduced.coarse
    if not np.all(np.abs(np.einsum("ij,ij->j", coarse, mass_r @ coarse) - 1) <= CACHE_TOLERANCE):
        return False
    if not residuals(stiffness_r, mass_r, eigenvalues, coarse).max() <= CACHE_TOLERANCE:
        return False
    probe = np.random.default_rng(0).standard_normal(k)
    gram_probe = coarse.T @ (mass_r @ (coarse @ probe))
    return bool(np.linalg.norm(gram_probe - probe) <= CACHE_TOLERANCE * np.linalg.norm(probe))
