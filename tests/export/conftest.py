"""Small dances for the export tests: a bumpy sphere by its harmonics, rigs by their modes."""

from __future__ import annotations

import numpy as np
import pytest
from helpers import bumpy_sphere, fixture_path

from eigendance.export.dance import HarmonicDance, rig_dance
from eigendance.harmonic.basis import HarmonicBasis
from eigendance.harmonic.mesh import Mesh
from eigendance.modal.model import ModalModel
from eigendance.modal.motion import band_mapping, mode_drive
from eigendance.modal.sample_rigs import load_rig
from eigendance.music.gallery import initial_gallery
from eigendance.music.spectrogram import Spectrogram

SONG = fixture_path("audio", "kevin_macleod_vibe_ace_20s-24s.ogg")  # 4 s


@pytest.fixture(scope="session")
def song():
    return Spectrogram.from_file(SONG)


@pytest.fixture(scope="session")
def basis():
    # Moved 3 units off the origin and scaled: exports are in the file's coordinates.
    mesh = bumpy_sphere(2)
    moved = Mesh.from_arrays(mesh.original_vertices * 2.5 + [3.0, -1.0, 0.5], mesh.faces)
    return HarmonicBasis.from_mesh(moved, 40, cache=False)


@pytest.fixture(scope="session")
def mappings(basis, song):
    return initial_gallery(basis, song, 4)


@pytest.fixture(scope="session")
def harmonic(basis, song, mappings):
    mapping = mappings[1]
    mapping.gain, mapping.smoothing = 1.5, 0.05  # both must reach the exports
    return HarmonicDance(basis, song, mapping, audio=SONG, name="sphere")


def rig(name: str, skinning: str, song, mode_count: int = 4):
    skeleton = load_rig(name)
    model = ModalModel.from_skeleton(skeleton)
    modes = np.arange(min(mode_count, model.n_modes))
    mapping = band_mapping(song.bands, len(modes))
    return rig_dance(skeleton, model, modes, song.duration,
                     lambda times: mode_drive(mapping, song, times, len(modes)), 0.3, 1.0,
                     skinning, SONG, f"{skinning}-rig")


@pytest.fixture(scope="session")
def chain_lbs(song):
    return rig("chain", "lbs", song)


@pytest.fixture(scope="session")
def figure_modal(song):
    return rig(fixture_path("rigged", "RiggedFigure.glb"), "modal", song)


def check_positions(found, expected, diagonal, tolerance=1e-4, what="positions"):
    """Every frame and vertex within tolerance·diagonal."""
    found, expected = np.asarray(found), np.asarray(expected)
    assert found.shape == expected.shape, (found.shape, expected.shape)
    error = np.linalg.norm(found - expected, axis=-1).max(axis=-1) / diagonal
    assert np.all(error <= tolerance), f"{what}: relative errors per frame {error}"
    return error
