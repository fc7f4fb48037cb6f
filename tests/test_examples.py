"""Every example in the package's docstrings runs and shows what it says (the public names'
are also run one by one in tests/test_public_api.py)."""

import doctest
import importlib
import pkgutil

import numpy as np
import pytest

import eigendance

MODULES = sorted(info.name for info in pkgutil.walk_packages(eigendance.__path__, "eigendance.")
                 if info.name.rsplit(".", 1)[-1] != "__main__")  # that one runs the CLI


@pytest.mark.parametrize("name", MODULES)
def test_the_examples_of_each_module_run(name):
    module = importlib.import_module(name)
    result = doctest.testmod(module, extraglobs={"np": np}, optionflags=doctest.ELLIPSIS,
                             verbose=False, report=True)
    assert result.failed == 0, f"{name}: {result.failed} failing example(s)"
