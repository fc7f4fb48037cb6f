"""Helpers of the export tests: the test song, rigs that dance to it, position checks."""

from __future__ import annotations

import os

import numpy as np
import pytest

from eigendance.export.dance import rig_dance
from eigendance.modal.model import ModalModel
from eigendance.modal.motion import band_mapping, rig_coefficients, rig_mapping
from eigendance.modal.sample_rigs import load_rig
from helpers import fixture_path

SONG = fixture_path("audio", "kevin_macleod_vibe_ace_20s-24s.ogg")  # 4 s
LONG_SONG = fixture_path("audio", "kevin_macleod_vibe_ace_0s-21s.ogg")  # 21 s


def required(what: str, present: bool, how: str) -> None:
    """Skip without `what`, but fail under CI, which must run every check."""
    if not present:
        message = f"{what} is not installed ({how})"
        if os.environ.get("CI"):
            pytest.fail(message)
        pytest.skip(message)


def rig(name: str, skinning: str, song, mode_count: int = 4, audio: str = SONG):
    skeleton = load_rig(name)
    model = ModalModel.from_skeleton(skeleton)
    modes = np.arange(min(mode_count, model.n_modes))
    mapping = rig_mapping(model, song, band_mapping(song.bands, len(modes)), modes, 0.3, 1.0)
    return rig_dance(skeleton, model, song.duration,
                     lambda times: rig_coefficients(model, song, mapping, times),
                     skinning, audio, f"{skinning}-rig")


def check_positions(found, expected, diagonal, tolerance=1e-4, what="positions"):
    """Every frame and vertex within tolerance·diagonal."""
    found, expected = np.asarray(found), np.asarray(expected)
    assert found.shape == expected.shape, (found.shape, expected.shape)
    error = np.linalg.norm(found - expected, axis=-1).max(axis=-1) / diagonal
    assert np.all(error <= tolerance), f"{what}: relative errors per frame {error}"
    print(f"{what}: largest error {error.max():.1e} of the diagonal over {len(error)} frames")
    return error


def spread_frames(count: int, frames: int = 6) -> list[int]:
    """`frames` sample indices spread over `count` samples, first and last included."""
    return sorted({int(round(i)) for i in np.linspace(0, count - 1, frames)})
