"""Broken real-world files on the command line (docs/design.md#errors): a mesh file cut short
or indexing past its vertices, a file that is not what its suffix says, an output folder that
cannot be written — each one line `eigendance: error: <file>: <what is wrong>`, exit status 1,
no output; an OBJ with relative indices is read as it means.

Every input is made here, by the test (from a fixture where a real file is cut short).
"""

import os

import numpy as np
import pytest
import soundfile

from eigendance.cli import main
from eigendance.harmonic.mesh import load_mesh
from helpers import fixture_path

KNIGHT = fixture_path("meshes", "decimated-knight.off")  # OFF: 502 vertices, 1000 faces
TETRA_OFF = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 1 3\n3 0 2 3\n3 1 2 3\n"

TETRA_PLY = ("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
             "property float z\nelement face 4\nproperty list uchar int vertex_indices\n"
             "end_header\n" + TETRA_OFF.split("\n", 2)[2])
TETRA_STL = "solid t\n" + "".join(
    f"facet normal 0 0 0\nouter loop\n{corners}endloop\nendfacet\n" for corners in
    ["vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n", "vertex 0 0 0\nvertex 1 0 0\nvertex 0 0 1\n"]
) + "endsolid t\n"


def run(argv, capfd) -> tuple[int, str]:
    """(exit status, stderr) of one command run in-process."""
    try:
        status = main([str(arg) for arg in argv])
    except SystemExit as exit_:
        status = exit_.code
    return status, capfd.readouterr().err


def refused(argv, capfd, *fragments) -> str:
    status, err = run(argv, capfd)
    lines = err.strip().splitlines()
    assert status == 1, err
    assert len(lines) == 1 and lines[0].startswith("eigendance: error: "), err
    assert "Traceback" not in err
    for fragment in fragments:
        assert fragment in lines[0], lines[0]
    return lines[0]


def knight_cut(fraction: float) -> bytes:
    with open(KNIGHT, "rb") as file:
        data = file.read()
    return data[: int(len(data) * fraction)]


@pytest.mark.parametrize("name, content, fragment", [
    # 502 vertex lines after 2 header lines (OFF, the counts): 10 % of the bytes stop in them
    ("knight-10.off", knight_cut(0.1), "the OFF header declares 502 vertices and 1000 faces; "
     f"the file holds {len(knight_cut(0.1).splitlines()) - 2} vertices and 0 faces"),
    # the faces cut short: trimesh read the 2 faces there are as a mesh of 2 triangles
    ("faces.off", TETRA_OFF.rsplit("3 0 2 3", 1)[0],
     "the OFF header declares 4 vertices and 4 faces; the file holds 4 vertices and 2 faces"),
    ("counts.off", "OFF\n999999999999 1 0\n0 0 0\n",
     "the OFF header declares 999999999999 vertices and 1 faces; the file holds 1 vertices"),
    ("header.off", "OFF\n\n", "the OFF header must give the numbers of vertices and faces"),
    # an ASCII PLY cut in its faces: trimesh read the faces there were (548 of the knight's
    # 1000 at 80 % of its bytes)
    ("faces.ply", TETRA_PLY.rsplit("3 0 2 3", 1)[0], "the PLY header declares 4 vertex and 4 "
                                                     "face elements; the file holds 4 and 2"),
    ("cut.stl", TETRA_STL.rsplit("facet", 1)[0], "an ASCII STL cut short (it does not end in "
                                                 "endsolid)"),
    ("past.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 2 3 99\n",
     "line 6: a face uses vertex 99, but the file holds 4 vertices"),
    ("before.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\nv 0 0 1\n",
     "line 4: a face uses vertex -4, but the file holds 4 vertices (3 before the face)"),
    ("uv.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/-2 2/-1 3/-1\n",
     "line 5: a face uses texture coordinate -2, but the file holds 1 texture coordinates"),
])
def test_a_mesh_file_cut_short_or_indexing_past_its_vertices_is_one_line(tmp_path, capfd, name,
                                                                          content, fragment):
    path = tmp_path / name
    path.write_bytes(content if isinstance(content, bytes) else content.encode())
    refused(["basis", path, "-k", 2, "-o", tmp_path / "b.npz"], capfd, f"{name}: {fragment}")
    assert sorted(os.listdir(tmp_path)) == [name]


def binary_tetra_ply() -> bytes:
    """The tetrahedron as a binary little-endian PLY, its bytes laid out by hand: 4 vertices of
    3 float32 (48 bytes), 4 faces of a uchar count and 3 int32 (52 bytes)."""
    header = TETRA_PLY.split("end_header\n")[0].replace("format ascii 1.0",
                                                        "format binary_little_endian 1.0")
    vertices = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], "<f4").tobytes()
    faces = b"".join(np.uint8(3).tobytes() + np.array(face, "<i4").tobytes()
                     for face in ([0, 1, 2], [0, 1, 3], [1, 2, 3], [0, 2, 3]))
    return (header + "end_header\n").encode() + vertices + faces


@pytest.mark.parametrize("keep", [90, 47, 0])
def test_a_binary_ply_cut_short_is_one_line_with_its_counts(tmp_path, capfd, keep):
    """Stop 37 left it: trimesh said "PLY is unexpected length!". The body needs 48 + 4 × 13
    = 100 bytes (by hand, above); cut to `keep` of them it says what the header declares."""
    data = binary_tetra_ply()
    path = tmp_path / "cut.ply"
    path.write_bytes(data[:len(data) - 100 + keep])
    refused(["basis", path, "-k", 2, "-o", tmp_path / "b.npz"], capfd,
            "cut.ply: the PLY header declares 4 vertex and 4 face elements, at least 100 "
            f"bytes; the file holds {keep} after its header (a file cut short?)")
    whole = tmp_path / "whole.ply"
    whole.write_bytes(data)
    mesh = load_mesh(whole)  # the check refuses only the cut
    assert len(mesh.vertices) == 4 and len(mesh.faces) == 4


def test_relative_obj_indices_count_back_from_the_face(tmp_path):
    """OBJ's -1 is the last vertex *before the face* (trimesh counted from the file's end: the
    second face became the first one again and the first vertex was lost)."""
    path = tmp_path / "relative.obj"
    path.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                    "f -3/-3 -2/-2 -1/-1\nv 0 0 1\nf 1/1 -2/2 -1/3\nf 1 2 4\nf 2 3 4\n")
    mesh = load_mesh(path)
    # by hand, 1-based: (1 2 3), (1 3 4), (1 2 4), (2 3 4): the tetrahedron's four faces
    assert len(mesh.vertices) == 4
    assert sorted(sorted(face) for face in mesh.faces.tolist()) == [[0, 1, 2], [0, 1, 3],
                                                                   [0, 2, 3], [1, 2, 3]]
    assert np.all(mesh.vertices[1:].argmax(axis=0) == [0, 1, 2])  # the file's order kept


@pytest.mark.parametrize("name, content, fragment", [
    ("array.npz", b"\x93NUMPY" + bytes(100), "not an .npz file (an .npz is a zip archive"),
    ("text.npz", b"not a zip at all", "not an .npz file (an .npz is a zip archive"),
])
def test_a_file_that_is_not_an_npz_is_one_line(tmp_path, capfd, name, content, fragment):
    """An .npy renamed .npz was exit status 2 (np.load gave an array, not an archive); text was
    'This file contains pickled (object) data'."""
    (tmp_path / name).write_bytes(content)
    song = tmp_path / "song.wav"
    soundfile.write(song, np.zeros(8000), 8000)
    refused(["animate", tmp_path / name, song, "-o", tmp_path / "a.npz"], capfd,
            f"{name}: {fragment}")


def test_text_named_mp3_says_what_ffmpeg_says_without_its_error_number(tmp_path, capfd):
    path = tmp_path / "song.mp3"
    path.write_text("this is not an mp3\n" * 20)
    line = refused(["spectrum", path, "-o", tmp_path / "s.npz"], capfd,
                   "song.mp3: not a readable audio file (Invalid data found when processing "
                   "input)")
    assert "Errno" not in line and str(tmp_path) not in line


def test_an_output_under_a_file_is_refused_before_the_work(tmp_path, capfd, monkeypatch):
    """`gallery -o m.json` with m.json a file: was 'm.json/0.json: cannot write (File exists)'
    after the basis was solved."""
    taken = tmp_path / "m.json"
    taken.write_text("the user's file")
    monkeypatch.setattr("eigendance.cli.harmonics.basis_for", pytest.fail)  # no work
    refused(["gallery", KNIGHT, "song.ogg", "-o", taken], capfd,
            f"{taken}/0.json: cannot write ({taken} is a file, not a folder)")
    assert taken.read_text() == "the user's file"


@pytest.mark.parametrize("argv", [["basis", KNIGHT, "-k", 2], ["animate-rig", "chain"],
                                  ["blender-addon"]])
def test_a_read_only_output_folder_is_refused_before_the_work(tmp_path, capfd, monkeypatch,
                                                              argv):
    """Was 'cannot write (Read-only file system)' after the work (the basis, the dance), or
    '… need about 83.4 kB of disk; 0.0 kB is free there' where the disk check came first."""
    folder = tmp_path / "read-only"
    folder.mkdir()
    folder.chmod(0o555)
    access = os.access
    if access(folder, os.W_OK):  # root: the permission bits do not stop it; the system's
        monkeypatch.setattr(os, "access",  # answer for a read-only mount is this one
                            lambda path, mode, **kw: os.fspath(path) != str(folder)
                            and access(path, mode, **kw))
    suffix = ".zip" if argv[0] == "blender-addon" else ".npz"
    monkeypatch.setattr("eigendance.cli.harmonics.read_model", pytest.fail)
    monkeypatch.setattr("eigendance.cli.rigs.rig_from", pytest.fail)
    refused([*argv, "-o", folder / f"out{suffix}"], capfd,
            f"{folder}/out{suffix}: cannot write (Permission denied)")
    assert os.listdir(folder) == []


@pytest.mark.parametrize("name, content", [("tetra.off", TETRA_OFF), ("tetra.ply", TETRA_PLY),
                                           ("tetra.stl", TETRA_STL)])
def test_the_whole_files_read(tmp_path, name, content):
    """The files the tests above cut short are read whole: the checks refuse only the cut."""
    path = tmp_path / name
    path.write_text(content)
    mesh = load_mesh(path)
    # an STL's corners are welded: two triangles on one edge, 4 vertices
    assert len(mesh.faces) == (2 if name.endswith(".stl") else 4) and len(mesh.vertices) == 4


def test_a_presets_folder_that_is_a_file_is_one_line(tmp_path, capfd):
    """`serve --presets FILE` answered GET /api/presets with a 500 (NotADirectoryError); the
    command line said 'no preset named …'. Now the store refuses it where it starts."""
    from eigendance.errors import InputError
    from eigendance.presets.store import PresetStore

    taken = tmp_path / "presets"
    taken.write_text("the user's file")
    with pytest.raises(InputError, match="presets: the presets folder is a file, not a folder"):
        PresetStore(taken)
    soundfile.write(tmp_path / "song.wav", np.zeros(8000), 8000)
    refused(["animate", KNIGHT, tmp_path / "song.wav", "--presets", taken, "--preset", "Kick",
             "-o", tmp_path / "a.npz"], capfd,
            f"{taken}: the presets folder is a file, not a folder")
    assert sorted(os.listdir(tmp_path)) == ["presets", "song.wav"]


def test_nan_skin_weights_are_one_line_naming_them(tmp_path, capfd):
    """A NaN in a skin's weights blended the bind pose into NaN positions: the message named
    the positions ('vertex positions must be finite'), which the file holds finite."""
    import pygltflib

    document = pygltflib.GLTF2().load(fixture_path("rigged", "RiggedSimple.glb"))
    accessor = document.accessors[document.meshes[0].primitives[0].attributes.WEIGHTS_0]
    view = document.bufferViews[accessor.bufferView]
    blob = bytearray(document.binary_blob())
    start = (view.byteOffset or 0) + (accessor.byteOffset or 0)
    blob[start:start + 4] = np.float32(np.nan).tobytes()  # vertex 0's first weight
    document.set_binary_blob(bytes(blob))
    path = tmp_path / "weights.glb"
    path.write_bytes(b"".join(document.save_to_bytes()))
    for command in ("modes", "animate-rig"):
        refused([command, path, "-o", tmp_path / "out.npz"], capfd,
                "weights.glb: mesh 0 primitive 0: WEIGHTS_0 holds NaN or infinite weights "
                "(1 vertices, the first 0)")
    assert sorted(os.listdir(tmp_path)) == ["weights.glb"]


def test_a_single_triangle_at_the_default_k_names_the_file_and_the_k_that_fits(tmp_path, capfd):
    """Was 'k = 150 harmonics need a mesh of more than 150 vertices; this one has 3': no file,
    no way out. A triangle's 3 vertices hold at most 2 harmonics besides the constant."""
    path = tmp_path / "triangle.obj"
    path.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    refused(["basis", path, "-o", tmp_path / "b.npz"], capfd,
            "triangle.obj: k = 150 harmonics need a mesh of more than 150 vertices; this one "
            "has 3; try -k 2")
    status, err = run(["basis", path, "-k", 2, "-o", tmp_path / "b.npz"], capfd)
    assert status == 0, err
