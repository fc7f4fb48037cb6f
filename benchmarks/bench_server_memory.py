"""Resident memory of `eigendance serve` (docs/design.md#server): the server process, its fork
server, its resource tracker and its workers, idle once started (the fork server's preload
done) and after the built-in cat is added (its basis solved; the peak sampled every 50 ms while
it is read and solved, then the settled figure). Resident (RSS) and proportional (PSS, shared
pages divided among the processes that share them: their sum is what the tree costs the
machine) per process, from /proc (Linux).

Run with the fork server's preload as it is (`processes.PRELOAD`) and as it was when
design.md's figure was measured (the eigen-solver and the server's analysis only, before
`batch.work` and `music.compiled`), in turn on the same machine; the old figure printed beside.
Not run by CI.

    python benchmarks/bench_server_memory.py [--preload now|before|both] [-k 24]
"""

from __future__ import annotations

import argparse
import json
import os
import socket
import sys
import tempfile
import threading
import time
import urllib.request

from browser_server import library_of, served

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                                "tests"))
from eigendance.processes import PRELOAD
from eigendance.server.serve import demo_paths
from helpers import descendants  # noqa: E402 - the tests' /proc walk

# design.md's figure before this benchmark: four rig uploads and six stiffness edits under
# --max-memory-mb 1024, the peak sampled every 50 ms, the preload then the first two modules.
OLD = {"server": 0.28, "tree": 0.56}
BEFORE = ("-c", "import sys; import eigendance.processes as p; p.PRELOAD = p.PRELOAD[:2]; "
          "from eigendance.cli.main import main; sys.exit(main(sys.argv[1:]))")
NOW = ("-m", "eigendance.cli")


def tree(pid: int) -> list[int]:
    """The process and its live descendants."""
    return [pid, *sorted(descendants(pid))]


def role(pid: int, server: int) -> str:
    try:
        with open(f"/proc/{pid}/cmdline", "rb") as file:
            line = file.read().decode(errors="replace")
    except OSError:
        return "gone"
    if pid == server:
        return "server"
    if "multiprocessing.resource_tracker import" in line:
        return "resource tracker"
    if "multiprocessing.forkserver import" in line and _parent(pid) == server:
        return "fork server"
    return "worker"  # the fork server's children (same command line), their band workers


def _parent(pid: int) -> int:
    with open(f"/proc/{pid}/stat") as file:
        return int(file.read().rsplit(")", 1)[1].split()[1])


def memory(pid: int) -> tuple[float, float]:
    """(RSS, PSS) in MB of one process; (0, 0) once it is gone."""
    values = {}
    try:
        with open(f"/proc/{pid}/smaps_rollup") as file:
            for line in file:
                name, _, rest = line.partition(":")
                if name in ("Rss", "Pss"):
                    values[name] = int(rest.split()[0]) / 1024
    except OSError:
        return 0.0, 0.0
    return values.get("Rss", 0.0), values.get("Pss", 0.0)


def snapshot(server: int) -> dict[str, tuple[float, float, int]]:
    """{role: (RSS MB, PSS MB, processes)} of the server's tree, and "tree" for the sum."""
    found: dict[str, list[float]] = {}
    for pid in tree(server):
        rss, pss = memory(pid)
        entry = found.setdefault(role(pid, server), [0.0, 0.0, 0])
        entry[0] += rss
        entry[1] += pss
        entry[2] += 1
    found["tree"] = [sum(v[i] for v in found.values()) for i in range(3)]
    return {key: tuple(value) for key, value in found.items()}


def settled(server: int, seconds: float = 120.0) -> dict:
    """The tree's snapshot once its RSS has changed by less than 2 MB over 3 s (the fork
    server's preload done), or after `seconds`."""
    deadline, history = time.monotonic() + seconds, []
    while True:
        shot = snapshot(server)
        history.append(shot["tree"][0])
        if len(history) >= 7 and max(history[-7:]) - min(history[-7:]) < 2:
            return shot
        if time.monotonic() > deadline:
            return shot
        time.sleep(0.5)


def add_and_peak(url: str, server: int, path: str) -> tuple[float, float, float]:
    """Upload `path`, sample the tree every 50 ms until its basis is ready: (peak server RSS,
    peak tree RSS, peak tree PSS) in MB."""
    with open(path, "rb") as file:
        request = urllib.request.Request(f"{url}api/upload?name={os.path.basename(path)}",
                                         file.read(), {"Content-Type": "application/octet-stream"})
    peak_server = peak_tree = peak_pss = 0.0
    answer: list = []

    def upload():
        with urllib.request.urlopen(request, timeout=600) as response:
            answer.append(json.load(response))

    thread = threading.Thread(target=upload)
    thread.start()
    last_poll = 0.0
    while True:
        shot = snapshot(server)
        peak_server = max(peak_server, shot.get("server", (0, 0, 0))[0])
        peak_tree = max(peak_tree, shot["tree"][0])
        peak_pss = max(peak_pss, shot["tree"][1])
        if not thread.is_alive() and time.monotonic() - last_poll > 0.5:
            last_poll = time.monotonic()
            meshes = library_of(url)["meshes"]
            if meshes and all(mesh["ready"] for mesh in meshes):
                break
        time.sleep(0.05)
    thread.join()
    return peak_server, peak_tree, peak_pss


def free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


def measure(launcher: tuple, k: int) -> dict:
    """The idle and cat figures of one server."""
    cat = demo_paths()[0]
    with tempfile.TemporaryDirectory() as cache, \
            served([], free_port(), ("-k", str(k)), launcher,
                   env=dict(os.environ, EIGENDANCE_CACHE_DIR=cache)) as (url, process, _):
        idle = settled(process.pid)
        peaks = add_and_peak(url, process.pid, cat)
        after = settled(process.pid)
    return {"idle": idle, "peak": peaks, "cat": after}


def show(label: str, result: dict) -> None:
    print(f"\n{label}")
    for phase in ("idle", "cat"):
        shot = result[phase]
        parts = ", ".join(f"{name} {rss:.0f} MB RSS / {pss:.0f} PSS ({int(n)})"
                          for name, (rss, pss, n) in sorted(shot.items()) if name != "tree")
        rss, pss, n = shot["tree"]
        print(f"  {phase:4s}: all {int(n)} processes {rss / 1024:.2f} GB RSS, {pss / 1024:.2f} GB "
              f"PSS — {parts}")
    server, whole, proportional = result["peak"]
    print(f"  peak while the cat was read and solved: server {server / 1024:.2f} GB, all "
          f"{whole / 1024:.2f} GB RSS, {proportional / 1024:.2f} GB PSS (sampled every 50 ms)")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--preload", choices=["now", "before", "both"], default="both")
    parser.add_argument("-k", type=int, default=24)
    options = parser.parse_args()
    print(f"load: {os.getloadavg()[0]:.1f} (1 min), {os.cpu_count()} cores")
    print(f"design.md's figure (four rigs, six edits, --max-memory-mb 1024, preload of the "
          f"time): server {OLD['server']:.2f} GB, with its fork server and workers "
          f"{OLD['tree']:.2f} GB RSS at the peak")
    runs = {"now": ("preload now: " + ", ".join(PRELOAD), NOW),
            "before": ("preload before: " + ", ".join(PRELOAD[:2]), BEFORE)}
    for name in (["before", "now"] if options.preload == "both" else [options.preload]):
        label, launcher = runs[name]
        show(label, measure(launcher, options.k))


if __name__ == "__main__":
    main()
