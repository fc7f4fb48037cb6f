"""The committed Vitest fixtures (web/test/fixtures) still match the Python reference."""

import functools
import json
import os

import numpy as np
from web_fixture_writer import FOLDER
from web_fixture_writer import build as build_all


@functools.cache
def build():
    """The fixtures as the Python reference writes them today (built once for all tests)."""
    return build_all()


def test_committed_fixtures_match_the_python_reference():
    fresh = json.loads(build()["reference.json"])
    with open(os.path.join(FOLDER, "reference.json")) as file:
        committed = json.load(file)
    assert committed["times"] == fresh["times"]
    np.testing.assert_allclose(committed["values"], fresh["values"], atol=1e-6)  # float32 FFT
    assert len(committed["cases"]) == len(fresh["cases"])
    for old, new in zip(committed["cases"], fresh["cases"], strict=True):
        np.testing.assert_allclose(old["mapping"]["transfer"], new["mapping"]["transfer"])
        np.testing.assert_allclose(old["phi"], new["phi"], rtol=1e-5, atol=1e-6)
        # Positions do not depend on eigenvector signs; allow solver round-off.
        np.testing.assert_allclose(old["positions"], new["positions"], atol=1e-6)


def test_committed_rig_fixtures_match_the_python_reference():
    fresh = json.loads(build()["rig.json"])
    with open(os.path.join(FOLDER, "rig.json")) as file:
        committed = json.load(file)
    assert committed["times"] == fresh["times"]
    for old, new in zip(committed["cases"], fresh["cases"], strict=True):
        assert old["mapping"]["modes"] == new["mapping"]["modes"]
        for key in ("coefficients", "positions", "rotations", "centres"):
            np.testing.assert_allclose(old[key], new[key], atol=1e-6, err_msg=key)


def test_committed_rhythm_fixtures_match_the_python_reference():
    fresh = json.loads(build()["rhythm.json"])
    with open(os.path.join(FOLDER, "rhythm.json")) as file:
        committed = json.load(file)
    assert committed["times"] == fresh["times"]
    np.testing.assert_allclose(committed["beats"], fresh["beats"])
    for old, new in zip(committed["cases"] + committed["rig_cases"],
                        fresh["cases"] + fresh["rig_cases"], strict=True):
        assert old["mapping"]["envelope"] == new["mapping"]["envelope"]
        assert old["mapping"]["pulse"] == new["mapping"]["pulse"]
        for key in ("phi", "shaped", "coefficients"):
            if key in old:
                np.testing.assert_allclose(old[key], new[key], rtol=1e-5, atol=1e-6,
                                           err_msg=key)
