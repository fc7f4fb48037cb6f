"""A content-addressed disk cache of named arrays (docs/design.md#cache).

`DiskCache.get(key, fetch)` returns the arrays stored under `key`, or computes them with
`fetch()` and stores them (the shape of trimesh's `DiskCache.get`). The cache knows nothing of
its clients: a key is any string that names everything the arrays depend on, and an entry is an
.npz file holding the arrays, the key itself and a SHA-256 checksum of the arrays. An entry that
cannot be read, that was stored under another key, whose arrays do not match its checksum, or
that the client's own check of its content refuses, is discarded and computed again; a cache
folder that cannot be written only costs the speed-up. Temporary files of killed writers are
swept by `writes.atomic_write`.

Folder: $EIGENDANCE_CACHE_DIR, else the platform's user cache folder.
"""

from __future__ import annotations

import hashlib
import os
import shutil
import zipfile
from collections.abc import Callable

import numpy as np
import platformdirs

from eigendance.errors import InputError
from eigendance.reads import read_npz
from eigendance.writes import atomic_save_npz

KEY, CHECKSUM = "__key__", "__checksum__"


def cache_folder() -> str:
    """$EIGENDANCE_CACHE_DIR, else the user cache folder of the platform.

    Returns
    -------
    str.
    """
    return os.environ.get("EIGENDANCE_CACHE_DIR") or platformdirs.user_cache_dir("eigendance")


def checksum(arrays: dict[str, np.ndarray]) -> str:
    """SHA-256 over the names, dtypes, shapes and bytes of the arrays, in name order.

    Parameters
    ----------
    arrays : {name: array}.

    Returns
    -------
    str, 64 hexadecimal digits.
    """
    digest = hashlib.sha256()
    for name in sorted(arrays):
        array = np.ascontiguousarray(arrays[name])
        digest.update(f"{name}:{array.dtype.str}:{array.shape};".encode())
        digest.update(array.reshape(-1).view(np.uint8))
    return digest.hexdigest()


class DiskCache:
    """Arrays stored under string keys in `folder` (default: `cache_folder()/subfolder`).

    Parameters
    ----------
    subfolder : the cache's subfolder.
    folder : the folder itself, or None.
    """

    def __init__(self, subfolder: str = "arrays", folder: str | None = None):
        self.folder = folder or os.path.join(cache_folder(), subfolder)

    def path(self, key: str) -> str:
        """The file of the entry for `key`.

        Parameters
        ----------
        key : the key.

        Returns
        -------
        str.
        """
        return os.path.join(self.folder, hashlib.sha256(key.encode()).hexdigest() + ".npz")

    def __contains__(self, key: str) -> bool:
        return self.load(key) is not None

    def get(self, key: str, fetch: Callable[[], dict[str, np.ndarray]],
            valid: Callable[[dict[str, np.ndarray]], bool] | None = None) -> dict[str, np.ndarray]:
        """The arrays stored under `key`, or `fetch()`'s, stored for the next call.

        valid: the client's check of a stored entry's content (an entry it refuses is computed
        again), for entries that are intact but wrong: written by a bug or by hand.

        Parameters
        ----------
        key : the key.
        fetch : () → the arrays, when nothing valid is stored.
        valid : arrays → bool, or None.

        Returns
        -------
        {name: array}.
        """
        found = self.load(key)
        if found is not None:
            if valid is None or valid(found):
                return found
            self._discard(self.path(key))
        arrays = fetch()
        self.store(key, arrays)
        return arrays

    def load(self, key: str) -> dict[str, np.ndarray] | None:
        """The arrays of a valid entry for `key`, or None (an invalid entry is removed).

        Parameters
        ----------
        key : the key.

        Returns
        -------
        {name: array} or None.
        """
        path = self.path(key)
        if not os.path.lexists(path):
            return None
        try:
            arrays = read_npz(path)  # a regular file whose declared sizes it holds
            stored_key, stored_sum = str(arrays.pop(KEY)), str(arrays.pop(CHECKSUM))
            if stored_key == key and stored_sum == checksum(arrays):
                return arrays
        except (InputError, OSError, ValueError, KeyError, zipfile.BadZipFile, EOFError):
            pass
        self._discard(path)
        return None

    def store(self, key: str, arrays: dict[str, np.ndarray]) -> None:
        """Write an entry atomically; an unwritable cache folder is ignored.

        Parameters
        ----------
        key : the key.
        arrays : {name: array}.
        """
        try:
            atomic_save_npz(self.path(key), alone=True, **arrays, **{KEY: np.array(key),
                                                         CHECKSUM: np.array(checksum(arrays))})
        except InputError:
            pass  # a read-only or full cache folder must not fail the computation

    def _discard(self, path: str) -> None:
        try:
            if os.path.isdir(path) and not os.path.islink(path):
                shutil.rmtree(path)
            else:
                os.unlink(path)
        except OSError:
            pass
