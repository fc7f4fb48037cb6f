"""Running the web app: the address, the demo's files and progress on the terminal
(docs/design.md#server)."""

from __future__ import annotations

import errno
import os
import socket
import sys
import time
from importlib import resources

import uvicorn
from tqdm import tqdm

from eigendance.errors import InputError
from eigendance.harmonic.cache import cache_folder
from eigendance.music.demo_music import write_demo_wav

DEFAULT_HOST = "127.0.0.1"
DEFAULT_PORT = 8765
DEMO_K = 150


def run(app, listening: socket.socket, announce=None) -> None:
    """Serve `app` on a socket from `listen` until interrupted; print `announce` (one line)
    once it serves. announce: the line, or a callable(port) that makes it."""
    host, bound = listening.getsockname()[:2]
    config = uvicorn.Config(app, host=host, port=bound, log_level="warning", access_log=False)
    server = uvicorn.Server(config)
    if announce:
        original = server.startup

        async def startup(sockets=None):
            await original(sockets=sockets)
            if server.started:
                print(announce(bound) if callable(announce) else announce, flush=True)

        server.startup = startup
    with listening:
        server.run(sockets=[listening])
    if not server.started:
        raise InputError(f"cannot serve on {host}:{bound}: the app did not start")


def listen(host: str, port: int) -> socket.socket:
    """A TCP socket bound to host:port (port 0: any free one); InputError naming the problem.

    Bound before anything else starts (uvicorn would log its own lines and exit, after the
    library had started solving), so an address in use, unknown or not allowed is one line.
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


def terminal_progress(library) -> None:
    """Show basis jobs on stderr: a tqdm bar on a terminal, and one line when each finishes."""
    bars = {}

    def listener(job):
        bar = bars.get(job.id)
        if bar is None:
            if job.state == "running" and not job.cached:
                print(f"eigendance: computing the basis of {job.name} (k = {job.total}; "
                      "cached for the next run)…", file=sys.stderr)
            bar = bars[job.id] = tqdm(total=job.total, desc="basis eigenpairs", unit="pair",
                                      file=sys.stderr, disable=not sys.stderr.isatty(),
                                      leave=False)
        bar.update(max(0, job.done - bar.n))
        if job.state in ("done", "error") and not getattr(bar, "reported", False):
            bar.reported = True
            bar.close()
            name = job.message if job.state == "error" else job.name
            seconds = time.time() - job.started
            if job.state == "error":
                print(f"eigendance: basis failed: {name}", file=sys.stderr)
            else:
                how = "from the cache" if job.cached else f"{seconds:.1f} s"
                print(f"eigendance: basis of {name} ready (k = {job.total}, {how})",
                      file=sys.stderr)

    library.progress_listeners.append(listener)


def demo_paths() -> list[str]:
    """The built-in mesh and the procedural track (written once as WAV into the cache folder)."""
    mesh = os.fspath(resources.files("eigendance") / "data" / "cat_lowres.obj")
    song = os.path.join(cache_folder(), "demo-music", "eigendance-demo-music.wav")
    os.makedirs(os.path.dirname(song), exist_ok=True)
    if not os.path.exists(song):
        write_demo_wav(song)
    return [mesh, song]
