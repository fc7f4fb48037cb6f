"""Running the web app: the address, the demo's files and progress on the terminal
(docs/design.md#server)."""

from __future__ import annotations

import os
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


def run(app, host: str, port: int, announce: str | None = None) -> None:
    """Serve `app` until interrupted; print `announce` (one line) once the socket listens."""
    config = uvicorn.Config(app, host=host, port=port, log_level="warning", access_log=False)
    server = uvicorn.Server(config)
    if announce:
        original = server.startup

        async def startup(sockets=None):
            await original(sockets=sockets)
            if server.started:
                print(announce, flush=True)

        server.startup = startup
    server.run()
    if not server.started:
        raise InputError(f"cannot listen on {host}:{port} (in use, or not allowed)")


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
