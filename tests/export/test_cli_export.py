"""`eigendance export` and `eigendance render` (docs/design.md#cli, #exports): what they write
and print, and bad input on one line with nothing left behind."""

from __future__ import annotations

import os

import numpy as np
import pygltflib
import pytest
import trimesh
from export_helpers import SONG

from eigendance.cli import main
from eigendance.music.mapping import Mapping
from helpers import fixture_path


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    folder = tmp_path_factory.mktemp("cli")
    sphere = trimesh.creation.icosphere(2)
    sphere.vertices *= [1.3, 1.0, 0.8]
    sphere.export(folder / "sphere.obj")
    rng = np.random.default_rng(5)
    Mapping(rng.uniform(0, 1, 64), rng.uniform(-0.3, 0.3, 16), gain=2.0,
            shading="flat").save(folder / "mapping.json")
    (folder / "broken.json").write_text("{not json")
    return folder


def run(capsys, *arguments):
    status = main([str(argument) for argument in arguments])
    captured = capsys.readouterr()
    return status, captured.out, captured.err


def test_export_writes_each_format_and_prints_the_sizes(files, tmp_path, capsys):
    tmp_path = tmp_path / "out"
    for name in ("dance.glb", "dance.pc2", "dance.usda"):
        status, out, err = run(capsys, "export", files / "sphere.obj", SONG, "--mapping",
                               files / "mapping.json", "-k", 20, "--fps", 12, "-o",
                               tmp_path / name)
        assert status == 0, err
        assert f"{name}: 49 frames of 162 vertices at 12 fps" in out
    assert "as a point cache" in out and "× the size" in out
    assert sorted(os.listdir(tmp_path)) == ["dance.glb", "dance.obj", "dance.ogg", "dance.pc2",
                                            "dance.usda"]
    extras = pygltflib.GLTF2().load(str(tmp_path / "dance.glb")).extras["eigendance"]
    assert extras["audio"] == "dance.ogg" and extras["mapping"]["gain"] == 2.0


def test_a_mesh_with_non_manifold_edges_dances_with_the_robust_laplacian(tmp_path, capsys):
    """The birthday cake has 197 non-manifold edges: `export` takes the robust Laplacian, as
    the server does, instead of refusing it with a hint naming a flag `export` does not have;
    the written dance moves."""
    cake = fixture_path("textured", "kenney_cakeBirthday.glb")
    welded = trimesh.load(cake, force="mesh")
    welded.merge_vertices(merge_tex=True, merge_norm=True)  # as its positions weld
    counts = np.unique(welded.edges_sorted, axis=0, return_counts=True)[1]
    assert (counts > 2).sum() > 100  # trimesh's own count of edges in more than two faces
    status, out, err = run(capsys, "export", cake, SONG, "-k", 20, "--fps", 12, "--duration", 2,
                           "-o", tmp_path / "cake.glb")
    assert status == 0, err
    assert "non-manifold" not in err
    gltf = pygltflib.GLTF2().load(str(tmp_path / "cake.glb"))
    assert gltf.meshes[0].primitives[0].targets  # morph targets: the harmonics it drives


def test_export_of_a_rig_reports_the_modal_skinning_difference(tmp_path, capsys):
    status, out, err = run(capsys, "export", "loop8", SONG, "--fps", 10, "-o",
                           tmp_path / "loop.glb")
    assert status == 0, err
    assert "modal skinning differs by at most" in out and "of the diagonal" in out
    status, out, err = run(capsys, "export", "loop8", SONG, "--skinning", "lbs", "--fps", 10,
                           "-o", tmp_path / "loop.usd")
    assert status == 0 and "differs" not in out


def test_render_writes_the_video_and_the_gallery(files, tmp_path, capsys):
    tmp_path = tmp_path / "out"
    status, out, err = run(capsys, "render", files / "sphere.obj", SONG, "--mapping",
                           files / "mapping.json", "-k", 20, "--fps", 8, "--size", "96x64",
                           "-o", tmp_path / "one.mp4")
    assert status == 0, err
    assert "one.mp4: 32 frames, 96x64 at 8 fps, 4.00 s of video with the song" in out
    status, out, err = run(capsys, "render", files / "sphere.obj", SONG, "-k", 20, "--gallery",
                           3, "--breed", files / "mapping.json", files / "mapping.json",
                           "--fps", 4, "--size", "160x96", "-o", tmp_path / "gallery.mp4")
    assert status == 0, err
    assert "3 tiles" in out
    assert sorted(os.listdir(tmp_path)) == ["gallery.mp4", "one.mp4"]


@pytest.mark.parametrize("arguments, message", [
    (["export", "{mesh}", "missing.ogg", "-o", "{out}/a.glb"], "missing.ogg: no such file"),
    (["export", "{files}/broken.json", SONG, "-o", "{out}/a.glb"], "broken.json"),
    (["export", "{mesh}", SONG, "--mapping", "{files}/broken.json", "-o", "{out}/a.glb"],
     "broken.json: malformed JSON"),
    (["export", "{mesh}", SONG, "-o", "{out}/a.fbx"], "unknown export format '.fbx'"),
    (["export", "{mesh}", SONG, "--format", "usd", "-o", "{out}/a.glb"], "must end in"),
    (["render", "{mesh}", SONG, "-o", "{out}/a.avi"], "name it .mp4"),
    (["render", "{mesh}", SONG, "--breed", "{files}/mapping.json", "-o", "{out}/a.mp4"],
     "without a gallery size; try --gallery 8"),
    (["render", "{mesh}", SONG, "--gallery", "20", "-o", "{out}/a.mp4"], "2 to 16 items"),
    (["render", "loop4", SONG, "--gallery", "4", "-o", "{out}/a.mp4"], "render a rig on its own"),
    (["render", "{mesh}", SONG, "--gallery", "4", "--mapping", "{files}/mapping.json", "-o",
      "{out}/a.mp4"], "a gallery makes its own mappings"),
    (["render", "{mesh}", "{files}/song.npz", "-o", "{out}/a.mp4"], "not its spectrogram"),
    (["export", "loop8", SONG, "--modes", "0,99", "-o", "{out}/a.glb"], "mode"),
])
def test_bad_input_is_one_line_and_writes_nothing(files, tmp_path, capsys, arguments, message):
    out = tmp_path / "out"
    out.mkdir()
    arguments = [a.format(mesh=files / "sphere.obj", files=files, out=out) for a in arguments]
    status, _, err = run(capsys, *arguments, "-k", 20)
    assert status == 1, err
    assert err.count("\n") == 1 and err.startswith("eigendance: error: ") and message in err, err
    assert os.listdir(out) == []


def test_an_existing_output_needs_force(files, tmp_path, capsys):
    output = tmp_path / "a.glb"
    output.write_bytes(b"mine")
    status, _, err = run(capsys, "export", files / "sphere.obj", SONG, "-k", 20, "-o", output)
    assert status == 1 and "a.glb exists; pass --force to overwrite it" in err
    assert output.read_bytes() == b"mine"
    status, _, err = run(capsys, "export", files / "sphere.obj", SONG, "-k", 20, "--force",
                         "-o", output)
    assert status == 0 and output.read_bytes()[:4] == b"glTF"


def test_bad_numbers_are_refused_by_the_parser(files, capsys):
    for flag, value in (("--size", "641x360"), ("--fps", "0"), ("--fps", "nan")):
        with pytest.raises(SystemExit) as exit:
            main(["render", str(files / "sphere.obj"), SONG, flag, value, "-o", "x.mp4"])
        assert exit.value.code == 1  # one line, exit 1, like any bad input
        assert f"argument {flag}" in capsys.readouterr().err


def test_help_names_the_formats(capsys):
    with pytest.raises(SystemExit):
        main(["export", "--help"])
    assert "glb" in capsys.readouterr().out


def test_a_very_large_output_says_its_size_and_needs_force(files, tmp_path, capsys,
                                                           monkeypatch):
    """A point cache (or animation file) beyond limits.LARGE_OUTPUT is announced with its size
    and written only with --force (here the limit is lowered to 10 kB)."""
    import eigendance.limits as limits

    monkeypatch.setattr(limits, "LARGE_OUTPUT", 1e4)
    for command, name in (("export", "dance.pc2"), ("animate", "dance.npz")):
        status, _, err = run(capsys, command, files / "sphere.obj", SONG, "-k", 20, "--mapping",
                             files / "mapping.json", "-o", tmp_path / name)
        assert status == 1 and "a very large file; pass --force to write it anyway" in err, err
        assert f"{name}: " in err and " kB" in err and not (tmp_path / name).exists()
        status, _, err = run(capsys, command, files / "sphere.obj", SONG, "-k", 20, "--mapping",
                             files / "mapping.json", "-o", tmp_path / name, "--force")
        assert status == 0 and (tmp_path / name).exists(), err
