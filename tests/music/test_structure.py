"""The rhythm on real recordings against librosa's default call, bars (meter and phase) and
sections (docs/design.md#rhythm)."""

from dataclasses import replace

import librosa
import mir_eval
import numpy as np
import pytest

from eigendance.errors import InputError
from eigendance.modal.model import ModalModel
from eigendance.modal.motion import mode_coefficients, tempo_lock
from eigendance.modal.sample_rigs import sample_rig
from eigendance.music.decode import read_audio
from eigendance.music.mapping import Mapping
from eigendance.music.rhythm import Rhythm, beat_phase
from eigendance.music.spectrogram import Spectrogram
from eigendance.music.structure import bar_scores
from helpers import fixture_path

SR = 22050
REAL = [fixture_path("audio", "emegeme_country_20s-45s.ogg"),  # CC0, 25 s
        fixture_path("audio", "kevin_macleod_vibe_ace_0s-21s.ogg")]  # CC BY 3.0, 21 s


def at_22050(path):
    samples, rate = read_audio(path)
    return librosa.resample(samples, orig_sr=rate, target_sr=SR)


def beat_f(reference, estimate):
    return mir_eval.beat.f_measure(mir_eval.beat.trim_beats(np.asarray(reference)),
                                   mir_eval.beat.trim_beats(np.asarray(estimate)))


@pytest.mark.parametrize("path", REAL)
def test_real_recordings_have_librosas_tempo_and_beats(path):
    """The reference is `librosa.beat.beat_track(y=y, sr=22050)` with its defaults."""
    tempo, beats = librosa.beat.beat_track(y=at_22050(path), sr=SR, units="time")
    tempo = float(np.ravel(tempo)[0])
    rhythm = Spectrogram.from_file(path, bands=16).rhythm
    assert abs(rhythm.tempo - tempo) <= 0.04 * tempo
    assert beat_f(beats, rhythm.beats) >= 0.9
    assert rhythm.meter in (3, 4)
    index = np.searchsorted(rhythm.beats, rhythm.downbeats)
    np.testing.assert_array_equal(np.diff(index), rhythm.meter)  # every m-th beat


def test_sections_find_where_two_real_songs_are_joined():
    first, second = (at_22050(path) for path in REAL)
    joined = np.concatenate([first, second])
    rhythm = Spectrogram.from_samples(joined, SR, bands=16).rhythm
    join = len(first) / SR
    assert len(rhythm.sections) >= 1
    assert np.min(np.abs(rhythm.sections - join)) <= 3.0, (join, rhythm.sections)


def tone(frequency, seconds, level):
    t = np.arange(int(seconds * SR)) / SR
    return level * np.sin(2 * np.pi * frequency * t) * np.exp(-t / 0.25)


def bars_piece(meter, bpm=120.0, bars=12, first=0.5):
    """A bass note on every downbeat, a chord on every beat, the chord changing with the bar."""
    period = 60 / bpm
    beats = first + period * np.arange(meter * bars)
    track = np.zeros(int((beats[-1] + 1) * SR))
    chords = ([261.6, 329.6, 392.0], [220.0, 261.6, 329.6], [174.6, 220.0, 261.6],
              [196.0, 246.9, 293.7])
    for i, b in enumerate(beats):
        start = int(round(b * SR))
        chord = chords[(i // meter) % len(chords)]
        sound = sum(tone(f, period, 0.15) for f in chord)
        if i % meter == 0:
            sound = sound + tone(chord[0] / 4, period, 0.6)
        track[start:start + len(sound)] += sound[:len(track) - start]
    return track, beats, beats[::meter]


@pytest.mark.parametrize("meter", [3, 4])
def test_bars_find_the_meter_and_phase_of_a_piece(meter):
    """A code path check on a synthesised piece with known bars: the meter, and downbeat F."""
    samples, beats, downbeats = bars_piece(meter)
    rhythm = Spectrogram.from_samples(samples, SR, bands=16).rhythm
    assert beat_f(beats, rhythm.beats) >= 0.85
    assert rhythm.meter == meter
    assert beat_f(downbeats, rhythm.downbeats) >= 0.8


def test_bar_scores_by_hand():
    """Accents 1, 0, 0 repeated: phase 0 of meter 3 stands out; meter 4 mixes them."""
    accent = np.tile([1.0, 0.0, 0.0], 8) + np.linspace(0, 0.01, 24)
    scores = bar_scores(accent)
    assert max(scores, key=scores.get) == (3, 0)
    assert scores[3, 0] > 10 and abs(scores[4, 0]) < 3


def test_downbeats_and_sections_round_trip_and_old_files_load(tmp_path):
    samples, _, _ = bars_piece(3, bars=16)
    song = Spectrogram.from_samples(samples, SR, bands=16)
    song.save(tmp_path / "s.npz")
    loaded = Spectrogram.load(tmp_path / "s.npz")
    np.testing.assert_array_equal(loaded.rhythm.downbeats, song.rhythm.downbeats)
    np.testing.assert_array_equal(loaded.rhythm.sections, song.rhythm.sections)
    assert loaded.rhythm.meter == 3
    with np.load(tmp_path / "s.npz") as data:  # a version-2 file from before sections
        arrays = {key: data[key] for key in data.files if key != "sections"}
    np.savez(tmp_path / "older.npz", **arrays)
    assert len(Spectrogram.load(tmp_path / "older.npz").rhythm.sections) == 0
    assert np.all(np.isfinite(beat_phase(song.rhythm.beats, [0.0, 5.0])))


def test_the_rig_lock_accents_each_bars_first_beat():
    """A locked sway's turning points fall on the beats (|sin| = 1 there); on a bar's first
    beat it reaches a quarter further (docs/design.md#tempo-lock): the motion's magnitude at the
    downbeats over that at the other beats is 1.25, on a song with hand-placed beats in 3."""
    song = Spectrogram.from_samples(np.zeros(SR * 8), SR, bands=16)
    beats = 0.5 + 0.5 * np.arange(14)  # 120 BPM
    song.rhythm = replace(song.rhythm, beats=beats, tempo=120.0, downbeats=beats[1::3])
    model = ModalModel.from_skeleton(sample_rig("loop8"))
    c = mode_coefficients(model, beats, beat=tempo_lock(song, None, beats))
    magnitude = np.abs(c).max(axis=1)
    down = np.isin(beats, beats[1::3])
    assert magnitude[~down].min() > 0
    np.testing.assert_allclose(magnitude[down] / magnitude[~down].mean(), 1.25, rtol=1e-9)
    np.testing.assert_allclose(magnitude[~down], magnitude[~down].mean(), rtol=1e-9)
    # half a beat from a downbeat: 1 + ¼·cos²(π/4) = 1.125 of the free amplitude
    half = beats[4] + 0.25
    accent = tempo_lock(song, None, [half])[2]
    np.testing.assert_allclose(accent, [1.125], rtol=1e-12)


def test_a_section_gene_scales_the_dance_per_part_and_old_mappings_play_as_before():
    """g(t) = sections[s mod n], s the section starts ≤ t: φ − b = g·(φ without the gene − b),
    by hand on a song whose parts start at 2 s and 4 s (three parts, a two-factor gene)."""
    rate = 100.0
    values = np.random.default_rng(3).random((601, 4)).astype(np.float32)
    song = Spectrogram(np.arange(601) / rate, [20.0, 200.0, 2000.0, 5000.0, 10000.0], values,
                       rate, 22050, 6.0)
    song.rhythm = Rhythm(np.zeros(601), np.zeros(0), np.zeros(0), 0.0, rate,
                         sections=np.array([2.0, 4.0]))
    plain = Mapping([0.1, 0.4, 0.6, 0.9], [1.0, -2.0, 0.5], offset=0.3)
    gene = replace(plain, sections=(0.5, 2.0))
    times = np.array([0.5, 1.99, 2.0, 3.5, 4.5, 5.9])
    factor = np.array([0.5, 0.5, 2.0, 2.0, 0.5, 0.5])  # parts 0, 1, 2 → 0.5, 2, 0.5 (cycled)
    without = plain.play(song, times, 3, offset=0.3)
    np.testing.assert_allclose(gene.play(song, times, 3, offset=0.3) - 0.3,
                               factor[:, None] * (without - 0.3), rtol=1e-12, atol=1e-12)
    # round trip; a document without the field (every file written before it) plays as before
    document = gene.to_json()
    assert document["sections"] == [0.5, 2.0] and "sections" not in plain.to_json()
    assert Mapping.from_json(document).to_json() == document
    np.testing.assert_array_equal(Mapping.from_json(plain.to_json()).play(song, times, 3),
                                  plain.play(song, times, 3))
    # a song without sections: g ≡ 1
    bare = replace(song, rhythm=replace(song.rhythm, sections=np.zeros(0)))
    np.testing.assert_array_equal(gene.play(bare, times, 3), plain.play(bare, times, 3))
    for bad in ([], [-1.0], [11.0], ["x"], [1.0] * 65):
        with pytest.raises(InputError, match="sections"):
            Mapping.from_json({**document, "sections": bad})
