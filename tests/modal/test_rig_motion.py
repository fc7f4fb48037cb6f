"""One music pipeline for rigs (docs/design.md#modal-motion): coefficients from a Spectrogram and
a Mapping, the palette and its default rule, the song calibration, the rig as a gallery dancer."""

import dataclasses
import math

import numpy as np
import pytest

from eigendance.errors import EigendanceError
from eigendance.modal.model import ModalModel
from eigendance.modal.motion import default_mapping, rig_coefficients, song_calibrated
from eigendance.modal.palette import (
    COMBINED_BEND,
    MODE_BEND,
    MODE_SPREAD,
    TEMPO_BAND,
    default_palette,
    joint_bend,
    mode_reach,
    resolve_palette,
)
from eigendance.modal.rig import Rig
from eigendance.modal.rig_gallery import rig_gallery
from eigendance.modal.sample_rigs import load_rig, sample_rig
from eigendance.music.breeding import breed
from eigendance.music.dancer import full_scale_motion
from eigendance.music.gallery import initial_gallery
from eigendance.music.mapping import Mapping
from eigendance.music.mode_settings import ModeSettings
from eigendance.music.spectrogram import Spectrogram
from helpers import fixture_path


@pytest.fixture(scope="module")
def loop():
    return Rig.from_skeleton(sample_rig("loop16"))


@pytest.fixture(scope="module")
def song():
    return Spectrogram.from_file(fixture_path("audio", "kevin_macleod_vibe_ace_20s-24s.ogg"),
                                 bands=16)


def test_coefficients_follow_the_formula_band_by_band(loop, song, rng):
    """c_{κ_ν}(t) = φ_ν(t)·μ_ν·sin(2π ν_{κ_ν} s t + γ_ν) with φ_ν = gain·a_k(ν)·Σ_{ξ→ν} g̃ + b,
    written out with loops over bands here (the library uses one bincount). The model without
    its skin's floor, so the amplitudes given are the ones played (the floor: test_floor.py)."""
    model = dataclasses.replace(loop.model, floor=None)
    selected = [7, 2, 4]  # taken in ascending order: targets 0, 1, 2 are modes 2, 4, 7
    palette = ModeSettings(np.array(selected), np.array([0.3, 0.1, 0.2]),
                           np.array([0.5, 1.0, 2.0]), 1.7, "free")  # the thesis's motion
    mapping = Mapping(rng.uniform(0, 1, 16), rng.normal(size=5), gain=1.3, offset=0.25,
                      modes=palette)
    times = np.linspace(0, 3.9, 40)
    coefficients = rig_coefficients(model, song, mapping, times)
    order = np.argsort(selected)
    modes = np.array(selected)[order]
    amplitudes, phases = palette.amplitudes[order], palette.phases[order]
    reach = mode_reach(model)
    values = song.at(times)
    k = len(modes)
    for frame, t in enumerate(times):
        for target, mode in enumerate(modes):
            cell = min(4, int(math.floor((target + 0.5) * 5 / k)))
            total = sum(values[frame, band] for band in range(16)
                        if min(k - 1, int(math.floor(mapping.transfer[band] * k))) == target)
            phi = 1.3 * mapping.amplification[cell] * total + 0.25
            expected = phi * amplitudes[target] / reach[mode] * math.sin(
                2 * math.pi * model.frequencies[mode] * 1.7 * t + phases[target])
            assert coefficients[frame, mode] == pytest.approx(expected, rel=1e-9, abs=1e-12)
    others = np.setdiff1d(np.arange(model.n_modes), modes)
    assert np.all(coefficients[:, others] == 0)


def test_the_offset_decides_what_silence_does(loop, song):
    silent = Spectrogram(song.times, song.band_edges, np.zeros_like(song.values), song.rate,
                         song.sample_rate, song.duration)
    times = np.linspace(0.1, 3, 30)
    still = rig_coefficients(loop.model, silent, Mapping(np.full(16, 0.5), [1.0]), times)
    assert np.all(still == 0)  # b = 0: silence is the rest pose
    sway = rig_coefficients(loop.model, silent, Mapping(np.full(16, 0.5), [1.0], offset=1.0),
                            times)
    steady = rig_coefficients(loop.model, None, None, times)  # music off: φ ≡ 1
    np.testing.assert_allclose(sway, steady, rtol=1e-12)  # b = 1: the thesis's idle sway
    assert np.abs(steady).max() > 0


def test_a_saved_mapping_plays_the_same_motion(loop, song, tmp_path):
    mapping = song_calibrated(Mapping(np.linspace(0, 1, 16), [1.0, -0.5, 2.0], smoothing=0.3,
                                      modes=default_palette(loop.model).to_settings()),
                              song, len(default_palette(loop.model).selected))
    path = tmp_path / "m.json"
    mapping.save(path)
    times = np.linspace(0, 4, 33)
    np.testing.assert_array_equal(rig_coefficients(loop.model, song, Mapping.load(path), times),
                                  rig_coefficients(loop.model, song, mapping, times))


@pytest.mark.parametrize("name", ["loop4", "loop8", "loop16", "chain", "hand"])
def test_the_default_palette_follows_its_rule(name):
    model = ModalModel.from_skeleton(load_rig(name))
    palette = default_palette(model)
    chosen = model.frequencies[palette.selected]
    assert palette.selected.tolist() == list(range(len(chosen)))  # the lowest modes
    assert chosen.max() <= MODE_SPREAD * chosen.min() * (1 + 1e-12)
    played = chosen * palette.time_scale
    assert TEMPO_BAND[0] * (1 - 1e-9) <= played.min() and played.max() <= TEMPO_BAND[1] * (1 + 1e-9)
    if chosen.min() >= TEMPO_BAND[0] and chosen.max() <= TEMPO_BAND[1]:
        assert palette.time_scale == 1.0  # already dancing: natural time
    mu = palette.coefficient_amplitudes(model)
    bend = joint_bend(model)[:, palette.selected]
    alone = (bend * mu).max(axis=0)
    together = (bend * mu).sum(axis=1).max()
    assert together <= COMBINED_BEND * (1 + 1e-9)
    # Every mode alone bends its most bent joint equally: by MODE_BEND, or all scaled down
    # by the same factor so that together they reach COMBINED_BEND.
    np.testing.assert_allclose(alone, alone[0], rtol=1e-9)
    expected = MODE_BEND if together < COMBINED_BEND * (1 - 1e-9) else \
        MODE_BEND * COMBINED_BEND / (together / alone[0] * MODE_BEND)
    assert alone[0] == pytest.approx(expected, rel=1e-9)


def test_joint_bend_is_the_relative_rotation_of_the_two_bodies():
    """On the loop (revolute joints about z) the bend of joint j in mode κ is |ω_l − ω_i| (world
    rotation vectors per unit coefficient), with no sliding."""
    model = ModalModel.from_skeleton(sample_rig("loop8"))
    twists = model.modes.reshape(model.n_bodies, 6, -1)
    omega = np.einsum("bij,bjk->bik", model.body_rotations, twists[:, :3])
    first, second = model.joint_bodies.T
    expected = np.linalg.norm(omega[second] - omega[first], axis=1)
    np.testing.assert_allclose(joint_bend(model), expected, rtol=1e-12, atol=1e-12)  # 0 ± 1e-16


def test_song_calibration_drives_the_loudest_frame_at_one(song):
    for k in (1, 3, 8):
        mapping = default_mapping(song, k)
        phi = mapping.filter(mapping.shaped(song).values, k, offset=0.0)  # with its swell
        assert np.abs(phi).max() == pytest.approx(1.0, rel=1e-12)
    silent = Spectrogram(song.times, song.band_edges, np.zeros_like(song.values), song.rate,
                         song.sample_rate, song.duration)
    base = Mapping(np.full(16, 0.5), [2.0])
    assert song_calibrated(base, silent, 4).amplification.tolist() == [2.0]


def test_palette_errors_name_the_field(loop, song):
    with pytest.raises(EigendanceError, match="modes.selected names mode 99"):
        resolve_palette(loop.model, ModeSettings(selected=np.array([1, 99])))
    with pytest.raises(EigendanceError, match="modes.amplitudes has 1 values for 2"):
        resolve_palette(loop.model, ModeSettings(np.array([1, 2]), np.array([0.2])))
    with pytest.raises(EigendanceError, match="the mapping has 8 bands, the song's spectrogram 16"):
        rig_coefficients(loop.model, song, Mapping(np.full(8, 0.5), [1.0]), [0.0])
    rigid = Rig.from_skeleton(sample_rig("loop4").with_stiffness({}, scale=0.0)).model
    with pytest.raises(EigendanceError, match="no vibration mode"):
        rig_coefficients(rigid, None, None, [0.0])


def test_the_rig_is_a_gallery_dancer(loop, song):
    dancer = loop.dancer(band_edges=song.band_edges)
    k = len(loop.palette.selected)
    assert np.all(np.diff(dancer.frequencies) > 0)
    np.testing.assert_allclose(dancer.natural_frequencies,
                               loop.model.frequencies[loop.palette.selected])
    phi = np.eye(k)[:2] * 0.5
    moved = dancer.displacements(phi)
    coefficients = np.zeros((2, loop.model.n_modes))
    coefficients[:, loop.palette.selected] = phi * loop.palette.coefficient_amplitudes(loop.model)
    np.testing.assert_allclose(moved, loop.skin.positions(coefficients) - loop.skin.vertices)
    # The harmonic gallery's own code runs on it (calibration by displacement included).
    gallery = initial_gallery(dancer, song, size=6)
    assert len(gallery) == 6 and np.all(full_scale_motion(dancer, gallery) >= 0)
    # The direct transfer on ranked modes: bands in order onto modes in order, equal groups.
    items = rig_gallery(dancer, song, size=6)
    spread = items[1].harmonic_indices(k)
    assert np.all(np.diff(spread) >= 0) and set(spread.tolist()) == set(range(k))
    for item in items:  # each item's loudest frame drives its most driven mode at |φ| = 1
        assert np.abs(item.filter(song.values, k, offset=0.0)).max() == pytest.approx(1.0)
    children = breed(items[:3], size=4, seed=9)
    assert len(children) == 4 and all(c.bands == 16 for c in children)
