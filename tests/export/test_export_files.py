"""Point caches, USD and the all-or-nothing outputs (docs/design.md#exports)."""

from __future__ import annotations

import os
import struct
import warnings

import numpy as np
import pytest
import trimesh
from export_helpers import SONG, check_positions, file_times
from pxr import Usd, UsdGeom, UsdMedia, UsdUtils

from eigendance.errors import InputError
from eigendance.export.files import export_dance, format_of
from eigendance.export.output import Outputs
from eigendance.export.pointcache import pc2_size, read_pc2
from eigendance.harmonic.motion import positions_at


def test_the_point_cache_holds_every_frame_and_the_obj_the_rest_in_order(harmonic, tmp_path):
    report = export_dance(harmonic, tmp_path / "dance.pc2", fps=20)
    times = file_times(harmonic.duration, 20)
    with open(tmp_path / "dance.pc2", "rb") as file:
        header = file.read(32)
    assert header[:12] == b"POINTCACHE2\0"
    assert struct.unpack("<iiffi", header[12:]) == (1, harmonic.n, 0.0, 1.0, len(times))
    assert os.path.getsize(tmp_path / "dance.pc2") == pc2_size(harmonic.n, len(times))
    positions, _, _ = read_pc2(tmp_path / "dance.pc2")
    reference = positions_at(harmonic.basis, harmonic.spectrogram, harmonic.mapping, times)
    check_positions(positions, reference, harmonic.diagonal, 1e-6)
    rest = trimesh.load(tmp_path / "dance.obj", process=False)
    np.testing.assert_allclose(rest.vertices, harmonic.rest, rtol=0, atol=1e-6)
    np.testing.assert_array_equal(rest.faces, harmonic.faces)
    assert report["files"] == [str(tmp_path / n) for n in ("dance.pc2", "dance.obj",
                                                           "dance.ogg")]


@pytest.mark.parametrize("suffix", [".usd", ".usda"])
def test_usd_time_samples_are_the_frames_and_the_checker_passes(harmonic, tmp_path, suffix):
    path = tmp_path / f"dance{suffix}"
    export_dance(harmonic, path, fps=24)
    times = file_times(harmonic.duration, 24)
    stage = Usd.Stage.Open(str(path))
    assert stage.GetTimeCodesPerSecond() == 24 and stage.GetFramesPerSecond() == 24
    assert (stage.GetStartTimeCode(), stage.GetEndTimeCode()) == (0, len(times) - 1)
    assert UsdGeom.GetStageUpAxis(stage) == "Y"
    mesh = UsdGeom.Mesh(stage.GetPrimAtPath("/Dance/Mesh"))
    points = mesh.GetPointsAttr()
    assert points.GetTimeSamples() == list(range(len(times)))
    played = np.array([np.array(points.Get(code)) for code in range(len(times))])
    reference = positions_at(harmonic.basis, harmonic.spectrogram, harmonic.mapping, times)
    check_positions(played, reference, harmonic.diagonal, 1e-6)
    indices = np.array(mesh.GetFaceVertexIndicesAttr().Get()).reshape(-1, 3)
    np.testing.assert_array_equal(indices, harmonic.faces)
    song = UsdMedia.SpatialAudio(stage.GetPrimAtPath("/Dance/Song"))
    assert song.GetFilePathAttr().Get().path == "dance.ogg"
    assert (tmp_path / "dance.ogg").read_bytes() == open(SONG, "rb").read()
    comply(path)


def test_a_rig_in_usd_holds_its_skinned_frames(figure_modal, tmp_path):
    export_dance(figure_modal, tmp_path / "figure.usdc", fps=10)
    times = file_times(figure_modal.duration, 10)
    stage = Usd.Stage.Open(str(tmp_path / "figure.usdc"))
    points = UsdGeom.Mesh(stage.GetPrimAtPath("/Dance/Mesh")).GetPointsAttr()
    played = np.array([np.array(points.Get(code)) for code in range(len(times))])
    check_positions(played, figure_modal.positions(times), figure_modal.diagonal, 1e-6)
    comply(tmp_path / "figure.usdc")


def comply(path) -> None:
    """usd-core's compliance checker: no error, failed check or warning. (usd-core 26.5
    deprecates it for the validation framework, and 26.8 removed it: pinned in pyproject.)"""
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", "Use of UsdUtils.ComplianceChecker is deprecated")
        checker = UsdUtils.ComplianceChecker()
    checker.CheckCompliance(str(path))
    assert not checker.GetErrors() and not checker.GetFailedChecks(), \
        (checker.GetErrors(), checker.GetFailedChecks())
    assert not checker.GetWarnings(), checker.GetWarnings()


def test_formats_come_from_the_suffix_or_must_agree_with_it():
    assert [format_of(f"a{s}") for s in (".glb", ".PC2", ".usda")] == ["glb", "pc2", "usd"]
    with pytest.raises(InputError, match=r"unknown export format '\.fbx'"):
        format_of("dance.fbx")
    with pytest.raises(InputError, match="must end in .glb"):
        format_of("dance.usd", "glb")


def test_nothing_is_overwritten_without_force_and_a_failure_leaves_nothing(harmonic,
                                                                           tmp_path):
    (tmp_path / "dance.ogg").write_bytes(b"someone else's song")
    with pytest.raises(InputError, match="dance.ogg exists"):
        export_dance(harmonic, tmp_path / "dance.glb")
    assert sorted(os.listdir(tmp_path)) == ["dance.ogg"]  # checked before any work
    report = export_dance(harmonic, tmp_path / "dance.glb", force=True)
    assert (tmp_path / "dance.ogg").read_bytes() == open(SONG, "rb").read()
    assert len(report["files"]) == 2

    def fail(done, total):
        raise KeyboardInterrupt  # Ctrl-C in the middle of writing

    before = {name: (tmp_path / name).read_bytes() for name in os.listdir(tmp_path)}
    with pytest.raises(KeyboardInterrupt):
        export_dance(harmonic, tmp_path / "dance.glb", force=True, progress=fail)
    with pytest.raises(KeyboardInterrupt):
        export_dance(harmonic, tmp_path / "other.pc2", progress=fail)
    after = {name: (tmp_path / name).read_bytes() for name in os.listdir(tmp_path)}
    assert after == before  # no temporary, no half file, nothing replaced


def test_an_export_of_the_song_already_beside_it_reuses_it(harmonic, tmp_path):
    export_dance(harmonic, tmp_path / "dance.glb")
    report = export_dance(harmonic, tmp_path / "dance.usda")  # same song: no conflict
    assert report["files"] == [str(tmp_path / "dance.usda")]


def test_outputs_refuse_a_folder_and_the_same_file_twice(tmp_path):
    with pytest.raises(InputError, match="is a folder"):
        Outputs([tmp_path])
    with pytest.raises(InputError, match="same file twice"):
        Outputs([tmp_path / "a", tmp_path / "a"])
