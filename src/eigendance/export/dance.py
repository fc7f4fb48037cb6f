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
- `RigDance` (`export.rig_dance`): a rig moving in its modes, its skin skinned.

Positions come chunk by chunk (`frames`), so a long song never holds all frames in memory.
`dance.window(start, duration)` is the part of the song from `start` (docs/design.md#window):
its time t is the song's time start + t, so a clip's frames are frames of the whole dance, and
the exports write it from time 0 with the song cut to the same part.
"""

from __future__ import annotations

import copy
import math
import os
from collections.abc import Iterator
from dataclasses import dataclass

import numpy as np

from eigendance.errors import InputError
from eigendance.geometry import bounding_box_diagonal, vertex_normals
from eigendance.harmonic.basis import HarmonicBasis
from eigendance.harmonic.motion import iter_positions
from eigendance.music.mapping import Mapping
from eigendance.music.spectrogram import Spectrogram
from eigendance.window import Window

# The largest coordinate (model units) and body rotation (radians) a dance may reach: far
# beyond any dance (a mapping's amplification of 1e300 goes past them), well inside float32.
MAX_COORDINATE, MAX_TURN = 1e30, 1e6


def check_motion(values, mapping: str) -> None:
    """InputError naming the mapping unless every value is finite and at most MAX_COORDINATE in
    size as a float32 (what every file and the video hold).

    Parameters
    ----------
    values : positions (any shape).
    mapping : the mapping's name, for the message.
    """
    values = np.asarray(values)
    with np.errstate(all="ignore"):
        if not (np.isfinite(values).all() and np.abs(values).max(initial=0) <= MAX_COORDINATE):
            raise InputError(f"{mapping}: the motion it asks for leaves the range of numbers a "
                             "file holds; lower its amplification")


def video_times(duration: float, fps: float) -> np.ndarray:
    """Frame i of a video shows time i/fps, i < ⌈duration·fps⌉ (at least one frame): the frames
    cover [0, duration) and the video lasts as long as the song, to within one frame.

    Parameters
    ----------
    duration : s.
    fps : frames per second.

    Returns
    -------
    (⌈duration·fps⌉,) s.
    """
    if not (math.isfinite(fps) and fps > 0):
        raise InputError(f"frames per second must be a positive number, got {fps}")
    count = max(1, math.ceil(duration * fps - 1e-9))
    return np.arange(count) / float(fps)


@dataclass
class Morphs:
    """Harmonic motion as morph targets: positions(t_i) = rest + Σ_j weights[i, j]·targets[j].

    harmonics: (J,) the driven harmonics ν; targets: (J, n, 3) D_ν in original units;
    weights: (T, J) φ_ν(t_i) − 1.

    Parameters
    ----------
    harmonics, targets, weights : as above.
    """

    harmonics: np.ndarray
    targets: np.ndarray
    weights: np.ndarray


@dataclass
class SampleSkin:
    """A reduced harmonic dance as a skin: joint j sits at sample j's rest position c_j and
    moves by translation only, D_j(t) = Σ_ν (φ_ν(t) − 1)·C_jν; vertex i moves by
    Σ_j w_ij D_j(t) (docs/design.md#exports).

    Parameters
    ----------
    joints : (m, 3) c_j, original units.
    indices, weights : (n, 8) each vertex's samples and weights (≥ 0, summing to 1, largest
        first).
    coarse : (d, m, 3) C_jν for the d driven harmonics, original units.
    amplitudes : (T, d) φ_ν(t_i) − 1.
    """

    joints: np.ndarray
    indices: np.ndarray
    weights: np.ndarray
    coarse: np.ndarray
    amplitudes: np.ndarray

    def translations(self, joint: int) -> np.ndarray:
        """Joint `joint`'s position c_j + D_j(t_i) at every sample time.

        Parameters
        ----------
        joint : j.

        Returns
        -------
        (T, 3) float32.
        """
        moved = self.amplitudes @ self.coarse[:, joint, :]
        return (self.joints[joint] + moved).astype("<f4")

    def positions(self) -> np.ndarray:
        """What a viewer playing the skin shows (tests, short clips).

        Returns
        -------
        (T, n, 3) float64.
        """
        moved = np.einsum("td,djc->tjc", self.amplitudes, self.coarse)  # (T, m, 3)
        rest = np.einsum("ij,ijc->ic", self.weights, self.joints[self.indices])
        offsets = np.einsum("ij,tijc->tic", self.weights, moved[:, self.indices])
        return rest + offsets


class Dance:
    """What every export needs: a triangle mesh in the model file's coordinates that moves.

    faces (m, 3) int64; rest (n, 3) float64; center (3,) and scale: the framing of
    docs/design.md#mesh (the middle of the bounding box, half its largest side); duration (s);
    audio: the song's file or None; name: how messages and files call it; appearance: the
    model's look (`assets.Appearance`, drawn vertices on these), or None (clay). start: where
    the dance starts in the song (s; 0 unless it is a `window`), length: the whole song (s),
    note: what the window changed to fit the song (or None).
    """

    appearance = None
    name: str
    faces: np.ndarray
    rest: np.ndarray
    duration: float
    audio: str | None
    info: dict
    start: float = 0.0
    length: float = math.inf
    note: str | None = None

    def window(self, start: float | None = None, duration: float | None = None) -> Dance:
        """The part of the dance from `start` for `duration` seconds (docs/design.md#window).

        Parameters
        ----------
        start : s from this dance's start (None: 0).
        duration : s (None: to the song's end).

        Returns
        -------
        Dance of the same kind whose time t is this dance's time start + t (the song's time
        self.start + start + t), lasting `duration` (clamped to the song's end, with a `note`).
        InputError for a start or a duration outside the song (`window.Window.of`).

        Example
        -------
        >>> import trimesh
        >>> from eigendance.harmonic.mesh import Mesh
        >>> from eigendance.music.demo_music import demo_track
        >>> sphere = trimesh.creation.icosphere(2)
        >>> basis = HarmonicBasis.from_mesh(Mesh.from_arrays(sphere.vertices, sphere.faces), 16,
        ...                                 cache=False)
        >>> song = Spectrogram.from_samples(*demo_track(4.0))
        >>> dance = HarmonicDance(basis, song, Mapping(np.full(64, 0.3), np.full(16, 0.5)))
        >>> clip = dance.window(1.5, 2.0)
        >>> bool(np.allclose(clip.positions([0.0, 0.5]), dance.positions([1.5, 2.0])))
        True
        """
        clip = Window.of(start, duration, self.duration, self.song_name)
        dance = copy.copy(self)
        dance.start, dance.duration, dance.note = self.start + clip.start, clip.duration, \
            clip.note
        return dance

    @property
    def song_name(self) -> str:
        """How messages call the song: its file's name, else "the dance"."""
        return os.path.basename(self.audio) if self.audio else "the dance"

    @property
    def clipped(self) -> bool:
        """Whether the dance is a part of its song (starting later, or ending before it)."""
        return self.start > 0 or self.start + self.duration < self.length - 1e-9

    @property
    def n(self) -> int:
        """Vertices."""
        return len(self.rest)

    @property
    def center(self) -> np.ndarray:
        """(3,) the middle of the rest shape's bounding box."""
        return (self.rest.min(axis=0) + self.rest.max(axis=0)) / 2

    @property
    def scale(self) -> float:
        """Half the largest side of the rest shape's bounding box (1 for a point)."""
        return float((self.rest.max(axis=0) - self.rest.min(axis=0)).max() / 2) or 1.0

    @property
    def diagonal(self) -> float:
        """The rest shape's bounding-box diagonal."""
        return bounding_box_diagonal(self.rest)

    def rest_normals(self) -> np.ndarray:
        """Unit vertex normals of the rest shape (+z where none exists), as three.js computes them.

        Returns
        -------
        (n, 3) float64.
        """
        return vertex_normals(self.rest, self.faces, default=(0.0, 0.0, 1.0))

    def drawn(self, positions: np.ndarray) -> np.ndarray:
        """(…, n_d, 3) the drawn vertices' positions from the welded ones (…, n, 3): each at its
        welded vertex (docs/design.md#appearance); the positions themselves without a look.

        Parameters
        ----------
        positions : (…, n, 3).

        Returns
        -------
        (…, n_d, 3).
        """
        return positions if self.appearance is None else self.appearance.drawn(positions)

    def frames(self, times) -> Iterator[tuple[int, np.ndarray, np.ndarray | None]]:
        """The dance at `times`, chunk by chunk.

        Parameters
        ----------
        times : (T,) s of the dance.

        Yields
        ------
        (first frame index, positions (C, n, 3) float32, normals (C, n, 3) float32 or None when the
        rest normals hold).
        """
        raise NotImplementedError

    def loudest_times(self, count: int) -> np.ndarray:
        """Times the camera frames the dance at (besides its rest shape). Without a
        spectrogram to find the song's `count` loudest moments (a harmonic dance's), 8·count
        times spread evenly over the dance, so the widest poses are held too.

        Parameters
        ----------
        count : how many poses.

        Returns
        -------
        (8·count,) s of the dance.
        """
        return np.arange(8 * count) * (self.duration / (8 * count))

    def positions(self, times) -> np.ndarray:
        """All positions (T, n, 3) float64 at `times` (for tests and short clips).

        Parameters
        ----------
        times : (T,) s of the dance.

        Returns
        -------
        (T, n, 3) float64 (from the float32 frames).
        """
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
        self.duration = self.length = float(spectrogram.duration)
        self.audio = None if audio is None else os.fspath(audio)
        self.info = {"kind": "harmonics", "k": basis.k, "mapping": mapping.to_json()}
        self.appearance = basis.appearance

    def phi(self, times) -> np.ndarray:
        """φ(t) (T, k): the mapping's filter on the song (`Mapping.play`: smoothing, envelope,
        pulse) at the dance's times (the song's times start + t).

        Parameters
        ----------
        times : (T,) s of the dance.

        Returns
        -------
        (T, k).
        """
        times = self.start + np.asarray(times, dtype=np.float64)
        return self.mapping.play(self.spectrogram, times, self.basis.k)

    def loudest_times(self, count: int) -> np.ndarray:
        """The dance's `count` loudest moments (largest sum over bands of a spectrogram frame),
        at least 0.25 s apart, loudest first, in the dance's time: the poses the page frames a
        model in (web/src/motion.ts `loudestTimes`); a window's own loudest moments.

        Parameters
        ----------
        count : how many poses.

        Returns
        -------
        (≤ count,) s of the dance.
        """
        rate = self.spectrogram.rate
        first = int(math.ceil(self.start * rate - 1e-9))
        last = int(math.floor((self.start + self.duration) * rate + 1e-9))
        values = self.spectrogram.values[first:last + 1]
        order = np.argsort(-values.sum(axis=1, dtype=np.float64), kind="stable")
        times: list[float] = []
        for frame in order:  # stops after `count` picks: a few frames, not the song
            if len(times) == count:
                break
            t = (first + frame) / rate - self.start
            if all(abs(t - other) >= 0.25 for other in times):
                times.append(t)
        return np.array(times)

    def driven(self) -> np.ndarray:
        """The harmonics ν the mapping moves: targets of some band with a non-zero
        amplification (every other φ_ν is 1 at all times), ascending.

        Returns
        -------
        (J,) int64, J ≤ B.
        """
        return self.mapping.driven(self.basis.k)

    def morphs(self, times) -> Morphs:
        """The motion at `times` as morph targets (exact: X_φ is linear in φ).

        Parameters
        ----------
        times : (T,) s of the dance.

        Returns
        -------
        Morphs.
        """
        driven = self.driven()
        basis = self.basis
        targets = (basis.harmonics(driven).T[:, :, None]
                   * basis.coefficients[driven][:, None, :] * basis.scale)
        weights = self.phi(times)[:, driven] - 1.0
        # What a player computes, Σ weights·targets, must stay a finite float32 too.
        largest = np.abs(weights).max(initial=0) * np.abs(targets).max(initial=0) * len(driven)
        check_motion(largest + np.abs(self.rest).max(initial=0), self.mapping.name)
        return Morphs(driven, targets, weights)

    def sample_skin(self, times) -> SampleSkin:
        """The motion of a reduced basis at `times` as a skin on its samples (exact).

        Parameters
        ----------
        times : (T,) s of the dance.

        Returns
        -------
        SampleSkin.
        """
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
        times = self.start + np.asarray(times, dtype=np.float64)
        for first, positions in iter_positions(self.basis, self.spectrogram, self.mapping,
                                               times):
            check_motion(positions, self.mapping.name)
            yield first, positions, None
