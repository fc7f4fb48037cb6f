"""Batches under faults: Ctrl-C, a worker killed mid-job (kill -9), on local processes and on
Ray; the same plan gives the same files on both engines."""

import json
import os
import signal
import subprocess
import sys
import threading
import time

import av
import numpy as np
import pytest
from batch_helpers import lock_holders, song, temporaries, write_plan

from eigendance.batch.record import RECORD, read_entries
from eigendance.cli.main import main
from helpers import alive, descendants, start

LONG = {"models": ["sphere.obj", "loop4"], "songs": ["long*.wav"], "outputs": ["mp4", "npz"],
        "gallery": 2, "size": "96x64", "fps": 30, "k": 8}


def report(folder) -> list[dict]:
    with open(os.path.join(folder, "batch-report.jsonl")) as file:
        return [json.loads(line) for line in file]


def frames(path) -> np.ndarray:
    with av.open(str(path)) as video:
        return np.stack([frame.to_ndarray(format="rgb24") for frame in video.decode(video=0)])


def same_outputs(first, second) -> None:
    """Every output of two runs: the same bytes (glb, npz, pc2, songs, meshes), the same frames
    (mp4)."""
    names = sorted(name for name in os.listdir(first) if not name.startswith("batch-"))
    assert names == sorted(name for name in os.listdir(second)
                           if not name.startswith("batch-"))
    for name in names:
        if name.endswith(".mp4"):
            assert np.array_equal(frames(first / name), frames(second / name)), name
        else:
            assert (first / name).read_bytes() == (second / name).read_bytes(), name


def wait_for(condition, seconds=120.0):
    deadline = time.time() + seconds
    while not condition():
        assert time.time() < deadline, "timed out"
        time.sleep(0.01)


@pytest.fixture
def long_songs(inputs):
    for index in range(2):
        song(str(inputs / f"long{index}.wav"), seconds=6.0, seed=index)
    return inputs


def kill_a_writer(out, killed: list) -> threading.Thread:
    """A thread that kills (SIGKILL) the first process it sees holding the lock of a temporary
    output file in `out`: a worker mid-job."""
    def watch():
        deadline = time.time() + 120
        while time.time() < deadline and not killed:
            if os.path.isdir(out):
                for pid in lock_holders(out).values():
                    os.kill(pid, signal.SIGKILL)
                    killed.append(pid)
                    return
            time.sleep(0.005)

    thread = threading.Thread(target=watch, daemon=True)
    thread.start()
    return thread


def test_ctrl_c_stops_everything_and_the_next_run_makes_only_the_rest(long_songs):
    plan = write_plan(str(long_songs), **LONG, out="out")
    out = long_songs / "out"
    process = start([sys.executable, "-m", "eigendance.cli.main", "batch", plan, "-j", "2"],
                    stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                    start_new_session=True)
    wait_for(lambda: any(entry["key"] for entry in read_entries(str(out / RECORD)).values()))
    workers = descendants(process.pid)
    os.killpg(process.pid, signal.SIGINT)  # what a terminal sends to its foreground group
    _, errors = process.communicate(timeout=60)
    assert process.returncode == 130 and "interrupted" in errors and "Traceback" not in errors
    wait_for(lambda: not alive(workers), 10)
    assert temporaries(out) == []
    recorded = [name for name, entry in read_entries(str(out / RECORD)).items()
                if entry["key"]]  # complete (the others are claimed: made again)
    assert recorded and all(os.path.exists(out / name) for name in recorded)
    statuses = [line["status"] for line in report(out)]
    assert "interrupted" in statuses and len(statuses) == 8
    made = {name: os.stat(out / name).st_mtime_ns for name in recorded}

    assert main(["batch", plan, "-j", "2"]) == 0
    lines = report(out)
    assert sorted(name for line in lines for name in line["skipped"]) == sorted(recorded)
    assert not {name for line in lines for name in line["outputs"]} & set(recorded)
    assert {name: os.stat(out / name).st_mtime_ns for name in recorded} == made


@pytest.mark.parametrize("engine", ["local", "ray"])
def test_a_worker_killed_mid_job_is_retried_and_the_outputs_are_a_clean_runs(
        long_songs, engine, request):
    flags = ["--ray"] if engine == "ray" else ["-j", "2"]
    if engine == "ray":
        request.getfixturevalue("ray_session")
    settings = {**LONG, "songs": ["long0.wav"]}
    assert main(["batch", write_plan(str(long_songs), **settings, out="clean"), *flags]) == 0
    killed: list[int] = []
    watcher = kill_a_writer(long_songs / "out", killed)
    assert main(["batch", write_plan(str(long_songs), **settings, out="out"), *flags]) == 0
    watcher.join()
    assert killed, "no worker was caught writing"
    lines = report(long_songs / "out")
    assert [line["status"] for line in lines] == ["done"] * 4
    assert killed[0] not in {line["pid"] for line in lines}
    if engine == "local":  # Ray runs the task again by itself, not counted here
        assert sorted(line["attempts"] for line in lines) == [1, 1, 1, 2]
    assert temporaries(long_songs / "out") == []
    same_outputs(long_songs / "clean", long_songs / "out")


def test_the_same_plan_gives_the_same_files_on_every_engine(inputs, ray_session):
    settings = {"models": ["sphere.obj", "loop4"], "songs": ["a.wav"], "gallery": 2,
                "outputs": ["glb", "npz", "pc2", "mp4"], "size": "48x32", "fps": 12, "k": 8}
    assert main(["batch", write_plan(str(inputs), **settings, out="local"), "-j", "2"]) == 0
    assert main(["batch", write_plan(str(inputs), **settings, out="ray"), "--ray"]) == 0
    same_outputs(inputs / "local", inputs / "ray")
