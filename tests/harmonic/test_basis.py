import os

import numpy as np
import pytest

import eigendance.harmonic.basis as basis_module
from eigendance.errors import EigendanceError
from eigendance.harmonic.basis import HarmonicBasis
from eigendance.harmonic.construction import basis_cache, basis_key
from eigendance.harmonic.mesh import Mesh, load_mesh
from helpers import fixture_path, sphere


@pytest.fixture(scope="module")
def knight():
    return HarmonicBasis.from_mesh(load_mesh(fixture_path("meshes", "decimated-knight.off")), 40,
                                   cache=False)


def test_identity_filter_reproduces_vertices(knight):
    positions = knight.filter_positions(np.ones(knight.k))
    assert np.abs(positions - knight.vertices).max() <= 1e-12


def test_coefficients_and_residual_reconstruct(knight):
    rebuilt = knight.eigenvectors @ knight.coefficients + knight.residual
    assert np.abs(rebuilt - knight.vertices).max() <= 1e-12


def test_zero_filter_keeps_only_the_remainder(knight):
    assert np.allclose(knight.filter_positions(np.zeros(knight.k)), knight.residual)


def test_batched_filter_equals_one_at_a_time(knight, rng):
    phi = rng.uniform(0, 2, size=(3, 4, knight.k))
    batched = knight.filter_positions(phi)
    assert batched.shape == (3, 4, knight.n, 3)
    single = knight.filter_positions(phi[2, 1])
    expected = knight.vertices + knight.eigenvectors @ ((phi[2, 1] - 1)[:, None]
                                                        * knight.coefficients)
    assert np.allclose(batched[2, 1], single) and np.allclose(single, expected)


def test_filter_length_checked(knight):
    with pytest.raises(EigendanceError, match="k = 40"):
        knight.filter_positions(np.ones(7))


def test_save_load_round_trip(tmp_path, knight):
    path = tmp_path / "knight.npz"
    knight.save(path)
    loaded = HarmonicBasis.load(path)
    for name in ("vertices", "faces", "center", "mass", "eigenvalues", "eigenvectors",
                 "coefficients", "residual"):
        assert np.array_equal(getattr(loaded, name), getattr(knight, name)), name
    assert loaded.scale == knight.scale and loaded.laplacian == "cotan"
    assert np.allclose(knight.to_original(knight.vertices), loaded.to_original(loaded.vertices))


def test_load_rejects_other_files(tmp_path):
    path = tmp_path / "other.npz"
    np.savez(path, values=np.zeros(3))
    with pytest.raises(EigendanceError, match="missing"):
        HarmonicBasis.load(path)
    (tmp_path / "junk.npz").write_bytes(b"not a zip")
    with pytest.raises(EigendanceError, match="not an .npz file"):
        HarmonicBasis.load(tmp_path / "junk.npz")


def test_non_manifold_mesh_needs_robust():
    beetle = load_mesh(fixture_path("meshes", "beetle.obj"))
    with pytest.raises(EigendanceError, match=r"\d+ non-manifold edges") as caught:
        HarmonicBasis.from_mesh(beetle, 10)
    assert caught.value.remedy == {"laplacian": "robust"}
    basis = HarmonicBasis.from_mesh(beetle, 30, laplacian="robust")
    assert np.all(np.isfinite(basis.eigenvectors)) and basis.laplacian == "robust"
    gram = basis.eigenvectors.T @ (basis.mass[:, None] * basis.eigenvectors)
    assert np.abs(gram - np.eye(30)).max() <= 1e-8


def test_cache_hit_and_corrupt_entry_rebuilt(monkeypatch):
    mesh = sphere(2)
    first = HarmonicBasis.from_mesh(mesh, 12)
    path = basis_cache().path(basis_key(mesh, 12, "cotan"))
    calls = []
    original = basis_module.solve
    monkeypatch.setattr(basis_module, "solve", lambda *a, **kw: calls.append(1) or
                        original(*a, **kw))
    again = HarmonicBasis.from_mesh(mesh, 12)
    assert calls == [] and np.array_equal(again.eigenvectors, first.eigenvectors)
    with open(path, "r+b") as file:  # flip bytes in the middle of the stored arrays
        file.seek(2000)
        file.write(b"\xff" * 64)
    rebuilt = HarmonicBasis.from_mesh(mesh, 12)
    assert calls == [1] and np.allclose(rebuilt.eigenvalues, first.eigenvalues)
    assert HarmonicBasis.from_mesh(mesh, 12, cache=False) is not None and calls == [1, 1]


def test_saved_file_has_ordinary_permissions(tmp_path, knight):
    path = tmp_path / "knight.npz"
    knight.save(path)
    umask = os.umask(0)
    os.umask(umask)
    assert os.stat(path).st_mode & 0o777 == 0o666 & ~umask


def wrong_entries(mesh, k):
    """Entries that are intact (right key, right checksum) but not this solve's eigenpairs."""
    right = HarmonicBasis.from_mesh(mesh, k, cache=False)
    fewer = HarmonicBasis.from_mesh(mesh, k // 2, cache=False)
    other = HarmonicBasis.from_mesh(sphere(2), k, cache=False)  # 162 vertices as well
    shifted = np.roll(right.eigenvectors, 1, axis=0)  # the same rows, given to other vertices
    pairs = {"eigenvalues": right.eigenvalues, "eigenvectors": right.eigenvectors,
             "mass": right.mass}
    return right, {
        "half the harmonics": {"eigenvalues": fewer.eigenvalues,
                               "eigenvectors": fewer.eigenvectors, "mass": fewer.mass},
        "another mesh's basis": {"eigenvalues": other.eigenvalues,
                                 "eigenvectors": other.eigenvectors, "mass": other.mass},
        "eigenvalues doubled": {**pairs, "eigenvalues": 2 * right.eigenvalues},
        "eigenvectors zeroed": {**pairs, "eigenvectors": np.zeros_like(right.eigenvectors)},
        "vertices shifted": {**pairs, "eigenvectors": shifted},
        "mass doubled": {**pairs, "mass": 2 * right.mass},
        "one pair twice": {**pairs, "eigenvectors": right.eigenvectors[:, [0, 1, 1, *range(3, k)]],
                           "eigenvalues": right.eigenvalues[[0, 1, 1, *range(3, k)]]},
        "integers": {**pairs, "eigenvalues": right.eigenvalues.astype(np.int64)},
    }


def test_a_cache_entry_that_is_intact_but_wrong_is_solved_again(monkeypatch):
    """The cache's checksum guards against damage; the solve's own test against an entry that
    was written wrong: each of these is refused, solved again and replaced."""
    mesh = sphere(2)
    bumped = Mesh.from_arrays(mesh.vertices * [1, 1, 1.2], mesh.faces, name="bumped")
    right, entries = wrong_entries(bumped, 12)
    key = basis_key(bumped, 12, "cotan")
    calls = []
    original = basis_module.solve
    monkeypatch.setattr(basis_module, "solve", lambda *a, **kw: calls.append(1) or
                        original(*a, **kw))
    for name, arrays in entries.items():
        basis_cache().store(key, arrays)
        solved = HarmonicBasis.from_mesh(bumped, 12)
        assert len(calls) == 1, name
        calls.clear()
        np.testing.assert_allclose(solved.eigenvalues, right.eigenvalues, rtol=1e-8, atol=1e-10)
        again = HarmonicBasis.from_mesh(bumped, 12)  # the entry was replaced by a right one
        assert calls == [] and np.array_equal(again.eigenvectors, solved.eigenvectors), name
    os.remove(basis_cache().path(key))
    os.mkdir(basis_cache().path(key))  # a folder where the entry should be
    assert HarmonicBasis.from_mesh(bumped, 12).k == 12 and calls == [1]
    assert os.path.isfile(basis_cache().path(key))


def test_load_refuses_a_basis_whose_coefficients_do_not_follow(tmp_path, knight):
    path = tmp_path / "b.npz"
    knight.save(path)
    arrays = dict(np.load(path))
    np.savez(path, **{**arrays, "residual": arrays["residual"] + 0.1})
    with pytest.raises(EigendanceError, match="residual do not follow"):
        HarmonicBasis.load(path)
    np.savez(path, **{**arrays, "laplacian": np.array("spectral")})
    with pytest.raises(EigendanceError, match="laplacian must be one of cotan, robust"):
        HarmonicBasis.load(path)
