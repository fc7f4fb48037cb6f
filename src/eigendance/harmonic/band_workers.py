"""The processes that solve the eigen-solver's bands (docs/design.md#eigensolver).

Forked from a single-threaded caller, started by a fork server for a multi-threaded one (the web
server solves in a thread); they ignore Ctrl-C and die with the caller (`processes.start_worker`).
An interrupted or failed solve kills them at once and leaves no thread of the pool waiting.
"""

from __future__ import annotations

import multiprocessing
import os
import sys
import threading
from concurrent.futures import ProcessPoolExecutor
from multiprocessing import resource_tracker

from eigendance.processes import start_worker


class Workers:
    """Calls `function` on each of a list of arguments, in `workers` separate processes when
    there are several (the eigen-solver's bands).

    A single-threaded caller is forked (fast, and nothing is imported again). A multi-threaded
    one (the web server solves in a thread) is never forked — a fork copies locks other threads
    may hold — so its workers come from a fork server, a fresh single-threaded interpreter; like
    `spawn`, it imports the caller's main module (which needs the usual `__main__` guard). The
    workers ignore Ctrl-C (the caller handles it and stops them) and die with the caller,
    whatever signal ends it.

    Parameters
    ----------
    workers : processes.
    function : a module-level callable(argument) (the workers import its module).
    here : what runs instead when a call is made in this process (one argument, or one
        worker); default `function`.

    Example
    -------
    >>> with Workers(1, abs) as run:
    ...     run([-1, 2])
    [1, 2]
    """

    def __init__(self, workers: int, function, here=None):
        self.workers, self.function, self.pool = workers, function, None
        self.here = function if here is None else here

    def __enter__(self):
        return self

    def __call__(self, arguments: list) -> list:
        """[function(argument) for each argument], in order.

        Parameters
        ----------
        arguments : the arguments.

        Returns
        -------
        list of the results.
        """
        if len(arguments) == 1 or self.workers == 1:
            return [self.here(each) for each in arguments]
        if self.pool is None:
            methods = multiprocessing.get_all_start_methods()
            if threading.active_count() == 1 and "fork" in methods:
                method = "fork"
            else:
                method = "forkserver" if "forkserver" in methods else "spawn"
            if method != "fork":
                quiet_resource_tracker()
            context = multiprocessing.get_context(method)
            if method == "forkserver":
                context.set_forkserver_preload([self.function.__module__])
            self.pool = ProcessPoolExecutor(self.workers, mp_context=context,
                                            initializer=start_worker, initargs=(os.getpid(),))
        # Not `map`: on an interruption it cancels the queued futures from this thread while
        # the pool's own thread may be failing them (`__exit__`), which CPython 3.11 reports
        # as an InvalidStateError traceback. Unfinished futures are left to the pool.
        futures = [self.pool.submit(self.function, each) for each in arguments]
        return [future.result() for future in futures]

    def __exit__(self, kind, *exception):
        if self.pool is None:
            return
        if kind is not None:  # interrupted or failed: do not wait for bands nobody needs
            for process in list(getattr(self.pool, "_processes", {}).values()):
                process.kill()
            # The queue's feeder thread may be blocked writing bands to a pipe the killed
            # workers no longer read; joining it at exit would hang the interpreter.
            if (calls := getattr(self.pool, "_call_queue", None)) is not None:
                calls.cancel_join_thread()
            # A worker killed while it sent a band leaves half a message in the result pipe:
            # the pool's thread reading it would wait for the rest forever, and the
            # interpreter for that thread at exit (`basis` hung after SIGTERM), because this
            # process holds the pipe's writing end too. Closing it turns the wait into an EOF.
            if (results := getattr(self.pool, "_result_queue", None)) is not None:
                results._writer.close()
        self.pool.shutdown(wait=kind is None, cancel_futures=True)


# How the resource tracker's leak warning starts (a `-W` filter: regex on the message start).
TRACKER_WARNING = "ignore:resource_tracker:UserWarning"


def quiet_resource_tracker() -> None:
    """Start multiprocessing's resource tracker with its leak warning ignored.

    A fork server's queues hold named semaphores that the tracker (a child process sharing our
    stderr) unlinks if we die without doing it. When the web server is killed by SIGKILL it
    does so and prints "resource_tracker: There appear to be 5 leaked semaphore objects" under
    the dead server's output; the semaphores are cleaned up all the same. The tracker's
    interpreter gets the parent's `-W` options (sys.warnoptions) when it starts, the first time
    a fork server or a spawned process needs it.
    """
    if TRACKER_WARNING not in sys.warnoptions:
        sys.warnoptions.append(TRACKER_WARNING)
    resource_tracker.ensure_running()
