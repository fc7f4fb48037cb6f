"""Rhythm next to the spectrogram: onset strength, onsets, beats, tempo, bars and sections
(docs/design.md#rhythm).

Beats and the tempo are librosa's default call, `librosa.beat.beat_track(y=y, sr=22050)`, on the
envelope `music.onset.BeatFeatures` computes in bounded memory (librosa's onset strength, median
over mels, at 22050/512 frames per second); the tempo is librosa's (feature.tempo: the
autocorrelation tempogram averaged over the song, a log-normal prior around 120 BPM), its
tempogram computed in chunks of CHUNK_SECONDS with the window's half on either side, so that an
hour needs no more memory than a few minutes and every column is the one librosa computes.
Onsets are librosa's onset_detect on the mean-over-mels envelope. Bars and sections come from
`music.structure`.

The file's `onset_strength` is the streaming envelope that the page's live analysis reproduces
frame by frame (`OnsetEnvelope`, at the spectrogram's frames):

- mel power P_j,m = Σ_q M_m,q·|X_j(q)|², M librosa's mel filter bank (MEL_BANDS Slaney bands
  from 0 to min(MEL_FMAX, sr/2) Hz over the window's bins), |X| the spectrogram's magnitude
  (a full-scale sine reads ≈ 1);
- S_j,m = max(10·log₁₀ P_j,m, FLOOR_DB) (a fixed floor: the song's maximum is not known while
  it streams);
- e_j = mean over m of max(0, S_j,m − S_{j−L},m), L = max(1, round(LAG·rate)) frames, with
  S_{j<0} = FLOOR_DB (silence before the song).

The beat phase B(t) (`beat_phase`) counts beats continuously: B(b_i) = i, linear between beats
and extrapolated with the first and last intervals; the tempo over time is 60·dB/dt (beats per
minute, piecewise constant between beats).
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field

import numpy as np

from eigendance.errors import InputError
from eigendance.files import checked_array
from eigendance.music.constants import ANALYSIS
from eigendance.music.onset import ENVELOPE_LAG, FRAME_RATE
from eigendance.music.structure import bars, sections

# From analysis.json, which the page's live analysis reads too:
MEL_BANDS = int(ANALYSIS["onset"]["mel_bands"])  # bands of the onset envelope's mel spectrum
MEL_FMAX = float(ANALYSIS["onset"]["mel_fmax"])  # Hz: librosa's default analysis sees no higher
FLOOR_DB = float(ANALYSIS["onset"]["floor_db"])  # dB of full scale: the mel power's floor
LAG = float(ANALYSIS["onset"]["lag"])  # s: the flux compares a frame with the one this earlier
CHUNK_SECONDS = 60.0  # the tempogram is computed over chunks this long
AC_SIZE = float(ANALYSIS["onset"]["tempo_window"])  # s: librosa.feature.tempo's ac_size
MIN_BEATS = 4  # fewer beats than this: no beat (the dance plays on loudness alone)
# How much stronger a bar's first beat is: the tempo-locked sway reaches this much further, and a
# pulse's kick on it is this much stronger (`Rhythm.downbeat_accent`).
DOWNBEAT_ACCENT = float(ANALYSIS["rhythm"]["downbeat_accent"])
QUIET = 1e-3  # an envelope whose 99th percentile is below this is silence


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
        used = np.flatnonzero(mel.any(axis=0))
        self.stop = int(used[-1]) + 1 if len(used) else 1
        self.mel = np.ascontiguousarray(mel[:, :self.stop].T, dtype=np.float32)  # (bins, m)
        self.lag = max(1, round(LAG * rate))
        self.previous = np.full((self.lag, MEL_BANDS), FLOOR_DB, dtype=np.float32)

    def feed(self, magnitude: np.ndarray) -> np.ndarray:
        """The envelope e_j of the next frames.

        Parameters
        ----------
        magnitude : (F, bins) magnitudes |X_j| of consecutive frames (the spectrogram's).

        Returns
        -------
        (F,) float32, dB per frame.
        """
        power = np.square(magnitude[:, :self.stop], dtype=np.float32) @ self.mel
        level = np.maximum(10 * np.log10(np.maximum(power, 1e-30)), FLOOR_DB)
        stacked = np.concatenate([self.previous, level])
        flux = np.maximum(stacked[self.lag:] - stacked[:-self.lag], 0)
        self.previous = stacked[-self.lag:]
        return flux.mean(axis=1).astype(np.float32)


@dataclass
class Rhythm:
    """What the rhythm analysis found in a song (docs/design.md#rhythm).

    onset_strength (T,) ≥ 0 at the spectrogram's frames (dB per frame); onsets, beats,
    downbeats (the beats that start a bar, `music.structure.bars`) and sections (the start
    times of the song's parts after the first, `music.structure.sections`): times in seconds,
    ascending; tempo: the song's tempo, beats per minute (0 when no beat was found); rate:
    frames per second of `onset_strength`.

    Parameters
    ----------
    onset_strength, onsets, beats, tempo, rate, downbeats, sections : as above.
    """

    onset_strength: np.ndarray
    onsets: np.ndarray
    beats: np.ndarray
    tempo: float
    rate: float
    downbeats: np.ndarray = field(default_factory=lambda: np.zeros(0))
    sections: np.ndarray = field(default_factory=lambda: np.zeros(0))

    @property
    def meter(self) -> int:
        """Beats per bar (the median count between downbeats), 0 without bars."""
        if len(self.downbeats) < 2 or not self.has_beats:
            return 0
        index = np.searchsorted(self.beats, self.downbeats)
        return int(np.median(np.diff(index)))

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

    def downbeat_accent(self, times) -> np.ndarray:
        """The bar's accent on the tempo lock: 1 + A·cos²(πx/2) for |x| < 1, else 1, where x is
        B(t) − B(d) for the downbeat d nearest in beats and A = DOWNBEAT_ACCENT (1 everywhere
        without beats or bars): largest on each bar's first beat, grown over the beat before
        and faded over the beat after (docs/design.md#tempo-lock).

        Parameters
        ----------
        times : (…,) s.

        Returns
        -------
        (…,) ≥ 1.
        """
        times = np.asarray(times, dtype=np.float64)
        if not self.has_beats or self.meter == 0:
            return np.ones(times.shape)
        at = beat_phase(self.beats, self.downbeats)  # the downbeats' beat numbers
        phase = beat_phase(self.beats, times)
        after = np.clip(np.searchsorted(self.downbeats, times, side="right"), 1, len(at) - 1)
        x = np.minimum(np.abs(phase - at[after - 1]), np.abs(phase - at[after]))
        return 1.0 + DOWNBEAT_ACCENT * np.where(x < 1.0, np.cos(np.pi * x / 2) ** 2, 0.0)

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


def librosa_tempo(envelope: np.ndarray, rate: float) -> float:
    """librosa.feature.tempo of the envelope with its defaults (the tempogram averaged over the
    song, the log-normal prior around 120 BPM), the tempogram built CHUNK_SECONDS at a time.

    Each chunk's tempogram is computed with half its window (AC_SIZE) of the envelope on either
    side, so every column equals the one of the whole envelope's tempogram.

    Parameters
    ----------
    envelope : (T,) onset strength.
    rate : its frames per second.

    Returns
    -------
    float, beats per minute.
    """
    import librosa  # heavy (numba): only when a song is analysed

    window = int(math.floor(AC_SIZE * rate))  # librosa.time_to_frames(ac_size)
    half = window // 2
    chunk = max(1, int(CHUNK_SECONDS * rate))
    total = np.zeros(window)
    for start in range(0, len(envelope), chunk):
        first = max(0, start - half)
        stop = min(len(envelope), start + chunk + half)
        gram = librosa.feature.tempogram(onset_envelope=envelope[first:stop], sr=rate,
                                         hop_length=1, win_length=window)
        columns = gram[:, start - first:start - first + min(chunk, len(envelope) - start)]
        total += columns.sum(axis=1)
    tempo = librosa.feature.tempo(tg=(total / len(envelope))[:, None], sr=rate, hop_length=1,
                                  aggregate=None)
    return float(np.ravel(tempo)[0])


def analyse_rhythm(envelope, rate: float, features) -> Rhythm:
    """Onsets, beats, tempo, bars and sections of a song.

    Parameters
    ----------
    envelope : (T,) the streaming onset strength e_j at the spectrogram's frames (`OnsetEnvelope`),
        kept as the Rhythm's `onset_strength`.
    rate : the spectrogram's frames per second.
    features : `music.onset.BeatFeatures.finish()` of the same song: the median and mean onset
        strength, mel dB and chroma at FRAME_RATE.

    Returns
    -------
    Rhythm (no beat, tempo 0, for silence or fewer than MIN_BEATS beats).
    """
    import librosa  # heavy (numba): only when a song is analysed

    envelope = np.asarray(envelope, dtype=np.float32)
    median, mean, decibels, chroma = features
    nothing = Rhythm(envelope, np.zeros(0), np.zeros(0), 0.0, float(rate))
    if len(median) < 3 or not np.percentile(mean, 99) > QUIET:
        return nothing
    onsets = librosa.onset.onset_detect(onset_envelope=mean, sr=FRAME_RATE, hop_length=1,
                                        units="time")
    onsets = np.asarray(onsets, dtype=np.float64)
    tempo = librosa_tempo(median, FRAME_RATE) if median.any() else 0.0
    if not (math.isfinite(tempo) and tempo > 0):
        return Rhythm(envelope, onsets, np.zeros(0), 0.0, float(rate))
    _, frames = librosa.beat.beat_track(onset_envelope=median, sr=FRAME_RATE, hop_length=1,
                                        bpm=tempo)
    beats = np.asarray(frames, dtype=np.float64) / FRAME_RATE
    if len(beats) < MIN_BEATS:
        return Rhythm(envelope, onsets, beats, 0.0, float(rate))
    at = np.maximum(np.asarray(frames) - ENVELOPE_LAG, 0)  # the beats' mel frames
    downbeats = beats[bars(at, decibels, chroma)]
    parts = sections(at, decibels, chroma, len(median) / FRAME_RATE)
    return Rhythm(envelope, onsets, beats, tempo, float(rate), downbeats, parts)


# ---------------------------------------------------------------------------------------------
# The spectrogram file's rhythm fields (docs/design.md#spectrogram-file, version 2)

FILE_KEYS = ("onset_strength", "onsets", "beats", "downbeats", "tempo")
OPTIONAL_KEYS = ("sections",)  # version-2 files written before sections existed lack them


def rhythm_arrays(rhythm: Rhythm) -> dict:
    """The arrays a version-2 spectrogram file holds for the rhythm.

    Parameters
    ----------
    rhythm : the song's rhythm.

    Returns
    -------
    dict of FILE_KEYS and OPTIONAL_KEYS → arrays (float32 strength, float64 times and tempo).
    """
    return {"onset_strength": np.asarray(rhythm.onset_strength, dtype=np.float32),
            "onsets": np.asarray(rhythm.onsets, dtype=np.float64),
            "beats": np.asarray(rhythm.beats, dtype=np.float64),
            "downbeats": np.asarray(rhythm.downbeats, dtype=np.float64),
            "sections": np.asarray(rhythm.sections, dtype=np.float64),
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
    for key in ("onsets", "beats", "downbeats", "sections"):
        if key not in data:  # sections: optional
            times[key] = np.zeros(0)
            continue
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
                  times["downbeats"], times["sections"])

