"""Harmonic animation: vertex positions over time for a basis, a spectrogram and a mapping.

At time t the filter is φ(t) = mapping.filter(spectrogram.at(t), k) (DESIGN §3, §4) and the
positions are X_φ = X + U((φ − 1) ⊙ X̃) (DESIGN §2), returned in the mesh file's coordinates
(after clean-up): X_φ·scale + center.

`positions_at` is the reference (float64, all requested times at once). `write_animation`
streams an animation file in chunks of frames, so memory stays at a few tens of MB whatever the
length of the song and the size of the mesh. Animation file (.npz, uncompressed): `times` (T,)
seconds, `faces` (m, 3) int64, `positions` (T, n, 3) float32.
"""

from __future__ import annotations

import math
import os
import zipfile

import numpy as np

from eigendance.errors import EigendanceError

CHUNK_BYTES = 64 << 20  # float64 working set of one chunk of frames


def frame_times(duration: float, fps: float) -> np.ndarray:
    """Frame times 0, 1/fps, … up to the duration included: ⌊duration·fps⌋ + 1 frames."""
    if not (np.isfinite(fps) and fps > 0):
        raise EigendanceError(f"--fps must be a positive number, got {fps}")
    return np.arange(int(math.floor(duration * fps + 1e-9)) + 1) / float(fps)


def positions_at(basis, spectrogram, mapping, times) -> np.ndarray:
    """Reference positions (…, n, 3) float64, original coordinates, at the given times (…,)."""
    phi = mapping.filter(spectrogram.at(times), basis.k)
    return basis.to_original(basis.filter_positions(phi))


class _Deformer:
    """The fused per-chunk product: original-coordinate positions for a chunk of filters."""

    def __init__(self, basis):
        self.basis = basis
        self.rest = basis.to_original(basis.vertices)  # (n, 3)
        self.coefficients = basis.coefficients * basis.scale  # (k, 3), original units

    def __call__(self, phi: np.ndarray, out: np.ndarray) -> np.ndarray:
        """phi (C, k) → out (C, n, 3) (any float dtype): rest + U((φ − 1) ⊙ X̃·scale)."""
        count, k = phi.shape
        weights = (phi - 1.0)[:, :, None] * self.coefficients[None]  # (C, k, 3)
        moved = self.basis.eigenvectors @ weights.transpose(1, 0, 2).reshape(k, 3 * count)
        np.add(moved.reshape(-1, count, 3).transpose(1, 0, 2), self.rest[None], out=out,
               casting="unsafe")
        return out


def chunk_frames(n: int) -> int:
    """Frames per chunk so that one chunk's float64 product stays near CHUNK_BYTES."""
    return max(1, min(512, CHUNK_BYTES // max(1, n * 3 * 8)))


def write_animation(path: str | os.PathLike, basis, spectrogram, mapping, fps: float = 30.0,
                    progress=None) -> int:
    """Write the animation file (see the module docstring) atomically; returns the frame count.

    Frames are computed chunk by chunk and streamed into the .npy member of the zip, so neither
    the positions nor the file are ever held in memory. progress: optional callable(done).
    """
    times = frame_times(spectrogram.duration, fps)
    deform = _Deformer(basis)
    n = basis.n
    per_chunk = chunk_frames(n)
    header = {"descr": np.lib.format.dtype_to_descr(np.dtype("<f4")), "fortran_order": False,
              "shape": (len(times), n, 3)}
    buffer = np.empty((per_chunk, n, 3), dtype="<f4")

    def write(file):
        with zipfile.ZipFile(file, "w", zipfile.ZIP_STORED, allowZip64=True) as archive:
            for name, array in (("times", times), ("faces", np.asarray(basis.faces, np.int64))):
                with archive.open(f"{name}.npy", "w") as member:
                    np.lib.format.write_array(member, np.ascontiguousarray(array))
            with archive.open("positions.npy", "w", force_zip64=True) as member:
                np.lib.format.write_array_header_1_0(member, header)
                for first in range(0, len(times), per_chunk):
                    chunk = times[first:first + per_chunk]
                    phi = mapping.filter(spectrogram.at(chunk), basis.k)
                    out = deform(phi, buffer[:len(chunk)])
                    member.write(memoryview(out).cast("B"))
                    if progress is not None:
                        progress(first + len(chunk))

    from eigendance.files import atomic_write

    atomic_write(path, write)
    return len(times)


def load_animation(path: str | os.PathLike) -> dict:
    """Read an animation file: {"times", "faces", "positions"} (positions fully in memory)."""
    from eigendance.files import load_npz

    return load_npz(path, ("times", "faces", "positions"))


def basis_from_path(path: str | os.PathLike, k: int = 300, progress=None):
    """A basis file (.npz) as is, or a mesh file solved for k harmonics (through the cache)."""
    from eigendance.harmonics import HarmonicBasis

    if os.fspath(path).lower().endswith(".npz"):
        return HarmonicBasis.load(path)
    if not (isinstance(k, int) and k >= 2):
        raise EigendanceError(f"-k must be an integer ≥ 2, got {k}")
    from eigendance.mesh import load_mesh

    mesh = load_mesh(path)
    return HarmonicBasis.from_mesh(mesh, k, progress=progress)


def spectrogram_from_path(path: str | os.PathLike, bands: int = 64, rate: float = 100):
    """A spectrogram file (.npz) as is, or an audio file analysed with `bands` and `rate`."""
    from eigendance.audio import Spectrogram

    if os.fspath(path).lower().endswith(".npz"):
        return Spectrogram.load(path)
    return Spectrogram.from_file(path, rate=rate, bands=bands)
