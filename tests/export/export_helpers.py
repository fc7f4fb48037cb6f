"""Helpers of the export tests: the test song, rigs that dance to it, position checks."""

from __future__ import annotations

import os

import numpy as np
import pytest

from eigendance.export.dance import rig_dance
from eigendance.modal.motion import band_mapping
from eigendance.modal.rig import Rig
from eigendance.modal.sample_rigs import load_rig
from helpers import fixture_path

SONG = fixture_path("audio", "kevin_macleod_vibe_ace_20s-24s.ogg")  # 4 s


def required(what: str, present: bool, how: str) -> None:
    """Skip without `what`, but fail under CI, which must run every check."""
    if not present:
        message = f"{what} is not installed ({how})"
        if os.environ.get("CI"):
            pytest.fail(message)
        pytest.skip(message)


def rig(name: str, skinning: str, song, mode_count: int = 4):
    dancer = Rig(load_rig(name), np.float64)
    modes = np.arange(min(mode_count, dancer.model.n_modes))
    mapping = dancer.mapping(song, band_mapping(song.bands, len(modes)), selected=modes,
                             amplitude=0.3, time_scale=1.0)
    return rig_dance(dancer, song, mapping, skinning, SONG, f"{skinning}-rig")


def check_positions(found, expected, diagonal, tolerance=1e-4, what="positions"):
    """Every frame and vertex within tolerance·diagonal."""
    found, expected = np.asarray(found), np.asarray(expected)
    assert found.shape == expected.shape, (found.shape, expected.shape)
    error = np.linalg.norm(found - expected, axis=-1).max(axis=-1) / diagonal
    assert np.all(error <= tolerance), f"{what}: relative errors per frame {error}"
    return error
