"""The eigendance command in a subprocess, for the add-on (no bpy here): where the command is,
a running job whose progress and error are read as it runs, and no job left behind when
Blender closes.

The command prints its progress bars (tqdm) only to a terminal: on Linux and macOS the job's
stderr is a pseudo-terminal, so that the add-on can show them in the status bar; elsewhere it
shows the elapsed time.
"""

import atexit
import os
import re
import shlex
import shutil
import signal
import subprocess
import threading
import time

try:  # a pseudo-terminal for the progress bars: POSIX only
    import fcntl
    import pty
    import struct
    import termios
except ImportError:  # Windows
    pty = None

INSTALL = ("install it with `pip install eigendance` (Python 3.11 or later) and set its path "
           "in the add-on's preferences (Edit > Preferences > Add-ons > eigendance)")
PROGRESS = re.compile(r"([A-Za-z][\w ]*):\s*(?:(\d+)%\|[^|]*\|\s*(\d+)/(\d+)|(\d+)\s*\w*\s*\[)")
ANSI = re.compile(r"\x1b\[[0-9;?]*[A-Za-z]")
RUNNING = set()  # every job started and not yet ended: killed when Blender closes


class CommandMissing(Exception):
    """The eigendance command cannot be found or run (its message is one line)."""


def command_words(setting: str) -> list[str]:
    """The command line that runs eigendance, from the add-on's preference.

    Parameters
    ----------
    setting : "eigendance" (looked up on PATH), a path to it, or a command with arguments
        ("/path/python -m eigendance").

    Returns
    -------
    list of str, the program first (an absolute path).
    """
    words = shlex.split(setting.strip(), posix=os.name != "nt") if setting.strip() else []
    if not words:
        raise CommandMissing(f"no eigendance command is set; {INSTALL}")
    program = os.path.expanduser(words[0])
    found = program if os.path.isfile(program) and os.access(program, os.X_OK) else \
        shutil.which(program)
    if not found:
        raise CommandMissing(f"the eigendance command {words[0]!r} was not found; {INSTALL}")
    return [found, *words[1:]]


def progress_of(text: str):
    """The last progress bar in a job's output: (label, fraction or None, count text).

    Parameters
    ----------
    text : the output's last characters (a tqdm bar redraws itself after "\\r").

    Returns
    -------
    (str, float or None, str), or None when the text shows no bar.
    """
    found = None
    for part in re.split(r"[\r\n]", ANSI.sub("", text)):
        match = PROGRESS.search(part)
        if match:
            label, percent, done, total, count = match.groups()
            if percent is not None:
                found = (label.strip(), int(done) / max(1, int(total)), f"{done}/{total}")
            else:
                found = (label.strip(), None, count)
    return found


class Job:
    """One run of the eigendance command: started at once, read in a thread, killed on demand
    or when Blender closes.

    Parameters
    ----------
    words : the command line (`command_words` + the sub-command and its arguments).
    """

    def __init__(self, words: list[str]):
        self.words, self.began, self.output = words, time.monotonic(), ""
        self.lock = threading.Lock()
        master = slave = None
        if pty is not None:
            master, slave = pty.openpty()
            # 160 columns: a terminal of 0 columns gets empty bars.
            fcntl.ioctl(slave, termios.TIOCSWINSZ, struct.pack("HHHH", 24, 160, 0, 0))
        try:
            # Its own process group: a kill reaches the workers it starts too.
            self.process = subprocess.Popen(
                words, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                stderr=slave if slave is not None else subprocess.STDOUT,
                start_new_session=os.name == "posix")
        except OSError as error:
            for fd in (master, slave):
                if fd is not None:
                    os.close(fd)
            raise CommandMissing(f"cannot run {words[0]!r} ({error.strerror}); "
                                 f"{INSTALL}") from None
        RUNNING.add(self)
        readers = [self.process.stdout.fileno()]
        if slave is not None:
            os.close(slave)  # the child holds it; the master ends when the child does
            readers.append(master)
        self.threads = [threading.Thread(target=self._read, args=(fd,), daemon=True)
                        for fd in readers]
        for thread in self.threads:
            thread.start()

    def _read(self, fd: int) -> None:
        while True:
            try:
                chunk = os.read(fd, 65536)
            except OSError:  # the pseudo-terminal's end (EIO) once the child is gone
                chunk = b""
            if not chunk:
                break
            with self.lock:
                self.output = (self.output + chunk.decode("utf-8", "replace"))[-20000:]
        if fd != self.process.stdout.fileno():
            os.close(fd)

    def poll(self):
        """The job's exit status, or None while it runs.

        Returns
        -------
        int or None.
        """
        status = self.process.poll()
        if status is not None:
            for thread in self.threads:
                thread.join(timeout=2)
            RUNNING.discard(self)
        return status

    def wait(self) -> int:
        """Wait for the job to end.

        Returns
        -------
        int, its exit status.
        """
        self.process.wait()
        return self.poll()

    def status(self) -> tuple[str, float | None]:
        """What the status bar shows: the current step and its fraction done (or None).

        Returns
        -------
        (str, float or None).
        """
        with self.lock:
            found = progress_of(self.output[-2000:])
        seconds = f"{time.monotonic() - self.began:.0f} s"
        if found is None:
            return f"eigendance: working… {seconds} (Esc cancels)", None
        label, fraction, count = found
        return f"eigendance: {label} {count} · {seconds} (Esc cancels)", fraction

    def error(self) -> str:
        """The one line that says why the job failed.

        Returns
        -------
        str.
        """
        with self.lock:
            lines = [line.strip() for line in re.split(r"[\r\n]", ANSI.sub("", self.output))
                     if line.strip()]
        for line in reversed(lines):
            if line.startswith("eigendance: "):
                return line
        status = self.process.returncode
        return lines[-1] if lines else f"eigendance ended with exit status {status}"

    def kill(self) -> None:
        """End the job and every process it started (SIGTERM, then SIGKILL after 5 s): the
        command removes its outputs."""
        if self.process.poll() is None:
            self._signal(signal.SIGTERM)
            try:
                self.process.wait(timeout=5)
            except subprocess.TimeoutExpired:
                self._signal(signal.SIGKILL if os.name == "posix" else signal.SIGTERM)
                self.process.wait()
        if os.name == "posix":  # workers left in the group once the command ended
            try:
                os.killpg(self.process.pid, signal.SIGKILL)
            except OSError:
                pass
        self.poll()

    def _signal(self, number) -> None:
        try:
            if os.name == "posix":
                os.killpg(self.process.pid, number)
            else:
                self.process.terminate()
        except OSError:
            pass


def kill_all() -> None:
    """End every job still running (the add-on's unregister, Blender's exit)."""
    for job in list(RUNNING):
        job.kill()


atexit.register(kill_all)
