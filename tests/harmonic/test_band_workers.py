"""The eigensolver's band workers: started from any thread, gone with the process that asked.

The workers come from a fork server, so the caller may be multi-threaded (the web server solves
in a thread); they die when the caller is killed by any signal, and Ctrl-C stops a solve at
once instead of waiting for the bands in flight.
"""

import os
import signal
import socket
import subprocess
import sys
import threading
import time

import numpy as np
import pytest
import trimesh

from eigendance.harmonic.eigensolver import solve_bands
from eigendance.harmonic.laplacian import laplacian
from helpers import alive, descendants, sphere, start

pytestmark = pytest.mark.skipif(not sys.platform.startswith("linux"), reason="reads /proc")


@pytest.fixture(scope="module")
def ball(tmp_path_factory):
    path = tmp_path_factory.mktemp("ball") / "ball.obj"
    trimesh.creation.icosphere(5).export(path)  # 10242 vertices: a solve of many bands
    return str(path)


def start_solve(ball, tmp_path, command=("basis", "-o", "out.npz"), count=2):
    """Start a solve and wait for `count` descendants: a command forks its two band workers;
    the server (multi-threaded) has a fork server start them, hence 3."""
    env = dict(os.environ, EIGENDANCE_CACHE_DIR=str(tmp_path / "cache"))
    process = start([sys.executable, "-m", "eigendance.cli", command[0], ball, "-k",
                                "900", *command[1:]], env=env, cwd=tmp_path,
                    stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                    start_new_session=True)
    deadline = time.time() + 60
    while len(workers := descendants(process.pid)) < count:
        assert process.poll() is None and time.time() < deadline, "no band workers started"
        time.sleep(0.1)
    return process, workers


@pytest.mark.parametrize("sent", [signal.SIGKILL, signal.SIGTERM])
def test_workers_die_with_a_killed_caller(ball, tmp_path, sent):
    process, workers = start_solve(ball, tmp_path)
    os.kill(process.pid, sent)
    process.wait(10)
    deadline = time.time() + 5
    while alive(workers) and time.time() < deadline:
        time.sleep(0.1)
    assert not alive(workers)
    assert not (tmp_path / "out.npz").exists()


def test_workers_of_the_web_server_die_with_it(ball, tmp_path):
    """The server solves in a thread: its workers come from a fork server, and go with it.
    multiprocessing's resource tracker then unlinks the fork server's semaphores without
    printing a leak warning under the dead server's output."""
    process, workers = start_solve(ball, tmp_path, ("serve", "--port", str(free_port())),
                                     count=3)
    os.kill(process.pid, signal.SIGKILL)
    process.wait(10)
    deadline = time.time() + 5
    while alive(workers) and time.time() < deadline:
        time.sleep(0.1)
    assert not alive(workers)
    # Read to the end: the tracker and the fork server share the server's stderr until they go.
    _, errors = process.communicate(timeout=60)
    assert "resource_tracker" not in errors and "leaked" not in errors


def free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


def test_ctrl_c_stops_a_solve_at_once(ball, tmp_path):
    process, workers = start_solve(ball, tmp_path)
    os.killpg(process.pid, signal.SIGINT)  # what a terminal sends to its foreground group
    _, errors = process.communicate(timeout=60)  # not a timing test: a hang fails, load does not
    assert process.returncode == 130 and "interrupted" in errors and "Traceback" not in errors
    deadline = time.time() + 10
    while alive(workers) and time.time() < deadline:
        time.sleep(0.1)
    assert not alive(workers)


def test_bands_solved_from_a_thread_equal_bands_solved_from_the_main_thread():
    mesh = sphere(4)
    stiffness, mass = laplacian(mesh.vertices, mesh.faces)
    results = {}

    def run():
        results["thread"] = solve_bands(stiffness, mass, 200, per_band=40)

    worker = threading.Thread(target=run)
    worker.start()
    worker.join(120)
    main_values, _ = solve_bands(stiffness, mass, 200, per_band=40)
    np.testing.assert_allclose(results["thread"][0], main_values, rtol=1e-9, atol=1e-9)


# A caller interrupted while its workers stream large bands back (SIGALRM raises Ctrl-C's
# KeyboardInterrupt after `delay` s): the killed workers often leave half a band in the
# result pipe. Before the fix the pool's reader thread waited for the rest forever and the
# interpreter for that thread at exit (half of these runs hung; `basis` hung after SIGTERM).
INTERRUPTED_STREAM = """
import signal, sys
import numpy as np
from eigendance.processes import Pool

BAND = np.ones(8_000_000)  # 64 MB: the workers spend their time sending results


def band(arguments):
    return BAND


def interrupt(*_):
    raise KeyboardInterrupt


signal.signal(signal.SIGALRM, interrupt)
signal.setitimer(signal.ITIMER_REAL, float(sys.argv[1]))
try:
    with Pool(2, band) as run:
        while True:
            run([None] * 4)
except KeyboardInterrupt:
    print("interrupted", flush=True)
"""


@pytest.mark.parametrize("delay", [0.5, 0.6, 0.7, 0.8])
def test_a_caller_interrupted_mid_band_exits(delay):
    process = start([sys.executable, "-c", INTERRUPTED_STREAM, str(delay)],
                    stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        output, errors = process.communicate(timeout=60)  # a hang fails, load does not
    except subprocess.TimeoutExpired:
        process.kill()
        process.communicate()
        pytest.fail("the interrupted caller did not exit")
    assert output == "interrupted\n" and errors == "" and process.returncode == 0
