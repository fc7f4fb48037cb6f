"""Files (docs/design.md#files): atomic writes that leave nothing behind, even when the writer is
killed (its temporary file is swept by the next write into that folder), checked reads."""

import fcntl
import os
import signal
import subprocess
import sys
import time

import numpy as np
import pytest
import trimesh

from eigendance.errors import InputError
from eigendance.files import checked_array, read_json
from eigendance.harmonic.basis import HarmonicBasis
from eigendance.harmonic.mesh import Mesh
from eigendance.music.spectrogram import Spectrogram
from eigendance.writes import TEMPORARY_PREFIX, atomic_save_npz, atomic_write, sweep_temporary_files
from helpers import start

# A writer that stops half-way: it writes a megabyte, says so, and waits to be killed.
STALLED_WRITER = """
import sys, time
from eigendance.writes import atomic_write
def write(file):
    file.write(b"x" * (1 << 20)); file.flush()
    print("writing", flush=True)
    time.sleep(600)
atomic_write(sys.argv[1], write)
"""


def temporary_files(folder):
    return sorted(name for name in os.listdir(folder) if name.startswith(TEMPORARY_PREFIX))


def size(path) -> int:
    try:
        return os.path.getsize(path)
    except OSError:  # renamed or removed meanwhile
        return 0


def stalled_writer(path):
    process = start([sys.executable, "-c", STALLED_WRITER, str(path)],
                    stdout=subprocess.PIPE, text=True)
    assert process.stdout.readline().strip() == "writing"
    return process


def test_a_killed_writer_leaves_no_output_and_the_next_write_sweeps_its_debris(tmp_path):
    process = stalled_writer(tmp_path / "out.bin")
    os.kill(process.pid, signal.SIGKILL)
    process.wait(10)
    assert not (tmp_path / "out.bin").exists() and len(temporary_files(tmp_path)) == 1
    atomic_write(tmp_path / "other.bin", lambda file: file.write(b"done"))
    assert temporary_files(tmp_path) == [] and (tmp_path / "other.bin").read_bytes() == b"done"


def test_a_live_writers_file_is_kept(tmp_path):
    process = stalled_writer(tmp_path / "out.bin")
    try:
        atomic_write(tmp_path / "other.bin", lambda file: file.write(b"done"))
        assert len(temporary_files(tmp_path)) == 1  # still being written: not ours to remove
    finally:
        os.kill(process.pid, signal.SIGKILL)
        process.wait(10)
    assert sweep_temporary_files(tmp_path) == 1 and temporary_files(tmp_path) == []


def test_the_sweep_keeps_other_files_and_a_fresh_empty_temporary_file(tmp_path):
    keep = ["mine.part", ".tmp-other.part", f"{TEMPORARY_PREFIX}x.txt", "data.npz"]
    for name in keep:
        (tmp_path / name).write_text("someone's")
    (tmp_path / f"{TEMPORARY_PREFIX}empty.part").write_bytes(b"")  # a writer about to lock it
    (tmp_path / f"{TEMPORARY_PREFIX}left.part").write_bytes(b"half")
    os.mkdir(tmp_path / f"{TEMPORARY_PREFIX}folder.part")
    assert sweep_temporary_files(tmp_path) == 1
    assert sorted(os.listdir(tmp_path)) == sorted(
        keep + [f"{TEMPORARY_PREFIX}empty.part", f"{TEMPORARY_PREFIX}folder.part"])
    old = time.time() - 3600
    os.utime(tmp_path / f"{TEMPORARY_PREFIX}empty.part", (old, old))
    assert sweep_temporary_files(tmp_path) == 1


def test_the_lock_is_held_until_the_rename(tmp_path):
    seen = []

    def write(file):
        file.write(b"data")
        file.flush()
        [name] = temporary_files(tmp_path)
        with open(tmp_path / name, "rb") as other:
            try:
                fcntl.flock(other, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except OSError:
                seen.append("locked")

    atomic_write(tmp_path / "out.bin", write)
    assert seen == ["locked"] and (tmp_path / "out.bin").read_bytes() == b"data"


def test_a_failed_write_leaves_nothing(tmp_path):
    def write(file):
        file.write(b"half")
        raise RuntimeError("stopped")

    with pytest.raises(RuntimeError):
        atomic_write(tmp_path / "out.bin", write)
    assert os.listdir(tmp_path) == []


def test_non_finite_arrays_are_not_written(tmp_path):
    with pytest.raises(InputError, match="not written: b holds NaN or infinite values"):
        atomic_save_npz(tmp_path / "x.npz", a=np.ones(3), b=np.array([1.0, np.inf]))
    assert os.listdir(tmp_path) == []
    atomic_save_npz(tmp_path / "x.npz", a=np.arange(3), names=np.array(["a", "b"]))


@pytest.mark.parametrize("array, kind, shape, message", [
    (np.array(["a"]), "float", (None,), "must hold real numbers, not <U1"),
    (np.ones(3, complex), "float", (None,), "must hold real numbers"),
    (np.ones((2, 2)), "float", (None,), r"has shape \(2, 2\); expected \(any,\)"),
    (np.array([1.0, np.nan]), "float", (2,), "holds NaN or infinite values"),
    (np.array([1.5]), "int", (1,), "must hold integers"),
    (np.array([2**64 - 1], np.uint64), "int", (1,), "beyond 2⁶³"),
    (np.ones(2), "str", (), "must be a string"),
])
def test_checked_arrays_name_the_file_and_the_field(array, kind, shape, message):
    with pytest.raises(InputError, match=message) as caught:
        checked_array({"field": array}, "field", "file.npz", kind, shape)
    assert str(caught.value).startswith("file.npz: field ")


@pytest.mark.parametrize("text, message", [
    ("{", "malformed JSON at line 1 column 2"),
    ("[" * 100000, "nested too deeply"),
    ('{"a": ' + "1" * 41 + "}", "an integer of 41 digits is out of range"),
    ('{"a": -' + "1" * 41 + "}", "an integer of 41 digits"),
])
def test_json_that_cannot_be_read_is_one_line(tmp_path, text, message):
    path = tmp_path / "doc.json"
    path.write_text(text)
    with pytest.raises(InputError, match=message):
        read_json(path)


def test_json_reads_ordinary_documents_and_refuses_what_is_not_text(tmp_path):
    path = tmp_path / "doc.json"
    path.write_text('{"a": [1, 2.5, null], "seed": 18446744073709551615}')
    assert read_json(path) == {"a": [1, 2.5, None], "seed": 2**64 - 1}
    path.write_bytes(b"\xff\xfe{}")
    with pytest.raises(InputError, match="not UTF-8"):
        read_json(path)
    with pytest.raises(InputError, match="no such file"):
        read_json(tmp_path / "missing.json")
    with pytest.raises(InputError, match="is a folder"):
        read_json(tmp_path)


def test_animate_killed_mid_write_leaves_no_output_and_the_next_run_cleans_up(tmp_path):
    """kill -9 of `eigendance animate` while it streams frames into its output folder."""
    sphere = trimesh.creation.icosphere(4)  # 2562 vertices
    HarmonicBasis.from_mesh(Mesh.from_arrays(sphere.vertices, sphere.faces), 6,
                            cache=False).save(tmp_path / "basis.npz")
    seconds = 60
    tone = np.sin(np.arange(seconds * 8000) / 3.0)
    Spectrogram.from_samples(tone, 8000).save(tmp_path / "song.npz")
    folder = tmp_path / "out"
    folder.mkdir()
    command = [sys.executable, "-m", "eigendance.cli", "animate", str(tmp_path / "basis.npz"),
               str(tmp_path / "song.npz"), "--fps", "60", "-k", "6", "-o", str(folder / "a.npz")]
    process = start(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    deadline = time.time() + 60
    while not any(size(folder / name) for name in temporary_files(folder)):
        assert process.poll() is None and time.time() < deadline, process.stderr.read()
        time.sleep(0.002)
    os.kill(process.pid, signal.SIGKILL)  # half-way through writing the output
    process.wait(10)
    assert os.listdir(folder) == temporary_files(folder) != []
    assert subprocess.run([*command[:-1], str(folder / "b.npz"), "--fps", "2"],
                          capture_output=True).returncode == 0
    assert os.listdir(folder) == ["b.npz"]
