"""The public API: what `eigendance` exports is documented and its examples run."""

import doctest
import inspect

import numpy as np
import pytest

import eigendance

# Where a class documents how it is made: its main constructor.
CONSTRUCTORS = {"HarmonicBasis": "from_mesh", "Spectrogram": "from_file",
                "ModalModel": "from_skeleton", "Mesh": "from_arrays"}


def test_all_lists_the_entry_points_the_readme_shows():
    with open("README.md", encoding="utf-8") as file:
        readme = file.read()
    for name in ("HarmonicBasis", "Spectrogram", "initial_gallery", "breed", "positions_at",
                 "Skeleton", "ModalModel", "ModalSkin", "linear_blend_skinning"):
        assert name in eigendance.__all__ and name in readme, name
    assert sorted(eigendance.__all__) == sorted(set(eigendance.__all__))


@pytest.mark.parametrize("name", eigendance.__all__)
def test_each_entry_point_states_parameters_returns_and_an_example(name):
    entry = getattr(eigendance, name)
    documented = inspect.getdoc(entry) or ""
    if inspect.isclass(entry) and name in CONSTRUCTORS:
        documented += inspect.getdoc(getattr(entry, CONSTRUCTORS[name])) or ""
    assert "Parameters" in documented, f"{name}: no Parameters section"
    if not inspect.isclass(entry):
        assert "Returns" in documented, f"{name}: no Returns section"
    assert "Example" in documented and ">>>" in documented, f"{name}: no example"


@pytest.mark.parametrize("name", eigendance.__all__)
def test_each_example_runs(name):
    entry = getattr(eigendance, name)
    module = inspect.getmodule(entry)
    finder = doctest.DocTestFinder(recurse=inspect.isclass(entry))
    tests = [test for test in finder.find(entry, name, module=module,
                                          globs={**vars(module), "np": np})
             if test.examples]
    assert tests, f"{name}: no runnable example"
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
    for test in tests:
        runner.run(test)
    assert runner.failures == 0, f"{name}: {runner.failures} failing example(s)"
