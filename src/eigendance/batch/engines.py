"""Where a batch's tasks run: local worker processes, or Ray (docs/design.md#batch).

Both engines take `Task`s (a function of `batch.work`, its arguments, some of them `Shared`
values earlier tasks prepared) and give back each task's report and, for a task whose value is
kept, a handle later tasks take as an argument. A task runs on one core; the driver keeps at
most `slots` tasks submitted.

- `LocalEngine`: one single-process `ProcessPoolExecutor` per slot, its worker started by the
  fork server (a fresh, single-threaded interpreter, `processes.context`), in a process group
  of its own, ignoring Ctrl-C and dying with the driver (`processes.start_worker`). A
  prepared value is written by the worker that made it into the run's `shared.Store` and
  memory-mapped by the workers that use it. A worker that dies (killed, out of memory) breaks
  only its own executor: the task is run again on a fresh one, at most MAX_RETRIES times.
- `RayEngine`: Ray tasks (one CPU each, retried by Ray when their worker dies, MAX_RETRIES
  times; never on an exception: a task returns its error), values kept in Ray's object store,
  which workers read without copying. `--ray` starts a local Ray; an address joins a cluster.
"""

from __future__ import annotations

import concurrent.futures
import logging
import os
from concurrent.futures.process import BrokenProcessPool
from dataclasses import dataclass, field

from eigendance import processes
from eigendance.batch import shared, work
from eigendance.errors import InputError

MAX_RETRIES = 3  # runs of a task whose worker died, after the first (Ray's default)


@dataclass
class Task:
    """A task for an engine.

    Parameters
    ----------
    name : what to call it (Ray's dashboard lists tasks by it).
    function : a function's name in `batch.work`.
    arguments : its arguments; prepared values (`Shared`, Ray's object references) only at the
        top level.
    keep : its value is kept for later tasks (a prepared input).
    attempts : runs so far (None on Ray, which runs a task again by itself).
    extra : the driver's bookkeeping.
    """

    name: str
    function: str
    arguments: tuple
    keep: bool = False
    attempts: int = 0
    extra: dict = field(default_factory=dict)  # the driver's bookkeeping


@dataclass(frozen=True)
class Shared:
    """A value a local task prepared.

    Parameters
    ----------
    path : the store's file that workers map (`shared.load`).
    """

    path: str


def died(task: Task) -> dict:
    """The report of a task whose worker kept dying.

    Parameters
    ----------
    task : the task.

    Returns
    -------
    dict, a task report with its error.
    """
    return {"error": f"its worker died {task.attempts} times (killed, or out of memory)",
            "kind": "crash", "seconds": None, "memory": None}


# --- local processes ------------------------------------------------------------------------

def _local_worker(caller: int) -> None:
    """Start a local worker: die with the caller, own process group, one thread per kind."""
    processes.start_worker(caller)
    os.setpgrp()  # the driver stops the worker and its children (encoder, renderers) together
    work.setup_worker()


def _local_task(function: str, arguments: tuple, keep: str | None, cache: str | None):
    """Run a task in a local worker; a kept value is saved to the store file `keep`."""
    arguments = tuple(shared.load(value.path) if isinstance(value, Shared) else value
                      for value in arguments)
    report, value = work.task(getattr(work, function), *arguments, cache=cache)
    if keep is None or report["error"] is not None:
        return report, None
    return report, Shared(shared.save(value, keep))


class LocalEngine:
    """Local worker processes (module docstring).

    Parameters
    ----------
    workers : processes, one task each at a time.
    cache : the content cache's folder for the tasks.
    """

    kind = "local"

    def __init__(self, workers: int, cache: str | None):
        self.slots, self.cache = workers, cache
        self.store = shared.Store()
        self.context = processes.context()
        self.executors: list[concurrent.futures.ProcessPoolExecutor | None] = [None] * workers
        self.running: dict[concurrent.futures.Future, tuple[int, Task]] = {}
        self._names = 0

    def describe(self) -> str:
        """The engine in words.

        Returns
        -------
        str, e.g. "2 local worker processes".
        """
        return f"{self.slots} local worker process{'es' if self.slots > 1 else ''}"

    def submit(self, task: Task) -> None:
        """Run `task` on a free worker (the driver submits at most `slots` at once).

        Parameters
        ----------
        task : the task.
        """
        busy = {slot for slot, _ in self.running.values()}
        slot = next(slot for slot in range(self.slots) if slot not in busy)
        if self.executors[slot] is None:
            self.executors[slot] = concurrent.futures.ProcessPoolExecutor(
                1, mp_context=self.context, initializer=_local_worker,
                initargs=(os.getpid(),))
        keep = None
        if task.keep:
            self._names += 1
            keep = self.store.path(str(self._names))
        future = self.executors[slot].submit(_local_task, task.function, task.arguments, keep,
                                             self.cache)
        task.attempts += 1
        self.running[future] = (slot, task)

    def finished(self, timeout: float | None = None) -> list[tuple[Task, dict, object]]:
        """Wait for tasks to end: [(task, report, handle)], a task whose worker died run again
        (not listed) until MAX_RETRIES.

        Parameters
        ----------
        timeout : s to wait at most (None: until one ends).

        Returns
        -------
        list, possibly empty after `timeout`.
        """
        done, _ = concurrent.futures.wait(list(self.running), timeout,
                                          concurrent.futures.FIRST_COMPLETED)
        results = []
        for future in done:
            slot, task = self.running.pop(future)
            try:
                report, value = future.result()
            except BrokenProcessPool:
                self._replace(slot)
                if task.attempts <= MAX_RETRIES:
                    self.submit(task)
                    continue
                report, value = died(task), None
            results.append((task, report, value))
        return results

    def _replace(self, slot: int) -> None:
        executor, self.executors[slot] = self.executors[slot], None
        if executor is not None:
            executor.shutdown(wait=False, cancel_futures=True)

    def release(self, handle) -> None:
        """Forget a prepared value no task needs any more (workers keep their mapping).

        Parameters
        ----------
        handle : a `Shared` value.
        """
        if isinstance(handle, Shared):
            try:
                os.unlink(handle.path)
            except OSError:
                pass

    def close(self, interrupted: bool = False) -> None:
        """Stop the workers (at once, with their children, when interrupted) and remove the
        store.

        Parameters
        ----------
        interrupted : kill the workers instead of letting them finish.
        """
        for executor in self.executors:
            if executor is None:
                continue
            if interrupted:  # each worker with its children, no thread left waiting on them
                processes.kill_pool(executor, group=True)
            executor.shutdown(wait=True, cancel_futures=True)
        self.executors = [None] * self.slots
        self.running.clear()
        self.store.close()


# --- Ray --------------------------------------------------------------------------------------

def _ray_task(function: str, *arguments, cache: str | None = None):
    """Run a task in a Ray worker (Ray resolves the object references among the arguments)."""
    work.setup_worker()
    return work.task(getattr(work, function), *arguments, cache=cache)


class RayEngine:
    """Ray tasks (module docstring).

    Parameters
    ----------
    address : "local" (start a local Ray with `workers` CPUs), "auto" or a cluster's address
        (join it); a Ray already started in this process is used as it is.
    workers : CPUs of a local Ray (None: all).
    cache : the content cache's folder for the tasks (on a cluster: shared storage).
    """

    kind = "ray"

    def __init__(self, address: str, workers: int | None, cache: str | None):
        try:
            import ray  # an optional extra, 400 MB: only when asked for
        except ImportError:
            raise InputError("Ray is not installed; pip install 'eigendance[ray]'") from None
        self.ray, self.cache, self.started = ray, cache, False
        if not ray.is_initialized():
            options = {"log_to_driver": False, "include_dashboard": True,
                       "logging_level": logging.WARNING}  # the dashboard is said by the batch
            try:
                if address == "local":
                    context = ray.init(num_cpus=workers, **options)
                else:
                    context = ray.init(address=address, **options)
            except (ConnectionError, RuntimeError, ValueError) as error:
                raise InputError(f"Ray at {address}: cannot start or join it ({error})") \
                    from None
            self.started = True
            self.dashboard = context.dashboard_url or ""
        else:
            self.dashboard = ray._private.worker.get_dashboard_url() or ""
        cpus = int(ray.cluster_resources().get("CPU", 1))
        self.cpus = cpus
        self.slots = 2 * cpus  # a task queued on each CPU: no wait between two tasks
        self.remote = ray.remote(num_cpus=1, max_retries=MAX_RETRIES,
                                 retry_exceptions=False)(_ray_task)
        self.running: dict = {}

    def describe(self) -> str:
        """The engine in words, with the dashboard's address.

        Returns
        -------
        str, e.g. "Ray, 8 CPUs, dashboard http://127.0.0.1:8265".
        """
        where = f", dashboard http://{self.dashboard}" if self.dashboard else ""
        return f"Ray, {self.cpus} CPUs{where}"

    def submit(self, task: Task) -> None:
        """Submit `task` to Ray.

        Parameters
        ----------
        task : the task.
        """
        report, value = self.remote.options(num_returns=2, name=task.name[:100]).remote(
            task.function, *task.arguments, cache=self.cache)
        self.running[report] = (task, value)

    def finished(self, timeout: float | None = None) -> list[tuple[Task, dict, object]]:
        """Wait for tasks to end: [(task, report, handle)] (the handle an object reference).

        Parameters
        ----------
        timeout : s to wait at most (None: until one ends).

        Returns
        -------
        list, possibly empty after `timeout`.
        """
        ready, _ = self.ray.wait(list(self.running), num_returns=1, timeout=timeout)
        if ready:  # whatever else has ended too
            ready, _ = self.ray.wait(list(self.running), num_returns=len(self.running),
                                     timeout=0)
        results = []
        for reference in ready:
            task, value = self.running.pop(reference)
            task.attempts = None  # Ray runs a task again by itself when its worker dies
            try:
                report = self.ray.get(reference)
            except self.ray.exceptions.RayError:  # its worker died MAX_RETRIES + 1 times
                task.attempts = MAX_RETRIES + 1
                report, value = died(task), None
            results.append((task, report, value if task.keep and not report["error"] else None))
        return results

    def release(self, handle) -> None:
        """Forget a prepared value (Ray frees it when no task holds it).

        Parameters
        ----------
        handle : an object reference.
        """
        del handle

    def close(self, interrupted: bool = False) -> None:
        """Cancel what runs (when interrupted) and stop the local Ray this engine started.

        Parameters
        ----------
        interrupted : cancel the running tasks, killing their workers.
        """
        if interrupted:
            for reference in self.running:
                try:
                    self.ray.cancel(reference, force=True)
                except Exception:  # noqa: BLE001, S110 - already ended or lost: nothing to stop
                    pass
        self.running.clear()
        if self.started:
            self.ray.shutdown()
