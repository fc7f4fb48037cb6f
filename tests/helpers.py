"""Small meshes made by code and paths of the test fixtures."""

import os

import trimesh

from eigendance.mesh import Mesh

FIXTURES = os.path.join(os.path.dirname(__file__), "fixtures")
SHARED = os.path.normpath(os.path.join(os.path.dirname(__file__), "..", "..", "shared", "data"))


def sphere(subdivisions=3) -> Mesh:
    """Unit icosphere (642 vertices at 3 subdivisions, 2562 at 4)."""
    icosphere = trimesh.creation.icosphere(subdivisions)
    return Mesh.from_arrays(icosphere.vertices, icosphere.faces, name="sphere")


def fixture_path(*parts):
    return os.path.join(FIXTURES, *parts)
