"""The mass matrix M of L u = λ M u as the eigen-solvers use it (docs/design.md#eigensolver).

M is diagonal for a mesh (its vertex areas, a vector) or a sparse symmetric positive definite
matrix for a reduced basis (PᵀMP, docs/design.md#reduced-basis). With a factor M = R Rᵀ the
problem is the symmetric standard one A y = λ y, A = R⁻¹ L R⁻ᵀ, y = Rᵀ u: the solvers work
with y. For a diagonal M, R = M^½; for a sparse M, R = Πᵀ(I + F) D^½ from the LDLᵀ
factorisation of qdldl (F strictly lower triangular, Π the fill-reducing permutation).
"""

from __future__ import annotations

import numpy as np
import qdldl
import scipy.sparse as sp


class Mass:
    """M = R Rᵀ, diagonal or sparse SPD, with the products the eigen-solvers need.

    Parameters
    ----------
    mass : (n,) positive vertex areas (diagonal M), or a sparse (n, n) symmetric positive
        definite matrix.

    Example
    -------
    >>> M = Mass(sp.csc_matrix([[2.0, 1.0], [1.0, 2.0]]))
    >>> u = np.array([1.0, -1.0])
    >>> bool(np.allclose(M.from_y(M.to_y(u)), u)), float(M.norms(u[:, None])[0])
    (True, 2.0)
    """

    def __init__(self, mass):
        if sp.issparse(mass):
            self.diagonal = None
            self.matrix = sp.csc_matrix(mass, dtype=np.float64)
        else:
            self.diagonal = np.asarray(mass, dtype=np.float64).reshape(-1)
            self.matrix = None
            self._root = np.sqrt(self.diagonal)
        self._factor = None  # (qdldl solver, R as CSR) of a sparse M, built when first needed

    def __getstate__(self):  # band workers get a copy: the factorisation is not picklable
        state = dict(self.__dict__)
        state["_factor"] = None
        return state

    @property
    def n(self) -> int:
        """Rows n."""
        return len(self.diagonal) if self.diagonal is not None else self.matrix.shape[0]

    @property
    def total(self) -> float:
        """1ᵀ M 1: the area of the surface."""
        if self.diagonal is not None:
            return float(self.diagonal.sum())
        return float(self.matrix.sum())

    def sparse(self) -> sp.csc_matrix:
        """M as a sparse matrix.

        Returns
        -------
        (n, n) csc.
        """
        return sp.diags(self.diagonal).tocsc() if self.diagonal is not None else self.matrix

    def times(self, vectors: np.ndarray) -> np.ndarray:
        """M x.

        Parameters
        ----------
        vectors : (n,) or (n, c) x.

        Returns
        -------
        M x, the shape of x.
        """
        if self.diagonal is not None:
            return self.diagonal.reshape((-1,) + (1,) * (np.ndim(vectors) - 1)) * vectors
        return self.matrix @ vectors

    def shifted(self, stiffness, shift: float) -> sp.csc_matrix:
        """L − σM (the same sparsity for every σ).

        Parameters
        ----------
        stiffness : L (n, n) sparse.
        shift : σ.

        Returns
        -------
        (n, n) csc.
        """
        return (stiffness - shift * self.sparse()).tocsc()

    def norms(self, vectors: np.ndarray) -> np.ndarray:
        """uᵀ M u of each column.

        Parameters
        ----------
        vectors : (n, c).

        Returns
        -------
        (c,).
        """
        return np.einsum("ij,ij->j", vectors, self.times(vectors))

    def _factors(self):
        if self._factor is None:
            solver = qdldl.Solver(self.matrix)
            lower, pivots, order = solver.factors()
            if not np.all(pivots > 0):
                raise ValueError("the mass matrix is not positive definite")
            n = self.n
            identity = sp.identity(n, format="csc")
            permutation = sp.csr_matrix((np.ones(n), (order, np.arange(n))), (n, n))
            factor = (permutation @ (identity + lower) @ sp.diags(np.sqrt(pivots))).tocsr()
            self._factor = (solver, factor, factor.T.tocsr())
        return self._factor

    def to_y(self, vectors: np.ndarray) -> np.ndarray:
        """y = Rᵀ u.

        Parameters
        ----------
        vectors : (n,) or (n, c) u.

        Returns
        -------
        y, the shape of u.
        """
        if self.diagonal is not None:
            return self._root.reshape((-1,) + (1,) * (np.ndim(vectors) - 1)) * vectors
        return self._factors()[2] @ vectors

    def factor_times(self, vectors: np.ndarray) -> np.ndarray:
        """R y.

        Parameters
        ----------
        vectors : (n,) or (n, c) y.

        Returns
        -------
        R y, the shape of y.
        """
        if self.diagonal is not None:
            return self._root.reshape((-1,) + (1,) * (np.ndim(vectors) - 1)) * vectors
        return self._factors()[1] @ vectors

    def from_y(self, vectors: np.ndarray) -> np.ndarray:
        """u = R⁻ᵀ y = M⁻¹ R y.

        Parameters
        ----------
        vectors : (n,) or (n, c) y.

        Returns
        -------
        u, the shape of y.
        """
        if self.diagonal is not None:
            return vectors / self._root.reshape((-1,) + (1,) * (np.ndim(vectors) - 1))
        solver, factor, _ = self._factors()
        products = factor @ vectors
        if products.ndim == 1:
            return solver.solve(products)
        return np.column_stack([solver.solve(column) for column in products.T])


def as_mass(mass) -> Mass:
    """`mass` as a `Mass`.

    Parameters
    ----------
    mass : (n,) areas, a sparse (n, n) matrix, or a `Mass` (returned as is).

    Returns
    -------
    Mass.
    """
    return mass if isinstance(mass, Mass) else Mass(mass)
