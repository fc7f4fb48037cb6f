"""The initial gallery: S mappings to choose from before any breeding (docs/design.md#gallery).

A gallery works on any *dancer* — the harmonics of a mesh or the vibration modes of a rig —
through the `Dancer` protocol: its frequencies (ascending) and the displacements a filter gives.
Sizes follow one rule, shared by the library, the command line, the server and the page:
`check_gallery_size`.
"""

from __future__ import annotations

from typing import Protocol

import numpy as np

from eigendance.errors import InputError
from eigendance.music.mapping import Mapping, filters

MIN_GALLERY, MAX_GALLERY, DEFAULT_GALLERY = 2, 16, 8
TARGET_MOTION = 0.05  # strongest initial item: RMS displacement / bounding-box diagonal
CALIBRATIONS = ("strongest", "each")


class Dancer(Protocol):
    """What a gallery needs of a model: k frequencies and the motion of a filter."""

    @property
    def frequencies(self) -> np.ndarray:
        """(k,) ascending: √λ of a mesh's harmonics, or a rig's natural frequencies."""

    @property
    def diagonal(self) -> float:
        """Bounding-box diagonal of the rest shape, in the units of `displacements`."""

    def displacements(self, phi: np.ndarray) -> np.ndarray:
        """(S, k) filters → (S, n, 3) displacements of the n vertices from the rest shape."""


def check_gallery_size(size) -> int:
    """The gallery size as an int; InputError unless it is an integer in [MIN, MAX]."""
    if isinstance(size, bool) or not isinstance(size, int | np.integer) or \
            not MIN_GALLERY <= size <= MAX_GALLERY:
        raise InputError(f"a gallery has {MIN_GALLERY} to {MAX_GALLERY} items; got {size!r}")
    return int(size)


def initial_indices(frequencies, band_edges, positions=None) -> np.ndarray:
    """ν_ini at (possibly fractional) band positions x (default 0 … B−1), int64.

    ν_ini(x) = the smallest ν with f_x / f_{B−1} ≤ ω_ν / ω_{k−1} (thesis 6-4 with ω = √λ),
    where f_x is the geometric centre of band x. Band edges are geometric, so
    f_x / f_{B−1} = (e_B / e_0)^((x − B + 1)/B) exactly, which also defines f_x between bands
    (the gallery's t(εξ)).
    """
    frequencies = np.maximum(np.asarray(frequencies, dtype=np.float64), 0.0)
    band_edges = np.asarray(band_edges, dtype=np.float64)
    bands = len(band_edges) - 1
    if positions is None:
        positions = np.arange(bands, dtype=np.float64)
    if not frequencies[-1] > 0:
        raise InputError("the model has no positive frequency; cannot build transfers")
    ratio = (band_edges[-1] / band_edges[0]) ** ((np.asarray(positions) - bands + 1) / bands)
    levels = frequencies / frequencies[-1]  # non-decreasing, ends at 1
    index = np.searchsorted(levels, ratio, side="left")
    return np.minimum(index, len(frequencies) - 1).astype(np.int64)


def direct_transfer(frequencies, band_edges, positions=None) -> np.ndarray:
    """t_ini = (ν_ini + ½)/k: low sounds drive low harmonics (thesis 6-4)."""
    k = len(frequencies)
    return (initial_indices(frequencies, band_edges, positions) + 0.5) / k


def reversed_transfer(frequencies, band_edges, positions=None) -> np.ndarray:
    """t_rev = (k − 1 − ν_ini + ½)/k: low sounds drive high harmonics."""
    k = len(frequencies)
    return (k - 1 - initial_indices(frequencies, band_edges, positions) + 0.5) / k


def gallery_epsilons(size: int) -> np.ndarray:
    """The ⌈S/2⌉ compressions ε of the transfers: 0, 1, 2/S, 4/S, …"""
    count = (size + 1) // 2
    return np.array([0.0, 1.0, *[2 * i / size for i in range(1, count - 1)]])[:count]


def gallery_intervals(size: int) -> np.ndarray:
    """The ⌈S/2⌉ normalised amplification intervals I_ε = [ε², (ε + 2/S)²], ε = 0, 2/S, …"""
    eps = 2 * np.arange((size + 1) // 2) / size
    return np.stack([eps ** 2, (eps + 2 / size) ** 2], axis=1)


def initial_gallery(dancer: Dancer, spectrogram, size: int = DEFAULT_GALLERY,
                    amplitude: float | None = None,
                    calibration: str = "strongest") -> list[Mapping]:
    """The S items of the initial gallery (thesis 6.2.2).

    Parameters
    ----------
    dancer : a `HarmonicBasis` (or any `Dancer`).
    spectrogram : a `Spectrogram`, or its band edges (B+1,) Hz.
    size : S, checked by `check_gallery_size` (odd sizes too).
    amplitude : M_a; by default calibrated (see below).
    calibration : "strongest" or "each" (see below).

    Returns
    -------
    S mappings. Item i < ⌈S/2⌉: transfer t_ini(ε_i·ξ), amplification +M_a on interval I_i,
    0 elsewhere; the other ⌊S/2⌋ items: t_rev(ε_i·ξ) and −M_a on I_i. ε_i = 0, 1, 2/S, 4/S, …;
    I_i = [(2i/S)², ((2i+2)/S)²] of the normalised harmonic range: harmonic ν is in I_i when
    its cell centre (ν + ½)/k lies in [lower, upper) (the last one closed).
    M_a is calibrated so that the strongest item at full-scale input (g̃ ≡ 1) moves the
    vertices by TARGET_MOTION (5%) of the bounding-box diagonal, RMS. calibration="each" gives
    every item that moves at all its own M_a, so that each moves by 5%.

    Example
    -------
    >>> import trimesh
    >>> from eigendance.harmonic.basis import HarmonicBasis
    >>> from eigendance.harmonic.mesh import Mesh
    >>> from eigendance.music.spectrogram import band_edges
    >>> sphere = trimesh.creation.icosphere(2)
    >>> basis = HarmonicBasis.from_mesh(Mesh.from_arrays(sphere.vertices, sphere.faces), 30,
    ...                                 cache=False)
    >>> gallery = initial_gallery(basis, band_edges(64, 44100), size=5)
    >>> len(gallery), gallery[0].bands, len(gallery[0].amplification)
    (5, 64, 30)
    """
    if calibration not in CALIBRATIONS:
        raise InputError(f"unknown calibration '{calibration}' (expected one of "
                         f"{', '.join(CALIBRATIONS)})")
    size = check_gallery_size(size)
    edges = np.asarray(getattr(spectrogram, "band_edges", spectrogram), dtype=np.float64)
    bands = len(edges) - 1
    frequencies = dancer.frequencies
    k = len(frequencies)
    xi = np.arange(bands, dtype=np.float64)
    centres = (np.arange(k) + 0.5) / k
    intervals = gallery_intervals(size)
    epsilons = gallery_epsilons(size)
    transfers, shapes = [], []
    for sign, transfer, count in ((1.0, direct_transfer, (size + 1) // 2),
                                  (-1.0, reversed_transfer, size // 2)):
        for i, eps in enumerate(epsilons[:count]):
            transfers.append(transfer(frequencies, edges, eps * xi))
            lower, upper = intervals[i]
            last = i == len(intervals) - 1
            inside = (centres >= lower) & ((centres <= upper) if last else (centres < upper))
            shapes.append(sign * inside.astype(np.float64))
    if amplitude is not None:
        amplitudes = np.full(size, float(amplitude))
    else:
        motion = full_scale_motion(dancer, [Mapping(t, a) for t, a in
                                            zip(transfers, shapes, strict=True)])
        if not motion.max() > 1e-12:
            raise InputError("no initial gallery item moves this model: it has too few "
                             "harmonics", remedy={"k": 2 * k})
        target = TARGET_MOTION * dancer.diagonal
        if calibration == "strongest":
            amplitudes = np.full(size, target / motion.max())
        else:  # items that cannot move (transfer and amplification never meet) keep 0 · shape
            amplitudes = np.where(motion > 1e-9 * motion.max(),
                                  target / np.maximum(motion, 1e-300), 0.0)
    return [Mapping(t, m * a, None, f"gallery item {i}")
            for i, (t, a, m) in enumerate(zip(transfers, shapes, amplitudes, strict=True))]


def full_scale_motion(dancer: Dancer, mappings: list[Mapping]) -> np.ndarray:
    """RMS vertex displacement of each mapping at full-scale input g̃ ≡ 1 (S,)."""
    phi = filters(mappings, np.ones(mappings[0].bands), len(dancer.frequencies))  # (S, k)
    moved = dancer.displacements(phi)  # (S, n, 3)
    return np.sqrt((moved ** 2).sum(axis=2).mean(axis=1))


def strongest_item(dancer: Dancer, spectrogram, size: int = DEFAULT_GALLERY) -> Mapping:
    """The initial-gallery item that moves the model most at full-scale input (the default)."""
    gallery = initial_gallery(dancer, spectrogram, size, calibration="strongest")
    return gallery[int(np.argmax(full_scale_motion(dancer, gallery)))]
