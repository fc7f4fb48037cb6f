"""Small meshes made by code and paths of the test fixtures."""

import os

import trimesh

from eigendance.harmonic.mesh import Mesh

FIXTURES = os.path.join(os.path.dirname(__file__), "fixtures")


def sphere(subdivisions=3) -> Mesh:
    """Unit icosphere (642 vertices at 3 subdivisions, 2562 at 4)."""
    icosphere = trimesh.creation.icosphere(subdivisions)
    return Mesh.from_arrays(icosphere.vertices, icosphere.faces, name="sphere")


def fixture_path(*parts):
    return os.path.join(FIXTURES, *parts)


def bumpy_sphere(subdivisions=2) -> Mesh:
    """An icosphere with a smooth bump pattern and a stretch: energy in many harmonics."""
    import numpy as np

    icosphere = trimesh.creation.icosphere(subdivisions)
    vertices = icosphere.vertices * [1.3, 1.0, 0.8]
    x, y, z = icosphere.vertices.T
    vertices = vertices * (1 + 0.15 * np.sin(3 * x) * np.cos(2 * y) + 0.1 * z ** 2)[:, None]
    return Mesh.from_arrays(vertices, icosphere.faces, name="bumpy sphere")
