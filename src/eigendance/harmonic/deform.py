"""The deformation kernel: X_φ = X + U((φ − 1) ⊙ X̃) for batches of filters (docs/design.md#filter).

Every Python path that moves a mesh by its harmonics goes through `Deformer`: the basis's
`filter_positions`, animation files, gallery calibration and exports. The browser runs the same
formula on the GPU (web/src/deform.ts). U is a dense (n, k) array, or a reduced basis's
P U_r (docs/design.md#reduced-basis), applied as P (U_r W) without forming U.
"""

from __future__ import annotations

import numpy as np


class Deformer:
    """rest + U((φ − 1) ⊙ X̃) for filters φ, one matrix product per batch.

    Parameters
    ----------
    eigenvectors : (n, k) U, or a `ReducedHarmonics` (U = P U_r).
    coefficients : (k, 3) X̃ = Uᵀ M X, in the units the positions should have.
    rest : (n, 3) positions for φ ≡ 1 (X, in the same units), or None for displacements only.

    Example
    -------
    >>> U = np.eye(3)[:, :2]; X = np.arange(9.0).reshape(3, 3)
    >>> Deformer(U, U.T @ X, X)(np.array([[1.0, 1.0]]))[0].tolist() == X.tolist()
    True
    """

    def __init__(self, eigenvectors: np.ndarray, coefficients: np.ndarray,
                 rest: np.ndarray | None = None):
        self.eigenvectors = eigenvectors
        self.reduced = None if isinstance(eigenvectors, np.ndarray) else eigenvectors
        self.coefficients_rows = np.ascontiguousarray(coefficients.T)  # (3, k)
        self.rest = None if rest is None else np.asarray(rest)
        self.rest_rows = None if rest is None else np.ascontiguousarray(self.rest.T)

    @property
    def n(self) -> int:
        """Vertices n."""
        if self.reduced is not None:
            return self.reduced.interpolation.n
        return self.eigenvectors.shape[0]

    @property
    def k(self) -> int:
        """Harmonics k."""
        return self.coefficients_rows.shape[1]

    def __call__(self, phi: np.ndarray, out: np.ndarray | None = None) -> np.ndarray:
        """phi (C, k) → positions (C, n, 3), written into `out` (any float dtype) if given.

        Computed as Wᵀ·Uᵀ (3C × n; Uᵀ is a view, BLAS transposes): each row is one coordinate
        of one filter, so the scatter into (C, n, 3) reads whole rows (faster than U·W's
        (n, 3C) layout; measured in benchmarks/bench_animate.py).
        """
        phi = np.atleast_2d(np.asarray(phi, dtype=np.float64))
        count = len(phi)
        weights = (phi - 1.0)[:, None, :] * self.coefficients_rows[None]  # (C, 3, k)
        if out is None:
            out = np.empty((count, self.n, 3))
        if self.reduced is not None:
            return self._reduced(weights, out)
        moved = (weights.reshape(3 * count, self.k) @ self.eigenvectors.T).reshape(count, 3, -1)
        for axis in range(3):  # contiguous reads, stride-3 writes: faster than one transpose
            if self.rest_rows is None:
                np.copyto(out[:, :, axis], moved[:, axis, :], casting="unsafe")
            else:
                np.add(moved[:, axis, :], self.rest_rows[axis], out=out[:, :, axis],
                       casting="unsafe")
        return out

    def _reduced(self, weights: np.ndarray, out: np.ndarray) -> np.ndarray:
        """P (U_r W): the coarse displacements (m, 3C), then ≤ 8 of them per vertex."""
        count = len(weights)
        coarse = self.reduced.coarse @ weights.reshape(3 * count, self.k).T  # (m, 3C)
        moved = (self.reduced.interpolation.matrix() @ coarse).reshape(self.n, count, 3)
        if self.rest is None:
            np.copyto(out, moved.transpose(1, 0, 2), casting="unsafe")
        else:
            np.add(moved.transpose(1, 0, 2), self.rest, out=out, casting="unsafe")
        return out
