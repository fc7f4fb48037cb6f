"""Worker processes that leave Ctrl-C to their caller and die with it (docs/design.md#batch).

The eigen-solver's band workers and a batch's workers start with `start_worker(caller)`:
Ctrl-C (SIGINT, which a terminal sends to its whole foreground group) is ignored, so the
caller alone decides what an interruption stops; on Linux the kernel kills the worker when its
parent dies (PR_SET_PDEATHSIG), and, elsewhere or as a second guard, a thread polls the caller
and the parent and exits when either is gone. However the caller ends, no worker is left
behind.
"""

from __future__ import annotations

import ctypes
import os
import signal
import sys
import threading
import time

POLL_SECONDS = 0.5


def start_worker(caller: int) -> None:
    """In a new worker process: ignore Ctrl-C and exit when `caller` or the parent is gone.

    Parameters
    ----------
    caller : the process id of the process the worker works for.
    """
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    parent = os.getppid()
    if sys.platform.startswith("linux"):  # the kernel kills us when our parent dies
        PR_SET_PDEATHSIG = 1
        ctypes.CDLL(None, use_errno=True).prctl(PR_SET_PDEATHSIG, signal.SIGKILL)

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
