"""Modal analysis of a skeleton and the body motion it gives (DESIGN §5, thesis ch. 4–5).

Velocities are spatial [ω; v] in each body's frame (origin at its centre of mass), stacked into
one vector of length 6·n_b. For a joint j between bodies i and l at P:

- Ad_{i→j} = [[Ω, 0], [[O]×Ω, Ω]] with Ω = R_jᵀ R_i and O = R_jᵀ (c_i − P): body i's velocity
  seen at P in the joint frame (3-60).
- constraints (4-12): Γᵐ (Ad_{i→j} v̂_i − Ad_{l→j} v̂_l) = 0, stacked into G v̂ = 0.
- elastic deflection: Γᶠ (Ad_{i→j} v̂_i − Ad_{l→j} v̂_l), stacked into R, the **difference** of
  the two bodies' motions (DESIGN's fix of (4-35)); K = diag of the free rows' stiffnesses.
- N: orthonormal basis of ker G from the SVD with a relative rank tolerance, so loops (dependent
  rows) give dim N = 6n_b − rank G.
- M̃ = NᵀMN, K̃ = NᵀRᵀKRN, K̃u = λM̃u; modes η = Nu (ηᵀMη = I), frequencies ν = √λ/2π Hz.
  The dim N − rank(RN) smallest eigenvalues are rigid motions of the whole (λ = 0; also any
  mechanism left free by a zero stiffness): counted, not kept as vibrations. Joint damping
  is read with the skeleton but not used: the modes are those of the undamped system.

Motion: c_κ(t) = φ_κ(t)·μ_κ·sin(2πν_κ s t + γ_κ); body b's twist p̂_b = Σ_κ c_κ η_κ^b = [θ; x] in
its body frame moves it exactly: rotation exp([θ]×) about its centre of mass, then translation x.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass

import numpy as np
import scipy.linalg

from eigendance.errors import EigendanceError
from eigendance.files import atomic_save_npz, load_npz
from eigendance.skeleton import Skeleton

RANK_TOLERANCE = 1e-9  # singular values below this times the largest count as zero

MODAL_KEYS = ("frequencies", "modes", "rigid_modes", "nullspace_dim", "constraint_rows",
              "constraint_rank", "body_names")


def skew(vectors: np.ndarray) -> np.ndarray:
    """[a]× for a (..., 3) array: (..., 3, 3) with [a]× b = a × b."""
    vectors = np.asarray(vectors, dtype=float)
    x, y, z = vectors[..., 0], vectors[..., 1], vectors[..., 2]
    zero = np.zeros_like(x)
    return np.stack([np.stack([zero, -z, y], -1), np.stack([z, zero, -x], -1),
                     np.stack([-y, x, zero], -1)], -2)


def rotation_exp(vectors: np.ndarray) -> np.ndarray:
    """exp([θ]×) for a (..., 3) array of rotation vectors (Rodrigues), (..., 3, 3)."""
    vectors = np.asarray(vectors, dtype=float)
    angle = np.linalg.norm(vectors, axis=-1)[..., None, None]
    small = angle < 1e-8
    safe = np.where(small, 1.0, angle)
    a = np.where(small, 1.0 - angle**2 / 6, np.sin(safe) / safe)
    b = np.where(small, 0.5 - angle**2 / 24, (1 - np.cos(safe)) / safe**2)
    k = skew(vectors)
    return np.eye(3) + a * k + b * (k @ k)


def rotate_by_vectors(vectors: np.ndarray, rotation_vectors: np.ndarray) -> np.ndarray:
    """exp([r]×) v for matching (..., 3) arrays, without forming matrices (Rodrigues)."""
    angle = np.linalg.norm(rotation_vectors, axis=-1, keepdims=True)
    small = angle < 1e-8
    safe = np.where(small, 1.0, angle)
    a = np.where(small, 1.0 - angle**2 / 6, np.sin(safe) / safe)
    b = np.where(small, 0.5 - angle**2 / 24, (1 - np.cos(safe)) / safe**2)
    cross = np.cross(rotation_vectors, vectors)
    return vectors + a * cross + b * np.cross(rotation_vectors, cross)


def joint_adjoints(skeleton: Skeleton) -> tuple[np.ndarray, np.ndarray]:
    """Ad_{i→j} and Ad_{l→j} for every joint, each (n_joints, 6, 6)."""
    joints = skeleton.joints
    if not joints:
        return np.zeros((0, 6, 6)), np.zeros((0, 6, 6))
    centers, rotations = skeleton.centers, skeleton.rotations
    joint_rotations = np.array([skeleton.joint_rotation(joint) for joint in joints])
    positions = np.array([joint.position for joint in joints])
    pairs = np.array([joint.bodies for joint in joints])

    def adjoint(body_index):
        omega = np.einsum("jba,jbc->jac", joint_rotations, rotations[body_index])  # R_jᵀ R_b
        offset = np.einsum("jba,jb->ja", joint_rotations, centers[body_index] - positions)
        result = np.zeros((len(joints), 6, 6))
        result[:, :3, :3] = omega
        result[:, 3:, 3:] = omega
        result[:, 3:, :3] = skew(offset) @ omega
        return result

    return adjoint(pairs[:, 0]), adjoint(pairs[:, 1])


def joint_matrices(skeleton: Skeleton) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """G (constrained rows), R (free rows) and the stiffness diagonal K of a skeleton."""
    n_bodies, joints = skeleton.n_bodies, skeleton.joints
    first, second = joint_adjoints(skeleton)
    full = np.zeros((len(joints), 6, n_bodies, 6))
    pairs = np.array([joint.bodies for joint in joints], dtype=int).reshape(-1, 2)
    rows = np.arange(len(joints))
    full[rows, :, pairs[:, 0], :] = first
    full[rows, :, pairs[:, 1], :] -= second
    full = full.reshape(6 * len(joints), 6 * n_bodies)
    constrained = np.zeros((len(joints), 6), dtype=bool)
    for index, joint in enumerate(joints):
        constrained[index, list(joint.constrained_rows)] = True
    constrained = constrained.reshape(-1)
    stiffness = np.concatenate([joint.stiffness for joint in joints]) if joints else np.zeros(0)
    return full[constrained], full[~constrained], stiffness


def nullspace(matrix: np.ndarray, n_columns: int, tolerance: float = RANK_TOLERANCE):
    """(orthonormal basis of ker matrix as columns, rank) by SVD with a relative tolerance."""
    if matrix.shape[0] == 0:
        return np.eye(n_columns), 0
    _, singular, vt = np.linalg.svd(matrix, full_matrices=True)
    rank = int(np.sum(singular > tolerance * singular[0])) if singular.size and \
        singular[0] > 0 else 0
    return vt[rank:].T.copy(), rank


def matrix_rank(matrix: np.ndarray, tolerance: float = RANK_TOLERANCE) -> int:
    if matrix.size == 0:
        return 0
    singular = np.linalg.svd(matrix, compute_uv=False)
    return int(np.sum(singular > tolerance * singular[0])) if singular[0] > 0 else 0


@dataclass
class ModalModel:
    """Vibration modes of a skeleton (DESIGN §5, modal file of §8).

    frequencies: (nm,) Hz ascending, vibration modes only. modes: (6·n_b, nm), M-orthonormal,
    body b's twist [θ; x] (body frame) in rows 6b … 6b+5. body_centers (n_b, 3) and
    body_rotations (n_b, 3, 3): the rest pose, needed to move bodies and skin.
    """

    frequencies: np.ndarray
    modes: np.ndarray
    rigid_modes: int
    nullspace_dim: int
    constraint_rows: int
    constraint_rank: int
    body_names: list[str]
    body_centers: np.ndarray
    body_rotations: np.ndarray
    mass: np.ndarray | None = None  # diagonal of M, (6·n_b,)

    @property
    def n_modes(self) -> int:
        return len(self.frequencies)

    @property
    def n_bodies(self) -> int:
        return len(self.body_names)

    @classmethod
    def from_skeleton(cls, skeleton: Skeleton, stiffness: float = 1.0,
                      keep_matrices: bool = False) -> ModalModel:
        """Modal analysis; `stiffness` multiplies every joint stiffness.

        The dense factorisations (a few hundred rows) run on one BLAS thread: faster at this
        size than several, and much faster on a busy machine.
        """
        from threadpoolctl import threadpool_limits

        with threadpool_limits(1):
            return cls._analyse(skeleton, stiffness, keep_matrices)

    @classmethod
    def _analyse(cls, skeleton: Skeleton, stiffness: float, keep_matrices: bool) -> ModalModel:
        n_columns = 6 * skeleton.n_bodies
        constraints, deflection, stiffnesses = joint_matrices(skeleton)
        basis, rank = nullspace(constraints, n_columns)
        mass = skeleton.spatial_inertia
        reduced_mass = basis.T @ (mass[:, None] * basis)
        deflection_reduced = deflection @ basis
        reduced_stiffness = deflection_reduced.T @ ((stiffness * stiffnesses)[:, None]
                                                    * deflection_reduced)
        reduced_mass = (reduced_mass + reduced_mass.T) / 2
        reduced_stiffness = (reduced_stiffness + reduced_stiffness.T) / 2
        dimension = basis.shape[1]
        if dimension:
            eigenvalues, vectors = scipy.linalg.eigh(reduced_stiffness, reduced_mass)
        else:
            eigenvalues, vectors = np.zeros(0), np.zeros((0, 0))
        elastic = stiffnesses > 0
        rigid = dimension - matrix_rank(deflection_reduced[elastic]) if dimension else 0
        modes = basis @ vectors[:, rigid:]
        frequencies = np.sqrt(np.clip(eigenvalues[rigid:], 0, None)) / (2 * math.pi)
        model = cls(frequencies, modes, rigid, dimension, constraints.shape[0], rank,
                    skeleton.body_names, skeleton.centers, skeleton.rotations, mass)
        if keep_matrices:
            model.matrices = {"G": constraints, "N": basis, "R": deflection, "K": stiffnesses,
                              "rigid": basis @ vectors[:, :rigid]}
        return model

    # ----------------------------------------------------------------- analysis
    def body_energy(self) -> np.ndarray:
        """(n_b, nm): each body's share of a mode's kinetic energy ηᵀMη (columns sum to 1)."""
        mass = self.mass if self.mass is not None else np.ones(self.modes.shape[0])
        energy = (mass[:, None] * self.modes**2).reshape(self.n_bodies, 6, -1).sum(axis=1)
        total = energy.sum(axis=0, keepdims=True)
        return energy / np.where(total > 0, total, 1)

    def default_amplitudes(self, angle: float = 0.3, size: float | None = None) -> np.ndarray:
        """μ per mode so that its largest body rotation is at most `angle` radians and its
        largest body translation at most angle·size (size: the rest pose's extent)."""
        twists = self.modes.reshape(self.n_bodies, 6, -1)
        rotation = np.linalg.norm(twists[:, :3], axis=1).max(axis=0)
        translation = np.linalg.norm(twists[:, 3:], axis=1).max(axis=0)
        if size is None:
            extent = self.body_centers.max(axis=0) - self.body_centers.min(axis=0)
            size = float(np.linalg.norm(extent)) or 1.0
        reference = np.maximum(rotation, translation / size)
        return angle / np.where(reference > 0, reference, 1)

    # ----------------------------------------------------------------- motion
    def coefficients(self, times, amplitudes=None, phases=None, time_scale: float = 1.0,
                     drive=None, modes=None) -> np.ndarray:
        """c_κ(t) = φ_κ(t)·μ_κ·sin(2πν_κ s t + γ_κ), shape (T, nm).

        modes: indices of the modes that move (others get c = 0); default all. drive: φ,
        shape (T, nm) (or (T, len(modes)) when `modes` is given), default 1.
        """
        times = np.asarray(times, dtype=float).reshape(-1)
        selected = np.arange(self.n_modes) if modes is None else np.asarray(modes, dtype=int)
        if selected.size and (selected.min() < 0 or selected.max() >= self.n_modes):
            raise EigendanceError(f"mode index out of range: the model has {self.n_modes} "
                                  f"vibration modes (0 … {self.n_modes - 1})")
        amplitudes = self.default_amplitudes() if amplitudes is None else \
            np.broadcast_to(np.asarray(amplitudes, dtype=float), (self.n_modes,))
        phases = np.zeros(self.n_modes) if phases is None else \
            np.broadcast_to(np.asarray(phases, dtype=float), (self.n_modes,))
        result = np.zeros((times.size, self.n_modes))
        argument = 2 * math.pi * self.frequencies[selected] * time_scale * times[:, None] \
            + phases[selected]
        values = amplitudes[selected] * np.sin(argument)
        if drive is not None:
            drive = np.asarray(drive, dtype=float)
            if drive.shape == (times.size, self.n_modes) and modes is not None:
                drive = drive[:, selected]
            if drive.shape != values.shape:
                raise EigendanceError(f"drive has shape {drive.shape}; expected "
                                      f"{values.shape} (frames, modes)")
            values = values * drive
        result[:, selected] = values
        return result

    def twists(self, coefficients) -> np.ndarray:
        """Body twists [θ; x] in body frames, (T, n_b, 6), for coefficients (T, nm)."""
        coefficients = np.atleast_2d(np.asarray(coefficients, dtype=float))
        return (coefficients @ self.modes.T).reshape(len(coefficients), self.n_bodies, 6)

    def body_poses(self, coefficients) -> tuple[np.ndarray, np.ndarray]:
        """World rotations (T, n_b, 3, 3) and centres (T, n_b, 3) of every body: rotation
        exp([θ]×) about the centre of mass, then translation x, both in the body frame."""
        twist = self.twists(coefficients)
        rotations = self.body_rotations[None] @ rotation_exp(twist[..., :3])
        centers = self.body_centers[None] + np.einsum("bij,tbj->tbi", self.body_rotations,
                                                      twist[..., 3:])
        return rotations, centers

    def body_transforms(self, coefficients) -> np.ndarray:
        """World transforms (T, n_b, 4, 4) taking rest-pose points to posed points."""
        rotations, centers = self.body_poses(coefficients)
        linear = rotations @ np.swapaxes(self.body_rotations, -1, -2)[None]
        transforms = np.zeros(linear.shape[:2] + (4, 4))
        transforms[..., :3, :3] = linear
        transforms[..., :3, 3] = centers - np.einsum("tbij,bj->tbi", linear, self.body_centers)
        transforms[..., 3, 3] = 1
        return transforms

    # ----------------------------------------------------------------- files
    def save(self, path: str | os.PathLike) -> None:
        atomic_save_npz(
            path, frequencies=self.frequencies, modes=self.modes,
            rigid_modes=np.int64(self.rigid_modes), nullspace_dim=np.int64(self.nullspace_dim),
            constraint_rows=np.int64(self.constraint_rows),
            constraint_rank=np.int64(self.constraint_rank),
            body_names=np.array(self.body_names, dtype=str), body_centers=self.body_centers,
            body_rotations=self.body_rotations,
            mass=self.mass if self.mass is not None else np.ones(self.modes.shape[0]))

    @classmethod
    def load(cls, path: str | os.PathLike) -> ModalModel:
        data = load_npz(path, MODAL_KEYS)
        names = [str(name) for name in data["body_names"]]
        n_bodies = len(names)
        centers = data.get("body_centers", np.zeros((n_bodies, 3)))
        rotations = data.get("body_rotations", np.tile(np.eye(3), (n_bodies, 1, 1)))
        modes = np.asarray(data["modes"], dtype=float)
        if modes.ndim != 2 or modes.shape[0] != 6 * n_bodies or \
                modes.shape[1] != len(data["frequencies"]):
            raise EigendanceError(f"{os.fspath(path)}: modes and frequencies do not match "
                                  f"{n_bodies} bodies")
        return cls(np.asarray(data["frequencies"], dtype=float), modes, int(data["rigid_modes"]),
                   int(data["nullspace_dim"]), int(data["constraint_rows"]),
                   int(data["constraint_rank"]), names, centers, rotations, data.get("mass"))


def band_drive(values, n_modes: int, amplification: float | None = None,
               offset: float = 0.0) -> np.ndarray:
    """A simple φ (T, n_modes) from a spectrogram-like (T, B) array in [0, 1].

    Bands are assigned to modes in order, in contiguous groups (band ξ drives mode
    ⌊ξ·n_modes/B⌋: low sounds drive low modes), and φ_κ = a · Σ_{ξ→κ} g̃(ξ) + offset, the
    thesis's (6-2) with a constant amplification a. Default a = n_modes / B, so a full-scale
    spectrum gives φ ≈ 1, and offset 0, so silence stands still (offset 1 is (6-2) exactly:
    silence moves every mode at its base amplitude μ). With fewer bands than modes, a mode
    that no band reaches takes the band ⌊κ·B/n_modes⌋. This stands in for the mapping of
    DESIGN §4 (eigendance.mapping), whose Mapping.filter gives φ of the same shape.
    """
    values = np.asarray(values, dtype=float)
    if values.ndim != 2:
        raise EigendanceError(f"band values must be (frames, bands), not shape {values.shape}")
    frames, bands = values.shape
    if n_modes == 0:
        return np.zeros((frames, 0))
    if bands == 0:
        raise EigendanceError("band values have no bands")
    if amplification is None:
        amplification = n_modes / bands
    group_of_band = np.minimum(np.arange(bands) * n_modes // bands, n_modes - 1)
    sums = np.zeros((n_modes, frames))
    np.add.at(sums, group_of_band, values.T)
    reached = np.zeros(n_modes, dtype=bool)
    reached[group_of_band] = True
    fallback = np.minimum(np.arange(n_modes) * bands // n_modes, bands - 1)
    sums[~reached] = values.T[fallback[~reached]]
    return amplification * sums.T + offset
