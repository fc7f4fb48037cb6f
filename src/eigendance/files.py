"""Atomic writes and checked reads of .npz files (the project's on-disk formats, DESIGN §8)."""

from __future__ import annotations

import os
import tempfile
import zipfile

import numpy as np

from eigendance.errors import EigendanceError


def atomic_write(path: str | os.PathLike, write, sync: bool = True) -> None:
    """Call write(file) on a temporary file beside `path`, then rename it over `path`.

    Readers never see a half-written file, and a failed write leaves no debris. sync=False skips
    the fsync (for large files that are cheap to recompute).
    """
    path = os.fspath(path)
    folder = os.path.dirname(os.path.abspath(path))
    os.makedirs(folder, exist_ok=True)
    handle, temporary = tempfile.mkstemp(dir=folder, prefix=".tmp-", suffix=".part")
    try:
        with os.fdopen(handle, "wb") as file:
            write(file)
            if sync:
                file.flush()
                os.fsync(file.fileno())
        # mkstemp creates 0600; give the file the permissions a plain open() would.
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(temporary, 0o666 & ~umask)
        os.replace(temporary, path)
    except BaseException:
        if os.path.exists(temporary):
            os.unlink(temporary)
        raise


def atomic_save_npz(path, **arrays) -> None:
    """np.savez (uncompressed: the eigenvectors are incompressible floats) written atomically."""
    atomic_write(path, lambda file: np.savez(file, **arrays))


def load_npz(path, required: tuple[str, ...]) -> dict:
    """Load every array of an .npz file, checking that the `required` keys are present."""
    path = os.fspath(path)
    try:
        with np.load(path, allow_pickle=False) as data:
            arrays = {name: data[name] for name in data.files}
    except FileNotFoundError:
        raise EigendanceError(f"{path}: no such file") from None
    except (OSError, ValueError, zipfile.BadZipFile, EOFError) as error:
        raise EigendanceError(f"{path}: not a readable .npz file ({error})") from None
    missing = [name for name in required if name not in arrays]
    if missing:
        raise EigendanceError(f"{path}: missing {', '.join(missing)} (not an eigendance file "
                              "of this kind)")
    return arrays


def refuse_overwrite(path, force: bool) -> None:
    """Raise unless `path` is free or the user asked to overwrite it."""
    if os.path.exists(path) and not force:
        raise EigendanceError(f"{os.fspath(path)} exists; pass --force to overwrite it")
