"""Files: kinds by suffix, atomic writes, checked reads of .npz (docs/design.md#files).

One table says which suffixes are meshes, audio, rigs and mappings; the CLI, the server and the
loaders all ask `kind_of`. Every output is written to a temporary file beside its destination
and renamed over it, so a reader never sees half a file and a failure leaves nothing behind.
"""

from __future__ import annotations

import os
import tempfile
import zipfile

import numpy as np

from eigendance.errors import InputError, one_line

MESH_SUFFIXES = (".obj", ".ply", ".off", ".stl", ".gltf", ".glb")
# libsndfile reads the first group itself; PyAV (FFmpeg) reads everything.
AUDIO_SUFFIXES = (".wav", ".wave", ".flac", ".ogg", ".oga", ".mp3", ".aif", ".aiff", ".opus",
                  ".m4a", ".aac", ".mp4", ".webm", ".mka")
RIG_SUFFIXES = (".json", ".gltf", ".glb")
MAPPING_SUFFIXES = (".json",)
KINDS = {"mesh": MESH_SUFFIXES, "audio": AUDIO_SUFFIXES, "mapping": MAPPING_SUFFIXES}


def suffix_of(path: str | os.PathLike) -> str:
    """The lower-case suffix of a path, with its dot ('' if none)."""
    return os.path.splitext(os.fspath(path))[1].lower()


def kind_of(name: str | os.PathLike, kinds: tuple[str, ...] = ("mesh", "audio", "mapping")) -> str:
    """'mesh', 'audio' or 'mapping' by suffix, among `kinds`; InputError for any other."""
    suffix = suffix_of(name)
    for kind in kinds:
        if suffix in KINDS[kind]:
            return kind
    name = os.path.basename(os.fspath(name))
    if len(kinds) == 1:
        raise InputError(f"{name}: unknown {kinds[0]} format '{suffix or '(none)'}' (expected "
                         f"one of {', '.join(KINDS[kinds[0]])})", status=415)
    known = "; ".join(f"{kind}: {' '.join(KINDS[kind])}" for kind in kinds)
    raise InputError(f"{name}: unknown file type '{suffix or '(none)'}' ({known})", status=415)


def check_suffix(path: str | os.PathLike, kind: str) -> None:
    """InputError unless `path` has one of the suffixes of `kind`."""
    kind_of(path, (kind,))


def check_readable(path: str | os.PathLike) -> str:
    """The path as a string; InputError if it is not an existing, non-empty regular file."""
    path = os.fspath(path)
    if not os.path.exists(path):
        raise InputError(f"{path}: no such file", status=404)
    if not os.path.isfile(path):
        raise InputError(f"{path}: not a regular file")
    if os.path.getsize(path) == 0:
        raise InputError(f"{os.path.basename(path)}: the file is empty")
    return path


def atomic_write(path: str | os.PathLike, write, sync: bool = True) -> None:
    """Call write(file) on a temporary file beside `path`, then rename it over `path`.

    Readers never see a half-written file, and a failed write leaves no debris. sync=False skips
    the fsync (for large files that are cheap to recompute). An output that cannot be written
    (a folder in the way, no permission, a full disk) is an InputError naming the path.
    """
    path = os.fspath(path)
    if os.path.isdir(path):
        raise InputError(f"{path}: is a folder; give a file name for the output")
    folder = os.path.dirname(os.path.abspath(path))
    try:
        os.makedirs(folder, exist_ok=True)
        handle, temporary = tempfile.mkstemp(dir=folder, prefix=".tmp-", suffix=".part")
    except OSError as error:
        raise InputError(f"{path}: cannot write ({error.strerror or one_line(error)})") from None
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
    except BaseException as error:
        if os.path.exists(temporary):
            os.unlink(temporary)
        if isinstance(error, OSError):
            raise InputError(f"{path}: cannot write "
                             f"({error.strerror or one_line(error)})") from None
        raise


def atomic_save_npz(path, **arrays) -> None:
    """np.savez (uncompressed: the eigenvectors are incompressible floats) written atomically."""
    atomic_write(path, lambda file: np.savez(file, **arrays))


def load_npz(path, required: tuple[str, ...]) -> dict:
    """Every array of an .npz file, checking that the `required` keys are present."""
    path = check_readable(path)
    try:
        with np.load(path, allow_pickle=False) as data:
            arrays = {name: data[name] for name in data.files}
    except (OSError, ValueError, zipfile.BadZipFile, EOFError) as error:
        raise InputError(f"{path}: not a readable .npz file ({one_line(error)})") from None
    missing = [name for name in required if name not in arrays]
    if missing:
        raise InputError(f"{path}: missing {', '.join(missing)} (not an eigendance file "
                         "of this kind)")
    return arrays


def refuse_overwrite(path, force: bool) -> None:
    """InputError unless `path` is free or the caller asked to overwrite it."""
    path = os.fspath(path)
    if os.path.isdir(path):
        raise InputError(f"{path}: is a folder; give a file name for the output")
    if os.path.exists(path) and not force:
        raise InputError(f"{path} exists", remedy={"force": True})
