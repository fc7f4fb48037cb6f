"""The Blender add-on in real Blender (docs/design.md#blender-add-on): `eigendance blender-addon`
writes the zip, Blender 5.0 and 4.2 LTS (the bpy wheels, as tests/export/test_blender.py finds
them) install and enable it, and its operators bake the cat, a textured model and the Fox rig
on a 20 s part of a song.

At five frames spread over the song, the evaluated positions equal what `eigendance animate` and
`eigendance animate-rig` compute on the same inputs within 1e-4 of the bounding-box diagonal;
the sound strip holds the song (5.0: the 4.2 wheel has no audio); the object keeps its
materials and its transform; undo removes the bake; a bad song and a missing command are one
line in the report.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import zipfile
from importlib.resources import files

import numpy as np
import pytest
from export_helpers import (
    LONG_SONG,
    check_positions,
    in_file_order,
    read_obj,
    spread_frames,
)
from scipy.spatial import cKDTree
from test_blender import blender

from eigendance.cli.main import main
from eigendance.music.mapping import Mapping
from helpers import fixture_path

ROOT = os.path.join(os.path.dirname(__file__), "..", "..")
SCRIPT = os.path.join(os.path.dirname(__file__), "blender_addon_run.py")
CAT = str(files("eigendance") / "data" / "cat_lowres.obj")  # the built-in cat
ROBOT = fixture_path("textured", "robot.obj")
FOX = fixture_path("rigged", "Fox.glb")
FPS, START, DURATION, K = 5, 0.4, 20.0, 30
COUNT = 101  # t_i = i/fps, i = 0 … 20 s · 5 fps (file_times)
SAMPLES = spread_frames(COUNT, 5)
ENV = {**os.environ, "PYTHONPATH": os.path.abspath(os.path.join(ROOT, "src"))}


def eigendance(*words):
    run = subprocess.run([sys.executable, "-m", "eigendance", *map(str, words)], env=ENV,
                         capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr[-2000:]


def write_obj(path, vertices, triangles):
    """The OBJ the add-on writes of these float32 numbers (shortest exact text), written here."""
    lines = [f"v {float(x)!r} {float(y)!r} {float(z)!r}" for x, y, z in
             np.asarray(vertices, dtype=np.float32)]
    lines += [f"f {a} {b} {c}" for a, b, c in np.asarray(triangles) + 1]
    path.write_text("\n".join(lines) + "\n")


def animated(tmp_path, name, vertices, triangles, mapping):
    """`eigendance animate` on the same vertices: its positions at the sample frames."""
    mesh = tmp_path / f"{name}.obj"
    write_obj(mesh, vertices, triangles)
    out = tmp_path / f"{name}.npz"
    eigendance("animate", mesh, LONG_SONG, "-k", K, "--mapping", mapping, "--fps", FPS,
               "--start", START, "--duration", DURATION, "-o", out)
    positions = np.load(out)["positions"]
    assert len(positions) == COUNT
    return positions[SAMPLES]


def gallery_item(tmp_path, name, vertices, triangles, item):
    mesh = tmp_path / f"{name}-gallery.obj"
    write_obj(mesh, vertices, triangles)
    eigendance("gallery", mesh, LONG_SONG, "-k", K, "-o", tmp_path / f"{name}-gallery")
    return tmp_path / f"{name}-gallery" / f"{item - 1}.json"


def test_blender_addon_writes_an_extension_zip(tmp_path):
    path = tmp_path / "eigendance_blender.zip"
    assert main(["blender-addon", "-o", str(path)]) == 0
    with zipfile.ZipFile(path) as archive:
        names = set(archive.namelist())
        manifest = archive.read("blender_manifest.toml").decode()
    assert {"blender_manifest.toml", "__init__.py", "operators.py", "runner.py"} <= names
    assert 'id = "eigendance"' in manifest and 'blender_version_min = "4.2.0"' in manifest
    assert main(["blender-addon", "-o", str(path)]) == 1  # never over a file unasked
    assert main(["blender-addon", "-o", str(tmp_path / "addon.tar")]) == 1


@pytest.mark.parametrize("version", ["5.0", "4.2"])
def test_the_addon_bakes_as_the_command_line_animates(version, tmp_path):
    python = blender(version)
    addon = tmp_path / "eigendance_blender.zip"
    assert main(["blender-addon", "-o", str(addon)]) == 0
    cat_vertices, cat_faces = read_obj(CAT)
    cat_mapping = gallery_item(tmp_path, "cat", cat_vertices, cat_faces, 3)
    plan = {"zip": str(addon), "command": f"{sys.executable} -m eigendance",
            "song": os.path.abspath(LONG_SONG), "fps": FPS, "start": START,
            "duration": DURATION, "k": K, "samples": SAMPLES,
            "cat": {"obj": str(tmp_path / "cat-gallery.obj"), "mapping": str(cat_mapping)},
            "textured": {"obj": ROBOT, "item": 5}, "fox": {"glb": FOX},
            "blend": str(tmp_path / "scene.blend")}
    (tmp_path / "plan.json").write_text(json.dumps(plan))
    out = tmp_path / "found.npz"
    home = tmp_path / "home"  # the extension installs into this user's Blender, not the tester's
    run = subprocess.run([python, SCRIPT, str(tmp_path / "plan.json"), str(out)],
                         env={**ENV, "HOME": str(home), "BLENDER_USER_RESOURCES": str(home)},
                         capture_output=True, text=True, timeout=1200)
    assert run.returncode == 0 and out.exists(), run.stdout[-3000:] + run.stderr[-3000:]
    assert "Traceback" not in run.stdout + run.stderr
    found = dict(np.load(out))
    assert str(found["version"]).startswith(version)

    # The cat: the same vertices, so the same order; its transform is its own.
    expected = in_file_order(animated(tmp_path, "cat", found["cat_rest"],
                                      found["cat_triangles"], cat_mapping),
                             found["cat_rest"], found["cat_triangles"])
    diagonal = float(np.linalg.norm(np.ptp(found["cat_rest"], axis=0)))
    check_positions(found["cat_frames"], expected, diagonal, 1e-4, f"Blender {version} cat")
    assert np.abs(expected[2] - expected[0]).max() > 1e-3 * diagonal  # it moves

    # The textured robot, imported by Blender with its materials, gallery item 5.
    robot_mapping = gallery_item(tmp_path, "robot", found["textured_rest"],
                                 found["textured_triangles"], 5)
    expected = in_file_order(animated(tmp_path, "robot", found["textured_rest"],
                                      found["textured_triangles"], robot_mapping),
                             found["textured_rest"], found["textured_triangles"])
    diagonal = float(np.linalg.norm(np.ptp(found["textured_rest"], axis=0)))
    check_positions(found["textured_frames"], expected, diagonal, 1e-4, f"Blender {version} robot")
    check_positions(found["cache_frames"], expected, diagonal, 1e-4,
                    f"Blender {version} robot, Mesh Cache")
    assert list(found["cache_modifiers"])[:1] == ["MESH_CACHE"]
    assert (tmp_path / "eigendance" / "robot.pc2").exists()
    assert "in no face" in str(found["cat_cache"])
    before, after = found["textured_materials"]
    assert len(before) > 0 and list(before) == list(after)
    for name in ("cat", "textured"):
        assert bool(found[f"{name}_undone"]), f"{name}: undo left the bake"
        first, last, fps = found[f"{name}_timing"]
        assert (last - first + 1, fps) == (COUNT, FPS)

    # The Fox: the body transforms of animate-rig, on Blender's own skin (nearest at rest).
    reference = tmp_path / "fox.npz"
    eigendance("animate-rig", FOX, LONG_SONG, "--skinning", "lbs", "--fps", FPS, "--start",
               START, "--duration", DURATION, "-o", reference)
    positions = np.load(reference)["positions"][SAMPLES]
    rest = np.load(reference)["rest_vertices"]
    z_up = np.array([[1.0, 0, 0], [0, 0, -1], [0, 1, 0]])  # glTF Y up in Blender
    distance, index = cKDTree(rest @ z_up.T).query(found["fox_rest"])
    diagonal = float(np.linalg.norm(np.ptp(rest, axis=0)))
    assert distance.max() <= 1e-5 * diagonal
    check_positions(found["fox_frames"], positions[:, index] @ z_up.T, diagonal, 1e-4,
                    f"Blender {version} Fox")

    if version == "5.0":  # the 4.2 wheel is built without audio: no sound strip there
        for name in ("cat", "textured", "fox"):
            song, start = found[f"{name}_strip"]
            assert os.path.samefile(song, LONG_SONG) and int(start) == 1
    back = str(found["gallery_mapping"])  # saved in the page, back in the scene's settings
    assert os.path.dirname(back) == str(tmp_path / "eigendance")  # beside the .blend
    assert Mapping.load(back).to_json() == Mapping.load(str(cat_mapping)).to_json()
    for case in ("bad_song", "no_command"):
        message = str(found[case])
        assert message and "\n" not in message.strip() and "Traceback" not in message, message
    assert "not found" in str(found["no_command"]) and "pip install" in str(found["no_command"])
