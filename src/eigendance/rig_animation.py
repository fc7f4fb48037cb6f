"""Animate a rig: modal model → music-driven coefficients → body transforms → skinned vertices.

Used by `eigendance modes` and `eigendance animate-rig`. The drive φ (frames × modes) is a plain
array, so the project's mapping (eigendance.mapping, `Mapping.filter(values)`) can replace the
simple built-in one here: `band_drive` over the loudness of `bands` log-spaced bands of a sound
file read with soundfile (WAV, FLAC, OGG …), or φ ≡ 1 without audio.
"""

from __future__ import annotations

import math
import os

import numpy as np

from eigendance.errors import EigendanceError
from eigendance.files import atomic_save_npz
from eigendance.modal import ModalModel
from eigendance.sample_rigs import SAMPLE_RIGS, add_tube_skin, sample_rig
from eigendance.skeleton import Skeleton
from eigendance.skinning import ModalSkin, linear_blend_skinning

FRAME_CHUNK = 64  # frames skinned per batch (bounds the memory of linear blend skinning)


def load_rig(rig: str) -> Skeleton:
    """A skeleton JSON or glTF file, or the name of a built-in sample rig (loop4, loop8,
    loop16, chain) when no such file exists. A skeleton without mesh gets a tube skin."""
    if rig in SAMPLE_RIGS and not os.path.exists(rig):
        return sample_rig(rig)
    skeleton = Skeleton.load(rig)
    if skeleton.vertices is None:
        add_tube_skin(skeleton)
    return skeleton


def mode_table(model: ModalModel, top: int = 3, limit: int | None = None) -> list[str]:
    """Lines: index, frequency (Hz) and the bodies carrying most of each mode's energy."""
    energy = model.body_energy()
    lines = [f"{'mode':>5} {'frequency Hz':>13}  bodies that move most (share of energy)"]
    count = model.n_modes if limit is None else min(limit, model.n_modes)
    for index in range(count):
        order = np.argsort(energy[:, index])[::-1][:top]
        movers = ", ".join(f"{model.body_names[b]} {energy[b, index]:.0%}" for b in order)
        lines.append(f"{index:>5} {model.frequencies[index]:>13.4f}  {movers}")
    if count < model.n_modes:
        lines.append(f"  … {model.n_modes - count} more (all are in the file)")
    return lines


def parse_modes(text: str | None, n_modes: int) -> np.ndarray:
    """'0,2,5-8' → indices; None → the lowest min(8, n_modes) modes."""
    if text is None:
        return np.arange(min(8, n_modes))
    indices = []
    try:
        for part in text.split(","):
            part = part.strip()
            if "-" in part:
                low, high = (int(v) for v in part.split("-", 1))
                indices.extend(range(low, high + 1))
            elif part:
                indices.append(int(part))
    except ValueError:
        raise EigendanceError(f"--modes {text!r}: expected indices like 0,2,5-8") from None
    bad = [i for i in indices if not 0 <= i < n_modes]
    if bad:
        raise EigendanceError(f"--modes: mode {bad[0]} does not exist (the rig has {n_modes} "
                              f"vibration modes, 0 … {n_modes - 1})")
    if not indices:
        raise EigendanceError("--modes selects no mode")
    return np.array(sorted(set(indices)))


def read_audio(path: str) -> tuple[np.ndarray, int]:
    """Mono float samples (channels averaged) and the sample rate, via soundfile."""
    try:
        import soundfile
    except ImportError:  # pragma: no cover - a declared dependency
        raise EigendanceError("reading audio needs the soundfile package") from None
    if not os.path.exists(path):
        raise EigendanceError(f"{path}: no such file")
    try:
        samples, rate = soundfile.read(path, dtype="float64", always_2d=True)
    except (RuntimeError, ValueError, TypeError, soundfile.LibsndfileError) as error:
        message = " ".join(str(error).split())
        raise EigendanceError(f"{path}: cannot decode audio ({message})") from None
    if not len(samples):
        raise EigendanceError(f"{path}: the audio has no samples")
    return samples.mean(axis=1), int(rate)


def band_loudness(samples, rate: int, times, bands: int = 16, floor_db: float = -80.0,
                  smoothing: float = 0.08) -> np.ndarray:
    """(T, bands) loudness in [0, 1] at `times`: Hann-windowed |FFT| (2048 samples at 44.1 kHz)
    around each time, the largest magnitude in each of `bands` bands log-spaced from 20 Hz to
    min(16 kHz, rate/2), in dB over [floor_db, 0], smoothed with time constant `smoothing` s.
    A simple stand-in for the project's spectrogram (DESIGN §3)."""
    samples = np.asarray(samples, dtype=float)
    times = np.asarray(times, dtype=float)
    size = 1 << math.ceil(math.log2(0.046 * rate))
    window = 0.5 - 0.5 * np.cos(2 * np.pi * np.arange(size) / size)  # periodic Hann
    centres = np.round(times * rate).astype(np.int64)
    padded = np.concatenate([np.zeros(size // 2), samples, np.zeros(size)])
    index = centres[:, None] + np.arange(size)[None, :]  # offset by the leading padding
    index = np.clip(index, 0, len(padded) - 1)
    magnitude = np.abs(np.fft.rfft(padded[index] * window, axis=1)) * 2 / window.sum()
    frequencies = np.fft.rfftfreq(size, 1 / rate)
    edges = np.geomspace(20.0, min(16000.0, rate / 2), bands + 1)
    values = np.zeros((len(times), bands))
    for band in range(bands):
        inside = (frequencies >= edges[band]) & (frequencies < edges[band + 1])
        if np.any(inside):
            values[:, band] = magnitude[:, inside].max(axis=1)
        else:
            centre = math.sqrt(edges[band] * edges[band + 1])
            values[:, band] = [np.interp(centre, frequencies, row) for row in magnitude]
    decibels = 20 * np.log10(np.maximum(values, 1e-12))
    loudness = np.clip((decibels - floor_db) / -floor_db, 0, 1)
    step = float(np.median(np.diff(times))) if len(times) > 1 else 1.0
    keep = math.exp(-step / smoothing)
    smoothed = np.zeros_like(loudness)
    state = np.zeros(bands)
    for frame in range(len(times)):
        state = keep * state + (1 - keep) * loudness[frame]
        smoothed[frame] = state
    return smoothed


def animate_rig(skeleton: Skeleton, model: ModalModel, times, modes, amplitude: float = 0.3,
                time_scale: float = 1.0, drive=None, skinning: str = "modal",
                progress=None) -> dict:
    """Arrays of the animation file: times, faces, float32 positions (T, n, 3), body
    rotations/centres/transforms per frame, the coefficients and the modes used."""
    times = np.asarray(times, dtype=float)
    amplitudes = model.default_amplitudes(amplitude, size=skeleton.size)
    phases = np.linspace(0, math.pi, model.n_modes, endpoint=False)
    coefficients = model.coefficients(times, amplitudes, phases, time_scale, drive, modes)
    transforms = model.body_transforms(coefficients)
    rotations, centers = model.body_poses(coefficients)
    positions = np.empty((len(times), len(skeleton.vertices), 3), dtype=np.float32)
    skin = ModalSkin(model, skeleton.vertices, skeleton.weights, dtype=np.float32) \
        if skinning == "modal" else None
    for start in range(0, len(times), FRAME_CHUNK):
        stop = min(start + FRAME_CHUNK, len(times))
        if skin is not None:
            positions[start:stop] = skin.positions(coefficients[start:stop])
        else:
            positions[start:stop] = linear_blend_skinning(skeleton.vertices, skeleton.weights,
                                                          transforms[start:stop])
        if progress is not None:
            progress(stop)
    return {"times": times, "faces": skeleton.faces.astype(np.int64), "positions": positions,
            "rest_vertices": skeleton.vertices, "weights": skeleton.weights.astype(np.float32),
            "body_names": np.array(model.body_names, dtype=str),
            "body_rotations": rotations, "body_centers": centers,
            "body_transforms": transforms.astype(np.float32), "coefficients": coefficients,
            "modes": np.asarray(modes, dtype=np.int64),
            "frequencies": model.frequencies, "skinning": np.array(skinning)}


def save_animation(path, arrays: dict) -> None:
    atomic_save_npz(path, **arrays)
