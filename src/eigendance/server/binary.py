"""Compact binary bundles of named arrays, read by the web app (web/src/bundle.ts).

Layout (little-endian): b"EDB1", uint32 header length H, H bytes of UTF-8 JSON padded with
spaces to a multiple of 4, then the arrays, each starting at a multiple of 4 bytes. The header is
``{"meta": {...}, "arrays": {name: {"dtype": "float32"|"float16"|"uint32", "shape": [...],
"offset": bytes from the start of the data}}}``.

Basis bundle (`basis_bundle`): vertices (n,3) f32 normalised, faces (m,3) u32, eigenvalues (k,)
f32, coefficients (k,3) f32 and `harmonics` (n, 4·⌈k/4⌉) f32 (or f16 on request) — the eigenvectors
packed four harmonics per RGBA texel (zero padded), ready for a float texture.
Spectrogram bundle (`spectrogram_bundle`): times (T,) f32, values (T,B) f32, band_edges (B+1,)
f32, meta rate/sample_rate/duration.
"""

from __future__ import annotations

import json
import struct

import numpy as np

MAGIC = b"EDB1"
DTYPES = {"float32": np.dtype("<f4"), "uint32": np.dtype("<u4"), "float16": np.dtype("<f2")}


def pack(meta: dict, arrays: dict[str, np.ndarray], half: tuple[str, ...] = ()) -> bytes:
    """Bundle the arrays: integers as uint32, floats as float32 (float16 for names in `half`)."""
    entries, blobs, offset = {}, [], 0
    for name, array in arrays.items():
        if np.issubdtype(np.asarray(array).dtype, np.integer):
            dtype = "uint32"
        else:
            dtype = "float16" if name in half else "float32"
        data = np.ascontiguousarray(array, dtype=DTYPES[dtype]).tobytes()
        entries[name] = {"dtype": dtype, "shape": list(np.shape(array)), "offset": offset}
        padding = (-len(data)) % 4
        blobs.append(data + b"\0" * padding)
        offset += len(data) + padding
    header = json.dumps({"meta": meta, "arrays": entries}).encode()
    header += b" " * ((-len(header)) % 4)
    return MAGIC + struct.pack("<I", len(header)) + header + b"".join(blobs)


def unpack(data: bytes) -> tuple[dict, dict[str, np.ndarray]]:
    if data[:4] != MAGIC:
        raise ValueError("not an eigendance bundle")
    (length,) = struct.unpack("<I", data[4:8])
    header = json.loads(data[8:8 + length])
    start = 8 + length
    arrays = {}
    for name, entry in header["arrays"].items():
        dtype = DTYPES[entry["dtype"]]
        count = int(np.prod(entry["shape"], dtype=np.int64))
        arrays[name] = np.frombuffer(data, dtype, count, start + entry["offset"]).reshape(
            entry["shape"])
    return header["meta"], arrays


def packed_harmonics(eigenvectors: np.ndarray) -> np.ndarray:
    n, k = eigenvectors.shape
    width = 4 * ((k + 3) // 4)
    packed = np.zeros((n, width), dtype=np.float32)
    packed[:, :k] = eigenvectors
    return packed


def basis_bundle(basis, name: str = "mesh", half: bool = False) -> bytes:
    """The basis for the web app; `half` sends the harmonics as float16 (half the bytes,
    ≈ 1e-3 relative rounding of each eigenvector entry)."""
    meta = {"kind": "basis", "name": name, "n": basis.n, "k": basis.k,
            "faces": int(len(basis.faces)), "laplacian": basis.laplacian,
            "scale": float(basis.scale), "center": [float(c) for c in basis.center]}
    return pack(meta, {
        "vertices": basis.vertices, "faces": basis.faces.astype(np.uint32),
        "eigenvalues": basis.eigenvalues, "coefficients": basis.coefficients,
        "harmonics": packed_harmonics(basis.eigenvectors)}, half=("harmonics",) if half else ())


def spectrogram_bundle(spectrogram, name: str = "song") -> bytes:
    values = np.asarray(spectrogram.values, dtype=np.float32)
    meta = {"kind": "spectrogram", "name": name, "rate": float(spectrogram.rate),
            "frames": int(values.shape[0]), "bands": int(values.shape[1]),
            "sample_rate": int(getattr(spectrogram, "sample_rate", 0) or 0),
            "duration": float(getattr(spectrogram, "duration", 0.0)
                              or spectrogram.times[-1])}
    return pack(meta, {"times": np.asarray(spectrogram.times), "values": values,
                       "band_edges": np.asarray(spectrogram.band_edges)})
