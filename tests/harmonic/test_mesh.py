import numpy as np
import pytest
import trimesh

from eigendance.errors import EigendanceError
from eigendance.harmonic.mesh import Mesh, load_mesh
from helpers import fixture_path

TETRAHEDRON_V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], float)
TETRAHEDRON_F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])


def test_normalised_into_unit_box_and_invertible():
    vertices = TETRAHEDRON_V * 7 + [3, -2, 5]
    mesh = Mesh.from_arrays(vertices, TETRAHEDRON_F)
    assert np.allclose(mesh.vertices.min(0).min(), -1) and np.allclose(mesh.vertices.max(), 1)
    assert np.allclose(mesh.original_vertices, vertices)


def test_cleanup_counts_and_keeps_vertex_order():
    # vertex 4 duplicates vertex 1, vertex 5 is unused, triangle [0,1,4] collapses, last repeats.
    vertices = np.vstack([TETRAHEDRON_V, TETRAHEDRON_V[1], [[9, 9, 9]]])
    faces = np.vstack([TETRAHEDRON_F, [[0, 1, 4], [2, 4, 3]]])
    mesh = Mesh.from_arrays(vertices, faces)
    assert mesh.report == {"duplicate_vertices": 1, "unreferenced_vertices": 1,
                           "zero_area_faces": 1, "repeated_faces": 1}
    assert len(mesh.vertices) == 4 and len(mesh.faces) == 4
    assert list(mesh.vertex_map) == [0, 1, 2, 3, 1, -1]
    assert np.allclose(mesh.original_vertices, TETRAHEDRON_V)


def test_zero_area_sliver_removed():
    vertices = np.vstack([TETRAHEDRON_V, [[0.5, 0.5, 0]]])  # on the segment from vertex 1 to 2
    faces = np.vstack([TETRAHEDRON_F, [[1, 4, 2]]])
    assert Mesh.from_arrays(vertices, faces).report["zero_area_faces"] == 1


@pytest.mark.parametrize("vertices, faces, message", [
    (np.zeros((0, 3)), np.zeros((0, 3), int), "vertices must be"),
    (TETRAHEDRON_V, np.zeros((0, 3), int), "faces must be"),
    (np.where(np.eye(4, 3) == 1, np.nan, TETRAHEDRON_V), TETRAHEDRON_F, "NaN or infinite"),
    (TETRAHEDRON_V, TETRAHEDRON_F + 1, "outside 0..3"),
    (TETRAHEDRON_V, TETRAHEDRON_F[:, :2], "faces must be"),
    (np.zeros((4, 3)), TETRAHEDRON_F, r"vertices \(nearly\) coincide"),
    (TETRAHEDRON_V * 1e300, TETRAHEDRON_F, r"coordinates reach 1e\+300"),
])
def test_bad_arrays_give_one_line_errors(vertices, faces, message):
    with pytest.raises(EigendanceError, match=message) as error:
        Mesh.from_arrays(vertices, faces)
    assert "\n" not in str(error.value)


@pytest.mark.parametrize("suffix", [".obj", ".ply", ".off", ".stl", ".glb"])
def test_formats_round_trip(tmp_path, suffix):
    box = trimesh.creation.box()
    path = tmp_path / f"box{suffix}"
    box.export(path)
    mesh = load_mesh(path)
    assert len(mesh.vertices) == 8 and len(mesh.faces) == 12


def test_gltf_scene_primitives_are_merged(tmp_path):
    scene = trimesh.Scene([trimesh.creation.box(), trimesh.creation.icosphere(1)])
    scene.geometry["geometry_1"].apply_translation([3, 0, 0])
    path = tmp_path / "two.glb"
    scene.export(path)
    mesh = load_mesh(path)
    assert len(mesh.vertices) == 8 + 42


@pytest.mark.parametrize("content, suffix, message", [
    (b"", ".obj", "empty"),
    (b"v 0 0 0\nv 1 0 0\nv 0 1 0\n", ".obj", "no triangles"),
    (b"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", ".off", "outside 0..2|cannot read"),
    (b"garbage", ".xyz", "unknown mesh format"),
    (b"\x00\x01binary junk", ".ply", "cannot read|no triangles"),
])
def test_broken_files_give_one_line_errors(tmp_path, content, suffix, message):
    path = tmp_path / f"broken{suffix}"
    path.write_bytes(content)
    with pytest.raises(EigendanceError, match=message) as error:
        load_mesh(path)
    assert "\n" not in str(error.value)


def test_missing_file():
    with pytest.raises(EigendanceError, match="no such file"):
        load_mesh("/nonexistent/mesh.obj")


def test_non_manifold_edges_are_counted():
    mesh = load_mesh(fixture_path("meshes", "beetle.obj"))
    assert mesh.non_manifold_edge_count() > 0
    assert load_mesh(fixture_path("meshes", "decimated-knight.off")).non_manifold_edge_count() == 0
