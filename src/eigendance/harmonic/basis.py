"""HarmonicBasis: the manifold harmonics of a mesh (docs/design.md#basis).

U = [u_0 … u_{k-1}] solves L u = λ M u with Uᵀ M U = I. The coefficients X̃ = Uᵀ M X (k×3) and
the remainder D = X − U X̃ give filtered positions X_φ = X + U((φ − 1) ⊙ X̃); φ ≡ 1 returns X.
A large mesh gets a reduced basis (docs/design.md#reduced-basis): U = P U_r, never formed.
"""

from __future__ import annotations

import hashlib
import os
import time
from dataclasses import dataclass

import numpy as np

from eigendance.errors import InputError
from eigendance.files import checked_array, load_npz
from eigendance.geometry import MAX_COORDINATE, bounding_box_diagonal
from eigendance.harmonic.cache import DiskCache
from eigendance.harmonic.deform import Deformer
from eigendance.harmonic.eigensolver import RESIDUAL_TOLERANCE, SOLVER_VERSION, residuals, solve
from eigendance.harmonic.laplacian import LAPLACIANS
from eigendance.harmonic.laplacian import laplacian as build_laplacian
from eigendance.harmonic.mesh import Mesh, load_mesh
from eigendance.harmonic.reduced import (
    REDUCED_KEYS,
    ReducedHarmonics,
    check_reduced,
    reduced_arrays,
    reduced_from_arrays,
    reduced_harmonics,
    reduced_key,
    reduced_pairs_fit,
    sample_count,
    solve_bytes,
)
from eigendance.limits import check_memory, memory_budget
from eigendance.writes import atomic_save_npz

FORMAT_KEYS = ("vertices", "faces", "center", "scale", "mass", "eigenvalues", "eigenvectors",
               "coefficients", "residual", "laplacian")
# A reduced basis file holds REDUCED_KEYS instead of the eigenvectors.
COMMON_KEYS = tuple(name for name in FORMAT_KEYS if name != "eigenvectors")
# A cached solve is used only if its pairs pass the solver's own test with this slack
# (‖Lu − λMu‖ ≤ tol·max(λ,1)·‖Mu‖, and Uᵀ M U = I within tol).
CACHE_TOLERANCE = 10 * RESIDUAL_TOLERANCE
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
            return cls._reduced(mesh, k, laplacian, cache, progress, samples)
        per_harmonic = SOLVE_BYTES_PER_VALUE * mesh.n
        fits = int(memory_budget() // per_harmonic)
        check_memory(per_harmonic * k, f"{mesh.name}: {k} harmonics of {mesh.n} vertices",
                     remedy={"k": fits} if 1 <= fits < k else None)
        timing = {"seconds": 0.0}
        operators = {}

        def stiffness_and_mass():
            if not operators:
                operators["L, M"] = build_laplacian(mesh.vertices, mesh.faces, laplacian)
            return operators["L, M"]

        def solved() -> dict[str, np.ndarray]:
            stiffness, mass = stiffness_and_mass()
            start = time.perf_counter()
            eigenvalues, eigenvectors = solve(stiffness, mass, k, solver, progress)
            timing["seconds"] = time.perf_counter() - start
            return {"eigenvalues": eigenvalues, "eigenvectors": eigenvectors, "mass": mass}

        if cache:
            arrays = basis_cache().get(basis_key(mesh, k, laplacian, solver), solved,
                                       lambda found: eigenpairs_fit(*stiffness_and_mass(), k,
                                                                    found))
        else:
            arrays = solved()
        eigenvalues, eigenvectors, mass = (arrays[name] for name in
                                           ("eigenvalues", "eigenvectors", "mass"))
        if progress is not None:
            progress(k)
        return cls.from_arrays(mesh, eigenvalues, eigenvectors, mass, laplacian,
                               timing["seconds"])

    @classmethod
    def _reduced(cls, mesh: Mesh, k: int, laplacian: str, cache: bool, progress,
                 samples: int | None) -> HarmonicBasis:
        """The reduced basis of `mesh` (docs/design.md#reduced-basis), through the cache."""
        count = sample_count(mesh.n, k) if samples is None else int(samples)
        if not k < count <= mesh.n:
            raise InputError(f"{mesh.name}: a reduced basis of k = {k} harmonics needs more "
                             f"than k samples and at most one per vertex ({mesh.n}); asked "
                             f"for {count}", remedy={"samples": 4 * k} if 4 * k <= mesh.n
                             else {"exact": True})
        check_memory(solve_bytes(mesh.n, len(mesh.faces), k, count, laplacian),
                     f"{mesh.name}: a reduced basis of {k} harmonics of {mesh.n} vertices")
        timing = {"seconds": 0.0}
        operators = {}

        def stiffness_and_mass():
            if not operators:
                operators["L, M"] = build_laplacian(mesh.vertices, mesh.faces, laplacian)
            return operators["L, M"]

        def solved() -> dict[str, np.ndarray]:
            stiffness, mass = stiffness_and_mass()
            start = time.perf_counter()
            eigenvalues, reduced = reduced_harmonics(stiffness, mass, mesh.vertices, mesh.faces,
                                                     k, count, progress)
            timing["seconds"] = time.perf_counter() - start
            return {"eigenvalues": eigenvalues, "mass": mass, **reduced_arrays(reduced)}

        if cache:
            key = reduced_key(basis_key(mesh, k, laplacian, "bands"), count)
            arrays = basis_cache().get(key, solved, lambda found: reduced_pairs_fit(
                *stiffness_and_mass(), k, found))
        else:
            arrays = solved()
        if progress is not None:
            progress(k)
        return cls.from_arrays(mesh, arrays["eigenvalues"], None, arrays["mass"], laplacian,
                               timing["seconds"], reduced_from_arrays(arrays))

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
