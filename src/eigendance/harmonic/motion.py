"""Harmonic motion: vertex positions over time for a basis, a spectrogram and a mapping
(docs/design.md#harmonic-motion).

At time t the filter is φ(t) = mapping.play(spectrogram, t, k) and the positions are
X_φ = X + U((φ − 1) ⊙ X̃), returned in the mesh file's coordinates (after clean-up):
X_φ·scale + center.

`positions_at` is the reference (float64, all requested times at once). `write_animation`
streams an animation file in chunks of frames, so memory stays at a few tens of MB whatever the
length of the song and the size of the mesh. Animation file (.npz, uncompressed): `times` (T,)
seconds, `faces` (m, 3) int64, `positions` (T, n, 3) float32.
"""

from __future__ import annotations

import os
import zipfile
from concurrent.futures import ThreadPoolExecutor

import numpy as np

from eigendance.files import load_npz
from eigendance.harmonic.basis import HarmonicBasis
from eigendance.inputs.defaults import DEFAULT_FPS
from eigendance.limits import check_output
from eigendance.music.mapping import Mapping
from eigendance.music.spectrogram import Spectrogram, frame_times
from eigendance.window import Window
from eigendance.writes import OUT_OF_RANGE, atomic_write, check_finite

CHUNK_BYTES = 24 << 20  # float64 product of one chunk of frames (cache-friendly; measured)


def positions_at(basis: HarmonicBasis, spectrogram: Spectrogram, mapping: Mapping,
                 times) -> np.ndarray:
    """The reference positions of a mesh dancing to a song.

    Parameters
    ----------
    basis : the mesh's harmonics.
    spectrogram : the song's banded loudness.
    mapping : the sound-to-motion mapping.
    times : (…,) seconds.

    Returns
    -------
    (…, n, 3) float64 positions in the mesh file's coordinates.

    Example
    -------
    >>> import trimesh
    >>> from eigendance.harmonic.mesh import Mesh
    >>> sphere = trimesh.creation.icosphere(2)
    >>> basis = HarmonicBasis.from_mesh(Mesh.from_arrays(sphere.vertices, sphere.faces), 16,
    ...                                 cache=False)
    >>> song = Spectrogram.from_samples(np.sin(np.arange(8000) / 3.0), 8000)
    >>> still = Mapping(np.full(64, 0.5), np.zeros(16))        # a ≡ 0: φ ≡ 1, no motion
    >>> positions = positions_at(basis, song, still, [0.0, 0.5])
    >>> positions.shape, bool(np.allclose(positions[1], sphere.vertices))
    ((2, 162, 3), True)
    """
    phi = mapping.play(spectrogram, times, basis.k)
    return basis.to_original(basis.filter_positions(phi))


def chunk_frames(n: int) -> int:
    """Frames per chunk so that one chunk's float64 product stays near CHUNK_BYTES.

    Parameters
    ----------
    n : vertices.

    Returns
    -------
    int, 1 … 512.
    """
    return max(1, min(512, CHUNK_BYTES // max(1, n * 3 * 8)))


def iter_positions(basis, spectrogram, mapping, times, dtype=np.float32):
    """Positions for `times` chunk by chunk: yields (first frame index, (C, n, 3) array).

    Original coordinates, `dtype` (float32 by default). The arrays come from two buffers used
    in turn: a chunk stays valid until the next-but-one is requested (copy it to keep it).

    Parameters
    ----------
    basis, spectrogram, mapping : the mesh's harmonics, the song, the mapping.
    times : (T,) s of the song.
    dtype : of the positions.

    Yields
    ------
    (first frame index, (C, n, 3)).
    """
    times = np.asarray(times, dtype=np.float64)
    play = mapping.player(spectrogram)
    deform = basis.deformer(original=True)
    per_chunk = chunk_frames(basis.n)
    buffers = [np.empty((min(per_chunk, len(times)), basis.n, 3), dtype=dtype)
               for _ in range(2)]
    for number, first in enumerate(range(0, len(times), per_chunk)):
        chunk = times[first:first + per_chunk]
        phi = play(chunk, basis.k)
        yield first, deform(phi, buffers[number % 2][:len(chunk)])


def write_animation(path: str | os.PathLike, basis, spectrogram, mapping, fps: float = DEFAULT_FPS,
                    progress=None, window: Window | None = None, force: bool = False) -> int:
    """Write the animation file (see the module docstring) atomically.

    Frames are computed chunk by chunk and streamed into the .npy member of the zip, so neither
    the positions nor the file are ever held in memory; a writer thread stores (CRC + write) one
    chunk while the next is computed. A chunk that is not finite (an amplification or a model
    too large for float32) ends the write with an InputError, and no file is left. Its size is
    checked first: it must fit on the disk, and beyond `limits.LARGE_OUTPUT` it is written only
    with `force`.

    Parameters
    ----------
    path : the .npz to write.
    basis, spectrogram, mapping : the mesh's harmonics, the song, the mapping.
    fps : frames per second.
    progress : optional callable(done frames).
    window : the part of the song (`window.Window`; None: the whole song): the file's times
        start at 0 and its frame at time t is the song's at window.start + t.
    force : write a file beyond `limits.LARGE_OUTPUT`.

    Returns
    -------
    int, the frame count.
    """
    window = window or Window(0.0, spectrogram.duration)
    times = frame_times(window.duration, fps)
    check_output(path, 12.0 * len(times) * basis.n, f"{os.path.basename(os.fspath(path))}: "
                 f"{len(times)} frames of {basis.n} vertices", force)
    header = {"descr": np.lib.format.dtype_to_descr(np.dtype("<f4")), "fortran_order": False,
              "shape": (len(times), basis.n, 3)}

    def write(file):
        with zipfile.ZipFile(file, "w", zipfile.ZIP_STORED, allowZip64=True) as archive:
            for name, array in (("times", times), ("faces", np.asarray(basis.faces, np.int64))):
                with archive.open(f"{name}.npy", "w") as member:
                    np.lib.format.write_array(member, np.ascontiguousarray(array))
            with (archive.open("positions.npy", "w", force_zip64=True) as member,
                  ThreadPoolExecutor(max_workers=1) as writer):
                np.lib.format.write_array_header_1_0(member, header)
                job = None
                for first, positions in iter_positions(basis, spectrogram, mapping,
                                                       window.start + times, np.dtype("<f4")):
                    check_finite(positions, f"{os.fspath(path)}: not written: positions",
                                 OUT_OF_RANGE)
                    if job is not None:
                        job.result()  # frees the buffer the generator fills next
                    job = writer.submit(member.write, memoryview(positions).cast("B"))
                    if progress is not None:
                        progress(first + len(positions))
                if job is not None:
                    job.result()

    # Animation files are large, derived data: forcing hundreds of MB to disk would cost more
    # than computing them, so no fsync; readers still never see a half-written file.
    atomic_write(path, write, sync=False)
    return len(times)


def load_animation(path: str | os.PathLike) -> dict:
    """Read an animation file: {"times", "faces", "positions"} (positions fully in memory).

    Parameters
    ----------
    path : an animation file.

    Returns
    -------
    {"times", "faces", "positions"}.
    """
    return load_npz(path, ("times", "faces", "positions"))
