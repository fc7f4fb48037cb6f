"""Helpers of the export tests: the test song, rigs that dance to it, position checks."""

from __future__ import annotations

import math

import numpy as np

from eigendance.export.rig_dance import rig_dance
from eigendance.modal.motion import band_mapping
from eigendance.modal.rig import Rig
from eigendance.modal.sample_rigs import load_rig
from helpers import fixture_path, required  # noqa: F401 - the export tests' import

SONG = fixture_path("audio", "kevin_macleod_vibe_ace_20s-24s.ogg")  # 4 s
LONG_SONG = fixture_path("audio", "kevin_macleod_vibe_ace_0s-21s.ogg")  # 21 s


def rig(name: str, skinning: str, song, mode_count: int = 4, audio: str = SONG):
    dancer = Rig(load_rig(name), np.float64)
    modes = np.arange(min(mode_count, dancer.model.n_modes))
    mapping = dancer.mapping(song, band_mapping(song.bands, len(modes)), selected=modes,
                             amplitude=0.3, time_scale=1.0)
    return rig_dance(dancer, song, mapping, skinning, audio, f"{skinning}-rig")


def file_times(duration: float, fps: float) -> np.ndarray:
    """t_i = i/fps for i = 0 … ⌊duration·fps⌋, written out here (docs/design.md#exports), not
    taken from the exports' own code."""
    return np.arange(math.floor(duration * fps + 1e-9) + 1) / fps


def video_frame_times(duration: float, fps: float) -> np.ndarray:
    """Frame i of a video shows i/fps, i < ⌈duration·fps⌉ (at least one), written out here."""
    return np.arange(max(1, math.ceil(duration * fps - 1e-9))) / fps


def check_positions(found, expected, diagonal, tolerance=1e-4, what="positions"):
    """Every frame and vertex within tolerance·diagonal."""
    found, expected = np.asarray(found), np.asarray(expected)
    assert found.shape == expected.shape, (found.shape, expected.shape)
    error = np.linalg.norm(found - expected, axis=-1).max(axis=-1) / diagonal
    assert np.all(error <= tolerance), f"{what}: relative errors per frame {error}"
    print(f"{what}: largest error {error.max():.1e} of the diagonal over {len(error)} frames")
    return error


def spread_frames(count: int, frames: int = 6) -> list[int]:
    """`frames` sample indices spread over `count` samples, first and last included."""
    return sorted({int(round(i)) for i in np.linspace(0, count - 1, frames)})


def read_obj(path):
    """An OBJ's vertices (n, 3) and faces (lists of vertex indices), read here as written."""
    vertices, faces = [], []
    with open(path, encoding="utf-8") as file:
        for line in file:
            words = line.split()
            if words[:1] == ["v"]:
                vertices.append([float(w) for w in words[1:4]])
            elif words[:1] == ["f"]:
                faces.append([int(w.split("/")[0]) - 1 for w in words[1:]])
    return np.array(vertices), faces


def in_file_order(positions, rest, triangles):
    """`animate`'s positions of the cleaned mesh (exact duplicates welded, first one kept;
    unused vertices dropped, docs/design.md#mesh) put back on every vertex of the file, as
    the add-on bakes them: a welded vertex moves with its twin, a dropped one stays."""
    rest = np.asarray(rest, dtype=np.float64)
    used = np.zeros(len(rest), dtype=bool)
    used[np.concatenate([np.ravel(face) for face in triangles])] = True
    _, first, inverse = np.unique(rest, axis=0, return_index=True, return_inverse=True)
    twin = first[inverse.ravel()]
    kept = np.unique(twin[used])
    assert len(kept) == positions.shape[1]
    found = np.broadcast_to(rest, (len(positions), *rest.shape)).copy()
    mapped = np.isin(twin, kept)
    found[:, mapped] = positions[:, np.searchsorted(kept, twin[mapped])]
    return found
