"""The committed Vitest fixtures (web/test/fixtures) still match the Python reference: the
numbers (JSON) and the binary bundles (.bin), regenerated and compared."""

import functools
import json
import os

import numpy as np
import pytest
from web_fixture_writer import FOLDER
from web_fixture_writer import build as build_all

from eigendance.server.binary import unpack


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


def test_committed_live_fixture_matches_the_python_reference():
    """live.json: the offline spectrogram and onset envelope that Vitest holds the live
    analysis (web/src/live-analysis.ts) to, at 44.1, 48 and 96 kHz."""
    fresh = json.loads(build()["live.json"])
    with open(os.path.join(FOLDER, "live.json")) as file:
        committed = json.load(file)
    for old, new in zip(committed["cases"], fresh["cases"], strict=True):
        assert old["sample_rate"] == new["sample_rate"] and old["frames"] == new["frames"]
        for key in ("values", "onset", "edges"):
            np.testing.assert_allclose(old[key], new[key], rtol=1e-5, atol=2e-6, err_msg=key)


# Axes along which a regenerated bundle may differ by sign: an eigenvector (a harmonic, a
# vibration mode) is defined up to its sign, and the solver's choice follows round-off.
SIGNED = {"harmonics": -1, "coefficients": 0, "tau": None, "rho": None, "body_twists": 0}


def same_numbers(old, new, where: str) -> None:
    """Meta documents equal, floats to round-off (1e-9 relative)."""
    if isinstance(old, dict):
        assert isinstance(new, dict) and set(old) == set(new), f"{where}: keys {old} {new}"
        for key in old:
            same_numbers(old[key], new[key], f"{where}.{key}")
    elif isinstance(old, list):
        assert isinstance(new, list) and len(old) == len(new), where
        for index, (a, b) in enumerate(zip(old, new, strict=True)):
            same_numbers(a, b, f"{where}[{index}]")
    elif isinstance(old, float):
        assert new == pytest.approx(old, rel=1e-9, abs=1e-12), where
    else:
        assert old == new, where


def aligned(old: np.ndarray, new: np.ndarray, name: str) -> np.ndarray:
    """`new` with each eigenvector's sign turned to match `old` (SIGNED)."""
    if name not in SIGNED:
        return new
    if SIGNED[name] is None:  # (n, G, 3, 4): mode 4g + j is [:, g, :, j]
        signs = np.sign(np.einsum("igdj,igdj->gj", old, new))
        return new * np.where(signs == 0, 1, signs)[None, :, None, :]
    axis = SIGNED[name] % new.ndim
    moved_old, moved_new = np.moveaxis(old, axis, 0), np.moveaxis(new, axis, 0)
    signs = np.sign(np.sum(moved_old.reshape(len(moved_old), -1)
                           * moved_new.reshape(len(moved_new), -1), axis=1))
    shape = [1] * new.ndim
    shape[axis] = -1
    return new * np.where(signs == 0, 1, signs).reshape(shape)


@pytest.mark.parametrize("name", ["basis.bin", "basis16.bin", "spectrogram.bin", "rig.bin",
                                  "rhythm.bin"])
def test_committed_bundles_are_what_python_writes_today(name):
    """The binary bundles the Vitest tests parse, regenerated: the same arrays (names, shapes,
    dtypes; values to float32 round-off, eigenvectors up to their sign) and the same meta. A
    change of the bundle format or of the Python reference fails here until `python
    tests/web/web_fixture_writer.py` rewrites them."""
    fresh_meta, fresh = unpack(build()[name])
    with open(os.path.join(FOLDER, name), "rb") as file:
        meta, arrays = unpack(file.read())
    same_numbers(meta, fresh_meta, name)
    assert sorted(arrays) == sorted(fresh), f"{name}: arrays {sorted(arrays)} ≠ {sorted(fresh)}"
    half = name == "basis16.bin"
    for key, old in arrays.items():
        new = fresh[key]
        assert (old.dtype, old.shape) == (new.dtype, new.shape), f"{name}: {key}"
        new = aligned(old.astype(np.float64), new.astype(np.float64), key)
        scale = max(1.0, float(np.abs(old).max(initial=0.0)))
        np.testing.assert_allclose(old, new, rtol=0, atol=(2e-3 if half else 1e-6) * scale,
                                   err_msg=f"{name}: {key}")
