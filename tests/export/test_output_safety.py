"""Outputs are never unsafe (issue 21, docs/design.md#errors): a full disk is one line before
or while writing, a killed `render` or `export` leaves no temporary file and no process, and
`Outputs` never writes over an input.

The full disk is a small tmpfs where the test may mount one (root), else a fake that answers
ENOSPC; the kills are SIGTERM and SIGKILL of the real command line.
"""

from __future__ import annotations

import contextlib
import errno
import os
import shutil
import signal
import subprocess
import sys
import time

import numpy as np
import pytest
import soundfile
from export_helpers import SONG

import eigendance.export.files
import eigendance.export.video
from eigendance.cli import main
from eigendance.export.output import Outputs
from eigendance.writes import TEMPORARY_NAME
from helpers import descendants, fixture_path, parents, start

KNIGHT = fixture_path("meshes", "decimated-knight.off")


@contextlib.contextmanager
def small_disk(path, size: str):
    """A tmpfs of `size` at `path` (root only; else the test is skipped for the fake ones)."""
    os.makedirs(path, exist_ok=True)
    mounted = os.geteuid() == 0 and subprocess.run(
        ["mount", "-t", "tmpfs", "-o", f"size={size}", "tmpfs", os.fspath(path)],
        capture_output=True).returncode == 0
    if not mounted:
        pytest.skip("no tmpfs can be mounted here (the ENOSPC fakes below run instead)")
    try:
        yield path
    finally:
        subprocess.run(["umount", "-l", os.fspath(path)], capture_output=True)


def one_error(capfd, argv) -> str:
    try:
        status = main([str(arg) for arg in argv])
    except SystemExit as exit_:
        status = exit_.code
    _, err = capfd.readouterr()
    lines = err.strip().splitlines()
    assert status == 1 and len(lines) == 1 and lines[0].startswith("eigendance: error: "), err
    return lines[0]


@pytest.fixture(scope="module")
def knight_basis(tmp_path_factory):
    path = tmp_path_factory.mktemp("basis") / "knight.npz"
    assert main(["basis", KNIGHT, "-k", "8", "-o", str(path)]) == 0
    return path


@pytest.mark.parametrize("suffix", [".pc2", ".usda", ".usdc", ".glb", ".mp4"])
def test_an_output_larger_than_the_disk_is_refused_before_writing(tmp_path, capfd,
                                                                  knight_basis, suffix):
    # A glb is planned as written (`gltf.glb_size`): the knight's 36 kB and its 58 kB song fit
    # 256k, so its disk is smaller.
    with small_disk(tmp_path / "disk", "64k" if suffix == ".glb" else "256k") as disk:
        command = "render" if suffix == ".mp4" else "export"
        line = one_error(capfd, [command, knight_basis, SONG, "--fps", 240, "--size", "1280x720",
                                 "-o", disk / f"d{suffix}"] if suffix == ".mp4" else
                         [command, knight_basis, SONG, "--fps", 240, "-o", disk / f"d{suffix}"])
        assert "of disk; " in line and "is free there" in line, line
        assert os.listdir(disk) == []


@pytest.mark.parametrize("suffix", [".pc2", ".mp4"])
def test_a_disk_that_fills_while_writing_is_one_line(tmp_path, capfd, knight_basis,
                                                     monkeypatch, suffix):
    """The plan fits (it is faked to 0 bytes), the disk fills: one line, nothing left."""
    monkeypatch.setattr(eigendance.export.files, "planned_bytes", lambda *_: 0.0)
    monkeypatch.setattr(eigendance.export.video, "video_bytes", lambda *_: 0.0)
    with small_disk(tmp_path / "disk", "24k") as disk:
        argv = ["export", knight_basis, SONG, "--fps", 60, "-o", disk / "d.pc2"] \
            if suffix == ".pc2" else \
            ["render", knight_basis, SONG, "--size", "320x240", "--duration", 3,
             "-o", disk / "d.mp4"]
        line = one_error(capfd, argv)
        assert line.endswith("cannot write (No space left on device)"), line
        assert os.listdir(disk) == []


def test_enospc_inside_an_export_is_an_input_error_naming_the_destination(tmp_path):
    """The fake for machines without tmpfs: the write raises ENOSPC."""
    destination = tmp_path / "d.pc2"
    with pytest.raises(eigendance.export.output.InputError,
                       match=r"d\.pc2: cannot write \(No space left on device\)"):
        with Outputs([destination]) as outputs:
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), outputs.temporary(destination))
    assert os.listdir(tmp_path) == []


def test_outputs_never_overwrite_an_input(tmp_path):
    model = tmp_path / "dance.obj"
    model.write_text("v 0 0 0\n")
    with pytest.raises(eigendance.export.output.InputError, match="never overwritten"):
        Outputs([tmp_path / "dance.pc2", model], force=True, inputs=[model])
    assert model.read_text() == "v 0 0 0\n"


# --- kills ---------------------------------------------------------------------------------

def command_name(pid: int) -> str:
    try:
        with open(f"/proc/{pid}/comm") as file:
            return file.read().strip()
    except OSError:
        return ""


@pytest.fixture(scope="module")
def long_song(tmp_path_factory):
    path = tmp_path_factory.mktemp("song") / "long.wav"
    rate = 8000
    # 3 minutes: a quiet host writes a 60-s point cache at 240 fps (88 MB) before a kill lands.
    soundfile.write(path, 0.5 * np.sin(2 * np.pi * 440 * np.arange(180 * rate) / rate), rate)
    return path


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="reads /proc")
@pytest.mark.parametrize("command, kill", [("render", signal.SIGKILL), ("render", signal.SIGTERM),
                                           ("export", signal.SIGKILL)])
def test_a_killed_render_or_export_leaves_no_file_and_no_process(tmp_path, knight_basis,
                                                                 long_song, command, kill):
    out = tmp_path / "out"
    out.mkdir()
    argv = [sys.executable, "-m", "eigendance", command, knight_basis, long_song]
    argv += ["--size", "640x360", "-o", out / "v.mp4"] if command == "render" else \
        ["--fps", 240, "-o", out / "d.pc2"]
    process = start([str(arg) for arg in argv], stdout=subprocess.DEVNULL,
                    stderr=subprocess.PIPE)
    deadline = time.monotonic() + 120
    children: set[int] = set()
    while time.monotonic() < deadline and process.poll() is None:
        children |= descendants(process.pid)
        encoding = command != "render" or any(command_name(pid).startswith("ffmpeg")
                                              for pid in children)
        if encoding and any(TEMPORARY_NAME.fullmatch(name) for name in os.listdir(out)):
            break
        time.sleep(0.02)
    assert process.poll() is None, process.stderr.read().decode()
    if command == "render":
        time.sleep(0.3)  # frames reach the encoder
    children |= descendants(process.pid)
    process.send_signal(kill)
    process.wait(timeout=60)
    deadline = time.monotonic() + 60  # a bound, not a timing: the janitor acts at once
    while time.monotonic() < deadline and (os.listdir(out) or children & set(parents())):
        time.sleep(0.05)
    assert os.listdir(out) == [], "temporary files left"
    assert not children & set(parents()), \
        [command_name(pid) for pid in children & set(parents())]
    shutil.rmtree(out)
