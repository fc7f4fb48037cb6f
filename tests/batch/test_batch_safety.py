"""A batch never loses or overwrites a file (issue 34): outputs distinct by construction, no
output over an input with or without --force, globs that never take the batch's own outputs,
no record written through a link, one line for a plan value the system refuses, and the store
of a killed batch swept by the next one."""

import os
import shutil
import signal
import time

import pytest
import trimesh
from batch_helpers import song, write_plan

from eigendance.batch import shared
from eigendance.batch.names import unique_parts
from eigendance.batch.plan import read_plan
from eigendance.batch.record import RECORD, REPORT
from eigendance.cli.main import main
from eigendance.writes import LOCK_NAME

CHEAP = {"outputs": ["pc2"], "gallery": 2, "fps": 10, "k": 8}


@pytest.fixture
def folder(tmp_path):
    """A sphere m.obj and a song s.wav."""
    trimesh.creation.icosphere(1).export(tmp_path / "m.obj")
    song(str(tmp_path / "s.wav"), seconds=1.0)
    return tmp_path


def contents(folder) -> dict[str, bytes]:
    return {name: (folder / name).read_bytes() for name in sorted(os.listdir(folder))
            if (folder / name).is_file()}


def one_error(capsys) -> str:
    errors = capsys.readouterr().err.strip().splitlines()
    assert len(errors) == 1 and errors[0].startswith("eigendance: error: "), errors
    assert "Traceback" not in errors[0]
    return errors[0]


# --- case 1: names numbered against every other name ----------------------------------------

def test_numbered_names_never_take_another_inputs_name(folder):
    paths = ["d1/a/b/c/bunny.obj", "d2/a/b/c/bunny.obj", "a_b_c_bunny_2.obj"]
    parts = unique_parts(paths, "model")
    assert len({part.lower() for part in parts}) == 3, parts
    for path in paths:
        os.makedirs(folder / os.path.dirname(path) if os.path.dirname(path) else folder,
                    exist_ok=True)
        shutil.copy(folder / "m.obj", folder / path)
    plan = read_plan(write_plan(str(folder), models=paths, songs=["s.wav"], out="out", **CHEAP))
    stems = [job.stem for job in plan.jobs()]
    assert len({stem.lower() for stem in stems}) == len(stems) == 6


def test_names_stay_distinct_ignoring_case_after_every_step():
    paths = ["x/Bunny.obj", "y/bunny.obj", "bunny_2.obj", "BUNNY_3.obj", "z/bunny.ply",
             "Bunny_obj.obj"]
    parts = unique_parts(paths, "model")
    assert len({part.lower() for part in parts}) == len(parts), parts


# --- case 2: no output over an input, --force or not ------------------------------------------

@pytest.mark.parametrize("force", [[], ["--force"]], ids=["plain", "force"])
def test_an_output_that_would_replace_an_input_is_refused_before_any_work(folder, capsys,
                                                                          force):
    shutil.copy(folder / "m.obj", folder / "m-s-0.obj")
    plan = write_plan(str(folder), models=["m.obj", "m-s-0.obj"], songs=["s.wav"], out=".",
                      **CHEAP)
    before = contents(folder)
    assert main(["batch", plan, *force]) == 1
    message = one_error(capsys)
    assert "m-s-0.obj" in message and "input" in message
    assert contents(folder) == before  # nothing written, no input touched


@pytest.mark.parametrize("named", ["m-s-0.mtl", "m-s-1_texture0.png"])
def test_an_output_named_like_a_file_a_model_names_is_refused(folder, capsys, named):
    """A point cache writes `{stem}.mtl` and a look's `{stem}_texture<i>.png`: never over the
    MTL an OBJ input names, nor over an image its MTL names."""
    if named.endswith(".mtl"):
        (folder / named).write_text("newmtl skin\nKd 1 0 0\n")
        (folder / "m.obj").write_text(f"mtllib {named}\n" + (folder / "m.obj").read_text())
    else:
        (folder / named).write_bytes(b"\x89PNG\r\n\x1a\n")
        (folder / "look.mtl").write_text(f"newmtl skin\nmap_Kd {named}\n")
        (folder / "m.obj").write_text("mtllib look.mtl\n" + (folder / "m.obj").read_text())
    plan = write_plan(str(folder), models=["m.obj"], songs=["s.wav"], out=".", **CHEAP)
    before = contents(folder)
    assert main(["batch", plan, "--force"]) == 1
    assert named in one_error(capsys)
    assert contents(folder) == before


# --- case 3: globs never take the batch's own outputs ---------------------------------------

def test_outputs_in_the_inputs_folder_are_not_fed_back_in(folder):
    plan = write_plan(str(folder), models=["*.obj"], songs=["*.wav"], out=".", **CHEAP)
    assert main(["batch", plan, "-j", "1"]) == 0
    assert (folder / "m-s-0.obj").exists() and (folder / "m-s-0.wav").exists()
    again = read_plan(plan)
    assert [model.path for model in again.models] == [str(folder / "m.obj")]
    assert [each.path for each in again.songs] == [str(folder / "s.wav")]
    assert len(again.jobs()) == 2
    assert main(["batch", plan, "-j", "1"]) == 0  # everything up to date


# --- case 7: the record and the report are never written through a link --------------------

@pytest.mark.parametrize("name", [RECORD, REPORT])
def test_a_planted_link_for_the_record_or_report_is_refused(folder, tmp_path_factory, capsys,
                                                           name):
    target = tmp_path_factory.mktemp("elsewhere") / "precious.txt"
    target.write_text("keep me\n")
    (folder / "out").mkdir()
    os.symlink(target, folder / "out" / name)
    plan = write_plan(str(folder), models=["loop4"], songs=["s.wav"], out="out",
                      outputs=["npz"], gallery=2, fps=10)
    assert main(["batch", plan]) == 1
    assert "is a link" in one_error(capsys)
    assert target.read_text() == "keep me\n"
    assert os.path.islink(folder / "out" / name)
    assert sorted(os.listdir(folder / "out")) == [name]


# --- case 9: plan values the system refuses ---------------------------------------------------

@pytest.mark.parametrize("text", [
    'out = "o\\u0000ut"',
    'models = ["m\\u0000.obj"]',
    "x = " + "[" * 5000 + "]" * 5000,
    'out = "/sys/kernel"',
], ids=["NUL in out", "NUL in models", "5000 levels", "/sys/kernel"])
def test_a_plan_value_the_system_refuses_is_one_line_not_a_bug(folder, capsys, text):
    settings = {"models": ["m.obj"], "songs": ["s.wav"], "outputs": ["npz"], "gallery": 2,
                "out": "out"}
    key = text.split(" = ")[0]
    lines = [f"{k} = {v!r}".replace("'", '"') for k, v in settings.items() if k != key]
    (folder / "plan.toml").write_text("\n".join([text, *lines]) + "\n")
    before = contents(folder)
    assert main(["batch", str(folder / "plan.toml")]) == 1
    one_error(capsys)
    assert contents(folder) == before and not (folder / "out").exists()


# --- case 10: the store of a killed batch is swept by the next one --------------------------

def test_the_store_of_a_killed_batch_is_swept_by_the_next(tmp_path):
    pid = os.fork()
    if pid == 0:  # a batch driver, killed with its store full
        try:
            shared.Store(str(tmp_path)).put(list(range(1000)))
            time.sleep(60)
        finally:
            os._exit(0)
    deadline = time.time() + 30
    while not any(os.path.isfile(os.path.join(tmp_path, name, "1.shared"))
                  for name in os.listdir(tmp_path)):
        assert time.time() < deadline
        time.sleep(0.01)
    os.kill(pid, signal.SIGKILL)
    os.waitpid(pid, 0)
    (killed,) = os.listdir(tmp_path)
    running = shared.Store(str(tmp_path))  # a live store of another batch: kept
    assert os.path.isfile(os.path.join(running.folder, LOCK_NAME))
    old = time.time() - 3600
    for name in (killed, os.path.basename(running.folder)):
        os.utime(tmp_path / name, (old, old))
    foreign = tmp_path / f"{shared.STORE_PREFIX}foreign"  # no lock file: not ours to judge
    foreign.mkdir()
    os.utime(foreign, (old, old))
    fresh = shared.Store(str(tmp_path))
    assert sorted(os.listdir(tmp_path)) == sorted(
        [os.path.basename(running.folder), os.path.basename(fresh.folder), foreign.name])
    for store in (running, fresh):
        store.close()
    assert os.listdir(tmp_path) == [foreign.name]
