"""One reader for every model (docs/design.md#appearance): every mesh node of the scene with its
world transform, Draco, materials and textures, OBJ with its MTL, the drawn → welded map, and
one clear line for what cannot be read. Checked against trimesh's own scene reader, the files'
accessor bounds and hand-made spoiled copies of the real fixtures."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
import warnings

import numpy as np
import pygltflib
import pytest
import trimesh
from scipy.spatial import cKDTree

from eigendance.assets import other_formats
from eigendance.assets.appearance import WELD_TOLERANCE
from eigendance.assets.gltf import GltfFile
from eigendance.assets.reader import read_model
from eigendance.errors import InputError, ModelWarning
from eigendance.harmonic.mesh import load_mesh
from helpers import fixture_path, start

CAKE = fixture_path("textured", "kenney_cakeBirthday.glb")
SPEEDER = fixture_path("textured", "craft_speederD.gltf")
MORPHS = fixture_path("textured", "MorphStressTest.gltf")
ASTRONAUT = fixture_path("rigged", "quaternius_Astronaut_FinnTheFrog.glb")


def one_line_error(call, match=None) -> str:
    with pytest.raises(InputError, match=match) as caught:
        call()
    assert "\n" not in str(caught.value)
    return str(caught.value)


def test_every_mesh_node_comes_in_with_its_world_transform():
    """The cake draws one mesh under five nodes (instancing) and another under a sixth: the
    same triangles in world coordinates as trimesh's scene reader gives."""
    model = read_model(CAKE)
    reference = trimesh.load(CAKE, force="mesh", process=False)
    ours = np.sort(np.sort(model.positions[model.triangles].round(5), axis=1).reshape(-1, 9),
                   axis=0)
    theirs = np.sort(np.sort(reference.vertices[reference.faces].round(5), axis=1)
                     .reshape(-1, 9), axis=0)
    assert len(ours) == len(theirs) == 6 * 222
    np.testing.assert_allclose(ours, theirs, atol=1e-4)
    assert len(model.materials) == 7
    assert [len(p.triangles) for p in model.parts] == [6 * n for n in (16, 37, 63, 50, 6, 6, 44)]


def test_drawn_vertices_follow_their_welded_vertex():
    mesh = load_mesh(CAKE)
    look, model = mesh.appearance, read_model(CAKE)
    drawn = model.positions  # nothing is dropped on the cake: the same drawn vertices
    assert look.n == len(drawn)
    gap = np.linalg.norm(drawn - mesh.original_vertices[look.welded], axis=1)
    assert gap.max() <= WELD_TOLERANCE * np.linalg.norm(np.ptp(drawn, axis=0)) * 1.01
    assert look.n > mesh.n  # split at seams and between parts of different materials
    faces = {tuple(sorted(f)) for f in mesh.faces.tolist()}
    assert faces <= {tuple(sorted(f)) for f in look.welded[look.triangles].tolist()}


def test_a_gltf_with_its_bin_beside_it_and_without(tmp_path):
    model = read_model(SPEEDER)
    assert len(model.parts) == 4 and len(model.triangles) == 322
    shutil.copy(SPEEDER, tmp_path / "alone.gltf")
    one_line_error(lambda: read_model(tmp_path / "alone.gltf"), "craft_speederD_data.bin.*missing")


@pytest.mark.parametrize("uri", ["../craft_speederD_data.bin", "/etc/passwd", "sub/../../x.bin"])
def test_files_outside_the_models_folder_are_refused(tmp_path, uri):
    document = json.loads(open(SPEEDER).read())
    document["buffers"][0]["uri"] = uri
    (tmp_path / "model").mkdir()
    (tmp_path / "model" / "evil.gltf").write_text(json.dumps(document))
    shutil.copy(fixture_path("textured", "craft_speederD_data.bin"), tmp_path)
    one_line_error(lambda: read_model(tmp_path / "model" / "evil.gltf"), "outside the model")


def test_an_accessor_larger_than_its_buffer_is_one_line(tmp_path):
    document = json.loads(open(SPEEDER).read())
    document["accessors"][0]["count"] *= 40
    (tmp_path / "big.gltf").write_text(json.dumps(document))
    shutil.copy(fixture_path("textured", "craft_speederD_data.bin"), tmp_path)
    one_line_error(lambda: read_model(tmp_path / "big.gltf"), "accessor 0")


def test_a_required_extension_we_cannot_decode_is_named(tmp_path):
    document = json.loads(open(SPEEDER).read())
    document["extensionsUsed"] = ["EXT_meshopt_compression"]
    document["extensionsRequired"] = ["EXT_meshopt_compression"]
    (tmp_path / "packed.gltf").write_text(json.dumps(document))
    one_line_error(lambda: read_model(tmp_path / "packed.gltf"), "EXT_meshopt_compression")


def test_what_cannot_be_kept_is_listed_once(tmp_path):
    document = json.loads(open(SPEEDER).read())
    lines = dict(document["meshes"][0]["primitives"][0], mode=1)
    document["meshes"][0]["primitives"].append(lines)
    (tmp_path / "lines.gltf").write_text(json.dumps(document))
    shutil.copy(fixture_path("textured", "craft_speederD_data.bin"), tmp_path)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        model = read_model(tmp_path / "lines.gltf")
    found = [w for w in caught if issubclass(w.category, ModelWarning)]
    assert len(found) == 1 and "1 line primitive" in str(found[0].message)
    assert len(model.triangles) == 322
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        read_model(MORPHS)  # its own morph targets: the rest shape is kept, not the targets
    assert "16 morph targets" in str(caught[0].message)


def test_a_broken_texture_costs_only_the_texture(tmp_path):
    document = json.loads(open(MORPHS).read())
    document["images"][1] = {"uri": "data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAA"}  # cut
    (tmp_path / "broken.gltf").write_text(json.dumps(document))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        model = read_model(tmp_path / "broken.gltf")
    assert "broken image" in " ".join(str(w.message) for w in caught)
    assert model.materials[0].base_color_texture is None  # image 1 was its base colour
    assert model.materials[0].occlusion_texture is not None
    assert len(model.images) == 2


def test_draco_primitives_are_decoded():
    """The astronaut is Draco-compressed: the decoded positions fill the accessor's bounds."""
    gltf = GltfFile(ASTRONAUT)
    for mesh in gltf.document.meshes:
        primitive = mesh.primitives[0]
        accessor = gltf.document.accessors[primitive.attributes.POSITION]
        attributes, faces = gltf.draco(primitive.extensions["KHR_draco_mesh_compression"], "")
        positions = attributes["POSITION"]
        assert len(positions) == accessor.count and faces.max() < accessor.count
        np.testing.assert_allclose(positions.min(axis=0), accessor.min, atol=1e-3)
        np.testing.assert_allclose(positions.max(axis=0), accessor.max, atol=1e-3)
    model = read_model(ASTRONAUT)
    assert len(model.images) == 1 and model.images[0].mime_type in ("image/png", "image/jpeg")
    assert model.materials[0].base_color_texture is not None and len(model.uvs) == 1


def test_an_obj_keeps_its_mtl_and_a_plain_obj_reads_as_before():
    robot = load_mesh(fixture_path("textured", "robot.obj")).appearance
    assert len(robot.materials) == 3
    blue = max(robot.materials, key=lambda m: m.base_color[2] - m.base_color[0])
    np.testing.assert_allclose(blue.base_color[:3], [0.0, 0.4179, 1.0], atol=1e-3)  # Kd, linear
    beetle = load_mesh(fixture_path("meshes", "beetle.obj"))
    plain = trimesh.load(fixture_path("meshes", "beetle.obj"), force="mesh", process=False)
    assert beetle.appearance is None
    np.testing.assert_allclose(beetle.original_vertices,
                               plain.vertices[np.unique(beetle.vertex_map[beetle.vertex_map >= 0],
                                                        return_index=True)[1]], atol=1e-12)


def test_ply_vertex_colours_come_through(tmp_path):
    box = trimesh.creation.box()
    box.visual.vertex_colors = np.tile([255, 0, 0, 255], (len(box.vertices), 1))
    box.export(tmp_path / "red.ply")
    look = load_mesh(tmp_path / "red.ply").appearance
    np.testing.assert_allclose(look.colors, np.tile([1.0, 0, 0, 1], (look.n, 1)))


def test_a_format_we_cannot_read_says_how_to_convert(tmp_path):
    (tmp_path / "Stag.fbx").write_bytes(b"Kaydara FBX Binary  \x00")
    message = one_line_error(lambda: load_mesh(tmp_path / "Stag.fbx"))
    assert "File › Export › glTF 2.0" in message


# A conversion that never ends: its folder's name printed, then Blender "works" for a minute.
CONVERTING = """
import os, sys, time
from eigendance.assets import other_formats
other_formats.blender_available = lambda: True
def export(path, glb, *rest):
    print(os.path.dirname(glb), flush=True)
    time.sleep(60)
other_formats._blender_export = export
with other_formats.converted(sys.argv[1], "Stag.fbx"):
    pass
"""


def test_the_folders_of_killed_conversions_are_swept_by_the_next(tmp_path, monkeypatch):
    """A conversion killed outright (SIGKILL) leaves its temporary folder; the next conversion
    removes it (older than writes.FRESH_SECONDS), and leaves a running one's alone."""
    fbx, temporary = tmp_path / "Stag.fbx", tmp_path / "tmp"
    fbx.write_bytes(b"Kaydara FBX Binary  \x00")
    temporary.mkdir()
    running = [start([sys.executable, "-c", CONVERTING, str(fbx)], stdout=subprocess.PIPE,
                     text=True, env=dict(os.environ, TMPDIR=str(temporary))) for _ in range(2)]
    try:
        killed, alive = [process.stdout.readline().strip() for process in running]
        running[0].kill()
        running[0].wait()
        hour_ago = time.time() - 3600
        for folder in (killed, alive):
            assert os.path.isdir(folder) and folder.startswith(str(temporary))
            os.utime(folder, (hour_ago, hour_ago))
        monkeypatch.setattr(tempfile, "tempdir", str(temporary))
        monkeypatch.setattr(other_formats, "blender_available", lambda: True)
        monkeypatch.setattr(other_formats, "_blender_export",
                            lambda path, glb, *rest: open(glb, "wb").close())
        with other_formats.converted(str(fbx), "Stag.fbx") as glb:
            assert os.path.isfile(glb)
        assert not os.path.exists(killed) and os.path.isdir(alive)
        assert os.listdir(temporary) == [os.path.basename(alive)]
    finally:
        for process in running:
            process.kill()
            process.wait()


def test_every_shared_kind_of_file_reads_with_positions_that_match_trimesh():
    """trimesh reads (non-Draco) glTF scenes itself: our drawn triangles are its triangles."""
    for path in (SPEEDER, fixture_path("rigged", "Fox.glb")):
        ours = read_model(path)
        theirs = trimesh.load(path, force="mesh", process=False)
        tree = cKDTree(theirs.vertices)
        assert tree.query(ours.positions)[0].max() < 1e-5 * np.ptp(theirs.vertices, 0).max()
        assert pygltflib.GLTF2().load(path).meshes
