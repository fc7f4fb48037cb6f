"""The banded loudness spectrogram of music (docs/design.md#spectrogram).

The analysis runs chunk by chunk on the decoder's output, so memory stays bounded by the chunk
size plus the result (T × B float32 values) however long the track is.

One definition for every consumer (browser, video, glTF, both pipelines):

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
import time
from dataclasses import dataclass, replace

import numpy as np

from eigendance.errors import InputError
from eigendance.files import checked_array, load_npz
from eigendance.music.analyser import (
    MAX_FRAMES,
    MAX_SAMPLE_RATE,
    Analyser,
    band_edges,
    exponential_smoothing,
    frame_centres,
    hann,
    window_length,
)
from eigendance.music.decode import CHUNK_SAMPLES, mono, open_audio
from eigendance.music.rhythm import Rhythm, analyse_rhythm, rhythm_arrays, rhythm_from_arrays
from eigendance.writes import atomic_save_npz, atomic_write

__all__ = ["Spectrogram", "band_edges", "check_picture_path", "frame_centres", "frame_times",
           "hann", "save_picture", "warm_up", "window_length"]

FORMAT_KEYS = ("times", "band_edges", "values", "rate", "sample_rate", "duration")
FILE_VERSION = 2  # written (with the rhythm); version 1 (no `version` field, no rhythm) is read


@dataclass
class Spectrogram:
    """Banded loudness of a track: values[j, b] ∈ [0, 1] at times[j] = j / rate.

    The builders take the analysis options of docs/design.md#spectrogram as keywords, with
    these defaults: rate=100 frames/s, bands=64, fmin=20 Hz, fmax=16 kHz, floor_db=−80 dB,
    smoothing=0.08 s.

    Parameters
    ----------
    times : (T,) s.
    band_edges : (B+1,) Hz.
    values : (T, B) in [0, 1].
    rate : frames per second.
    sample_rate : the audio's, Hz.
    duration : the audio's, s.
    rhythm : the song's onsets, beats and tempo (`music.rhythm.Rhythm`, docs/design.md#rhythm),
        or None (a version-1 file, or analysed with rhythm=False).

    Example
    -------
    >>> sine = np.sin(2 * np.pi * 440 * np.arange(44100) / 44100)   # 1 s of A4, full scale
    >>> spectrogram = Spectrogram.from_samples(sine, 44100)
    >>> spectrogram.values.shape, round(float(spectrogram.duration), 3)
    ((101, 64), 1.0)
    >>> loudest = spectrogram.values[50].argmax()
    >>> bool(spectrogram.band_edges[loudest] <= 440 < spectrogram.band_edges[loudest + 1])
    True
    """

    times: np.ndarray  # (T,) seconds
    band_edges: np.ndarray  # (B+1,) Hz
    values: np.ndarray  # (T, B) float32
    rate: float
    sample_rate: int
    duration: float
    rhythm: Rhythm | None = None  # None: a version-1 file, or analysed without rhythm

    @property
    def bands(self) -> int:
        """B."""
        return self.values.shape[1]

    @property
    def band_centres(self) -> np.ndarray:
        """Geometric centre √(edge_b · edge_{b+1}) of each band, Hz."""
        return np.sqrt(self.band_edges[:-1] * self.band_edges[1:])

    @classmethod
    def from_chunks(cls, chunks, sample_rate: int, **options) -> Spectrogram:
        """Analyse an iterable of mono float chunks (the streaming core of the other builders).

        options: those of the class docstring, name (how messages call the audio) and rhythm
        (default True: also the rhythm of docs/design.md#rhythm).

        Parameters
        ----------
        chunks : iterable of (m,) float arrays.
        sample_rate : Hz.
        **options : rate, bands, fmin, fmax, floor_db, smoothing, name, rhythm.

        Returns
        -------
        Spectrogram (with its `rhythm` unless rhythm=False).
        """
        analyser = Analyser(sample_rate, **options)
        for chunk in chunks:
            analyser.feed(chunk)
        values = analyser.finish()
        rhythm = None
        if analyser.onsets is not None:
            envelope = np.concatenate(analyser.envelope) if analyser.envelope else \
                np.zeros(len(values), np.float32)
            rhythm = analyse_rhythm(envelope, analyser.rate, analyser.features.finish())
        return cls(np.arange(len(values)) / analyser.rate, analyser.edges, values,
                   analyser.rate, int(sample_rate), analyser.total / sample_rate, rhythm)

    @classmethod
    def from_samples(cls, samples, sample_rate: int, **options) -> Spectrogram:
        """From PCM samples (n,) or (n, channels) in [-1, 1]; channels are averaged.

        Parameters
        ----------
        samples : (n,) or (n, channels).
        sample_rate : Hz.
        **options : as for `from_chunks`.

        Returns
        -------
        Spectrogram.
        """
        samples = mono(samples)
        chunks = (samples[i:i + CHUNK_SAMPLES] for i in range(0, len(samples), CHUNK_SAMPLES))
        return cls.from_chunks(chunks, sample_rate, **options)

    @classmethod
    def from_file(cls, path: str | os.PathLike, **options) -> Spectrogram:
        """Decode and analyse an audio file in bounded memory (any format `open_audio` reads).

        Parameters
        ----------
        path : the audio file.
        options : rate, bands, fmin, fmax, floor_db, smoothing (see the class docstring).

        Returns
        -------
        Spectrogram with T = ⌊duration·rate⌋ + 1 frames of B bands.
        """
        sample_rate, chunks = open_audio(path)
        return cls.from_chunks(chunks, sample_rate, name=os.path.basename(os.fspath(path)),
                               **options)

    def at(self, times) -> np.ndarray:
        """Values at arbitrary times (…,) s → (…, B) float64, linear between frames, clamped.

        Parameters
        ----------
        times : (…,) s.

        Returns
        -------
        (…, B).
        """
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

    def smoothed(self, smoothing: float) -> Spectrogram:
        """The spectrogram smoothed once more over its frames, with time constant `smoothing` s.

        s_j = m·s_{j−1} + (1 − m)·v_j, m = exp(−1/(rate·smoothing)), s_{−1} = 0 (the player's
        smoothing slider, web/src/filter.ts `smoothed`); 0 returns the spectrogram itself.

        Parameters
        ----------
        smoothing : s ≥ 0.

        Returns
        -------
        Spectrogram.
        """
        if not smoothing > 0:
            return self
        memory = math.exp(-1.0 / (self.rate * smoothing))
        values = exponential_smoothing(self.values, memory, np.zeros(self.bands))
        return replace(self, values=values.astype(np.float32))

    def save(self, path: str | os.PathLike) -> None:
        """Write the spectrogram file (docs/design.md#spectrogram-file) atomically: version 2
        with the rhythm, version 1 (the same fields as before) for a spectrogram without it.

        Parameters
        ----------
        path : the .npz to write.
        """
        extra = {} if self.rhythm is None else \
            {"version": np.int64(FILE_VERSION), **rhythm_arrays(self.rhythm)}
        atomic_save_npz(path, times=self.times, band_edges=self.band_edges,
                        values=self.values.astype(np.float32), rate=np.float64(self.rate),
                        sample_rate=np.int64(self.sample_rate),
                        duration=np.float64(self.duration), **extra)

    @classmethod
    def load(cls, path: str | os.PathLike) -> Spectrogram:
        """Read a spectrogram file, checked: InputError naming the field for anything that
        breaks docs/design.md#spectrogram-file (a missing field, a wrong type or shape, NaN,
        values outside [0, 1], frame times that do not follow from the rate and duration).
        Version 1 (no `version` field) has no rhythm; version 2 holds it.

        Parameters
        ----------
        path : a spectrogram file.

        Returns
        -------
        Spectrogram.
        """
        path = os.fspath(path)
        data = load_npz(path, FORMAT_KEYS)
        values = checked_array(data, "values", path, shape=(None, None))
        count, bands = values.shape
        if count < 1 or bands < 1:
            raise InputError(f"{path}: the spectrogram has no frames or no bands")
        times = checked_array(data, "times", path, shape=(count,))
        edges = checked_array(data, "band_edges", path, shape=(bands + 1,))
        rate, duration = (float(checked_array(data, name, path)) for name in ("rate", "duration"))
        sample_rate = int(checked_array(data, "sample_rate", path, "int"))
        if not (np.all((values >= 0) & (values <= 1))):
            raise InputError(f"{path}: values must lie in [0, 1]")
        if not (np.all(edges > 0) and np.all(np.diff(edges) > 0)):
            raise InputError(f"{path}: band_edges must be positive and increasing")
        if not (rate > 0 and duration >= 0 and 0 < sample_rate <= MAX_SAMPLE_RATE):
            raise InputError(f"{path}: rate must be positive, duration ≥ 0 and sample_rate from "
                             f"1 to {MAX_SAMPLE_RATE} Hz")
        if abs(math.floor(duration * rate) + 1 - count) > 1 or not np.allclose(
                times, np.arange(count) / rate, rtol=1e-9, atol=1e-9):
            raise InputError(f"{path}: {count} frames do not fit a duration of {duration:g} s "
                             f"at {rate:g} frames per second (times[j] = j / rate)")
        version = int(checked_array(data, "version", path, "int")) if "version" in data else 1
        if version not in (1, FILE_VERSION):
            raise InputError(f"{path}: version must be 1 or {FILE_VERSION}, got {version}")
        rhythm = None if version == 1 else \
            rhythm_from_arrays(data, path, count, rate, duration)
        return cls(times, edges, values.astype(np.float32), rate, sample_rate, duration, rhythm)


def frame_times(duration: float, fps: float) -> np.ndarray:
    """Frame times 0, 1/fps, … up to `duration` (s) included: ⌊duration·fps⌋ + 1 frames.

    Parameters
    ----------
    duration : s ≥ 0.
    fps : frames per second.

    Returns
    -------
    (⌊duration·fps⌋ + 1,) s; InputError beyond MAX_FRAMES.
    """
    if not (np.isfinite(fps) and fps > 0):
        raise InputError(f"frames per second must be a positive number, got {fps}")
    if not (np.isfinite(duration) and duration >= 0):
        raise InputError(f"the duration must be a finite number of seconds ≥ 0, got {duration}")
    count = math.floor(duration * fps + 1e-9) + 1
    if count > MAX_FRAMES:
        raise InputError(f"{duration:g} s at {fps:g} frames per second make {count} frames; "
                         f"at most {MAX_FRAMES} are made at once (use fewer frames per second)")
    return np.arange(count) / float(fps)


PICTURE_FORMATS = ("png", "svg", "pdf", "jpg", "jpeg")


def check_picture_path(path: str | os.PathLike) -> str:
    """The picture format named by the suffix of `path`; InputError for one we cannot draw.

    Parameters
    ----------
    path : the picture to write.

    Returns
    -------
    str, "png", "svg", "pdf" or "jpg".
    """
    suffix = os.path.splitext(os.fspath(path))[1].lstrip(".").lower()
    if suffix not in PICTURE_FORMATS:
        raise InputError(f"{os.fspath(path)}: cannot draw a picture of type '{suffix}' "
                         f"(use {', '.join(PICTURE_FORMATS)})")
    return suffix


def save_picture(spectrogram: Spectrogram, path: str | os.PathLike,
                 title: str | None = None) -> None:
    """Draw a spectrogram: time across, band (labelled in Hz) up, loudness as colour; the
    beats (if any) as white ticks along the top edge with thin lines across.

    Parameters
    ----------
    spectrogram : the song.
    path : .png, .svg, .pdf or .jpg.
    title : drawn above, or None.
    """
    from matplotlib.figure import Figure  # heavy (≈0.5 s): only for pictures

    format = check_picture_path(path)
    width = min(16.0, max(6.0, 2 + spectrogram.duration / 4))
    figure = Figure(figsize=(width, 4.5), dpi=100)
    axes = figure.subplots()
    rate, bands = spectrogram.rate, spectrogram.bands
    image = axes.imshow(spectrogram.values.T, origin="lower", aspect="auto", cmap="magma",
                        vmin=0, vmax=1, interpolation="nearest",
                        extent=(-0.5 / rate, (len(spectrogram.values) - 0.5) / rate,
                                -0.5, bands - 0.5))
    ticks = list(range(0, bands, max(1, bands // 8)))
    axes.set_yticks(ticks)
    axes.set_yticklabels([f"{spectrogram.band_centres[b]:.0f}" for b in ticks])
    rhythm = spectrogram.rhythm
    if rhythm is not None and len(rhythm.beats):
        axes.vlines(rhythm.beats, -0.5, bands - 0.5, colors="white", linewidths=0.4,
                    alpha=0.35)
        axes.plot(rhythm.beats, np.full(len(rhythm.beats), bands - 1.5), "v", color="white",
                  markersize=3, label=f"beats ({rhythm.tempo:.0f} BPM)")
        axes.legend(loc="lower right", fontsize="small", framealpha=0.5)
    axes.set_xlabel("time (s)")
    axes.set_ylabel("band centre (Hz)")
    axes.set_title(title or f"{bands} bands, {rate:g} frames/s, {spectrogram.sample_rate} Hz")
    figure.colorbar(image, ax=axes, label="loudness")
    figure.tight_layout()
    atomic_write(path, lambda file: figure.savefig(file, format=format))


def warm_up() -> float:
    """Analyse two seconds of clicks once, so that numba compiles (and caches on disk) librosa's
    kernels now rather than at the first song (2–10 s the first time ever). `make setup` (so
    `make demo` and `make test`) calls it.

    Returns
    -------
    float: the seconds it took.
    """
    start = time.perf_counter()
    clicks = np.zeros(2 * 22050)
    clicks[::11025] = 1.0
    Spectrogram.from_samples(clicks, 22050)
    return time.perf_counter() - start
