"""Spectrogram speed: a 3-minute stereo 44.1 kHz track, decoded and analysed
(docs/design.md#spectrogram).

Prints the project's figure (times real time, decode included; target ≥ 200×) beside a baseline
measured in the same run: the same definition computed frame by frame in a Python loop (one FFT
and one band loop per frame), on the same decoded samples. Not run by CI.

    python benchmarks/bench_spectrum.py [--seconds 180] [--format wav|flac|ogg|mp3]
"""

from __future__ import annotations

import argparse
import math
import os
import tempfile
import time

import numpy as np
import soundfile

from eigendance.music.decode import read_audio
from eigendance.music.demo_music import demo_track
from eigendance.music.spectrogram import Spectrogram, band_edges, frame_centres, hann


def stereo_track(seconds: float) -> tuple[np.ndarray, int]:
    """The demo music repeated to `seconds`, with a delayed, quieter copy on the right."""
    samples, sr = demo_track()
    count = int(seconds * sr)
    left = np.resize(samples, count)
    right = 0.6 * np.roll(left, sr // 7)
    return np.stack([left, right], axis=1), sr


def naive_spectrogram(samples: np.ndarray, sr: int, rate=100.0, bands=64, floor_db=-80.0,
                      smoothing=0.08) -> np.ndarray:
    """docs/design.md#spectrogram written the obvious way: a Python loop over frames and bands."""
    N = 1 << math.ceil(math.log2(0.046 * sr))
    window = hann(N)
    edges = band_edges(bands, sr)
    frequencies = np.arange(N // 2 + 1) * sr / N
    count = int(math.floor(len(samples) * rate / sr)) + 1
    padded = np.concatenate([np.zeros(N // 2), samples, np.zeros(N + 1)])
    memory = math.exp(-1 / (rate * smoothing))
    state = np.zeros(bands)
    out = np.empty((count, bands), np.float32)
    for j, centre in enumerate(frame_centres(0, count, sr, rate)):
        magnitude = np.abs(np.fft.rfft(padded[centre:centre + N] * window)) * 2 / window.sum()
        values = np.empty(bands)
        for b in range(bands):
            inside = (frequencies >= edges[b]) & (frequencies < edges[b + 1])
            if inside.any():
                values[b] = magnitude[inside].max()
            else:
                values[b] = np.interp(math.sqrt(edges[b] * edges[b + 1]), frequencies, magnitude)
        loud = np.clip((20 * np.log10(np.maximum(values, 1e-30)) - floor_db) / -floor_db, 0, 1)
        state = memory * state + (1 - memory) * loud
        out[j] = state
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=180.0)
    parser.add_argument("--format", default="wav", choices=["wav", "flac", "ogg", "mp3"])
    args = parser.parse_args()
    samples, sr = stereo_track(args.seconds)
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, f"track.{args.format}")
        soundfile.write(path, samples, sr)
        size = os.path.getsize(path) / 1e6
        Spectrogram.from_samples(samples[: sr], sr)  # warm-up: imports, FFT plans
        timings = []
        for _ in range(3):
            start = time.perf_counter()
            spectrogram = Spectrogram.from_file(path)
            timings.append(time.perf_counter() - start)
        ours = min(timings)
        decoded, _ = read_audio(path)
        start = time.perf_counter()
        reference = naive_spectrogram(decoded, sr)
        naive = time.perf_counter() - start
    difference = np.abs(reference - spectrogram.values).max()
    print(f"track: {args.seconds:.0f} s stereo {sr} Hz {args.format.upper()} ({size:.1f} MB), "
          f"{len(spectrogram.times)} frames × {spectrogram.bands} bands")
    print(f"eigendance Spectrogram.from_file (decode + analysis): {ours:.3f} s "
          f"(best of 3: {', '.join(f'{t:.3f}' for t in timings)}) = "
          f"{args.seconds / ours:.0f}× real time (target ≥ 200×)")
    print(f"baseline: Python loop over frames (analysis only): {naive:.3f} s = "
          f"{args.seconds / naive:.0f}× real time")
    print(f"ratio baseline/eigendance: {naive / ours:.1f}×; max |difference| "
          f"{difference:.2g} (float32 FFT vs float64)")


if __name__ == "__main__":
    main()
