"""Motion that reads as dancing by default, on any rig (docs/design.md#modal-motion).

For every fixture rig and built-in rig, with every fixture song and the demo track, the default
motion (`rig_coefficients` without a mapping) must have, at the song's loud moments:
- a dominant frequency of the bodies' motion in 0.5–4 Hz: the peak of the power spectrum of
  the bodies' rotation angles over time (rotation vectors relative to the rest pose, taken from
  the posed rotation matrices, summed over bodies and axes);
- a largest joint rotation in 5°–45°: the angle of the relative rotation between the two bodies
  of each joint, measured against the rest pose, over the loud frames (mean loudness in the top
  quarter of the song's frames); never above 45° at any frame.
Every initial-gallery item stays within 45° too.
"""

import dataclasses
import glob
import os

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from eigendance.modal.model import ModalModel
from eigendance.modal.motion import body_poses, rig_coefficients
from eigendance.modal.palette import DANCE_BAND, default_amplitudes
from eigendance.modal.rig import Rig
from eigendance.modal.rig_gallery import rig_gallery
from eigendance.modal.sample_rigs import SAMPLE_RIGS, load_rig
from eigendance.music.demo_music import demo_track
from eigendance.music.spectrogram import Spectrogram
from helpers import fixture_path

FPS = 50.0
FIXTURE_RIGS = sorted(os.path.basename(p) for p in glob.glob(fixture_path("rigged", "*.gl*")))
RIGS = list(SAMPLE_RIGS) + FIXTURE_RIGS
SONGS = ["kevin_macleod_vibe_ace_20s-24s.ogg", "sorohanro_solo_trumpet_06.ogg", "demo"]


@pytest.fixture(scope="module")
def songs():
    found = {name: Spectrogram.from_file(fixture_path("audio", name)) for name in SONGS[:2]}
    samples, rate = demo_track(8.0)
    found["demo"] = Spectrogram.from_samples(samples, rate)
    return found


@pytest.fixture(scope="module")
def rigs():
    return {}


def rig_of(rigs, name) -> Rig:
    if name not in rigs:
        rigs[name] = Rig.from_skeleton(load_rig(name if name in SAMPLE_RIGS
                                                else fixture_path("rigged", name)))
    return rigs[name]


def relative_angles(rotations: np.ndarray, rest: np.ndarray) -> np.ndarray:
    """(T, n, 3, 3) rotations against (n, 3, 3) rest → (T, n, 3) rotation vectors of restᵀR."""
    relative = np.einsum("bji,tbjk->tbik", rest, rotations)
    vectors = Rotation.from_matrix(relative.reshape(-1, 3, 3)).as_rotvec()
    return vectors.reshape(relative.shape[:2] + (3,))


def dominant_frequency(angles: np.ndarray, rate: float) -> float:
    """Peak of the summed power spectrum of (T, n, 3) angle signals (Hann window, zero padded
    to 8× for a finer grid), Hz, DC excluded."""
    signal = angles - angles.mean(axis=0)
    window = np.hanning(len(signal))[:, None, None]
    size = 8 * len(signal)
    power = (np.abs(np.fft.rfft(signal * window, n=size, axis=0)) ** 2).sum(axis=(1, 2))
    frequencies = np.fft.rfftfreq(size, 1 / rate)
    return float(frequencies[1:][np.argmax(power[1:])])


def joint_angles(model: ModalModel, rotations: np.ndarray) -> np.ndarray:
    """(T,) the largest joint rotation per frame, degrees."""
    first, second = model.joint_bodies.T
    rest = np.einsum("jba,jbc->jac", model.body_rotations[first], model.body_rotations[second])
    now = np.einsum("tjba,tjbc->tjac", rotations[:, first], rotations[:, second])
    change = np.einsum("jba,tjbc->tjac", rest, now)
    angles = Rotation.from_matrix(change.reshape(-1, 3, 3)).magnitude()
    return np.degrees(angles.reshape(len(rotations), -1)).max(axis=1)


def floor_bound(rig) -> bool:
    """Whether the floor scaled the default palette down (below the joint bends' rule)."""
    palette = rig.palette
    return bool(np.any(palette.amplitudes < 0.999 * default_amplitudes(
        dataclasses.replace(rig.model, floor=None), palette.selected)))


def loud_frames(spectrogram: Spectrogram, times: np.ndarray) -> np.ndarray:
    loudness = spectrogram.at(times).mean(axis=1)
    return loudness >= np.percentile(loudness, 75)


@pytest.mark.parametrize("rig_name", RIGS)
def test_the_default_motion_dances_on_every_rig_and_song(rig_name, rigs, songs):
    rig = rig_of(rigs, rig_name)
    for song_name, spectrogram in songs.items():
        times = np.arange(0, spectrogram.duration, 1 / FPS)
        rotations, _ = body_poses(rig.model, rig_coefficients(rig.model, spectrogram, None, times))
        frequency = dominant_frequency(relative_angles(rotations, rig.model.body_rotations), FPS)
        angles = joint_angles(rig.model, rotations)
        loud = loud_frames(spectrogram, times)
        where = f"{rig_name} × {song_name}"
        assert DANCE_BAND[0] <= frequency <= DANCE_BAND[1], f"{where}: {frequency:.2f} Hz"
        # At least 5° unless the floor holds the rig back (docs/design.md#the-floor).
        low = 5.0 if not floor_bound(rig) else 1.0
        assert low <= angles[loud].max() <= 45.0, f"{where}: {angles[loud].max():.1f}°"
        assert angles.max() <= 45.0, f"{where}: {angles.max():.1f}° at some frame"


@pytest.mark.parametrize("rig_name", ["hand", "loop16", "Fox.glb", "quaternius_men_Casual.glb"])
def test_every_initial_gallery_item_stays_within_45_degrees(rig_name, rigs, songs):
    rig = rig_of(rigs, rig_name)
    spectrogram = songs["demo"]
    times = np.arange(0, spectrogram.duration, 1 / FPS)
    items = rig_gallery(rig.dancer(band_edges=spectrogram.band_edges), spectrogram, 8)
    moving = 0
    for item in items:
        rotations, _ = body_poses(rig.model, rig_coefficients(rig.model, spectrogram, item,
                                                              times))
        largest = joint_angles(rig.model, rotations).max()
        assert largest <= 45.0, f"{rig_name}, {item.name}: {largest:.1f}°"
        moving += largest > 1.0
    assert moving == len(items)  # every tile moves
