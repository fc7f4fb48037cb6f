"""The rig gallery offers dances that differ (issue 22): every pair of items of every built-in
rig's gallery moves differently, on real recordings and on the demo track.

The motion is measured independently of how the gallery is built: each item's mode
coefficients c(t) come from `rig_coefficients` (the definition of rig motion that the page,
the command line and the exports reproduce) at every spectrogram frame, and its displacement
field from the modal skin, d(t) = Σ_κ c_κ(t) τ_κ. Two items s, r correlate
Σ_t ⟨d_s, d_r⟩ / √(Σ_t |d_s|² Σ_t |d_r|²) (with ⟨d_s, d_r⟩ = c_sᵀ (T Tᵀ) c_r, T the skin's
displacement per unit coefficient, (modes, 3n)).

The bound √(2/3) ≈ 0.816 is the one the mesh gallery promises for its items that share
harmonics (docs/design.md#gallery: two signed combinations correlate at most √(2/3) when the
loudness is alike): no two rig dances may move more alike than that. Before issue 22, loop4's
(one mode) eight items were one dance, correlation 1.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest

from eigendance.modal.motion import rig_coefficients
from eigendance.modal.palette import DANCE_BAND
from eigendance.modal.rig import Rig
from eigendance.modal.rig_gallery import rig_gallery
from eigendance.modal.sample_rigs import SAMPLE_RIGS, sample_rig
from eigendance.music.demo_music import demo_track
from eigendance.music.spectrogram import Spectrogram
from helpers import fixture_path

BOUND = math.sqrt(2 / 3)
SONGS = ["kevin_macleod_vibe_ace_20s-24s.ogg", "sorohanro_solo_trumpet_06.ogg", "demo"]


@pytest.fixture(scope="module")
def songs():
    found = {name: Spectrogram.from_file(fixture_path("audio", name)) for name in SONGS[:2]}
    samples, rate = demo_track(30.0)
    found["demo"] = Spectrogram.from_samples(samples, rate)
    return found


@pytest.fixture(scope="module")
def rigs():
    return {name: Rig.from_skeleton(sample_rig(name), dtype=np.float64) for name in SAMPLE_RIGS}


def correlations(rig: Rig, spectrogram: Spectrogram, items) -> tuple[np.ndarray, np.ndarray]:
    """(|correlation| (S, S) of the items' displacement fields over the song, RMS motion (S,))."""
    coefficients = np.stack([rig_coefficients(rig.model, spectrogram, item, spectrogram.times)
                             for item in items])  # (S, T, modes)
    gram = rig.skin.displacement @ rig.skin.displacement.T
    flat = coefficients.reshape(len(items), -1)
    inner = (coefficients @ gram).reshape(len(items), -1) @ flat.T
    energy = np.sqrt(np.diag(inner))
    return np.abs(inner) / np.outer(energy, energy).clip(1e-300), energy


@pytest.mark.parametrize("size", [8, 16])
@pytest.mark.parametrize("song", SONGS)
def test_every_pair_of_dances_of_every_built_in_rig_differs(rigs, songs, song, size):
    spectrogram = songs[song]
    for name, rig in rigs.items():
        items = rig_gallery(rig.dancer(band_edges=spectrogram.band_edges), spectrogram, size)
        corr, energy = correlations(rig, spectrogram, items)
        assert np.all(energy > 0), f"{name} × {song}: items {np.flatnonzero(energy == 0)} " \
            "do not move"
        for s, r in itertools.combinations(range(size), 2):
            assert corr[s, r] < BOUND, f"{name} × {song}: items {s + 1} and {r + 1} correlate " \
                f"{corr[s, r]:.3f}"


def test_each_dance_plays_within_the_dancing_band(rigs, songs):
    """The items' own tempos keep every selected mode in DANCE_BAND; item 0 is the default."""
    spectrogram = songs["demo"]
    for name, rig in rigs.items():
        items = rig_gallery(rig.dancer(band_edges=spectrogram.band_edges), spectrogram, 16)
        assert items[0].modes.time_scale == pytest.approx(rig.palette.time_scale)
        natural = rig.model.frequencies[rig.palette.selected]
        for item in items:
            played = item.modes.time_scale * natural
            assert DANCE_BAND[0] - 1e-9 <= played.min() and played.max() <= DANCE_BAND[1] + 1e-9, \
                f"{name}: {played}"
            assert list(item.modes.selected) == list(rig.palette.selected)
        assert len({round(item.modes.time_scale, 6) for item in items}) == len(items)
