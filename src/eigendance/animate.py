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

CHUNK_BYTES = 24 << 20  # float64 product of one chunk of frames (cache-friendly; measured)


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
        self.rest_rows = np.ascontiguousarray(basis.to_original(basis.vertices).T)  # (3, n)
        self.coefficients = basis.coefficients * basis.scale  # (k, 3), original units

    def __call__(self, phi: np.ndarray, out: np.ndarray) -> np.ndarray:
        """phi (C, k) → out (C, n, 3) (any float dtype): rest + U((φ − 1) ⊙ X̃·scale).

        Computed as Wᵀ·Uᵀ (3C × n; Uᵀ is a view, BLAS transposes): each row is one coordinate
        of one frame, so the scatter into (C, n, 3) reads whole rows (faster than U·W's
        (n, 3C) layout).
        """
        count, k = phi.shape
        weights = (phi - 1.0)[:, None, :] * self.coefficients.T[None]  # (C, 3, k)
        moved = (weights.reshape(3 * count, k) @ self.basis.eigenvectors.T).reshape(count, 3, -1)
        for axis in range(3):  # contiguous reads, stride-3 writes: faster than one transpose
            np.add(moved[:, axis, :], self.rest_rows[axis], out=out[:, :, axis],
                   casting="unsafe")
        return out


def chunk_frames(n: int) -> int:
    """Frames per chunk so that one chunk's float64 product stays near CHUNK_BYTES."""
    return max(1, min(512, CHUNK_BYTES // max(1, n * 3 * 8)))


def iter_positions(basis, spectrogram, mapping, times, dtype=np.float32):
    """Positions for `times` chunk by chunk: yields (first frame index, (C, n, 3) array).

    Original coordinates, `dtype` (float32 by default). The arrays come from two buffers used
    in turn: a chunk stays valid until the next-but-one is requested (copy it to keep it).
    """
    times = np.asarray(times, dtype=np.float64)
    deform = _Deformer(basis)
    per_chunk = chunk_frames(basis.n)
    buffers = [np.empty((min(per_chunk, len(times)), basis.n, 3), dtype=dtype)
               for _ in range(2)]
    for number, first in enumerate(range(0, len(times), per_chunk)):
        chunk = times[first:first + per_chunk]
        phi = mapping.filter(spectrogram.at(chunk), basis.k)
        yield first, deform(phi, buffers[number % 2][:len(chunk)])


def write_animation(path: str | os.PathLike, basis, spectrogram, mapping, fps: float = 30.0,
                    progress=None) -> int:
    """Write the animation file (see the module docstring) atomically; returns the frame count.

    Frames are computed chunk by chunk and streamed into the .npy member of the zip, so neither
    the positions nor the file are ever held in memory; a writer thread stores (CRC + write) one
    chunk while the next is computed. progress: optional callable(done frames).
    """
    times = frame_times(spectrogram.duration, fps)
    header = {"descr": np.lib.format.dtype_to_descr(np.dtype("<f4")), "fortran_order": False,
              "shape": (len(times), basis.n, 3)}

    def write(file):
        from concurrent.futures import ThreadPoolExecutor

        with zipfile.ZipFile(file, "w", zipfile.ZIP_STORED, allowZip64=True) as archive:
            for name, array in (("times", times), ("faces", np.asarray(basis.faces, np.int64))):
                with archive.open(f"{name}.npy", "w") as member:
                    np.lib.format.write_array(member, np.ascontiguousarray(array))
            with (archive.open("positions.npy", "w", force_zip64=True) as member,
                  ThreadPoolExecutor(max_workers=1) as writer):
                np.lib.format.write_array_header_1_0(member, header)
                job = None
                for first, positions in iter_positions(basis, spectrogram, mapping, times,
                                                       np.dtype("<f4")):
                    if job is not None:
                        job.result()  # frees the buffer the generator fills next
                    job = writer.submit(member.write, memoryview(positions).cast("B"))
                    if progress is not None:
                        progress(first + len(positions))
                if job is not None:
                    job.result()

    from eigendance.files import atomic_write

    # Animation files are large, derived data: forcing hundreds of MB to disk would cost more
    # than computing them, so no fsync; readers still never see a half-written file.
    atomic_write(path, write, sync=False)
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
