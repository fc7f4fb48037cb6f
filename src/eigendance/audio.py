"""Decode music and compute its banded loudness spectrogram (DESIGN §3, §8).

Decoding: WAV, FLAC, OGG (Vorbis/Opus) and MP3 through soundfile (libsndfile); anything else
(M4A/AAC, Opus in WebM/MKV, …), and any file libsndfile refuses, through PyAV (FFmpeg). Channels
are mixed to mono by their mean (not PyAV's −3 dB mono resampler); the file's sample rate is
kept. Files are read in chunks and the analysis runs chunk by chunk, so memory stays bounded by
the chunk size plus the output (T × B float32 values) however long the track is.

Spectrogram, one definition for every consumer (browser, video, glTF):

- frames j = 0 … ⌊duration·rate⌋, frame j centred on sample c_j = ⌊j·sr/rate + ½⌋ (round half
  up) and covering samples c_j − N/2 … c_j + N/2 − 1, zero outside the signal;
- periodic Hann window of N = the smallest power of two ≥ 0.046·sr samples; magnitude
  |rfft| · 2/Σw, so a full-scale sine reads ≈ 1;
- B bands with edges geomspace(fmin, min(fmax, sr/2), B+1); a band's magnitude is the largest
  magnitude among bins q with edge_b ≤ q·sr/N < edge_{b+1}; a band holding no bin takes the
  magnitude spectrum interpolated linearly (over bin frequency) at its geometric centre;
- loudness v = clip((20·log10(magnitude) − floor_db)/(−floor_db), 0, 1);
- smoothing s_j = m·s_{j−1} + (1 − m)·v_j, m = exp(−1/(rate·τ)), s_{−1} = 0;
- `times[j] = j / rate`; between frames values are interpolated linearly (`Spectrogram.at`).
"""

from __future__ import annotations

import math
import os
from collections.abc import Iterator
from dataclasses import dataclass

import numpy as np

from eigendance.errors import EigendanceError

FORMAT_KEYS = ("times", "band_edges", "values", "rate", "sample_rate", "duration")

# Suffixes read by libsndfile first; the rest go straight to PyAV.
SOUNDFILE_SUFFIXES = (".wav", ".wave", ".flac", ".ogg", ".oga", ".mp3", ".aif", ".aiff")

CHUNK_SAMPLES = 1 << 18  # samples per decoded chunk (per channel): ≈ 6 s at 44.1 kHz
FRAME_BATCH = 1024  # analysis frames per batched FFT


def window_length(sample_rate: float) -> int:
    """N = the smallest power of two ≥ 0.046·sr (2048 at 44.1 and 48 kHz)."""
    return 1 << max(0, math.ceil(math.log2(0.046 * sample_rate)))


def frame_count(sample_count: int, sample_rate: int, rate: float) -> int:
    """Number of analysis frames: ⌊duration·rate⌋ + 1."""
    return int(math.floor(sample_count * rate / sample_rate)) + 1


def frame_centres(first: int, stop: int, sample_rate: int, rate: float) -> np.ndarray:
    """c_j = ⌊j·sr/rate + ½⌋ for j in [first, stop), as int64."""
    j = np.arange(first, stop, dtype=np.float64)
    return np.floor(j * sample_rate / rate + 0.5).astype(np.int64)


def band_edges(bands: int, sample_rate: float, fmin: float = 20.0,
               fmax: float = 16000.0) -> np.ndarray:
    """geomspace(fmin, min(fmax, sr/2), bands + 1)."""
    return np.geomspace(fmin, min(fmax, sample_rate / 2), bands + 1)


# ---------------------------------------------------------------------------------------------
# Decoding


def _one_line(error: BaseException) -> str:
    return (" ".join(str(error).split()) or type(error).__name__)[:200]


def open_audio(path: str | os.PathLike) -> tuple[int, Iterator[np.ndarray]]:
    """Open an audio file: (sample rate, iterator over mono float64 chunks).

    Raises EigendanceError with one line for a missing, empty, unreadable or corrupt file.
    """
    path = os.fspath(path)
    name = os.path.basename(path)
    if not os.path.isfile(path):
        raise EigendanceError(f"{path}: no such file")
    if os.path.getsize(path) == 0:
        raise EigendanceError(f"{name}: the file is empty")
    if os.path.splitext(path)[1].lower() in SOUNDFILE_SUFFIXES:
        opened = _open_soundfile(path)
        if opened is not None:
            return opened
    return _open_pyav(path)


def _open_soundfile(path: str):
    import soundfile

    try:
        file = soundfile.SoundFile(path)
    except Exception:  # libsndfile refuses it: let FFmpeg try
        return None
    if file.channels < 1 or file.samplerate < 1:
        file.close()
        return None
    name = os.path.basename(path)

    def chunks():
        with file:
            while True:
                try:
                    block = file.read(CHUNK_SAMPLES, dtype="float32", always_2d=True)
                except Exception as error:
                    raise EigendanceError(f"{name}: corrupt audio data "
                                          f"({_one_line(error)})") from None
                if len(block) == 0:
                    return
                yield block.mean(axis=1, dtype=np.float64)

    return int(file.samplerate), chunks()


_INTEGER_SCALE = {"u8": 128.0, "s16": 32768.0, "s32": 2147483648.0, "s64": 9223372036854775808.0}


def _open_pyav(path: str):
    import av

    name = os.path.basename(path)
    try:
        container = av.open(path)
    except Exception as error:
        raise EigendanceError(f"{name}: not a readable audio file ({_one_line(error)})") from None
    streams = [stream for stream in container.streams if stream.type == "audio"]
    if not streams:
        container.close()
        raise EigendanceError(f"{name}: the file holds no audio stream")
    stream = streams[0]
    frames = container.decode(stream)
    try:  # the first frame's rate is the truth (HE-AAC streams may announce half of it)
        first = next(frames, None)
    except Exception as error:
        container.close()
        raise EigendanceError(f"{name}: corrupt audio data ({_one_line(error)})") from None
    sample_rate = int(first.sample_rate if first is not None
                      else stream.codec_context.sample_rate or 0)
    if sample_rate < 1:
        container.close()
        raise EigendanceError(f"{name}: the audio stream has no sample rate")

    def chunks():
        with container:
            if first is None:
                return
            yield _mono(first)
            try:
                for frame in frames:
                    if frame.sample_rate != sample_rate:
                        raise EigendanceError(f"{name}: the sample rate changes inside the "
                                              f"stream ({sample_rate} → {frame.sample_rate} Hz)")
                    yield _mono(frame)
            except EigendanceError:
                raise
            except Exception as error:
                raise EigendanceError(f"{name}: corrupt audio data "
                                      f"({_one_line(error)})") from None

    return sample_rate, chunks()


def _mono(frame) -> np.ndarray:
    """One PyAV audio frame → mono float64: the mean of its channels, in [-1, 1]."""
    array = frame.to_ndarray()
    channels = len(frame.layout.channels)
    if not frame.format.is_planar:
        array = array.reshape(-1, channels).T
    kind = frame.format.name.rstrip("p")
    if kind in _INTEGER_SCALE:
        offset = 128.0 if kind == "u8" else 0.0
        return (array.mean(axis=0, dtype=np.float64) - offset) / _INTEGER_SCALE[kind]
    return array.mean(axis=0, dtype=np.float64)


def read_audio(path: str | os.PathLike) -> tuple[np.ndarray, int]:
    """The whole file as mono float64 samples (for short files and tests) and its sample rate."""
    sample_rate, chunks = open_audio(path)
    parts = list(chunks)
    samples = np.concatenate(parts) if parts else np.zeros(0)
    return samples, sample_rate


def mono(samples) -> np.ndarray:
    """(n,) or (n, channels) samples → mono float64 by the mean of the channels.

    Float samples are taken as they are (full scale ±1); integer PCM is scaled by 2^(bits−1).
    """
    samples = np.asarray(samples)
    if np.issubdtype(samples.dtype, np.integer):
        samples = samples / float(2 ** (8 * samples.dtype.itemsize - 1))
    if samples.ndim == 1:
        return samples.astype(np.float64)
    if samples.ndim == 2 and samples.shape[1] >= 1:
        return samples.mean(axis=1, dtype=np.float64)
    raise EigendanceError(f"samples must be (n,) or (n, channels), got {samples.shape}")


# ---------------------------------------------------------------------------------------------
# Analysis


def hann(length: int) -> np.ndarray:
    """Periodic Hann window, 0.5 − 0.5·cos(2πn/N) (= scipy.signal.get_window('hann', N))."""
    return 0.5 - 0.5 * np.cos(2 * np.pi * np.arange(length) / length)


def exponential_smoothing(values: np.ndarray, memory: float, previous) -> np.ndarray:
    """s_j = m·s_{j−1} + (1 − m)·v_j along axis 0, s_{−1} = previous; vectorised over frames.

    Closed form per block: s_j = m^(j+1)·s_{−1} + (1 − m)·m^j·Σ_{i≤j} m^(−i)·v_i, in blocks
    short enough that m^(−i) stays far from overflow (all terms are positive: no cancellation).
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


class _Analyser:
    """Streaming spectrogram: feed mono chunks, get smoothed band values chunk by chunk."""

    def __init__(self, sample_rate, rate, bands, fmin, fmax, floor_db, smoothing):
        if not (isinstance(sample_rate, int | np.integer) and sample_rate > 0):
            raise EigendanceError(f"sample rate must be a positive integer, got {sample_rate}")
        if not (np.isfinite(rate) and rate > 0):
            raise EigendanceError(f"--rate must be a positive number of frames per second, "
                                  f"got {rate}")
        if not (isinstance(bands, int | np.integer) and bands >= 1):
            raise EigendanceError(f"--bands must be a positive integer, got {bands}")
        top = min(fmax, sample_rate / 2)
        if not (0 < fmin < top):
            raise EigendanceError(f"the band range {fmin:g}–{top:g} Hz is empty at a sample "
                                  f"rate of {sample_rate} Hz")
        if not floor_db < 0:
            raise EigendanceError(f"the loudness floor must be negative (dB), got {floor_db}")
        if not smoothing >= 0:
            raise EigendanceError(f"smoothing must be ≥ 0 s, got {smoothing}")
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

    def feed(self, chunk: np.ndarray) -> None:
        chunk = np.asarray(chunk).ravel()
        if not np.all(np.isfinite(chunk)):
            raise EigendanceError("the audio holds NaN or infinite samples")
        self.total += len(chunk)
        self.buffer = np.concatenate([self.buffer, chunk.astype(np.float32)])
        self._process(final=False)

    def finish(self) -> np.ndarray:
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
        from scipy.fft import rfft

        magnitude = np.abs(rfft(frames * self.window, axis=1))  # float32
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


@dataclass
class Spectrogram:
    """Banded loudness of a track (DESIGN §3): values[j, b] ∈ [0, 1] at times[j] = j / rate."""

    times: np.ndarray  # (T,) seconds
    band_edges: np.ndarray  # (B+1,) Hz
    values: np.ndarray  # (T, B) float32
    rate: float
    sample_rate: int
    duration: float

    @property
    def bands(self) -> int:
        return self.values.shape[1]

    @property
    def band_centres(self) -> np.ndarray:
        """Geometric centre √(edge_b · edge_{b+1}) of each band, Hz."""
        return np.sqrt(self.band_edges[:-1] * self.band_edges[1:])

    @classmethod
    def from_chunks(cls, chunks, sample_rate: int, rate: float = 100, bands: int = 64,
                    fmin: float = 20.0, fmax: float = 16000.0, floor_db: float = -80.0,
                    smoothing: float = 0.08) -> Spectrogram:
        """Analyse an iterable of mono float chunks (the streaming core of the other builders)."""
        analyser = _Analyser(sample_rate, rate, bands, fmin, fmax, floor_db, smoothing)
        for chunk in chunks:
            analyser.feed(chunk)
        values = analyser.finish()
        return cls(np.arange(len(values)) / float(rate), analyser.edges, values, float(rate),
                   int(sample_rate), analyser.total / sample_rate)

    @classmethod
    def from_samples(cls, samples, sample_rate: int, rate: float = 100, bands: int = 64,
                     fmin: float = 20.0, fmax: float = 16000.0, floor_db: float = -80.0,
                     smoothing: float = 0.08) -> Spectrogram:
        """From PCM samples (n,) or (n, channels) in [-1, 1]; channels are averaged."""
        samples = mono(samples)
        chunks = (samples[i:i + CHUNK_SAMPLES] for i in range(0, len(samples), CHUNK_SAMPLES))
        return cls.from_chunks(chunks, sample_rate, rate, bands, fmin, fmax, floor_db, smoothing)

    @classmethod
    def from_file(cls, path: str | os.PathLike, rate: float = 100, bands: int = 64,
                  fmin: float = 20.0, fmax: float = 16000.0, floor_db: float = -80.0,
                  smoothing: float = 0.08) -> Spectrogram:
        """Decode and analyse an audio file in bounded memory (see the module docstring)."""
        sample_rate, chunks = open_audio(path)
        return cls.from_chunks(chunks, sample_rate, rate, bands, fmin, fmax, floor_db, smoothing)

    def at(self, times) -> np.ndarray:
        """Values at arbitrary times (…,) → (…, B) float64, linear between frames, clamped."""
        times = np.asarray(times, dtype=np.float64)
        values = self.values
        if len(values) == 1:
            return np.broadcast_to(values[0].astype(np.float64),
                                   (*times.shape, self.bands)).copy()
        position = times * self.rate
        index = np.clip(np.floor(position), 0, len(values) - 2).astype(np.int64)
        weight = np.clip(position - index, 0.0, 1.0)[..., None]
        below = values[index].astype(np.float64)
        above = values[index + 1].astype(np.float64)
        return below * (1 - weight) + above * weight

    def save(self, path: str | os.PathLike) -> None:
        """Write the spectrogram file of DESIGN §8 atomically."""
        from eigendance.files import atomic_save_npz

        atomic_save_npz(path, times=self.times, band_edges=self.band_edges,
                        values=self.values.astype(np.float32), rate=np.float64(self.rate),
                        sample_rate=np.int64(self.sample_rate),
                        duration=np.float64(self.duration))

    @classmethod
    def load(cls, path: str | os.PathLike) -> Spectrogram:
        """Read a spectrogram file; a missing key or inconsistent shape raises EigendanceError."""
        from eigendance.files import load_npz

        data = load_npz(path, FORMAT_KEYS)
        spectrogram = cls(data["times"], data["band_edges"], data["values"],
                          float(data["rate"]), int(data["sample_rate"]), float(data["duration"]))
        values = spectrogram.values
        if (values.ndim != 2 or spectrogram.times.shape != (len(values),)
                or spectrogram.band_edges.shape != (values.shape[1] + 1,)):
            raise EigendanceError(f"{os.fspath(path)}: inconsistent array shapes in "
                                  "spectrogram file")
        return spectrogram

    def save_png(self, path: str | os.PathLike, title: str | None = None) -> None:
        """Picture: time across, band (labelled in Hz) up, loudness as colour (PNG, SVG…)."""
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        from eigendance.files import atomic_write

        width = min(16.0, max(6.0, 2 + self.duration / 4))
        figure, axes = plt.subplots(figsize=(width, 4.5), dpi=100)
        image = axes.imshow(self.values.T, origin="lower", aspect="auto", cmap="magma",
                            vmin=0, vmax=1, interpolation="nearest",
                            extent=(-0.5 / self.rate, (len(self.values) - 0.5) / self.rate,
                                    -0.5, self.bands - 0.5))
        ticks = [b for b in range(0, self.bands, max(1, self.bands // 8))]
        axes.set_yticks(ticks)
        axes.set_yticklabels([f"{self.band_centres[b]:.0f}" for b in ticks])
        axes.set_xlabel("time (s)")
        axes.set_ylabel("band centre (Hz)")
        axes.set_title(title or f"{self.bands} bands, {self.rate:g} frames/s, "
                                f"{self.sample_rate} Hz")
        figure.colorbar(image, ax=axes, label="loudness")
        figure.tight_layout()
        suffix = os.path.splitext(os.fspath(path))[1].lstrip(".").lower() or "png"
        atomic_write(path, lambda file: figure.savefig(file, format=suffix))
        plt.close(figure)
