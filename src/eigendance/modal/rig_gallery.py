"""A rig's modes as a gallery dancer, and the initial gallery of mode mappings
(docs/design.md#modal-motion).

`RigDancer` lets the music pipeline's gallery (`eigendance.music.gallery`) work on the
palette's modes as it works on a mesh's harmonics; `rig_gallery` is the initial gallery of mode
mappings, calibrated to the song. `Rig.dancer` makes the dancer of a rig.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from eigendance.geometry import bounding_box_diagonal
from eigendance.modal.model import ModalModel
from eigendance.modal.motion import mode_drive, song_calibrated
from eigendance.modal.palette import DANCE_BAND, Palette
from eigendance.modal.skinning import ModalSkin
from eigendance.music.gallery import DEFAULT_GALLERY, initial_gallery
from eigendance.music.mapping import Mapping
from eigendance.music.spectrogram import Spectrogram

QUADRATURE = math.pi / 2  # phase between gallery items next to each other in tempo
# The dances of a rig gallery run free at their own tempo and phase (`rig_gallery`).
GALLERY_TEMPO = "free"


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
    def vertices(self) -> np.ndarray:
        """(n, 3) the skin's vertices at rest, the rig's unit."""
        return self.skin.vertices

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
    """The initial gallery of mode mappings (thesis 6.2.2 on the palette's modes), each item
    with a palette of its own.

    The transfers and amplification intervals of `initial_gallery` (on the dancer's ranked
    modes). The harmonics' intervals are made for k in the hundreds: with a palette of a few
    modes an item's interval may hold no mode its bands reach (or only modes the song's loud
    bands do not reach: a solo trumpet); such an item amplifies all its modes instead (same
    sign), so that every tile moves. Each item's amplification is then calibrated to the song
    (`song_calibrated`): its loudest frame drives its most driven mode at φ = 1, the default
    motion's level (docs/design.md#modal-motion). A few modes give few different transfers
    (one mode: every item the same), so the items also play at their own tempo and phase
    (`varied_palettes`): item 0 the dancer's palette, the others its time scale and phases
    varied. They run free (`modes.tempo` "free", GALLERY_TEMPO): the tempo lock
    (docs/design.md#tempo-lock) would round every time scale to ½, 1 or 2 cycles per beat and
    every phase to π/2 + nπ, and a one-mode rig's dances would be one dance again; the default
    dance (`Rig.mapping`) locks, and the player's "on the beat" switch locks any of them.

    Parameters
    ----------
    dancer : the rig's `RigDancer`.
    spectrogram : the song.
    size : S, 2 … 16.

    Returns
    -------
    list of S mappings, each with its palette (`modes`).
    """
    items = initial_gallery(dancer, spectrogram, size, amplitude=1.0)
    k = len(dancer.frequencies)
    palettes = varied_palettes(dancer.palette, dancer.natural_frequencies, len(items))
    playing = []
    for item, palette in zip(items, palettes, strict=True):
        if not _moves(item, spectrogram, k):
            sign = -1.0 if item.amplification.min() < 0 else 1.0
            item = item.with_genes(item.transfer, np.full(k, sign), item.seed, item.name)
        playing.append(replace(song_calibrated(item, spectrogram, k),
                               modes=replace(palette.to_settings(), tempo=GALLERY_TEMPO)))
    return playing


def _moves(item: Mapping, spectrogram: Spectrogram, k: int) -> bool:
    """Whether the item moves some mode on this song (on a silent song: at full-scale input)."""
    if np.any(spectrogram.values):
        drive = mode_drive(item, spectrogram, spectrogram.times, k, offset=0.0)
        return bool(np.abs(drive).max(initial=0.0) > 1e-12)
    return bool(np.any(item.filter(np.ones(spectrogram.bands), k, offset=0.0)))


def varied_palettes(palette: Palette, frequencies, count: int) -> list[Palette]:
    """`count` palettes of the same modes and amplitudes at their own tempo and phase.

    Item i plays at time scale s·f_i with f_i = lo·(hi/lo)^{u_i}, u_i = frac(u_0 + i·(√5 − 1)/2):
    lo and hi the factors (within [1/2, 2]) that keep every selected frequency s·f·ν inside
    DANCE_BAND, u_0 the exponent of f_0 = 1 (item 0 is `palette`). The golden-ratio sequence
    spreads any number of items evenly (three-gap theorem), so over a song two items drift
    apart in phase; over a short one (4 s) the two nearest in tempo would not, so items sorted
    by tempo alternate between the phases γ and γ + 90°: those neighbours are in quadrature.
    Measured on the built-in rigs (tests/modal/test_rig_gallery.py): no two items of 8 or 16
    correlate beyond 0.76 on a 4-second song, 0.2 on a 30-second one.

    Parameters
    ----------
    palette : the dancer's palette (time scale s, phases γ).
    frequencies : (k,) natural frequencies ν of its selected modes, Hz.
    count : items.

    Returns
    -------
    list of `count` Palettes.
    """
    played = palette.time_scale * np.asarray(frequencies, dtype=float)
    low, high = DANCE_BAND
    lo = max(0.5, low / played.min()) if played.min() > 0 else 1.0
    hi = min(2.0, high / played.max()) if played.max() > 0 else 1.0
    lo, hi = min(lo, 1.0), max(hi, 1.0)  # the palette's own tempo is always allowed
    step = (math.sqrt(5) - 1) / 2
    first = math.log(1.0 / lo) / math.log(hi / lo) if hi > lo else 0.0
    spread = [(first + item * step) % 1.0 for item in range(count)]
    rank = np.argsort(np.argsort(spread, kind="stable"), kind="stable")
    out = [palette]
    for item in range(1, count):
        turn = QUADRATURE * ((rank[item] - rank[0]) % 2)
        out.append(Palette(palette.selected.copy(), palette.amplitudes.copy(),
                           np.mod(palette.phases + turn, 2 * math.pi),
                           float(palette.time_scale * lo * (hi / lo) ** spread[item])))
    return out
