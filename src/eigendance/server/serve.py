"""Running the web app: the address, the library's temporary folder, the end of the process,
the demo's files and progress on the terminal (docs/design.md#server).

The library lives in a folder of the system's temporary folder, removed when the server ends:
normally, by Ctrl-C, SIGTERM or SIGHUP. A server killed outright (SIGKILL) cannot remove it;
the next server removes such folders (those whose lock nobody holds any more). The first
Ctrl-C or SIGTERM stops the solve in progress at once (`Library.stop`) and ends the server
within a second, open connections (server-sent events) included; its fork server and resource
tracker end before it does (`processes.stop_fork_server`, at its exit). Exit status 130, 143 or
129: 128 + the signal, the shell's convention.
"""

from __future__ import annotations

import asyncio
import atexit
import contextlib
import ctypes
import errno
import os
import resource
import shutil
import signal
import socket
import sys
import threading
import time
from collections.abc import Iterator
from importlib import resources

import uvicorn
from tqdm import tqdm

from eigendance.errors import InputError, one_line
from eigendance.harmonic.cache import cache_folder
from eigendance.music.demo_music import write_demo_wav
from eigendance.server.connections import MAX_CONNECTIONS, Connection
from eigendance.server.guard import DEFAULT_HOST
from eigendance.server.library import Library
from eigendance.server.workers import warm
from eigendance.writes import LOCK_NAME, locked_folder, sweep_locked_folders, swept_locked_folder

DEFAULT_PORT = 8765
FOLDER_PREFIX = "eigendance-library-"
DEMO_PREFIX = "eigendance-demo-"  # the demo's music where the cache cannot hold it
GRACE_SECONDS = 1.0  # how long open connections may take to finish once the server stops
# glibc's mallopt parameters (malloc.h) and our values (`return_freed_memory`).
M_MMAP_THRESHOLD, M_ARENA_MAX = -3, -8
MMAP_THRESHOLD, MALLOC_ARENAS = 1 << 20, 2
KEEP_ALIVE_SECONDS = 5.0  # an idle connection is closed this long after its last answer
# File descriptors the server asks for (its soft limit raised up to the hard one): the open
# connections (`server.connections`) and the files, pipes and processes of its work.
OPEN_FILES = 4 * MAX_CONNECTIONS + 1024
# (With uvicorn's backlog at MAX_CONNECTIONS, asyncio accepts at most that many connections
# before `Connection` sees them: 2 × MAX_CONNECTIONS descriptors at most, under Linux's
# customary 1024.)

__all__ = ["DEFAULT_HOST", "DEFAULT_PORT", "LOCK_NAME", "demo_paths", "library_session",
           "listen", "run", "terminal_progress"]


class _Server(uvicorn.Server):
    """uvicorn's server, calling `on_exit` (in a thread) at the first Ctrl-C or SIGTERM."""

    def __init__(self, config, on_exit=None):
        super().__init__(config)
        self.on_exit = on_exit

    def handle_exit(self, sig, frame):
        if self.on_exit is not None and not self.should_exit:
            # A signal handler must not wait for locks the interrupted code may hold.
            threading.Thread(target=self.on_exit, name="stop", daemon=True).start()
        super().handle_exit(sig, frame)


def run(app, listening: socket.socket, announce=None, on_exit=None) -> None:
    """Serve `app` on a socket from `listen` until interrupted.

    Parameters
    ----------
    app : the ASGI app (`create_app`).
    listening : the bound socket.
    announce : the line to print once it serves, or a callable(port) that makes it.
    on_exit : called at the first Ctrl-C or SIGTERM (e.g. `Library.stop`).
    """
    host, bound = listening.getsockname()[:2]
    raise_open_files(OPEN_FILES)
    return_freed_memory()
    server = _Server(server_config(app, host, bound), on_exit)
    original = server.startup

    async def startup(sockets=None):
        asyncio.get_running_loop().set_exception_handler(_one_line_handler())
        await original(sockets=sockets)
        if server.started and announce:
            print(announce(bound) if callable(announce) else announce, flush=True)

    server.startup = startup
    hung_up = []
    with listening, _handling({signal.SIGHUP: lambda number, frame: hung_up.append(number) or
                               server.handle_exit(number, frame)}):
        server.run(sockets=[listening])
    if hung_up:  # uvicorn ends gracefully at SIGINT and SIGTERM only; SIGHUP the same way
        raise SystemExit(128 + signal.SIGHUP)
    if not server.started:
        raise InputError(f"cannot serve on {host}:{bound}: the app did not start")


def server_config(app, host: str, port: int) -> uvicorn.Config:
    """uvicorn's settings for the app: our connections (`server.connections`: header and body
    timeouts, a bound on open connections, refusals in JSON), the keep-alive time, the
    backlog, no access log.

    Parameters
    ----------
    app : the ASGI app.
    host : the address it listens on.
    port : the port.

    Returns
    -------
    uvicorn.Config.
    """
    return uvicorn.Config(app, host=host, port=port, log_level="warning", access_log=False,
                          proxy_headers=False, timeout_graceful_shutdown=GRACE_SECONDS,
                          http=Connection, timeout_keep_alive=KEEP_ALIVE_SECONDS,
                          backlog=MAX_CONNECTIONS)  # also the most accepted at one go


def raise_open_files(wanted: int) -> int:
    """Raise the soft limit of open files towards `wanted` (never past the hard limit).

    Parameters
    ----------
    wanted : file descriptors.

    Returns
    -------
    int, the soft limit now.
    """
    soft, hard = resource.getrlimit(resource.RLIMIT_NOFILE)
    target = wanted if hard == resource.RLIM_INFINITY else min(wanted, hard)
    if soft != resource.RLIM_INFINITY and soft < target:
        with contextlib.suppress(ValueError, OSError):
            resource.setrlimit(resource.RLIMIT_NOFILE, (target, hard))
            soft = target
    return soft


def return_freed_memory() -> bool:
    """Make glibc give freed arrays back to the system (docs/design.md#server).

    By default glibc raises its mmap threshold up to 32 MB after a large block is freed, so
    arrays up to that size then come from heaps that stay as large as their peak, one heap per
    thread (up to 8 per core). The server's worker threads each build and free hundreds of MB (a
    rig analysis, a basis bundle): its RSS grew to 2.5 times the library's budget. A fixed
    threshold of MMAP_THRESHOLD and MALLOC_ARENAS heaps keep it near what the library holds.

    Returns
    -------
    bool: whether glibc took the settings (False on other C libraries).
    """
    try:
        libc = ctypes.CDLL("libc.so.6")
        return bool(libc.mallopt(M_MMAP_THRESHOLD, MMAP_THRESHOLD)
                    and libc.mallopt(M_ARENA_MAX, MALLOC_ARENAS))
    except (OSError, AttributeError):
        return False


def _one_line_handler():
    """An event-loop exception handler writing one line on stderr, at most once a second per
    message (asyncio's default writes a traceback each time: when the process runs out of file
    descriptors, one per attempt to accept a connection)."""
    said: dict[str, float] = {}

    def handler(loop, context):
        message = str(context.get("message", "event loop error"))
        if time.monotonic() - said.get(message, -1e9) < 1.0:
            return
        said[message] = time.monotonic()
        error = context.get("exception")
        detail = f" ({type(error).__name__}: {one_line(error, 200)})" if error else ""
        print(f"eigendance: {one_line(message, 200)}{detail}", file=sys.stderr, flush=True)

    return handler


def listen(host: str, port: int) -> socket.socket:
    """A TCP socket bound to host:port, listening.

    Bound before anything else starts (uvicorn would log its own lines and exit, after the
    library had started solving), so an address in use, unknown or not allowed is one line.

    Parameters
    ----------
    host : the address.
    port : the port (0: any free one).

    Returns
    -------
    socket.socket; InputError naming the problem (remedy port 0 for a port in use).
    """
    try:
        family, kind, protocol, _, address = socket.getaddrinfo(
            host or None, port, type=socket.SOCK_STREAM, flags=socket.AI_PASSIVE)[0]
    except (socket.gaierror, UnicodeError) as error:
        raise InputError(f"cannot listen on {host}: unknown address "
                         f"({getattr(error, 'strerror', None) or error})") from None
    listening = socket.socket(family, kind, protocol)
    try:
        listening.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)  # as uvicorn does
        listening.bind(address)
        listening.listen(socket.SOMAXCONN)
    except OSError as error:
        listening.close()
        remedy = {"port": 0} if error.errno == errno.EADDRINUSE else None
        raise InputError(f"cannot listen on {host}:{port}: {error.strerror or error}",
                         remedy=remedy) from None
    listening.set_inheritable(True)
    return listening


@contextlib.contextmanager
def library_session(**options) -> Iterator[Library]:
    """A `Library` in a new temporary folder, for as long as the block runs; then its work is
    stopped and the folder removed, however the block ends (SIGTERM and SIGHUP end it as an
    exception, `SystemExit(128 + signal)`).

    Parameters
    ----------
    **options : those of `Library`.

    Yields
    ------
    Library.
    """
    with swept_locked_folder(FOLDER_PREFIX) as folder, \
            _handling({signal.SIGTERM: _leave, signal.SIGHUP: _leave}):
        library = Library(folder, **options)
        warm()  # the worker processes' fork server loads while the server starts
        try:
            yield library
        finally:
            library.close()


def sweep_library_folders(parent: str | None = None) -> int:
    """Remove the library folders that killed servers left (`writes.sweep_locked_folders`: not
    while their lock is held, nor without a lock file, nor younger than FRESH_SECONDS).

    Parameters
    ----------
    parent : where to look (default: the system's temporary folder).

    Returns
    -------
    int, how many were removed.
    """
    return sweep_locked_folders(FOLDER_PREFIX, parent)


@contextlib.contextmanager
def _handling(handlers: dict):
    """{signal: handler} while the block runs (in the main thread; elsewhere nothing)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = {number: signal.signal(number, handler) for number, handler in handlers.items()}
    try:
        yield
    finally:
        for number, handler in previous.items():
            signal.signal(number, handler)


def _leave(number, frame):
    """SIGTERM and SIGHUP end the process as SystemExit(128 + signal), which runs every
    `finally` on the way (their default action would end it without removing anything)."""
    raise SystemExit(128 + number)


def terminal_progress(library) -> None:
    """Show basis jobs on stderr: a tqdm bar on a terminal, and one line when each finishes.

    Parameters
    ----------
    library : the library whose jobs to show.
    """
    bars = {}

    def listener(job):
        bar = bars.get(job.id)
        name = one_line(job.name, 120)  # an upload's name may hold terminal escapes
        if bar is None:
            if job.state == "running" and not job.cached:
                print(f"eigendance: computing the basis of {name} (k = {job.total}; "
                      "cached for the next run)…", file=sys.stderr)
            bar = bars[job.id] = tqdm(total=job.total, desc="basis eigenpairs", unit="pair",
                                      file=sys.stderr, disable=not sys.stderr.isatty(),
                                      leave=False)
        bar.update(max(0, job.done - bar.n))
        if job.state in ("done", "error") and not getattr(bar, "reported", False):
            bar.reported = True
            bar.close()
            if library.stopping.is_set():
                return  # the server is ending: "interrupted" says it
            name = one_line(job.message) if job.state == "error" else name
            seconds = time.time() - job.started
            if job.state == "error":
                print(f"eigendance: basis failed: {name}", file=sys.stderr)
            else:
                how = "from the cache" if job.cached else f"{seconds:.1f} s"
                print(f"eigendance: basis of {name} ready (k = {job.total}, {how})",
                      file=sys.stderr)

    library.progress_listeners.append(listener)


def demo_paths() -> list[str]:
    """The built-in mesh and the procedural track (written once as WAV into the cache folder;
    where it cannot be written, into a `writes.locked_folder` for this run, removed at its end
    or, after a kill, by the next run's `writes.sweep_locked_folders`).

    Returns
    -------
    [mesh path, song path].
    """
    mesh = os.fspath(resources.files("eigendance") / "data" / "cat_lowres.obj")
    song = os.path.join(cache_folder(), "demo-music", "eigendance-demo-music.wav")
    sweep_locked_folders(DEMO_PREFIX)  # those of killed runs
    if os.path.isfile(song):
        return [mesh, song]
    try:
        os.makedirs(os.path.dirname(song), exist_ok=True)
        write_demo_wav(song)
    except (OSError, InputError) as error:  # a cache folder that is a file, read-only, full
        reason = one_line(error) if isinstance(error, InputError) else \
            f"{os.path.dirname(song)}: cannot write ({error.strerror or one_line(error)})"
        folder, lock = locked_folder(DEMO_PREFIX)
        atexit.register(os.close, lock)  # atexit runs last first: the folder goes, then its lock
        atexit.register(shutil.rmtree, folder, True)
        print(f"eigendance: warning: {reason}; the demo's music is made for this run only "
              "(the cache folder cannot be written)", file=sys.stderr)
        song = os.path.join(folder, "eigendance-demo-music.wav")
        write_demo_wav(song)
    return [mesh, song]
