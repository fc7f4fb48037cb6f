import numpy as np

from eigendance.harmonic.lanczos import lanczos_extreme


def operator(spectrum, seed=0):
    """A dense symmetric operator Q diag(spectrum) Qᵀ with a random orthogonal Q."""
    q, _ = np.linalg.qr(np.random.default_rng(seed).standard_normal((len(spectrum),) * 2))
    return (q * spectrum) @ q.T, q


def test_largest_magnitudes_from_both_ends():
    spectrum = np.concatenate([np.linspace(-1, 1, 380), [9, 7, 5, -8, -6, -4]])
    matrix, _ = operator(spectrum)
    theta, vectors = lanczos_extreme(lambda x: matrix @ x, len(spectrum), 6)
    assert np.allclose(np.sort(theta), [-8, -6, -4, 5, 7, 9], atol=1e-12)
    assert np.abs(vectors.T @ vectors - np.eye(6)).max() < 1e-12
    assert np.abs(matrix @ vectors - vectors * theta).max() < 1e-10


def test_deflation_finds_the_other_copy_of_a_multiple_eigenvalue():
    spectrum = np.concatenate([np.linspace(0, 1, 300), [10, 10, 6]])
    matrix, q = operator(spectrum, seed=1)
    known = q[:, 300] + q[:, 301]  # one direction of the eigenspace of 10
    known /= np.linalg.norm(known)
    theta, copy = lanczos_extreme(lambda x: matrix @ x, len(spectrum), 2, deflate=known[None])
    assert np.allclose(np.sort(theta), [6, 10], atol=1e-12)
    other = copy[:, np.argmax(theta)]
    assert abs(known @ other) < 1e-12
    assert np.isclose(np.linalg.norm(q[:, 300:302].T @ other), 1, atol=1e-10)  # in the space


def test_too_few_steps_give_none():
    matrix, _ = operator(np.linspace(1, 2, 200))  # no gaps to speak of
    assert lanczos_extreme(lambda x: matrix @ x, 200, 20, max_steps=21) is None


def test_invariant_subspace_restarts_on_a_tiny_problem():
    matrix, _ = operator(np.array([3.0, -2.0, 1.0, 0.5]))
    theta, vectors = lanczos_extreme(lambda x: matrix @ x, 4, 4)
    assert np.allclose(np.sort(theta), [-2, 0.5, 1, 3], atol=1e-12)
    assert np.abs(vectors.T @ vectors - np.eye(4)).max() < 1e-12
