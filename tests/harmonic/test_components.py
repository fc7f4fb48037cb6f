"""The solve of an operator in separate components (harmonic.components), checked against
dense solves of the pieces and of the whole operator (scipy.linalg.eigh), not against itself."""

import numpy as np
import pytest
import scipy.linalg
import scipy.sparse as sp

from eigendance.harmonic import eigensolver
from eigendance.harmonic import laplacian as operators
from eigendance.harmonic.components import groups
from eigendance.harmonic.eigensolver import residuals, solve
from eigendance.harmonic.mesh import Mesh, load_mesh
from helpers import fixture_path, sphere


def copies(mesh: Mesh, count: int, step=(3.0, 0.0, 0.0)) -> Mesh:
    """`count` translated copies of `mesh` (same vertex order), normalised together."""
    offsets = np.repeat(np.arange(count), mesh.n)[:, None] * np.asarray(step)
    faces = np.concatenate([mesh.faces + i * mesh.n for i in range(count)])
    return Mesh.from_arrays(np.tile(mesh.vertices, (count, 1)) + offsets, faces, name="copies")


def dense_values(stiffness, mass, k):
    """The k smallest eigenvalues of L u = λ M u, dense LAPACK."""
    return scipy.linalg.eigh(stiffness.toarray(), np.diag(mass), eigvals_only=True,
                             subset_by_index=[0, k - 1])


@pytest.fixture
def uncoupled(monkeypatch):
    """Laplacians without contact springs: one component per piece."""
    monkeypatch.setattr(operators, "CONTACT_STIFFNESS", 0.0)
    return operators.laplacian


def assert_basis(stiffness, mass, values, vectors, k):
    """k pairs, ascending, accepted residuals, Uᵀ M U = I over the whole mesh."""
    assert values.shape == (k,) and vectors.shape == (len(mass), k)
    assert np.all(np.diff(values) >= 0)
    assert residuals(stiffness, mass, values, vectors).max() <= eigensolver.RESIDUAL_TOLERANCE
    assert np.abs(vectors.T @ (mass[:, None] * vectors) - np.eye(k)).max() <= 1e-9


@pytest.mark.parametrize("count", [2, 8])
def test_translated_copies_repeat_each_eigenvalue_of_the_single_mesh(uncoupled, count):
    """Copies of the knight (no symmetry of its own): each eigenvalue of one knight, solved
    densely on its own, `count` times; the copies are found identical and solved once."""
    knight = load_mesh(fixture_path("meshes", "decimated-knight.off"))
    mesh = copies(knight, count)
    stiffness, mass = uncoupled(mesh.vertices, mesh.faces)
    found = groups(stiffness, mass)
    assert [len(group.members) for group in found] == [count]
    k = 60
    values, vectors = solve(stiffness, mass, k)
    # The copies are normalised together: one knight scaled by the same factor.
    single_stiffness, single_mass = uncoupled(mesh.vertices[:knight.n], knight.faces)
    single = dense_values(single_stiffness, single_mass, -(-k // count))
    assert np.allclose(values, np.repeat(single, count)[:k], rtol=1e-8, atol=1e-9)
    assert_basis(stiffness, mass, values, vectors, k)
    for column in range(k):  # each eigenvector lives on one copy
        assert sum(np.abs(vectors[i * knight.n:(i + 1) * knight.n, column]).max() > 0
                   for i in range(count)) == 1


def test_components_of_different_sizes_equal_a_dense_solve_of_the_whole(uncoupled):
    """Two spheres (642 and 162 vertices) and a scaled copy of the small one: nothing shared
    between unequal blocks, every pair of the whole operator found (dense LAPACK on all 966)."""
    big, small = sphere(3), sphere(2)
    vertices = np.concatenate([big.vertices, small.vertices + [3, 0, 0],
                               2 * small.vertices + [8, 0, 0]])
    faces = np.concatenate([big.faces, small.faces + big.n, small.faces + big.n + small.n])
    mesh = Mesh.from_arrays(vertices, faces, name="three spheres")
    stiffness, mass = uncoupled(mesh.vertices, mesh.faces)
    assert sorted(len(group.members[0]) for group in groups(stiffness, mass)) == [162, 162, 642]
    k = 80
    values, vectors = solve(stiffness, mass, k)
    assert np.allclose(values, dense_values(stiffness, mass, k), rtol=1e-8, atol=1e-9)
    assert np.count_nonzero(values < 1e-9) == 3  # one constant per piece
    assert_basis(stiffness, mass, values, vectors, k)


def test_identical_pieces_the_band_solver_cannot_close(uncoupled):
    """Eight copies of an icosphere (eigenvalues of multiplicity 8·(2l+1), up to 56, where a
    single-vector Krylov space on the whole operator sees one vector per eigenvalue): by
    component the sphere is solved once (by bands: 642 vertices) and equals a dense solve of
    one sphere, 8 times."""
    mesh = copies(sphere(3), 8)
    stiffness, mass = uncoupled(mesh.vertices, mesh.faces)
    values, vectors = solve(stiffness, mass, 100)
    one = sphere(3).n
    single = dense_values(*uncoupled(mesh.vertices[:one], mesh.faces[:len(sphere(3).faces)]), 13)
    assert np.allclose(values, np.repeat(single, 8)[:100], rtol=1e-8, atol=1e-9)
    assert_basis(stiffness, mass, values, vectors, 100)


def test_pieces_coupled_by_contacts_stay_one_component():
    """The teapot's pieces touch: with the contact springs its operator is one component, and
    the solve is the band solver's on the whole operator."""
    mesh = load_mesh(fixture_path("meshes", "teapot.obj"))
    stiffness, mass = operators.laplacian(mesh.vertices, mesh.faces, "robust")
    found = groups(stiffness, mass)
    assert len(found) == 1 and len(found[0].members) == 1
    assert np.array_equal(found[0].members[0], np.arange(mesh.n))


def test_one_component_is_the_band_solver_unchanged(monkeypatch):
    """A connected operator goes to solve_bands once, with the caller's k and progress."""
    mesh = sphere(3)
    stiffness, mass = operators.laplacian(mesh.vertices, mesh.faces)
    calls = []

    def recorded(stiffness, mass, k, progress=None, **options):
        calls.append((stiffness.shape[0], k, progress))
        return np.zeros(k), np.zeros((stiffness.shape[0], k))

    monkeypatch.setattr(eigensolver, "solve_bands", recorded)
    solve(stiffness, mass, 50, progress=print)
    assert calls == [(mesh.n, 50, print)]


def test_sparse_mass_and_isolated_vertices(uncoupled):
    """A block-diagonal problem with a sparse SPD mass, two equal blocks and two 1×1 blocks
    (an isolated vertex: L = 0): equal to a dense generalised solve of the whole."""
    rng = np.random.default_rng(0)
    graph = sp.random(700, 700, density=0.01, random_state=1)
    graph = graph + graph.T + sp.diags(np.ones(699), 1) + sp.diags(np.ones(699), -1)
    block = sp.diags(np.asarray(graph.sum(axis=1)).ravel()) - graph
    mass_block = sp.diags(rng.uniform(1, 2, 700)) + 0.1 * sp.diags(np.ones(699), 1) \
        + 0.1 * sp.diags(np.ones(699), -1)
    stiffness = sp.block_diag([block, sp.csc_matrix((1, 1)), block, sp.csc_matrix((1, 1))])
    mass = sp.block_diag([mass_block, sp.identity(1), mass_block, 2 * sp.identity(1)]).tocsc()
    assert sorted(len(group.members) for group in groups(stiffness, mass)) == [1, 1, 2]
    values, vectors = solve(stiffness.tocsc(), mass, 40)
    dense = scipy.linalg.eigh(stiffness.toarray(), mass.toarray(), eigvals_only=True,
                              subset_by_index=[0, 39])
    assert np.allclose(values, dense, rtol=1e-8, atol=1e-9)
    assert np.abs(vectors.T @ (mass @ vectors) - np.eye(40)).max() <= 1e-9


def test_progress_rises_to_k(uncoupled):
    """Progress over the pieces (solved by bands: 642 vertices each) never goes back and
    stays within 0…k."""
    mesh = copies(sphere(3), 3)
    stiffness, mass = uncoupled(mesh.vertices, mesh.faces)
    seen = []
    solve(stiffness, mass, 60, progress=seen.append)
    assert seen and seen == sorted(seen) and all(0 <= done <= 60 for done in seen)
