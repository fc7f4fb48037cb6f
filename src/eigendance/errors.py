"""Errors by kind (docs/design.md#errors).

Every message is one complete line that names the input and what is wrong with it, in words a
user of the library, the command line or the web page understands: no command-line flags. The
front ends add their own hints from `remedy` (the CLI turns {"solver": "eigsh"} into
"try --solver eigsh").

- `InputError`: the input is wrong or the request impossible (a malformed file, a bad value, an
  output that cannot be written). The user can fix it: CLI exit status 1, HTTP 4xx.
- `InternalError`: a failure of ours (a solver that did not converge, a check of our own results
  that failed). It is a bug to report: CLI exit status 2, HTTP 500.
"""

from __future__ import annotations

import errno


class EigendanceError(Exception):
    """Base of the errors eigendance raises on purpose; ``str(error)`` is one line.

    remedy: settings that may avoid the error, {parameter: value}, e.g. {"laplacian": "robust"}.

    Parameters
    ----------
    message : the error on one line (folded onto one line if it is not).
    remedy : settings that may avoid it.

    Example
    -------
    >>> str(EigendanceError("spaced    out\ttext"))
    'spaced out text'
    """

    def __init__(self, message: str, remedy: dict | None = None):
        super().__init__(one_line(message))
        self.remedy = dict(remedy or {})


class InputError(EigendanceError, ValueError):
    """Bad input or an impossible request; `status` is the HTTP status the server answers.

    Parameters
    ----------
    message : one line naming the input and the problem.
    remedy : settings that may avoid it, e.g. {"laplacian": "robust"}.
    status : HTTP status (400, or 404, 409, 413, 415 where they fit).

    Example
    -------
    >>> error = InputError("bunny.obj: 47 non-manifold edges", remedy={"laplacian": "robust"})
    >>> str(error), error.remedy, error.status
    ('bunny.obj: 47 non-manifold edges', {'laplacian': 'robust'}, 400)
    """

    def __init__(self, message: str, remedy: dict | None = None, status: int = 400):
        super().__init__(message, remedy)
        self.status = status


class InternalError(EigendanceError, RuntimeError):
    """A failure of eigendance itself (a bug to report), not of its input.

    Parameters
    ----------
    message : one line saying what failed.
    remedy : settings that may avoid it, e.g. {"solver": "eigsh"}.

    Example
    -------
    >>> isinstance(InternalError("eigen-solver: residual 1e-3"), EigendanceError)
    True
    """


def one_line(error: BaseException | str, limit: int = 300) -> str:
    """The text of an error (or a string) on one line, at most `limit` characters.

    Control characters (terminal escapes included) are dropped, so a message built from a file
    name or a file's content cannot rewrite the user's terminal.

    Parameters
    ----------
    error : an exception or a string.
    limit : the most characters kept (longer text ends in "…").

    Returns
    -------
    str.
    """
    text = error if isinstance(error, str) else (str(error) or type(error).__name__)
    text = "".join(character if character.isprintable() else " " for character in text)
    text = " ".join(text.split())
    return text if len(text) <= limit else text[:limit - 1] + "…"


class ModelWarning(UserWarning):
    """What a model file holds that eigendance cannot keep (points, lines, an unreadable
    texture, morph targets of its own): one line naming the file, issued once per read."""


def disk_full(error: BaseException) -> bool:
    """Whether an error is a full disk or an exhausted quota (the server answers 507).

    Parameters
    ----------
    error : any exception.

    Returns
    -------
    bool.

    Example
    -------
    >>> disk_full(OSError(errno.ENOSPC, "No space left on device")), disk_full(ValueError())
    (True, False)
    """
    return isinstance(error, OSError) and error.errno in (errno.ENOSPC, errno.EDQUOT)
