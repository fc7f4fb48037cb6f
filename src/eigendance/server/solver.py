"""The library's solve queue: mesh bases computed one at a time by one daemon thread
(docs/design.md#server).

Each mesh item's basis is computed through `HarmonicBasis.from_mesh` (and its disk cache); its
`Job` records the progress for the page (server-sent events) and for `progress_listeners` (the
terminal). `stop` ends the solve in progress at once (its band worker processes are killed, the
next progress report raises `Stopped`) and drops the queued ones; `close` also ends the thread.
"""

from __future__ import annotations

import multiprocessing
import os
import queue
import threading
import time
from collections.abc import Callable

from eigendance.errors import EigendanceError, one_line
from eigendance.harmonic.basis import HarmonicBasis
from eigendance.harmonic.construction import basis_cache, basis_key
from eigendance.harmonic.reduced import reduced_key, sample_count
from eigendance.server.binary import basis_bundle
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
    """

    def __init__(self, solved: Callable[[MeshItem], None], public: Callable[[str], str]):
        self.solved, self.public = solved, public
        self.jobs: dict[str, Job] = {}
        self.progress_listeners: list[Callable[[Job], None]] = []  # e.g. the terminal's bars
        self.stopping = threading.Event()
        self.solving: MeshItem | None = None
        self.solve_children: set = set()  # processes that existed before the current solve
        self.queue: queue.Queue = queue.Queue()
        self.worker = threading.Thread(target=self._run, name="basis", daemon=True)
        self.worker.start()

    def put(self, item: MeshItem, mesh, laplacian: str) -> None:
        """Queue the basis of a mesh item.

        Parameters
        ----------
        item : the mesh item (its job and k).
        mesh : its cleaned `Mesh`.
        laplacian : "cotan" or "robust".
        """
        self.jobs[item.job.id] = item.job
        self.queue.put((item, mesh, laplacian))

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
            item, mesh, laplacian = self.queue.get()
            if item is None:
                return
            self._solve(item, mesh, laplacian)

    def _solve(self, item: MeshItem, mesh, laplacian: str) -> None:
        job = item.job
        if item.removed or self.stopping.is_set():
            job.update(state="error", message=f"{item.name}: removed from the library")
            return
        key = basis_key(mesh, item.k, laplacian)
        if item.construction == "reduced":
            key = reduced_key(key, sample_count(mesh.n, item.k))
        job.cached = os.path.isfile(basis_cache().path(key))
        self.solving, self.solve_children = item, set(multiprocessing.active_children())
        job.update(state="running")
        self.tell(job)

        def progress(done):
            if item.removed or self.stopping.is_set():
                raise Stopped
            job.update(done=int(min(done, job.total)))
            self.tell(job)

        try:
            basis = HarmonicBasis.from_mesh(mesh, item.k, laplacian=laplacian, progress=progress,
                                            construction=item.construction)
            if item.removed or self.stopping.is_set():
                raise Stopped
            item.bundle = basis_bundle(basis, item.name)
            item.basis = basis
            job.update(state="done", done=job.total)
            self.solved(item)
        except Exception as error:  # noqa: BLE001 - reported to the page, never crashes the server
            job.update(state="error", message=self._failure(item, error))
        finally:
            self.solving = None
        self.tell(job)

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
        """Kill the band worker processes of the solve in progress (the processes started
        since it began): the solve fails at once instead of finishing its bands."""
        if self.solving is None:
            return
        for process in set(multiprocessing.active_children()) - self.solve_children:
            process.kill()

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
        self.queue.put((None, None, None))
        self.worker.join(timeout)
