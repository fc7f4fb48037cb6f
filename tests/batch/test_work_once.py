"""Work once: every model, every song (its spectrogram at each band count, its rhythm once) and
every gallery of a plan is prepared by one task, whatever the number of jobs that use it; a
prepared value is released once its last user is done; a second plan on the same songs reads
their analysis from the content cache. The engine here runs the tasks in this process and
records them (the real engines run the same graph: tests/batch/test_faults.py)."""

import numpy as np
from batch_helpers import write_plan

from eigendance.batch import work
from eigendance.batch.plan import read_plan
from eigendance.batch.run import run_plan
from eigendance.harmonic.construction import BasisRecord
from eigendance.music import spectrogram as spectrogram_module
from eigendance.music.mapping import Mapping


class Handle:
    """A kept value, as an engine hands it back."""

    def __init__(self, value):
        self.value = value


class RecordingEngine:
    """Runs each task at once, here; records (function, arguments) and what was released."""

    kind = "recording"
    slots = 2

    def __init__(self):
        self.calls, self.released, self.running, self.results = [], [], {}, []

    def describe(self):
        return "this process"

    def submit(self, task):
        arguments = tuple(value.value if isinstance(value, Handle) else value
                          for value in task.arguments)
        self.calls.append((task.function, arguments))
        report, value = work.task(getattr(work, task.function), *arguments)
        task.attempts += 1
        self.results.append((task, report, Handle(value) if task.keep else None))
        self.running[id(task)] = task

    def finished(self, timeout=None):
        done, self.results = self.results, []
        for task, _, _ in done:
            self.running.pop(id(task))
        return done

    def release(self, handle):
        self.released.append(handle)

    def close(self, interrupted=False):
        pass


class Silent:
    def start(self, *_):
        pass

    def job(self, *_):
        pass

    def failure(self, message):
        raise AssertionError(message)


def run(plan_path):
    engine = RecordingEngine()
    outcome = run_plan(read_plan(plan_path), lambda: engine, Silent())
    assert [line["status"] for line in outcome.lines] == ["done"] * len(outcome.lines)
    return engine, outcome


def called(engine, function):
    return [arguments for name, arguments in engine.calls if name == function]


def count_rhythm_analyses(monkeypatch) -> list:
    """Every rhythm analysis made in this process from now on."""
    calls = []
    analyse = spectrogram_module.analyse_rhythm

    def counted(*arguments, **options):
        calls.append(1)
        return analyse(*arguments, **options)

    monkeypatch.setattr(spectrogram_module, "analyse_rhythm", counted)
    return calls


def test_each_model_song_and_gallery_is_prepared_once(inputs, monkeypatch):
    monkeypatch.setenv("EIGENDANCE_CACHE_DIR", str(inputs / "cache"))
    rhythms = count_rhythm_analyses(monkeypatch)
    plan = write_plan(str(inputs), models=["sphere.obj", "loop4"], songs=["*.wav"], gallery=3,
                      outputs=["npz"], out="out", fps=10, k=8)
    engine, outcome = run(plan)
    assert len(outcome.lines) == 2 * 2 * 3
    models = called(engine, "prepare_model")
    assert sorted(str(arguments[0]).rsplit("/", 1)[-1] for arguments in models) == \
        ["loop4", "sphere.obj"]
    songs = called(engine, "prepare_song")
    assert sorted(arguments[0].rsplit("/", 1)[-1] for arguments in songs) == ["a.wav", "b.wav"]
    galleries = called(engine, "prepare_gallery")
    assert len(galleries) == 4  # one per (model, song), of 3 items
    assert len(called(engine, "make_outputs")) == 12
    assert len(engine.released) == 2 + 2 + 4  # every prepared value, once its jobs are done
    assert len(rhythms) == 2
    # Another plan on the same songs: their spectrograms and rhythms come from the cache.
    engine, _ = run(write_plan(str(inputs), models=["loop4"], songs=["*.wav"], gallery=2,
                               outputs=["npz"], out="out2", fps=10))
    assert len(called(engine, "prepare_song")) == 2 and len(rhythms) == 2


def test_each_song_is_analysed_once_per_band_count_and_its_rhythm_once(inputs, monkeypatch):
    monkeypatch.setenv("EIGENDANCE_CACHE_DIR", str(inputs / "cache"))
    rhythms = count_rhythm_analyses(monkeypatch)
    for name, bands in (("narrow", 16), ("wide", 64), ("wide2", 64)):
        Mapping(np.linspace(0, 1, bands), np.linspace(-1, 1, 8), name=name).save(
            inputs / f"{name}.json")
    plan = write_plan(str(inputs), models=["sphere.obj"], songs=["*.wav"],
                      mappings=["*.json"], outputs=["npz"], out="out", fps=10, k=8)
    engine, outcome = run(plan)
    assert len(outcome.lines) == 2 * 3
    songs = sorted((arguments[0].rsplit("/", 1)[-1], arguments[2])
                   for arguments in called(engine, "prepare_song"))
    assert songs == [("a.wav", 16), ("a.wav", 64), ("b.wav", 16), ("b.wav", 64)]
    assert len(rhythms) == 2  # once per song, shared by its two band counts
    for arguments in called(engine, "make_outputs"):
        spectrogram, mapping = arguments[2], arguments[3]
        assert spectrogram.bands == mapping.bands and spectrogram.rhythm is not None
    # The rhythm does not depend on the bands: shared, it is what each band count would get.
    wide = [arguments for arguments in called(engine, "prepare_song") if len(arguments) == 4][-1]
    alone = spectrogram_module.Spectrogram.from_file(wide[0], bands=wide[2])
    shared = [arguments[2] for arguments in called(engine, "make_outputs")
              if arguments[2].bands == wide[2] and arguments[0]["song"] == wide[0]][0]
    for name in ("onset_strength", "onsets", "beats"):
        np.testing.assert_array_equal(getattr(shared.rhythm, name), getattr(alone.rhythm, name))
    assert shared.rhythm.tempo == alone.rhythm.tempo


def test_a_mesh_is_solved_on_the_basis_its_mappings_were_made_on(inputs, monkeypatch):
    """The k and the construction a mapping records (a reduced basis of 8 harmonics on 40
    samples here, which the rule would not choose for 162 vertices) are what the model is
    prepared with; the plan's `construction` overrides it."""
    monkeypatch.setenv("EIGENDANCE_CACHE_DIR", str(inputs / "cache"))
    Mapping(np.linspace(0, 1, 16), np.linspace(-1, 1, 8),
            basis=BasisRecord(8, "reduced", 40)).save(inputs / "made.json")
    settings = {"models": ["sphere.obj"], "songs": ["a.wav"], "mappings": ["made.json"],
                "outputs": ["npz"], "fps": 10}
    engine, _ = run(write_plan(str(inputs), **settings, out="out"))
    (arguments,) = called(engine, "prepare_model")
    assert arguments[2:] == (8, "reduced", 40)
    assert work.prepare_model(*arguments).construction == "reduced"
    engine, _ = run(write_plan(str(inputs), **settings, out="out2", construction="exact"))
    assert called(engine, "prepare_model")[0][2:] == (8, "exact", None)
