"""Exports opened in Blender (docs/design.md#exports): its glTF importer (shape keys, armature),
the OBJ + Mesh Cache modifier for .pc2, and its USD importer; evaluated vertex positions at three
frames equal the reference within 1e-4 of the bounding-box diagonal.

Blender runs as the `bpy` wheel (the `blender` extra) in its own virtual environment,
.venv-blender (`make blender`; bpy pins its own numpy), or the Python named by
$EIGENDANCE_BLENDER_PYTHON; without it these tests are skipped, except under CI.
"""

from __future__ import annotations

import os
import subprocess

import numpy as np
import pytest
from export_helpers import check_positions, required
from scipy.spatial import cKDTree

from eigendance.export.dance import sample_times
from eigendance.export.files import export_dance

ROOT = os.path.join(os.path.dirname(__file__), "..", "..")
BLENDER_PYTHON = os.environ.get("EIGENDANCE_BLENDER_PYTHON") or \
    os.path.join(ROOT, ".venv-blender", "bin", "python")
SCRIPT = os.path.join(os.path.dirname(__file__), "blender_positions.py")
FPS = 15


@pytest.fixture(scope="module")
def blender():
    required("Blender (bpy)", os.path.exists(BLENDER_PYTHON), "make blender")
    return BLENDER_PYTHON


def from_blender(points: np.ndarray, kind: str) -> np.ndarray:
    """Blender is Z-up: its glTF and USD importers map a Y-up point (x, y, z) to (x, −z, y);
    the OBJ for the Mesh Cache is imported without conversion."""
    if kind == "pc2":
        return points
    return np.stack([points[..., 0], points[..., 2], -points[..., 1]], axis=-1)


@pytest.mark.parametrize("dance_name, kind", [
    ("harmonic", "glb"), ("harmonic", "pc2"), ("harmonic", "usd"), ("reduced_harmonic", "glb"),
    ("chain_lbs", "glb"), ("fox_lbs", "glb"), ("chain_lbs", "usd"), ("figure_modal", "pc2")])
def test_blender_plays_the_export_as_the_reference_moves(blender, request, tmp_path,
                                                         dance_name, kind):
    dance = request.getfixturevalue(dance_name)
    path = tmp_path / f"dance.{kind}"
    export_dance(dance, path, fps=FPS)
    times = sample_times(dance.duration, FPS)
    frames = [0, len(times) // 2, len(times) - 1]
    out = tmp_path / "blender.npz"
    run = subprocess.run([blender, SCRIPT, kind, str(path), str(FPS), str(out),
                          *map(str, frames)], capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr[-2000:]
    found = np.load(out)
    played = from_blender(found["frames"], kind)
    times = times[frames]
    expected = dance.blend_positions(times) if kind == "glb" and hasattr(dance, "blend_positions") \
        else dance.positions(times)  # a rig's glb is linear blend skinning; any other is exact
    # The importer may split or reorder vertices: match each of Blender's to ours at frame 0.
    distance, index = cKDTree(expected[0]).query(played[0])
    assert distance.max() <= 1e-5 * dance.diagonal
    assert set(index) == set(range(dance.n))
    if kind == "pc2":  # the Mesh Cache modifier maps by index: the order must be kept
        np.testing.assert_array_equal(index, np.arange(dance.n))
    check_positions(played, expected[:, index], dance.diagonal, 1e-4,
                    f"Blender {found['version']} {kind}")
    assert np.abs(expected[1] - expected[0]).max() > 1e-3 * dance.diagonal  # it moves
