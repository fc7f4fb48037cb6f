"""Prepared inputs shared by every local worker without copying (docs/design.md#batch).

The local engine's counterpart of Ray's object store, made the same way: an object (a basis, a
rig, a spectrogram, a gallery) is pickled with protocol 5, its large arrays taken out of band
(`pickle.PickleBuffer`) and written raw, 64-byte aligned, into one file after the small pickled
rest. A worker maps the file read-only and unpickles the rest over views of the mapping, so
every array is a read-only view of pages the system shares among all the processes that map
the file: a basis is read from disk once per machine, not once per worker.

The files live in a folder private to the run (`Store`), removed when the batch ends; only the
batch's own processes read them. The run holds the folder's lock (`writes.locked_folder`, as a
server holds its library's), so the folder of a killed batch driver — every prepared basis, rig
and spectrogram — is swept by the next batch to start.
"""

from __future__ import annotations

import functools
import mmap
import os
import pickle
import shutil
import struct

from eigendance.writes import atomic_write, locked_folder, sweep_locked_folders

ALIGN = 64
HEADER = struct.Struct("<8sQQ")  # magic, pickle length, buffer count
MAGIC = b"EDSHARE1"
STORE_PREFIX = "eigendance-batch-"


def save(obj, path: str) -> str:
    """Write `obj` as a shared file (module docstring), atomically.

    Parameters
    ----------
    obj : any picklable object (arrays inside are written out of band).
    path : the file to write.

    Returns
    -------
    str, the path.
    """
    buffers: list[pickle.PickleBuffer] = []
    data = pickle.dumps(obj, protocol=5, buffer_callback=buffers.append)
    raws = [buffer.raw() for buffer in buffers]
    offsets, end = [], _aligned(HEADER.size + 16 * len(raws) + len(data))
    for raw in raws:
        offsets.append(end)
        end = _aligned(end + raw.nbytes)
    table = struct.pack(f"<{2 * len(raws)}Q", *(value for offset, raw in
                                                zip(offsets, raws, strict=True)
                                                for value in (offset, raw.nbytes)))

    def write(file):
        file.write(HEADER.pack(MAGIC, len(data), len(raws)) + table + data)
        for offset, raw in zip(offsets, raws, strict=True):
            file.seek(offset)
            file.write(raw)
        file.truncate(end)

    atomic_write(path, write, sync=False, alone=True)  # read back by this run only
    return path


def _aligned(offset: int) -> int:
    return -(-offset // ALIGN) * ALIGN


@functools.lru_cache(maxsize=32)
def load(path: str):
    """The object of a shared file, its arrays read-only views of the file mapped in memory
    (kept per process: a worker maps each file once).

    Parameters
    ----------
    path : a file written by `save`.

    Returns
    -------
    The object.
    """
    with open(path, "rb") as file:
        mapped = mmap.mmap(file.fileno(), 0, access=mmap.ACCESS_READ)
    view = memoryview(mapped)
    magic, length, count = HEADER.unpack_from(view)
    if magic != MAGIC:
        raise ValueError(f"{path}: not a shared object file")
    table = struct.unpack_from(f"<{2 * count}Q", view, HEADER.size)
    begin = HEADER.size + 16 * count
    buffers = [view[table[2 * i]:table[2 * i] + table[2 * i + 1]] for i in range(count)]
    return pickle.loads(view[begin:begin + length], buffers=buffers)


class Store:
    """A private folder of shared files for one run, removed on exit.

    Parameters
    ----------
    parent : where to make it (default: the system's temporary folder).
    """

    def __init__(self, parent: str | None = None):
        sweep_locked_folders(STORE_PREFIX, parent)  # the stores of killed batches
        self.folder, self._lock = locked_folder(STORE_PREFIX, parent)
        self._count = 0

    def put(self, obj) -> str:
        """Share an object: the path workers `load`.

        Parameters
        ----------
        obj : the object.

        Returns
        -------
        str.
        """
        self._count += 1
        return save(obj, os.path.join(self.folder, f"{self._count}.shared"))

    def path(self, name: str) -> str:
        """A new file's path in the store, for a worker to `save` into.

        Parameters
        ----------
        name : a name unique in this run.

        Returns
        -------
        str.
        """
        return os.path.join(self.folder, name + ".shared")

    def close(self) -> None:
        """Remove the folder and everything in it, then drop its lock."""
        shutil.rmtree(self.folder, ignore_errors=True)
        if self._lock is not None:
            os.close(self._lock)
            self._lock = None
