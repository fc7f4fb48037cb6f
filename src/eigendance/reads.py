"""Reading files within bounds (docs/design.md#errors): only regular files are opened, and the
sizes a file declares are checked against the bytes it holds and the memory available before
anything is allocated.

A FIFO, a device or a directory in place of a file would block a reader forever or feed it
without end; `open_regular` opens without blocking and refuses anything but a regular file. An
.npz member declares its array's shape in its header and numpy allocates that shape before it
reads a byte; `read_npz` compares every declared size with what the archive really holds (the
sizes zipfile checks while it inflates) and their total with `limits.memory_budget`.
"""

from __future__ import annotations

import os
import stat
import zipfile
from typing import BinaryIO

import numpy as np

from eigendance.errors import InputError, one_line
from eigendance.limits import memory_budget, size_text


def open_regular(path: str | os.PathLike, what: str | None = None) -> BinaryIO:
    """Open a file for reading in binary; InputError unless it is a regular file (checked on the
    open file, so a FIFO swapped in meanwhile is refused too; opening never blocks).

    Parameters
    ----------
    path : the file.
    what : how messages call it (default: the path).

    Returns
    -------
    A binary file object (close it, or use it in a with block).

    Example
    -------
    >>> import os, tempfile
    >>> fifo = os.path.join(tempfile.mkdtemp(), "pipe.npz")
    >>> os.mkfifo(fifo)
    >>> open_regular(fifo, "pipe.npz")
    Traceback (most recent call last):
    ...
    eigendance.errors.InputError: pipe.npz: not a regular file (a FIFO); only files are read
    """
    what = what or os.fspath(path)
    try:
        descriptor = os.open(path, os.O_RDONLY | os.O_NONBLOCK | os.O_CLOEXEC)
    except OSError as error:
        raise InputError(f"{what}: cannot be read ({error.strerror or error})",
                         status=404 if error.errno == 2 else 400) from None
    mode = os.fstat(descriptor).st_mode
    if not stat.S_ISREG(mode):
        os.close(descriptor)
        kind = {stat.S_IFIFO: "a FIFO", stat.S_IFDIR: "a folder", stat.S_IFCHR: "a device",
                stat.S_IFBLK: "a device", stat.S_IFSOCK: "a socket"}.get(stat.S_IFMT(mode),
                                                                       "not a file")
        raise InputError(f"{what}: not a regular file ({kind}); only files are read")
    os.set_blocking(descriptor, True)
    return os.fdopen(descriptor, "rb")


# The first bytes of a zip archive (an .npz): a local file header, or an empty one's end record.
ZIP_MAGIC = (b"PK\x03\x04", b"PK\x05\x06")


def read_npz(path: str | os.PathLike, what: str | None = None) -> dict[str, np.ndarray]:
    """Every array of an .npz file, each member's declared size checked first.

    Parameters
    ----------
    path : the file (a regular file: `open_regular`).
    what : how messages call it (default: the path).

    Returns
    -------
    {name: array}; InputError when the file is not a readable .npz, a member declares more
    bytes than it holds, or the arrays would not fit in `limits.memory_budget`.
    """
    what = what or os.fspath(path)
    with open_regular(path, what) as file:
        head = file.read(4)
        if head not in ZIP_MAGIC:  # np.load would take it for an .npy or a pickle
            raise InputError(f"{what}: not an .npz file (an .npz is a zip archive; this one "
                             f"begins {head!r})")
        file.seek(0)
        try:
            with np.load(file, allow_pickle=False) as data:
                _check_declared(data.zip, what)
                return {name: data[name] for name in data.files}
        except InputError:
            raise
        except (OSError, ValueError, zipfile.BadZipFile, EOFError, KeyError) as error:
            raise InputError(f"{what}: not a readable .npz file ({one_line(error)})") from None


def _check_declared(archive: zipfile.ZipFile, what: str) -> None:
    """InputError when a member's header declares an array larger than the member, or when the
    members together exceed the memory budget."""
    total = 0
    for info in archive.infolist():
        total += info.file_size
        if not info.filename.endswith(".npy"):
            continue
        with archive.open(info) as member:
            version = np.lib.format.read_magic(member)
            read_header = np.lib.format.read_array_header_1_0 if version == (1, 0) else \
                np.lib.format.read_array_header_2_0
            shape, _, dtype = read_header(member)
        declared = int(np.prod(shape, dtype=object)) * dtype.itemsize
        if declared > info.file_size:
            raise InputError(f"{what}: {info.filename[:-4]} declares {shape} {dtype} "
                             f"({size_text(declared)}) in {size_text(info.file_size)}")
    if total > memory_budget():
        raise InputError(f"{what}: its arrays need {size_text(total)} of memory; "
                         f"{size_text(memory_budget())} can be used")
