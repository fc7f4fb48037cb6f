"""Small meshes made by code, paths of the test fixtures, the processes a test starts (with the
signal dispositions it needs) and the processes a process started (Linux /proc)."""

import os
import signal
import subprocess
import time

import pytest
import trimesh

from eigendance.harmonic.mesh import Mesh

FIXTURES = os.path.join(os.path.dirname(__file__), "fixtures")


def sphere(subdivisions=3) -> Mesh:
    """Unit icosphere (642 vertices at 3 subdivisions, 2562 at 4)."""
    icosphere = trimesh.creation.icosphere(subdivisions)
    return Mesh.from_arrays(icosphere.vertices, icosphere.faces, name="sphere")


def required(what: str, present: bool, how: str) -> None:
    """Skip without `what`, but fail under CI (CI set in the environment), which must run
    every check: a test never passes for want of its tool there."""
    if not present:
        message = f"{what} is not installed ({how})"
        if os.environ.get("CI"):
            pytest.fail(message)
        pytest.skip(message)


def fixture_path(*parts):
    return os.path.join(FIXTURES, *parts)


def bumpy_sphere(subdivisions=2) -> Mesh:
    """An icosphere with a smooth bump pattern and a stretch: energy in many harmonics."""
    import numpy as np

    icosphere = trimesh.creation.icosphere(subdivisions)
    vertices = icosphere.vertices * [1.3, 1.0, 0.8]
    x, y, z = icosphere.vertices.T
    vertices = vertices * (1 + 0.15 * np.sin(3 * x) * np.cos(2 * y) + 0.1 * z ** 2)[:, None]
    return Mesh.from_arrays(vertices, icosphere.faces, name="bumpy sphere")


CHILD_SIGNALS = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)


def default_signals() -> None:
    """In a child about to run a command: Ctrl-C, SIGTERM and SIGHUP at their default
    dispositions and unblocked, as a terminal's foreground job has them, whatever the test
    runner inherited (`nohup make test &` and background jobs ignore SIGINT and SIGHUP, and
    Python then never turns SIGINT into KeyboardInterrupt)."""
    for number in CHILD_SIGNALS:
        signal.signal(number, signal.SIG_DFL)
    signal.pthread_sigmask(signal.SIG_UNBLOCK, CHILD_SIGNALS)


def start(command, **options) -> subprocess.Popen:
    """subprocess.Popen(command, **options) with `default_signals` in the child: every process a
    test signals is started so, never relying on what the tests inherited."""
    return subprocess.Popen(command, preexec_fn=default_signals, **options)


def parents() -> dict[int, int]:
    """pid → parent pid of every live (non-zombie) process."""
    table = {}
    for name in os.listdir("/proc"):
        if name.isdigit():
            try:
                with open(f"/proc/{name}/stat") as file:
                    fields = file.read().rsplit(")", 1)[1].split()
            except OSError:
                continue
            if fields[0] != "Z":
                table[int(name)] = int(fields[1])
    return table


def descendants(pid: int) -> set[int]:
    table, found, frontier = parents(), set(), {pid}
    while frontier:
        frontier = {child for child, parent in table.items() if parent in frontier} - found
        found |= frontier
    return found


def alive(pids: set[int]) -> set[int]:
    return pids & set(parents())


def wait_for(condition, seconds=5.0) -> bool:
    """Poll condition() every 2 ms until it holds (True) or `seconds` pass (False)."""
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        if condition():
            return True
        time.sleep(0.002)
    return False


def folded_over(rest, faces, moved):
    """Which faces are folded over (their normal against the rest normal) in each frame
    (F, n, 3) → (F, m) bool, and each face's area weight (m,): an independent reading of what a
    gallery's fold cap promises, from positions alone."""
    import numpy as np

    def normals(x):
        return np.cross(x[..., faces[:, 1], :] - x[..., faces[:, 0], :],
                        x[..., faces[:, 2], :] - x[..., faces[:, 0], :])
    at_rest = normals(rest)
    return (np.einsum("fij,ij->fi", normals(moved), at_rest) < 0,
            np.linalg.norm(at_rest, axis=-1))
