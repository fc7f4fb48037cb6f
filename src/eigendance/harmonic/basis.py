"""HarmonicBasis: the manifold harmonics of a mesh (docs/design.md#basis).

U = [u_0 … u_{k-1}] solves L u = λ M u with Uᵀ M U = I. The coefficients X̃ = Uᵀ M X (k×3) and
the remainder D = X − U X̃ give filtered positions X_φ = X + U((φ − 1) ⊙ X̃); φ ≡ 1 returns X.
A large mesh gets a reduced basis (docs/design.md#reduced-basis): U = P U_r, never formed.
"""

from __future__ import annotations

import os
from dataclasses import dataclass

import numpy as np

from eigendance.errors import InputError
from eigendance.files import checked_array, load_npz
from eigendance.geometry import MAX_COORDINATE, bounding_box_diagonal
from eigendance.harmonic.construction import (
    CONSTRUCTIONS,
    choose_construction,
    exact_pairs,
    reduced_pairs,
)
from eigendance.harmonic.deform import Deformer
from eigendance.harmonic.laplacian import LAPLACIANS
from eigendance.harmonic.mesh import Mesh, load_mesh
from eigendance.harmonic.reduced import (
    REDUCED_KEYS,
    ReducedHarmonics,
    check_reduced,
    reduced_arrays,
    reduced_from_arrays,
)
from eigendance.writes import atomic_save_npz

FORMAT_KEYS = ("vertices", "faces", "center", "scale", "mass", "eigenvalues", "eigenvectors",
               "coefficients", "residual", "laplacian")
# A reduced basis file holds REDUCED_KEYS instead of the eigenvectors.
COMMON_KEYS = tuple(name for name in FORMAT_KEYS if name != "eigenvectors")


@dataclass
class HarmonicBasis:
    """The first k manifold harmonics of a normalised mesh, with everything the filter needs.

    Arrays follow the basis file (docs/design.md#basis-file): vertices (n,3) normalised, faces
    (m,3), center (3,), scale (), mass (n,) vertex areas, eigenvalues (k,) ascending in
    (length)^-2, eigenvectors (n,k), coefficients (k,3), residual (n,3), laplacian "cotan" |
    "robust". Original coordinates are ``vertices * scale + center``.

    Parameters
    ----------
    vertices, faces, center, scale, mass, eigenvalues, eigenvectors, coefficients, residual,
    laplacian : as above.
    seconds : how long the solve took (0 for a basis read from a file).

    Example
    -------
    >>> import trimesh
    >>> sphere = trimesh.creation.icosphere(2)
    >>> basis = HarmonicBasis.from_mesh(Mesh.from_arrays(sphere.vertices, sphere.faces), k=9,
    ...                                 cache=False)
    >>> (np.round(basis.eigenvalues[:4], 1) + 0.0).tolist()   # unit sphere: l(l+1) = 0, 2, 2, 2
    [0.0, 2.0, 2.0, 2.0]
    >>> bool(np.allclose(basis.filter_positions(np.ones(9)), basis.vertices))   # φ ≡ 1
    True
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
    seconds: float = 0.0  # time the eigen-solve took (not saved; 0 when it came from the cache)
    appearance: object = None  # the mesh's assets.Appearance (not saved; docs/design.md#appearance)
    reduced: ReducedHarmonics | None = None  # a reduced basis: U = P U_r; eigenvectors is None

    @property
    def k(self) -> int:
        """Harmonics k."""
        return len(self.eigenvalues)

    @property
    def n(self) -> int:
        """Vertices n."""
        return len(self.vertices)

    @property
    def construction(self) -> str:
        """"exact" or "reduced" (docs/design.md#reduced-basis)."""
        return "exact" if self.reduced is None else "reduced"

    @property
    def vectors(self):
        """U as the deformation kernel takes it: the (n, k) array, or the `ReducedHarmonics`."""
        return self.eigenvectors if self.reduced is None else self.reduced

    def harmonics(self, targets) -> np.ndarray:
        """U[:, targets], for an exact or a reduced basis (only these columns are formed).

        Parameters
        ----------
        targets : (t,) harmonic indices.

        Returns
        -------
        (n, t).
        """
        if self.reduced is None:
            return self.eigenvectors[:, np.asarray(targets, dtype=np.int64)]
        return self.reduced.columns(targets)

    @property
    def frequencies(self) -> np.ndarray:
        """Mesh frequency √λ_ν of each harmonic (length^-1)."""
        return np.sqrt(np.maximum(self.eigenvalues, 0))

    @classmethod
    def from_arrays(cls, mesh: Mesh, eigenvalues, eigenvectors, mass, laplacian="cotan",
                    seconds=0.0, reduced: ReducedHarmonics | None = None) -> HarmonicBasis:
        """The basis of `mesh` from a solve's eigenpairs: X̃ = Uᵀ M X, D = X − U X̃.

        Parameters
        ----------
        mesh : the normalised mesh.
        eigenvalues : (k,).
        eigenvectors : (n, k), M-orthonormal; None for a reduced basis.
        mass : (n,).
        laplacian : "cotan" or "robust".
        seconds : how long the solve took.
        reduced : a reduced basis's `ReducedHarmonics` (U = P U_r), or None.

        Returns
        -------
        HarmonicBasis.
        """
        weighted = mass[:, None] * mesh.vertices
        if reduced is None:
            coefficients = eigenvectors.T @ weighted
            residual = mesh.vertices - eigenvectors @ coefficients
        else:
            coefficients = reduced.transpose_lift(weighted)
            residual = mesh.vertices - reduced.lift(coefficients)
        return cls(mesh.vertices, mesh.faces, mesh.center, mesh.scale, mass, eigenvalues,
                   eigenvectors, coefficients, residual, laplacian, seconds, mesh.appearance,
                   reduced)

    @classmethod
    def from_mesh(cls, mesh: Mesh | str | os.PathLike, k: int, laplacian: str = "cotan",
                  solver: str = "bands", cache: bool = True, progress=None,
                  construction: str = "auto", samples: int | None = None) -> HarmonicBasis:
        """Compute (or fetch from the disk cache) the first k harmonics of a mesh or mesh file.

        Parameters
        ----------
        mesh : a `Mesh` or the path of a mesh file (OBJ, PLY, OFF, STL, glTF/GLB).
        k : number of harmonics, 1 ≤ k < n.
        laplacian : "cotan" (needs a manifold mesh) or "robust".
        solver : "bands" (spectrum slicing) or "eigsh" (the naive baseline); exact bases only.
        cache : read and write the disk cache (`basis_key`, `reduced_key` name the entry).
        progress : optional callable(done) told how many eigenpairs are accepted so far.
        construction : "exact", "reduced" (docs/design.md#reduced-basis) or "auto"
            (`choose_construction`: exact when it fits the time and memory rule).
        samples : samples of a reduced basis (default `reduced.sample_count`).

        Returns
        -------
        HarmonicBasis with k harmonics, verified: L u = λ M u and Uᵀ M U = I (a reduced basis:
        L_r c = λ M_r c and Uᵀ M U = U_rᵀ M_r U_r = I).
        """
        if construction not in CONSTRUCTIONS:
            raise InputError(f"unknown construction '{construction}' (expected one of "
                             f"{', '.join(CONSTRUCTIONS)})")
        if not isinstance(mesh, Mesh):
            mesh = load_mesh(mesh)
        if laplacian == "cotan" and (count := mesh.non_manifold_edge_count()):
            raise InputError(f"{mesh.name}: {count} non-manifold edges (shared by more than two "
                             "triangles); the cotangent Laplacian needs a manifold mesh",
                             remedy={"laplacian": "robust"})
        if construction == "auto":
            construction = choose_construction(mesh.n, k, samples)
        if construction == "reduced":
            eigenvalues, mass, reduced, seconds = reduced_pairs(mesh, k, laplacian, samples,
                                                                cache, progress)
            eigenvectors = None
        else:
            eigenvalues, eigenvectors, mass, seconds = exact_pairs(mesh, k, laplacian, solver,
                                                                   cache, progress)
            reduced = None
        if progress is not None:
            progress(k)
        return cls.from_arrays(mesh, eigenvalues, eigenvectors, mass, laplacian, seconds,
                               reduced)

    @property
    def diagonal(self) -> float:
        """Bounding-box diagonal of the normalised mesh (≤ 2√3)."""
        return bounding_box_diagonal(self.vertices)

    def displacements(self, phi) -> np.ndarray:
        """U((φ − 1) ⊙ X̃) for filters (S, k) → (S, n, 3), normalised units.

        Parameters
        ----------
        phi : (S, k).

        Returns
        -------
        (S, n, 3).
        """
        return Deformer(self.vectors, self.coefficients)(phi)

    def motion_gram(self, targets) -> np.ndarray:
        """G_νμ = mean over vertices of ⟨D_ν(x), D_μ(x)⟩ for the harmonics `targets` (T,) → (T, T).

        D_ν = u_ν X̃_νᵀ (n, 3) is the displacement of harmonic ν per unit of φ_ν − 1, so a filter
        moves the vertices by RMS √((φ − 1)ᵀ G (φ − 1)) (normalised units; the gallery's
        calibration, docs/design.md#gallery).

        Parameters
        ----------
        targets : (T,) harmonic indices.

        Returns
        -------
        (T, T), normalised units squared.
        """
        targets = np.asarray(targets, dtype=np.int64)
        if self.reduced is None:
            columns = self.eigenvectors[:, targets]
            overlaps = columns.T @ columns
        else:
            overlaps = self.reduced.gram(targets)
        return overlaps * (self.coefficients[targets] @ self.coefficients[targets].T) / self.n

    def deformer(self, original: bool = False) -> Deformer:
        """The deformation kernel for this basis, in normalised or original coordinates.

        Parameters
        ----------
        original : positions in the file's coordinates (else normalised).

        Returns
        -------
        Deformer.
        """
        if original:
            return Deformer(self.vectors, self.coefficients * self.scale,
                            self.to_original(self.vertices))
        return Deformer(self.vectors, self.coefficients, self.vertices)

    def filter_positions(self, phi) -> np.ndarray:
        """Filtered normalised positions X + U((φ − 1) ⊙ X̃) for φ of shape (..., k) → (..., n, 3).

        All leading axes (gallery items, frames) go through a single matrix product.

        Parameters
        ----------
        phi : (…, k).

        Returns
        -------
        (…, n, 3) normalised.
        """
        phi = np.asarray(phi, dtype=np.float64)
        if phi.shape[-1:] != (self.k,):
            raise InputError(f"the filter has {phi.shape[-1:]} values per item; "
                             f"the basis has k = {self.k}")
        batch = phi.shape[:-1]
        return self.deformer()(phi.reshape(-1, self.k)).reshape(*batch, self.n, 3)

    def to_original(self, positions: np.ndarray) -> np.ndarray:
        """Map normalised positions back to the mesh file's coordinates.

        Parameters
        ----------
        positions : (…, n, 3) normalised.

        Returns
        -------
        (…, n, 3) in the file's unit.
        """
        return positions * self.scale + self.center

    def save(self, path: str | os.PathLike) -> None:
        """Write the basis file atomically (a temporary file, then a rename).

        Parameters
        ----------
        path : the .npz to write.
        """
        arrays = {name: getattr(self, name) for name in COMMON_KEYS}
        if self.reduced is None:
            arrays["eigenvectors"] = self.eigenvectors
        else:
            arrays.update(reduced_arrays(self.reduced))
        atomic_save_npz(path, **arrays)

    @classmethod
    def load(cls, path: str | os.PathLike) -> HarmonicBasis:
        """Read a basis file, checked: InputError naming the field for anything that is not a
        basis (a missing field, a wrong type or shape, NaN, faces past the vertices, a
        coefficient or remainder that does not follow from the vertices and eigenvectors).

        Parameters
        ----------
        path : a basis file.

        Returns
        -------
        HarmonicBasis.
        """
        path = os.fspath(path)
        data = load_npz(path, COMMON_KEYS)
        fields = {"vertices": checked_array(data, "vertices", path, shape=(None, 3)),
                  "eigenvalues": checked_array(data, "eigenvalues", path, shape=(None,))}
        n, k = len(fields["vertices"]), len(fields["eigenvalues"])
        if n < 3 or k < 1:
            raise InputError(f"{path}: a basis needs at least 3 vertices and 1 harmonic, "
                             f"has {n} and {k}")
        for name, shape in (("center", (3,)), ("scale", ()), ("mass", (n,)),
                            ("coefficients", (k, 3)), ("residual", (n, 3))):
            fields[name] = checked_array(data, name, path, shape=shape)
        fields["faces"] = faces = checked_array(data, "faces", path, "int", (None, 3))
        fields["laplacian"] = checked_array(data, "laplacian", path, "str")
        fields["scale"] = float(fields["scale"])
        if len(faces) == 0 or faces.min() < 0 or faces.max() >= n:
            raise InputError(f"{path}: faces must be triangles of vertex indices 0 … {n - 1}")
        if fields["laplacian"] not in LAPLACIANS:
            raise InputError(f"{path}: laplacian must be one of {', '.join(LAPLACIANS)}")
        if not fields["scale"] > 0 or not np.all(fields["mass"] > 0):
            raise InputError(f"{path}: scale and mass must be positive")
        fields["eigenvectors"], fields["reduced"] = _load_vectors(data, path, n, k)
        basis = cls(**fields)
        if not np.abs(basis.to_original(basis.vertices)).max() <= MAX_COORDINATE:
            raise InputError(f"{path}: original coordinates (vertices·scale + center) beyond "
                             f"±{MAX_COORDINATE:.0e}")
        expected = cls.from_arrays(Mesh(basis.vertices, basis.faces, basis.center, basis.scale,
                                        np.arange(n)), basis.eigenvalues, basis.eigenvectors,
                                   basis.mass, reduced=basis.reduced)
        for name in ("coefficients", "residual"):
            stored, rebuilt = getattr(basis, name), getattr(expected, name)
            if not np.abs(stored - rebuilt).max() <= 1e-8 * (1 + np.abs(rebuilt).max()):
                raise InputError(f"{path}: {name} do not follow from the vertices, mass and "
                                 "eigenvectors (not a basis file written by eigendance)")
        return basis


def _load_vectors(data: dict, path: str, n: int, k: int):
    """(eigenvectors, None) of an exact basis file or (None, ReducedHarmonics) of a reduced
    one, checked."""
    if "eigenvectors" in data:
        return checked_array(data, "eigenvectors", path, shape=(n, k)), None
    missing = [name for name in REDUCED_KEYS if name not in data]
    if missing:
        raise InputError(f"{path}: missing eigenvectors (or {', '.join(missing)} of a reduced "
                         "basis); not an eigendance basis file")
    arrays = {"samples": checked_array(data, "samples", path, "int", (None,)),
              "interpolation_indices": checked_array(data, "interpolation_indices", path,
                                                     "int", (n, None)),
              "interpolation_weights": checked_array(data, "interpolation_weights", path,
                                                     shape=(n, None)),
              "coarse_eigenvectors": checked_array(data, "coarse_eigenvectors", path,
                                                   shape=(None, k))}
    problem = check_reduced(arrays, n, k)
    if problem:
        raise InputError(f"{path}: reduced basis: {problem}")
    return None, reduced_from_arrays(arrays)


