"""Eigen-solvers for L u = λ M u with M diagonal (DESIGN §2).

`solve_eigsh` is the naive one-shot shift-invert `scipy.sparse.linalg.eigsh`, the baseline of
every benchmark. `solve_bands` (the default) slices the spectrum into bands solved one by one.
Both return (eigenvalues (k,) ascending, eigenvectors (n, k)) with Uᵀ M U = I.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as sla

from eigendance.errors import EigendanceError

SOLVERS = ("bands", "eigsh")
# Shift below the spectrum (λ_0 = 0) so that L - σM is non-singular. Units of λ: a normalised
# mesh's first non-zero eigenvalue is of order 1.
BASELINE_SHIFT = -1e-2


def check_request(n: int, k: int) -> None:
    if k < 1:
        raise EigendanceError(f"k must be at least 1, got {k}")
    if k >= n:
        raise EigendanceError(f"k = {k} harmonics need a mesh of more than {k} vertices; "
                              f"this one has {n}")


def solve_eigsh(stiffness: sp.spmatrix, mass: np.ndarray, k: int,
                progress=None) -> tuple[np.ndarray, np.ndarray]:
    """Naive baseline: all k pairs in one ARPACK shift-invert run around σ = BASELINE_SHIFT."""
    n = stiffness.shape[0]
    check_request(n, k)
    if n <= 500:
        return _dense(stiffness, mass, k)
    values, vectors = sla.eigsh(sp.csc_matrix(stiffness), k=k, M=sp.diags(mass).tocsc(),
                                sigma=BASELINE_SHIFT, which="LM")
    if progress is not None:
        progress(k)
    return _sorted_m_normalised(values, vectors, mass)


def _dense(stiffness, mass, k):
    """Small problems: dense symmetric solve of M^-1/2 L M^-1/2."""
    root = 1 / np.sqrt(mass)
    values, vectors = np.linalg.eigh(root[:, None] * stiffness.toarray() * root[None, :])
    return values[:k], root[:, None] * vectors[:, :k]


def _sorted_m_normalised(values, vectors, mass):
    order = np.argsort(values)
    values, vectors = values[order], vectors[:, order]
    vectors = vectors / np.sqrt(np.einsum("ij,i,ij->j", vectors, mass, vectors))
    return values, vectors


# --- Spectrum slicing -------------------------------------------------------------------------

PER_BAND = 150          # eigenpairs per band: fastest per pair in measurements (notes)
OVERLAP = 0.15          # fraction of a band's width shared with its neighbours
RESIDUAL_TOLERANCE = 1e-7  # ‖Lu − λMu‖ ≤ tol·max(λ,1)·‖Mu‖, checked for every accepted pair


@dataclass
class Band:
    """One shift-invert solve: every eigenvalue with |λ − σ| < radius is in `eigenvalues`.

    below: Sylvester inertia of L − σM, the number of eigenvalues < σ (None if unknown).
    """

    shift: float
    radius: float
    eigenvalues: np.ndarray
    eigenvectors: np.ndarray
    below: int | None

    @property
    def lower(self) -> float:
        return self.shift - self.radius

    @property
    def upper(self) -> float:
        return self.shift + self.radius


class _ShiftInvert:
    """(A − σI)^-1 for A = M^-½ L M^-½, via an LDLᵀ (qdldl) or LU (SuperLU) factorisation."""

    def __init__(self, stiffness, mass, shift):
        self.root = np.sqrt(mass)
        shifted = (stiffness - shift * sp.diags(mass)).tocsc()
        self.below = None
        try:
            import qdldl

            self._factor = qdldl.Solver(shifted)
            diagonal = self._factor.factors()[1]
            if np.all(np.isfinite(diagonal)) and np.all(diagonal != 0):
                # P(L − σM)Pᵀ = L D Lᵀ is a congruence: D's negatives count eigenvalues < σ.
                self.below = int((diagonal < 0).sum())
            self._solve = self._factor.solve
        except Exception:  # zero pivot or missing wheel: pivoting LU is slower but safe
            self._factor = sla.splu(shifted, permc_spec="COLAMD")
            self._solve = self._factor.solve

    def __call__(self, x):
        x = np.asarray(x).reshape(-1)
        return self.root * self._solve(self.root * x)


def _solve_band(stiffness, mass, shift: float, count: int) -> Band:
    """The `count` eigenpairs nearest `shift`, by ARPACK on the shift-inverted operator."""
    n = stiffness.shape[0]
    operator = _ShiftInvert(stiffness, mass, shift)
    linear = sla.LinearOperator((n, n), matvec=operator, dtype=np.float64)
    theta, vectors = sla.eigsh(linear, k=count, ncv=min(n - 1, 2 * count + 1), which="LM",
                               tol=1e-13)
    eigenvalues = shift + 1 / theta
    vectors = vectors / operator.root[:, None]  # u = M^-½ y, M-orthonormal
    distance = np.sort(np.abs(eigenvalues - shift))
    # Every eigenvalue nearer than the farthest one returned was found; stop inside the widest
    # gap of the outer tenth so that a multiple eigenvalue on the edge is never half-trusted.
    outer = distance[int(0.9 * count):]
    if len(outer) >= 2:
        gaps = np.diff(outer)
        widest = int(np.argmax(gaps))
        radius = (outer[widest] + outer[widest + 1]) / 2
    else:
        radius = distance[-1] * (1 - 1e-9)
    order = np.argsort(eigenvalues)
    return Band(shift, float(radius), eigenvalues[order], vectors[:, order], operator.below)


def _band_worker(arguments):
    from threadpoolctl import threadpool_limits

    stiffness, mass, shift, count = arguments
    with threadpool_limits(1):  # two band workers on two cores, one BLAS thread each
        return _solve_band(stiffness, mass, shift, count)


def _stitch(bands: list[Band]):
    """Join bands sorted by shift into one spectrum without gaps or duplicates.

    Between neighbours the cut goes through the widest gap of the overlap of their trusted
    windows, so a cluster of (near-)equal eigenvalues always comes from a single band.
    Returns (pieces, gap): pieces = [(band, mask of its accepted pairs)] in ascending order,
    gap = (a, b), the first interval no band covers, or None.
    """
    pieces = []
    cut = -np.inf  # the first band's shift lies below λ_0 = 0: it holds the smallest eigenvalues
    for band, following in zip(bands, [*bands[1:], None], strict=True):
        upper, gap = band.upper, None
        if following is not None and following.lower >= band.upper:
            gap = (band.upper, following.lower)
        elif following is not None:
            start = max(following.lower, cut)
            inside = band.eigenvalues[(band.eigenvalues > start) & (band.eigenvalues < upper)]
            points = np.concatenate([[start], inside, [upper]])
            widest = int(np.argmax(np.diff(points)))
            upper = (points[widest] + points[widest + 1]) / 2
        pieces.append((band, (band.eigenvalues > cut) & (band.eigenvalues < upper)))
        cut = upper
        if gap is not None:
            return pieces, gap
    return pieces, None


def solve_bands(stiffness: sp.spmatrix, mass: np.ndarray, k: int, progress=None,
                per_band: int = PER_BAND, workers: int = 2) -> tuple[np.ndarray, np.ndarray]:
    """Spectrum slicing (after Vallet & Lévy 2008): shift-invert bands of `per_band` pairs.

    The first band sits just below λ_0 = 0; each next shift is placed from the eigenvalue density
    seen so far (nearly constant on a surface, by Weyl's law) so that neighbouring windows
    overlap by OVERLAP of their width; uncovered gaps get an extra band. Bands after the first run
    `workers` at a time in separate processes. Every accepted pair is checked by its residual,
    and each band's Sylvester inertia must equal the number of accepted eigenvalues below its
    shift, so no eigenpair is missed or doubled.
    """
    n = stiffness.shape[0]
    check_request(n, k)
    if n <= 600:
        return _dense(stiffness, mass, k)
    per_band = max(1, min(per_band, n // 3))
    first_count = min(n - 2, per_band if k > per_band else k + max(4, k // 10))
    bands = [_solve_band(stiffness, mass, BASELINE_SHIFT, first_count)]
    pool = None
    try:
        while True:
            pieces, gap = _stitch(bands)
            found = sum(int(keep.sum()) for _, keep in pieces)
            if progress is not None:
                progress(min(found, k))
            if gap is None and found >= k:
                break
            last = bands[-1]
            inside = (last.eigenvalues > last.lower) & (last.eigenvalues < last.upper)
            density = max(inside.sum(), 1) / (last.upper - max(last.lower, 0))
            half_width = per_band / (2 * density)
            if gap is not None:
                shifts = [(gap[0] + gap[1]) / 2]
            else:
                step = 2 * half_width * (1 - OVERLAP)
                start = last.upper + half_width * (1 - 2 * OVERLAP)
                missing = k - found
                count = max(1, min(workers, int(np.ceil(missing / (per_band * (1 - OVERLAP))))))
                shifts = [start + step * i for i in range(count)]
            arguments = [(stiffness, mass, shift, min(per_band, n - 2)) for shift in shifts]
            if len(arguments) > 1:
                if pool is None:
                    import multiprocessing
                    from concurrent.futures import ProcessPoolExecutor

                    # fork: no re-import of the caller's script (spawn would need a main guard)
                    method = "fork" if "fork" in multiprocessing.get_all_start_methods() else None
                    pool = ProcessPoolExecutor(workers,
                                               mp_context=multiprocessing.get_context(method))
                new = list(pool.map(_band_worker, arguments))
            else:
                new = [_solve_band(*arguments[0])]
            bands = sorted(bands + new, key=lambda band: band.shift)
    finally:
        if pool is not None:
            pool.shutdown()
    values = np.concatenate([band.eigenvalues[keep] for band, keep in pieces])[:k]
    vectors = np.empty((n, k))
    filled = 0
    for band, keep in pieces:
        taken = min(int(keep.sum()), k - filled)
        vectors[:, filled:filled + taken] = band.eigenvectors[:, keep][:, :taken]
        filled += taken
    _verify(stiffness, mass, values, vectors, bands)
    return values, vectors


def _verify(stiffness, mass, values, vectors, bands):
    """Residual of every pair, and inertia counts against the accepted eigenvalues."""
    worst = 0.0
    for start in range(0, len(values), 256):  # column blocks bound the temporary memory
        block, value = vectors[:, start:start + 256], values[start:start + 256]
        weighted = mass[:, None] * block
        residual = np.linalg.norm(stiffness @ block - weighted * value, axis=0)
        scale = np.maximum(np.abs(value), 1) * np.linalg.norm(weighted, axis=0)
        worst = max(worst, float(np.max(residual / scale)))
    if not worst <= RESIDUAL_TOLERANCE:
        raise EigendanceError(f"eigen-solver: residual {worst:.1e} above tolerance; "
                              "try --solver eigsh")
    for band in bands:
        if band.below is not None and band.shift < values[-1]:
            accepted = int((values < band.shift).sum())
            if accepted != band.below:
                raise EigendanceError(
                    f"eigen-solver: {band.below} eigenvalues lie below {band.shift:.4g} but "
                    f"{accepted} were found; try --solver eigsh")


def solve(stiffness, mass, k: int, solver: str = "bands", progress=None):
    """Dispatch to `solve_bands` or `solve_eigsh`; see SOLVERS."""
    if solver == "bands":
        return solve_bands(stiffness, mass, k, progress)
    if solver == "eigsh":
        return solve_eigsh(stiffness, mass, k, progress)
    raise EigendanceError(f"unknown solver '{solver}' (expected one of {', '.join(SOLVERS)})")
