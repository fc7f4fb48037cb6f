"""Exports opened in Blender (docs/design.md#exports): its glTF importer (shape keys, armature),
the OBJ + Mesh Cache modifier for .pc2, and its USD importer; evaluated vertex positions at three
frames equal the reference within 1e-4 of the bounding-box diagonal.

Blender runs as the `bpy` wheel (the `blender` extra) in its own virtual environment,
.venv-blender (`make blender`; bpy pins its own numpy), or the Python named by
$EIGENDANCE_BLENDER_PYTHON; Blender 4.2 LTS likewise in .venv-blender42 (or
$EIGENDANCE_BLENDER42_PYTHON). Without them these tests are skipped, except under CI.

The textured, multi-part cake dances on a 21 s song with morph weights below 0 and above 1
(Blender clamps each shape key to [min(0, initial weight), 1]: the glb must be written so that
it plays anyway); the character with a gun on its hand bone keeps its prop, and with its skin
rippling in its harmonics (morph targets under the skin) it plays as `animate-rig --surface`.
Six frames spread over the song are checked.
"""

from __future__ import annotations

import os
import subprocess

import numpy as np
import pytest
from export_helpers import check_positions, file_times, required, spread_frames
from scipy.spatial import cKDTree

from eigendance.export.files import export_dance

ROOT = os.path.join(os.path.dirname(__file__), "..", "..")
BLENDERS = {
    "5.0": os.environ.get("EIGENDANCE_BLENDER_PYTHON") or
    os.path.join(ROOT, ".venv-blender", "bin", "python"),
    "4.2": os.environ.get("EIGENDANCE_BLENDER42_PYTHON") or
    os.path.join(ROOT, ".venv-blender42", "bin", "python")}
SCRIPT = os.path.join(os.path.dirname(__file__), "blender_positions.py")
FPS = 15
LONG_FPS = 5  # the 21 s song: 106 samples


def blender(version: str) -> str:
    python = BLENDERS[version]
    required(f"Blender {version} (bpy)", os.path.exists(python), "make blender")
    return python


def from_blender(points: np.ndarray, kind: str) -> np.ndarray:
    """Blender is Z-up: its glTF and USD importers map a Y-up point (x, y, z) to (x, −z, y);
    the OBJ for the Mesh Cache is imported without conversion."""
    if kind == "pc2":
        return points
    return np.stack([points[..., 0], points[..., 2], -points[..., 1]], axis=-1)


CASES = [("harmonic", "glb"), ("harmonic", "pc2"), ("harmonic", "usd"),
         ("reduced_harmonic", "glb"),
         ("chain_lbs", "glb"), ("fox_lbs", "glb"), ("chain_lbs", "usd"), ("figure_modal", "pc2"),
         ("cake", "glb"), ("cake", "pc2"), ("cake", "usd"),
         ("gun_lbs", "glb"), ("gun_lbs", "usd"), ("gun_modal", "pc2"), ("gun_surface", "glb")]
# Blender 4.2 LTS on the glbs (shape keys, armature); the point cache and USD in 5.0.
VERSIONED = [("5.0", *case) for case in CASES] + [("4.2", *case) for case in CASES
                                                   if case[1] == "glb"]


@pytest.mark.parametrize("version, dance_name, kind", VERSIONED)
def test_blender_plays_the_export_as_the_reference_moves(version, request, tmp_path,
                                                         dance_name, kind):
    python = blender(version)
    dance = request.getfixturevalue(dance_name)
    fps = LONG_FPS if dance.duration > 20 else FPS
    path = tmp_path / f"dance.{kind}"
    export_dance(dance, path, fps=fps)
    times = file_times(dance.duration, fps)
    frames = spread_frames(len(times)) if dance.duration > 20 else \
        [0, len(times) // 2, len(times) - 1]
    out = tmp_path / "blender.npz"
    run = subprocess.run([python, SCRIPT, kind, str(path), str(fps), str(out),
                          *map(str, frames)], capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr[-2000:]
    found = np.load(out)
    played = from_blender(found["frames"], kind)
    times = times[frames]
    expected = dance.blend_positions(times) if kind == "glb" and hasattr(dance, "weights") \
        else dance.positions(times)
    # The importer may split or reorder vertices: match each of Blender's to ours at frame 0.
    distance, index = cKDTree(expected[0]).query(played[0])
    assert distance.max() <= 1e-5 * dance.diagonal
    assert set(index) == set(range(dance.n))
    if kind == "pc2":  # the Mesh Cache modifier maps by index: the order must be kept
        np.testing.assert_array_equal(index, np.arange(dance.n))
    check_positions(played, expected[:, index], dance.diagonal, 1e-4,
                    f"Blender {found['version']} {kind}")
    assert np.abs(expected[1] - expected[0]).max() > 1e-3 * dance.diagonal  # it moves
    if dance_name in ("cake", "gun_surface") and kind == "glb":  # beyond Blender's [0, 1]
        weights = dance.morphs(times).weights
        assert weights.min() < 0 and weights.max() > 1
