"""Worker processes that leave Ctrl-C to their caller and die with it (docs/design.md#batch).

The eigen-solver's band workers and a batch's workers start with `start_worker(caller)`:
Ctrl-C (SIGINT, which a terminal sends to its whole foreground group) is ignored, so the
caller alone decides what an interruption stops; on Linux the kernel kills the worker when its
parent dies (PR_SET_PDEATHSIG), and, elsewhere or as a second guard, a thread polls the caller
and the parent and exits when either is gone. However the caller ends, no worker is left
behind. Programs we run (ffmpeg) start with `die_with_parent` for the same reason: a killed
`render` leaves no encoder writing on (docs/design.md#errors).
"""

from __future__ import annotations

import ctypes
import os
import signal
import sys
import threading
import time

POLL_SECONDS = 0.5
PR_SET_PDEATHSIG = 1
# Resolved here, in the parent: the child of a fork runs only this C call before exec (a
# preexec_fn that imported or took a lock could deadlock in a threaded parent such as the server).
_prctl = ctypes.CDLL(None, use_errno=True).prctl if sys.platform.startswith("linux") else None


def die_with_parent() -> None:
    """subprocess's preexec_fn for a program we run: the kernel kills it (SIGKILL) when the
    thread that started it dies, however it dies (Linux; elsewhere nothing).

    Example
    -------
    >>> import subprocess, sys
    >>> subprocess.run([sys.executable, "-c", "pass"], preexec_fn=die_with_parent).returncode
    0
    """
    if _prctl is not None:
        _prctl(PR_SET_PDEATHSIG, signal.SIGKILL)


def start_worker(caller: int) -> None:
    """In a new worker process: ignore Ctrl-C and exit when `caller` or the parent is gone.

    Parameters
    ----------
    caller : the process id of the process the worker works for.
    """
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    parent = os.getppid()
    die_with_parent()  # the kernel kills us when our parent dies

    def watch():  # elsewhere, and as a second guard: poll the caller and the parent
        while True:
            time.sleep(POLL_SECONDS)
            try:
                os.kill(caller, 0)
            except ProcessLookupError:
                os._exit(1)
            except PermissionError:
                pass
            if os.getppid() != parent:
                os._exit(1)

    threading.Thread(target=watch, name="watch-caller", daemon=True).start()
