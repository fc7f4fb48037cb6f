"""Where the eigen-solver's bands go and how they join (docs/design.md#eigensolver).

`solve_bands` (harmonic.eigensolver) solves the spectrum in bands of ≈ count pairs around
shifts σ. The shifts are planned in index space (`next_shifts`) from a counting function N(λ)
(`counting`): Weyl's law before any pair is known, a fit to the pairs found after. Bands are
sized to fill whole rounds of the workers (`band_size`) and joined into one spectrum without
gaps or duplicates (`stitch`).
"""

from __future__ import annotations

import numpy as np

# Shift below the spectrum (λ_0 = 0) so that L - σM is non-singular. Units of λ: a normalised
# mesh's first non-zero eigenvalue is of order 1.
BASELINE_SHIFT = -1e-2
OVERLAP = 0.10  # fraction of a band's width shared with its neighbours


def stitch(bands: list) -> tuple:
    """Join bands sorted by shift into one spectrum without gaps or duplicates.

    Between neighbours the cut goes through the widest gap of the overlap of their trusted
    windows, so a cluster of (near-)equal eigenvalues always comes from a single band.

    Parameters
    ----------
    bands : `eigensolver.Band`s sorted by shift.

    Returns
    -------
    (pieces, gap): pieces = [(band, mask of its accepted pairs)] in ascending order, gap =
    (a, b), the first interval no band covers, or None.
    """
    if bands[0].lower >= BASELINE_SHIFT:  # the lowest window must reach below λ_0 = 0
        return [], (BASELINE_SHIFT, bands[0].lower)
    pieces = []
    cut = -np.inf
    for band, following in zip(bands, [*bands[1:], None], strict=True):
        upper, gap = band.upper, None
        if following is not None and following.lower >= band.upper:
            gap = (band.upper, following.lower)
        elif following is not None:
            start = max(following.lower, cut)
            inside = band.eigenvalues[(band.eigenvalues > start) & (band.eigenvalues < upper)]
            points = np.concatenate([[start], inside, [upper]])
            widest = int(np.argmax(np.diff(points)))
            upper = (points[widest] + points[widest + 1]) / 2
        pieces.append((band, (band.eigenvalues > cut) & (band.eigenvalues < upper)))
        cut = upper
        if gap is not None:
            return pieces, gap
    return pieces, None


def band_size(k: int, per_band: int, workers: int) -> int:
    """Pairs per band near `per_band` such that the bands fill whole rounds of `workers`.

    The first band holds ≈ count pairs, each next one (1 − OVERLAP)·count new ones; a round
    with an idle worker costs as much as a full one, so the size grows until it saves a round.

    Parameters
    ----------
    k : pairs wanted.
    per_band : pairs per band, about.
    workers : bands solved at once.

    Returns
    -------
    int, pairs per band.
    """
    def rounds(count):
        bands = 1 + max(0, int(np.ceil((k - count) / ((1 - OVERLAP) * count))))
        return int(np.ceil(bands / workers))

    sizes = range(per_band, int(1.25 * per_band) + 1)
    return min(sizes, key=lambda count: (rounds(count / 1.05), count))  # 5% margin


def next_shifts(pieces, gap, k: int, count: int, workers: int, area: float) -> list[float]:
    """Shifts of the next round: the gap's middle, or bands above the pairs found so far.

    Planned in index space: N(λ), the number of eigenvalues below λ (`counting`), places each
    window of `count` pairs so that it shares OVERLAP·count pairs with its lower neighbour; the
    last one reaches pair k with a small margin.

    Parameters
    ----------
    pieces, gap : `stitch` of the bands so far.
    k : pairs wanted.
    count : pairs per band.
    workers : bands solved at once.
    area : the total mass (Weyl's law).

    Returns
    -------
    list of shifts.
    """
    if gap is not None:
        return [(gap[0] + gap[1]) / 2]
    values = np.concatenate([band.eigenvalues[keep] for band, keep in pieces]) if pieces else []
    inverse = counting(np.asarray(values), area)
    centres = []
    overlap = OVERLAP * count
    if not pieces:
        # First band at pair ≈ 0.4·count: its window reaches below λ_0 = 0 and up to pair count.
        # Weyl's law alone is rougher than a fit: the next window overlaps it twice as much.
        centres, top, overlap = [0.4 * count], count, 2 * overlap
    else:
        top = len(values)
    while len(centres) < workers and top < k + 0.05 * count:
        centres.append(top - overlap + count / 2)
        top += count - overlap
        overlap = OVERLAP * count
    return [inverse(centre) for centre in centres]


def counting(values: np.ndarray, area: float):
    """λ(i): the inverse of a smooth counting function N(λ) = aλ + b√λ + c.

    Weyl's law for a surface gives a = area/4π (and a boundary term in √λ); before any pair is
    known that is all, after it the three terms are fitted to the last pairs found (N(λ_j) ≈
    j + ½), which follows the local density better than Weyl's constant.

    Parameters
    ----------
    values : the eigenvalues found so far, ascending.
    area : the total mass.

    Returns
    -------
    callable(i) → λ.
    """
    a, b, c = area / (4 * np.pi), 0.0, 0.0
    index = np.arange(len(values)) + 0.5
    fitted = values > 0
    if fitted.sum() >= 20:
        recent = values[fitted][-400:]
        design = np.column_stack([recent, np.sqrt(recent), np.ones_like(recent)])
        solution = np.linalg.lstsq(design, index[fitted][-400:], rcond=None)[0]
        if solution[0] > 0:
            a, b, c = solution

    def inverse(i):
        root = (-b + np.sqrt(max(b * b - 4 * a * (c - i), 0))) / (2 * a)  # √λ
        return max(root, 0.0) ** 2

    return inverse
