"""HarmonicBasis: the manifold harmonics of a mesh and the spectral filter (DESIGN §2, §8).

U = [u_0 … u_{k-1}] solves L u = λ M u with Uᵀ M U = I. The coefficients X̃ = Uᵀ M X (k×3) and
the remainder D = X − U X̃ give filtered positions X_φ = X + U((φ − 1) ⊙ X̃); φ ≡ 1 returns X.
"""

from __future__ import annotations

import os
import time
from dataclasses import dataclass

import numpy as np

from eigendance.errors import EigendanceError
from eigendance.mesh import Mesh

FORMAT_KEYS = ("vertices", "faces", "center", "scale", "mass", "eigenvalues", "eigenvectors",
               "coefficients", "residual", "laplacian")


@dataclass
class HarmonicBasis:
    """The first k manifold harmonics of a normalised mesh, with everything the filter needs.

    Arrays follow the basis file of DESIGN §8: vertices (n,3) normalised, faces (m,3), center
    (3,), scale (), mass (n,), eigenvalues (k,) ascending in (length)^-2, eigenvectors (n,k),
    coefficients (k,3), residual (n,3), laplacian "cotan" | "robust".
    """

    vertices: np.ndarray
    faces: np.ndarray
    center: np.ndarray
    scale: float
    mass: np.ndarray
    eigenvalues: np.ndarray
    eigenvectors: np.ndarray
    coefficients: np.ndarray
    residual: np.ndarray
    laplacian: str = "cotan"
    seconds: float = 0.0  # time the eigen-solve took (not saved)

    @property
    def k(self) -> int:
        return len(self.eigenvalues)

    @property
    def n(self) -> int:
        return len(self.vertices)

    @property
    def frequencies(self) -> np.ndarray:
        """Mesh frequency √λ_ν of each harmonic (length^-1)."""
        return np.sqrt(np.maximum(self.eigenvalues, 0))

    @classmethod
    def from_arrays(cls, mesh: Mesh, eigenvalues, eigenvectors, mass, laplacian="cotan",
                    seconds=0.0) -> HarmonicBasis:
        coefficients = eigenvectors.T @ (mass[:, None] * mesh.vertices)
        residual = mesh.vertices - eigenvectors @ coefficients
        return cls(mesh.vertices, mesh.faces, mesh.center, mesh.scale, mass, eigenvalues,
                   eigenvectors, coefficients, residual, laplacian, seconds)

    @classmethod
    def from_mesh(cls, mesh: Mesh | str | os.PathLike, k: int, laplacian: str = "cotan",
                  solver: str = "bands", cache: bool = True, progress=None) -> HarmonicBasis:
        """Compute (or fetch from the cache) the first k harmonics of a mesh or mesh file.

        progress: optional callable(done) told how many of the k eigenpairs are accepted so far.
        """
        from eigendance import cache as basis_cache
        from eigendance.eigen import solve
        from eigendance.laplacian import laplacian as build_laplacian
        from eigendance.mesh import load_mesh

        if not isinstance(mesh, Mesh):
            mesh = load_mesh(mesh)
        if laplacian == "cotan" and (count := mesh.non_manifold_edge_count()):
            raise EigendanceError(f"{mesh.name}: {count} non-manifold edges (shared by more than "
                                  "two triangles); use --laplacian robust for such meshes")
        key = basis_cache.key(mesh, k, laplacian) if cache else None
        if key is not None and (found := basis_cache.fetch(key)) is not None:
            return found
        stiffness, mass = build_laplacian(mesh.vertices, mesh.faces, laplacian)
        start = time.perf_counter()
        eigenvalues, eigenvectors = solve(stiffness, mass, k, solver, progress)
        basis = cls.from_arrays(mesh, eigenvalues, eigenvectors, mass, laplacian,
                                time.perf_counter() - start)
        if key is not None:
            basis_cache.store(key, basis)
        return basis

    def filter_positions(self, phi) -> np.ndarray:
        """Filtered normalised positions X + U((φ − 1) ⊙ X̃) for φ of shape (..., k) → (..., n, 3).

        All leading axes (gallery items, frames) go through a single matrix product U · W.
        """
        phi = np.asarray(phi, dtype=np.float64)
        if phi.shape[-1:] != (self.k,):
            raise EigendanceError(f"filter has {phi.shape[-1:]} values per item; "
                                  f"the basis has k = {self.k}")
        batch = phi.shape[:-1]
        # weights: (k, 3·items) = (φ − 1) ⊙ X̃ per item, stacked side by side.
        weights = (phi.reshape(-1, self.k, 1) - 1) * self.coefficients
        weights = weights.transpose(1, 0, 2).reshape(self.k, -1)
        moved = (self.eigenvectors @ weights).reshape(self.n, -1, 3).transpose(1, 0, 2)
        return (self.vertices + moved).reshape(*batch, self.n, 3)

    def to_original(self, positions: np.ndarray) -> np.ndarray:
        """Map normalised positions back to the mesh file's coordinates."""
        return positions * self.scale + self.center

    def save(self, path: str | os.PathLike) -> None:
        """Write the basis file of DESIGN §8 atomically (a temporary file, then a rename)."""
        from eigendance.files import atomic_save_npz

        atomic_save_npz(path, **{name: getattr(self, name) for name in FORMAT_KEYS})

    @classmethod
    def load(cls, path: str | os.PathLike) -> HarmonicBasis:
        """Read a basis file; a missing key or inconsistent shape raises EigendanceError."""
        from eigendance.files import load_npz

        data = load_npz(path, FORMAT_KEYS)
        basis = cls(**{name: data[name] for name in FORMAT_KEYS})
        basis.scale = float(basis.scale)
        basis.laplacian = str(basis.laplacian)
        n, k = basis.eigenvectors.shape
        if (basis.vertices.shape != (n, 3) or basis.eigenvalues.shape != (k,)
                or basis.coefficients.shape != (k, 3) or basis.mass.shape != (n,)):
            raise EigendanceError(f"{os.fspath(path)}: inconsistent array shapes in basis file")
        return basis
