"""Compact binary bundles of named arrays, read by the web app (web/src/bundle.ts).

Layout (little-endian): b"EDB1", uint32 header length H, H bytes of UTF-8 JSON padded with
spaces to a multiple of 4, then the arrays, each starting at a multiple of 4 bytes. The header is
``{"meta": {...}, "arrays": {name: {"dtype": "float32"|"float16"|"uint32"|"uint16"|"uint8",
"shape": [...], "offset": bytes from the start of the data}}}``.

Basis bundle (`basis_bundle`): vertices (n,3) f32 normalised, faces (m,3) u32, eigenvalues (k,)
f32, coefficients (k,3) f32 and `harmonics` (n, 4·⌈k/4⌉) f32 (or f16 on request) — the eigenvectors
packed four harmonics per RGBA texel (zero padded), ready for a float texture. A reduced basis
(docs/design.md#reduced-basis; meta `construction` "reduced", `samples` the count asked of the
sampler and `placed` m, as `BasisRecord`) sends instead `coarse` (m, 4·⌈k/4⌉) f32 (always: it
is small), U_r packed the same way, and P:
`weights` (n, 8) f16 (exact: multiples of 2⁻¹¹) and `indices` (n, 8) u16 (u32 when m > 65536).
Spectrogram bundle (`spectrogram_bundle`): times (T,) f32, values (T,B) f32, band_edges (B+1,)
f32, beats (n_b,), onsets (n_o,), downbeats (n_d,) and sections (n_s,) f32 seconds (the song's
rhythm, bars and parts, docs/design.md#rhythm; empty without them), meta rate/sample_rate/duration,
tempo (beats per minute, 0: no beat) and meter (beats per bar, 0: no bars).
Rig bundle (`rig_bundle`): what the page needs to play a rig — modal skinning packed for float
textures, linear blend skinning for three.js, the bodies and their per-mode twists; the arrays
and their units are listed in docs/web.md#rig-bundle.
Appearance bundle (`appearance_bundle`): a model's look — drawn vertices, their map onto the
welded ones, materials with the shader's rule for each, the images' bytes
(docs/web.md#appearance-bundle).
"""

from __future__ import annotations

import json
import struct

import numpy as np

from eigendance.geometry import bounding_box_diagonal
from eigendance.modal.bodies import CONSTRAINED_ROWS
from eigendance.modal.floor import tile_amplitudes
from eigendance.modal.palette import (
    default_phases,
    joint_bend,
    mode_reach,
    single_mode_amplitudes,
)
from eigendance.shaders.programs import material_shading

MAGIC = b"EDB1"
DTYPES = {"float32": np.dtype("<f4"), "uint32": np.dtype("<u4"), "float16": np.dtype("<f2"),
          "uint16": np.dtype("<u2"), "uint8": np.dtype("u1")}


def pack(meta: dict, arrays: dict[str, np.ndarray], half: tuple[str, ...] = ()) -> bytes:
    """Bundle the arrays: bytes (uint8) and uint16 arrays as they are, other integers as uint32,
    floats as float32 (float16 arrays, and names in `half`, as float16).

    Parameters
    ----------
    meta : the header's JSON `meta`.
    arrays : {name: array}, in the order they are packed.
    half : names of float arrays sent as float16.

    Returns
    -------
    bytes of the bundle (see the module docstring).
    """
    entries, blobs, offset = {}, [], 0
    for name, array in arrays.items():
        kind = np.asarray(array).dtype
        if kind == np.uint8:
            dtype = "uint8"
        elif kind == np.uint16:
            dtype = "uint16"
        elif np.issubdtype(kind, np.integer):
            dtype = "uint32"
        else:
            dtype = "float16" if name in half or kind == np.float16 else "float32"
        data = memoryview(np.ascontiguousarray(array, dtype=DTYPES[dtype]).reshape(-1)).cast("B")
        entries[name] = {"dtype": dtype, "shape": list(np.shape(array)), "offset": offset}
        padding = (-len(data)) % 4
        blobs.extend((data, b"\0" * padding))  # joined once below: no copy per array
        offset += len(data) + padding
    header = json.dumps({"meta": meta, "arrays": entries}).encode()
    header += b" " * ((-len(header)) % 4)
    return MAGIC + struct.pack("<I", len(header)) + header + b"".join(blobs)


def unpack(data: bytes) -> tuple[dict, dict[str, np.ndarray]]:
    """The meta and arrays of a bundle (tests, tools): the inverse of `pack`.

    Parameters
    ----------
    data : the bundle's bytes.

    Returns
    -------
    (meta, {name: array}) the arrays viewing `data`; ValueError when it is no bundle.
    """
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
    """The eigenvectors packed four harmonics per RGBA texel, zero padded.

    Parameters
    ----------
    eigenvectors : (n, k).

    Returns
    -------
    (n, 4·⌈k/4⌉) float32.
    """
    n, k = eigenvectors.shape
    width = 4 * ((k + 3) // 4)
    packed = np.zeros((n, width), dtype=np.float32)
    packed[:, :k] = eigenvectors
    return packed


def basis_bundle(basis, name: str = "mesh", half: bool = False) -> bytes:
    """The basis for the web app (docs/web.md).

    Parameters
    ----------
    basis : the mesh's `HarmonicBasis`.
    name : how the page calls the mesh.
    half : send the harmonics as float16 (half the bytes, ≈ 1e-3 relative rounding of each
        eigenvector entry); a reduced basis's coarse basis is always float32 (it is small).

    Returns
    -------
    bytes of the bundle: vertices, faces, eigenvalues, coefficients, harmonics (a reduced
    basis: its coarse basis and interpolation instead, module docstring).
    """
    meta = {"kind": "basis", "name": name, "n": basis.n, "k": basis.k,
            "faces": int(len(basis.faces)), "laplacian": basis.laplacian,
            "scale": float(basis.scale), "center": [float(c) for c in basis.center],
            "construction": basis.construction}
    arrays = {"vertices": basis.vertices, "faces": basis.faces.astype(np.uint32),
              "eigenvalues": basis.eigenvalues, "coefficients": basis.coefficients}
    if basis.reduced is None:
        arrays["harmonics"] = packed_harmonics(basis.eigenvectors)
        return pack(meta, arrays, half=("harmonics",) if half else ())
    reduced = basis.reduced
    meta["samples"], meta["placed"] = reduced.asked, reduced.count  # as `BasisRecord`'s
    indices = reduced.interpolation.indices
    arrays.update(coarse=packed_harmonics(reduced.coarse),
                  weights=reduced.interpolation.weights.astype(np.float16),  # exact
                  indices=indices.astype(np.uint16 if reduced.count <= 1 << 16 else np.uint32))
    return pack(meta, arrays)  # `half` does not apply: the coarse basis is small


def spectrogram_bundle(spectrogram, name: str = "song") -> bytes:
    """The spectrogram for the web app.

    Parameters
    ----------
    spectrogram : the song's `Spectrogram`.
    name : how the page calls the song.

    Returns
    -------
    bytes of the bundle: times (T,) s, values (T, B), band_edges (B+1,) Hz, beats, onsets,
    downbeats, sections s; meta rate, sample_rate, duration, tempo, meter.
    """
    values = np.asarray(spectrogram.values, dtype=np.float32)
    meta = {"kind": "spectrogram", "name": name, "rate": float(spectrogram.rate),
            "frames": int(values.shape[0]), "bands": int(values.shape[1]),
            "sample_rate": int(getattr(spectrogram, "sample_rate", 0) or 0),
            "duration": float(getattr(spectrogram, "duration", 0.0)
                              or spectrogram.times[-1])}
    rhythm = getattr(spectrogram, "rhythm", None)
    beats = rhythm.beats if rhythm is not None and rhythm.has_beats else np.zeros(0)
    meta["tempo"] = float(rhythm.tempo) if len(beats) else 0.0
    meta["meter"] = int(rhythm.meter) if len(beats) else 0
    events = {key: np.asarray(getattr(rhythm, key) if rhythm is not None else np.zeros(0),
                              dtype=np.float64) for key in ("onsets", "downbeats", "sections")}
    if not len(beats):
        events["downbeats"] = np.zeros(0)
    return pack(meta, {"times": np.asarray(spectrogram.times), "values": values,
                       "band_edges": np.asarray(spectrogram.band_edges),
                       "beats": np.asarray(beats, dtype=np.float64), **events})


def packed_modes(per_mode: np.ndarray, n: int) -> np.ndarray:
    """Per-mode vertex vectors packed four modes per RGBA texel, like the harmonics.

    Parameters
    ----------
    per_mode : (nm, 3n) per-mode rows of per-vertex vectors (`ModalSkin.displacement`,
        `.rotation`).
    n : vertices.

    Returns
    -------
    (n, G, 3, 4) float32, G = ⌈nm/4⌉: texel (i, g, d) holds coordinate d of modes 4g … 4g+3
    (zero padded), so that a shader adds dot(c[4g:4g+4], texel) to coordinate d of vertex i.
    """
    nm = len(per_mode)
    groups = (nm + 3) // 4
    padded = np.zeros((4 * groups, n, 3), dtype=np.float32)
    padded[:nm] = per_mode.reshape(nm, n, 3)
    return np.ascontiguousarray(padded.reshape(groups, 4, n, 3).transpose(2, 0, 3, 1))


def top_weights(weights: np.ndarray, count: int = 4) -> tuple[np.ndarray, np.ndarray]:
    """The `count` largest skin weights of every vertex and their bodies, renormalised to sum 1
    (three.js SkinnedMesh reads four).

    Parameters
    ----------
    weights : (n, n_b) skin weights.
    count : influences kept per vertex.

    Returns
    -------
    indices (n, 4) and weights (n, 4) (padded with weight 0 when count < 4).
    """
    weights = np.asarray(weights, dtype=float)
    count = min(count, weights.shape[1])
    order = np.argsort(-weights, axis=1, kind="stable")[:, :count]
    top = np.take_along_axis(weights, order, axis=1)
    top = top / np.maximum(top.sum(axis=1, keepdims=True), 1e-300)
    if count < 4:  # pad to four influences of weight 0
        order = np.pad(order, ((0, 0), (0, 4 - count)))
        top = np.pad(top, ((0, 0), (0, 4 - count)))
    return order, top


def rig_meta(rig, name: str = "rig", revision: int = 0, edited: bool = False) -> dict:
    """The rig bundle's JSON header `meta` (docs/web.md#rig-bundle), also `GET /api/rigs/{id}`.

    Parameters
    ----------
    rig : the `Rig` (its loop closures and default stiffness per joint come from it).
    name : how the page calls it.
    revision : how many edits made it.
    edited : whether its pose or stiffness differs from the rig as loaded.

    Returns
    -------
    dict: counts, size, centre and diagonal, body names, frequencies (Hz), the joints (type,
    rows, stiffness, default stiffness, closes_loop), the default palette, `edited`.
    """
    skeleton, model, palette = rig.skeleton, rig.model, rig.palette
    nm = model.n_modes
    low, high = skeleton.vertices.min(axis=0), skeleton.vertices.max(axis=0)
    return {
        "kind": "rig", "name": name, "revision": int(revision), "edited": bool(edited),
        "n": int(len(skeleton.vertices)),
        "faces": int(len(skeleton.faces)), "bodies": model.n_bodies,
        "joints": len(skeleton.joints), "modes": int(nm), "groups": (nm + 3) // 4,
        "rigid_modes": int(model.rigid_modes), "size": float(model.size),
        "center": ((low + high) / 2).tolist(), "diagonal": bounding_box_diagonal(skeleton.vertices),
        "body_names": list(model.body_names),
        "frequencies": model.frequencies.tolist(),
        "joint_list": [{"name": joint.name, "type": joint.type,
                        "bodies": [int(b) for b in joint.bodies],
                        "free_rows": list(joint.free_rows),
                        "constrained_rows": list(CONSTRAINED_ROWS[joint.type]),
                        "stiffness": joint.stiffness.tolist(),
                        "default_stiffness": default.tolist(),
                        "closes_loop": bool(loop)}
                       for joint, default, loop in zip(skeleton.joints, rig.default_stiffness,
                                                       rig.closes_loop, strict=True)],
        "palette": None if palette is None else palette.to_settings().to_json(),
        "offset": 0.0,
    }


def rig_bundle(rig, name: str = "rig", revision: int = 0, edited: bool = False) -> bytes:
    """A `eigendance.modal.rig.Rig` for the web app (docs/web.md#rig-bundle), all float32.

    Parameters
    ----------
    rig : the rig (its skin, modes, rest bones).
    name : how the page calls it.
    revision : how many edits made it.
    edited : whether its pose or stiffness differs from the rig as loaded.

    Returns
    -------
    bytes of the bundle.
    """
    skeleton, model, skin = rig.skeleton, rig.model, rig.skin
    n, nm = len(skin.vertices), model.n_modes
    joints, weights = top_weights(skeleton.weights)
    bones = rig.rest_bones
    column_major = np.swapaxes  # three.js Matrix4.fromArray reads columns first
    twists = model.modes.reshape(model.n_bodies, 6, nm).transpose(2, 0, 1)
    return pack(rig_meta(rig, name, revision, edited), {
        "vertices": skin.vertices, "faces": skeleton.faces.astype(np.uint32),
        "tau": packed_modes(skin.displacement, n), "rho": packed_modes(skin.rotation, n),
        "frequencies": model.frequencies,
        "amplitudes": single_mode_amplitudes(model), "reach": mode_reach(model),
        "tile_amplitudes": tile_amplitudes(model, skin, single_mode_amplitudes(model)),
        "phases": default_phases(np.arange(nm)),
        "skin_joints": joints.astype(np.uint32), "skin_weights": weights,
        "bone_matrices": column_major(bones, 1, 2).reshape(-1, 16),
        "bind_matrices": column_major(np.linalg.inv(bones), 1, 2).reshape(-1, 16),
        "body_centers": model.body_centers, "body_rotations": model.body_rotations,
        "body_ends": np.array([[b.start, b.end] for b in skeleton.bodies]).reshape(-1, 2, 3),
        "body_radii": np.array([b.radius for b in skeleton.bodies]),
        "body_twists": twists,
        "joint_bodies": model.joint_bodies.astype(np.uint32),
        "joint_positions": model.joint_positions,
        "joint_bend": joint_bend(model),  # (j, k): the page's palette caps the bend with it
    })


def appearance_bundle(appearance, name: str = "model") -> bytes:
    """A model's look for the web app (docs/web.md#appearance-bundle).

    Parameters
    ----------
    appearance : an `assets.Appearance` (its `welded` map onto the vertices of the basis or
        rig bundle of the same model).
    name : the model's name.

    Returns
    -------
    bytes: meta {kind "appearance", name, drawn, materials (each with `shading`: the surface
    shader's defines, uniforms and textures, `shaders.programs.material_shading`), images,
    parts, uvSets, colors, tangents}; arrays welded (n_d,) uint32, normals (n_d, 3), uv0, uv1
    (n_d, 2), colors (n_d, 4), tangents (n_d, 4), triangles<p> (m_p, 3) uint32 per part,
    image<i> (bytes,) uint8 the encoded PNG or JPEG of image i.
    """
    meta = {"kind": "appearance", "name": name, **appearance.to_json()}
    colors = appearance.colors is not None
    for material, described in zip(appearance.materials, meta["materials"], strict=True):
        described["shading"] = material_shading(material, len(appearance.uvs), colors)
    arrays = dict(appearance.arrays())
    arrays["welded"] = np.asarray(appearance.welded, dtype=np.uint32)
    for key in list(arrays):
        if key.startswith("triangles"):
            arrays[key] = np.asarray(arrays[key], dtype=np.uint32)
    for index, image in enumerate(appearance.images):
        arrays[f"image{index}"] = np.frombuffer(image.data, dtype=np.uint8)
    return pack(meta, arrays)
