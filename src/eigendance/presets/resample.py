"""A preset made on one model, fitted to another (docs/design.md#presets).

Harmonics are matched by frequency: harmonic i of a basis vibrates at ω_i = √λ_i; relative to
the model's fundamental (its first ω above 10⁻⁹ of the largest), r_i = ω_i / ω₁ is how many
times faster than the slowest shape change it moves, whatever the model's size. Each harmonic j
of the new model takes the amplification of the old harmonic whose r is nearest in log scale
(the constant harmonic, r = 0, takes the old constant's), and each band that drove old harmonic
ν drives the new harmonic nearest to r_ν (transfer (j + ½)/k). Without the old model's
frequencies the mapping's own rule applies (by normalised index, `Mapping.amplification_for`).
Palettes are matched by mode rank (modes are numbered by frequency): the selected modes the new
rig has keep their amplitude and phase.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from eigendance.music.filter import resample_amplification
from eigendance.music.mapping import Mapping
from eigendance.music.mode_settings import ModeSettings


def relative_frequencies(eigenvalues) -> np.ndarray:
    """r_i = √λ_i / √λ_fundamental, 0 for the constant harmonic(s).

    Parameters
    ----------
    eigenvalues : (K,) ascending eigenvalues λ of a basis.

    Returns
    -------
    (K,) float64 ≥ 0.

    Example
    -------
    >>> relative_frequencies([0.0, 2.0, 6.0, 8.0]).round(3).tolist()
    [0.0, 1.0, 1.732, 2.0]
    """
    omega = np.sqrt(np.clip(np.asarray(eigenvalues, dtype=np.float64), 0.0, None))
    moving = omega > 1e-9 * max(float(omega.max(initial=0.0)), 1e-300)
    if not moving.any():
        return np.zeros_like(omega)
    return np.where(moving, omega / omega[moving][0], 0.0)


def nearest(source, target) -> np.ndarray:
    """For each target frequency, the index of the nearest source frequency (log scale; 0 only
    matches 0).

    Parameters
    ----------
    source : (K,) relative frequencies r of the old model.
    target : (k,) those of the new one.

    Returns
    -------
    (k,) int64 indices into source.
    """
    source, target = np.asarray(source, float), np.asarray(target, float)
    big = 1e6
    log_source = np.where(source > 0, np.log(np.maximum(source, 1e-300)), -big)
    log_target = np.where(target > 0, np.log(np.maximum(target, 1e-300)), -big)
    return np.abs(log_target[:, None] - log_source[None, :]).argmin(axis=1).astype(np.int64)


def resample_mapping(mapping: Mapping, source_eigenvalues, target_eigenvalues) -> Mapping:
    """The mapping for a model with `target_eigenvalues`, matched by harmonic frequency.

    Parameters
    ----------
    mapping : made on a model with `source_eigenvalues`.
    source_eigenvalues : (K,) the old basis's eigenvalues.
    target_eigenvalues : (k,) the new basis's.

    Returns
    -------
    Mapping with k amplification values and its transfer moved to the new harmonics.
    """
    old = relative_frequencies(source_eigenvalues)
    new = relative_frequencies(target_eigenvalues)
    K, k = len(old), len(new)
    amplification = resample_amplification(mapping.amplification, K)[nearest(old, new)]
    driven = mapping.harmonic_indices(K)
    moved = nearest(new, old[driven])
    transfer = (moved + 0.5) / k
    return replace(mapping, transfer=transfer, amplification=amplification)


def resample_palette(modes: ModeSettings | None, count: int) -> ModeSettings | None:
    """A palette for a rig of `count` modes, matched by mode rank.

    Parameters
    ----------
    modes : the palette (None: the default rule, kept).
    count : the new rig's number of modes.

    Returns
    -------
    ModeSettings: the selected modes below `count` with their amplitudes and phases; if none
    is, the lowest modes, as many as were selected (at most `count`).

    Example
    -------
    >>> palette = ModeSettings(np.array([1, 5, 9]), np.array([0.1, 0.2, 0.3]), None)
    >>> resample_palette(palette, 6).selected.tolist()
    [1, 5]
    """
    if modes is None or modes.selected is None:
        return modes
    keep = np.flatnonzero(modes.selected < count)
    selected = modes.selected[keep]
    if not len(keep):
        keep = np.arange(min(len(modes.selected), count))
        selected = keep.copy()

    def cut(values):
        return None if values is None else values[keep]

    return replace(modes, selected=selected, amplitudes=cut(modes.amplitudes),
                   phases=cut(modes.phases))


def fit_mapping(mapping: Mapping, source_eigenvalues, target_eigenvalues=None,
                mode_count: int | None = None) -> Mapping:
    """A preset's mapping for the model it is applied to.

    Parameters
    ----------
    mapping : the preset's mapping.
    source_eigenvalues : the eigenvalues of the model it was made on, or None (unknown).
    target_eigenvalues : those of the mesh it plays on, or None (a rig).
    mode_count : the rig's number of modes, or None (a mesh).

    Returns
    -------
    Mapping; unchanged when nothing is known to match.
    """
    if source_eigenvalues is not None and target_eigenvalues is not None \
            and len(source_eigenvalues) and len(target_eigenvalues):
        mapping = resample_mapping(mapping, source_eigenvalues, target_eigenvalues)
    if mode_count is not None:
        mapping = replace(mapping, modes=resample_palette(mapping.modes, mode_count))
    return mapping
