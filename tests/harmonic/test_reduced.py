"""The reduced basis (docs/design.md#reduced-basis) against what it must be: P a partition of
unity with few non-negative weights, Galerkin eigenvalues above the exact ones (min-max) and
near a sphere's l(l+1), Uᵀ M U = I, the lazy U = P U_r equal to the product formed, and a
dance close to the exact basis's where the harmonics are well apart."""

import numpy as np
import pytest

import eigendance.harmonic.basis as basis_module
import eigendance.harmonic.construction as construction_module
from eigendance.errors import EigendanceError
from eigendance.geometry import vertex_normals
from eigendance.harmonic.basis import HarmonicBasis
from eigendance.harmonic.construction import basis_cache, basis_key, choose_construction
from eigendance.harmonic.interpolation import MOST, QUANTUM
from eigendance.harmonic.mesh import load_mesh
from eigendance.harmonic.reduced import reduced_key
from eigendance.music.gallery import initial_gallery
from eigendance.music.spectrogram import Spectrogram
from helpers import fixture_path, sphere


@pytest.fixture(scope="module")
def cat():
    from importlib.resources import files

    return load_mesh(files("eigendance") / "data" / "cat_lowres.obj")


@pytest.fixture(scope="module")
def cat_bases(cat):
    """The cat (7,949 vertices, a real model) exact and reduced with 1,500 samples, k = 30."""
    exact = HarmonicBasis.from_mesh(cat, 30, cache=False, construction="exact")
    reduced = HarmonicBasis.from_mesh(cat, 30, cache=False, construction="reduced",
                                      samples=1500)
    return exact, reduced


def test_weights_are_a_partition_of_unity_of_at_most_eight_samples(cat_bases):
    weights = cat_bases[1].reduced.interpolation.weights
    indices = cat_bases[1].reduced.interpolation.indices
    assert weights.shape[1] <= MOST == 8 and indices.shape == weights.shape
    assert (weights >= 0).all() and np.array_equal(weights.sum(axis=1), np.ones(len(weights)))
    assert np.array_equal(weights / QUANTUM, np.round(weights / QUANTUM))  # exact in float16
    assert np.array_equal(weights.astype(np.float16).astype(np.float64), weights)


def test_weights_reproduce_positions_in_the_tangent_plane(cat_bases, cat):
    """Linear precision: P applied to the samples' positions gives back every vertex's position
    up to the normal direction (and the 2⁻¹¹ rounding of the weights), checked by the plain
    product of the stored weights and indices."""
    reduced = cat_bases[1].reduced
    sample_positions = cat.vertices[reduced.samples]
    rebuilt = np.einsum("ij,ijk->ik", reduced.interpolation.weights,
                        sample_positions[reduced.interpolation.indices])
    normals = vertex_normals(cat.vertices, cat.faces)
    error = rebuilt - cat.vertices
    tangential = np.linalg.norm(error - (error * normals).sum(1, keepdims=True) * normals,
                                axis=1)
    spacing = np.sqrt(cat_bases[1].mass.sum() / reduced.count)
    assert np.median(tangential) <= 2e-3 * spacing  # a weight's rounding: 2⁻¹¹ of a spacing
    assert np.quantile(tangential, 0.98) <= 0.05 * spacing  # all but the rims of holes


def test_eigenvalues_lie_above_the_exact_ones_and_close(cat_bases):
    """Rayleigh–Ritz in a subspace: λ̃_ν ≥ λ_ν for every ν (Courant–Fischer)."""
    exact, reduced = cat_bases
    assert np.all(reduced.eigenvalues[1:] >= exact.eigenvalues[1:] * (1 - 1e-9))
    relative = (reduced.eigenvalues[1:] - exact.eigenvalues[1:]) / exact.eigenvalues[1:]
    assert np.median(relative) <= 0.02 and relative.max() <= 0.05


def test_sphere_eigenvalues_near_l_l_plus_1():
    mesh = sphere(4)  # 2,562 vertices, 400 samples
    basis = HarmonicBasis.from_mesh(mesh, 25, cache=False, construction="reduced", samples=400)
    l = np.arange(5)
    expected = np.repeat(l * (l + 1), 2 * l + 1).astype(float)
    assert abs(basis.eigenvalues[0]) <= 1e-8
    assert np.all(np.abs(basis.eigenvalues[1:] - expected[1:]) <= 0.03 * expected[1:])


def test_harmonics_are_m_orthonormal_and_the_lazy_product_is_p_times_ur(cat_bases):
    reduced = cat_bases[1]
    matrix = reduced.reduced.interpolation.matrix()
    formed = matrix.toarray() @ reduced.reduced.coarse  # U = P U_r, formed here only
    assert np.abs(formed.T @ (reduced.mass[:, None] * formed) - np.eye(30)).max() <= 1e-9
    assert np.allclose(reduced.harmonics(np.arange(30)), formed, atol=1e-13)
    phi = np.random.default_rng(3).uniform(0, 2, (2, 30))
    expected = reduced.vertices + np.einsum("ik,sk,kj->sij", formed, phi - 1,
                                            reduced.coefficients)
    assert np.allclose(reduced.filter_positions(phi), expected, atol=1e-12)
    assert np.allclose(reduced.filter_positions(np.ones(30)), reduced.vertices, atol=1e-13)
    targets = np.array([1, 4, 7])
    gram = np.einsum("ij,ik->jk", formed[:, targets], formed[:, targets]) * (
        reduced.coefficients[targets] @ reduced.coefficients[targets].T) / reduced.n
    assert np.allclose(reduced.motion_gram(targets), gram, rtol=1e-10, atol=1e-16)


def test_the_reduced_dance_follows_the_exact_one(cat_bases):
    """Gallery items driving harmonics far from others in the spectrum (here the lowest two)
    dance as with the exact basis; items on clustered harmonics exchange motion inside their
    cluster (docs/design.md#reduced-basis) and are bounded loosely."""
    exact, reduced = cat_bases
    song = Spectrogram.from_file(fixture_path("audio", "kevin_macleod_vibe_ace_20s-24s.ogg"))
    items = initial_gallery(exact, song, 8)
    times = np.linspace(0, song.duration, 60)
    errors = []
    for item in items:
        phi = item.play(song, times, 30)  # the one path from a song to the filter
        moved, moved_reduced = exact.displacements(phi), reduced.displacements(phi)
        errors.append(np.sqrt(((moved - moved_reduced) ** 2).sum() / (moved ** 2).sum()))
    assert max(errors[:2]) <= 0.02
    assert np.median(errors) <= 0.1 and max(errors) <= 0.6


def test_save_load_round_trip_and_a_broken_partition_is_refused(tmp_path, cat_bases):
    reduced = cat_bases[1]
    path = tmp_path / "reduced.npz"
    reduced.save(path)
    assert "eigenvectors" not in np.load(path).files
    loaded = HarmonicBasis.load(path)
    assert loaded.construction == "reduced" and loaded.eigenvectors is None
    phi = np.full(30, 1.5)
    assert np.array_equal(loaded.filter_positions(phi), reduced.filter_positions(phi))
    arrays = dict(np.load(path))
    weights = arrays["interpolation_weights"].copy()
    weights[5, 0] += 0.25
    np.savez(path, **{**arrays, "interpolation_weights": weights})
    with pytest.raises(EigendanceError, match="sum to 1"):
        HarmonicBasis.load(path)


def test_reduced_bases_are_cached_and_a_wrong_entry_is_solved_again(monkeypatch, cat):
    calls = []
    original = basis_module.reduced_harmonics
    monkeypatch.setattr(basis_module, "reduced_harmonics",
                        lambda *a, **kw: calls.append(1) or original(*a, **kw))
    first = HarmonicBasis.from_mesh(cat, 12, construction="reduced", samples=600)
    again = HarmonicBasis.from_mesh(cat, 12, construction="reduced", samples=600)
    assert calls == [1] and np.array_equal(again.reduced.coarse, first.reduced.coarse)
    HarmonicBasis.from_mesh(cat, 12, construction="reduced", samples=700)  # another key
    assert calls == [1, 1]
    key = reduced_key(basis_key(cat, 12, "cotan"), 600)
    entry = dict(np.load(basis_cache().path(key)))
    stored = {name: entry[name] for name in entry if not name.startswith("__")}
    basis_cache().store(key, {**stored, "coarse_eigenvectors": np.roll(
        stored["coarse_eigenvectors"], 1, axis=0)})  # intact, but not the eigenpairs
    rebuilt = HarmonicBasis.from_mesh(cat, 12, construction="reduced", samples=600)
    assert calls == [1, 1, 1] and np.allclose(rebuilt.eigenvalues, first.eigenvalues)


def test_the_rule_picks_exact_for_small_and_reduced_for_large(monkeypatch):
    assert choose_construction(5_000, 300) == "exact"  # fewer vertices than samples
    assert choose_construction(100_000, 300) == "exact"
    assert choose_construction(1_000_000, 300) == "reduced"
    monkeypatch.setattr(construction_module, "memory_budget", lambda: 1e8)  # 100 MB left
    assert choose_construction(100_000, 300) == "reduced"


def test_a_mesh_in_several_pieces_gets_a_sample_on_each():
    """Three spheres apart: the Laplacian couples the pieces (docs/design.md#laplacian), so one
    constant harmonic; every piece has samples of its own and moves. The beetle (non-manifold
    edges, robust Laplacian) gives a result."""
    import trimesh

    from eigendance.harmonic.contacts import components
    from eigendance.harmonic.mesh import Mesh

    ball = trimesh.creation.icosphere(3)
    pieces = [(ball.vertices * scale + [4.0 * i, 0, 0], ball.faces + len(ball.vertices) * i)
              for i, scale in enumerate((1.0, 0.5, 0.2))]
    mesh = Mesh.from_arrays(np.vstack([v for v, _ in pieces]), np.vstack([f for _, f in pieces]))
    basis = HarmonicBasis.from_mesh(mesh, 12, cache=False, construction="reduced", samples=300)
    count, labels = components(mesh.n, mesh.faces)
    assert count == 3 and set(labels[basis.reduced.samples]) == {0, 1, 2}
    assert np.sum(np.abs(basis.eigenvalues) <= 1e-6 * basis.eigenvalues[-1]) == 1  # coupled: 1
    moved = basis.filter_positions(np.full(12, 2.0)) - basis.vertices
    assert all(np.abs(moved[labels == piece]).max() > 0 for piece in range(3))
    beetle = load_mesh(fixture_path("meshes", "beetle.obj"))
    robust = HarmonicBasis.from_mesh(beetle, 12, laplacian="robust", cache=False,
                                     construction="reduced", samples=300)
    assert np.isfinite(robust.filter_positions(np.full(12, 2.0))).all()


def test_both_sheets_of_a_thin_part_get_samples():
    """A box 1 × 1 × 0.03 (11k vertices): its top and bottom pass through the same voxel cells
    (spacing ≈ 0.06). Each cell is split into the pieces of surface connected inside it, so both
    sheets get half the samples and the lowest harmonics come within a few percent of the exact
    solver's (one sample per cell: 29 on top, 227 below, errors of 60–170%)."""
    import trimesh

    from eigendance.harmonic.mesh import Mesh

    box = trimesh.creation.box(extents=[1.0, 1.0, 0.03])
    mesh = Mesh.from_arrays(*trimesh.remesh.subdivide_to_size(box.vertices, box.faces, 0.03))
    exact = HarmonicBasis.from_mesh(mesh, 6, cache=False, construction="exact")
    reduced = HarmonicBasis.from_mesh(mesh, 6, cache=False, construction="reduced", samples=250)
    heights = reduced.vertices[reduced.reduced.samples, 2]
    assert min((heights > 0).sum(), (heights < 0).sum()) >= 0.4 * len(heights)
    relative = reduced.eigenvalues[1:4] / exact.eigenvalues[1:4] - 1
    assert np.all(relative >= -1e-9) and np.all(relative <= 0.05)
