"""Worker threads and worker processes for the app's heavy work, so that the event loop only
routes and streams (docs/design.md#server).

Worker threads (`in_worker`) run every request's work that may block: parsing, galleries,
breeding, bundles. `asyncio.to_thread` would do, but its threads are waited for when the process
ends: a Ctrl-C during a 30-second decoding would take 30 seconds. These are daemon threads: the
process ends at once, and the work in progress with it (its answer was going nowhere).

A thread shares the interpreter's lock (the GIL) with the event loop: pure-Python work (a glTF's
JSON into dataclasses, trimesh's OBJ parser, a rig's joint graph, `bytes.join` of a bundle)
makes every request wait, up to 0.8 s at once. The analysis of an added file therefore runs in
worker processes (`Processes.run`, called from a worker thread, which waits without the lock):
a mesh file read and cleaned, a rig loaded, analysed and bundled, a song decoded. Their results
come back pickled and are unpickled by the pool's own thread (numpy arrays by a copy).
"""

from __future__ import annotations

import asyncio
import multiprocessing
import os
import queue
import threading
from concurrent.futures import Future, ProcessPoolExecutor
from concurrent.futures.process import BrokenProcessPool

from eigendance.errors import InternalError
from eigendance.processes import start_worker

THREADS = max(4, os.cpu_count() or 1)
PROCESSES = 2  # analyses at once; each process holds about 200 MB of imported modules at rest
# Imported once by the fork server, so that a new worker process starts in milliseconds.
PRELOAD = ["eigendance.server.preload"]


class Workers:
    """`threads` daemon threads, started on first use, running submitted calls in turn.

    Parameters
    ----------
    threads : how many threads.
    """

    def __init__(self, threads: int = THREADS):
        self.threads, self.started = threads, 0
        self.calls: queue.SimpleQueue = queue.SimpleQueue()
        self.lock = threading.Lock()

    def submit(self, function, *args) -> Future:
        """Run function(*args) in a worker thread.

        Parameters
        ----------
        function : what to call.
        *args : its arguments.

        Returns
        -------
        concurrent.futures.Future of its result (or exception).
        """
        future: Future = Future()
        self.calls.put((future, function, args))
        with self.lock:
            if self.started < self.threads:
                self.started += 1
                threading.Thread(target=self._work, name=f"worker-{self.started}",
                                 daemon=True).start()
        return future

    def _work(self) -> None:
        while True:
            future, function, args = self.calls.get()
            if not future.set_running_or_notify_cancel():
                continue
            try:
                result = function(*args)
            except BaseException as error:  # noqa: BLE001 - handed to the awaiting request
                future.set_exception(error)
            else:
                future.set_result(result)


WORKERS = Workers()


async def in_worker(function, *args):
    """function(*args) in a worker thread, awaited: the event loop stays free meanwhile.

    Parameters
    ----------
    function : what to call.
    *args : its arguments.

    Returns
    -------
    Its result (its exception is raised here).
    """
    return await asyncio.wrap_future(WORKERS.submit(function, *args))


class Processes:
    """`processes` worker processes, started on first use, that die with the server.

    They come from a fork server (a fresh single-threaded interpreter: the server has threads,
    and forking a process with threads copies locks they may hold), ignore Ctrl-C, and die with
    their parent (`processes.start_worker`). `stop` kills them while they work. One pool serves
    the process (`PROCESSES`): the libraries of one process (tests) share it.

    Parameters
    ----------
    processes : how many processes.
    """

    def __init__(self, processes: int = PROCESSES):
        self.processes, self.pool, self.busy = processes, None, 0
        self.lock = threading.Lock()

    def run(self, function, *args):
        """function(*args) in a worker process; the calling thread waits without the GIL.

        Parameters
        ----------
        function : a module-level function (pickled by name).
        *args : its arguments (pickled).

        Returns
        -------
        Its result (its exception is raised here, of the same type and message).
        InternalError when the process died (killed, out of memory, or `stop`).
        """
        with self.lock:
            if self.pool is None:
                self.pool = ProcessPoolExecutor(self.processes, mp_context=context(),
                                                initializer=start, initargs=(os.getpid(),))
            pool = self.pool
            self.busy += 1
        try:
            return pool.submit(function, *args).result()
        except BrokenProcessPool:
            self._drop(pool)
            raise InternalError("the analysis's worker process died (killed, or out of "
                                "memory)") from None
        finally:
            with self.lock:
                self.busy -= 1

    def stop(self) -> None:
        """Kill the processes if they work, failing the work in progress at once (an idle pool
        stays); safe to call more than once."""
        with self.lock:
            pool = self.pool if self.busy else None
        if pool is not None:
            self._drop(pool)

    def _drop(self, pool: ProcessPoolExecutor) -> None:
        """Kill the processes of `pool` and forget it (the next `run` starts a new one)."""
        with self.lock:
            if self.pool is pool:
                self.pool = None
        for process in list((getattr(pool, "_processes", None) or {}).values()):
            process.kill()
        # The call queue's feeder thread may be blocked writing to a pipe the killed processes
        # no longer read; joining it at exit would hang the interpreter.
        if (calls := getattr(pool, "_call_queue", None)) is not None:
            calls.cancel_join_thread()
        pool.shutdown(wait=False, cancel_futures=True)


PROCESSES_POOL = Processes()


def context():
    """The start method of the server's worker processes: a fork server, which has imported
    PRELOAD (the server has threads: forking it would copy locks they may hold), else spawn.

    Returns
    -------
    multiprocessing context.
    """
    if "forkserver" not in multiprocessing.get_all_start_methods():
        return multiprocessing.get_context("spawn")
    forkserver = multiprocessing.get_context("forkserver")
    forkserver.set_forkserver_preload(PRELOAD)
    return forkserver


def warm() -> None:
    """Start the fork server now (it imports PRELOAD in its own process, in about 2 s), so that the
    first analysis does not wait for it; nothing without a fork server."""
    if context().get_start_method() == "forkserver":
        from multiprocessing import forkserver

        forkserver.ensure_running()


def start(caller: int) -> None:
    """In a new worker process: ignore Ctrl-C, die with the server (`processes.start_worker`),
    and give freed arrays back to the system as the server does (`serve.return_freed_memory`).

    Parameters
    ----------
    caller : the server's process id.
    """
    from eigendance.server.serve import return_freed_memory

    start_worker(caller)
    return_freed_memory()
