import numpy as np
import pytest
import scipy.linalg

from eigendance.eigen import solve_bands, solve_eigsh
from eigendance.errors import EigendanceError
from eigendance.laplacian import laplacian
from eigendance.mesh import load_mesh
from helpers import fixture_path, sphere


def residuals(stiffness, mass, values, vectors):
    """‖Lu − λMu‖ / (max(λ,1)·‖Mu‖) per pair."""
    r = stiffness @ vectors - (mass[:, None] * vectors) * values
    return np.linalg.norm(r, axis=0) / (np.maximum(values, 1)
                                        * np.linalg.norm(mass[:, None] * vectors, axis=0))


@pytest.fixture(scope="module")
def sphere_problem():
    mesh = sphere(4)  # 2562 vertices
    return laplacian(mesh.vertices, mesh.faces)


@pytest.fixture(scope="module")
def sphere_bands(sphere_problem):
    # Small bands (40 pairs) force many band boundaries inside the sphere's multiplets.
    return solve_bands(*sphere_problem, 300, per_band=40)


def test_sphere_spectrum_is_l_l_plus_1_with_multiplicities(sphere_bands):
    values, _ = sphere_bands
    start = 0
    for degree in range(9):
        multiplet = values[start:start + 2 * degree + 1]
        # Discretisation error grows with l (2% at l = 7 on this 2562-vertex sphere).
        assert np.allclose(multiplet, degree * (degree + 1), rtol=0.004 * degree, atol=1e-8)
        assert np.ptp(multiplet) < 0.01 * max(degree, 1) ** 2, degree
        start += 2 * degree + 1
        if start < len(values):  # a clear gap to the next multiplet
            assert values[start] > (degree + 0.5) * (degree + 1.5)


def test_residuals_and_m_orthonormality(sphere_problem, sphere_bands):
    stiffness, mass = sphere_problem
    values, vectors = sphere_bands
    assert residuals(stiffness, mass, values, vectors).max() <= 1e-6
    gram = vectors.T @ (mass[:, None] * vectors)
    assert np.abs(gram - np.eye(len(values))).max() <= 1e-8


@pytest.fixture(scope="module")
def sphere_dense(sphere_problem):
    stiffness, mass = sphere_problem
    return scipy.linalg.eigh(stiffness.toarray(), np.diag(mass), subset_by_index=[0, 299])


def test_bands_equal_dense_solve_nothing_missed_or_doubled(sphere_dense, sphere_bands):
    assert np.allclose(sphere_bands[0], sphere_dense[0], rtol=1e-8, atol=1e-9)


def test_missed_copies_of_a_multiple_eigenvalue_are_found_again(sphere_problem, sphere_dense):
    """A band that lost pairs of multiplets (as one Krylov space does) gets them back."""
    import eigendance.eigen as eigen

    stiffness, mass = sphere_problem
    values, vectors = sphere_dense
    shift, radius = 20.0, 9.0  # around l = 4, down to l = 3: 16 pairs, in 4 exact multiplets
    window = np.flatnonzero(np.abs(values - shift) < radius)
    assert len(window) == 16
    lost = window[[0, 10, 11]]  # one copy of λ ≈ 11.95, two of λ ≈ 19.87
    kept = np.setdiff1d(window, lost)
    damaged = eigen.Band(shift, radius, values[kept], vectors[:, kept], None,
                         eigen.residuals(stiffness, mass, values[kept], vectors[:, kept]))
    repaired = eigen._complete_band(stiffness, mass, damaged, 3)
    assert np.allclose(repaired.eigenvalues, values[window], rtol=1e-10)
    assert repaired.residuals.max() <= eigen.RESIDUAL_TOLERANCE
    gram = repaired.eigenvectors.T @ (mass[:, None] * repaired.eigenvectors)
    assert np.abs(gram - np.eye(16)).max() <= 1e-8


def test_bands_agree_with_eigsh(sphere_problem, sphere_bands):
    baseline, _ = solve_eigsh(*sphere_problem, 300)
    assert np.allclose(sphere_bands[0], baseline, rtol=1e-8, atol=1e-10)


def test_several_components_each_have_a_zero_eigenvalue():
    mesh = load_mesh(fixture_path("meshes", "teapot.obj"))
    from scipy.sparse.csgraph import connected_components

    from eigendance.harmonics import HarmonicBasis
    from eigendance.mesh import Mesh

    basis = HarmonicBasis.from_mesh(mesh, 20, laplacian="robust")
    components = connected_components(Mesh.adjacency(mesh))[0]
    assert components >= 2
    assert np.all(np.abs(basis.eigenvalues[:components]) < 1e-8)
    assert basis.eigenvalues[components] > 1e-3


def test_mesh_with_boundary_knight():
    mesh = load_mesh(fixture_path("meshes", "decimated-knight.off"))
    stiffness, mass = laplacian(mesh.vertices, mesh.faces)
    values, vectors = solve_bands(stiffness, mass, 60, per_band=25)
    dense = scipy.linalg.eigh(stiffness.toarray(), np.diag(mass), eigvals_only=True,
                              subset_by_index=[0, 59])
    assert np.allclose(values, dense, rtol=1e-8, atol=1e-9)


def test_k_too_large():
    mesh = sphere(1)
    with pytest.raises(EigendanceError, match="more than"):
        solve_bands(*laplacian(mesh.vertices, mesh.faces), 42)


def test_gaps_between_bands_are_filled(sphere_problem, monkeypatch):
    """With bands placed apart (negative overlap) the solver must fill every gap it leaves."""
    import eigendance.eigen as eigen

    monkeypatch.setattr(eigen, "OVERLAP", -0.4)
    stiffness, mass = sphere_problem
    values, _ = solve_bands(stiffness, mass, 120, per_band=30, workers=1)
    dense = scipy.linalg.eigh(stiffness.toarray(), np.diag(mass), eigvals_only=True,
                              subset_by_index=[0, 119])
    assert np.allclose(values, dense, rtol=1e-8, atol=1e-9)


def test_inertia_mismatch_is_reported(sphere_problem):
    """A band whose Sylvester count disagrees with the accepted eigenvalues fails loudly."""
    import eigendance.eigen as eigen

    stiffness, mass = sphere_problem
    values, vectors = solve_bands(stiffness, mass, 20, per_band=30)
    liar = eigen.Band(shift=7.0, radius=1.0, eigenvalues=values, eigenvectors=vectors, below=3,
                      residuals=eigen.residuals(stiffness, mass, values, vectors))
    with pytest.raises(EigendanceError, match="3 eigenvalues lie below 7"):
        eigen._verify(values, [(liar, np.ones(len(values), bool))], [liar])
