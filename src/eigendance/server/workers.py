"""Worker threads and worker processes for the app's heavy work, so that the event loop only
routes and streams (docs/design.md#server).

Worker threads (`in_worker`) run every request's work that may block: parsing, galleries,
breeding, bundles. `asyncio.to_thread` would do, but its threads are waited for when the process
ends: a Ctrl-C during a 30-second decoding would take 30 seconds. These are daemon threads: the
process ends at once, and the work in progress with it (its answer was going nowhere).

A thread shares the interpreter's lock (the GIL) with the event loop: pure-Python work (a glTF's
JSON into dataclasses, trimesh's OBJ parser, a rig's joint graph, `bytes.join` of a bundle)
makes every request wait, up to 0.8 s at once. The analysis of an added file therefore runs in
a worker process of its own (`run`, called from a worker thread, which waits without the lock):
a mesh file read and cleaned, a file's kind found, a rig loaded, analysed and bundled, a song
decoded (librosa's kernels compiled once, in the fork server: `music.compiled`), a basis
solved. Their results come back through `server.transfer`, without a copy under the lock.
"""

from __future__ import annotations

import asyncio
import os
import queue
import socket
import threading
from concurrent.futures import Future

from eigendance import processes
from eigendance.errors import InternalError, one_line
from eigendance.server import transfer

THREADS = max(4, os.cpu_count() or 1)
# A worker process yields the processors to the server's event loop (and its band workers too,
# which inherit it): on 2 busy cores, the loop otherwise waited up to 0.14 s for a time slice.
NICE = 10


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


RUNNING: set = set()  # the worker processes at work (`run`), killed by `stop`
RUNNING_LOCK = threading.Lock()


def run(function, *args, progress=None, started=None):
    """function(*args) in a new worker process; the calling thread waits without the GIL.

    The process comes from the fork server (`processes.context`), ignores Ctrl-C and dies with
    the server (`work`); it ends with the call. Its result comes back through `server.transfer`.

    Parameters
    ----------
    function : a module-level function (pickled by name).
    *args : its arguments (pickled).
    progress : None, or a callable given each value the function reports through its own
        `progress` keyword (it may raise to stop the work: the process is killed).
    started : None, or a callable given the process once it runs (to kill it).

    Returns
    -------
    Its result (its exception is raised here, of the same type and message).
    InternalError when the process died (killed, out of memory, or `stop`).
    """
    mine, theirs = socket.socketpair()
    process = context().Process(target=work, name=f"eigendance {function.__name__}",
                                args=(theirs, function, args, progress is not None))
    try:
        process.start()
        theirs.close()
        with RUNNING_LOCK:
            RUNNING.add(process)
        if started is not None:
            started(process)
        while True:
            try:
                kind, value = transfer.receive(mine)
            except (EOFError, OSError):
                raise InternalError("the analysis's worker process died (killed, or out of "
                                    "memory)") from None
            if kind == "progress":
                progress(value)
            elif kind == "error":
                raise value
            else:
                return value
    finally:
        theirs.close()
        mine.close()
        with RUNNING_LOCK:
            RUNNING.discard(process)
        if process.pid is not None:
            processes.kill(process)
            process.join()
            process.close()


def stop() -> None:
    """Kill the worker processes at work: their calls fail at once (InternalError)."""
    with RUNNING_LOCK:
        running = list(RUNNING)
    for process in running:
        kill(process)


def kill(process) -> None:
    """Kill a worker process of `run`, if it has not ended and been closed meanwhile
    (`processes.kill`).

    Parameters
    ----------
    process : a multiprocessing Process.
    """
    processes.kill(process)


def work(connection: socket.socket, function, args: tuple, progress: bool) -> None:
    """The worker process of `run`: call function(*args), send its result or its exception.

    Ctrl-C is the server's; the kernel kills this process when its parent (the fork server,
    which ends with the server) dies (`processes.start_worker`); it runs at a lower priority
    (NICE) than the server. No thread watches the server, as `processes.start_worker` does:
    single-threaded, this process forks its own workers (the eigen-solver's bands), whose
    queues hold no named semaphores that a killed process would leave to the resource tracker.

    Parameters
    ----------
    connection : the socket to the server.
    function, args : the call.
    progress : whether to give the function a `progress` keyword that sends what it reports.
    """
    processes.start_worker()
    os.nice(NICE)
    try:
        keywords = {"progress": lambda done: transfer.send(connection, ("progress", done))} \
            if progress else {}
        message = ("result", function(*args, **keywords))
    except Exception as error:  # noqa: BLE001 - handed to the server, which reports it
        message = ("error", error)
    try:
        transfer.send(connection, message)
    except Exception as error:  # noqa: BLE001 - a result that cannot be pickled
        transfer.send(connection, ("error", InternalError(
            f"{function.__name__}: {type(error).__name__}: {one_line(error)}")))
    connection.close()


def warm() -> None:
    """Start the fork server now (`processes.warm`), so that the first analysis does not wait
    for it."""
    processes.warm()


def context():
    """The start method of the server's worker processes (`processes.context`: the fork server,
    the server has threads).

    Returns
    -------
    multiprocessing context.
    """
    return processes.context()
