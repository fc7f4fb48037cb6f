"""Rhythm next to the spectrogram: onset strength, onsets, beats, tempo (docs/design.md#rhythm).

The onset-strength envelope is ours, computed frame by frame by the spectrogram's own analysis
(same frames, same window, same frame rate), so that a streaming analysis can reproduce it:

- mel power P_j,m = Σ_q M_m,q·|X_j(q)|², M librosa's mel filter bank (MEL_BANDS Slaney bands
  from 0 to min(MEL_FMAX, sr/2) Hz over the window's bins), |X| the spectrogram's magnitude
  (a full-scale sine reads ≈ 1);
- S_j,m = max(10·log₁₀ P_j,m, FLOOR_DB) (a fixed floor: the song's maximum is not known while
  it streams);
- e_j = mean over m of max(0, S_j,m − S_{j−L},m), L = max(1, round(LAG·rate)) frames, with
  S_{j<0} = FLOOR_DB (silence before the song).

Onsets, beats and the tempo are librosa's (onset_detect, beat_track, feature.tempo) run on
that envelope at the spectrogram's frame rate (sr = rate, hop_length = 1); the tempo's
tempogram is averaged over chunks of CHUNK_SECONDS so that an hour of audio needs no more memory
than a few minutes. The beat phase B(t) (`beat_phase`) counts beats continuously: B(b_i) = i,
linear between beats and extrapolated with the first and last intervals; the tempo over time is
60·dB/dt (beats per minute, piecewise constant between beats).
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field

import numpy as np

from eigendance.errors import InputError
from eigendance.files import checked_array
from eigendance.music.constants import ANALYSIS

# From analysis.json, which the page's live analysis reads too:
MEL_BANDS = int(ANALYSIS["onset"]["mel_bands"])  # bands of the onset envelope's mel spectrum
MEL_FMAX = float(ANALYSIS["onset"]["mel_fmax"])  # Hz: librosa's default analysis sees no higher
FLOOR_DB = float(ANALYSIS["onset"]["floor_db"])  # dB of full scale: the mel power's floor
LAG = float(ANALYSIS["onset"]["lag"])  # s: the flux compares a frame with the one this earlier
CHUNK_SECONDS = 60.0  # the tempogram is averaged over chunks this long
BASS_FMAX = float(ANALYSIS["onset"]["bass_fmax"])  # Hz: the bass mel bands are centred below
OFFBEAT_RATIO = 1.5  # beats move half a beat when the bass hits there this much harder
FAST = 160.0  # BPM: above this, every other beat is kept when the bass marks one parity
MIN_BEATS = 4  # fewer beats than this: no beat (the dance plays on loudness alone)
QUIET = 1e-3  # an envelope whose 99th percentile is below this (dB per frame) is silence


class OnsetEnvelope:
    """The streaming onset-strength envelope (module docstring): feed magnitude frames.

    Parameters
    ----------
    sample_rate : Hz.
    window : N, the analysis window (the spectrogram's), samples.
    rate : frames per second.
    """

    def __init__(self, sample_rate: int, window: int, rate: float):
        import librosa  # heavy (numba, 1–2 s): only when a song is analysed

        with warnings.catch_warnings():  # a low sample rate leaves some mel bands empty
            warnings.simplefilter("ignore")
            mel = librosa.filters.mel(sr=sample_rate, n_fft=window, n_mels=MEL_BANDS,
                                      fmin=0.0, fmax=min(MEL_FMAX, sample_rate / 2))
        centres = librosa.mel_frequencies(MEL_BANDS + 2, fmin=0.0,
                                          fmax=min(MEL_FMAX, sample_rate / 2))[1:-1]
        self.low = centres < BASS_FMAX  # the bands of the bass envelope
        used = np.flatnonzero(mel.any(axis=0))
        self.stop = int(used[-1]) + 1 if len(used) else 1
        self.mel = np.ascontiguousarray(mel[:, :self.stop].T, dtype=np.float32)  # (bins, m)
        self.lag = max(1, round(LAG * rate))
        self.previous = np.full((self.lag, MEL_BANDS), FLOOR_DB, dtype=np.float32)

    def feed(self, magnitude: np.ndarray) -> np.ndarray:
        """The envelope of the next frames: e_j and the bass envelope (the same mean over the
        mel bands centred below BASS_FMAX).

        Parameters
        ----------
        magnitude : (F, bins) magnitudes |X_j| of consecutive frames (the spectrogram's).

        Returns
        -------
        (F, 2) float32, dB per frame: [:, 0] e_j, [:, 1] the bass envelope.
        """
        power = np.square(magnitude[:, :self.stop], dtype=np.float32) @ self.mel
        level = np.maximum(10 * np.log10(np.maximum(power, 1e-30)), FLOOR_DB)
        stacked = np.concatenate([self.previous, level])
        flux = np.maximum(stacked[self.lag:] - stacked[:-self.lag], 0)
        self.previous = stacked[-self.lag:]
        bass = flux[:, self.low].mean(axis=1) if self.low.any() else np.zeros(len(flux))
        return np.stack([flux.mean(axis=1), bass], axis=1).astype(np.float32)


@dataclass
class Rhythm:
    """What the rhythm analysis found in a song (docs/design.md#rhythm).

    onset_strength (T,) ≥ 0 at the spectrogram's frames (dB per frame); onsets, beats and
    downbeats: times in seconds, ascending (downbeats: empty, librosa's tracker gives none);
    tempo: the song's tempo, beats per minute (0 when no beat was found); rate: frames per
    second of `onset_strength`.

    Parameters
    ----------
    onset_strength, onsets, beats, tempo, rate, downbeats : as above.
    """

    onset_strength: np.ndarray
    onsets: np.ndarray
    beats: np.ndarray
    tempo: float
    rate: float
    downbeats: np.ndarray = field(default_factory=lambda: np.zeros(0))

    @property
    def has_beats(self) -> bool:
        """Whether the dances can follow a beat: at least MIN_BEATS beats and a tempo."""
        return len(self.beats) >= MIN_BEATS and self.tempo > 0

    def beat_phase(self, times) -> np.ndarray:
        """B(t): beats counted continuously (`beat_phase`); NaN-free, needs has_beats.

        Parameters
        ----------
        times : (…,) s.

        Returns
        -------
        (…,) beats (B(b_i) = i).
        """
        return beat_phase(self.beats, times)

    def tempo_curve(self, times) -> np.ndarray:
        """Tempo over time: 60·dB/dt, piecewise constant between beats.

        Parameters
        ----------
        times : (…,) s.

        Returns
        -------
        (…,) beats per minute (0 everywhere without beats).
        """
        times = np.asarray(times, dtype=np.float64)
        if not self.has_beats:
            return np.zeros(times.shape)
        intervals = np.diff(self.beats)
        index = np.clip(np.searchsorted(self.beats, times, side="right") - 1, 0,
                        len(intervals) - 1)
        return 60.0 / intervals[index]

    def summary(self) -> str:
        """One line for a person: the tempo and the number of beats, or that there is none.

        Returns
        -------
        str ("tempo 120.0 BPM, 20 beats, 21 onsets").
        """
        if not self.has_beats:
            return ("no beat detected: the dance follows the loudness alone "
                    f"({len(self.onsets)} onsets)")
        return (f"tempo {self.tempo:.1f} BPM, {len(self.beats)} beats, "
                f"{len(self.onsets)} onsets")


def beat_phase(beats, times) -> np.ndarray:
    """B(t): B(b_i) = i, linear between beats, extrapolated with the first and last intervals
    before the first beat and after the last one.

    Parameters
    ----------
    beats : (n,) s, n ≥ 2, ascending.
    times : (…,) s.

    Returns
    -------
    (…,) beats.

    Example
    -------
    >>> beat_phase([1.0, 1.5, 2.5], [0.5, 1.25, 2.0, 3.5]).tolist()
    [-1.0, 0.5, 1.5, 3.0]
    """
    beats = np.asarray(beats, dtype=np.float64)
    times = np.asarray(times, dtype=np.float64)
    count = len(beats)
    inside = np.interp(times, beats, np.arange(count, dtype=np.float64))
    first, last = beats[1] - beats[0], beats[-1] - beats[-2]
    before = (times - beats[0]) / first
    after = count - 1 + (times - beats[-1]) / last
    return np.where(times < beats[0], before, np.where(times > beats[-1], after, inside))


def mean_tempogram_tempo(envelope: np.ndarray, rate: float) -> float:
    """librosa's tempo (feature.tempo, its default prior around 120 BPM) of the tempogram
    averaged over chunks of CHUNK_SECONDS.

    Parameters
    ----------
    envelope : (T,) onset strength.
    rate : its frames per second.

    Returns
    -------
    float, beats per minute.
    """
    import librosa  # heavy (numba): only when a song is analysed

    chunk = max(1, int(CHUNK_SECONDS * rate))
    total, frames = None, 0
    for start in range(0, len(envelope), chunk):
        piece = envelope[start:start + chunk]
        gram = librosa.feature.tempogram(onset_envelope=piece, sr=rate, hop_length=1)
        total = gram.sum(axis=1) if total is None else total + gram.sum(axis=1)
        frames += gram.shape[1]
    tempo = librosa.feature.tempo(tg=(total / frames)[:, None], sr=rate, hop_length=1,
                                  aggregate=None)
    return float(np.ravel(tempo)[0])


def bass_phase(beats: np.ndarray, bass: np.ndarray, rate: float) -> np.ndarray:
    """The beats, moved by half a beat where the bass hits the half-beats harder.

    A tracker can lock onto the off-beat (a guitar's "chick", off-beat hi-hats), or onto the
    eighth notes; the bass and the kick drum mark the beat itself. With h the largest bass
    envelope within ±30 ms (`bass`, (T,) at `rate`): if the mean h at the midpoints between
    beats is more than OFFBEAT_RATIO times the mean h at the beats, the midpoints are the
    beats; then, above FAST beats per minute, if one parity of the beats (even or odd) has a
    mean h more than OFFBEAT_RATIO times the other's, only that parity is kept.

    Parameters
    ----------
    beats : (n,) s, ascending.
    bass : (T,) the bass envelope at `rate`.
    rate : frames per second.

    Returns
    -------
    (m,) s: the beats, moved or thinned (themselves when the bass says nothing).
    """
    if len(beats) < MIN_BEATS or not np.any(bass > 0):
        return beats
    reach = max(1, round(0.03 * rate))

    def strength(times):
        frames = np.clip(np.round(times * rate).astype(np.int64), 0, len(bass) - 1)
        window = frames[:, None] + np.arange(-reach, reach + 1)
        return bass[np.clip(window, 0, len(bass) - 1)].max(axis=1).mean()

    middles = (beats[:-1] + beats[1:]) / 2
    if strength(middles) > OFFBEAT_RATIO * strength(beats[:-1]):
        beats = middles
    if 60 / np.median(np.diff(beats)) > FAST and len(beats) >= 2 * MIN_BEATS:
        even, odd = strength(beats[0::2]), strength(beats[1::2])
        if max(even, odd) > OFFBEAT_RATIO * min(even, odd):  # a tracker at double tempo
            beats = beats[0::2] if even >= odd else beats[1::2]
    return beats


def analyse_rhythm(envelope, rate: float, bass=None) -> Rhythm:
    """Onsets, beats and the tempo from the onset-strength envelope (T,) at `rate` frames/s
    (bass: the bass envelope (T,) that `bass_phase` checks the beats' phase with).

    Parameters
    ----------
    envelope : (T,) onset strength e_j (`OnsetEnvelope`), dB per frame.
    rate : frames per second.
    bass : (T,) the bass envelope, or None (no check of the beats' phase).

    Returns
    -------
    Rhythm (no beat, tempo 0, for silence or fewer than MIN_BEATS beats).

    Example
    -------
    >>> rate = 100.0
    >>> envelope = np.zeros(1000, dtype=np.float32)
    >>> envelope[25::50] = 10.0                      # a click every 0.5 s: 120 BPM
    >>> rhythm = analyse_rhythm(envelope, rate)
    >>> round(rhythm.tempo), len(rhythm.beats) >= 15
    (120, True)
    """
    import librosa  # heavy (numba): only when a song is analysed

    envelope = np.asarray(envelope, dtype=np.float32)
    nothing = Rhythm(envelope, np.zeros(0), np.zeros(0), 0.0, float(rate))
    if len(envelope) < 3 or not np.percentile(envelope, 99) > QUIET:
        return nothing
    onsets = librosa.onset.onset_detect(onset_envelope=envelope, sr=rate, hop_length=1,
                                        units="time")
    tempo = mean_tempogram_tempo(envelope, rate)
    if not (math.isfinite(tempo) and tempo > 0):
        return Rhythm(envelope, onsets, np.zeros(0), 0.0, float(rate))
    _, beats = librosa.beat.beat_track(onset_envelope=envelope, sr=rate, hop_length=1,
                                       bpm=tempo, units="time")
    beats = np.asarray(beats, dtype=np.float64)
    if bass is not None:
        checked = bass_phase(beats, np.asarray(bass, dtype=np.float32), rate)
        if len(checked) < len(beats) * 0.75:  # every other beat: half the tempo
            tempo /= 2
        beats = checked
    if len(beats) < MIN_BEATS:
        return Rhythm(envelope, onsets, beats, 0.0, float(rate))
    return Rhythm(envelope, np.asarray(onsets, dtype=np.float64), beats, tempo, float(rate))


# ---------------------------------------------------------------------------------------------
# The spectrogram file's rhythm fields (docs/design.md#spectrogram-file, version 2)

FILE_KEYS = ("onset_strength", "onsets", "beats", "downbeats", "tempo")


def rhythm_arrays(rhythm: Rhythm) -> dict:
    """The arrays a version-2 spectrogram file holds for the rhythm.

    Parameters
    ----------
    rhythm : the song's rhythm.

    Returns
    -------
    dict of FILE_KEYS → arrays (float32 strength, float64 times and tempo).
    """
    return {"onset_strength": np.asarray(rhythm.onset_strength, dtype=np.float32),
            "onsets": np.asarray(rhythm.onsets, dtype=np.float64),
            "beats": np.asarray(rhythm.beats, dtype=np.float64),
            "downbeats": np.asarray(rhythm.downbeats, dtype=np.float64),
            "tempo": np.float64(rhythm.tempo)}


def rhythm_from_arrays(data: dict, path, frames: int, rate: float, duration: float) -> Rhythm:
    """The rhythm of a version-2 file, checked: InputError naming the field otherwise.

    Parameters
    ----------
    data : the file's arrays.
    path : the file, for messages.
    frames : T, the spectrogram's frames.
    rate : frames per second.
    duration : the song's, s.

    Returns
    -------
    Rhythm.
    """
    missing = [key for key in FILE_KEYS if key not in data]
    if missing:
        raise InputError(f"{path}: a version-2 spectrogram file lacks {', '.join(missing)}")
    strength = checked_array(data, "onset_strength", path, shape=(frames,))
    if np.any(strength < 0):
        raise InputError(f"{path}: onset_strength must be ≥ 0")
    times = {}
    for key in ("onsets", "beats", "downbeats"):
        values = checked_array(data, key, path, shape=(None,))
        if np.any(np.diff(values) <= 0) or np.any(values < 0) or \
                np.any(values > duration + 1.0):
            raise InputError(f"{path}: {key} must be increasing times within the song "
                             f"(0 … {duration:g} s)")
        times[key] = values
    tempo = float(checked_array(data, "tempo", path))
    if not 0 <= tempo <= 1000:
        raise InputError(f"{path}: tempo must be 0 … 1000 beats per minute, got {tempo:g}")
    return Rhythm(strength.astype(np.float32), times["onsets"], times["beats"], tempo, rate,
                  times["downbeats"])

