"""How a harmonic basis is computed (docs/design.md#reduced-basis, docs/design.md#cache).

Which construction (`choose_construction`: exact when the solve fits the time and memory
rule, else reduced) and the disk cache of eigenpairs (`basis_key` names an entry,
`eigenpairs_fit` and `reduced.reduced_pairs_fit` check one before it is used).
`basis.HarmonicProblem` plans each solve against the memory available and fetches or stores
its eigenpairs here.
"""

from __future__ import annotations

import hashlib
import os
from dataclasses import dataclass

import numpy as np

from eigendance.checks import number
from eigendance.errors import InputError
from eigendance.harmonic.cache import DiskCache
from eigendance.harmonic.eigensolver import SOLVER_VERSION, residuals
from eigendance.harmonic.mesh import Mesh
from eigendance.harmonic.reduced import (
    CACHE_TOLERANCE,
    sample_count,
)
from eigendance.limits import memory_budget

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


@dataclass(frozen=True)
class BasisRecord:
    """The basis a mapping was made on (docs/design.md#mapping-file): the same record gives the
    same harmonics, so the same dance.

    Parameters
    ----------
    k : harmonics.
    construction : "exact" or "reduced".
    samples : the samples a reduced basis asked the sampler for (`sampling.spread_samples`:
        with the mesh they fix the samples placed); None: exact, or the default count.
    placed : the samples m a reduced basis placed (about `samples`), or None; a check, not an
        input: the same mesh and `samples` place them again.

    Example
    -------
    >>> record = BasisRecord.from_json({"k": 150, "construction": "exact", "samples": None})
    >>> record, record.describe()
    (BasisRecord(k=150, construction='exact', samples=None, placed=None), \
'k = 150 harmonics (exact)')
    >>> BasisRecord(20, "reduced", 2000, 2062).describe()
    'k = 20 harmonics (reduced, 2000 samples asked, 2062 placed)'
    >>> BasisRecord.from_json({"k": 20, "construction": "reduced", "samples": 2062})  # older
    BasisRecord(k=20, construction='reduced', samples=None, placed=2062)
    """

    k: int
    construction: str = "exact"
    samples: int | None = None
    placed: int | None = None

    def describe(self) -> str:
        """The record in words, as a message says it.

        Returns
        -------
        str.
        """
        how = [self.construction]
        if self.samples is not None:
            how.append(f"{self.samples} samples asked")
        if self.placed is not None:
            how.append(f"{self.placed} placed")
        return f"k = {self.k} harmonics ({', '.join(how)})"

    def to_json(self) -> dict:
        """{"k", "construction", "samples", "placed"}.

        Returns
        -------
        dict.
        """
        return {"k": self.k, "construction": self.construction, "samples": self.samples,
                "placed": self.placed}

    @classmethod
    def from_json(cls, data, name: str = "mapping") -> BasisRecord:
        """A record from a mapping document's "basis", checked. A reduced record without
        "placed" is older: its "samples" were the samples placed, made from the default count
        (all the page asked for), so it reads as that default with those samples placed.

        Parameters
        ----------
        data : the document's "basis" object.
        name : how messages call the mapping.

        Returns
        -------
        BasisRecord.

        Raises
        ------
        InputError
            For a field that is not an object of a positive integer k, a construction
            "exact" or "reduced" and samples and placed null or integers above k.
        """
        if not isinstance(data, dict):
            raise InputError(f"{name}: basis must be an object {{k, construction, samples}}")
        k = number(data.get("k"), f"{name}: basis.k", 1, 20000, integer=True)
        construction = data.get("construction", "exact")
        if construction not in CONSTRUCTIONS[1:]:
            raise InputError(f"{name}: basis.construction must be \"exact\" or \"reduced\", "
                             f"not {construction!r}")
        counts = {}
        for field in ("samples", "placed"):
            counts[field] = data.get(field)
            if counts[field] is not None:
                counts[field] = number(counts[field], f"{name}: basis.{field}", k, 10**7,
                                       integer=True, above=True)
        if construction == "reduced" and "placed" not in data:
            counts = {"samples": None, "placed": counts["samples"]}
        return cls(k, construction, counts["samples"], counts["placed"])


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


def is_cached(key: str) -> bool:
    """Whether the disk cache of eigen-solves holds an entry for `key` (checked when read).

    Parameters
    ----------
    key : a solve's key (`basis_key`, `reduced.reduced_key`).

    Returns
    -------
    bool.
    """
    return os.path.isfile(basis_cache().path(key))


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
