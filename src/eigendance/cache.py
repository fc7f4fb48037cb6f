"""Content-addressed cache of harmonic bases, so the same mesh is never solved twice.

Key: SHA-256 of the normalised geometry (vertices and faces as stored), k, the Laplacian and
FORMAT_VERSION. Entries are basis files written atomically; one that cannot be read or does not
match its key is deleted and recomputed. Folder: $EIGENDANCE_CACHE_DIR, else the platform's
user cache folder.
"""

from __future__ import annotations

import hashlib
import os

import numpy as np

from eigendance.errors import EigendanceError

FORMAT_VERSION = 1


def folder() -> str:
    configured = os.environ.get("EIGENDANCE_CACHE_DIR")
    if configured:
        return configured
    import platformdirs

    return platformdirs.user_cache_dir("eigendance")


def key(mesh, k: int, laplacian: str) -> str:
    digest = hashlib.sha256()
    digest.update(f"eigendance-basis v{FORMAT_VERSION} k={k} laplacian={laplacian}".encode())
    digest.update(np.ascontiguousarray(mesh.vertices, dtype=np.float64).tobytes())
    digest.update(np.ascontiguousarray(mesh.faces, dtype=np.int64).tobytes())
    return digest.hexdigest()


def path_of(entry_key: str) -> str:
    return os.path.join(folder(), "bases", f"{entry_key}.npz")


def fetch(entry_key: str):
    """The cached HarmonicBasis for this key, or None (a corrupt entry is removed)."""
    from eigendance.harmonics import HarmonicBasis

    path = path_of(entry_key)
    if not os.path.exists(path):
        return None
    try:
        basis = HarmonicBasis.load(path)
        if not (np.all(np.isfinite(basis.eigenvectors)) and np.all(np.isfinite(basis.eigenvalues))):
            raise EigendanceError("non-finite values")
        return basis
    except EigendanceError:
        os.unlink(path)
        return None


def store(entry_key: str, basis) -> None:
    try:
        basis.save(path_of(entry_key))
    except OSError:
        pass  # a read-only or full cache folder must not fail the computation
