"""What one request may allocate, checked before the work starts (docs/design.md#errors).

A value that is valid on its own (k = 20000 harmonics, 1000 frames per second, a day of
animation) can still ask for more memory or disk than the machine has. The planned size is
compared with what is there before anything is allocated, so the request ends in a one-line
`InputError` instead of the out-of-memory killer or a full disk.
"""

from __future__ import annotations

import os
import shutil

from eigendance.errors import InputError

# Share of the memory available now that one result may plan to use: the estimates are
# generous, and the point is to refuse what cannot fit, not what might.
MEMORY_SHARE = 0.8


def available_memory() -> int:
    """Bytes of memory available to a new allocation: Linux's MemAvailable, else all RAM.

    Returns
    -------
    int, bytes.
    """
    try:
        with open("/proc/meminfo", encoding="ascii") as file:
            for line in file:
                if line.startswith("MemAvailable:"):
                    return int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        pass
    return os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")


def memory_budget() -> float:
    """Bytes one result may plan to use: MEMORY_SHARE of the memory available now.

    Returns
    -------
    float, bytes.
    """
    return MEMORY_SHARE * available_memory()


def size_text(count: float) -> str:
    """Bytes in words: '3.2 GB', '512 MB'.

    Parameters
    ----------
    count : bytes.

    Returns
    -------
    str.
    """
    for unit, size in (("TB", 1e12), ("GB", 1e9), ("MB", 1e6)):
        if count >= size:
            return f"{count / size:.1f} {unit}"
    return f"{count / 1e3:.1f} kB"


def check_memory(planned: float, what: str, remedy: dict | None = None) -> None:
    """InputError unless `planned` bytes fit in MEMORY_SHARE of the memory available now.

    what: the request in words, e.g. "teapot.obj: 20000 harmonics of 1.2M vertices".

    Parameters
    ----------
    planned : bytes.
    what : the request in words.
    remedy : settings that may avoid the error (the CLI shows them as flags).
    """
    limit = memory_budget()
    if planned > limit:
        raise InputError(f"{what} need about {size_text(planned)} of memory; "
                         f"{size_text(limit)} can be used", remedy=remedy)


# Bytes above which an output is written only when asked for (`force`): a point cache of a
# million vertices for a 3-minute song is 65 GB, more than anyone means to write by accident.
LARGE_OUTPUT = 4e9


def check_output(path: str | os.PathLike, planned: float, what: str, force: bool) -> None:
    """InputError unless `planned` bytes fit on the disk and, beyond LARGE_OUTPUT, `force`
    asks for them: the size is said before anything is written.

    Parameters
    ----------
    path : the output.
    planned : its size, bytes.
    what : the output in words, e.g. "dance.pc2: 5401 frames of 1151994 vertices".
    force : write it however large.
    """
    check_disk(path, planned, what)
    if planned > LARGE_OUTPUT and not force:
        raise InputError(f"{what} would be {size_text(planned)}, a very large file",
                         remedy={"force": "write it anyway"})


def check_disk(path: str | os.PathLike, planned: float, what: str,
               remedy: dict | None = None) -> None:
    """InputError unless `planned` bytes fit on the disk that holds `path`'s folder.

    Parameters
    ----------
    path : the output.
    planned : bytes.
    what : the request in words.
    remedy : settings that may avoid the error.
    """
    folder = os.path.dirname(os.path.abspath(os.fspath(path)))
    while folder and not os.path.isdir(folder):
        folder = os.path.dirname(folder)
    try:
        free = shutil.disk_usage(folder or ".").free
    except OSError:
        return  # unknown: the write itself reports a full disk
    if planned > free:
        raise InputError(f"{what} need about {size_text(planned)} of disk; "
                         f"{size_text(free)} is free there", remedy=remedy)
