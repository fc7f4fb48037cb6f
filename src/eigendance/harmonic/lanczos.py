"""Lanczos iteration with full re-orthogonalisation, for one shift-invert band
(docs/design.md#eigensolver).

For a symmetric operator B (here B = (A − σI)⁻¹ with A = M^-½ L M^-½) the Lanczos recurrence
builds an orthonormal basis V_m of the Krylov space span{v, Bv, …, B^(m−1) v} in which B is the
tridiagonal T_m = V_mᵀ B V_m (diagonal α, off-diagonal β). If T_m s = θ s, the Ritz pair
(θ, y = V_m s) has residual ‖B y − θ y‖ = |β_m s_m|, so convergence is read from T_m alone.

Why not ARPACK: it re-orthogonalises the same way but computes the Ritz vectors with level-2
BLAS (`dseupd`, a quarter of a band's time); here they are one matrix product, and the
iteration stops as soon as the wanted pairs have converged, with no restart.
"""

from __future__ import annotations

import numpy as np
import scipy.linalg as sla

# DGKS criterion: a second Gram-Schmidt pass when the first removed more than ~30% of the norm.
REORTHOGONALISE = 0.717


def lanczos_extreme(apply, n: int, count: int, *, tol: float = 1e-13,
                    max_steps: int | None = None, seed: int = 0, deflate=None):
    """The `count` eigenpairs of largest |θ| of the symmetric operator `apply` (R^n → R^n).

    Runs until every wanted Ritz pair satisfies |β_m s_m| ≤ tol·|θ|, checking T_m every few
    steps. Returns (theta (count,), vectors (n, count) orthonormal), or None when `max_steps`
    (default 3·count + 50) were not enough. A Krylov space from one start vector holds one
    direction per eigenspace, so copies of a multiple eigenvalue can be missed; callers check
    the count and find the missing copies again with `deflate` = the known eigenvectors (rows,
    orthonormal), which the iteration then stays orthogonal to.

    Parameters
    ----------
    apply : x (n,) → A x.
    n : the dimension.
    count : pairs wanted.
    tol : the relative residual accepted.
    max_steps : the most steps (default 3·count + 50).
    seed : of the start vector.
    deflate : (p, n) orthonormal rows kept out, or None.

    Returns
    -------
    (theta, vectors), or None.
    """
    max_steps = min(n - (0 if deflate is None else len(deflate)), max_steps or 3 * count + 50)
    basis = np.empty((max_steps + 1, n))  # Lanczos vectors as rows: each pass is one gemv
    alpha, beta = np.zeros(max_steps), np.zeros(max_steps)
    rng = np.random.default_rng(seed)
    known = np.empty((0, n)) if deflate is None else deflate
    basis[0] = _orthogonal_start(rng, known)
    next_check = count
    for j in range(max_steps):
        w = apply(basis[j])
        w -= (known @ w) @ known
        previous = basis[:j + 1]
        h = previous @ w
        w -= h @ previous
        if np.linalg.norm(w) < REORTHOGONALISE * np.linalg.norm(h):
            correction = previous @ w
            w -= correction @ previous
            h += correction
        alpha[j], beta[j] = h[j], np.linalg.norm(w)
        if beta[j] <= 1e-10 * np.abs(h).max() and j + 1 < max_steps:
            # Invariant subspace: go on from a random direction orthogonal to it (β_j = 0).
            w = _orthogonal_start(rng, np.vstack([known, previous]))
            beta[j] = 0.0
            basis[j + 1] = w
        else:
            basis[j + 1] = w / beta[j]
        steps = j + 1
        if steps < next_check and steps < max_steps:
            continue
        theta, ritz = sla.eigh_tridiagonal(alpha[:steps], beta[:steps - 1])
        wanted = np.argsort(-np.abs(theta))[:count]
        error = np.abs(beta[j] * ritz[-1, wanted])
        converged = int((error <= tol * np.abs(theta[wanted])).sum())
        if converged == count:
            vectors = (ritz[:, wanted].T @ basis[:steps]).T  # Ritz vectors: one GEMM
            return theta[wanted], vectors
        # Pairs converge at about one every two steps: look again after an eighth of the rest.
        next_check = steps + max(2, (count - converged) // 4)
    return None


def _unit(vector):
    return vector / np.linalg.norm(vector)


def _orthogonal_start(rng, previous):
    w = rng.standard_normal(previous.shape[1])
    for _ in range(2):
        w -= (previous @ w) @ previous
    return _unit(w)
