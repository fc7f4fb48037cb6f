"""Rotations: the cross-product matrix and the exponential map (docs/design.md#modal-motion).

A body's twist [θ; x] turns it by exp([θ]×), the rotation by |θ| radians about θ/|θ|
(Rodrigues' formula).
"""

from __future__ import annotations

import numpy as np


def skew(vectors: np.ndarray) -> np.ndarray:
    """[a]× for a (..., 3) array: (..., 3, 3) with [a]× b = a × b.

    Parameters
    ----------
    vectors : (..., 3).

    Returns
    -------
    (..., 3, 3).
    """
    vectors = np.asarray(vectors, dtype=float)
    x, y, z = vectors[..., 0], vectors[..., 1], vectors[..., 2]
    zero = np.zeros_like(x)
    return np.stack([np.stack([zero, -z, y], -1), np.stack([z, zero, -x], -1),
                     np.stack([-y, x, zero], -1)], -2)


def _rodrigues(angle: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """sin(θ)/θ and (1 − cos θ)/θ², with their series below θ = 1e-8 (no 0/0)."""
    small = angle < 1e-8
    safe = np.where(small, 1.0, angle)
    return (np.where(small, 1.0 - angle**2 / 6, np.sin(safe) / safe),
            np.where(small, 0.5 - angle**2 / 24, (1 - np.cos(safe)) / safe**2))


def rotation_exp(vectors: np.ndarray) -> np.ndarray:
    """exp([θ]×) for a (..., 3) array of rotation vectors (Rodrigues), (..., 3, 3).

    Parameters
    ----------
    vectors : (..., 3) rotation vectors, radians.

    Returns
    -------
    (..., 3, 3) rotations.
    """
    vectors = np.asarray(vectors, dtype=float)
    a, b = _rodrigues(np.linalg.norm(vectors, axis=-1)[..., None, None])
    k = skew(vectors)
    return np.eye(3) + a * k + b * (k @ k)


def rotate_by_vectors(vectors: np.ndarray, rotation_vectors: np.ndarray) -> np.ndarray:
    """exp([r]×) v for matching (..., 3) arrays, without forming matrices (Rodrigues).

    Parameters
    ----------
    vectors : (..., 3) the vectors to turn.
    rotation_vectors : (..., 3) radians.

    Returns
    -------
    (..., 3) turned vectors.
    """
    a, b = _rodrigues(np.linalg.norm(rotation_vectors, axis=-1, keepdims=True))
    cross = np.cross(rotation_vectors, vectors)
    return vectors + a * cross + b * np.cross(rotation_vectors, cross)
