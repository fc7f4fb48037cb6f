"""Eigen-solvers for L u = λ M u (docs/design.md#eigensolver).

M is diagonal (a mesh's vertex areas) or, for a reduced basis, a sparse SPD matrix
(`eigendance.harmonic.mass`).

`solve_eigsh` is the naive one-shot shift-invert `scipy.sparse.linalg.eigsh`, the baseline of
every benchmark. `solve_bands` (the default) slices the spectrum into bands solved one by one;
`solve` gives it each connected component of the operator separately (`harmonic.components`).
Both return (eigenvalues (k,) ascending, eigenvectors (n, k)) with Uᵀ M U = I.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import qdldl
import scipy.linalg
import scipy.sparse as sp
import scipy.sparse.linalg as sla
from scipy.sparse.csgraph import connected_components
from threadpoolctl import threadpool_limits

from eigendance.errors import InputError, InternalError
from eigendance.harmonic.components import solve_components
from eigendance.harmonic.lanczos import lanczos_extreme
from eigendance.harmonic.mass import as_mass
from eigendance.harmonic.slicing import BASELINE_SHIFT, band_size, next_shifts, stitch
from eigendance.processes import Pool

SOLVERS = ("bands", "eigsh")
SOLVER_VERSION = 3  # part of every cache key: a new version recomputes cached bases (3: the
# contacts' reach capped at 1% of the diagonal, harmonic.contacts.TOUCH_LENGTH)
# Meshes of at most this many vertices are solved densely, by both solvers.
DENSE_VERTICES = 600


def check_request(n: int, k: int, name: str = "the mesh") -> None:
    """InputError unless k harmonics of an n-vertex mesh can be asked for (1 ≤ k, k ≤ n − 1);
    its remedy the largest k that can.

    Parameters
    ----------
    n : vertices.
    k : harmonics.
    name : how the message calls the mesh.
    """
    if k < 1:
        raise InputError(f"k must be at least 1, got {k}")
    if k >= n:
        raise InputError(f"{name}: k = {k} harmonics need a mesh of more than {k} vertices; "
                         f"this one has {n}", remedy={"k": n - 1} if n > 1 else None)


def solve_eigsh(stiffness: sp.spmatrix, mass: np.ndarray, k: int,
                progress=None) -> tuple[np.ndarray, np.ndarray]:
    """Naive baseline: all k pairs in one ARPACK shift-invert run around σ = BASELINE_SHIFT.

    Parameters
    ----------
    stiffness : L (n, n) sparse.
    mass : (n,).
    k : pairs.
    progress : optional callable(pairs done).

    Returns
    -------
    (eigenvalues (k,) ascending, eigenvectors (n, k) M-orthonormal).
    """
    n = stiffness.shape[0]
    check_request(n, k)
    mass = as_mass(mass)
    if n <= DENSE_VERTICES:
        return _dense(stiffness, mass, k)
    values, vectors = sla.eigsh(sp.csc_matrix(stiffness), k=k, M=mass.sparse(),
                                sigma=BASELINE_SHIFT, which="LM")
    if progress is not None:
        progress(k)
    return _sorted_m_normalised(values, vectors, mass)


def _dense(stiffness, mass, k):
    """Small problems: dense symmetric solve of M^-1/2 L M^-1/2 (or L u = λ M u).

    One BLAS thread below 1000 rows: on a busy host OpenBLAS's threads make a 150-row `eigh`
    take 0.8 s instead of 5 ms (measured: a mesh of 8 small pieces, load 5).
    """
    mass = as_mass(mass)
    with threadpool_limits(1 if stiffness.shape[0] < 1000 else None):
        return _dense_solve(stiffness, mass, k)


def _dense_solve(stiffness, mass, k):
    if mass.diagonal is None:
        values, vectors = scipy.linalg.eigh(stiffness.toarray(), mass.sparse().toarray(),
                                            subset_by_index=[0, k - 1])
        return values, vectors
    root = 1 / np.sqrt(mass.diagonal)
    values, vectors = np.linalg.eigh(root[:, None] * stiffness.toarray() * root[None, :])
    return values[:k], root[:, None] * vectors[:, :k]


def _sorted_m_normalised(values, vectors, mass):
    order = np.argsort(values)
    values, vectors = values[order], vectors[:, order]
    vectors = vectors / np.sqrt(as_mass(mass).norms(vectors))
    return values, vectors


# --- Spectrum slicing -------------------------------------------------------------------------

PER_BAND = 60           # eigenpairs per band: fastest for bunny k = 1070 (benchmarks/)
RESIDUAL_TOLERANCE = 1e-7  # ‖Lu − λMu‖ ≤ tol·max(λ,1)·‖Mu‖, checked for every accepted pair
MAX_REPAIRS = 8         # searches for missed copies of multiple eigenvalues before giving up


@dataclass(eq=False)  # bands are told apart by identity
class Band:
    """One shift-invert solve: every eigenvalue with |λ − σ| < radius is in `eigenvalues`.

    below: Sylvester inertia of L − σM, the number of eigenvalues < σ (None if unknown).
    residuals: ‖Lu − λMu‖ / (max(|λ|,1)·‖Mu‖) of each pair, computed where the band was solved.

    Parameters
    ----------
    shift : σ.
    radius : the band's half width.
    eigenvalues : (p,).
    eigenvectors : (n, p).
    below, residuals : as above.
    """

    shift: float
    radius: float
    eigenvalues: np.ndarray
    eigenvectors: np.ndarray
    below: int | None
    residuals: np.ndarray

    @property
    def lower(self) -> float:
        """σ − radius."""
        return self.shift - self.radius

    @property
    def upper(self) -> float:
        """σ + radius."""
        return self.shift + self.radius


class _ShiftInvert:
    """(A − σI)^-1 = Rᵀ(L − σM)⁻¹R for A = R⁻¹ L R⁻ᵀ (M = R Rᵀ, `harmonic.mass`), via an LDLᵀ
    (qdldl) or LU (SuperLU) factorisation.

    L − σM has the same sparsity for every σ, so each process keeps its last LDLᵀ and only
    redoes the numeric part (half the time); the operator it belonged to stops working.
    """

    _last = None  # per process: (pattern key, qdldl.Solver, the _ShiftInvert using it)

    def __init__(self, stiffness, mass, shift):
        self.mass = as_mass(mass)
        shifted = self.mass.shifted(stiffness, shift)
        self.below = None
        try:
            factor = self._factorise(shifted)
            diagonal = factor.factors()[1]
            pivots_usable = np.all(np.isfinite(diagonal)) and np.all(diagonal != 0)
        except Exception:  # zero pivot or missing wheel
            pivots_usable = False
        if pivots_usable:
            # P(L − σM)Pᵀ = L D Lᵀ is a congruence: D's negatives count eigenvalues < σ.
            self.below = int((diagonal < 0).sum())
            self._solve = factor.solve
        else:  # σ (nearly) on an eigenvalue: pivoting LU is slower but safe
            self._solve = sla.splu(shifted, permc_spec="COLAMD").solve

    def _factorise(self, shifted):
        key = (shifted.shape, hash(shifted.indptr.tobytes()), hash(shifted.indices.tobytes()))
        if _ShiftInvert._last is not None and _ShiftInvert._last[0] == key:
            _, solver, previous = _ShiftInvert._last
            previous._solve = previous._reused
            solver.update(shifted)
        else:
            solver = qdldl.Solver(shifted)
        _ShiftInvert._last = (key, solver, self)
        return solver

    def _reused(self, x):
        raise RuntimeError("this shift's factorisation was reused for a later shift")

    def __call__(self, x):
        x = np.asarray(x).reshape(-1)
        return self.mass.to_y(self._solve(self.mass.factor_times(x)))


def _solve_band(stiffness, mass, shift: float, count: int, null: np.ndarray) -> Band:
    """The `count` eigenpairs nearest `shift` besides the null space, from (A − σI)^-1.

    Lanczos (or ARPACK's, if that has not converged in 3·count + 50 steps) runs orthogonal to
    `null` (rows: L's kernel, see `null_space`), whose pairs (0, u) join the band when its
    window reaches λ = 0: a Krylov space would find one of them only.
    """
    n = stiffness.shape[0]
    operator = _ShiftInvert(stiffness, mass, shift)
    known = operator.mass.to_y(null.T).T  # y = Rᵀ u: orthonormal rows
    found = lanczos_extreme(operator, n, count, deflate=known)
    if found is None:
        def deflated(x):
            x = x - (known @ x) @ known
            y = operator(x)
            return y - (known @ y) @ known

        linear = sla.LinearOperator((n, n), matvec=deflated, dtype=np.float64)
        found = sla.eigsh(linear, k=count, ncv=min(n - 1, 2 * count + 1), which="LM", tol=1e-13)
    theta, vectors = found
    eigenvalues = shift + 1 / theta
    radius = _trusted_radius(np.abs(eigenvalues - shift))
    rows = operator.mass.from_y(vectors).T
    if abs(shift) < radius:
        eigenvalues = np.concatenate([np.zeros(len(null)), eigenvalues])
        rows = np.concatenate([null, rows])
    return _band(stiffness, mass, shift, radius, eigenvalues, rows, operator.below)


def _trusted_radius(distance: np.ndarray) -> float:
    """Radius within which every eigenvalue was found, from the returned distances |λ − σ|.

    Lanczos finds the nearest ones first, so all up to the farthest returned, except copies of a
    multiple eigenvalue that its Krylov space did not see. The inertia counts catch those
    inside; the farthest pair may be one copy of a multiple eigenvalue whose other copies lie
    unseen at the same distance, so it is left out (with any returned copies of it).
    """
    far = distance.max()
    edge = np.isclose(distance, far, rtol=1e-8, atol=0)
    if edge.all():
        return float(far * (1 + 1e-9))
    return float((distance[~edge].max() + far) / 2)


def _band(stiffness, mass, shift, radius, eigenvalues, rows, below) -> Band:
    """A Band from unsorted pairs (eigenvectors as rows), with pairs of poor residual refined."""
    order = np.argsort(eigenvalues, kind="stable")
    eigenvalues, vectors = eigenvalues[order], _columns(rows[order])
    accuracy = residuals(stiffness, mass, eigenvalues, vectors)
    poor = accuracy > RESIDUAL_TOLERANCE / 100
    if poor.any():
        eigenvalues[poor], vectors[:, poor] = _refine(stiffness, mass, vectors[:, poor])
        accuracy[poor] = residuals(stiffness, mass, eigenvalues[poor], vectors[:, poor])
    return Band(shift, radius, eigenvalues, vectors, below, accuracy)


def _refine(stiffness, mass, vectors):
    """Sharper eigenpairs from approximate low eigenvectors (those just above the null space).

    A pair found from a far shift σ has ‖Lu − λMu‖ ≈ tol·λ_max/|θ|, relative to max(λ,1): up
    to 1e-7 for λ ≈ 0. One inverse-iteration step at BASELINE_SHIFT (the error shrinks by
    |λ − σ₀| / |λ_j − σ₀| along every other eigenvector j) and a Rayleigh–Ritz fix that.
    """
    operator = _ShiftInvert(stiffness, mass, BASELINE_SHIFT)
    refined = np.column_stack([operator(column) for column in operator.mass.to_y(vectors).T])
    refined = operator.mass.from_y(refined)
    gram = refined.T @ operator.mass.times(refined)
    energy = refined.T @ (stiffness @ refined)
    values, mixing = scipy.linalg.eigh((energy + energy.T) / 2, (gram + gram.T) / 2)
    return values, refined @ mixing


def _complete_band(stiffness, mass, band: Band, missing: int) -> Band:
    """`band` plus the copies of multiple eigenvalues it missed inside its window.

    Lanczos again, kept orthogonal to the band's eigenvectors: the deflated operator's largest
    |θ| are then the missing copies (and, beyond the window, eigenvalues nobody asked for).
    """
    n = stiffness.shape[0]
    operator = _ShiftInvert(stiffness, mass, band.shift)
    known = operator.mass.to_y(band.eigenvectors).T  # y = Rᵀ u: orthonormal rows
    # The copies may sit next to eigenvalues just outside the window: allow a long run.
    found = lanczos_extreme(operator, n, missing + 4, deflate=known, seed=len(known),
                            max_steps=3 * missing + 300)
    if found is None:
        return band
    theta, vectors = found
    eigenvalues = band.shift + 1 / theta
    inside = np.abs(eigenvalues - band.shift) < band.radius
    return _band(stiffness, mass, band.shift, band.radius,
                 np.concatenate([band.eigenvalues, eigenvalues[inside]]),
                 np.concatenate([band.eigenvectors.T,
                                 operator.mass.from_y(vectors[:, inside]).T]),
                 band.below)


def null_space(stiffness, mass, most: int) -> np.ndarray:
    """L's kernel as M-orthonormal rows (p, n), at most `most` of them.

    The constant on each connected component of the graph of L's non-zero weights:
    u_c = 1_c / √area_c, and L u_c = 0 because every row of L sums to zero.

    Parameters
    ----------
    stiffness : L.
    mass : (n,).
    most : the most rows kept.

    Returns
    -------
    (p, n).
    """
    mass = as_mass(mass)
    graph = sp.csr_matrix(stiffness, copy=True)
    graph.eliminate_zeros()
    count, labels = connected_components(graph, directed=False)
    count = min(count, most)
    rows = np.zeros((count, mass.n))
    inside = labels < count
    rows[labels[inside], np.flatnonzero(inside)] = 1
    return rows / np.sqrt(mass.norms(rows.T))[:, None]


def residuals(stiffness, mass, eigenvalues, eigenvectors) -> np.ndarray:
    """‖Lu − λMu‖ / (max(|λ|,1)·‖Mu‖) of each pair, in column blocks to bound the memory.

    Parameters
    ----------
    stiffness : L.
    mass : (n,) areas, or a sparse mass (`harmonic.mass`).
    eigenvalues : (k,).
    eigenvectors : (n, k).

    Returns
    -------
    (k,).
    """
    mass = as_mass(mass)
    result = np.empty(len(eigenvalues))
    for start in range(0, len(eigenvalues), 256):
        block, value = eigenvectors[:, start:start + 256], eigenvalues[start:start + 256]
        weighted = mass.times(block)
        residual = np.linalg.norm(stiffness @ block - weighted * value, axis=0)
        scale = np.maximum(np.abs(value), 1) * np.linalg.norm(weighted, axis=0)
        result[start:start + 256] = residual / scale
    return result


def _band_worker(arguments):
    with threadpool_limits(1):  # two band workers on two cores, one BLAS thread each
        return _solve_band(*arguments)


def solve_bands(stiffness: sp.spmatrix, mass: np.ndarray, k: int, progress=None,
                per_band: int = PER_BAND, workers: int = 2) -> tuple[np.ndarray, np.ndarray]:
    """Spectrum slicing (after Vallet & Lévy 2008): shift-invert bands of ≈`per_band` pairs.

    The first shifts come from Weyl's law (N(λ) ≈ area·λ/4π eigenvalues below λ), the later
    ones from a counting function fitted to the eigenvalues found so far, so that neighbouring
    windows share OVERLAP of their pairs; uncovered gaps get an extra band. Bands run
    `workers` at a time in separate processes. L's kernel (one constant per connected
    component) is known exactly and kept out of every Krylov space. Each band's Sylvester
    inertia (and one more at the top) must equal the number of accepted eigenvalues below its
    shift, else the bands around it look again for the copies of multiple eigenvalues they
    missed; every accepted pair is checked by its residual. Nothing is missed or doubled.

    Parameters
    ----------
    stiffness : L (n, n) sparse.
    mass : (n,).
    k : pairs.
    progress : optional callable(pairs done).
    per_band : pairs per band, about.
    workers : bands solved at once.

    Returns
    -------
    (eigenvalues (k,) ascending, eigenvectors (n, k) M-orthonormal).
    """
    n = stiffness.shape[0]
    check_request(n, k)
    mass = as_mass(mass)
    if n <= DENSE_VERTICES:
        return _dense(stiffness, mass, k)
    null = null_space(stiffness, mass, k)
    if len(null) >= k:  # k components or more: every wanted pair has λ = 0
        return np.zeros(k), _columns(null)
    per_band = max(1, min(per_band, n // 3))
    count = min(n - 2 - len(null), band_size(k, per_band, workers))
    if k <= 0.8 * count:  # one band from the bottom of the spectrum
        count = min(n - 2 - len(null), k + max(4, k // 10))
        bands = [_solve_band(stiffness, mass, BASELINE_SHIFT, count, null)]
    else:
        bands = []
    repairs, rounds = 0, 0
    most = 4 * math.ceil(k / count) + 8  # rounds of new bands before giving up (no progress)
    told = _Told(progress, k)
    with Pool(workers, _band_worker, here=lambda each: _solve_band(*each)) as run:
        while True:
            pieces, gap = stitch(bands) if bands else ([], None)
            found = sum(int(keep.sum()) for _, keep in pieces)
            told(found)
            if bands and gap is None and found >= k:
                values, vectors = _assemble(pieces, k, n)
                wrong, missing = _miscounted(stiffness, mass, bands, pieces, k)
                if not wrong:
                    break
                if repairs == MAX_REPAIRS:
                    raise InternalError(
                        f"eigen-solver: {missing} eigenpair(s) still missing after {repairs} "
                        "searches for multiple eigenvalues", remedy={"solver": "eigsh"})
                repairs += 1
                bands = [_complete_band(stiffness, mass, band, missing) if band in wrong
                         else band for band in bands]
            else:
                rounds += 1
                if rounds > most:  # e.g. copies of a multiple eigenvalue at every band's edge
                    raise InternalError(f"eigen-solver: the bands do not close after {most} "
                                        "rounds", remedy={"solver": "eigsh"})
                shifts = next_shifts(pieces, gap, k, count, workers, mass.total)
                bands += run([(stiffness, mass, shift, count, null) for shift in shifts],
                             finished=lambda band, done=list(bands): told.band(done, band))
            bands.sort(key=lambda band: band.shift)
    _verify(values, pieces, bands)
    return values, vectors


class _Told:
    """The pairs found so far, told to `progress` as each band ends (not only each round's
    last): never fewer than told before, at most k."""

    def __init__(self, progress, k: int):
        self.progress, self.k, self.most = progress, k, 0

    def __call__(self, found: int) -> None:
        if self.progress is not None and min(found, self.k) > self.most:
            self.most = min(found, self.k)
            self.progress(self.most)

    def band(self, done: list, band) -> None:
        """A band of the round ended: the pairs of the bands done so far, stitched."""
        if self.progress is None:
            return
        done.append(band)
        done.sort(key=lambda each: each.shift)
        self(sum(int(keep.sum()) for _, keep in stitch(done)[0]))


def _assemble(pieces, k: int, n: int):
    """The first k accepted pairs of the stitched pieces, in ascending order."""
    values = np.concatenate([band.eigenvalues[keep] for band, keep in pieces])[:k]
    rows = np.empty((k, n))
    filled = 0
    for band, keep in pieces:
        taken = min(int(keep.sum()), k - filled)
        np.take(band.eigenvectors.T, np.flatnonzero(keep)[:taken], axis=0,
                out=rows[filled:filled + taken])
        filled += taken
    return values, rows.T


def _columns(rows):
    """(n, c) eigenvectors as the transpose of C-ordered rows: each vector is contiguous."""
    return np.ascontiguousarray(rows).T


def _miscounted(stiffness, mass, bands, pieces, k: int):
    """(bands, missing): the bands around the first shift whose count disagrees, or ([], 0).

    Sylvester's count at each shift and at a cut just above λ_(k−1) must equal the number of
    accepted eigenvalues below it. Between two shifts with agreeing counts nothing is missing;
    a copy of a multiple eigenvalue that a Krylov space did not see shows up as a shortfall.
    """
    accepted = np.concatenate([band.eigenvalues[keep] for band, keep in pieces])
    counted = [(band.shift, band.below) for band in bands]
    if max(band.shift for band in bands) <= accepted[k - 1]:
        # One more count above λ_(k−1), in the widest gap there, where it is unambiguous.
        points = np.append(accepted[k - 1:], pieces[-1][0].upper)
        widest = int(np.argmax(np.diff(points)))
        top = (points[widest] + points[widest + 1]) / 2
        counted.append((top, _ShiftInvert(stiffness, mass, top).below))
    low = -np.inf
    for shift, below in counted:
        if below is None:
            continue
        found = int((accepted < shift).sum())
        if found > below:
            raise InternalError(f"eigen-solver: {below} eigenvalues lie below {shift:.4g} but "
                                f"{found} were found", remedy={"solver": "eigsh"})
        if found < below:
            wrong = [band for band in bands if band.lower < shift and band.upper > low]
            return wrong, (below - found)
        low = shift
    return [], 0


def _verify(values, pieces, bands):
    """Residual of every accepted pair, and inertia counts against the accepted eigenvalues."""
    worst = max(float(band.residuals[keep].max(initial=0)) for band, keep in pieces)
    if not worst <= RESIDUAL_TOLERANCE:
        raise InternalError(f"eigen-solver: residual {worst:.1e} above tolerance",
                            remedy={"solver": "eigsh"})
    for band in bands:
        if band.below is not None and band.shift < values[-1]:
            accepted = int((values < band.shift).sum())
            if accepted != band.below:
                raise InternalError(
                    f"eigen-solver: {band.below} eigenvalues lie below {band.shift:.4g} but "
                    f"{accepted} were found", remedy={"solver": "eigsh"})


def _solve_piece(stiffness, mass, k: int, progress=None):
    """`solve_bands` on one connected operator; dense when k reaches n − 1, and `solve_eigsh`
    for bands it cannot certify."""
    if k >= stiffness.shape[0] - 1:  # a small piece of a mesh in pieces: all of its spectrum
        return _dense(stiffness, mass, k)
    try:
        return solve_bands(stiffness, mass, k, progress)
    except InternalError:  # bands it cannot certify (many copies of multiple eigenvalues)
        return solve_eigsh(stiffness, mass, k, progress)


def solve(stiffness, mass, k: int, solver: str = "bands", progress=None):
    """Dispatch to `solve_bands` or `solve_eigsh`; see SOLVERS.

    "bands" solves each connected component of L's graph on its own, and identical components
    once (`harmonic.components`); "eigsh", the baseline, solves the whole operator at once.

    Parameters
    ----------
    stiffness : L.
    mass : (n,).
    k : pairs.
    solver : "bands" or "eigsh".
    progress : optional callable(pairs done).

    Returns
    -------
    (eigenvalues (k,) ascending, eigenvectors (n, k) M-orthonormal).
    """
    if solver == "bands":
        check_request(stiffness.shape[0], k)
        return solve_components(stiffness, mass, k, _solve_piece, progress)
    if solver == "eigsh":
        return solve_eigsh(stiffness, mass, k, progress)
    raise InputError(f"unknown solver '{solver}' (expected one of {', '.join(SOLVERS)})")
