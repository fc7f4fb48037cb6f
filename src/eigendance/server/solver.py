"""The library's solve queue: mesh bases computed one at a time, each in a process of its own,
by one daemon thread (docs/design.md#server).

Each mesh item's basis is computed by its mesh's `HarmonicProblem` (and its disk cache) with its
bundle, in a worker process that loads the problem its reading worker saved
(`analysis.solve_basis`: the Laplacian's assembly and the eigen-solver hold the interpreter's
lock for seconds); the saved problem is removed once its solve ends, or is dropped. The basis
comes back without the mesh's look, which the item has (`MeshItem.appearance`, given to the
basis here: held once). The thread relays its
progress to the item's `Job`, for the page (server-sent events) and for `progress_listeners`
(the terminal). `stop` ends the solve in progress at once (its process is killed, and its band
workers with it) and drops the queued ones; `close` also ends the thread.
"""

from __future__ import annotations

import os
import queue
import threading
import time
from collections.abc import Callable

from eigendance.errors import EigendanceError, InternalError, one_line
from eigendance.harmonic.construction import is_cached
from eigendance.server import analysis, workers
from eigendance.server.items import Job, MeshItem


class Stopped(Exception):
    """Raised in a solve's progress callback to end it: the mesh was removed or the server is
    stopping."""


class BasisSolver:
    """One thread computing the bases of the queued mesh items, in turn.

    Parameters
    ----------
    solved : called with a mesh item once its basis and bundle are set (to charge them).
    public : a message → the message as the page may see it (`Library.public`).
    discard : removes a saved problem once its solve ends (`Shelf.discard`).
    """

    def __init__(self, solved: Callable[[MeshItem], None], public: Callable[[str], str],
                 discard: Callable[[str], None] = os.unlink):
        self.solved, self.public, self.discard = solved, public, discard
        self.jobs: dict[str, Job] = {}
        self.progress_listeners: list[Callable[[Job], None]] = []  # e.g. the terminal's bars
        self.stopping = threading.Event()
        self.solving: MeshItem | None = None
        self.process = None  # the solve's process, while it runs
        self.queue: queue.Queue = queue.Queue()
        self.worker = threading.Thread(target=self._run, name="basis", daemon=True)
        self.worker.start()

    def put(self, item: MeshItem, mesh: analysis.ReadMesh) -> None:
        """Queue the basis of a mesh item.

        Parameters
        ----------
        item : the mesh item (its job and k).
        mesh : its mesh as read: its saved problem (construction for the item's k decided)
            and cache key.
        """
        self.jobs[item.job.id] = item.job
        self.queue.put((item, mesh))

    def forget(self, item: MeshItem) -> None:
        """A mesh item is removed: stop its solve, fail its queued job, forget the job.

        Parameters
        ----------
        item : the mesh item, already marked `removed`.
        """
        if self.solving is item:
            self.stop_solve()
        self.jobs.pop(item.job.id, None)
        if item.job.state == "queued":
            item.job.update(state="error", message=f"{item.name}: removed from the library")

    def _run(self) -> None:
        while True:
            item, mesh = self.queue.get()
            if item is None:
                return
            self._solve(item, mesh)

    def _solve(self, item: MeshItem, mesh: analysis.ReadMesh) -> None:
        job = item.job
        if item.removed or self.stopping.is_set():
            self.discard(mesh.parsed)
            job.update(state="error", message=f"{item.name}: removed from the library")
            return
        job.cached = is_cached(mesh.key)
        self.solving = item
        job.update(state="running")
        self.tell(job)

        def progress(done):
            if item.removed or self.stopping.is_set():
                raise Stopped
            job.update(done=int(min(done, job.total)))
            self.tell(job)

        try:
            try:
                basis, bundle = self._compute(item, mesh.parsed, progress)
            finally:  # before the job ends: whoever waits for it sees no solve, no file
                self.solving = None
                self.discard(mesh.parsed)
            if item.removed or self.stopping.is_set():
                raise Stopped
            basis.appearance = item.appearance
            item.basis, item.bundle = basis, bundle
            job.update(state="done", done=job.total)
            self.solved(item)
        except Exception as error:  # noqa: BLE001 - reported to the page, never crashes the server
            job.update(state="error", message=self._failure(item, error))
        self.tell(job)

    def _compute(self, item: MeshItem, parsed: str, progress):
        """(basis, bundle) of a mesh item, computed in a worker process (`analysis.solve_basis`)
        while this thread relays its progress; the process is killed when `progress` raises
        (`Stopped`) or the solve is stopped (`stop_solve`)."""
        if self.stopping.is_set() or item.removed:
            raise Stopped
        try:
            return workers.run(analysis.solve_basis, parsed, item.k, progress=progress,
                               started=lambda process: setattr(self, "process", process))
        except InternalError:
            if item.removed or self.stopping.is_set():
                raise Stopped from None
            raise
        finally:
            self.process = None

    def _failure(self, item: MeshItem, error: Exception) -> str:
        if item.removed or self.stopping.is_set():
            return f"{item.name}: removed from the library" if item.removed else \
                f"{item.name}: the server stopped before the basis was done"
        if isinstance(error, EigendanceError):
            return self.public(str(error))
        return self.public(f"{item.name}: the basis failed (internal error: "
                           f"{type(error).__name__}: {one_line(error, 200)})")

    def tell(self, job: Job) -> None:
        """Give the job's new state to every progress listener.

        Parameters
        ----------
        job : the job that changed.
        """
        for listener in self.progress_listeners:
            listener(job)

    def stop_solve(self) -> None:
        """Kill the process of the solve in progress (its band workers die with it): the solve
        fails at once."""
        process = self.process
        if process is not None:
            workers.kill(process)

    def wait(self, timeout: float | None = None) -> bool:
        """Block until every job has finished (tests, the command line).

        Parameters
        ----------
        timeout : seconds at most (None: no limit).

        Returns
        -------
        bool: True when every job finished in time.
        """
        deadline = None if timeout is None else time.time() + timeout
        for job in list(self.jobs.values()):
            with job.changed:
                while job.busy:
                    left = None if deadline is None else deadline - time.time()
                    if left is not None and left <= 0:
                        return False
                    job.changed.wait(left)
        return True

    def stop(self) -> None:
        """End the work in progress at once: the solve (its workers are killed) and the queued
        ones. Safe to call from any thread, more than once."""
        self.stopping.set()
        self.stop_solve()

    def close(self, timeout: float = 2.0) -> None:
        """`stop`, then give the thread `timeout` seconds to end (it is a daemon thread: a solve
        step that cannot be interrupted does not keep the process alive).

        Parameters
        ----------
        timeout : seconds.
        """
        self.stop()
        self.queue.put((None, None))
        self.worker.join(timeout)
