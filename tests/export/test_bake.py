"""`eigendance bake` (docs/design.md#blender-add-on): a mesh's dance in its file's vertex order,
as morph targets or a point cache, equal to what `eigendance animate` writes; and the add-on's
runner (no bpy): the command found or named in one line, its progress read from its bars, its
error line, a job killed."""

from __future__ import annotations

import importlib.util
import os
import sys

import numpy as np
import pytest
from export_helpers import SONG, in_file_order, read_obj

from eigendance.cli.main import main
from eigendance.export.pointcache import read_pc2
from helpers import fixture_path

RUNNER = os.path.join(os.path.dirname(__file__), "..", "..", "src", "eigendance", "blender",
                      "eigendance_blender", "runner.py")


def load_runner():
    spec = importlib.util.spec_from_file_location("eigendance_blender_runner", RUNNER)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def teapot_with_a_twin(tmp_path_factory):
    """The teapot with its first vertex repeated at the end, in a triangle of its own (welded
    by the clean-up, the triangle then a repeat): the dance keeps it, moving with its twin."""
    folder = tmp_path_factory.mktemp("bake")
    text = open(fixture_path("meshes", "teapot.obj"), encoding="utf-8").read()
    first = next(line for line in text.splitlines() if line.startswith("v "))
    path = folder / "teapot.obj"
    count = sum(line.startswith("v ") for line in text.splitlines())
    path.write_text(text + f"\n{first}\nf {count + 1} 2 3\n")
    return path


def test_bake_writes_the_animation_in_the_files_order(teapot_with_a_twin, tmp_path):
    morphs, cache = tmp_path / "dance.npz", tmp_path / "dance.pc2"
    animation = tmp_path / "animate.npz"
    common = ["-k", "20", "--fps", "10", "--start", "1", "--duration", "2.5"]
    assert main(["bake", str(teapot_with_a_twin), SONG, "--item", "4", *common, "-o",
                 str(morphs)]) == 0
    assert main(["gallery", str(teapot_with_a_twin), SONG, "-k", "20", "-o",
                 str(tmp_path / "gallery")]) == 0
    assert main(["animate", str(teapot_with_a_twin), SONG, "--mapping",
                 str(tmp_path / "gallery" / "3.json"), *common, "-o", str(animation)]) == 0
    assert main(["bake", str(teapot_with_a_twin), SONG, "--mapping",
                 str(tmp_path / "gallery" / "3.json"), *common, "-o", str(cache)]) == 0
    baked = np.load(morphs)
    rest = baked["rest"]
    vertices, faces = read_obj(teapot_with_a_twin)
    np.testing.assert_allclose(rest, vertices, rtol=0, atol=1e-12)  # the file's, in its order
    # The cleaned mesh's (welded, the unused vertex dropped) put back on the file's vertices.
    expected = in_file_order(np.load(animation)["positions"], vertices, faces)
    np.testing.assert_allclose(rest[-1], rest[0], rtol=0, atol=1e-12)  # the twin's place
    weights = baked["weights"]
    assert np.abs(weights).max() <= 1.0 + 1e-6 and len(weights) == len(expected) == 26
    positions = rest + np.einsum("tj,jnc->tnc", weights, baked["targets"])
    diagonal = float(np.linalg.norm(np.ptp(rest, axis=0)))
    assert np.abs(positions - expected).max() <= 1e-5 * diagonal
    assert np.abs(positions[:, -1] - positions[:, 0]).max() <= 1e-5 * diagonal  # moves with it
    points, _, _ = read_pc2(cache)
    assert np.abs(points - positions).max() <= 1e-5 * diagonal


@pytest.mark.parametrize("words, message", [
    (["--item", "9"], "--item"),
    (["-o", "dance.glb"], "bake writes .npz"),
])
def test_bake_refuses_in_one_line(teapot_with_a_twin, tmp_path, capsys, words, message):
    output = [] if "-o" in words else ["-o", str(tmp_path / "x.npz")]
    try:
        status = main(["bake", str(teapot_with_a_twin), SONG, *words, *output])
    except SystemExit as end:  # argparse's errors end the parse
        status = end.code
    assert status == 1
    error = capsys.readouterr().err
    assert message in error and error.count("\n") == 1


def test_the_runner_finds_the_command_or_says_what_to_install(tmp_path):
    runner = load_runner()
    assert runner.command_words(f"{sys.executable} -m eigendance")[1:] == ["-m", "eigendance"]
    with pytest.raises(runner.CommandMissing, match="pip install eigendance"):
        runner.command_words("eigendance-not-here")
    with pytest.raises(runner.CommandMissing, match="no eigendance command"):
        runner.command_words("  ")


def test_the_runner_reads_progress_and_errors_and_kills():
    runner = load_runner()
    bar = "eigenpairs:  45%|████▌     | 9/20 [00:01<00:01, 5.20pair/s]"
    assert runner.progress_of(f"\r{bar}") == ("eigenpairs", 0.45, "9/20")
    assert runner.progress_of("\rframes: 120frame [00:02, 60frame/s]") == \
        ("frames", None, "120")
    assert runner.progress_of("nothing here") is None
    script = ("import sys, time\nfrom tqdm import tqdm\n"
              "for i in tqdm(range(4), desc='frames', file=sys.stderr, mininterval=0):\n"
              "    time.sleep(0.05)\n"
              "print('eigendance: error: song.mp3: not a readable audio file', file=sys.stderr)\n"
              "sys.exit(1)\n")
    job = runner.Job([sys.executable, "-c", script])
    assert job.wait() == 1
    assert job.error() == "eigendance: error: song.mp3: not a readable audio file"
    if runner.pty is not None:  # tqdm draws its bar on the pseudo-terminal
        assert "frames" in job.output and "4/4" in job.output
    sleeper = runner.Job([sys.executable, "-c", "import time; time.sleep(60)"])
    assert sleeper in runner.RUNNING
    runner.kill_all()
    assert sleeper.process.returncode is not None and sleeper not in runner.RUNNING
