"""The motion an export writes: a mesh dancing by its harmonics, or a rig by its modes
(docs/design.md#exports).

Every format (glTF, point cache, USD, video) reads one of two kinds of dance, both in the model
file's coordinates:

- `HarmonicDance`: X_φ(t) = X + Σ_ν (φ_ν(t) − 1)·U[:,ν]·X̃_ν (docs/design.md#harmonic-motion).
  Only the harmonics the mapping drives move (ν(ξ) for some band ξ, with a non-zero
  amplification: at most B = 64 of them), so the motion is exactly a set of morph targets
  D_ν = U[:,ν]·X̃_ν·scale (n×3, original units) with weights φ_ν(t) − 1 (`morphs`). With a
  reduced basis (U = P U_r, docs/design.md#reduced-basis) it is exactly linear blend skinning
  with translation-only joints at the samples: x_i(t) = rest_i + Σ_j w_ij D_j(t) (`sample_skin`).
- `RigDance`: bodies move by world transforms T_b(t) (4×4, rest pose → posed), the skin by
  linear blend skinning x′ = Σ_b w_ib T_b(t)x (exactly what a glTF skin plays) or by modal
  skinning (docs/design.md#skinning). `pose(times)` gives the transforms and mode coefficients:
  the one place rig motion enters the exports.

Positions come chunk by chunk (`frames`), so a long song never holds all frames in memory.
"""

from __future__ import annotations

import math
import os
from collections.abc import Callable, Iterator
from dataclasses import dataclass

import numpy as np

from eigendance.errors import InputError
from eigendance.geometry import bounding_box_diagonal
from eigendance.harmonic.basis import HarmonicBasis
from eigendance.harmonic.motion import iter_positions
from eigendance.modal.model import ModalModel
from eigendance.modal.motion import body_transforms
from eigendance.modal.skeleton import Skeleton
from eigendance.modal.skinning import ModalSkin, linear_blend_skinning
from eigendance.music.mapping import Mapping
from eigendance.music.spectrogram import Spectrogram

RIG_CHUNK = 64  # frames skinned per batch


def video_times(duration: float, fps: float) -> np.ndarray:
    """Frame i of a video shows time i/fps, i < ⌈duration·fps⌉ (at least one frame): the frames
    cover [0, duration) and the video lasts as long as the song, to within one frame."""
    if not (math.isfinite(fps) and fps > 0):
        raise InputError(f"frames per second must be a positive number, got {fps}")
    count = max(1, math.ceil(duration * fps - 1e-9))
    return np.arange(count) / float(fps)


def sample_times(duration: float, fps: float) -> np.ndarray:
    """Samples of an animation file: 0, 1/fps, … up to the duration included."""
    if not (math.isfinite(fps) and fps > 0):
        raise InputError(f"frames per second must be a positive number, got {fps}")
    return np.arange(int(math.floor(duration * fps + 1e-9)) + 1) / float(fps)


def vertex_normals(vertices: np.ndarray, faces: np.ndarray) -> np.ndarray:
    """Unit area-weighted vertex normals (n, 3), as three.js computeVertexNormals; a vertex
    whose triangles' normals cancel gets +z (it still must be a unit vector)."""
    corners = vertices[faces]
    face = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    normals = np.zeros_like(vertices, dtype=np.float64)
    for corner in range(3):
        np.add.at(normals, faces[:, corner], face)
    length = np.linalg.norm(normals, axis=1, keepdims=True)
    normals = np.divide(normals, length, out=np.zeros_like(normals), where=length > 0)
    normals[length[:, 0] <= 0] = (0.0, 0.0, 1.0)
    return normals


@dataclass
class Morphs:
    """Harmonic motion as morph targets: positions(t_i) = rest + Σ_j weights[i, j]·targets[j].

    harmonics: (J,) the driven harmonics ν; targets: (J, n, 3) D_ν in original units;
    weights: (T, J) φ_ν(t_i) − 1.
    """

    harmonics: np.ndarray
    targets: np.ndarray
    weights: np.ndarray


@dataclass
class SampleSkin:
    """A reduced harmonic dance as a skin: joint j sits at sample j's rest position c_j and
    moves by translation only, D_j(t) = Σ_ν (φ_ν(t) − 1)·C_jν; vertex i moves by
    Σ_j w_ij D_j(t) (docs/design.md#exports).

    joints: (m, 3) c_j, original units; indices, weights: (n, 8) each vertex's samples and
    weights (≥ 0, summing to 1, largest first); coarse: (d, m, 3) C_jν for the d driven
    harmonics, original units; amplitudes: (T, d) φ_ν(t_i) − 1.
    """

    joints: np.ndarray
    indices: np.ndarray
    weights: np.ndarray
    coarse: np.ndarray
    amplitudes: np.ndarray

    def translations(self, joint: int) -> np.ndarray:
        """(T, 3) float32: joint `joint`'s position c_j + D_j(t_i) at every sample time."""
        moved = self.amplitudes @ self.coarse[:, joint, :]
        return (self.joints[joint] + moved).astype("<f4")

    def positions(self) -> np.ndarray:
        """(T, n, 3) float64: what a viewer playing the skin shows (tests, short clips)."""
        moved = np.einsum("td,djc->tjc", self.amplitudes, self.coarse)  # (T, m, 3)
        rest = np.einsum("ij,ijc->ic", self.weights, self.joints[self.indices])
        offsets = np.einsum("ij,tijc->tic", self.weights, moved[:, self.indices])
        return rest + offsets


class Dance:
    """What every export needs: a triangle mesh in the model file's coordinates that moves.

    faces (m, 3) int64; rest (n, 3) float64; center (3,) and scale: the framing of
    docs/design.md#mesh (the middle of the bounding box, half its largest side); duration (s);
    audio: the song's file or None; name: how messages and files call it; appearance: the
    model's look (`assets.Appearance`, drawn vertices on these), or None (clay).
    """

    appearance = None
    name: str
    faces: np.ndarray
    rest: np.ndarray
    duration: float
    audio: str | None
    info: dict

    @property
    def n(self) -> int:
        return len(self.rest)

    @property
    def center(self) -> np.ndarray:
        return (self.rest.min(axis=0) + self.rest.max(axis=0)) / 2

    @property
    def scale(self) -> float:
        return float((self.rest.max(axis=0) - self.rest.min(axis=0)).max() / 2) or 1.0

    @property
    def diagonal(self) -> float:
        return bounding_box_diagonal(self.rest)

    def rest_normals(self) -> np.ndarray:
        return vertex_normals(self.rest, self.faces)

    def drawn(self, positions: np.ndarray) -> np.ndarray:
        """(…, n_d, 3) the drawn vertices' positions from the welded ones (…, n, 3): each at its
        welded vertex (docs/design.md#appearance); the positions themselves without a look."""
        return positions if self.appearance is None else self.appearance.drawn(positions)

    def frames(self, times) -> Iterator[tuple[int, np.ndarray, np.ndarray | None]]:
        """(first frame index, positions (C, n, 3) float32, normals (C, n, 3) or None when the
        rest normals hold) for `times`, chunk by chunk."""
        raise NotImplementedError

    def loudest_times(self, count: int) -> np.ndarray:
        """Times the camera frames the dance at (besides its rest shape). Without a
        spectrogram to find the song's `count` loudest moments (a harmonic dance's), 8·count
        times spread evenly over the dance, so the widest poses are held too."""
        return np.arange(8 * count) * (self.duration / (8 * count))

    def positions(self, times) -> np.ndarray:
        """All positions (T, n, 3) float64 at `times` (for tests and short clips)."""
        times = np.asarray(times, dtype=np.float64).reshape(-1)
        out = np.empty((len(times), self.n, 3))
        for first, chunk, _ in self.frames(times):
            out[first:first + len(chunk)] = chunk
        return out


class HarmonicDance(Dance):
    """A mesh moved by its harmonics (docs/design.md#harmonic-motion).

    Parameters
    ----------
    basis : the mesh's harmonics.
    spectrogram : the song's banded loudness.
    mapping : the sound-to-motion mapping (gain and smoothing included).
    audio : the song's file, written beside or into the export, or None.
    name : how messages and files call it.
    """

    def __init__(self, basis: HarmonicBasis, spectrogram: Spectrogram, mapping: Mapping,
                 audio: str | os.PathLike | None = None, name: str = "dance"):
        if mapping.bands != spectrogram.bands:
            raise InputError(f"{mapping.name}: the mapping has {mapping.bands} bands; the "
                             f"song's spectrogram has {spectrogram.bands}")
        self.basis, self.spectrogram, self.mapping = basis, spectrogram, mapping
        self.name = name
        self.faces = np.asarray(basis.faces, dtype=np.int64)
        self.rest = basis.to_original(basis.vertices)
        self.duration = float(spectrogram.duration)
        self.audio = None if audio is None else os.fspath(audio)
        self.info = {"kind": "harmonics", "k": basis.k, "mapping": mapping.to_json()}
        self.appearance = basis.appearance

    def phi(self, times) -> np.ndarray:
        """φ(t) (T, k): the mapping's filter of the (smoothed) spectrogram."""
        values = self.spectrogram.smoothed(self.mapping.smoothing).at(
            np.asarray(times, dtype=np.float64))
        return self.mapping.filter(values, self.basis.k)

    def loudest_times(self, count: int) -> np.ndarray:
        """The song's `count` loudest moments (largest sum over bands of a spectrogram frame),
        at least 0.25 s apart, loudest first: the poses the page frames a model in
        (web/src/motion.ts `loudestTimes`)."""
        values = self.spectrogram.values
        order = np.argsort(-values.sum(axis=1, dtype=np.float64), kind="stable")
        times: list[float] = []
        for frame in order:  # stops after `count` picks: a few frames, not the song
            if len(times) == count:
                break
            t = frame / self.spectrogram.rate
            if all(abs(t - other) >= 0.25 for other in times):
                times.append(t)
        return np.array(times)

    def driven(self) -> np.ndarray:
        """The harmonics ν the mapping moves: targets of some band with a non-zero
        amplification (every other φ_ν is 1 at all times), ascending."""
        targets = np.unique(self.mapping.harmonic_indices(self.basis.k))
        return targets[self.mapping.amplification_for(self.basis.k)[targets] != 0]

    def morphs(self, times) -> Morphs:
        """The motion at `times` as morph targets (exact: X_φ is linear in φ)."""
        driven = self.driven()
        basis = self.basis
        targets = (basis.harmonics(driven).T[:, :, None]
                   * basis.coefficients[driven][:, None, :] * basis.scale)
        return Morphs(driven, targets, self.phi(times)[:, driven] - 1.0)

    def sample_skin(self, times) -> SampleSkin:
        """The motion of a reduced basis at `times` as a skin on its samples (exact)."""
        reduced = self.basis.reduced
        if reduced is None:
            raise ValueError("only a reduced basis moves as a skin on its samples")
        driven = self.driven()
        coarse = reduced.coarse[:, driven].T[:, :, None] * \
            (self.basis.coefficients[driven] * self.basis.scale)[:, None, :]
        order = np.argsort(-reduced.interpolation.weights, axis=1, kind="stable")
        weights = np.take_along_axis(reduced.interpolation.weights, order, axis=1)
        indices = np.where(weights > 0, np.take_along_axis(
            reduced.interpolation.indices, order, axis=1), 0)
        return SampleSkin(self.rest[reduced.samples], indices, weights, coarse,
                          self.phi(times)[:, driven] - 1.0)

    def frames(self, times):
        for first, positions in iter_positions(self.basis, self.spectrogram, self.mapping,
                                               times):
            yield first, positions, None


class RigDance(Dance):
    """A rig's skin moved by its bodies (docs/design.md#skinning).

    Parameters
    ----------
    vertices : (n, 3) rest positions of the skin; faces : (m, 3) triangles.
    weights : (n, n_b) skin weights, rows summing to 1 (dense or scipy sparse).
    pose : times (T,) → (transforms (T, n_b, 4, 4) from the rest pose, coefficients (T, nm)).
    rest_frames : (n_b, 4, 4) each body's frame in the rest pose (where a glTF joint sits).
    body_names : one name per body.
    duration : seconds.
    modal : a `ModalSkin` to move the skin by modal skinning, or None for linear blend skinning.
    audio, name : as for `HarmonicDance`.
    appearance : the skin's look (`assets.Appearance`), or None (clay).
    """

    def __init__(self, vertices, faces, weights, pose: Callable, rest_frames, body_names,
                 duration: float, modal: ModalSkin | None = None,
                 audio: str | os.PathLike | None = None, name: str = "dance", info=None,
                 appearance=None):
        self.rest = np.asarray(vertices, dtype=np.float64)
        self.faces = np.asarray(faces, dtype=np.int64)
        self.weights = weights.toarray() if hasattr(weights, "toarray") else \
            np.asarray(weights, dtype=np.float64)
        self.pose = pose
        self.rest_frames = np.asarray(rest_frames, dtype=np.float64)
        self.body_names = [str(name) for name in body_names]
        self.duration = float(duration)
        self.modal = modal
        self.audio = None if audio is None else os.fspath(audio)
        self.name = name
        self.info = {"kind": "rig", "skinning": "modal" if modal else "lbs", **(info or {})}
        self.appearance = appearance

    def frames(self, times):
        times = np.asarray(times, dtype=np.float64)
        normals = self.rest_normals()
        for first in range(0, len(times), RIG_CHUNK):
            transforms, coefficients = self.pose(times[first:first + RIG_CHUNK])
            if self.modal is not None:
                positions = self.modal.positions(coefficients)
                turned = self.modal.normals(coefficients, normals)
            else:
                positions, turned = linear_blend_skinning(self.rest, self.weights, transforms,
                                                          normals)
            yield first, positions.astype(np.float32), turned.astype(np.float32)

    def blend_positions(self, times) -> np.ndarray:
        """(T, n, 3) linear blend skinning at `times`: what a glTF skin plays."""
        transforms, _ = self.pose(np.asarray(times, dtype=np.float64))
        return linear_blend_skinning(self.rest, self.weights, transforms)


def rig_dance(skeleton: Skeleton, model: ModalModel, duration: float,
              coefficients: Callable, skinning: str = "modal", audio=None,
              name: str = "dance") -> RigDance:
    """A rig moving in its vibration modes, as `eigendance animate-rig` moves it.

    Parameters
    ----------
    skeleton : the rig with its skin; model : its modes (`ModalModel.from_skeleton`).
    duration : seconds.
    coefficients : times (T,) → c (T, nm), e.g. `modal.motion.rig_coefficients` of a song and
        the mapping `modal.motion.rig_mapping` resolved (docs/design.md#modal-motion).
    skinning : "modal" or "lbs".
    audio, name : the song's file (or None) and how files call the dance.

    Returns
    -------
    RigDance whose `pose(times)` gives the body transforms (`modal.motion.body_transforms`)
    and c_κ(t).
    """
    if skinning not in ("modal", "lbs"):
        raise InputError(f"skinning must be modal or lbs, got {skinning!r}")

    def pose(times):
        moving = coefficients(np.asarray(times, dtype=float))
        return body_transforms(model, moving), moving

    moving_modes = np.flatnonzero(np.abs(coefficients(np.linspace(0, duration, 64))).max(axis=0))
    frames = np.zeros((model.n_bodies, 4, 4))
    frames[:, :3, :3] = model.body_rotations
    frames[:, :3, 3] = model.body_centers
    frames[:, 3, 3] = 1
    modal = ModalSkin(model, skeleton.vertices, skeleton.weights) if skinning == "modal" else None
    info = {"modes": [int(m) for m in moving_modes],
            "frequencies_hz": [float(model.frequencies[m]) for m in moving_modes]}
    return RigDance(skeleton.vertices, skeleton.faces, skeleton.weights, pose, frames,
                    model.body_names, duration, modal, audio, name, info,
                    getattr(skeleton, "appearance", None))
