import numpy as np
import pytest

from eigendance.errors import EigendanceError
from eigendance.harmonic.laplacian import laplacian
from helpers import sphere


@pytest.mark.parametrize("kind", ["cotan", "robust"])
def test_psd_symmetric_zero_row_sums_and_area(kind):
    mesh = sphere(3)
    stiffness, mass = laplacian(mesh.vertices, mesh.faces, kind)
    assert abs(stiffness - stiffness.T).max() == 0
    assert np.allclose(stiffness @ np.ones(len(mass)), 0, atol=1e-10)
    assert stiffness.diagonal().min() > 0  # L_ii = Σ cotangent weights: PSD convention
    # The areas sum to the inscribed polyhedron's area, a little below 4π.
    assert 0.98 * 4 * np.pi < mass.sum() < 4 * np.pi


def test_cotan_weight_of_a_right_triangle_pair():
    # Unit square split along its diagonal: the diagonal's opposite angles are 90°, cot = 0;
    # each side has one opposite angle of 45°, so L_ij = -cot(45°)/2 = -1/2.
    vertices = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], float)
    faces = np.array([[0, 1, 2], [0, 2, 3]])
    stiffness, mass = laplacian(vertices, faces)
    assert stiffness[0, 2] == pytest.approx(0, abs=1e-12)
    assert stiffness[0, 1] == pytest.approx(-0.5)
    assert mass.sum() == pytest.approx(1.0)


def test_unknown_kind():
    mesh = sphere(1)
    with pytest.raises(EigendanceError, match="unknown Laplacian"):
        laplacian(mesh.vertices, mesh.faces, "graph")
