"""Worker processes, one way for all (docs/design.md#worker-processes).

The eigen-solver's bands (`Pool`), the web server's analyses (`server.workers.run`), a batch's
tasks (`batch.engines.LocalEngine`) and a video's render workers (`export.video`) start, die and
are killed here:

- how they start (`context`): a fork of the caller where that is safe, else multiprocessing's
  fork server — one per process, which imports PRELOAD once (the one list: multiprocessing's
  preload is process-wide, and the first fork server to start keeps it), so that a worker starts
  in milliseconds with the eigen-solver and the analysis imported; spawn where neither exists.
- how they die with their caller (`start_worker`): Ctrl-C (SIGINT, which a terminal sends to its
  whole foreground group) is ignored, so the caller alone decides what an interruption stops; on
  Linux the kernel kills the worker when its parent dies (PR_SET_PDEATHSIG), and a worker given
  its caller also has a thread poll the caller and the parent and exit when either is gone.
  Programs we run (ffmpeg) start with `die_with_parent` for the same reason: a killed `render`
  leaves no encoder writing on (docs/design.md#errors).
- how they are killed (`kill`, `kill_pool`): at once (SIGKILL), their process group too where
  they lead one, and a process that has ended meanwhile is no error.
- how the helpers end with the process (at its exit, however it ends: a return, Ctrl-C,
  SIGTERM turned into an exception): the fork server is killed at once and reaped
  (`stop_fork_server`; its workers die with it), then the resource tracker is reaped once it
  has cleaned up after them (`reap_resource_tracker`), so that nothing of ours outlives the
  process (a fork server left to end alone tore its interpreter down for 0.9–3.6 s after the
  server it served had exited).
"""

from __future__ import annotations

import atexit
import contextlib
import ctypes
import multiprocessing
import multiprocessing.forkserver
import os
import signal
import sys
import threading
import time
from concurrent.futures import ProcessPoolExecutor, as_completed
from multiprocessing import resource_tracker, util

POLL_SECONDS = 0.5
PR_SET_PDEATHSIG = 1
# What the fork server imports once, before it forks any worker: what the workers run — the
# eigen-solver (bands, and every other kind of worker solves), the server's analysis and a
# batch's tasks (`batch.work`: export, rigs, songs). The last costs the server's fork server
# 94 MB resident, but 5 MB proportional (shared libraries, mostly), and 0.15 s when it starts;
# without it each batch worker imported it itself (0.15 s, 22 MB of its own). `music.compiled`
# compiles librosa's numba kernels once in the fork server (2–15 s when it starts), so that each
# worker that analyses a song (the server's, a batch's) does not. With both, the server's fork
# server holds 346 MB resident, 180 MB proportional (77 and 46 MB without them:
# benchmarks/bench_server_memory.py).
PRELOAD = ("eigendance.harmonic.eigensolver", "eigendance.server.analysis",
           "eigendance.batch.work", "eigendance.music.compiled")
# How the resource tracker's leak warning starts (a `-W` filter: regex on the message start).
TRACKER_WARNING = "ignore:resource_tracker:UserWarning"
# How long the process's exit waits for the resource tracker to end (`reap_resource_tracker`):
# it ends once the workers sharing it are gone, at once after the fork server's kill.
TRACKER_SECONDS = 2.0
# multiprocessing's exit priority of `reap_resource_tracker`: after every other finalizer (a
# queue's semaphores tell the tracker they are gone, which would start a new one once closed).
LAST = -100
# Resolved here, in the parent: the child of a fork runs only this C call before exec (a
# preexec_fn that imported or took a lock could deadlock in a threaded parent such as the server).
_prctl = ctypes.CDLL(None, use_errno=True).prctl if sys.platform.startswith("linux") else None


def can_fork() -> bool:
    """Whether this platform forks (Linux, macOS; not Windows).

    Returns
    -------
    bool.
    """
    return "fork" in multiprocessing.get_all_start_methods()


def context(how: str = "fresh"):
    """The multiprocessing context workers start from.

    Parameters
    ----------
    how : "fresh": a fork server's, a fresh single-threaded interpreter that has imported PRELOAD
        (like spawn, it imports the caller's main module, which needs the usual `__main__`
        guard); spawn where there is no fork server. "auto": a fork of the caller when it is
        single-threaded (fast, nothing imported again), else "fresh" (a fork copies locks other
        threads may hold). "fork": a fork of the caller whatever its threads, for a worker that
        imports nothing and takes no lock (`can_fork` first).

    Returns
    -------
    multiprocessing context.

    Raises
    ------
    ValueError
        For another `how`, or "fork" where the platform does not fork.
    """
    if how not in ("fresh", "auto", "fork"):
        raise ValueError(f"how: 'fresh', 'auto' or 'fork', not {how!r}")
    if how == "fork" or (how == "auto" and threading.active_count() == 1 and can_fork()):
        return multiprocessing.get_context("fork")
    quiet_resource_tracker()
    if "forkserver" not in multiprocessing.get_all_start_methods():
        return multiprocessing.get_context("spawn")
    forkserver = multiprocessing.get_context("forkserver")
    forkserver.set_forkserver_preload(list(PRELOAD))
    _end_with_process()
    return forkserver


def warm() -> None:
    """Start the fork server now (it imports PRELOAD in its own process, in about 2 s), so that the
    first worker does not wait for it; nothing without a fork server."""
    if context().get_start_method() == "forkserver":
        multiprocessing.forkserver.ensure_running()


_ENDING: list = []  # the processes (pids) whose exit ends their helpers: registered once


def _end_with_process() -> None:
    """Register `stop_fork_server` and `reap_resource_tracker` to run at this process's exit,
    once per process."""
    if os.getpid() in _ENDING:
        return
    _ENDING.append(os.getpid())
    # First at exit (atexit runs the last registered first, before multiprocessing's own exit
    # function joins the children), and the tracker's part after every finalizer.
    atexit.register(stop_fork_server)
    util.Finalize(None, reap_resource_tracker, exitpriority=LAST)


def stop_fork_server() -> None:
    """Kill this process's fork server at once (SIGKILL) and reap it; its workers die with it
    (`start_worker`). Left to end by itself when its caller exits, it tore down its interpreter
    (numpy, scipy, librosa, numba) for 0.9–3.6 s after a stopped server had exited. Nothing where
    there is none or it is not this process's child (a fork of its caller)."""
    server = multiprocessing.forkserver._forkserver
    pid = getattr(server, "_forkserver_pid", None)
    if pid is None:
        return
    try:
        ended = os.waitpid(pid, os.WNOHANG)[0]
    except ChildProcessError:
        return  # not ours: a fork's copy of its caller's state
    if not ended:
        with contextlib.suppress(ProcessLookupError):
            os.kill(pid, signal.SIGKILL)
        with contextlib.suppress(ChildProcessError):
            os.waitpid(pid, 0)
    with contextlib.suppress(OSError, TypeError):
        os.close(server._forkserver_alive_fd)
    # As multiprocessing's own `_stop` leaves it (its socket file goes with its temporary
    # folder): a later worker would start a new fork server.
    server._forkserver_pid = server._forkserver_alive_fd = server._forkserver_address = None


def reap_resource_tracker(seconds: float = TRACKER_SECONDS) -> bool:
    """Let multiprocessing's resource tracker end now, and reap it: it ends when every process
    sharing it has (unlinking what they left), at once after `stop_fork_server`.

    Parameters
    ----------
    seconds : how long to wait for it; a tracker still busy is left to end alone.

    Returns
    -------
    bool, whether none of ours is left (none ran, or it ended).
    """
    tracker = resource_tracker._resource_tracker
    pid, fd = getattr(tracker, "_pid", None), getattr(tracker, "_fd", None)
    if pid is None or fd is None:
        return True
    tracker._fd = tracker._pid = None
    with contextlib.suppress(OSError):
        os.close(fd)  # its end of file: the tracker cleans up and exits
    deadline = time.monotonic() + seconds
    while True:
        try:
            if os.waitpid(pid, os.WNOHANG) != (0, 0):
                return True
        except ChildProcessError:
            return True
        if time.monotonic() > deadline:
            return False
        time.sleep(0.01)


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


def start_worker(caller: int | None = None) -> None:
    """In a new worker process: ignore Ctrl-C and die with the parent; with `caller`, also exit
    when the caller is gone.

    Parameters
    ----------
    caller : None, or the process id of the process the worker works for (a fork server's
        workers are not its children): a thread polls it and the parent, which also guards
        where the kernel does not kill orphans.
    """
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    parent = os.getppid()
    die_with_parent()  # the kernel kills us when our parent dies
    if caller is None:
        return

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


def kill(process, group: bool = False) -> None:
    """Kill a worker process at once (SIGKILL); nothing when it has ended (and perhaps been
    closed) meanwhile.

    Parameters
    ----------
    process : a multiprocessing Process.
    group : kill its process group too (a worker that leads one, with its children: an
        encoder, renderers).
    """
    if group:
        try:
            os.killpg(process.pid, signal.SIGKILL)
            return
        except (ProcessLookupError, PermissionError, TypeError, ValueError):
            pass  # it leads no group (yet), has no pid or is closed: kill it alone
    try:
        process.kill()
    except (ValueError, AttributeError):  # closed, or never started
        pass


def kill_pool(pool: ProcessPoolExecutor, group: bool = False) -> None:
    """Kill a process pool's workers at once and leave no thread of the pool waiting on them;
    `pool.shutdown` follows.

    Parameters
    ----------
    pool : the pool.
    group : kill each worker's process group too (`kill`).
    """
    for process in list((getattr(pool, "_processes", None) or {}).values()):
        kill(process, group)
    # The queue's feeder thread may be blocked writing calls to a pipe the killed workers no
    # longer read; joining it at exit would hang the interpreter.
    if (calls := getattr(pool, "_call_queue", None)) is not None:
        calls.cancel_join_thread()
    # A worker killed while it sent a result leaves half a message in the result pipe: the
    # pool's thread reading it would wait for the rest forever, and the interpreter for that
    # thread at exit (`basis` hung after SIGTERM), because this process holds the pipe's
    # writing end too. Closing it turns the wait into an EOF.
    if (results := getattr(pool, "_result_queue", None)) is not None:
        results._writer.close()


MANAGER_SECONDS = 5.0  # at most this long for a killed pool's own thread to end


class Pool:
    """Calls `function` on each of a list of arguments, in `workers` separate processes when
    there are several (the eigen-solver's bands).

    The workers come from `context("auto")`: forked from a single-threaded caller, from the fork
    server for a multi-threaded one (the web server solves in a thread). They ignore Ctrl-C (the
    caller handles it and stops them) and die with the caller, whatever signal ends it; an
    interrupted or failed call kills them at once (`kill_pool`).

    Parameters
    ----------
    workers : processes.
    function : a module-level callable(argument) (the workers import its module).
    here : what runs instead when a call is made in this process (one argument, or one
        worker); default `function`.

    Example
    -------
    >>> with Pool(1, abs) as run:
    ...     run([-1, 2])
    [1, 2]
    """

    def __init__(self, workers: int, function, here=None):
        self.workers, self.function, self.pool = workers, function, None
        self.here = function if here is None else here

    def __enter__(self):
        return self

    def __call__(self, arguments: list, finished=None) -> list:
        """[function(argument) for each argument], in order.

        Parameters
        ----------
        arguments : the arguments.
        finished : None, or a callable(result) told of each result as soon as it is there
            (in the order they finish: a caller's progress between calls).

        Returns
        -------
        list of the results.
        """
        if len(arguments) == 1 or self.workers == 1:
            results = []
            for each in arguments:
                results.append(self.here(each))
                if finished is not None:
                    finished(results[-1])
            return results
        if self.pool is None:
            self.pool = ProcessPoolExecutor(self.workers, mp_context=context("auto"),
                                            initializer=start_worker, initargs=(os.getpid(),))
        # Not `map`: on an interruption it cancels the queued futures from this thread while
        # the pool's own thread may be failing them (`__exit__`), which CPython 3.11 reports
        # as an InvalidStateError traceback. Unfinished futures are left to the pool.
        futures = [self.pool.submit(self.function, each) for each in arguments]
        if finished is not None:
            for future in as_completed(futures):
                finished(future.result())
        return [future.result() for future in futures]

    def __exit__(self, kind, *exception):
        if self.pool is None:
            return
        if kind is not None:  # interrupted or failed: do not wait for results nobody needs
            kill_pool(self.pool)
        self.pool.shutdown(wait=kind is None, cancel_futures=True)
        # The pool's own thread, seeing its workers gone, closes its wake-up pipe as it ends;
        # if the interpreter's exit hook wakes it in that moment it writes to the closed pipe
        # ("Exception ignored … Bad file descriptor" on a Ctrl-C'd run, 1 in about 30 under
        # load). Its workers are dead and its result pipe at EOF, so it ends at once: wait.
        thread = getattr(self.pool, "_executor_manager_thread", None)
        if kind is not None and thread is not None:
            thread.join(MANAGER_SECONDS)
