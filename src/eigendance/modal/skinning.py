"""Modal skinning and linear blend skinning of a mesh bound to a skeleton
(docs/design.md#skinning).

Modal skinning (thesis §5.3, corrected for body frames away from the origin): per vertex i and
mode κ, precompute in world coordinates the blended first-order motion

    τ_iκ = Σ_b w_ib (ω_bκ × (x_i − c_b) + u_bκ),    ρ_iκ = Σ_b w_ib ω_bκ,

with (ω_bκ, u_bκ) body b's share of mode κ turned into world coordinates (R_b θ, R_b x) and c_b
its centre of mass. Since Σ_b w_ib ω_bκ × x_i = ρ_iκ × x_i, both come from two products with the
weight matrix. Per frame, x_i' = x_i + Σ_κ c_κ τ_iκ for all frames at once is ONE matrix product
(T, nm) · (nm, 3n), and normals turn by exp([Σ_κ c_κ ρ_iκ]×).

Linear blend skinning applies the exact body transforms (`motion.body_transforms`) blended by
the weights; the two agree to first order in the amplitudes.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse

from eigendance.errors import InputError
from eigendance.geometry import cross
from eigendance.limits import check_memory
from eigendance.modal.model import ModalModel
from eigendance.modal.rotations import rotate_by_vectors

# Peak bytes of building a modal skin per value of τ (vertex × mode × coordinate): measured
# 40 (benchmarks/bench_limits.py: float64 products cast to float32, transposed copies).
SKIN_PEAK_BYTES = 48


def skin_bytes(vertices: int, modes: int) -> int:
    """Peak memory of building the modal skin of `modes` modes on `vertices` vertices.

    Parameters
    ----------
    vertices : n.
    modes : nm.

    Returns
    -------
    int, bytes.
    """
    return SKIN_PEAK_BYTES * 3 * int(vertices) * int(modes)


def _checked(vertices, weights, n_bodies):
    vertices = np.asarray(vertices, dtype=float)
    if vertices.ndim != 2 or vertices.shape[1] != 3:
        raise InputError(f"vertices must be (n, 3), not shape {vertices.shape}")
    if weights.shape != (len(vertices), n_bodies):
        raise InputError(f"skin weights have shape {weights.shape}; expected "
                              f"({len(vertices)}, {n_bodies}) (vertices, bodies)")
    return vertices


class ModalSkin:
    """Precomputed modal skinning of a mesh for the modes of a model.

    Parameters
    ----------
    model : the rig's modes.
    vertices : (n, 3) rest positions, in the bodies' coordinates.
    weights : (n, n_b) skin weights (dense or scipy sparse), rows summing to 1.
    dtype : float32 halves memory and time per frame (what a GPU uses); float64 by default.
    name : how messages call the rig (InputError when its skin would not fit in memory,
        `skin_bytes`, checked before anything is allocated).

    Attributes: displacement (nm, 3n) — row κ is τ_·κ flattened; rotation (nm, 3n) — ρ_·κ.

    Example
    -------
    >>> from eigendance.modal.motion import mode_coefficients
    >>> from eigendance.modal.sample_rigs import sample_rig
    >>> rig = sample_rig("chain")
    >>> model = ModalModel.from_skeleton(rig)
    >>> skin = ModalSkin(model, rig.vertices, rig.weights)
    >>> moved = skin.positions(mode_coefficients(model, [0.0, 0.25]))   # (T, n, 3)
    >>> moved.shape == (2, len(rig.vertices), 3), bool(np.allclose(moved[0], rig.vertices))
    (True, True)
    """

    def __init__(self, model: ModalModel, vertices, weights, dtype=np.float64,
                 name: str = "rig"):
        weights = weights if hasattr(weights, "tocsr") else np.asarray(weights, dtype=float)
        self.vertices = _checked(vertices, weights, model.n_bodies)
        n, nm, nb = len(self.vertices), model.n_modes, model.n_bodies
        check_memory(skin_bytes(n, nm), f"{name}: the modal skin's values ({nm} modes on "
                     f"{n} vertices)")
        if not hasattr(weights, "tocsr") and np.count_nonzero(weights) < 0.25 * weights.size:
            weights = scipy.sparse.csr_array(weights)  # a vertex follows a few bodies
        twists = model.modes.reshape(nb, 6, nm)
        omega = np.einsum("bij,bjk->bki", model.body_rotations, twists[:, :3])  # (nb, nm, 3)
        linear = np.einsum("bij,bjk->bki", model.body_rotations, twists[:, 3:])
        offset = linear - cross(omega, model.body_centers[:, None, :])
        if not hasattr(weights, "tocsr"):
            weights = weights.astype(dtype)
        # The per-body arrays are small: cast them first, so the large ones are made in dtype.
        omega, offset = omega.astype(dtype), offset.astype(dtype)
        rho = np.asarray(weights @ omega.reshape(nb, nm * 3)).reshape(n, nm, 3).astype(
            dtype, copy=False)
        tau = cross(rho, self.vertices.astype(dtype)[:, None, :])
        tau += np.asarray(weights @ offset.reshape(nb, nm * 3)).reshape(n, nm, 3)
        self.displacement = np.ascontiguousarray(tau.transpose(1, 0, 2)).reshape(nm, 3 * n)
        self.rotation = np.ascontiguousarray(rho.transpose(1, 0, 2)).reshape(nm, 3 * n)
        self._flat_vertices = self.vertices.reshape(-1).astype(dtype)

    @property
    def n_modes(self) -> int:
        """Modes nm."""
        return self.displacement.shape[0]

    def positions(self, coefficients) -> np.ndarray:
        """(T, n, 3) skinned positions for coefficients c (T, nm): x + c·τ, one product.

        Parameters
        ----------
        coefficients : (T, nm) (or (nm,)).

        Returns
        -------
        (T, n, 3) in the skin's dtype.
        """
        coefficients = np.atleast_2d(np.asarray(coefficients, dtype=self.displacement.dtype))
        if coefficients.shape[1] != self.n_modes:
            raise InputError(f"coefficients have {coefficients.shape[1]} modes; the skin "
                                  f"has {self.n_modes}")
        flat = coefficients @ self.displacement
        flat += self._flat_vertices
        return flat.reshape(len(coefficients), -1, 3)

    def normals(self, coefficients, normals) -> np.ndarray:
        """(T, n, 3) rest normals turned by exp([Σ_κ c_κ ρ_iκ]×).

        Parameters
        ----------
        coefficients : (T, nm).
        normals : (n, 3) rest normals.

        Returns
        -------
        (T, n, 3) float64.
        """
        coefficients = np.atleast_2d(np.asarray(coefficients, dtype=self.rotation.dtype))
        turn = (coefficients @ self.rotation).reshape(len(coefficients), -1, 3)
        normals = np.asarray(normals, dtype=float)
        return rotate_by_vectors(np.broadcast_to(normals, turn.shape), turn)


def linear_blend_skinning(vertices, weights, transforms, normals=None, displacements=None):
    """Linear blend skinning: x' = Σ_b w_ib (A_b x + t_b).

    Parameters
    ----------
    vertices : (n, 3) rest positions.
    weights : (n, n_b) skin weights, rows summing to 1 (dense or scipy sparse).
    transforms : (T, n_b, 4, 4) (or (n_b, 4, 4)) world transforms of the bodies from the rest
        pose, e.g. `modal.motion.body_transforms`.
    normals : optional (n, 3) rest normals, turned by the blended linear parts.
    displacements : optional (T, n, 3) moves of the rest positions before skinning (a rig's
        surface, `modal.surface`): x' = Σ_b w_ib (A_b (x + d) + t_b).

    Returns
    -------
    positions (T, n, 3), and unit normals (T, n, 3) when `normals` is given.

    Example
    -------
    >>> lift = np.eye(4); lift[2, 3] = 1.0                    # one body, moved up by 1
    >>> linear_blend_skinning([[0.0, 0, 0], [1, 0, 0]], np.ones((2, 1)), lift[None]).tolist()
    [[[0.0, 0.0, 1.0], [1.0, 0.0, 1.0]]]
    """
    transforms = np.asarray(transforms, dtype=float)
    if transforms.ndim == 3:
        transforms = transforms[None]
    weights = weights if hasattr(weights, "tocsr") else np.asarray(weights, dtype=float)
    vertices = _checked(vertices, weights, transforms.shape[1])
    frames, n_bodies = transforms.shape[:2]
    rows = transforms[:, :, :3, :].transpose(1, 0, 2, 3).reshape(n_bodies, frames * 12)
    blended = np.asarray(weights @ rows).reshape(len(vertices), frames, 3, 4)
    positions = np.einsum("ntij,nj->tni", blended[..., :3], vertices) + \
        blended[..., 3].transpose(1, 0, 2)
    if displacements is not None:
        moves = np.asarray(displacements, dtype=float).reshape(positions.shape)
        positions += np.matmul(blended[..., :3], moves.transpose(1, 0, 2)[..., None])[
            ..., 0].transpose(1, 0, 2)
    if normals is None:
        return positions
    turned = np.einsum("ntij,nj->tni", blended[..., :3], np.asarray(normals, dtype=float))
    length = np.linalg.norm(turned, axis=-1, keepdims=True)
    return positions, turned / np.where(length > 0, length, 1)
