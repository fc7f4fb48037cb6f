"""A rig's modes as a gallery dancer, and the initial gallery of mode mappings
(docs/design.md#modal-motion).

`RigDancer` lets the music pipeline's gallery (`eigendance.music.gallery`) work on the
palette's modes as it works on a mesh's harmonics; `rig_gallery` is the initial gallery of mode
mappings, calibrated to the song. `Rig.dancer` makes the dancer of a rig.
"""

from __future__ import annotations

import numpy as np

from eigendance.geometry import bounding_box_diagonal
from eigendance.modal.model import ModalModel
from eigendance.modal.motion import song_calibrated
from eigendance.modal.palette import Palette
from eigendance.modal.skinning import ModalSkin
from eigendance.music.gallery import DEFAULT_GALLERY, initial_gallery
from eigendance.music.mapping import Mapping
from eigendance.music.spectrogram import Spectrogram


class RigDancer:
    """A rig's selected modes as a `eigendance.music.gallery.Dancer`.

    The k targets are the palette's selected modes, ascending; a filter φ (S, k) moves them
    with coefficients c = φ·μ (their largest excursion, sin = 1), skinned by the modal skin.

    `frequencies` ranks the modes instead of giving their natural frequencies: mode κ of k
    stands at ω_κ = (e_B/e_0)^((κ+1)/k), e the band edges (default 20 Hz–16 kHz), so the
    gallery's direct transfer (thesis 6-4) sends the bands in order onto the modes in order,
    in equal groups. A rig's natural frequencies span a factor of a few and a song's bands a
    factor of 800: 6-4 on the natural frequencies would send nearly every band to the lowest
    mode. `natural_frequencies` are the Hz.

    Parameters
    ----------
    model : the rig's modes.
    skin : its modal skin.
    palette : the modes that dance.
    band_edges : (B+1,) Hz of the song's bands, or None (20 Hz … 16 kHz).
    """

    def __init__(self, model: ModalModel, skin: ModalSkin, palette: Palette, band_edges=None):
        self.model, self.skin, self.palette = model, skin, palette
        self._amplitudes = palette.coefficient_amplitudes(model)
        self._diagonal = bounding_box_diagonal(skin.vertices)
        edges = np.asarray(band_edges if band_edges is not None else (20.0, 16000.0))
        k = len(palette.selected)
        self._ranks = (edges[-1] / edges[0]) ** ((np.arange(k) + 1.0) / k)

    @property
    def frequencies(self) -> np.ndarray:
        """(k,) the selected modes' ranks ω_κ (see the class docstring), ascending."""
        return self._ranks

    @property
    def natural_frequencies(self) -> np.ndarray:
        """(k,) natural frequencies of the selected modes, Hz, ascending."""
        return self.model.frequencies[self.palette.selected]

    @property
    def diagonal(self) -> float:
        """Bounding-box diagonal of the skin at rest, the rig's unit."""
        return self._diagonal

    def displacements(self, phi) -> np.ndarray:
        """(S, k) filters → (S, n, 3) displacements of the skin's vertices.

        Parameters
        ----------
        phi : (S, k) filters.

        Returns
        -------
        (S, n, 3) displacements, the rig's unit.
        """
        phi = np.atleast_2d(np.asarray(phi, dtype=float))
        coefficients = np.zeros((len(phi), self.model.n_modes))
        coefficients[:, self.palette.selected] = phi * self._amplitudes
        return self.skin.positions(coefficients) - self.skin.vertices


def rig_gallery(dancer: RigDancer, spectrogram: Spectrogram,
                size: int = DEFAULT_GALLERY) -> list[Mapping]:
    """The initial gallery of mode mappings (thesis 6.2.2 on the palette's modes).

    The transfers and amplification intervals of `initial_gallery` (on the dancer's ranked
    modes). The harmonics' intervals are made for k in the hundreds: with a palette of a few
    modes an item's interval may hold no mode its bands reach; such an item amplifies all its
    modes instead (same sign), so that every tile moves. Each item's amplification is then
    calibrated to the song (`song_calibrated`): its loudest frame drives its most driven mode
    at φ = 1, the default motion's level (docs/design.md#modal-motion).

    Parameters
    ----------
    dancer : the rig's `RigDancer`.
    spectrogram : the song.
    size : S, 2 … 16.

    Returns
    -------
    list of S mappings.
    """
    items = initial_gallery(dancer, spectrogram, size, amplitude=1.0)
    k = len(dancer.frequencies)
    full = np.ones(spectrogram.bands)
    playing = []
    for item in items:
        if not np.any(item.filter(full, k, offset=0.0)):
            sign = -1.0 if item.amplification.min() < 0 else 1.0
            item = item.with_genes(item.transfer, np.full(k, sign), item.seed, item.name)
        playing.append(song_calibrated(item, spectrogram, k))
    return playing
