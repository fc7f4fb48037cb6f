"""The record of a batch's outputs, beside them, and its report (docs/design.md#batch).

`out/batch-record.jsonl` holds one line per output written: its name, its content key
(`content.output_key`) and each of its files (the main file and what it wrote beside: the song,
a point cache's rest mesh …) with their size, modification time and SHA-256. A line is appended
and flushed to disk as soon as an output is complete, so a batch stopped in any way (Ctrl-C, a
killed process, a power cut: a torn last line is ignored) resumes from what it finished. An
output is complete when its line has the same key and each of its files is there with the
same size and the same modification time or, failing that, the same SHA-256; otherwise it is
made again. Before a run makes anything, each output it will make is *claimed*: a line without
a key naming the files it writes, so that a file a worker finished just before Ctrl-C (or a
kill), not yet recorded, counts as the batch's own and is made again without `--force`. At the
end of a run the record is rewritten compactly (one line per output),
atomically. While a batch runs it holds a lock on its output folder: a second batch writing
into the same folder stops with one line.

`out/batch-report.jsonl` has one line per job of the last run: its status, timings and
output paths.
"""

from __future__ import annotations

import fcntl
import json
import os

from eigendance.errors import InputError
from eigendance.files import file_digest  # noqa: F401 - the record's content key
from eigendance.writes import atomic_write

RECORD, REPORT = "batch-record.jsonl", "batch-report.jsonl"


def file_entry(path: str) -> dict:
    """What the record keeps of a file: its size, modification time and SHA-256.

    Parameters
    ----------
    path : a file.

    Returns
    -------
    {"bytes", "mtime_ns", "sha256"}.
    """
    status = os.stat(path)
    return {"bytes": status.st_size, "mtime_ns": status.st_mtime_ns,
            "sha256": file_digest(path)}


class Record:
    """The record of the outputs in one folder (module docstring); a context manager holding the
    folder's lock.

    Parameters
    ----------
    out : the output folder (made if missing).
    """

    def __init__(self, out: str):
        self.out = out
        self.entries: dict[str, dict] = {}
        self._lock = self._journal = None

    def __enter__(self) -> Record:
        try:
            os.makedirs(self.out, exist_ok=True)
            self._lock = os.open(self.out, os.O_RDONLY)
        except OSError as error:
            raise InputError(f"{self.out}: cannot use the folder ({error.strerror})") from None
        try:
            fcntl.flock(self._lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            os.close(self._lock)
            self._lock = None
            raise InputError(f"{self.out}: another batch is writing there; wait for it or "
                             "give another out folder") from None
        try:
            self._open_journal()
        except BaseException:
            os.close(self._lock)
            self._lock = None
            raise
        return self

    def _open_journal(self) -> None:
        """Read the record and open it for appending: never through a link (a planted one would
        get our lines appended to its target), nor a report that is one."""
        for name in (RECORD, REPORT):
            if os.path.islink(os.path.join(self.out, name)):
                raise InputError(f"{os.path.join(self.out, name)}: is a link; a batch writes its "
                                 "record and report only as files of their own: remove it")
        path = os.path.join(self.out, RECORD)
        self.entries = read_entries(path)
        flags = os.O_WRONLY | os.O_APPEND | os.O_CREAT | getattr(os, "O_NOFOLLOW", 0)
        try:
            self._journal = os.fdopen(os.open(path, flags, 0o644), "a", encoding="utf-8")
        except OSError as error:
            raise InputError(f"{path}: cannot write the record ({error.strerror})") from None

    def __exit__(self, *exception) -> None:
        try:
            if self._journal is not None:
                self._journal.close()
                self.compact()
        finally:
            if self._lock is not None:
                os.close(self._lock)  # drops the lock
            self._lock = self._journal = None

    def complete(self, output: str, key: str) -> bool:
        """Whether `output` (a name in the folder) is recorded under `key` with every file intact.

        Parameters
        ----------
        output : the output's file name.
        key : its content key now.

        Returns
        -------
        bool.
        """
        entry = self.entries.get(output)
        if entry is None or entry.get("key") != key:
            return False
        for name, stored in entry.get("files", {}).items():
            if not isinstance(stored, dict):
                return False
            path = os.path.join(self.out, name)
            try:
                status = os.stat(path)
            except OSError:
                return False
            if status.st_size != stored.get("bytes"):
                return False
            if status.st_mtime_ns != stored.get("mtime_ns"):
                if file_digest(path) != stored.get("sha256"):
                    return False
                stored["mtime_ns"] = status.st_mtime_ns  # touched, not changed
        return True

    def ours(self, name: str) -> bool:
        """Whether a file of the folder was written by a batch (any recorded output's file).

        Parameters
        ----------
        name : a file name in the folder.

        Returns
        -------
        bool.
        """
        return any(name in entry.get("files", {}) for entry in self.entries.values())

    def add(self, output: str, key: str, files: dict[str, dict]) -> None:
        """Record a complete output now (appended and flushed to disk).

        Parameters
        ----------
        output : the output's file name.
        key : its content key.
        files : {file name in the folder: `file_entry`}, the main file first.
        """
        entry = {"output": output, "key": key, "files": files}
        self.entries[output] = entry
        self._journal.write(json.dumps(entry, sort_keys=True) + "\n")
        self._journal.flush()
        os.fsync(self._journal.fileno())

    def claim(self, outputs: dict[str, list[str]]) -> None:
        """Record outputs about to be made as the batch's, not complete (no key): a file a
        worker writes there is the batch's even when it was stopped before `add` (appended and
        flushed to disk at once).

        Parameters
        ----------
        outputs : {output's file name: the names it writes in the folder}.
        """
        for output, names in outputs.items():
            entry = {"output": output, "key": None, "files": dict.fromkeys(names)}
            self.entries[output] = entry
            self._journal.write(json.dumps(entry, sort_keys=True) + "\n")
        self._journal.flush()
        os.fsync(self._journal.fileno())

    def compact(self) -> None:
        """Rewrite the record with one line per output (atomically)."""
        text = "".join(json.dumps(entry, sort_keys=True) + "\n"
                       for entry in self.entries.values())
        atomic_write(os.path.join(self.out, RECORD), lambda file: file.write(text.encode()),
                     alone=True)


def recorded_files(out: str) -> set[str]:
    """The files of `out` that a batch wrote or claimed (any recorded output's files), with the
    record and the report themselves: what a plan's globs never take as inputs.

    Parameters
    ----------
    out : the output folder.

    Returns
    -------
    set of normalized absolute paths.
    """
    path = os.path.join(out, RECORD)
    names = {RECORD, REPORT}
    if not os.path.islink(path):
        for entry in read_entries(path).values():
            names.update(name for name in entry["files"] if isinstance(name, str))
    return {os.path.normpath(os.path.join(os.path.abspath(out), name)) for name in names}


def read_entries(path: str) -> dict[str, dict]:
    """The record's entries by output, the last line of each output winning; lines that are
    not whole JSON objects (a torn last line) are skipped.

    Parameters
    ----------
    path : the record file.

    Returns
    -------
    {output: entry}.
    """
    entries: dict[str, dict] = {}
    try:
        with open(path, encoding="utf-8", errors="replace") as file:
            for line in file:
                try:
                    entry = json.loads(line)
                except ValueError:
                    continue
                if isinstance(entry, dict) and isinstance(entry.get("output"), str) and \
                        isinstance(entry.get("files"), dict):
                    entries[entry["output"]] = entry
    except FileNotFoundError:
        pass
    except OSError as error:
        raise InputError(f"{path}: cannot read the record ({error.strerror})") from None
    return entries


def write_report(out: str, lines: list[dict]) -> str:
    """Write `out/batch-report.jsonl`, one JSON object per job, atomically.

    Parameters
    ----------
    out : the output folder.
    lines : one dict per job.

    Returns
    -------
    str, the report's path.
    """
    path = os.path.join(out, REPORT)
    text = "".join(json.dumps(line, sort_keys=True) + "\n" for line in lines)
    atomic_write(path, lambda file: file.write(text.encode()), alone=True)
    return path
