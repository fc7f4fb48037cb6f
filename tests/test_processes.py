"""The one module for worker processes: how they start, and a kill that is never an error."""

import multiprocessing
import os
import subprocess
import sys
import threading
import time

import pytest

from eigendance import processes
from helpers import default_signals

pytestmark = pytest.mark.skipif(not sys.platform.startswith("linux"), reason="fork, killpg")


def test_auto_forks_a_single_threaded_caller_and_not_a_threaded_one():
    # A fresh interpreter is single-threaded (this one may hold other tests' threads).
    alone = subprocess.run([sys.executable, "-c", "from eigendance import processes; "
                            "print(processes.context('auto').get_start_method())"],
                           capture_output=True, text=True, check=True)
    assert alone.stdout.strip() == "fork"
    assert processes.context("fork").get_start_method() == "fork"
    assert processes.context("fresh").get_start_method() == "forkserver"
    stop = threading.Event()
    thread = threading.Thread(target=stop.wait)
    thread.start()
    try:  # a second thread: a fork would copy locks it may hold
        assert processes.context("auto").get_start_method() == "forkserver"
    finally:
        stop.set()
        thread.join()
    with pytest.raises(ValueError, match="how"):
        processes.context("spawn")


def test_every_fork_server_preloads_the_one_list():
    """multiprocessing's preload is process-wide: whoever asks, the list is PRELOAD."""
    for how in ("fresh", "auto"):
        context = processes.context(how)
        if context.get_start_method() == "forkserver":
            assert multiprocessing.forkserver._forkserver._preload_modules == \
                list(processes.PRELOAD)


def _sleep_with_a_child():
    os.setpgrp()
    if os.fork() == 0:  # a child in the worker's group (an encoder, say)
        time.sleep(60)
        os._exit(0)
    time.sleep(60)


def test_kill_takes_the_group_and_is_no_error_once_ended():
    context = processes.context("fork")
    process = context.Process(target=_sleep_with_a_child)
    process.start()
    deadline = time.time() + 10
    while os.getpgid(process.pid) != process.pid and time.time() < deadline:
        time.sleep(0.01)
    processes.kill(process, group=True)
    process.join(10)
    assert process.exitcode == -9
    with pytest.raises(ProcessLookupError):  # the child went with it
        deadline = time.time() + 10
        while time.time() < deadline:
            os.killpg(process.pid, 0)
            time.sleep(0.05)
    processes.kill(process)  # ended
    process.close()
    processes.kill(process, group=True)  # closed
    processes.kill(context.Process(target=time.sleep))  # never started


STOP_AND_START_AGAIN = """
import os
import multiprocessing.forkserver as forkserver
from eigendance import processes

def started_and_joined():
    process = processes.context().Process(target=os.getpid)
    process.start()
    process.join()
    return process.exitcode, forkserver._forkserver._forkserver_pid

code, first = started_and_joined()
processes.stop_fork_server()  # killed and reaped: gone, not a zombie
gone = not os.path.exists(f"/proc/{first}")
again, second = started_and_joined()  # a later worker starts a new fork server
print(code, again, gone, first, second)
"""


def test_the_fork_server_ends_with_its_caller_and_a_stopped_one_starts_again():
    """stop_fork_server kills and reaps it, a later worker starts a new one, and the caller's
    exit ends the new one and the resource tracker before the caller has exited."""
    ran = subprocess.run([sys.executable, "-c", STOP_AND_START_AGAIN], capture_output=True,
                         text=True, timeout=120, preexec_fn=default_signals)
    code, again, gone, first, second = ran.stdout.split()
    assert (code, again, gone) == ("0", "0", "True"), ran.stderr
    assert first != second
    assert not os.path.exists(f"/proc/{second}")  # it was the caller's child: reaped


def test_a_pool_tells_each_result_as_it_is_there_and_returns_them_in_order():
    """`Pool(…)(arguments, finished)`: finished hears every result once (in two processes, in the
    order they end; in one, in order), and the call still returns them in the arguments'
    order."""
    for workers in (1, 2):
        heard = []
        with processes.Pool(workers, abs) as run:
            assert run([-3, 1, -2], finished=heard.append) == [3, 1, 2]
        assert sorted(heard) == [1, 2, 3]
