"""The whole body dances: a rig's skin ripples in its harmonics while its bones sway in their
modes (docs/design.md#surface-of-a-rig).

The skin (every skinned and attached mesh of the rig, welded as `modal.gltf_skin` welds it) gets
its manifold harmonics in the bind pose (`HarmonicBasis.from_mesh`, with its cache; pieces that
touch are coupled as for any mesh, docs/design.md#laplacian). A surface mapping (a
`music.mapping.Mapping`, as a gallery of the harmonic half makes one) drives them:

    d_i(t) = Σ_ν (φ_ν(t) − 1)·u_ν(i)·X̃_ν·scale          (bind pose, the rig's units)

and the displacement is applied in the bind pose *before* skinning, so the ripples ride on the
moving limbs:

    linear blend:  x_i' = Σ_b w_ib T_b(t)(x_i + d_i)
    modal (first order): x_i' = x_i + d_i + Σ_κ c_κ (τ_iκ + ρ_iκ × d_i)

(τ, ρ of `modal.skinning`: x + d moved by the blended first-order twist). A glTF viewer plays the
first exactly: morph targets are applied before the skin.
"""

from __future__ import annotations

import numpy as np

from eigendance.errors import InputError
from eigendance.harmonic.basis import HarmonicBasis
from eigendance.harmonic.laplacian import laplacian_for
from eigendance.harmonic.mesh import Mesh
from eigendance.music.mapping import Mapping
from eigendance.music.spectrogram import Spectrogram

SURFACE_K = 100  # harmonics of a rig's skin by default (the gallery drives the lowest ones)


class SkinHarmonics:
    """The manifold harmonics of a rig's skin in the bind pose.

    Parameters
    ----------
    skeleton : the rig's skeleton (its vertices, faces and name).
    k : harmonics (at most one fewer than the skin's vertices).
    cache : read and write the basis cache (`HarmonicBasis.from_mesh`).

    Attributes: basis (`HarmonicBasis` of the cleaned skin, normalised); vertex_map (n,) the
    cleaned vertex of each skin vertex, −1 for one the clean-up dropped (it does not ripple).

    Example
    -------
    >>> from eigendance.modal.sample_rigs import load_rig
    >>> skin = SkinHarmonics(load_rig("chain"), 12, cache=False)
    >>> moved = skin.displacements(np.ones((2, 12)))      # φ ≡ 1: no ripple
    >>> moved.shape == (2, skin.n, 3), float(np.abs(moved).max())
    (True, 0.0)
    """

    def __init__(self, skeleton, k: int = SURFACE_K, cache: bool = True):
        mesh = Mesh.from_arrays(skeleton.vertices, skeleton.faces, skeleton.name)
        k = int(min(k, mesh.n - 1))
        if k < 1:
            raise InputError(f"{skeleton.name}: the skin has too few vertices for harmonics")
        self.basis = HarmonicBasis.from_mesh(mesh, k, laplacian_for(mesh), cache=cache)
        self.vertex_map = np.asarray(mesh.vertex_map, dtype=np.int64)
        self.n = len(skeleton.vertices)

    @property
    def k(self) -> int:
        """Harmonics k."""
        return self.basis.k

    def scatter(self, values: np.ndarray) -> np.ndarray:
        """Per-vertex values (…, n_clean, 3) of the cleaned skin → (…, n, 3) of the rig's skin
        (0 at a vertex the clean-up dropped).

        Parameters
        ----------
        values : (…, n_clean, 3).

        Returns
        -------
        (…, n, 3).
        """
        kept = self.vertex_map >= 0
        if kept.all():
            return values[..., self.vertex_map, :]
        out = np.zeros((*values.shape[:-2], self.n, 3), dtype=values.dtype)
        out[..., kept, :] = values[..., self.vertex_map[kept], :]
        return out

    def displacements(self, phi) -> np.ndarray:
        """d = U((φ − 1) ⊙ X̃)·scale for filters φ (T, k): the bind-pose ripple.

        Parameters
        ----------
        phi : (T, k).

        Returns
        -------
        (T, n, 3) float64, the rig's units.
        """
        phi = np.atleast_2d(np.asarray(phi, dtype=np.float64))
        if phi.shape[1] != self.k:
            raise InputError(f"the surface filter has {phi.shape[1]} values; the skin has "
                             f"k = {self.k} harmonics")
        return self.scatter(self.basis.displacements(phi) * self.basis.scale)

    def targets(self, harmonics) -> np.ndarray:
        """D_ν = u_ν X̃_νᵀ·scale (J, n, 3): the ripple of each harmonic per unit of φ_ν − 1.

        Parameters
        ----------
        harmonics : (J,) harmonic indices.

        Returns
        -------
        (J, n, 3) float64, the rig's units.
        """
        harmonics = np.asarray(harmonics, dtype=np.int64)
        basis = self.basis
        fields = (basis.harmonics(harmonics).T[:, :, None]
                  * basis.coefficients[harmonics][:, None, :] * basis.scale)
        return self.scatter(fields)


class SurfaceDance:
    """A surface mapping playing on a rig's skin harmonics to a song.

    Parameters
    ----------
    harmonics : the skin's `SkinHarmonics`.
    spectrogram : the song (its bands must be the mapping's).
    mapping : the surface mapping (its `gain` sets the surface's share of the motion).

    Example
    -------
    >>> from eigendance.modal.sample_rigs import load_rig
    >>> skin = SkinHarmonics(load_rig("chain"), 12, cache=False)
    >>> song = Spectrogram.from_samples(np.sin(np.arange(8000) / 3.0), 8000)
    >>> still = Mapping(np.full(64, 0.5), np.zeros(12))     # a ≡ 0: φ ≡ 1
    >>> float(np.abs(SurfaceDance(skin, song, still).displacements([0.0, 0.5])).max())
    0.0
    """

    def __init__(self, harmonics: SkinHarmonics, spectrogram: Spectrogram, mapping: Mapping):
        if mapping.bands != spectrogram.bands:
            raise InputError(f"{mapping.name}: the surface mapping has {mapping.bands} bands; "
                             f"the song's spectrogram has {spectrogram.bands}")
        self.harmonics, self.spectrogram, self.mapping = harmonics, spectrogram, mapping
        self._play = mapping.player(spectrogram)

    def phi(self, times) -> np.ndarray:
        """φ(t) (T, k) of the surface mapping at song times.

        Parameters
        ----------
        times : (T,) s of the song.

        Returns
        -------
        (T, k).
        """
        return self._play(np.asarray(times, dtype=np.float64), self.harmonics.k)

    def driven(self) -> np.ndarray:
        """The harmonics the mapping moves (a band's target with a non-zero amplification).

        Returns
        -------
        (J,) int64, ascending.
        """
        return self.mapping.driven(self.harmonics.k)

    def displacements(self, times) -> np.ndarray:
        """The bind-pose ripple d(t) (T, n, 3) at song times.

        Parameters
        ----------
        times : (T,) s of the song.

        Returns
        -------
        (T, n, 3) float64, the rig's units.
        """
        return self.harmonics.displacements(self.phi(times))


def surface_skinned(skin, coefficients, displacements) -> np.ndarray:
    """Modal skinning of the displaced bind pose: x + d + Σ_κ c_κ (τ_κ + ρ_κ × d).

    Parameters
    ----------
    skin : the rig's `ModalSkin`.
    coefficients : (T, nm).
    displacements : (T, n, 3) bind-pose ripple d.

    Returns
    -------
    (T, n, 3) in the skin's dtype.
    """
    positions = skin.positions(coefficients)
    coefficients = np.atleast_2d(np.asarray(coefficients, dtype=skin.rotation.dtype))
    turn = (coefficients @ skin.rotation).reshape(positions.shape)
    displacements = np.asarray(displacements, dtype=positions.dtype).reshape(positions.shape)
    positions += displacements
    positions += np.cross(turn, displacements)
    return positions


def surface_share(bones: np.ndarray, whole: np.ndarray, rest: np.ndarray) -> float:
    """The surface's share of the motion: RMS over frames and vertices of (whole − bones)
    over the RMS of (whole − rest) — 0 with the surface off, 1 with the bones still.

    Parameters
    ----------
    bones : (T, n, 3) positions with the surface off.
    whole : (T, n, 3) positions with the surface on.
    rest : (n, 3) the rest pose.

    Returns
    -------
    float in [0, ∞) (0 when nothing moves).

    Example
    -------
    >>> rest = np.zeros((1, 3)); bones = np.array([[[3.0, 0, 0]]])
    >>> surface_share(bones, bones + [0, 4.0, 0], rest)       # |(0,4,0)| / |(3,4,0)|
    0.8
    """
    moved = np.sqrt(np.mean(np.sum((np.asarray(whole) - rest) ** 2, axis=-1)))
    ripple = np.sqrt(np.mean(np.sum((np.asarray(whole) - bones) ** 2, axis=-1)))
    return float(ripple / moved) if moved > 0 else 0.0
