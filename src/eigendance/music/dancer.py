"""Dancers and how much a mapping moves them on a song (docs/design.md#gallery).

A gallery works on any *dancer* — the harmonics of a mesh, the vibration modes of a rig —
through the `Dancer` protocol. The Gram matrix G_νμ = mean over the vertices of
⟨D_ν(x), D_μ(x)⟩ (`motion_gram`) gives the RMS displacement √(wᵀ G w) of the music's share
w = φ − b of any filter, so a gallery is measured on every frame of a song without forming a
position: `gallery_motion` (m, the peak, the main harmonic range of each item),
`gallery_correlations` (how alike two items move), `full_scale_motion` (the most the music can
move an item).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol

import numpy as np

from eigendance.geometry import cross
from eigendance.music.filter import filters
from eigendance.music.mapping import Mapping

CALIBRATION_FRAMES = 6000  # at most this many evenly spaced frames of the song are measured
MAIN_SHARE = 0.9  # the "main harmonic range" of an item holds this share of its motion energy
# Edges shorter than this fraction of the diagonal count as this long in `edge_strain` (a
# degenerate edge would otherwise strain without bound under any motion).
STRAIN_FLOOR = 1e-3


class Dancer(Protocol):
    """What a gallery needs of a model: its frequencies and the motions filters give it.

    Displacements must be affine in φ: a filter moves the model by Σ_ν (φ_ν − b) D_ν,
    D_ν (n, 3) the displacement field of target ν (harmonics: b = 1 and D_ν = u_ν X̃_νᵀ; a rig's
    modes: b = 0). A dancer may also give `motion_gram(targets)` — (T,) → (T, T), the mean over
    the vertices of ⟨D_ν(x), D_μ(x)⟩ — without forming positions (`HarmonicBasis` does); else
    `motion_gram` below forms it from the displacements.

    Parameters
    ----------
    A protocol: any object with these attributes and methods (`HarmonicBasis`, `RigDancer`).
    """

    @property
    def frequencies(self) -> np.ndarray:
        """(k,) ascending: √λ of a mesh's harmonics, or a rig's (ranked) modes."""

    @property
    def diagonal(self) -> float:
        """Bounding-box diagonal of the rest shape, in the units of the displacements."""

    def displacements(self, phi) -> np.ndarray:
        """(S, k) filters → (S, n, 3) displacements of the n vertices from the rest shape.

        Parameters
        ----------
        phi : (S, k) filters.

        Returns
        -------
        (S, n, 3).
        """


def motion_gram(dancer: Dancer, targets) -> np.ndarray:
    """G_νμ = mean over the vertices of ⟨D_ν(x), D_μ(x)⟩ for `targets` (T,) → (T, T): the
    dancer's own when it has one, else from its displacements, D_ν = d(e_ν) − d(0).

    Parameters
    ----------
    dancer : the model.
    targets : (T,) target indices.

    Returns
    -------
    (T, T) in the displacements' units squared.
    """
    targets = np.asarray(targets, dtype=np.int64)
    own = getattr(dancer, "motion_gram", None)  # optional in the protocol: a fast path
    if own is not None:
        return own(targets)
    filters_ = np.zeros((len(targets) + 1, len(dancer.frequencies)))
    filters_[np.arange(1, len(targets) + 1), targets] = 1.0
    moved = dancer.displacements(filters_)
    fields = (moved[1:] - moved[0]).reshape(len(targets), -1)
    return fields @ fields.T / moved.shape[1]


def song_times(spectrogram) -> np.ndarray:
    """The times of at most CALIBRATION_FRAMES evenly spaced frames of the song.

    Parameters
    ----------
    spectrogram : the song.

    Returns
    -------
    (F,) s, ascending.
    """
    count = len(spectrogram.values)
    frames = np.arange(count) if count <= CALIBRATION_FRAMES else \
        np.linspace(0, count - 1, CALIBRATION_FRAMES).round().astype(int)
    return frames / spectrogram.rate


def frame_motion(w: np.ndarray, gram: np.ndarray) -> np.ndarray:
    """RMS displacement of each frame: √(wᵀ G w) for weights w (F, T) on T targets → (F,).

    Parameters
    ----------
    w : (F, T) φ − b on the targets.
    gram : (T, T) their Gram matrix.

    Returns
    -------
    (F,) in the displacements' units.
    """
    return np.sqrt(np.maximum(((w @ gram) * w).sum(axis=1), 0.0))


def edge_strain(dancer: Dancer, phi) -> np.ndarray:
    """The largest strain of any edge of the dancer's surface under each filter (S, k) → (S,):
    max over the edges ij of |D_i − D_j| / |x_i − x_j| (the linearised change of the edge's
    length over its rest length, rest lengths floored at STRAIN_FLOOR of the diagonal); zeros
    for a dancer without `vertices` and `faces` (a rig's modes).

    Parameters
    ----------
    dancer : the model.
    phi : (S, k) filters.

    Returns
    -------
    (S,) dimensionless: 1 lets an edge collapse to a point or double its length.
    """
    return surface_caps(dancer, phi, None)[0]


def fold_scale(dancer: Dancer, phi, share: float) -> float:
    """The largest factor α by which these filters' motion may be scaled before faces holding
    more than `share` of the surface's area fold over (turn past edge-on) in one of them; inf
    for a dancer without `vertices` and `faces` (a rig's modes) or when none ever folds.

    Displacements are affine in φ, so at α·(φ − b) a face's edges are e_i + α·d_i and its
    normal is along c(α) = e₁×e₂ + α·(d₁×e₂ + e₁×d₂) + α²·(d₁×d₂): it folds over where
    n₀·c(α) = 0 first, the smallest positive root of that quadratic (exact, not linearised).
    A face folding under any filter counts at its smallest root; α is the area-weighted
    `share`-quantile of those roots.

    Parameters
    ----------
    dancer : the model.
    phi : (S, k) filters (the frames measured).
    share : fraction of the surface's area allowed to fold over, in [0, 1).

    Returns
    -------
    float α > 0, or inf.
    """
    return surface_caps(dancer, phi, share)[1]


def surface_caps(dancer: Dancer, phi, share: float | None) -> tuple[np.ndarray, float]:
    """`edge_strain` and `fold_scale` (when `share` is not None) in one pass over the filters:
    one displacement and one gather of the faces' corners per filter serve both.

    Parameters
    ----------
    dancer : the model.
    phi : (S, k) filters.
    share : as `fold_scale`'s, or None (no fold measured: inf).

    Returns
    -------
    ((S,) strains, α).
    """
    faces, rest = getattr(dancer, "faces", None), getattr(dancer, "vertices", None)
    phi = np.atleast_2d(np.asarray(phi, dtype=np.float64))
    if faces is None or rest is None or not len(faces):
        return np.zeros(len(phi)), np.inf
    faces = np.asarray(faces)
    corners = np.asarray(rest, dtype=np.float64)[faces]  # (m, 3 corners, 3)
    sides = np.roll(corners, -1, axis=1) - corners  # i→j, j→k, k→i: the faces' edges
    length = np.maximum(np.linalg.norm(sides, axis=-1), STRAIN_FLOOR * dancer.diagonal)
    e1, e2 = sides[:, 0], -sides[:, 2]  # corner 0 to corners 1 and 2
    normal = cross(e1, e2)
    area = np.linalg.norm(normal, axis=1)
    folding = share is not None and bool((area > 0).any())
    if folding:  # a degenerate face has no normal to fold
        normal = normal / np.where(area > 0, area, 1.0)[:, None]
        # n·(d₁×e₂ + e₁×d₂) = d₁·(e₂×n) + d₂·(n×e₁): the rest shape's part once
        lever1, lever2 = cross(e2, normal), cross(normal, e1)
        folds = np.full(len(faces), np.inf)
    strain = np.zeros(len(phi))
    for s, filter_ in enumerate(phi):  # one frame at a time: (n, 3) and (m, 3, 3) in memory
        moved = dancer.displacements(filter_[None])[0][faces]
        changes = np.roll(moved, -1, axis=1) - moved
        strain[s] = (np.linalg.norm(changes, axis=-1) / length).max(initial=0.0)
        if folding:
            d1, d2 = changes[:, 0], -changes[:, 2]
            linear = np.einsum("ij,ij->i", d1, lever1) + np.einsum("ij,ij->i", d2, lever2)
            square = np.einsum("ij,ij->i", normal, cross(d1, d2))
            folds = np.minimum(folds, first_positive_root(area, linear, square))
    if not folding:
        return strain, np.inf
    kept = area > 0
    folds, area = folds[kept], area[kept]
    order = np.argsort(folds)
    reached = np.cumsum(area[order]) / area.sum()
    first = int(np.searchsorted(reached, share, side="right"))
    return strain, float(folds[order[first]]) if first < len(order) else np.inf


def first_positive_root(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> np.ndarray:
    """The smallest t > 0 with a + b·t + c·t² = 0 for each row (a > 0), inf where none is.

    Parameters
    ----------
    a, b, c : (m,) coefficients, a > 0.

    Returns
    -------
    (m,) float64.
    """
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        flat = np.abs(c) <= 1e-12 * (np.abs(b) + a)  # a linear equation, to rounding
        linear = np.where(b < 0, -a / b, np.inf)
        root = np.sqrt(np.maximum(b * b - 4 * a * c, 0.0))
        # Both roots without cancellation: q = −(b + sign(b)·√disc)/2, t = q/c and a/q.
        q = -0.5 * (b + np.where(b < 0, -root, root))
        pair = np.stack([q / c, a / q])
        pair = np.where(pair > 0, pair, np.inf).min(axis=0)
        quadratic = np.where(b * b - 4 * a * c >= 0, pair, np.inf)
    return np.where(flat, linear, quadratic)


@dataclass
class ItemMotion:
    """How one mapping moves a model on a song: m (fraction of the diagonal), the largest frame's
    motion (same unit) and the main harmonic range [lowest, highest] (MAIN_SHARE of its energy).

    Parameters
    ----------
    motion : m.
    peak : the largest frame's motion.
    lowest, highest : the main harmonic range (−1 when the mapping moves nothing).
    """

    motion: float
    peak: float
    lowest: int
    highest: int

    def as_json(self) -> dict:
        """The measures as the page shows them.

        Returns
        -------
        {"motion", "peak", "harmonics": [lowest, highest]}.
        """
        return {"motion": self.motion, "peak": self.peak,
                "harmonics": [self.lowest, self.highest]}


def item_weights(dancer: Dancer, spectrogram, mapping: Mapping) -> tuple[np.ndarray, np.ndarray]:
    """The targets a mapping moves on the song, and φ − 1 on them at the song's frames (F, T)
    (`Mapping.play`: its smoothing, envelope and pulse).

    Parameters
    ----------
    dancer : the model.
    spectrogram : the song.
    mapping : the mapping.

    Returns
    -------
    (targets (T,) int64, w (F, T)).
    """
    k = len(dancer.frequencies)
    w = mapping.play(spectrogram, song_times(spectrogram), k) - 1.0
    targets = np.flatnonzero(np.abs(w).max(axis=0) > 0)
    return targets, w[:, targets]


def gallery_motion(dancer: Dancer, spectrogram, mappings) -> list[ItemMotion]:
    """m, the peak and the main harmonic range of each mapping on the song (any mappings: an
    initial gallery or bred children). m = 95th percentile over the frames of the RMS vertex
    displacement divided by the bounding-box diagonal.

    Parameters
    ----------
    dancer : the model.
    spectrogram : the song.
    mappings : the mappings.

    Returns
    -------
    list of ItemMotion, one per mapping.
    """
    results = []
    diagonal = dancer.diagonal
    for mapping in mappings:
        targets, w = item_weights(dancer, spectrogram, mapping)
        if not len(targets):
            results.append(ItemMotion(0.0, 0.0, -1, -1))
            continue
        gram = motion_gram(dancer, targets)
        rms = frame_motion(w, gram) / diagonal
        energy = (w ** 2).mean(axis=0) * np.diag(gram)
        share = np.cumsum(energy) / max(energy.sum(), 1e-300)
        tail = (1 - MAIN_SHARE) / 2
        lowest = targets[min(len(targets) - 1, np.searchsorted(share, tail, side="right"))]
        highest = targets[min(len(targets) - 1, np.searchsorted(share, 1 - tail))]
        results.append(ItemMotion(float(np.percentile(rms, 95)), float(rms.max()),
                                  int(lowest), int(highest)))
    return results


def full_scale_motion(dancer: Dancer, mappings) -> np.ndarray:
    """RMS vertex displacement of each mapping at full-scale input g̃ ≡ 1 (S,), in the units
    of the displacements: the most the music can move it (a pulse, if any, at its full kick).

    Parameters
    ----------
    dancer : the model.
    mappings : the mappings.

    Returns
    -------
    (S,).
    """
    k = len(dancer.frequencies)
    motion = []
    for mapping in mappings:
        w = filters([mapping], np.ones((1, mapping.bands)), k, 1.0,
                    np.full((1, 1), mapping.pulse.amount))[0] - 1.0
        targets = np.flatnonzero(w[0])
        motion.append(frame_motion(w[:, targets], motion_gram(dancer, targets))[0]
                      if len(targets) else 0.0)
    return np.array(motion)


def gallery_correlations(dancer: Dancer, spectrogram, mappings) -> np.ndarray:
    """(S, S) correlation of the items' displacement fields over the song's frames:
    Σ_f ⟨d_s(f), d_r(f)⟩ / √(Σ_f |d_s(f)|² Σ_f |d_r(f)|²), ⟨·,·⟩ over all vertices.

    Parameters
    ----------
    dancer : the model.
    spectrogram : the song.
    mappings : the S mappings.

    Returns
    -------
    (S, S), ones on the diagonal.
    """
    weights = [item_weights(dancer, spectrogram, mapping) for mapping in mappings]
    union = np.unique(np.concatenate([targets for targets, _ in weights]))
    gram = motion_gram(dancer, union)
    where = [np.searchsorted(union, targets) for targets, _ in weights]
    size = len(mappings)
    inner = np.zeros((size, size))
    for s in range(size):
        projected = weights[s][1] @ gram[where[s]]  # (F, |union|)
        for r in range(s, size):
            inner[s, r] = inner[r, s] = np.sum(projected[:, where[r]] * weights[r][1])
    norms = np.sqrt(np.maximum(np.diag(inner), 1e-300))
    return inner / norms[:, None] / norms[None, :]


# ---------------------------------------------------------------------------------------------
