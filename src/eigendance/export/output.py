"""Outputs of an export: all of them or none (docs/design.md#exports).

An export may write several files (a .glb and its song, a .pc2 and its rest mesh, an .mp4 that
ffmpeg writes by name). `Outputs` checks every destination before any work starts, hands out a
temporary path beside each one (`.eigendance-XXXX.part.<suffix>`, locked by this process as
docs/design.md#files says, so that the temporaries of a killed export are swept by the next
write there), and renames them all into place only when the whole export has succeeded; an
error, Ctrl-C or any other exception deletes the temporaries, so a destination either keeps what
it held before or receives a complete file.

A process killed outright (SIGKILL) runs no cleanup, so a janitor process started with the
temporaries' names removes them the moment this one dies without having renamed or removed
them (its end of a pipe closes); the sweep is the second guard. An input of the command is
never a destination, `force` or not; a failed write (a full disk, a read-only folder) is an
`InputError` naming the destination.
"""

from __future__ import annotations

import errno
import os
import shutil
import subprocess
import sys

from eigendance.errors import InputError, one_line
from eigendance.writes import Renames, refuse_overwrite, temporary_beside

# The janitor: reads NUL-terminated paths; an empty record means the owner finished (renamed
# or removed them) and it exits at once (children forked by the owner may hold the pipe open);
# the end of its stdin without one means the owner died, and it removes them. Signals from the
# terminal or the owner's group do not stop it: only the owner's end of the pipe does.
JANITOR = """
import os, signal, sys
for number in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
    signal.signal(number, signal.SIG_IGN)
data = b""
while chunk := os.read(0, 65536):
    data += chunk
    records = data.split(b"\\0")
    if b"" in records[:-1]:
        sys.exit()
for record in data.split(b"\\0")[:-1]:
    try:
        os.unlink(os.fsdecode(record))
    except OSError:
        pass
"""


def check_space(log: str, path: str) -> None:
    """OSError(ENOSPC) naming `path` when a program's error output says the disk is full
    (ffmpeg writing a video or a song), so that `Outputs` reports it as an InputError.

    Parameters
    ----------
    log : the program's error output.
    path : the file it was writing.
    """
    if os.strerror(errno.ENOSPC) in log or "No space left" in log:
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), path)


def start_janitor() -> subprocess.Popen | None:
    """The janitor process of one `Outputs`.

    Returns
    -------
    subprocess.Popen, its stdin the pipe of names; None where none can start (the sweep
    remains).
    """
    try:
        return subprocess.Popen([sys.executable, "-I", "-S", "-c", JANITOR],
                                stdin=subprocess.PIPE, stdout=subprocess.DEVNULL,
                                stderr=subprocess.DEVNULL, start_new_session=True)
    except OSError:
        return None


class Outputs:
    """Temporary files beside their destinations, renamed over them together on success.

    Parameters
    ----------
    destinations : the files the export writes.
    force : overwrite destinations that exist (else InputError before any work).
    inputs : the files the command reads: never overwritten (InputError before any work).

    Example
    -------
    >>> import tempfile
    >>> folder = tempfile.mkdtemp()
    >>> with Outputs([os.path.join(folder, "a.txt")]) as outputs:
    ...     with open(outputs.temporary(os.path.join(folder, "a.txt")), "w") as file:
    ...         _ = file.write("done")
    >>> sorted(os.listdir(folder))
    ['a.txt']
    """

    def __init__(self, destinations, force: bool = False, inputs=()):
        self.destinations = [os.path.abspath(os.fspath(path)) for path in destinations]
        if len(set(self.destinations)) != len(self.destinations):
            raise InputError(f"{destinations[0]}: the export would write the same file twice")
        for path in self.destinations:
            refuse_overwrite(path, force, inputs)
        self.temporaries: dict[str, str] = {}
        self._renames = Renames()  # the temporaries, locked until renamed or removed
        self._janitor: subprocess.Popen | None = None

    def __enter__(self) -> Outputs:
        self._janitor = start_janitor()
        for path in self.destinations:
            try:
                # The destination's suffix stays last: USD and ffmpeg choose the format by it.
                handle, temporary = temporary_beside(path, os.path.splitext(path)[1])
            except OSError as error:
                self._discard()
                raise InputError(f"{path}: cannot write "
                                 f"({error.strerror or one_line(error)})") from None
            self._renames.add(temporary, path, handle)
            self.temporaries[path] = temporary
            self._tell_janitor(os.fsencode(temporary) + b"\0")
        return self

    def temporary(self, destination) -> str:
        """The temporary path that becomes `destination` on success.

        Parameters
        ----------
        destination : one of the export's files.

        Returns
        -------
        str, the path to write it to.
        """
        return self.temporaries[os.path.abspath(os.fspath(destination))]

    def copy(self, source, destination) -> None:
        """Copy the file `source` to the temporary of `destination`.

        Parameters
        ----------
        source : the file to copy.
        destination : one of the export's files.
        """
        try:
            shutil.copyfile(os.fspath(source), self.temporary(destination))
        except OSError as error:
            raise InputError(f"{destination}: cannot write "
                             f"({error.strerror or one_line(error)})") from None

    def __exit__(self, kind, error, traceback) -> None:
        if kind is not None:
            destination = self._destination_of(getattr(error, "filename", None))
            self._discard()
            if isinstance(error, OSError):  # a full disk, a folder made read-only …
                raise InputError(f"{destination}: cannot write "
                                 f"({error.strerror or one_line(error)})") from None
            return
        try:
            self._renames.commit()  # InputError naming the destination that cannot be written
        finally:
            self.temporaries.clear()
            self._done()

    def _discard(self) -> None:
        self._renames.discard()
        self.temporaries.clear()
        self._done()

    def _destination_of(self, filename) -> str:
        for path, temporary in self.temporaries.items():
            if filename in (path, temporary):
                return path
        return self.destinations[0]

    def _tell_janitor(self, record: bytes) -> None:
        if self._janitor is None:
            return
        try:
            self._janitor.stdin.write(record)
            self._janitor.stdin.flush()
        except OSError:
            self._janitor = None  # it is gone: the sweep remains

    def _done(self) -> None:
        if self._janitor is not None:  # done: the temporaries are renamed or removed
            janitor, self._janitor = self._janitor, None
            try:
                janitor.stdin.write(b"\0")
                janitor.stdin.close()
            except OSError:
                pass
            janitor.wait()
