"""Batches on local worker processes: what a job writes, a second run that makes nothing, outputs
altered or deleted made again, a job's bad input said once, files in the way."""

import json
import os
import subprocess
import sys

import numpy as np
from batch_helpers import write_plan

from eigendance.cli.main import main
from eigendance.music.mapping import Mapping

PLAN = {"models": ["sphere.obj", "loop4"], "songs": ["*.wav"],
        "outputs": ["glb", "npz", "pc2", "mp4"], "gallery": 2, "out": "out", "size": "32x32",
        "fps": 10, "k": 8}


def report(folder) -> list[dict]:
    with open(os.path.join(folder, "batch-report.jsonl")) as file:
        return [json.loads(line) for line in file]


def stamps(folder) -> dict[str, int]:
    return {name: os.stat(os.path.join(folder, name)).st_mtime_ns
            for name in os.listdir(folder) if not name.startswith("batch-")}


def test_a_batch_writes_what_the_commands_write_and_a_second_run_makes_nothing(inputs, capsys):
    plan = write_plan(str(inputs), **PLAN)
    out = inputs / "out"
    assert main(["batch", plan, "-j", "2"]) == 0
    lines = report(out)
    assert [line["status"] for line in lines] == ["done"] * 8
    assert sorted(name for name in os.listdir(out) if name.startswith("sphere-a-0")) == \
        ["sphere-a-0.glb", "sphere-a-0.mp4", "sphere-a-0.npz", "sphere-a-0.obj",
         "sphere-a-0.pc2", "sphere-a-0.wav"]
    summary = capsys.readouterr().out
    assert "done              8       32" in summary and "report: " in summary
    # The same dance by hand, through the commands a person would run: the same bytes.
    here = inputs / "by-hand"
    assert main(["gallery", str(inputs / "sphere.obj"), str(inputs / "a.wav"), "-n", "2",
                 "-k", "8", "-o", str(here)]) == 0
    for format in ("glb", "pc2"):
        assert main(["export", str(inputs / "sphere.obj"), str(inputs / "a.wav"), "-k", "8",
                     "--mapping", str(here / "1.json"), "--fps", "10",
                     "-o", str(here / f"sphere-a-1.{format}")]) == 0
        assert (here / f"sphere-a-1.{format}").read_bytes() == \
            (out / f"sphere-a-1.{format}").read_bytes()
    assert main(["animate-rig", "loop4", str(inputs / "b.wav"), "--fps", "10",
                 "-o", str(here / "rig.npz")]) == 0

    before = stamps(out)
    assert main(["batch", plan, "-j", "2"]) == 0
    assert [line["status"] for line in report(out)] == ["skipped"] * 8
    assert stamps(out) == before  # nothing was written again

    with open(out / "loop4-b-1.glb", "ab") as file:
        file.write(b"\0")
    os.unlink(out / "sphere-a-0.npz")
    os.utime(out / "sphere-b-0.pc2")  # touched, not changed: still complete
    assert main(["batch", plan, "-j", "2"]) == 0
    made = {line["job"]: line["outputs"] for line in report(out) if line["status"] == "done"}
    assert made == {"loop4-b-1": ["loop4-b-1.glb"], "sphere-a-0": ["sphere-a-0.npz"]}
    after = stamps(out)
    assert {name for name in after if after[name] != before.get(name)} == \
        {"loop4-b-1.glb", "sphere-a-0.npz", "sphere-b-0.pc2"}


def test_a_job_that_fails_on_its_input_is_said_once_and_the_others_go_on(inputs, capsys):
    (inputs / "broken.obj").write_text("v 0 0 0\nv 1 0 0\nf 1 2 3\n")
    (inputs / "noise.wav").write_bytes(b"RIFF....WAVEfmt not a song")
    plan = write_plan(str(inputs), **{**PLAN, "models": ["sphere.obj", "broken.obj"],
                                      "outputs": ["glb"]})
    assert main(["batch", plan, "-j", "2"]) == 1
    errors = capsys.readouterr().err.strip().splitlines()
    assert [line for line in errors if "broken.obj" in line][0].startswith(
        "eigendance: error: broken.obj: ")
    assert sum("broken.obj" in line for line in errors) == 1
    assert sum("noise.wav" in line for line in errors) == 1
    assert errors[-1].startswith("eigendance: error: 8 of 12 jobs failed (see ")
    lines = report(inputs / "out")
    done = sorted(line["job"] for line in lines if line["status"] == "done")
    assert done == ["sphere-a-0", "sphere-a-1", "sphere-b-0", "sphere-b-1"]
    assert all(line["error"] and line["kind"] == "input" for line in lines
               if line["status"] == "failed")


def test_a_file_in_the_way_that_no_batch_wrote_needs_force(inputs, capsys):
    plan = write_plan(str(inputs), **{**PLAN, "models": ["loop4"], "songs": ["a.wav"],
                                      "outputs": ["npz"]})
    (inputs / "out").mkdir()
    (inputs / "out" / "loop4-a-1.npz").write_bytes(b"mine")
    assert main(["batch", plan]) == 1
    assert "loop4-a-1.npz exists and was not written by a batch; pass --force" in \
        capsys.readouterr().err
    assert (inputs / "out" / "loop4-a-1.npz").read_bytes() == b"mine"
    assert main(["batch", plan, "--force", "--dry-run"]) == 0
    assert capsys.readouterr().out.splitlines() == ["loop4-a-0: npz", "loop4-a-1: npz",
                                                    "2 of 2 jobs to make"]
    assert main(["batch", plan, "--force"]) == 0
    assert (inputs / "out" / "loop4-a-1.npz").read_bytes() != b"mine"


def test_the_command_line_runs_a_batch_in_a_fresh_process(inputs):
    """As a person runs it: the console script, worker processes started from it."""
    plan = write_plan(str(inputs), **{**PLAN, "outputs": ["glb"], "songs": ["a.wav"]})
    done = subprocess.run([sys.executable, "-m", "eigendance.cli.main", "batch", plan, "-v"],
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    assert "sphere-a-0: sphere-a-0.glb (" in done.stderr
    assert [line["status"] for line in report(inputs / "out")] == ["done"] * 4


def test_a_plans_surface_ripples_the_rigs_skin_as_animate_rig_does(inputs):
    """`surface = "auto"`: each rig's skin also ripples (docs/design.md#surface-of-a-rig); the
    animation file holds what `animate-rig --surface auto` writes; meshes are as before."""
    Mapping(np.linspace(0, 1, 64), np.ones(4), name="sway").save(inputs / "sway.json")
    settings = {key: value for key, value in PLAN.items() if key != "gallery"}
    plan = write_plan(str(inputs), **{**settings, "models": ["loop4"], "songs": ["b.wav"],
                                      "outputs": ["npz", "glb"], "mappings": ["sway.json"],
                                      "surface": "auto"})
    out = inputs / "out"
    assert main(["batch", plan, "-j", "1"]) == 0
    here = inputs / "by-hand.npz"
    assert main(["animate-rig", "loop4", str(inputs / "b.wav"), "--fps", "10", "--mapping",
                 str(inputs / "sway.json"), "--surface", "auto", "-o", str(here)]) == 0
    with np.load(here) as made, np.load(out / "loop4-b-sway.npz") as batch:
        np.testing.assert_allclose(batch["positions"], made["positions"], atol=1e-6)
    plain = inputs / "plain.npz"
    assert main(["animate-rig", "loop4", str(inputs / "b.wav"), "--fps", "10", "--mapping",
                 str(inputs / "sway.json"), "-o", str(plain)]) == 0
    with np.load(plain) as still, np.load(here) as rippled:
        assert np.abs(still["positions"] - rippled["positions"]).max() > 1e-3
