"""The streaming analysis behind `music.spectrogram.Spectrogram` (docs/design.md#spectrogram):
frames, window, bands, loudness and smoothing, and the rhythm's features fed from the same
chunks. The definitions are in the docstring of `music.spectrogram`.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.fft import rfft

from eigendance.errors import InputError
from eigendance.music.constants import ANALYSIS
from eigendance.music.onset import BeatFeatures
from eigendance.music.rhythm import OnsetEnvelope

FRAME_BATCH = 1024  # analysis frames per batched FFT
# Defaults of docs/design.md#spectrogram: frames per second, bands, band range (Hz), loudness
# floor (dB), smoothing time constant (s) and window length (s), from analysis.json, which the
# page's live analysis (web/src/live-analysis.ts) reads too.
RATE, BANDS, FMIN, FMAX, FLOOR_DB, SMOOTHING, WINDOW_SECONDS = (
    float(ANALYSIS["rate"]), int(ANALYSIS["bands"]), float(ANALYSIS["fmin"]),
    float(ANALYSIS["fmax"]), float(ANALYSIS["floor_db"]), float(ANALYSIS["smoothing"]),
    float(ANALYSIS["window_seconds"]))
# Bounds that keep every allocation proportional to the audio, not to a header or an option:
# the window grows with the sample rate, the result with frames × bands, frame times with
# duration × frames per second.
MAX_SAMPLE_RATE = 1_000_000  # Hz
MAX_VALUES = 1 << 28  # T × B float32 values: 1 GiB (an hour at 100 frames/s × 64 bands: 23 M)
MAX_FRAMES = 10_000_000  # animation frames: 46 hours at 60 frames/s
# Samples beyond ±MAX_SAMPLE (full scale is ±1: +120 dB) are clipped there, so float32 frames
# and their spectra cannot overflow; loudness saturates at full scale long before.
MAX_SAMPLE = 1e6


def window_length(sample_rate: float) -> int:
    """N = the smallest power of two ≥ 0.046·sr (2048 at 44.1 kHz, 4096 at 48 kHz).

    Parameters
    ----------
    sample_rate : Hz.

    Returns
    -------
    int.
    """
    return 1 << max(0, math.ceil(math.log2(WINDOW_SECONDS * sample_rate)))


def frame_count(sample_count: int, sample_rate: int, rate: float) -> int:
    """Number of analysis frames: ⌊duration·rate⌋ + 1.

    Parameters
    ----------
    sample_count : samples.
    sample_rate : Hz.
    rate : frames per second.

    Returns
    -------
    int.
    """
    return int(math.floor(sample_count * rate / sample_rate)) + 1


def frame_centres(first: int, stop: int, sample_rate: int, rate: float) -> np.ndarray:
    """c_j = ⌊j·sr/rate + ½⌋ for j in [first, stop), as int64.

    Parameters
    ----------
    first, stop : frame indices.
    sample_rate : Hz.
    rate : frames per second.

    Returns
    -------
    (stop − first,) sample indices.
    """
    j = np.arange(first, stop, dtype=np.float64)
    return np.floor(j * sample_rate / rate + 0.5).astype(np.int64)


def band_edges(bands: int, sample_rate: float, fmin: float = FMIN,
               fmax: float = FMAX) -> np.ndarray:
    """geomspace(fmin, min(fmax, sr/2), bands + 1).

    Parameters
    ----------
    bands : B.
    sample_rate : Hz.
    fmin, fmax : Hz.

    Returns
    -------
    (B+1,) Hz.
    """
    return np.geomspace(fmin, min(fmax, sample_rate / 2), bands + 1)


def hann(length: int) -> np.ndarray:
    """Periodic Hann window, 0.5 − 0.5·cos(2πn/N) (= scipy.signal.get_window('hann', N)).

    Parameters
    ----------
    length : N.

    Returns
    -------
    (N,).
    """
    return 0.5 - 0.5 * np.cos(2 * np.pi * np.arange(length) / length)


def exponential_smoothing(values: np.ndarray, memory: float, previous) -> np.ndarray:
    """s_j = m·s_{j−1} + (1 − m)·v_j along axis 0, s_{−1} = previous; vectorised over frames.

    Closed form per block: s_j = m^(j+1)·s_{−1} + (1 − m)·m^j·Σ_{i≤j} m^(−i)·v_i, in blocks
    short enough that m^(−i) stays far from overflow (all terms are positive: no cancellation).

    Parameters
    ----------
    values : (F, B).
    memory : m in [0, 1).
    previous : (B,) s_{−1}.

    Returns
    -------
    (F, B).
    """
    values = np.asarray(values, dtype=np.float64)
    out = np.empty_like(values)
    state = np.asarray(previous, dtype=np.float64)
    if memory < 1e-30:  # below float32 resolution after one step: no smoothing
        return values.copy()
    if memory >= 1:
        out[:] = state
        return out
    block = max(1, int(300 / -math.log(memory)))  # m^(−block) ≤ e^300
    for first in range(0, len(values), block):
        v = values[first:first + block]
        j = np.arange(len(v), dtype=np.float64)[:, None]
        growth = memory ** -j  # m^(−i)
        decay = memory ** j  # m^j
        sums = np.cumsum(v * growth, axis=0)
        out[first:first + len(v)] = memory * decay * state + (1 - memory) * decay * sums
        state = out[first + len(v) - 1]
    return out


class Analyser:
    """Streaming spectrogram: feed mono chunks, get smoothed band values chunk by chunk (and,
    with rhythm=True, the rhythm's envelope and features).

    Parameters
    ----------
    sample_rate : Hz.
    rate, bands, fmin, fmax, floor_db, smoothing : the options of docs/design.md#spectrogram.
    name : how messages call the audio.
    rhythm : whether to compute the rhythm's envelope (`envelope`) and features (`features`).
    """

    def __init__(self, sample_rate, rate=RATE, bands=BANDS, fmin=FMIN, fmax=FMAX,
                 floor_db=FLOOR_DB, smoothing=SMOOTHING, name="audio", rhythm=True):
        self.name = name
        if not (isinstance(sample_rate, int | np.integer) and 0 < sample_rate <= MAX_SAMPLE_RATE):
            raise InputError(f"{name}: the sample rate must be an integer from 1 to "
                             f"{MAX_SAMPLE_RATE} Hz, got {sample_rate}")
        if not (np.isfinite(rate) and rate > 0):
            raise InputError(f"the frame rate must be a positive number of frames per second, "
                             f"got {rate}")
        if not (isinstance(bands, int | np.integer) and bands >= 1):
            raise InputError(f"the number of bands must be a positive integer, got {bands}")
        if not (np.isfinite(fmin) and np.isfinite(fmax) and 0 < fmin < fmax):
            raise InputError(f"the band range {fmin:g}–{fmax:g} Hz is empty")
        if not fmin < sample_rate / 2:
            raise InputError(f"{name}: a sample rate of {sample_rate} Hz holds no frequency "
                             f"above {sample_rate / 2:g} Hz, below the lowest band ({fmin:g} Hz)")
        if not floor_db < 0:
            raise InputError(f"the loudness floor must be negative (dB), got {floor_db}")
        if not smoothing >= 0:
            raise InputError(f"smoothing must be ≥ 0 s, got {smoothing}")
        self.sample_rate, self.rate, self.floor_db = int(sample_rate), float(rate), floor_db
        self.N = window_length(sample_rate)
        self.half = self.N // 2
        window = hann(self.N)
        # The 2/Σw scale is folded into the window. Frames, window and FFT are float32: its
        # rounding noise (≈ −140 dB of full scale) lies far below the −80 dB loudness floor.
        self.window = (window * (2.0 / window.sum())).astype(np.float32)
        self.edges = band_edges(bands, sample_rate, fmin, fmax)
        frequencies = np.arange(self.N // 2 + 1) * sample_rate / self.N
        first = np.searchsorted(frequencies, self.edges, side="left")  # first bin ≥ edge
        self.nonempty = first[1:] > first[:-1]
        self.reduce_starts = first[:-1][self.nonempty]
        self.reduce_stop = int(first[-1])
        centres = np.sqrt(self.edges[:-1] * self.edges[1:])[~self.nonempty]
        below = np.searchsorted(frequencies, centres, side="right") - 1
        self.interp_index = below
        self.interp_weight = (centres - frequencies[below]) / (frequencies[below + 1]
                                                               - frequencies[below])
        self.memory = math.exp(-1.0 / (rate * smoothing)) if smoothing > 0 else 0.0
        self.state = np.zeros((1, bands))
        self.buffer = np.zeros(self.half, dtype=np.float32)
        self.start = -self.half  # absolute sample index of buffer[0]
        self.next = 0  # next frame to compute
        self.total = 0  # samples received
        self.outputs: list[np.ndarray] = []
        # The onset-strength envelope of docs/design.md#rhythm, from the same frames.
        self.onsets = OnsetEnvelope(self.sample_rate, self.N, self.rate) if rhythm else None
        self.envelope: list[np.ndarray] = []
        # librosa's onset strength, mel dB and chroma (music.onset) for beats, bars, sections.
        self.features = BeatFeatures(self.sample_rate) if rhythm else None

    def feed(self, chunk: np.ndarray) -> None:
        """Analyse the next mono samples.

        Parameters
        ----------
        chunk : (m,) samples.
        """
        chunk = np.asarray(chunk).ravel()
        if not np.all(np.isfinite(chunk)):
            raise InputError(f"{self.name}: the audio holds NaN or infinite samples")
        chunk = np.clip(chunk, -MAX_SAMPLE, MAX_SAMPLE)
        if self.features is not None:
            self.features.feed(chunk)
        self.total += len(chunk)
        frames = frame_count(self.total, self.sample_rate, self.rate)
        if frames * (len(self.edges) - 1) > MAX_VALUES:
            raise InputError(f"{self.name}: the spectrogram would hold more than {MAX_VALUES} "
                             f"values ({frames} frames × {len(self.edges) - 1} bands so far); "
                             "analyse it with a lower frame rate or fewer bands")
        self.buffer = np.concatenate([self.buffer, chunk.astype(np.float32)])
        self._process(final=False)

    def finish(self) -> np.ndarray:
        """The last frames, once every chunk was fed.

        Returns
        -------
        (T, B) float32 smoothed loudness of every frame.
        """
        if self.total == 0:
            raise InputError(f"{self.name}: holds no audio samples")
        self.buffer = np.concatenate([self.buffer, np.zeros(self.N + 1, dtype=np.float32)])
        self._process(final=True)
        return np.concatenate(self.outputs) if self.outputs else np.zeros((0, len(self.edges) - 1),
                                                                          np.float32)

    def _process(self, final: bool) -> None:
        end = self.start + len(self.buffer)  # one past the last sample held
        if final:
            stop = frame_count(self.total, self.sample_rate, self.rate)
        else:
            stop = int((end - self.half) * self.rate / self.sample_rate) + 2
            centres = frame_centres(self.next, max(self.next, stop), self.sample_rate, self.rate)
            stop = self.next + int(np.searchsorted(centres + self.half, end, side="right"))
        if stop > self.next:
            windows = np.lib.stride_tricks.sliding_window_view(self.buffer, self.N)
        for first in range(self.next, stop, FRAME_BATCH):
            last = min(stop, first + FRAME_BATCH)
            offsets = frame_centres(first, last, self.sample_rate, self.rate) - self.half
            self.outputs.append(self._analyse(windows[offsets - self.start]))
        if stop > self.next:
            self.next = stop
        keep_from = int(frame_centres(self.next, self.next + 1, self.sample_rate,
                                      self.rate)[0]) - self.half
        if keep_from > self.start:
            drop = min(keep_from - self.start, len(self.buffer))
            self.buffer = self.buffer[drop:]
            self.start += drop

    def _analyse(self, frames: np.ndarray) -> np.ndarray:
        """(F, N) raw frames → (F, B) smoothed loudness, float32."""
        magnitude = np.abs(rfft(frames * self.window, axis=1))  # float32
        if self.onsets is not None:
            self.envelope.append(self.onsets.feed(magnitude))
        bands = np.empty((len(frames), len(self.edges) - 1))
        if len(self.reduce_starts):
            bands[:, self.nonempty] = np.maximum.reduceat(
                magnitude[:, :self.reduce_stop], self.reduce_starts, axis=1)
        if len(self.interp_index):
            weight = self.interp_weight
            bands[:, ~self.nonempty] = (magnitude[:, self.interp_index] * (1 - weight)
                                        + magnitude[:, self.interp_index + 1] * weight)
        decibels = 20 * np.log10(np.maximum(bands, 1e-30))  # float64 from here
        loudness = np.clip((decibels - self.floor_db) / -self.floor_db, 0.0, 1.0)
        if self.memory == 0.0:
            return loudness.astype(np.float32)
        smoothed = exponential_smoothing(loudness, self.memory, self.state[0])
        self.state = smoothed[-1:]
        return smoothed.astype(np.float32)


