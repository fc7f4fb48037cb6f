"""Writing outputs: atomically, never over an input, finite (docs/design.md#files).

Every output is written to a temporary file beside its destination and renamed over it, so a
reader never sees half a file and a failure leaves nothing behind; `all_or_nothing` defers the
renames of a command's several outputs until all are written. The writer holds a lock on its
temporary file; a temporary file nobody holds was left by a killed process, and the next write
into that folder removes it. Arrays of floats are checked finite before they are written, and
an output is never one of the command's inputs, nor an existing file unless asked.
"""

from __future__ import annotations

import contextlib
import contextvars
import errno
import fcntl
import os
import re
import shutil
import tempfile
import time

import numpy as np

from eigendance.errors import InputError, one_line

# Temporary files of `atomic_write` and `export.output.Outputs`: ours alone, so sweeping them
# never touches another program's files (`.eigendance-XXXX.part`, or `.eigendance-XXXX.part.mp4`
# where the writer needs the destination's suffix). An empty one younger than FRESH_SECONDS may
# belong to a writer that has not taken its lock yet.
TEMPORARY_PREFIX, TEMPORARY_SUFFIX = ".eigendance-", ".part"
TEMPORARY_NAME = re.compile(r"\.eigendance-.+\.part(\.[A-Za-z0-9]{1,8})?")
FRESH_SECONDS = 60.0
LOCK_NAME = ".lock"  # in a `locked_folder`: held (flock) by the process that owns the folder


def locked_temporary(folder: str, suffix: str = "") -> tuple[int, str]:
    """A new temporary file in `folder`, locked (exclusively) by this process until it is closed.

    Parameters
    ----------
    folder : an existing folder.
    suffix : appended after `.part` (a destination's suffix, for writers that need it).

    Returns
    -------
    (file descriptor, path); OSError as `tempfile.mkstemp` raises it.
    """
    handle, temporary = tempfile.mkstemp(dir=folder, prefix=TEMPORARY_PREFIX,
                                         suffix=TEMPORARY_SUFFIX + suffix)
    try:
        fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        pass  # a file system without locks: the file is still ours, only the sweep skips it
    return handle, temporary


def sweep_temporary_files(folder: str | os.PathLike, fresh: float = FRESH_SECONDS) -> int:
    """Remove the temporary files that killed writers left in `folder`; returns how many.

    A writer holds an exclusive lock on its temporary file until it renames or removes it, and
    the system drops the lock when the process dies, however it dies. So a temporary file whose
    lock can be taken is debris (unless it is empty and younger than `fresh` seconds: its writer
    may be about to lock it).

    Parameters
    ----------
    folder : a folder.
    fresh : s; 0 when no writer can be starting there (a batch whose workers are stopped).

    Returns
    -------
    int.
    """
    try:
        entries = list(os.scandir(folder))
    except OSError:
        return 0
    removed = 0
    now = time.time()
    for entry in entries:
        if not (TEMPORARY_NAME.fullmatch(entry.name) and entry.is_file(follow_symlinks=False)):
            continue
        try:
            with open(entry.path, "rb") as file:
                fcntl.flock(file, fcntl.LOCK_EX | fcntl.LOCK_NB)  # OSError while a writer holds it
                status = os.fstat(file.fileno())
                if status.st_size == 0 and now - status.st_mtime < fresh:
                    continue
                os.unlink(entry.path)
                removed += 1
        except OSError:
            continue
    return removed


class Renames:
    """The one all-or-nothing mechanism: locked temporary files beside their destinations,
    renamed over them together when all are written (`commit`), or all removed (`discard`).
    `all_or_nothing` holds one for a command's `atomic_write`s, `export.output.Outputs` one for
    an export's files.

    Example
    -------
    >>> import tempfile
    >>> folder = tempfile.mkdtemp()
    >>> renames = Renames()
    >>> handle, temporary = temporary_beside(os.path.join(folder, "a.txt"))
    >>> renames.add(temporary, os.path.join(folder, "a.txt"), handle)
    >>> renames.commit()
    >>> os.listdir(folder)
    ['a.txt']
    """

    def __init__(self):
        self.pending: list[tuple[str, str, int]] = []  # (temporary, destination, lock handle)

    def add(self, temporary: str, destination: str, handle: int) -> None:
        """Rename `temporary` over `destination` with the others; its lock is released then.

        Parameters
        ----------
        temporary : the written file (`temporary_beside`).
        destination : the output it becomes.
        handle : a file descriptor holding its lock (closed by `commit` or `discard`).
        """
        self.pending.append((temporary, os.fspath(destination), handle))

    def commit(self) -> None:
        """Give each temporary file the permissions a plain open() would (mkstemp makes 0600)
        and rename it over its destination; InputError naming the destination when one cannot
        be, and the temporaries not renamed yet are removed."""
        umask = os.umask(0)
        os.umask(umask)
        try:
            for temporary, path, _ in self.pending:
                os.chmod(temporary, 0o666 & ~umask)
                os.replace(temporary, path)
        except OSError as error:
            raise InputError(f"{path}: cannot write "
                             f"({error.strerror or one_line(error)})") from None
        finally:
            self.discard()

    def discard(self) -> None:
        """Remove the temporary files not renamed and release their locks."""
        for temporary, _, handle in self.pending:
            _remove(temporary)
            os.close(handle)
        self.pending.clear()


def temporary_beside(path: str | os.PathLike, suffix: str = "") -> tuple[int, str]:
    """A new locked temporary file in the folder of `path` (made if missing), once the debris of
    killed writers there is removed (`sweep_temporary_files`).

    Parameters
    ----------
    path : the destination.
    suffix : appended after `.part` (`locked_temporary`).

    Returns
    -------
    (file descriptor, path); OSError when the folder cannot be made or written.
    """
    folder = os.path.dirname(os.path.abspath(os.fspath(path)))
    os.makedirs(folder, exist_ok=True)
    sweep_temporary_files(folder)
    return locked_temporary(folder, suffix)


def locked_folder(prefix: str, parent: str | None = None) -> tuple[str, int]:
    """A new private folder for a process's temporary files (a server's library, a batch's
    store), with a `.lock` file this process holds (flock) for as long as it keeps the returned
    descriptor open: the system drops the lock when the process dies, however it dies, so
    `sweep_locked_folders` can tell the folders of killed processes.

    Parameters
    ----------
    prefix : the start of the folder's name (its owner's kind, e.g. "eigendance-batch-").
    parent : where to make it (default: the system's temporary folder).

    Returns
    -------
    (folder, descriptor of its held lock file); close the descriptor after removing the folder.
    """
    folder = tempfile.mkdtemp(prefix=prefix, dir=parent)
    handle = os.open(os.path.join(folder, LOCK_NAME), os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)
    try:
        fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        pass  # a file system without locks: the folder is still ours, only the sweep skips it
    return folder, handle


def sweep_locked_folders(prefix: str, parent: str | None = None,
                         fresh: float = FRESH_SECONDS) -> int:
    """Remove the folders of `locked_folder` that killed processes left. A folder is left alone
    while its lock is held, when it has no lock file (not ours to judge) and while it is younger
    than `fresh` seconds (its process may be about to take the lock).

    Parameters
    ----------
    prefix : the folders' prefix.
    parent : where to look (default: the system's temporary folder).
    fresh : seconds.

    Returns
    -------
    int, how many were removed.
    """
    parent = parent or tempfile.gettempdir()
    removed = 0
    try:
        entries = [entry for entry in os.scandir(parent) if entry.name.startswith(prefix)
                   and entry.is_dir(follow_symlinks=False)]
    except OSError:
        return 0
    for entry in entries:
        try:
            if time.time() - entry.stat(follow_symlinks=False).st_mtime < fresh:
                continue
            with open(os.path.join(entry.path, LOCK_NAME), "rb") as lock:
                fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)  # OSError while its owner runs
                shutil.rmtree(entry.path)
                removed += 1
        except OSError:
            continue
    return removed


@contextlib.contextmanager
def swept_locked_folder(prefix: str, parent: str | None = None):
    """A `locked_folder` for as long as the block runs, removed however the block ends; the
    folders that killed processes left under the same prefix are swept first
    (`sweep_locked_folders`): a server's library, a converter's glb.

    Parameters
    ----------
    prefix : the start of the folder's name (e.g. "eigendance-convert-").
    parent : where to make it (default: the system's temporary folder).

    Yields
    ------
    str, the folder.
    """
    sweep_locked_folders(prefix, parent)
    folder, lock = locked_folder(prefix, parent)
    try:
        yield folder
    finally:
        shutil.rmtree(folder, ignore_errors=True)
        os.close(lock)


# The renames a command defers until all its outputs are written (`all_or_nothing`), or None
# outside one.
_pending: contextvars.ContextVar[Renames | None] = contextvars.ContextVar("pending",
                                                                          default=None)


@contextlib.contextmanager
def all_or_nothing():
    """Within it, `atomic_write` keeps each output in its (locked) temporary file; they are all
    renamed into place when the block ends normally, and all removed when it raises: a command
    that writes several files (a spectrogram and its picture, an animation and its mapping)
    leaves none of them when it fails (`Renames`).

    Returns
    -------
    A context manager (nothing to bind); InputError when a rename at its end fails.

    Example
    -------
    >>> import tempfile
    >>> folder = tempfile.mkdtemp()
    >>> try:
    ...     with all_or_nothing():
    ...         atomic_write(os.path.join(folder, "a.txt"), lambda file: file.write(b"a"))
    ...         raise InputError("b.txt: cannot write")
    ... except InputError:
    ...     pass
    >>> os.listdir(folder)
    []
    """
    renames = Renames()
    token = _pending.set(renames)
    try:
        yield
    except BaseException:
        renames.discard()
        raise
    finally:
        _pending.reset(token)
    renames.commit()


def _remove(path: str) -> None:
    try:
        os.unlink(path)
    except OSError:
        pass


def atomic_write(path: str | os.PathLike, write, sync: bool = True, alone: bool = False) -> None:
    """Call write(file) on a temporary file beside `path`, then rename it over `path`.

    Readers never see a half-written file, and a failed write leaves no debris; the temporary
    files of killed writers in the same folder are removed first (`sweep_temporary_files`).
    sync=False skips the fsync (for large files that are cheap to recompute). An output that
    cannot be written (a folder in the way, no permission, a full disk) is an InputError naming
    the path. Within `all_or_nothing` the rename waits for the block's end (unless `alone`:
    a cache entry, useful whatever the command does next).

    Parameters
    ----------
    path : the file to write.
    write : callable(binary file).
    sync : fsync before the rename.
    alone : rename at once even within `all_or_nothing`.
    """
    path = os.fspath(path)
    if os.path.isdir(path):
        raise InputError(f"{path}: is a folder; give a file name for the output")
    try:
        # The lock is held until the file is renamed (the rename happens while it is open).
        handle, temporary = temporary_beside(path)
    except OSError as error:
        raise InputError(f"{path}: cannot write ({error.strerror or one_line(error)})") from None
    try:
        with os.fdopen(handle, "wb") as file:
            write(file)
            file.flush()
            if sync:
                os.fsync(file.fileno())
            # mkstemp creates 0600; give the file the permissions a plain open() would.
            umask = os.umask(0)
            os.umask(umask)
            os.fchmod(file.fileno(), 0o666 & ~umask)
            renames = None if alone else _pending.get()
            if renames is None:
                os.replace(temporary, path)
            else:  # renamed at the end of `all_or_nothing`, locked until then
                renames.add(temporary, path, os.dup(file.fileno()))
    except BaseException as error:
        if os.path.exists(temporary):
            os.unlink(temporary)
        if isinstance(error, OSError):
            raise InputError(f"{path}: cannot write "
                             f"({error.strerror or one_line(error)})") from None
        raise


def atomic_save_npz(path, alone: bool = False, **arrays) -> None:
    """np.savez (uncompressed: the eigenvectors are incompressible floats) written atomically.

    Every array of numbers must be finite: a result with NaN or infinite values is an InputError
    (its inputs were out of range) and no file is written.

    Parameters
    ----------
    path : the .npz to write.
    alone : as for `atomic_write`.
    **arrays : {name: array}.
    """
    for name, array in arrays.items():
        check_finite(array, f"{os.fspath(path)}: not written: {name}", OUT_OF_RANGE)
    atomic_write(path, lambda file: np.savez(file, **arrays), alone=alone)


OUT_OF_RANGE = "an input value is too large or too small for the result"


def check_finite(array, label: str, why: str = "") -> None:
    """InputError "{label} holds NaN or infinite values ({why})" unless every number in `array`
    is finite. Arrays of anything but floats (integers, strings) pass.

    Parameters
    ----------
    array : anything numpy takes.
    label : how the message names it.
    why : what the message adds in parentheses ('' for nothing).
    """
    array = np.asarray(array)
    if array.dtype.kind in "fc" and not np.isfinite(array).all():
        raise InputError(f"{label} holds NaN or infinite values" + (f" ({why})" if why else ""))


def refuse_overwrite(path, force: bool, inputs=()) -> None:
    """InputError unless `path` is free or the caller asked to overwrite it; an input of the
    command is never overwritten, `force` or not.

    Parameters
    ----------
    path : the output.
    force : overwrite anyway (not a folder, not an input).
    inputs : the files the command reads (None entries are skipped).
    """
    path = os.fspath(path)
    if os.path.isdir(path):
        raise InputError(f"{path}: is a folder; give a file name for the output")
    refuse_input(path, inputs)
    if os.path.exists(path) and not force:
        raise InputError(f"{path} exists", remedy={"force": True})
    check_writable(path)


def check_writable(path) -> None:
    """InputError unless a file can be made at `path`: the nearest folder above it that exists
    (the write makes the rest) is a folder, and one this process may write in, on a file system
    mounted for writing. Said before the work, not after it.

    Parameters
    ----------
    path : the output.
    """
    path = os.path.abspath(os.fspath(path))
    folder = os.path.dirname(path)
    while not os.path.lexists(folder) and os.path.dirname(folder) != folder:
        folder = os.path.dirname(folder)
    if not os.path.isdir(folder):
        raise InputError(f"{path}: cannot write ({folder} is a file, not a folder)")
    if not os.access(folder, os.W_OK | os.X_OK):  # EROFS for a read-only mount, root too
        try:
            read_only = os.statvfs(folder).f_flag & os.ST_RDONLY
        except OSError:
            read_only = False
        why = os.strerror(errno.EROFS if read_only else errno.EACCES)
        raise InputError(f"{path}: cannot write ({why})")


def refuse_input(path, inputs) -> None:
    """InputError when the output `path` is one of the command's `inputs` (None entries skipped).

    Parameters
    ----------
    path : an output.
    inputs : the files the command reads.
    """
    for source in inputs:
        if source is not None and same_file(path, source):
            raise InputError(f"{os.fspath(path)}: is an input of this command "
                             f"({os.fspath(source)}); an input is never overwritten, give the "
                             "output another name")


def same_file(first, second) -> bool:
    """Whether two paths name the same file (by its identity when both exist: links too).

    Parameters
    ----------
    first, second : paths.

    Returns
    -------
    bool.
    """
    try:
        return os.path.samefile(first, second)
    except (OSError, ValueError, TypeError):
        return os.path.abspath(os.fspath(first)) == os.path.abspath(os.fspath(second))
