"""Point caches for Blender's Mesh Cache modifier: .pc2 plus the rest mesh as .obj
(docs/design.md#exports).

PC2 (little-endian): b"POINTCACHE2\\0", int32 version 1, int32 points n, float32 start frame,
float32 sampling (frames per sample, 1 here), int32 samples T, then T × n × 3 float32 positions.
Sample i is the dance at time i/fps; frames are written chunk by chunk as they are computed.
The OBJ lists the rest positions in the same vertex order (the modifier maps by index), then the
triangles (`look_files.obj_text`), so importing it and adding the modifier plays the dance.
"""

from __future__ import annotations

import struct

import numpy as np

from eigendance.export.dance import Dance

MAGIC = b"POINTCACHE2\0"


def pc2_header(points: int, samples: int, start_frame: float = 0.0,
               sampling: float = 1.0) -> bytes:
    """The 32-byte PC2 header.

    Parameters
    ----------
    points : vertices.
    samples : frames.
    start_frame : the first frame.
    sampling : frames per sample.

    Returns
    -------
    bytes (32).
    """
    return MAGIC + struct.pack("<iiffi", 1, points, start_frame, sampling, samples)


def pc2_size(points: int, samples: int) -> int:
    """Bytes of a PC2 file: the header plus samples × points × 3 float32.

    Parameters
    ----------
    points : vertices.
    samples : frames.

    Returns
    -------
    int, bytes.
    """
    return len(pc2_header(points, samples)) + 12 * points * samples


def write_pc2(file, dance: Dance, times, progress=None) -> None:
    """Write the point cache of `dance` at `times` (s) to an open binary file.

    Parameters
    ----------
    file : a binary file open for writing.
    dance : the motion.
    times : (T,) sample times; sample i is written as frame i.
    progress : optional callable(frames done).
    """
    times = np.asarray(times, dtype=np.float64)
    file.write(pc2_header(dance.n, len(times)))
    for first, positions, _ in dance.frames(times):
        file.write(np.ascontiguousarray(positions, dtype="<f4").tobytes())
        if progress is not None:
            progress(first + len(positions))


def read_pc2(path) -> tuple[np.ndarray, float, float]:
    """(positions (T, n, 3) float32, start frame, sampling) of a PC2 file (for checks).

    Parameters
    ----------
    path : a .pc2 file.

    Returns
    -------
    (positions, start frame, sampling).
    """
    with open(path, "rb") as file:
        header = file.read(32)
        if header[:12] != MAGIC:
            raise ValueError(f"{path}: not a PC2 file")
        _, points, start, sampling, samples = struct.unpack("<iiffi", header[12:])
        data = np.frombuffer(file.read(), dtype="<f4")
    return data.reshape(samples, points, 3), start, sampling
