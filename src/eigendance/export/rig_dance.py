"""A rig's dance, as the exports read it (docs/design.md#exports): `RigDance`, a `modal.rig.Rig`
moving in its modes — bodies by world transforms T_b(t) (4×4, rest pose → posed), the skin by
linear blend skinning x′ = Σ_b w_ib T_b(t)x (exactly what a glTF skin plays) or by modal
skinning (docs/design.md#skinning), both asked of the rig — and `rig_dance`, which makes one.
`pose(times)` gives the transforms and mode coefficients: the one place rig motion enters the
exports. With a `surface` (`modal.surface.SurfaceDance`) the skin also ripples in its
harmonics, added in the bind pose before skinning: exactly morph targets under a skin. The
base, the window and the harmonic dance: `export.dance`.
"""

from __future__ import annotations

import os
from collections.abc import Callable

import numpy as np

from eigendance.errors import InputError
from eigendance.export.dance import MAX_TURN, Dance, Morphs, check_motion
from eigendance.modal.rig import SKINNINGS, Rig
from eigendance.music.mapping import Mapping
from eigendance.music.spectrogram import Spectrogram

RIG_CHUNK = 64  # frames skinned per batch


class RigDance(Dance):
    """A rig's skin moved by its modes (docs/design.md#skinning), asked of its `Rig`.

    Parameters
    ----------
    rig : the rig (its skeleton's skin, its modes, its skinning).
    coefficients : song times (T,) → mode coefficients c (T, nm), e.g. `Rig.coefficients` of a
        song and a mapping.
    duration : seconds (the song's).
    skinning : "modal" (first order, as the page plays it) or "lbs" (linear blend skinning of
        the exact body transforms, what a glTF skin plays).
    audio, name : as for `HarmonicDance`.
    info : more to write in the files' metadata.
    surface : the skin's ripple (`modal.surface.SurfaceDance`), or None.

    The skin's look (`assets.Appearance`) is the skeleton's.
    """

    def __init__(self, rig: Rig, coefficients: Callable, duration: float,
                 skinning: str = "modal", audio: str | os.PathLike | None = None,
                 name: str = "dance", info=None, surface=None):
        if skinning not in SKINNINGS:
            raise InputError(f"skinning must be modal or lbs, got {skinning!r}")
        skeleton = rig.skeleton
        self.rig, self.coefficients, self.skinning = rig, coefficients, skinning
        self.rest = np.asarray(skeleton.vertices, dtype=np.float64)
        self.faces = np.asarray(skeleton.faces, dtype=np.int64)
        weights = skeleton.weights
        self.weights = weights.toarray() if hasattr(weights, "toarray") else \
            np.asarray(weights, dtype=np.float64)
        self.rest_frames = rig.rest_bones
        self.body_names = [str(name) for name in rig.model.body_names]
        self.duration = self.length = float(duration)
        self.audio = None if audio is None else os.fspath(audio)
        self.name = name
        self.info = {"kind": "rig", "skinning": skinning, **(info or {})}
        self.appearance = getattr(skeleton, "appearance", None)
        self.surface = surface
        if surface is not None:
            self.info["surface"] = {"k": surface.harmonics.k,
                                    "mapping": surface.mapping.to_json()}

    def ripple(self, times):
        """The surface's bind-pose displacements (T, n, 3) at the dance's times, or None.

        Parameters
        ----------
        times : (T,) s of the dance.

        Returns
        -------
        (T, n, 3) float64 or None (no surface).
        """
        if self.surface is None:
            return None
        return self.surface.displacements(self.start + np.asarray(times, dtype=float))

    def morphs(self, times) -> Morphs:
        """The surface's ripple at `times` as morph targets, applied before the skin (exact:
        d is linear in φ).

        Parameters
        ----------
        times : (T,) s of the dance.

        Returns
        -------
        Morphs (in the bind pose, the rig's units).
        """
        driven = self.surface.driven()
        weights = self.surface.phi(self.start + np.asarray(times, dtype=float))[:, driven] - 1
        targets = self.surface.harmonics.targets(driven)
        largest = np.abs(weights).max(initial=0) * np.abs(targets).max(initial=0) * len(driven)
        check_motion(largest + np.abs(self.rest).max(initial=0), self.surface.mapping.name)
        return Morphs(driven, targets, weights)

    def pose(self, times) -> tuple[np.ndarray, np.ndarray]:
        """The body transforms and mode coefficients at the dance's times.

        Parameters
        ----------
        times : (T,) s of the dance (the song's times start + t).

        Returns
        -------
        transforms (T, n_b, 4, 4) from the rest pose, coefficients (T, nm).
        """
        moving = self.coefficients(self.start + np.asarray(times, dtype=float))
        return self.rig.body_transforms(moving), moving

    def frames(self, times):
        times = np.asarray(times, dtype=np.float64)
        normals = self.rest_normals()
        for first in range(0, len(times), RIG_CHUNK):
            moving = self.coefficients(self.start + times[first:first + RIG_CHUNK])
            positions, turned = self.rig.skinned(moving, self.skinning, normals,
                                                 self.ripple(times[first:first + RIG_CHUNK]))
            if self.surface is not None:
                check_motion(positions, self.surface.mapping.name)
            yield first, positions.astype(np.float32), turned.astype(np.float32)

    def blend_positions(self, times) -> np.ndarray:
        """(T, n, 3) linear blend skinning at `times`: what a glTF skin plays.

        Parameters
        ----------
        times : (T,) s of the dance.

        Returns
        -------
        (T, n, 3) float64.
        """
        return self.rig.positions(self.pose(times)[1], "lbs", self.ripple(times))


def rig_dance(rig: Rig, spectrogram: Spectrogram | None, mapping: Mapping | None,
              skinning: str = "modal", audio=None, name: str = "dance",
              duration: float | None = None, surface=None) -> RigDance:
    """A rig dancing to a song, as `eigendance animate-rig` moves it.

    Parameters
    ----------
    rig : the rig with its skin (`modal.rig.Rig`).
    spectrogram : the song, or None (music off: φ ≡ 1).
    mapping : the mapping it plays (`Rig.mapping` resolves one), or None for the default.
    skinning : "modal" or "lbs".
    audio, name : the song's file (or None) and how files call the dance.
    duration : seconds (default: the song's; 4 s without a song).
    surface : the skin's ripple (`modal.surface.SurfaceDance`), or None.

    Returns
    -------
    RigDance whose `pose(times)` gives the body transforms and c_κ(t) (`Rig.coefficients`).
    """
    if duration is None:
        duration = spectrogram.duration if spectrogram is not None else 4.0

    def coefficients(times):
        moving = rig.coefficients(spectrogram, mapping, times)
        with np.errstate(all="ignore"):  # bounds a body's turn (radians) and shift (units)
            largest = (np.abs(moving) @ np.abs(rig.model.modes).max(axis=0)).max(initial=0)
        if not (np.isfinite(moving).all() and largest <= MAX_TURN):
            name = mapping.name if mapping is not None else "the rig's mapping"
            raise InputError(f"{name}: the motion it asks for turns or moves a body by more "
                             f"than {MAX_TURN:g}; lower its amplification")
        return moving

    moving_modes = np.flatnonzero(np.abs(coefficients(np.linspace(0, duration, 64))).max(axis=0))
    info = {"modes": [int(m) for m in moving_modes],
            "frequencies_hz": [float(rig.model.frequencies[m]) for m in moving_modes]}
    return RigDance(rig, coefficients, duration, skinning, audio, name, info, surface)
