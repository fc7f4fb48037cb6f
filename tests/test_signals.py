"""The processes the tests start get the signal dispositions a terminal's foreground job has,
whatever the test runner inherited: `nohup make test &` and background jobs ignore SIGINT (and
nohup SIGHUP), and a Python started with SIGINT ignored never raises KeyboardInterrupt, so the
Ctrl-C tests would pass or fail by how the suite was started."""

import signal
import subprocess
import sys

from helpers import CHILD_SIGNALS, start

REPORT = ("import signal; print(signal.getsignal(signal.SIGINT) is signal.default_int_handler, "
          "signal.getsignal(signal.SIGHUP) == signal.SIG_DFL, "
          "signal.SIGINT in signal.pthread_sigmask(signal.SIG_BLOCK, []))")


def test_children_get_default_dispositions_even_from_a_runner_that_ignores_ctrl_c():
    previous = {number: signal.signal(number, signal.SIG_IGN) for number in CHILD_SIGNALS}
    blocked = signal.pthread_sigmask(signal.SIG_BLOCK, [signal.SIGINT])
    try:
        plain = subprocess.run([sys.executable, "-c", REPORT], capture_output=True, text=True)
        child = start([sys.executable, "-c", REPORT], stdout=subprocess.PIPE, text=True)
        out, _ = child.communicate(timeout=60)
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, blocked)
        for number, handler in previous.items():
            signal.signal(number, handler)
    assert plain.stdout.split() == ["False", "False", "True"]  # what the runner would pass on
    assert out.split() == ["True", "True", "False"]
