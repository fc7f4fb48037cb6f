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


# Mixed Voronoi areas (Meyer et al. 2003), by hand. A triangle with no obtuse angle gives vertex i
# (1/8)·Σ |e|²·cot(angle opposite e) over its two edges e at i; an obtuse one gives half its area
# to the obtuse vertex and a quarter to each other (barycentric lumping: a third to each).
MIXED_VORONOI = {
    # The unit square split along its diagonal: right angles at 1 and 3 (Voronoi and the
    # obtuse rule agree there: 1/2 of 1/2); 0 and 2 take 1/8 from each triangle.
    "square": ([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], [[0, 1, 2], [0, 2, 3]],
               [1 / 4, 1 / 4, 1 / 4, 1 / 4]),
    # Acute, area 2: cot = 1/2, 1/2, 3/4 at the corners; |e01|² = 4, |e02|² = |e12|² = 5.
    # Vertex 0: (4·3/4 + 5·1/2)/8 = 11/16; vertex 2: (5·1/2 + 5·1/2)/8 = 5/8.
    "acute": ([[0, 0, 0], [2, 0, 0], [1, 2, 0]], [[0, 1, 2]], [11 / 16, 11 / 16, 5 / 8]),
    # Obtuse at vertex 2 ((-1, -1)·(3, -1) = -2 < 0), area 2: 1/2, 1/2 and 1 (the plain
    # Voronoi formula would give vertex 0 a negative area, (2·3 − 16·1/2)/8 = −1/4).
    "obtuse": ([[0, 0, 0], [4, 0, 0], [1, 1, 0]], [[0, 1, 2]], [1 / 2, 1 / 2, 1.0]),
}


@pytest.mark.parametrize("name", MIXED_VORONOI)
def test_mass_is_the_mixed_voronoi_area(name):
    vertices, faces, areas = MIXED_VORONOI[name]
    _, mass = laplacian(np.array(vertices, float), np.array(faces))
    np.testing.assert_allclose(mass, areas, rtol=1e-12)


def test_unknown_kind():
    mesh = sphere(1)
    with pytest.raises(EigendanceError, match="unknown Laplacian"):
        laplacian(mesh.vertices, mesh.faces, "graph")
