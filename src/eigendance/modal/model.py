"""Modal analysis of a skeleton: its natural vibration modes (docs/design.md#modal-model).

Velocities are spatial [ω; v] in each body's frame (origin at its centre of mass), stacked into
one vector of length 6·n_b. For a joint j between bodies i and l at P:

- Ad_{i→j} = [[Ω, 0], [[O]×Ω, Ω]] with Ω = R_jᵀ R_i and O = R_jᵀ (c_i − P): body i's velocity
  seen at P in the joint frame (thesis 3-60).
- constraints (4-12): Γᵐ (Ad_{i→j} v̂_i − Ad_{l→j} v̂_l) = 0, stacked into G v̂ = 0.
- elastic deflection: Γᶠ (Ad_{i→j} v̂_i − Ad_{l→j} v̂_l), stacked into R: the **difference** of
  the two bodies' motions (the thesis's (4-35) adds them); K = diag of the free rows' stiffness.
- N: orthonormal basis of ker G from the SVD with a relative rank tolerance, so loops (dependent
  rows) give dim N = 6n_b − rank G.
- M̃ = NᵀMN, K̃ = NᵀRᵀKRN, K̃u = λM̃u; modes η = Nu (ηᵀMη = I), frequencies ν = √λ/2π Hz.
  The dim N − rank(RN) smallest eigenvalues are rigid motions of the whole (λ = 0; also any
  mechanism left free by a zero stiffness): counted, not kept as vibrations. Joint damping
  is read with the skeleton but not used: the modes are those of the undamped system.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass

import numpy as np
from threadpoolctl import threadpool_limits

from eigendance.errors import InputError
from eigendance.files import load_npz
from eigendance.geometry import bounding_box_diagonal
from eigendance.modal.rotations import skew
from eigendance.modal.skeleton import Skeleton
from eigendance.writes import atomic_save_npz

RANK_TOLERANCE = 1e-9  # singular values below this times the largest count as zero

MODAL_KEYS = ("frequencies", "modes", "rigid_modes", "nullspace_dim", "constraint_rows",
              "constraint_rank", "body_names")


def joint_adjoints(skeleton: Skeleton) -> tuple[np.ndarray, np.ndarray]:
    """Ad_{i→j} and Ad_{l→j} for every joint, each (n_joints, 6, 6).

    Parameters
    ----------
    skeleton : the bodies and joints.

    Returns
    -------
    (first, second): (n_joints, 6, 6) each.
    """
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
    """G (constrained rows), R (free rows) and the stiffness diagonal K of a skeleton.

    Parameters
    ----------
    skeleton : the bodies and joints.

    Returns
    -------
    G (constrained rows, 6·n_b columns), R (free rows, 6·n_b columns), K (free rows,).
    """
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


def null_space(matrix: np.ndarray, n_columns: int) -> np.ndarray:
    """Orthonormal basis of ker matrix as columns (n_columns, dim), relative tolerance.

    Parameters
    ----------
    matrix : (rows, n_columns), possibly with no rows.
    n_columns : its column count.

    Returns
    -------
    (n_columns, dim) orthonormal columns.
    """
    if matrix.shape[0] == 0:
        return np.eye(n_columns)
    # numpy's SVD, not scipy.linalg.null_space: numpy lets other threads run meanwhile (scipy's
    # LAPACK wrappers hold the GIL, and the server's event loop waited seconds for them).
    if matrix.shape[0] > n_columns:
        # Many rows (20,000 joints between two bodies): R of A = QR has A's null space and
        # singular values, and its SVD never asks LAPACK for a rows × rows matrix.
        matrix = np.linalg.qr(matrix, mode="r")
    _, singular, rows = np.linalg.svd(matrix, full_matrices=True)
    rank = int(np.sum(singular > RANK_TOLERANCE * singular[0])) if singular.size else 0
    return rows[rank:].T.copy()


def generalized_eigh(stiffness: np.ndarray, mass: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """K v = λ M v for symmetric K and positive definite M, as LAPACK's sygvd solves it (M = L Lᵀ,
    the standard problem of L⁻¹ K L⁻ᵀ), with numpy's routines, which let other threads run
    (scipy.linalg.eigh holds the GIL).

    Parameters
    ----------
    stiffness : (d, d) symmetric K.
    mass : (d, d) symmetric positive definite M.

    Returns
    -------
    eigenvalues (d,) ascending, eigenvectors (d, d) as columns, M-orthonormal (Vᵀ M V = I).

    Example
    -------
    >>> values, vectors = generalized_eigh(np.diag([2.0, 12.0]), np.diag([1.0, 3.0]))
    >>> values.round(6).tolist(), bool(np.allclose(vectors.T @ np.diag([1.0, 3.0]) @ vectors,
    ...                                            np.eye(2)))
    ([2.0, 4.0], True)
    """
    lower = np.linalg.cholesky(mass)
    standard = np.linalg.solve(lower, np.linalg.solve(lower, stiffness).T)
    eigenvalues, vectors = np.linalg.eigh((standard + standard.T) / 2)
    return eigenvalues, np.linalg.solve(lower.T, vectors)


def matrix_rank(matrix: np.ndarray) -> int:
    """Rank by SVD: singular values above RANK_TOLERANCE times the largest.

    Parameters
    ----------
    matrix : any 2-D array.

    Returns
    -------
    int.
    """
    if matrix.size == 0:
        return 0
    singular = np.linalg.svd(matrix, compute_uv=False)
    return int(np.sum(singular > RANK_TOLERANCE * singular[0])) if singular[0] > 0 else 0


@dataclass
class ModalModel:
    """Vibration modes of a skeleton (modal file: docs/design.md#modal-file).

    frequencies: (nm,) Hz ascending, vibration modes only. modes: (6·n_b, nm), M-orthonormal,
    body b's twist [θ; x] (body frame) in rows 6b … 6b+5. body_centers (n_b, 3) and
    body_rotations (n_b, 3, 3): the rest pose, needed to move bodies and skin. joint_bodies
    (n_j, 2) and joint_positions (n_j, 3): the two bodies of every joint and where it is;
    size: the skeleton's extent (`Skeleton.size`), the length that turns translations into
    angles (docs/design.md#modal-motion). floor: the skin's `modal.floor.SkinFloor` (the palette
    keeps the skin above it), set by `Rig`; None without a skin (not in the modal file).

    Parameters
    ----------
    frequencies, modes, rigid_modes, nullspace_dim, constraint_rows, constraint_rank, body_names,
    body_centers, body_rotations, mass, joint_bodies, joint_positions, size, floor : as above;
        `from_skeleton` makes them, `load` reads them.

    Example
    -------
    >>> from eigendance.modal.sample_rigs import planar_loop
    >>> model = ModalModel.from_skeleton(planar_loop(4, skin=False))
    >>> model.nullspace_dim, model.rigid_modes, model.n_modes   # thesis Table 4.1: dim N = 7
    (7, 6, 1)
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
    joint_bodies: np.ndarray | None = None  # (n_j, 2) int64
    joint_positions: np.ndarray | None = None  # (n_j, 3)
    size: float | None = None
    floor: object | None = None  # modal.floor.SkinFloor

    def __post_init__(self):
        if self.joint_bodies is None:
            self.joint_bodies = np.zeros((0, 2), dtype=np.int64)
        self.joint_bodies = np.asarray(self.joint_bodies, dtype=np.int64).reshape(-1, 2)
        if self.joint_positions is None:  # a modal file without them: between the centres
            self.joint_positions = self.body_centers[self.joint_bodies].mean(axis=1)
        self.joint_positions = np.asarray(self.joint_positions, dtype=float).reshape(-1, 3)
        if self.size is None:
            self.size = bounding_box_diagonal(self.body_centers) or 1.0
        self.size = float(self.size)

    @property
    def n_modes(self) -> int:
        """Vibration modes (rigid motions not counted)."""
        return len(self.frequencies)

    @property
    def n_bodies(self) -> int:
        """Bodies."""
        return len(self.body_names)

    @classmethod
    def from_skeleton(cls, skeleton: Skeleton, stiffness: float = 1.0,
                      keep_matrices: bool = False) -> ModalModel:
        """Modal analysis of a skeleton.

        Parameters
        ----------
        skeleton : bodies and elastic joints.
        stiffness : multiplies every joint stiffness (frequencies scale with its square root).
        keep_matrices : also keep G, N, R, K as `model.matrices` (tests, inspection).

        Returns
        -------
        ModalModel with the vibration modes, lowest frequency first.

        The dense factorisations (a few hundred rows) run on one BLAS thread: faster at this
        size than several, and much faster on a busy machine.
        """
        with threadpool_limits(1):
            return cls._analyse(skeleton, stiffness, keep_matrices)

    @classmethod
    def _analyse(cls, skeleton: Skeleton, stiffness: float, keep_matrices: bool) -> ModalModel:
        n_columns = 6 * skeleton.n_bodies
        constraints, deflection, stiffnesses = joint_matrices(skeleton)
        basis = null_space(constraints, n_columns)
        rank = n_columns - basis.shape[1]
        mass = skeleton.spatial_inertia
        reduced_mass = basis.T @ (mass[:, None] * basis)
        deflection_reduced = deflection @ basis
        reduced_stiffness = deflection_reduced.T @ ((stiffness * stiffnesses)[:, None]
                                                    * deflection_reduced)
        reduced_mass = (reduced_mass + reduced_mass.T) / 2
        reduced_stiffness = (reduced_stiffness + reduced_stiffness.T) / 2
        scaled = "joint stiffness" + (f" × {stiffness:g}" if stiffness != 1 else "")
        if not np.isfinite(reduced_stiffness).all():  # the product overflowed
            raise InputError(f"{skeleton.name}: {scaled} is beyond the range of numbers (the "
                             "stiffness matrix overflows); give smaller stiffnesses")
        dimension = basis.shape[1]
        if dimension:
            eigenvalues, vectors = generalized_eigh(reduced_stiffness, reduced_mass)
        else:
            eigenvalues, vectors = np.zeros(0), np.zeros((0, 0))
        elastic = stiffnesses > 0
        rigid = dimension - matrix_rank(deflection_reduced[elastic]) if dimension else 0
        modes = basis @ vectors[:, rigid:]
        frequencies = np.sqrt(np.clip(eigenvalues[rigid:], 0, None)) / (2 * math.pi)
        # The page's bundle and the files hold them as float32: beyond its range is infinite.
        if not (np.all(frequencies <= np.finfo(np.float32).max) and np.isfinite(modes).all()):
            raise InputError(f"{skeleton.name}: {scaled} gives frequencies beyond the range "
                             "of numbers (of 32-bit floats); give smaller stiffnesses")
        model = cls(frequencies, modes, rigid, dimension, constraints.shape[0], rank,
                    skeleton.body_names, skeleton.centers, skeleton.rotations, mass,
                    skeleton.joint_pairs,
                    np.array([joint.position for joint in skeleton.joints]).reshape(-1, 3),
                    skeleton.size)
        if keep_matrices:
            model.matrices = {"G": constraints, "N": basis, "R": deflection, "K": stiffnesses,
                              "rigid": basis @ vectors[:, :rigid]}
        return model

    def body_energy(self) -> np.ndarray:
        """(n_b, nm): each body's share of a mode's kinetic energy ηᵀMη (columns sum to 1).

        Returns
        -------
        (n_b, nm) shares, each column summing to 1.
        """
        mass = self.mass if self.mass is not None else np.ones(self.modes.shape[0])
        energy = (mass[:, None] * self.modes**2).reshape(self.n_bodies, 6, -1).sum(axis=1)
        total = energy.sum(axis=0, keepdims=True)
        return energy / np.where(total > 0, total, 1)

    # ----------------------------------------------------------------- files
    def save(self, path: str | os.PathLike) -> None:
        """Write the modal file (docs/design.md#modal-file) atomically.

        Parameters
        ----------
        path : the .npz to write.
        """
        atomic_save_npz(
            path, frequencies=self.frequencies, modes=self.modes,
            rigid_modes=np.int64(self.rigid_modes), nullspace_dim=np.int64(self.nullspace_dim),
            constraint_rows=np.int64(self.constraint_rows),
            constraint_rank=np.int64(self.constraint_rank),
            body_names=np.array(self.body_names, dtype=str), body_centers=self.body_centers,
            body_rotations=self.body_rotations,
            mass=self.mass if self.mass is not None else np.ones(self.modes.shape[0]),
            joint_bodies=self.joint_bodies, joint_positions=self.joint_positions,
            size=np.float64(self.size))

    @classmethod
    def load(cls, path: str | os.PathLike) -> ModalModel:
        """Read a modal file; a missing key or inconsistent shape raises InputError.

        Parameters
        ----------
        path : a modal file.

        Returns
        -------
        ModalModel.
        """
        data = load_npz(path, MODAL_KEYS)
        names = [str(name) for name in data["body_names"]]
        n_bodies = len(names)
        centers = data.get("body_centers", np.zeros((n_bodies, 3)))
        rotations = data.get("body_rotations", np.tile(np.eye(3), (n_bodies, 1, 1)))
        modes = np.asarray(data["modes"], dtype=float)
        if modes.ndim != 2 or modes.shape[0] != 6 * n_bodies or \
                modes.shape[1] != len(data["frequencies"]):
            raise InputError(f"{os.fspath(path)}: modes and frequencies do not match "
                             f"{n_bodies} bodies")
        joint_bodies = data.get("joint_bodies")
        if joint_bodies is not None and (joint_bodies.size and (
                joint_bodies.min() < 0 or joint_bodies.max() >= n_bodies)):
            raise InputError(f"{os.fspath(path)}: joint_bodies names a body out of range")
        size = data.get("size")
        return cls(np.asarray(data["frequencies"], dtype=float), modes, int(data["rigid_modes"]),
                   int(data["nullspace_dim"]), int(data["constraint_rows"]),
                   int(data["constraint_rank"]), names, centers, rotations, data.get("mass"),
                   joint_bodies, data.get("joint_positions"),
                   None if size is None else float(size))
