"""Rhythm (docs/design.md#rhythm): beats and onsets of synthesized tracks with exactly known
beats, scored with mir_eval; the spectrogram file v2; bad input; the envelope and the pulse of
mapping v3 against hand-derived numbers; the rig dance locked to the beats."""

import math
import os
from dataclasses import replace
from types import SimpleNamespace

import librosa
import mir_eval
import numpy as np
import pytest
import soundfile
from scipy.signal import find_peaks

from eigendance.cli import main
from eigendance.errors import EigendanceError
from eigendance.export.rig_dance import rig_dance
from eigendance.modal.motion import rig_coefficients, twists
from eigendance.modal.palette import lock_ratios, locked_phases
from eigendance.modal.rig import Rig
from eigendance.modal.sample_rigs import sample_rig
from eigendance.music.envelope import Envelope, Pulse, shape_values
from eigendance.music.mapping import Mapping
from eigendance.music.mode_settings import ModeSettings
from eigendance.music.rhythm import Rhythm
from eigendance.music.spectrogram import Spectrogram
from helpers import fixture_path

SR = 22050
KICK_MP3 = fixture_path("audio", "beatnet_808kick120bpm.mp3")  # a real kick track, 120 BPM
GUITAR_192K = fixture_path("audio", "florianreichelt_mysterious_acoustic_guitar.ogg")  # 192 kHz


def beat_times(seconds, bpm_start, bpm_end=None, first=0.2):
    """Beats from `first` with the tempo moving linearly from bpm_start to bpm_end."""
    bpm_end = bpm_start if bpm_end is None else bpm_end
    times, t = [], first
    while t < seconds - 0.3:
        times.append(t)
        t += 60 / (bpm_start + (bpm_end - bpm_start) * t / seconds)
    return np.array(times)


def place(track, at, sound):
    i = int(round(at * SR))
    track[i:i + len(sound)] += sound[:max(0, len(track) - i)]


def click():
    return np.random.default_rng(1).normal(0, 0.6, 200) * np.exp(-np.arange(200) / 40)


def kick():
    t = np.arange(int(0.25 * SR)) / SR
    return 0.9 * np.sin(2 * np.pi * (50 * t + 60 * (1 - np.exp(-t / 0.03)))) * np.exp(-t / 0.08)


def snare():
    return np.random.default_rng(2).normal(0, 0.4, 3000) * np.exp(-np.arange(3000) / 600)


def hat():
    noise = np.random.default_rng(3).normal(0, 0.15, 800)
    return np.diff(noise, prepend=0) * np.exp(-np.arange(800) / 150)


def drum_track(beats, syncopated=False):
    """Kick on 1 and 3, snare on 2 and 4, hats on the off-beats (and, syncopated, the kick also
    on the 'and' of 2 and the bass of the bar on the 'and' of 4), placed on the given beats."""
    track = np.zeros(int((beats[-1] + 1.0) * SR))
    for i, b in enumerate(beats):
        place(track, b, kick() if i % 2 == 0 else snare())
        period = (beats[i + 1] - b) if i + 1 < len(beats) else beats[-1] - beats[-2]
        place(track, b + period / 2, hat())
        if syncopated and i % 4 in (1, 3):
            place(track, b + period / 2, 0.6 * kick())
    return track


def tracks():
    beats = beat_times(12, 100)
    clicks = np.zeros(int(12 * SR))
    for b in beats:
        place(clicks, b, click())
    kicks_beats = beat_times(12, 128)
    kicks = np.zeros(int(12 * SR))
    for b in kicks_beats:
        place(kicks, b, kick())
    drift = beat_times(20, 105, 128)
    steady = beat_times(14, 112)
    return {"clicks 100 BPM": (clicks, beats),
            "kicks 128 BPM": (kicks, kicks_beats),
            "drum loop drifting 105 → 128 BPM": (drum_track(drift), drift),
            "syncopated drum loop 112 BPM": (drum_track(steady, syncopated=True), steady)}


@pytest.fixture(scope="module")
def analysed():
    return {name: (Spectrogram.from_samples(samples, SR, bands=16), beats)
            for name, (samples, beats) in tracks().items()}


def beat_f(reference, estimate):
    return mir_eval.beat.f_measure(mir_eval.beat.trim_beats(reference),
                                   mir_eval.beat.trim_beats(np.asarray(estimate)))


def librosa_default(samples):
    """The reference: librosa.beat.beat_track(y=y, sr=22050) with its defaults."""
    tempo, beats = librosa.beat.beat_track(y=np.asarray(samples, dtype=np.float32), sr=SR,
                                           units="time")
    return float(np.ravel(tempo)[0]), beats


def test_beats_are_librosas_default_call_and_hit_clicks_and_kicks(analysed):
    """Every track's beats and tempo are those of librosa's default call (a tracker's own
    behaviour included: it counts the drum loops' eighth notes); on clicks and kicks they hit
    the known beats."""
    for name, (song, _) in analysed.items():
        rhythm = song.rhythm
        assert rhythm.has_beats, name
        tempo, beats = librosa_default(tracks()[name][0])
        assert abs(rhythm.tempo - tempo) <= 0.04 * tempo, name
        assert beat_f(beats, rhythm.beats) >= 0.99, name
        assert np.all(np.isfinite(rhythm.onset_strength)) and len(rhythm.onset_strength) == \
            len(song.times)
        onsets = librosa.onset.onset_detect(y=tracks()[name][0].astype(np.float32), sr=SR,
                                            units="time")  # librosa's defaults
        assert mir_eval.onset.f_measure(onsets, rhythm.onsets, window=0.02)[0] >= 0.99, name
    for name in ("clicks 100 BPM", "kicks 128 BPM"):
        song, beats = analysed[name]
        assert beat_f(beats, song.rhythm.beats) >= 0.9, name
        assert abs(song.rhythm.tempo - float(name.split()[1])) < 3, name
    song, beats = analysed["clicks 100 BPM"]  # one onset per click, nothing else
    assert mir_eval.onset.f_measure(beats, song.rhythm.onsets, window=0.05)[0] >= 0.95


def test_tempo_over_time_follows_a_drift(analysed):
    """At the tracker's metrical level (librosa counts this loop's eighth notes: level 2)."""
    song, beats = analysed["drum loop drifting 105 → 128 BPM"]
    early, late = song.rhythm.tempo_curve([4.0, 17.0])
    truth = 60 / np.diff(beats)
    level = round(song.rhythm.tempo / np.median(truth))
    assert level in (1, 2)
    for time, tempo in ((4.0, early), (17.0, late)):  # librosa's tracker lags a drift a little
        expected = level * truth[np.searchsorted(beats, time) - 1]
        assert abs(tempo - expected) < 0.08 * expected, (time, tempo, expected)
    assert late > early + 10


def test_a_real_kick_track_at_120_bpm():
    song = Spectrogram.from_file(KICK_MP3)
    assert abs(song.rhythm.tempo - 120) < 0.04 * 120  # librosa's tempo grid: 117.5 BPM
    assert beat_f(np.arange(0, 10, 0.5), song.rhythm.beats) >= 0.9


def test_beat_phase_counts_beats_and_extrapolates():
    from eigendance.music.rhythm import beat_phase

    beats = np.array([1.0, 1.5, 2.0, 2.6])
    np.testing.assert_allclose(beat_phase(beats, [0.5, 1.0, 1.25, 2.3, 2.6, 3.2]),
                               [-1.0, 0.0, 0.5, 2.5, 3.0, 4.0])


# --------------------------------------------------------------------------------------------
# The spectrogram file, version 2


def test_version_2_file_round_trip_and_version_1_still_read(tmp_path, analysed):
    song, _ = analysed["clicks 100 BPM"]
    song.save(tmp_path / "s.npz")
    loaded = Spectrogram.load(tmp_path / "s.npz")
    np.testing.assert_array_equal(loaded.rhythm.beats, song.rhythm.beats)
    np.testing.assert_array_equal(loaded.rhythm.onsets, song.rhythm.onsets)
    assert loaded.rhythm.tempo == song.rhythm.tempo
    with np.load(tmp_path / "s.npz") as data:
        version1 = {key: data[key] for key in ("times", "band_edges", "values", "rate",
                                               "sample_rate", "duration")}
    np.savez(tmp_path / "v1.npz", **version1)
    old = Spectrogram.load(tmp_path / "v1.npz")
    assert old.rhythm is None
    np.testing.assert_array_equal(old.values, song.values)
    mapping = Mapping(np.full(16, 0.5), np.ones(4), pulse=Pulse(1.0))
    assert np.all(np.isfinite(mapping.play(old, old.times, 4)))  # no rhythm: no pulse


@pytest.mark.parametrize("change, message", [
    ({"beats": np.array([2.0, 1.0])}, "beats must be increasing"),
    ({"tempo": np.float64(np.nan)}, "tempo"),
    ({"onset_strength": np.zeros(3)}, "onset_strength has shape"),
    ({"version": np.int64(7)}, "version must be 1 or 2"),
])
def test_version_2_fields_are_checked(tmp_path, analysed, change, message):
    song, _ = analysed["clicks 100 BPM"]
    song.save(tmp_path / "s.npz")
    with np.load(tmp_path / "s.npz") as data:
        arrays = {key: data[key] for key in data.files}
    np.savez(tmp_path / "bad.npz", **{**arrays, **change})
    with pytest.raises(EigendanceError, match=message):
        Spectrogram.load(tmp_path / "bad.npz")


def test_spectrum_command_prints_the_tempo_and_draws_the_beats(tmp_path, capsys):
    samples, _ = tracks()["clicks 100 BPM"]
    soundfile.write(tmp_path / "clicks.wav", samples, SR)
    main(["spectrum", str(tmp_path / "clicks.wav"), "-o", str(tmp_path / "s.npz"),
          "--png", str(tmp_path / "s.png")])
    out = capsys.readouterr().out
    assert "BPM" in out and "beats" in out
    assert os.path.getsize(tmp_path / "s.png") > 1000


# --------------------------------------------------------------------------------------------
# Bad input: a result or one clear error, never a hang or a NaN


def check_plays(song):
    """Every number finite, and a mapping with a pulse and a rig dance still play on it."""
    assert np.all(np.isfinite(song.values)) and np.all(np.isfinite(song.rhythm.onset_strength))
    mapping = Mapping(np.linspace(0, 1, song.bands), np.ones(8), pulse=Pulse(2.0),
                      envelope=Envelope([0.1], [0.3], [0.05], True))
    assert np.all(np.isfinite(mapping.play(song, song.times, 8)))
    rig = Rig(sample_rig("loop4"))
    assert np.all(np.isfinite(rig_coefficients(rig.model, song, None, song.times)))


def test_silence_has_no_beat_and_still_plays(capsys, tmp_path):
    song = Spectrogram.from_samples(np.zeros(3 * SR), SR, bands=16)
    assert not song.rhythm.has_beats and song.rhythm.tempo == 0
    assert song.rhythm.summary().startswith("no beat detected")
    check_plays(song)
    soundfile.write(tmp_path / "silence.wav", np.zeros(SR), SR)
    main(["spectrum", str(tmp_path / "silence.wav"), "-o", str(tmp_path / "s.npz")])
    assert "no beat detected" in capsys.readouterr().out


def test_short_free_time_and_noise_give_a_result(rng):
    two_seconds = Spectrogram.from_samples(tracks()["clicks 100 BPM"][0][:2 * SR], SR, bands=16)
    check_plays(two_seconds)
    tiny = Spectrogram.from_samples(rng.normal(0, 0.1, 100), SR, bands=16)  # 5 ms
    assert not tiny.rhythm.has_beats
    # Rubato: notes at irregular times, the gaps drawn from 0.2 to 1.5 s.
    rubato = np.zeros(10 * SR)
    for at in np.cumsum(rng.uniform(0.2, 1.5, 12)):
        if at < 9.5:
            place(rubato, at, 0.3 * np.sin(2 * np.pi * 440 * np.arange(SR // 2) / SR)
                  * np.exp(-np.arange(SR // 2) / 3000))
    check_plays(Spectrogram.from_samples(rubato, SR, bands=16))
    check_plays(Spectrogram.from_samples(rng.normal(0, 0.2, 4 * SR), SR, bands=16))


def test_surround_and_high_sample_rates(tmp_path):
    samples, beats = tracks()["kicks 128 BPM"]
    surround = np.stack([samples * g for g in (1, 1, 0.5, 0.2, 0.7, 0.7)], axis=1)  # 5.1
    soundfile.write(tmp_path / "surround.wav", surround, SR)
    song = Spectrogram.from_file(tmp_path / "surround.wav", bands=16)
    assert beat_f(beats, song.rhythm.beats) >= 0.9
    guitar = Spectrogram.from_file(GUITAR_192K, bands=16)
    assert guitar.sample_rate == 192000
    check_plays(guitar)


# --------------------------------------------------------------------------------------------
# Mapping version 3: the envelope and the pulse


def test_envelope_auto_range_threshold_and_follower_by_hand():
    values = np.array([[0.2, 0.5], [0.4, 0.5], [0.6, 0.5], [0.8, 0.5]])
    # Band 0's 5th/95th percentiles: 0.2 + 0.15·0.2 = 0.23 and 0.2 + 2.85·0.2 = 0.77; band 1
    # is flat (carries nothing).
    ranged = shape_values(values, 10.0, Envelope(auto_range=True))
    np.testing.assert_allclose(ranged[:, 0], np.clip((values[:, 0] - 0.23) / 0.54, 0, 1))
    np.testing.assert_array_equal(ranged[:, 1], 0)
    gated = shape_values(values, 10.0, Envelope(threshold=[0.5, 0.6]))
    np.testing.assert_array_equal(gated, [[0, 0], [0, 0], [0.6, 0], [0.8, 0]])
    # Attack 0.1 s at 10 frames/s: m = e⁻¹ while rising; release 0: falls at once.
    follow = shape_values(np.array([[1.0], [1.0], [0.0]]), 10.0,
                          Envelope(attack=[0.1], release=[0.0]))
    np.testing.assert_allclose(follow.ravel(), [1 - math.exp(-1), 1 - math.exp(-2), 0.0])


def test_pulse_kicks_on_beats_and_decays():
    beats = Rhythm(np.zeros(500), np.array([0.5]), np.array([1.0, 2.0, 3.0, 4.0]), 60.0, 100.0)
    pulse = Pulse(amount=2.0, decay=0.25, low=0.5, high=1.0)
    np.testing.assert_allclose(pulse.signal(beats, [0.9, 1.0, 1.25, 2.5, 9.0]),
                               [0, 1, math.exp(-1), math.exp(-2), math.exp(-20)])
    np.testing.assert_array_equal(pulse.routed(4), [0, 0, 1, 1])  # centres ⅛, ⅜, ⅝, ⅞
    onsets = Pulse(amount=1.0, decay=0.25, source="onsets")
    assert onsets.signal(beats, [0.5])[0] == 1.0


def test_a_beat_pulse_kicks_a_bars_first_beat_a_quarter_harder():
    """As the rig's tempo lock accents it (analysis.json's downbeat_accent, 0.25): a kick on a
    downbeat is 1.25 times the others'; onsets, and a song without bars, are not accented."""
    beats = 0.25 + 0.5 * np.arange(12)  # 120 BPM
    downbeats = beats[1::4]  # bars of four from the second beat: 0.75, 2.75, 4.75 s
    song = SimpleNamespace(rhythm=Rhythm(np.zeros(700), downbeats, beats, 120.0, 100.0,
                                         downbeats))
    assert song.rhythm.meter == 4
    mapping = Mapping([0.5], [1.0], pulse=Pulse(amount=2.0, decay=0.25, source="beats"))
    # 1/8 s after the downbeat at 0.75 s, after the beat at 1.25 s; on the downbeat at 2.75 s,
    # then a beat later (3.25 s, no downbeat), half a beat after the one at 4.25 s.
    times = [0.875, 1.375, 2.75, 3.25, 4.5]
    np.testing.assert_allclose(mapping.kicks(song, times),
                               [2 * 1.25 * math.exp(-0.5), 2 * math.exp(-0.5), 2 * 1.25, 2.0,
                                2 * math.exp(-1)], rtol=1e-12)
    no_bars = SimpleNamespace(rhythm=replace(song.rhythm, downbeats=np.zeros(0)))
    np.testing.assert_allclose(mapping.kicks(no_bars, [0.875, 2.75]),
                               [2 * math.exp(-0.5), 2.0], rtol=1e-12)
    onsets = replace(mapping, pulse=Pulse(amount=2.0, decay=0.25, source="onsets"))
    np.testing.assert_allclose(onsets.kicks(song, [0.875, 2.75]), [2 * math.exp(-0.5), 2.0],
                               rtol=1e-12)  # the onsets fall on the downbeats: no accent


def test_mapping_version_3_round_trip_and_checks(tmp_path):
    mapping = Mapping([0.2, 0.7], [1.0, -2.0], envelope=Envelope([0.1, 0.2], [0.3], [0.0], True),
                      pulse=Pulse(1.5, 0.2, 0.1, 0.6, "onsets"),
                      modes=ModeSettings(tempo="free"))
    mapping.save(tmp_path / "m.json")
    again = Mapping.load(tmp_path / "m.json")
    assert again.to_json() == mapping.to_json() and again.to_json()["version"] == 3
    assert again.envelope.release.tolist() == [0.3, 0.3] and again.modes.tempo == "free"
    base = {**mapping.to_json()}
    for change, message in (({"envelope": {"attack": [-1.0]}}, "envelope.attack"),
                            ({"envelope": {"attack": [0.1, 0.1, 0.1]}}, "3 values for 2"),
                            ({"pulse": {"range": [0.8, 0.2]}}, "low ≤ high"),
                            ({"pulse": {"source": "bars"}}, "pulse.source"),
                            ({"modes": {"tempo": "swing"}}, "modes.tempo")):
        with pytest.raises(EigendanceError, match=message):
            Mapping.from_json({**base, **change}, "m.json")
    version2 = {**base, "version": 2}
    assert Mapping.from_json(version2).pulse.amount == 0  # fields of version 3 are ignored


# --------------------------------------------------------------------------------------------
# Both halves on the beat


def turning_points(signal, rate):
    low, high = np.percentile(signal, [5, 95])
    prominence = 0.1 * (high - low)
    extremes = np.concatenate([find_peaks(signal, prominence=prominence)[0],
                               find_peaks(-signal, prominence=prominence)[0]])
    return np.sort(extremes) / rate


def test_rig_dance_locks_to_the_beats(analysed):
    """The main sway of loop8's default dance turns on the beats (or half-beats) of a drifting
    drum loop; free-running it does not; the locked formula is c = φ·μ·α(t)·sin(2π r B(t) + γ′),
    α the bar's accent."""
    song, beats = analysed["drum loop drifting 105 → 128 BPM"]
    rig = Rig(sample_rig("loop8"))
    halves = np.sort(np.concatenate([beats, (beats[:-1] + beats[1:]) / 2]))
    scores = {}
    for tempo in ("beat", "free"):
        mapping = rig.mapping(song)
        mapping.modes.tempo = tempo
        c = rig.coefficients(song, mapping, song.times)
        moved = twists(rig.model, c).reshape(len(c), -1)  # the bodies' motion (the bench: skin)
        moved -= moved.mean(axis=0)
        sway = moved @ np.linalg.svd(moved[::4], full_matrices=False)[2][0]
        points = turning_points(sway, song.rate)
        scores[tempo] = max(beat_f(beats, points), beat_f(halves, points))
    assert scores["beat"] >= 0.8 and scores["free"] < 0.6, scores
    # The formula, B(t) by hand: linear between the detected beats.
    mapping = rig.mapping(song)
    times = np.array([3.0, 7.7, 12.1])
    detected = song.rhythm.beats
    phase = np.interp(times, detected, np.arange(len(detected)))
    free = replace_tempo(mapping, "free")
    drive = rig.coefficients(song, free, times)  # φ·μ·sin(free angle)
    palette = mapping.modes
    free_angle = 2 * np.pi * rig.model.frequencies[palette.selected] * palette.time_scale * \
        times[:, None] + palette.phases
    amplitude = drive[:, palette.selected] / np.sin(free_angle)
    ratios = lock_ratios(rig.model.frequencies[palette.selected], palette.time_scale,
                         song.rhythm.tempo)
    # the bar's accent by hand: 1 + ¼·cos²(πx/2) within a beat x of a downbeat's beat number
    x = np.abs(phase[:, None] - np.searchsorted(detected, song.rhythm.downbeats)).min(axis=1)
    accent = 1 + 0.25 * np.where(x < 1, np.cos(np.pi * x / 2) ** 2, 0)
    assert accent.max() > 1.05  # the times reach near a downbeat
    expected = amplitude * accent[:, None] * np.sin(2 * np.pi * ratios * phase[:, None]
                                                    + locked_phases(palette.phases))
    locked = rig.coefficients(song, mapping, times)[:, palette.selected]
    np.testing.assert_allclose(locked, expected, rtol=1e-6, atol=1e-12)
    # The exports play the Rig's motion: a dance and its window (the song's start + t) locked.
    dance = rig_dance(rig, song, mapping)
    np.testing.assert_array_equal(dance.pose(times)[1][:, palette.selected], locked)
    clip = dance.window(2.0, 11.0)
    np.testing.assert_array_equal(clip.pose(times - 2.0)[1], dance.pose(times)[1])


def replace_tempo(mapping, tempo):
    from dataclasses import replace

    return replace(mapping, modes=replace(mapping.modes, tempo=tempo))


def test_lock_ratios_pick_the_nearest_multiple_of_the_beat():
    # At 120 BPM (2 Hz): 0.9 Hz → ½ beat, 1.8 Hz → the beat, 5 Hz → double.
    np.testing.assert_array_equal(lock_ratios([0.9, 1.8, 5.0], 1.0, 120.0), [0.5, 1.0, 2.0])
    np.testing.assert_allclose(locked_phases([0.0, 1.0, 3.5, -2.0]),
                               [np.pi / 2, np.pi / 2, 3 * np.pi / 2, -np.pi / 2])
