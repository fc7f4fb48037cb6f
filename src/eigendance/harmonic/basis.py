"""HarmonicBasis: the manifold harmonics of a mesh (docs/design.md#basis).

U = [u_0 … u_{k-1}] solves L u = λ M u with Uᵀ M U = I. The coefficients X̃ = Uᵀ M X (k×3) and
the remainder D = X − U X̃ give filtered positions X_φ = X + U((φ − 1) ⊙ X̃); φ ≡ 1 returns X.
A large mesh gets a reduced basis (docs/design.md#reduced-basis): U = P U_r, never formed.

A `HarmonicProblem` is the eigenproblem of one mesh, built once, as potpourri3d's solvers are:
it owns the Laplacian's kind (`laplacian.laplacian_for` unless asked), where the mesh's pieces
touch (`contacts`), L and M (assembled once, when first needed), the construction of each basis
(exact or reduced, decided once per k: `construction_for`) and the disk cache's key (`key`), and
answers `basis(k)`. `HarmonicBasis.from_mesh` is its one-shot wrapper. `save` writes the parse
once (the cleaned mesh and the decisions, not its look) and `load` reads it back without
parsing or checking the mesh again: the server's reading worker saves it, its solve's worker
loads it, and the mesh never passes through the server (docs/design.md#server).
"""

from __future__ import annotations

import json
import os
import time
from dataclasses import dataclass

import numpy as np

from eigendance.errors import InputError
from eigendance.geometry import MAX_COORDINATE, bounding_box_diagonal
from eigendance.harmonic.basis_file import COMMON_KEYS, read_fields
from eigendance.harmonic.construction import (
    CONSTRUCTIONS,
    SOLVE_BYTES_PER_VALUE,
    BasisRecord,
    basis_cache,
    basis_key,
    choose_construction,
    eigenpairs_fit,
    is_cached,
)
from eigendance.harmonic.contacts import Contacts, contacts
from eigendance.harmonic.deform import Deformer
from eigendance.harmonic.eigensolver import SOLVERS, check_request, solve
from eigendance.harmonic.laplacian import LAPLACIANS, laplacian_for
from eigendance.harmonic.laplacian import laplacian as build_laplacian
from eigendance.harmonic.mesh import Mesh, load_mesh
from eigendance.harmonic.reduced import (
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
from eigendance.writes import atomic_save_npz, atomic_write

# The arrays of a saved problem (`HarmonicProblem.save`): the cleaned mesh's.
MESH_ARRAYS = ("vertices", "faces", "center", "scale", "vertex_map")


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
    def record(self) -> BasisRecord:
        """What a mapping made on this basis records of it (`BasisRecord`)."""
        if self.reduced is None:
            return BasisRecord(self.k, "exact")
        return BasisRecord(self.k, "reduced", self.reduced.asked, self.reduced.count)

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
        return HarmonicProblem(mesh, laplacian, construction, samples, solver, cache).basis(
            k, progress)

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
        fields = read_fields(path)
        basis = cls(**fields)
        if not np.abs(basis.to_original(basis.vertices)).max() <= MAX_COORDINATE:
            raise InputError(f"{path}: original coordinates (vertices·scale + center) beyond "
                             f"±{MAX_COORDINATE:.0e}")
        expected = cls.from_arrays(Mesh(basis.vertices, basis.faces, basis.center, basis.scale,
                                        np.arange(basis.n)), basis.eigenvalues, basis.eigenvectors,
                                   basis.mass, reduced=basis.reduced)
        for name in ("coefficients", "residual"):
            stored, rebuilt = getattr(basis, name), getattr(expected, name)
            if not np.abs(stored - rebuilt).max() <= 1e-8 * (1 + np.abs(rebuilt).max()):
                raise InputError(f"{path}: {name} do not follow from the vertices, mass and "
                                 "eigenvectors (not a basis file written by eigendance)")
        return basis


class HarmonicProblem:
    """The eigenproblem of a mesh's manifold harmonics, built once (see the module docstring).

    Parameters
    ----------
    mesh : a cleaned `Mesh`, or the path of a mesh file (`load_mesh`).
    laplacian : "cotan", "robust", or None for `laplacian_for(mesh)` (robust for non-manifold
        edges).
    construction : "auto" (`choose_construction`, per k), "exact" or "reduced".
    samples : samples of a reduced basis (default `reduced.sample_count`).
    solver : "bands" (spectrum slicing) or "eigsh" (the naive baseline); exact bases only.
    cache : read and write the disk cache.

    Raises
    ------
    InputError
        For an unknown construction, Laplacian or solver, and for the cotangent Laplacian on a
        mesh with non-manifold edges (its remedy: the robust one); `load_mesh`'s for a file.

    Example
    -------
    >>> import trimesh
    >>> sphere = trimesh.creation.icosphere(2)
    >>> problem = HarmonicProblem(Mesh.from_arrays(sphere.vertices, sphere.faces), cache=False)
    >>> problem.laplacian, problem.construction_for(9)
    ('cotan', 'exact')
    >>> (problem.basis(9).eigenvalues[:4].round(1) + 0.0).tolist()   # l(l+1) = 0, 2, 2, 2
    [0.0, 2.0, 2.0, 2.0]
    """

    def __init__(self, mesh: Mesh | str | os.PathLike, laplacian: str | None = None,
                 construction: str = "auto", samples: int | None = None,
                 solver: str = "bands", cache: bool = True):
        for value, allowed, what in ((construction, CONSTRUCTIONS, "construction"),
                                     (solver, SOLVERS, "solver")):
            if value not in allowed:
                raise InputError(f"unknown {what} '{value}' (expected one of "
                                 f"{', '.join(allowed)})")
        self.mesh = mesh if isinstance(mesh, Mesh) else load_mesh(mesh)
        self.laplacian = laplacian_for(self.mesh) if laplacian is None else laplacian
        if self.laplacian not in LAPLACIANS:
            raise InputError(f"unknown Laplacian '{self.laplacian}' (expected one of "
                             f"{', '.join(LAPLACIANS)})")
        if self.laplacian == "cotan" and (count := self.mesh.non_manifold_edge_count()):
            raise InputError(f"{self.mesh.name}: {count} non-manifold edges (shared by more than "
                             "two triangles); the cotangent Laplacian needs a manifold mesh",
                             remedy={"laplacian": "robust"})
        self.construction, self.samples = construction, samples
        self.solver, self.cache = solver, cache
        self._contacts: Contacts | None = None
        self._operators = None
        self._chosen: dict[int, str] = {}

    def save(self, path: str | os.PathLike) -> None:
        """Write the parse once, for another process to `load`: the cleaned mesh's arrays
        (MESH_ARRAYS), its name and clean-up report, the Laplacian and every construction
        decided so far; not its look (`Mesh.appearance`: the reader keeps it). Written
        atomically, without fsync (a file of the server's temporary folder, read once).

        Parameters
        ----------
        path : the .npz to write.
        """
        mesh = self.mesh
        meta = {"name": mesh.name, "report": mesh.report, "laplacian": self.laplacian,
                "construction": self.construction, "samples": self.samples,
                "solver": self.solver, "cache": self.cache, "chosen": self._chosen}
        arrays = {name: np.asarray(getattr(mesh, name)) for name in MESH_ARRAYS}
        arrays["meta"] = np.array(json.dumps(meta, default=int))
        atomic_write(path, lambda file: np.savez(file, **arrays), sync=False, alone=True)

    @classmethod
    def load(cls, path: str | os.PathLike) -> HarmonicProblem:
        """A problem as `save` wrote it, neither parsed nor checked again (its mesh has no
        look).

        Parameters
        ----------
        path : a file written by `save`.

        Returns
        -------
        HarmonicProblem.
        """
        with np.load(path, allow_pickle=False) as data:
            arrays = {name: data[name] for name in data.files}
        meta = json.loads(str(arrays.pop("meta")))
        arrays["scale"] = float(arrays["scale"])
        problem = cls.__new__(cls)
        problem.mesh = Mesh(**arrays, report=meta["report"], name=meta["name"])
        problem.laplacian, problem.construction = meta["laplacian"], meta["construction"]
        problem.samples, problem.solver = meta["samples"], meta["solver"]
        problem.cache, problem._contacts, problem._operators = meta["cache"], None, None
        problem._chosen = {int(k): chosen for k, chosen in meta["chosen"].items()}
        return problem

    @property
    def contacts(self) -> Contacts:
        """Where the mesh's pieces touch (`contacts.contacts`), found once."""
        if self._contacts is None:
            self._contacts = contacts(self.mesh.vertices, self.mesh.faces)
        return self._contacts

    def operators(self):
        """(L, M): the stiffness (n, n) sparse, its pieces coupled at `contacts`, and the mass
        (n,), assembled once (`laplacian.laplacian`).

        Returns
        -------
        (scipy.sparse.csc_matrix, numpy.ndarray).
        """
        if self._operators is None:
            self._operators = build_laplacian(self.mesh.vertices, self.mesh.faces,
                                              self.laplacian, self.contacts)
        return self._operators

    def construction_for(self, k: int) -> str:
        """The construction of the basis of k harmonics: the one asked for, or the one
        "auto" chooses (`choose_construction`), decided once for each k.

        Parameters
        ----------
        k : harmonics.

        Returns
        -------
        "exact" or "reduced".
        """
        if k not in self._chosen:
            self._chosen[k] = choose_construction(self.mesh.n, k, self.samples) \
                if self.construction == "auto" else self.construction
        return self._chosen[k]

    def sample_count(self, k: int) -> int | None:
        """Samples m of the basis of k harmonics; None for an exact one.

        Parameters
        ----------
        k : harmonics.

        Returns
        -------
        int or None.
        """
        if self.construction_for(k) == "exact":
            return None
        return sample_count(self.mesh.n, k) if self.samples is None else int(self.samples)

    def key(self, k: int) -> str:
        """The disk cache's key of the basis of k harmonics (`basis_key`, `reduced_key`).

        Parameters
        ----------
        k : harmonics.

        Returns
        -------
        str.
        """
        count = self.sample_count(k)
        if count is None:
            return basis_key(self.mesh, k, self.laplacian, self.solver)
        return reduced_key(basis_key(self.mesh, k, self.laplacian, "bands"), count)

    def cached(self, k: int) -> bool:
        """Whether the disk cache holds an entry for the basis of k harmonics (checked when
        read).

        Parameters
        ----------
        k : harmonics.

        Returns
        -------
        bool.
        """
        return is_cached(self.key(k))

    def basis(self, k: int, progress=None):
        """The first k harmonics (`HarmonicBasis`), through the disk cache.

        Parameters
        ----------
        k : harmonics, 1 ≤ k < n.
        progress : optional callable(done) told how many eigenpairs are accepted so far.

        Returns
        -------
        HarmonicBasis, verified: L u = λ M u and Uᵀ M U = I (a reduced basis: L_r c = λ M_r c
        and U_rᵀ M_r U_r = I).

        Raises
        ------
        InputError
            When the solve cannot fit the memory available (its remedy: a smaller k), or a
            reduced basis's samples are not between k and n.
        """
        if self.construction_for(k) == "reduced":
            arrays, seconds = self._reduced(k, progress)
            reduced, eigenvectors = reduced_from_arrays(arrays, self.sample_count(k)), None
        else:
            arrays, seconds = self._exact(k, progress)
            reduced, eigenvectors = None, arrays["eigenvectors"]
        if progress is not None:
            progress(k)
        return HarmonicBasis.from_arrays(self.mesh, arrays["eigenvalues"], eigenvectors,
                                         arrays["mass"], self.laplacian, seconds, reduced)

    def _exact(self, k: int, progress) -> tuple[dict, float]:
        """The eigenpairs on every vertex, planned against the memory available."""
        mesh = self.mesh
        check_request(mesh.n, k, mesh.name)
        per_harmonic = SOLVE_BYTES_PER_VALUE * mesh.n
        fits = int(memory_budget() // per_harmonic)
        check_memory(per_harmonic * k, f"{mesh.name}: {k} harmonics of {mesh.n} vertices",
                     remedy={"k": fits} if 1 <= fits < k else None)

        def solved() -> dict:
            stiffness, mass = self.operators()
            eigenvalues, eigenvectors = solve(stiffness, mass, k, self.solver, progress)
            return {"eigenvalues": eigenvalues, "eigenvectors": eigenvectors, "mass": mass}

        return self._fetch(k, solved, lambda found: eigenpairs_fit(*self.operators(), k, found))

    def _reduced(self, k: int, progress) -> tuple[dict, float]:
        """The eigenpairs of the reduced problem (docs/design.md#reduced-basis)."""
        mesh, count = self.mesh, self.sample_count(k)
        if not k < count <= mesh.n:
            raise InputError(f"{mesh.name}: a reduced basis of k = {k} harmonics needs more than "
                             f"k samples and at most one per vertex ({mesh.n}); asked for "
                             f"{count}", remedy={"samples": 4 * k} if 4 * k <= mesh.n
                             else {"exact": True})
        check_memory(solve_bytes(mesh.n, len(mesh.faces), k, count, self.laplacian),
                     f"{mesh.name}: a reduced basis of {k} harmonics of {mesh.n} vertices")

        def solved() -> dict:
            stiffness, mass = self.operators()
            eigenvalues, reduced = reduced_harmonics(stiffness, mass, mesh.vertices, mesh.faces,
                                                     k, count, progress)
            return {"eigenvalues": eigenvalues, "mass": mass, **reduced_arrays(reduced)}

        return self._fetch(k, solved, lambda found: reduced_pairs_fit(*self.operators(), k,
                                                                      found))

    def _fetch(self, k: int, solved, valid) -> tuple[dict, float]:
        """solved()'s arrays, through the disk cache when it is used, and the seconds the
        solve took (0 from the cache)."""
        timing = {"seconds": 0.0}

        def timed() -> dict:
            start = time.perf_counter()
            arrays = solved()
            timing["seconds"] = time.perf_counter() - start
            return arrays

        arrays = basis_cache().get(self.key(k), timed, valid) if self.cache else timed()
        return arrays, timing["seconds"]
