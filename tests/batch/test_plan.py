"""Plans: a bad plan ends in one line naming the file and the key before any work starts; names
are safe and unique; the example of --help is a plan."""


import pytest
from batch_helpers import write_plan

from eigendance.batch import plan as plan_module
from eigendance.batch.names import unique_parts
from eigendance.batch.plan import read_plan
from eigendance.cli import options
from eigendance.cli.main import main
from eigendance.errors import InputError
from eigendance.harmonic.construction import BasisRecord
from eigendance.inputs.defaults import DEFAULT_K
from eigendance.inputs.mapping import basis_choice
from eigendance.music.gallery import MAX_GALLERY, MIN_GALLERY
from eigendance.music.mapping import Mapping

GOOD = {"models": ["sphere.obj", "loop4"], "songs": ["*.wav"], "outputs": ["glb"],
        "gallery": 2, "out": "out"}

BAD = [  # (what changes, the key the message must name)
    ({"outputz": ["glb"]}, "outputz"),
    ({"outputs": ["gif"]}, "outputs"),
    ({"construction": "fast"}, "construction"),
    ({"outputs": []}, "outputs"),
    ({"outputs": "@42"}, "outputs"),
    ({"models": ["*.stl"]}, "models"),
    ({"models": ["missing.obj"]}, "models"),
    ({"models": ["a.wav"]}, "models"),
    ({"songs": ["songs/*.mp3"]}, "songs"),
    ({"songs": ["sphere.obj"]}, "songs"),
    ({"songs": ["."]}, "songs"),
    ({"gallery": 1}, "gallery"),
    ({"gallery": 17}, "gallery"),
    ({"gallery": 2.5}, "gallery"),
    ({"gallery": "@true"}, "gallery"),
    ({"mappings": ["m.json"]}, "gallery"),  # both given
    ({"gallery": None, "mappings": ["none/*.json"]}, "mappings"),
    ({"gallery": None, "mappings": ["bad.json"]}, "mappings"),
    ({"gallery": None}, "gallery"),  # neither
    ({"fps": 0}, "fps"),
    ({"fps": "@nan"}, "fps"),
    ({"fps": 1000}, "fps"),
    ({"k": 0}, "k"),
    ({"k": 3.5}, "k"),
    ({"start": -1}, "start"),
    ({"duration": 0}, "duration"),
    ({"duration": "@inf"}, "duration"),
    ({"size": "640x481"}, "size"),
    ({"size": [8, 8]}, "size"),
    ({"size": "@{width = 2}"}, "size"),
    ({"out": "sphere.obj"}, "out"),
    ({"out": 3}, "out"),
    ({"cache": "a.wav"}, "cache"),
    ({"surface": "bad.json"}, "surface"),
    ({"surface": 3}, "surface"),
    ({"surface": "none/*.json"}, "surface"),
]


@pytest.mark.parametrize(("change", "key"), BAD, ids=[f"{i}-{k}" for i, (_, k) in
                                                      enumerate(BAD)])
def test_a_bad_plan_is_one_line_naming_the_file_and_the_key_before_any_work(
        inputs, capsys, change, key):
    (inputs / "bad.json").write_text('{"format": "eigendance.mapping", "version": 2}')
    (inputs / "m.json").write_text("{}")
    settings = {**GOOD, **change}
    plan = write_plan(str(inputs), **{k: v for k, v in settings.items() if v is not None})
    assert main(["batch", plan]) == 1
    errors = capsys.readouterr().err.strip().splitlines()
    assert len(errors) == 1, errors
    assert errors[0].startswith(f"eigendance: error: {plan}: {key} "), errors[0]
    assert not (inputs / "out").exists()  # nothing was started


def test_a_plan_that_is_not_toml_or_missing_is_one_line(inputs, capsys):
    (inputs / "plan.toml").write_text("models = [\n")
    assert main(["batch", str(inputs / "plan.toml")]) == 1
    assert main(["batch", str(inputs / "none.toml")]) == 1
    errors = capsys.readouterr().err.strip().splitlines()
    assert len(errors) == 2
    assert errors[0].startswith(f"eigendance: error: {inputs / 'plan.toml'}: not a TOML plan (")
    assert errors[1] == f"eigendance: error: {inputs / 'none.toml'}: no such file"


def test_the_plan_checks_numbers_with_the_command_lines_ranges():
    assert (plan_module.HARMONICS, plan_module.FPS, plan_module.SECONDS) == \
        (options.HARMONICS.bounds, (0, 240), options.SECONDS.bounds)
    parser = options.argparse.ArgumentParser()
    from eigendance.cli.exports import add_render
    add_render(parser)
    render_fps = next(a for a in parser._actions if a.dest == "fps").type
    assert render_fps.bounds == plan_module.FPS
    assert options.gallery_size.bounds == (MIN_GALLERY, MAX_GALLERY)


def test_globs_and_defaults_are_read_relative_to_the_plan(inputs, monkeypatch):
    monkeypatch.chdir("/")  # not the plan's folder (restored after the test)
    plan = read_plan(write_plan(str(inputs), **GOOD))
    assert [model.name for model in plan.models] == ["sphere", "loop4"]
    assert [model.kind for model in plan.models] == ["mesh", "rig"]
    assert [song.path for song in plan.songs] == [str(inputs / "a.wav"), str(inputs / "b.wav")]
    assert (plan.fps, plan.k, plan.start, plan.duration, plan.size) == \
        (30.0, DEFAULT_K, 0.0, None, (1280, 720))
    assert [job.stem for job in plan.jobs()][:4] == ["sphere-a-0", "sphere-a-1", "loop4-a-0",
                                                     "loop4-a-1"]
    assert len(plan.jobs()) == 8


def test_k_is_the_one_the_mappings_were_made_on_unless_the_plan_says(inputs):
    """A mapping records its basis (docs/design.md#mapping-file): without `k`, the batch solves
    that k; mappings of different k need the plan's `k`; a mapping without the record: 150."""
    for name, k in (("a.json", 24), ("b.json", 24), ("c.json", 40)):
        Mapping([0.5], [1.0], basis=BasisRecord(k)).save(inputs / name)
    Mapping([0.5], [1.0]).save(inputs / "old.json")
    settings = {key: value for key, value in GOOD.items() if key != "gallery"}
    assert read_plan(write_plan(str(inputs), **settings, mappings=["a.json", "b.json"])).k == 24
    assert read_plan(write_plan(str(inputs), **settings, mappings=["old.json"])).k == DEFAULT_K
    both = {**settings, "mappings": ["a.json", "c.json"]}
    with pytest.raises(InputError, match=r"mappings were made on bases of different k "
                                         r"\(24, 40\)"):
        read_plan(write_plan(str(inputs), **both))
    assert read_plan(write_plan(str(inputs), **both, k=60)).k == 60


def test_the_construction_is_the_one_the_mappings_were_made_on_and_a_change_is_said(inputs,
                                                                                   capsys):
    """As k, the construction a mapping records is the batch's unless the plan says otherwise;
    then the batch says how the dance differs in the command line's words (`basis_choice`,
    printed as `say_note` prints it), before any work."""
    made = Mapping([0.5], [1.0], name="r.json", basis=BasisRecord(24, "reduced", 96))
    made.save(inputs / "r.json")
    Mapping([0.5], [1.0], basis=BasisRecord(24)).save(inputs / "e.json")
    settings = {key: value for key, value in GOOD.items() if key != "gallery"}
    plan = read_plan(write_plan(str(inputs), **settings, mappings=["r.json"]))
    assert (plan.k, plan.construction, plan.samples, plan.notes) == (24, "reduced", 96, [])
    with pytest.raises(InputError, match=r"mappings were made on bases of different "
                                         r"constructions \(exact, reduced\); set construction"):
        read_plan(write_plan(str(inputs), **settings, mappings=["r.json", "e.json"]))
    for asked, note in (({"construction": "exact"}, basis_choice(made, None, "exact").note),
                        ({"k": 60}, basis_choice(made, 60).note)):
        path = write_plan(str(inputs), **settings, mappings=["r.json"], **asked)
        plan = read_plan(path)
        assert plan.notes == [note] and note.startswith("r.json was made on k = 24 harmonics "
                                                        "(reduced, 96 samples asked); on ")
        assert main(["batch", path, "--dry-run"]) == 0
        assert capsys.readouterr().err.splitlines()[0] == f"{path}: note: {note}"


def test_names_are_safe_and_collisions_are_told_apart():
    names = unique_parts(["x/Song One.ogg", "y/song-one.mp3", "z/Café.ogg", "w/.hidden.ogg",
                          "a/b/voice.ogg", "c/b/voice.ogg", "d/ü.ogg"], "song")
    assert names == ["Song_One_ogg", "song_one_mp3", "Cafe", "hidden", "a_b_voice",
                     "c_b_voice", "u"]
    assert all("-" not in name and not name.startswith(".") for name in names)
    assert len({name.lower() for name in names}) == len(names)


def test_help_prints_an_example_plan_that_reads(capsys, tmp_path):
    with pytest.raises(SystemExit):
        main(["batch", "--help"])
    assert plan_module.EXAMPLE in capsys.readouterr().out
    for folder, name in (("meshes", "a.obj"), ("characters", "hero.glb"), ("songs", "x.ogg")):
        (tmp_path / folder).mkdir(exist_ok=True)
        (tmp_path / folder / name).write_bytes(b"0")
    (tmp_path / "single.mp3").write_bytes(b"0")
    (tmp_path / "plan.toml").write_text(plan_module.EXAMPLE)
    plan = read_plan(tmp_path / "plan.toml")
    assert (plan.outputs, len(plan.items), plan.size, plan.start, plan.duration) == \
        (("mp4", "glb"), 4, (1280, 720), 30.0, 15.0)
