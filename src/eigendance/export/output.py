"""Outputs of an export: all of them or none (docs/design.md#exports).

An export may write several files (a .glb and its song, a .pc2 and its rest mesh, an .mp4 that
ffmpeg writes by name). `Outputs` checks every destination before any work starts, hands out a
temporary path beside each one, and renames them all into place only when the whole export has
succeeded; an error, Ctrl-C or any other exception deletes the temporaries, so a destination
either keeps what it held before or receives a complete file.
"""

from __future__ import annotations

import os
import shutil
import tempfile

from eigendance.errors import InputError, one_line
from eigendance.files import refuse_overwrite


class Outputs:
    """Temporary files beside their destinations, renamed over them together on success.

    Parameters
    ----------
    destinations : the files the export writes.
    force : overwrite destinations that exist (else InputError before any work).

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

    def __init__(self, destinations, force: bool = False):
        self.destinations = [os.path.abspath(os.fspath(path)) for path in destinations]
        if len(set(self.destinations)) != len(self.destinations):
            raise InputError(f"{destinations[0]}: the export would write the same file twice")
        for path in self.destinations:
            refuse_overwrite(path, force)
        self.temporaries: dict[str, str] = {}

    def __enter__(self) -> Outputs:
        for path in self.destinations:
            folder = os.path.dirname(path)
            try:
                os.makedirs(folder, exist_ok=True)
                # The destination's suffix stays last: USD and ffmpeg choose the format by it.
                handle, temporary = tempfile.mkstemp(
                    dir=folder, prefix=".tmp-", suffix=".part" + os.path.splitext(path)[1])
            except OSError as error:
                self._discard()
                raise InputError(f"{path}: cannot write "
                                 f"({error.strerror or one_line(error)})") from None
            os.close(handle)
            self.temporaries[path] = temporary
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
            self._discard()
            return
        try:
            umask = os.umask(0)  # mkstemp creates 0600; give what a plain open() would
            os.umask(umask)
            for temporary in self.temporaries.values():
                os.chmod(temporary, 0o666 & ~umask)
            for path, temporary in self.temporaries.items():
                os.replace(temporary, path)
        except BaseException as failure:
            self._discard()
            if isinstance(failure, OSError):
                raise InputError(f"{failure.filename or self.destinations[0]}: cannot write "
                                 f"({failure.strerror or one_line(failure)})") from None
            raise

    def _discard(self) -> None:
        for temporary in self.temporaries.values():
            if os.path.exists(temporary):
                os.unlink(temporary)
        self.temporaries.clear()
