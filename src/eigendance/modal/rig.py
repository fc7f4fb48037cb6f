"""A rig: one object built once from a skeleton and queried by every caller
(docs/design.md#rig).

As potpourri3d's solver classes are built once and then asked, a `Rig` does the preprocessing
of the thesis's Table 7.2 once — the modal analysis, and (on first use) the modal-skinning
precomputation — and answers everything about the rig's motion: the palette a mapping plays,
the mode coefficients for a song, the bodies' poses and transforms, the skin's positions and
normals by modal skinning or by linear blend skinning, the arrays of an animation file, the
rest bone matrices, which joints close a loop and each joint's default stiffness. The command
line (`animate-rig`, `export`, `render`), the exports (`export.dance.rig_dance`) and the server
(`server.rigs`, `server.binary.rig_bundle`) all ask it, so rig motion is made one way. Edits
(`with_stiffness`, `rotate_joint`) give a new Rig and keep this one.
"""

from __future__ import annotations

import numpy as np

from eigendance.errors import InputError
from eigendance.geometry import vertex_normals
from eigendance.modal.floor import SkinFloor
from eigendance.modal.model import ModalModel
from eigendance.modal.motion import (
    body_poses,
    body_transforms,
    mapping_palette,
    rig_coefficients,
    rig_mapping,
)
from eigendance.modal.palette import Palette, default_palette
from eigendance.modal.rig_gallery import RigDancer
from eigendance.modal.skeleton import Skeleton
from eigendance.modal.skinning import ModalSkin, linear_blend_skinning
from eigendance.modal.surface import SURFACE_K, SkinHarmonics, surface_skinned
from eigendance.music.mapping import Mapping
from eigendance.music.spectrogram import Spectrogram

SKINNINGS = ("modal", "lbs")
FRAME_CHUNK = 64  # frames skinned per batch (bounds the memory of linear blend skinning)


class Rig:
    """A skeleton with a skin, its vibration modes and everything asked of its motion.

    Parameters
    ----------
    skeleton : bodies, joints and the skin (vertices, faces, weights).
    dtype : the modal skin's precision: float32 (as a GPU plays it, the default) or float64
        (a reference).

    Attributes: skeleton; model (`ModalModel`, the vibration modes, with the skin's floor); skin
    (`ModalSkin`, made with the rig when it has a skin and modes); palette (the default palette,
    None without vibration modes).

    Example
    -------
    >>> from eigendance.modal.sample_rigs import load_rig
    >>> rig = Rig(load_rig("hand"))
    >>> moved = rig.positions(rig.coefficients(None, None, [0.0, 0.5]))
    >>> moved.shape == (2, len(rig.skeleton.vertices), 3)
    True
    """

    def __init__(self, skeleton: Skeleton, dtype=np.float32):
        self.skeleton = skeleton
        self.model = ModalModel.from_skeleton(skeleton)
        self.dtype = np.dtype(dtype)
        self._skin: ModalSkin | None = None
        self._surfaces: dict[int, SkinHarmonics] = {}
        if self.model.n_modes and skeleton.vertices is not None and len(skeleton.vertices):
            # The palette keeps the skin above the floor (docs/design.md#the-floor).
            self.model.floor = SkinFloor.of_skin(self.skin.vertices, self.skin.displacement)
        self.palette: Palette | None = default_palette(self.model) if self.model.n_modes \
            else None

    @classmethod
    def from_skeleton(cls, skeleton: Skeleton, dtype=np.float32) -> Rig:
        """Modal analysis of a skeleton with a skin (`Rig(skeleton, dtype)`).

        Parameters
        ----------
        skeleton : bodies, joints and skin.
        dtype : the modal skin's precision (float32 by default, float64 for a reference).

        Returns
        -------
        Rig.

        Example
        -------
        >>> from eigendance.modal.sample_rigs import sample_rig
        >>> rig = Rig.from_skeleton(sample_rig("loop16"))
        >>> rig.model.n_modes, rig.skin.displacement.shape      # thesis Table 7.2: 13 modes
        (13, (13, 4608))
        """
        return cls(skeleton, dtype)

    # --- what the rig holds --------------------------------------------------------------------
    @property
    def skin(self) -> ModalSkin:
        """The modal skinning of the skin (`ModalSkin`), precomputed on first use and kept."""
        if self._skin is None:
            self._skin = ModalSkin(self.model, self.skeleton.vertices, self.skeleton.weights,
                                   self.dtype, self.skeleton.name)
        return self._skin

    def surface(self, k: int = SURFACE_K, cache: bool = True) -> SkinHarmonics:
        """The skin's manifold harmonics in the bind pose (`modal.surface`), made on first use
        and kept (the basis also goes to the disk cache).

        Parameters
        ----------
        k : harmonics (at most the skin's vertices − 1).
        cache : read and write the basis cache.

        Returns
        -------
        SkinHarmonics.
        """
        if k not in self._surfaces:
            self._surfaces[k] = SkinHarmonics(self.skeleton, k, cache)
        return self._surfaces[k]

    @property
    def rest_bones(self) -> np.ndarray:
        """(n_b, 4, 4) the bodies' frames at rest, [R_b | c_b] (body frame → world): where a
        glTF joint or a three.js bone sits."""
        bones = np.zeros((self.model.n_bodies, 4, 4))
        bones[:, :3, :3] = self.model.body_rotations
        bones[:, :3, 3] = self.model.body_centers
        bones[:, 3, 3] = 1.0
        return bones

    @property
    def closes_loop(self) -> np.ndarray:
        """(n_j,) bool: the joints whose two bodies stay connected without them (neither side
        can turn alone)."""
        return np.array([self.skeleton.joint_sides(index) is None
                         for index in range(len(self.skeleton.joints))], dtype=bool)

    @property
    def default_stiffness(self) -> list[np.ndarray]:
        """Each joint's stiffness by the default rule ("auto"), one value per free row."""
        return self.skeleton.automatic_stiffnesses()

    # --- motion ------------------------------------------------------------------------------
    def palette_of(self, mapping: Mapping | None) -> Palette:
        """The palette a mapping plays on this rig: its `modes`, completed by the default rule.

        Parameters
        ----------
        mapping : a mapping, or None (the default palette).

        Returns
        -------
        Palette (`modal.palette`).
        """
        return mapping_palette(self.model, mapping)

    def mapping(self, spectrogram: Spectrogram | None, mapping: Mapping | None = None,
                **overrides) -> Mapping:
        """The complete mapping the rig plays, its palette resolved (`modal.motion.rig_mapping`).

        Parameters
        ----------
        spectrogram : the song, or None.
        mapping : what to play (None: the default mapping for the song).
        **overrides : selected, amplitude, time_scale, offset, bands (`rig_mapping`).

        Returns
        -------
        Mapping with every palette field explicit.
        """
        return rig_mapping(self.model, spectrogram, mapping, **overrides)

    def coefficients(self, spectrogram: Spectrogram | None, mapping: Mapping | None,
                     times) -> np.ndarray:
        """The mode coefficients of the rig dancing to a song (`modal.motion.rig_coefficients`).

        Parameters
        ----------
        spectrogram : the song, or None (music off: φ ≡ 1).
        mapping : the mapping (None: the default one).
        times : (T,) song time, s.

        Returns
        -------
        (T, nm) coefficients c_κ(t).
        """
        return rig_coefficients(self.model, spectrogram, mapping, times)

    def body_poses(self, coefficients) -> tuple[np.ndarray, np.ndarray]:
        """World rotations and centres of every body for coefficients c.

        Parameters
        ----------
        coefficients : (T, nm).

        Returns
        -------
        rotations (T, n_b, 3, 3) and centres (T, n_b, 3), the skeleton's units.
        """
        return body_poses(self.model, coefficients)

    def body_transforms(self, coefficients) -> np.ndarray:
        """World transforms taking rest-pose points to posed points, for coefficients c.

        Parameters
        ----------
        coefficients : (T, nm).

        Returns
        -------
        (T, n_b, 4, 4).
        """
        return body_transforms(self.model, coefficients)

    def skinned(self, coefficients, skinning: str = "modal", normals=None, surface=None):
        """The skin moved by coefficients c: modal skinning (first order, as the page plays
        it) or linear blend skinning of the exact body transforms (what a glTF skin plays),
        with the surface's ripple d added in the bind pose before skinning (`modal.surface`).

        Parameters
        ----------
        coefficients : (T, nm).
        skinning : "modal" or "lbs".
        normals : (n, 3) rest normals to turn with the skin, or None. With a surface the
            normals are those of the moved skin (area-weighted, `geometry.vertex_normals`).
        surface : (T, n, 3) bind-pose displacements d (the rig's units; `SurfaceDance`), or
            None.

        Returns
        -------
        positions (T, n, 3) in the rig's `dtype` for "modal", float64 for "lbs"; with
        `normals`, also the unit normals (T, n, 3).
        """
        if skinning not in SKINNINGS:
            raise InputError(f"skinning must be modal or lbs, got {skinning!r}")
        skeleton = self.skeleton
        if surface is not None:
            if skinning == "lbs":
                positions = linear_blend_skinning(skeleton.vertices, skeleton.weights,
                                                  self.body_transforms(coefficients),
                                                  displacements=surface)
            else:
                positions = surface_skinned(self.skin, coefficients, surface)
            if normals is None:
                return positions
            return positions, np.stack([vertex_normals(frame, skeleton.faces, [0.0, 0, 1])
                                        for frame in positions])
        if skinning == "lbs":
            return linear_blend_skinning(skeleton.vertices, skeleton.weights,
                                         self.body_transforms(coefficients), normals)
        positions = self.skin.positions(coefficients)
        return positions if normals is None else (positions,
                                                  self.skin.normals(coefficients, normals))

    def positions(self, coefficients, skinning: str = "modal", surface=None) -> np.ndarray:
        """The skin's positions for coefficients c (`skinned` without normals).

        Parameters
        ----------
        coefficients : (T, nm).
        skinning : "modal" or "lbs".
        surface : (T, n, 3) the surface's bind-pose displacements (the rig's units), or None.

        Returns
        -------
        (T, n, 3) positions, the skeleton's units.

        Example
        -------
        >>> from eigendance.modal.sample_rigs import load_rig
        >>> rig = Rig(load_rig("chain"))
        >>> still = np.zeros((1, rig.model.n_modes))                # the bones at rest
        >>> lift = np.zeros((1, len(rig.skeleton.vertices), 3)); lift[..., 2] = 0.01
        >>> moved = rig.positions(still, "lbs", surface=lift) - rig.skeleton.vertices
        >>> bool(np.allclose(moved, lift))      # at rest the skin moves by the ripple alone
        True
        """
        return self.skinned(coefficients, skinning, surface=surface)

    def animation(self, times, coefficients, palette: Palette, skinning: str = "modal",
                  progress=None, surface=None) -> dict:
        """The arrays of the rig animation file (docs/design.md#animation-file).

        Parameters
        ----------
        times : (T,) s, as the file stores them.
        coefficients : (T, nm) at those frames (`coefficients`).
        palette : the palette that made them (stored with them).
        skinning : "modal" or "lbs".
        progress : optional callable(frames done).
        surface : optional callable(first, stop) → (stop − first, n, 3), the surface's
            bind-pose displacements of those frames (`SurfaceDance.displacements`).

        Returns
        -------
        {"times", "faces", "positions" (T, n, 3) float32, "rest_vertices", "weights",
        "body_names", "body_rotations", "body_centers", "body_transforms", "coefficients",
        "modes", "amplitudes", "phases", "time_scale", "frequencies", "skinning"}.
        """
        times = np.asarray(times, dtype=float)
        coefficients = np.asarray(coefficients, dtype=float)
        skeleton, model = self.skeleton, self.model
        rotations, centers = self.body_poses(coefficients)
        transforms = body_transforms(model, poses=(rotations, centers))
        positions = np.empty((len(times), len(skeleton.vertices), 3), dtype=np.float32)
        for start in range(0, len(times), FRAME_CHUNK):
            stop = min(start + FRAME_CHUNK, len(times))
            ripple = None if surface is None else surface(start, stop)
            positions[start:stop] = self.positions(coefficients[start:stop], skinning, ripple)
            if progress is not None:
                progress(stop)
        return {"times": times, "faces": skeleton.faces.astype(np.int64), "positions": positions,
                "rest_vertices": skeleton.vertices,
                "weights": skeleton.weights.astype(np.float32),
                "body_names": np.array(model.body_names, dtype=str),
                "body_rotations": rotations, "body_centers": centers,
                "body_transforms": transforms.astype(np.float32), "coefficients": coefficients,
                "modes": palette.selected.astype(np.int64), "amplitudes": palette.amplitudes,
                "phases": palette.phases, "time_scale": np.float64(palette.time_scale),
                "frequencies": model.frequencies, "skinning": np.array(skinning)}

    def dancer(self, palette: Palette | None = None, band_edges=None) -> RigDancer:
        """The palette's modes as a gallery `Dancer` (`modal.rig_gallery`).

        Parameters
        ----------
        palette : the modes that dance (default: the rig's default palette).
        band_edges : (B+1,) Hz, the song's bands (default 20 Hz … 16 kHz).

        Returns
        -------
        RigDancer.
        """
        return RigDancer(self.model, self.skin, palette or self.palette, band_edges)

    # --- edits -----------------------------------------------------------------------------------
    def with_stiffness(self, values: dict, scale: float = 1.0) -> Rig:
        """A new rig with new joint stiffness (`Skeleton.with_stiffness`).

        Parameters
        ----------
        values : {joint name or index: number | [one per free row] | "auto"}.
        scale : then multiplies every joint's stiffness.

        Returns
        -------
        Rig, analysed anew; this one is unchanged.
        """
        return Rig(self.skeleton.with_stiffness(values, scale), self.dtype)

    def rotate_joint(self, key, rotation) -> Rig:
        """A new rig in a new rest pose: one side of a joint turned (`Skeleton.rotate_joint`).

        Parameters
        ----------
        key : the joint's name or index.
        rotation : (3,) rotation vector, radians, world coordinates.

        Returns
        -------
        Rig, analysed anew; this one is unchanged.
        """
        return Rig(self.skeleton.rotate_joint(key, rotation), self.dtype)
