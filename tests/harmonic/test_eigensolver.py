import numpy as np
import pytest
import scipy.linalg

import eigendance.harmonic.eigensolver as eigen
import eigendance.harmonic.slicing as slicing
from eigendance.errors import EigendanceError
from eigendance.harmonic.eigensolver import solve_bands, solve_eigsh
from eigendance.harmonic.laplacian import laplacian
from eigendance.harmonic.mesh import load_mesh
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


def test_several_components_each_have_a_zero_eigenvalue(monkeypatch):
    """The solver's handling of several components: the teapot's pieces uncoupled (coupled,
    the operator is one component: tests/harmonic/test_parts.py)."""
    from eigendance.harmonic import laplacian as operators

    monkeypatch.setattr(operators, "CONTACT_STIFFNESS", 0.0)
    mesh = load_mesh(fixture_path("meshes", "teapot.obj"))
    from scipy.sparse.csgraph import connected_components

    from eigendance.harmonic.basis import HarmonicBasis
    from eigendance.harmonic.mesh import Mesh

    basis = HarmonicBasis.from_mesh(mesh, 20, laplacian="robust")
    components = connected_components(Mesh.adjacency(mesh))[0]
    assert components >= 2
    assert np.all(np.abs(basis.eigenvalues[:components]) < 1e-8)
    assert basis.eigenvalues[components] > 1e-3


def assert_knight_matches_dense():
    """60 band pairs on a mesh with a boundary and no symmetries equal a dense solve."""
    mesh = load_mesh(fixture_path("meshes", "decimated-knight.off"))
    stiffness, mass = laplacian(mesh.vertices, mesh.faces)
    values, _ = solve_bands(stiffness, mass, 60, per_band=25)
    dense = scipy.linalg.eigh(stiffness.toarray(), np.diag(mass), eigvals_only=True,
                              subset_by_index=[0, 59])
    assert np.allclose(values, dense, rtol=1e-8, atol=1e-9)


def test_mesh_with_boundary_knight():
    assert_knight_matches_dense()


def test_k_too_large():
    mesh = sphere(1)
    with pytest.raises(EigendanceError, match="more than"):
        solve_bands(*laplacian(mesh.vertices, mesh.faces), 42)


def test_gaps_between_bands_are_filled(sphere_problem, monkeypatch):
    """With bands placed apart (negative overlap) the solver must fill every gap it leaves."""
    monkeypatch.setattr(slicing, "OVERLAP", -0.4)
    stiffness, mass = sphere_problem
    values, _ = solve_bands(stiffness, mass, 120, per_band=30, workers=1)
    dense = scipy.linalg.eigh(stiffness.toarray(), np.diag(mass), eigvals_only=True,
                              subset_by_index=[0, 119])
    assert np.allclose(values, dense, rtol=1e-8, atol=1e-9)


def test_inertia_mismatch_is_reported(sphere_problem):
    """A band whose Sylvester count disagrees with the accepted eigenvalues fails loudly."""
    stiffness, mass = sphere_problem
    values, vectors = solve_bands(stiffness, mass, 20, per_band=30)
    liar = eigen.Band(shift=7.0, radius=1.0, eigenvalues=values, eigenvectors=vectors, below=3,
                      residuals=eigen.residuals(stiffness, mass, values, vectors))
    with pytest.raises(EigendanceError, match="3 eigenvalues lie below 7"):
        eigen._verify(values, [(liar, np.ones(len(values), bool))], [liar])


def test_null_space_is_one_constant_per_component(monkeypatch):
    from scipy.sparse.csgraph import connected_components

    from eigendance.harmonic import laplacian as operators
    from eigendance.harmonic.eigensolver import null_space
    from eigendance.harmonic.mesh import Mesh

    mesh = load_mesh(fixture_path("meshes", "teapot.obj"))
    coupled, mass = laplacian(mesh.vertices, mesh.faces, "robust")
    assert len(null_space(coupled, mass, 1000)) == 1  # the pieces coupled: one component
    monkeypatch.setattr(operators, "CONTACT_STIFFNESS", 0.0)
    stiffness, mass = laplacian(mesh.vertices, mesh.faces, "robust")
    null = null_space(stiffness, mass, 1000)
    assert len(null) == connected_components(Mesh.adjacency(mesh))[0] >= 2
    assert np.abs(null @ (mass[:, None] * null.T) - np.eye(len(null))).max() < 1e-12
    assert np.abs(stiffness @ null.T).max() < 1e-10 * abs(stiffness).max()
    assert len(null_space(stiffness, mass, 1)) == 1  # at most as many as asked for


def test_counting_function_inverts_weyl_law():

    area = 4 * np.pi  # N(λ) = λ
    assert np.isclose(slicing.counting(np.array([]), area)(250), 250)
    # Fitted from pairs that follow N(λ) = 2λ + 3√λ: the inverse is found beyond them.
    index = np.arange(300) + 0.5
    values = ((-3 + np.sqrt(9 + 8 * index)) / 4) ** 2  # N(λ_j) = j + ½
    assert np.isclose(slicing.counting(values, area)(2 * 30**2 + 3 * 30), 30**2, rtol=1e-9)


def test_trusted_radius_leaves_out_a_multiple_eigenvalue_on_the_edge():
    from eigendance.harmonic.eigensolver import _trusted_radius

    # The farthest pair may be one of several copies, the others unseen at the same distance:
    # the window stops before it, and before all returned copies of it.
    assert 0.5 < _trusted_radius(np.array([0.1, 0.5, 1.0])) < 1.0
    assert 0.5 < _trusted_radius(np.array([0.1, 0.5, 1.0, 1.0 + 1e-12, 1.0])) < 1.0
    assert _trusted_radius(np.array([2.0])) > 2.0  # a single pair is its own window


def test_refine_sharpens_low_eigenpairs(sphere_problem, sphere_dense):
    from eigendance.harmonic.eigensolver import _refine, residuals

    stiffness, mass = sphere_problem
    values, vectors = sphere_dense
    # A pair found from a far shift errs along high frequencies: its residual scales with
    # λ_max. One inverse-iteration step brings that scale down to its own λ.
    noise = stiffness @ np.random.default_rng(0).standard_normal((len(mass), 3)) / mass[:, None]
    noise /= np.sqrt(np.einsum("ij,i,ij->j", noise, mass, noise))
    rough = vectors[:, 1:4] + 1e-8 * noise
    before = residuals(stiffness, mass, values[1:4], rough).min()
    sharp_values, sharp = _refine(stiffness, mass, rough)
    assert np.allclose(sharp_values, 2, rtol=0.01)  # l = 1: λ = l(l+1)
    assert np.allclose(sharp_values, values[1:4], rtol=1e-12)
    assert residuals(stiffness, mass, sharp_values, sharp).max() < before / 100


def test_identical_components_many_exact_multiplicities():
    """Three copies of an icosphere: every eigenvalue 3-fold, up to 15-fold with the symmetry."""
    import trimesh

    copies = [trimesh.creation.icosphere(3).apply_translation([3 * i, 0, 0]) for i in range(3)]
    mesh = trimesh.util.concatenate(copies)
    stiffness, mass = laplacian(mesh.vertices, mesh.faces)
    values, vectors = solve_bands(stiffness, mass, 200, per_band=40)
    dense = scipy.linalg.eigh(stiffness.toarray(), np.diag(mass), eigvals_only=True,
                              subset_by_index=[0, 199])
    assert np.allclose(values, dense, rtol=1e-8, atol=1e-9)
    assert np.abs(vectors.T @ (mass[:, None] * vectors) - np.eye(200)).max() <= 1e-8


def test_lu_fallback_when_ldlt_fails(sphere_problem, monkeypatch):
    """A zero pivot in LDLᵀ (σ on an eigenvalue) falls back to SuperLU, without counts."""
    def zero_pivot(self, shifted):
        raise ValueError("zero pivot")

    monkeypatch.setattr(eigen._ShiftInvert, "_factorise", zero_pivot)
    assert eigen._ShiftInvert(*sphere_problem, 3.0).below is None
    # Without Sylvester's counts a missed copy of a multiple eigenvalue would go unnoticed:
    # a mesh without symmetries (the knight) has none.
    assert_knight_matches_dense()
