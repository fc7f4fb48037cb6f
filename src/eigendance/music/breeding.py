"""Breeding: the next gallery from the mappings a person selected (docs/design.md#breeding).

The random parts use `Mulberry32`, a tiny uint32 generator that a browser can port bit for bit;
`breed` documents the exact order of draws, so the same seed and parents give the same children
in Python and in the browser (tests/js/breed_reference.mjs).
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from eigendance.errors import InputError
from eigendance.music.dancer import frame_motion, motion_gram, song_times
from eigendance.music.envelope import Envelope, Pulse
from eigendance.music.filter import resample_amplification
from eigendance.music.gallery import PEAK_MOTION
from eigendance.music.mapping import Mapping


class Mulberry32:
    """mulberry32: a 32-bit state PRNG, ported bit for bit from its JavaScript original.

    JavaScript (the reference the browser uses)::

        function next() {            // returns a uint32
          a = (a + 0x6D2B79F5) | 0;
          let t = Math.imul(a ^ (a >>> 15), a | 1);
          t = (t + Math.imul(t ^ (t >>> 7), t | 61)) ^ t;
          return (t ^ (t >>> 14)) >>> 0;
        }
        uniform() = next() / 4294967296   // in [0, 1)

    The initial state is the seed modulo 2^32.

    Parameters
    ----------
    seed : any integer (taken modulo 2^32).
    """

    MASK = 0xFFFFFFFF

    def __init__(self, seed: int):
        self.state = int(seed) & self.MASK

    def next_uint32(self) -> int:
        """The next 32-bit output.

        Returns
        -------
        int in [0, 2^32).
        """
        M = self.MASK
        self.state = (self.state + 0x6D2B79F5) & M
        a = self.state
        t = ((a ^ (a >> 15)) * (a | 1)) & M
        t = ((t + (((t ^ (t >> 7)) * (t | 61)) & M)) & M) ^ t
        return (t ^ (t >> 14)) & M

    def uniform(self) -> float:
        """A float in [0, 1): next_uint32() / 2^32.

        Returns
        -------
        float.
        """
        return self.next_uint32() / 4294967296.0

    def below(self, count: int) -> int:
        """An integer in [0, count): ⌊uniform()·count⌋.

        Parameters
        ----------
        count : the bound, ≥ 1.

        Returns
        -------
        int.
        """
        return min(count - 1, int(math.floor(self.uniform() * count)))


def cross(first, second, random: Mulberry32, mean_segment: float | None = None) -> np.ndarray:
    """Segment-wise convex combination of two vectors of length L (thesis 6.2.1).

    Until L entries are filled: draw the segment length n — n = 1, then while n < (entries left)
    draw u and stop if u < p, else n += 1 (a Geometric(p) length truncated to what is left, one
    uniform per trial), p = min(1, 1/mean_segment), mean_segment = L/4 by default; then draw
    r = uniform() and fill the next n entries with r·first + (1 − r)·second.

    Parameters
    ----------
    first, second : (L,) the parents' vectors.
    random : the generator (its draws are consumed in the documented order).
    mean_segment : the mean segment length (default L/4).

    Returns
    -------
    (L,) the child's vector.
    """
    first = np.asarray(first, dtype=np.float64)
    second = np.asarray(second, dtype=np.float64)
    length = len(first)
    if mean_segment is None:
        mean_segment = length / 4
    p = min(1.0, 1.0 / mean_segment) if mean_segment > 0 else 1.0
    child = np.empty(length)
    filled = 0
    while filled < length:
        left = length - filled
        n = 1
        while n < left and not random.uniform() < p:
            n += 1
        r = random.uniform()
        segment = slice(filled, filled + n)
        child[segment] = r * first[segment] + (1 - r) * second[segment]
        filled += n
    return child


def breed(parents, size: int = 8, seed: int = 0,
          mean_segment: float | None = None) -> list[Mapping]:
    """S children of the selected parents (thesis 6.2.1); deterministic for a seed.

    Parameters
    ----------
    parents : the selected mappings (all with the same number of bands B).
    size : number of children S ≥ 1.
    seed : any integer; the generator starts from seed mod 2³².
    mean_segment : mean length of a crossed segment (default L/4 for vectors of length L).

    Returns
    -------
    S mappings (transfer of B values, amplification of parent 0's length K).

    One Mulberry32(seed) stream; per child, in this order:
      1. parents: i = below(P), then j = below(P − 1), j += 1 if j ≥ i (so i ≠ j); with a single
         parent no draw is made and i = j = 0;
      2. transfer: u = uniform(); if u < ½, cross(parent_i.transfer, parent_j.transfer);
         else draw u = uniform() and copy parent i's transfer if u < ½, else parent j's;
      3. amplification: the same as 2 with the amplifications (an independent coin).
    Amplifications of other lengths than parent 0's are first resampled to its length K; child
    transfers are clipped to [0, 1] (a convex combination can overshoot 1 by one rounding).
    The rhythm genes (version 3) come from a second stream, Mulberry32(seed + RHYTHM_STREAM),
    so the draws above are those of earlier versions; per child, after the same parent pair:
      4. envelope: the same as 2 with the vector [attack, release, threshold] (3B values);
         auto-range is parent i's;
      5. pulse: the same as 2 with [amount, decay, low, high] (low and high sorted after);
         the source is parent i's. When only one parent's pulse is active (amount > 0), the
         draws are the same but the child takes decay, range and source from that parent (an
         inactive pulse's range, 0–1 by default, would widen the kicks to every harmonic);
         only the amount is crossed with the inactive parent's 0.
    A rig's dance with a rippling skin carries surface genes (`Mapping.surface`,
    docs/design.md#surface-of-a-rig): when both parents have them (of one band count), the
    child's are `breed([surface_i, surface_j], 1, seed + SURFACE_STREAM + c)` (steps 1–5 on
    them), else parent i's.
    Children carry `seed` in their JSON, and parent i's other settings (gain, smoothing,
    offset, palette, look).

    Example
    -------
    >>> a = Mapping(np.linspace(0, 1, 4), np.ones(3))
    >>> b = Mapping(np.linspace(1, 0, 4), -np.ones(3))
    >>> children = breed([a, b], size=6, seed=1)
    >>> len(children), all(np.all(abs(c.amplification) <= 1) for c in children)
    (6, True)
    >>> [c.transfer.tolist() for c in children] == [c.transfer.tolist() for c in
    ...                                              breed([a, b], size=6, seed=1)]
    True
    """
    parents = list(parents)
    if not parents:
        raise InputError("breeding needs at least one parent mapping")
    if not isinstance(size, int | np.integer) or size < 1:
        raise InputError(f"the gallery size must be a positive integer, got {size}")
    bands = parents[0].bands
    K = len(parents[0].amplification)
    for parent in parents:
        if parent.bands != bands:
            raise InputError(f"{parent.name}: {parent.bands} bands, but "
                             f"{parents[0].name} has {bands}; parents must agree")
    transfers = [p.transfer for p in parents]
    amplifications = [resample_amplification(p.amplification, K) for p in parents]
    random = Mulberry32(seed)
    rhythm_random = Mulberry32(int(seed) + RHYTHM_STREAM)
    children = []
    for c in range(size):
        if len(parents) == 1:
            i = j = 0
        else:
            i = random.below(len(parents))
            j = random.below(len(parents) - 1)
            j += j >= i
        genes = []
        for vectors in (transfers, amplifications):
            if random.uniform() < 0.5:
                genes.append(cross(vectors[i], vectors[j], random, mean_segment))
            else:
                genes.append(vectors[i].copy() if random.uniform() < 0.5 else vectors[j].copy())
        transfer = np.clip(genes[0], 0.0, 1.0)
        # Settings besides the genes (gain, smoothing, offset, palette, look): parent i's.
        child = parents[i].with_genes(transfer, genes[1], int(seed), f"child {c}")
        child = with_rhythm_genes(child, parents[i], parents[j], rhythm_random, mean_segment)
        children.append(with_surface_genes(child, parents[i], parents[j],
                                           (int(seed) + SURFACE_STREAM + c) % (1 << 32),
                                           mean_segment))
    return children


RHYTHM_STREAM = 0x9E3779B9  # the rhythm genes' generator starts from seed + this
SURFACE_STREAM = 0x7F4A7C15  # child c's surface genes are bred with seed + this + c


def with_surface_genes(child: Mapping, first: Mapping, second: Mapping, seed: int,
                       mean_segment) -> Mapping:
    """The child with its parents' surface genes crossed (`breed`), or parent i's.

    Parameters
    ----------
    child : the child (parent i's surface, if any, so far).
    first, second : its parents i and j.
    seed : the surface genes' seed.
    mean_segment : the crossing's mean segment length.

    Returns
    -------
    Mapping.
    """
    ours, theirs = first.surface, second.surface
    if ours is None or theirs is None or ours.bands != theirs.bands or first is second:
        return child
    bred = breed([ours, theirs], 1, seed, mean_segment)[0]
    return replace(child, surface=replace(bred, name=f"{child.name} surface"))


def with_rhythm_genes(child: Mapping, first: Mapping, second: Mapping, random: Mulberry32,
                      mean_segment) -> Mapping:
    """The child with envelope and pulse genes of its parents (`breed`, steps 4 and 5).

    Parameters
    ----------
    child : the child with its transfer and amplification genes.
    first, second : its parents i and j (the first gives auto-range and the pulse's source,
        unless only the second's pulse is active).
    random : the rhythm genes' generator (Mulberry32(seed + RHYTHM_STREAM)).
    mean_segment : the crossing's mean segment length, as for the other genes.

    Returns
    -------
    Mapping.
    """

    def gene(a, b):
        if random.uniform() < 0.5:
            return cross(a, b, random, mean_segment)
        return np.array(a if random.uniform() < 0.5 else b, dtype=np.float64)

    def envelope_vector(m):
        e = m.envelope
        return np.concatenate([e.attack, e.release, e.threshold])

    def pulse_vector(m):
        p = m.pulse
        return np.array([p.amount, p.decay, p.low, p.high])

    bands = child.bands
    shape = gene(envelope_vector(first), envelope_vector(second))
    amount, decay, low, high = gene(pulse_vector(first), pulse_vector(second))
    low, high = sorted((float(np.clip(low, 0, 1)), float(np.clip(high, 0, 1))))
    source = first.pulse.source
    active = [p.pulse for p in (first, second) if p.pulse.amount > 0]
    if len(active) == 1:  # an inactive parent's decay, range and source are not expressed
        only = active[0]
        decay, low, high, source = only.decay, only.low, only.high, only.source
    envelope = Envelope(shape[:bands], shape[bands:2 * bands], np.clip(shape[2 * bands:], 0, 1),
                        first.envelope.auto_range)
    pulse = Pulse(max(0.0, float(amount)), max(1e-3, float(decay)), low, high, source)
    return replace(child, envelope=envelope, pulse=pulse)


# Children are calibrated like the first generation (docs/design.md#breeding): a crossing can
# send a loud band to a harmonic whose amplification was calibrated for a quiet one.
BOX_LIMIT = 1.3  # promised: a child's bounding box (diagonal) stays within this × the rest's
BOX_AIM = 1.2  # what the measured frames are held to: the margin covers frames not measured
MEASURED_FRAMES = 32  # the song's frames of largest RMS motion whose bounding box is measured


def box_growth(rest: np.ndarray, moved: np.ndarray) -> np.ndarray:
    """Bounding-box diagonal of each frame over the rest shape's.

    Parameters
    ----------
    rest : (n, 3) positions at rest.
    moved : (F, n, 3) positions.

    Returns
    -------
    (F,) ratios (1: the same size).
    """
    size = np.linalg.norm(np.ptp(rest, axis=0))
    return np.linalg.norm(moved.max(axis=1) - moved.min(axis=1), axis=1) / max(size, 1e-300)


def child_scale(dancer, spectrogram, child: Mapping, offset: float, swing: bool) -> float:
    """α ≤ 1 bounding one child: its largest frame's RMS motion at most PEAK_MOTION of the
    diagonal (the first generation's cap), and its bounding box at most BOX_AIM × the rest's on
    the MEASURED_FRAMES frames of largest RMS motion (bisection, the motion taken linear in α).

    Parameters
    ----------
    dancer : the model (`music.dancer.Dancer` with `vertices`, its rest positions).
    spectrogram : the song it will dance to.
    child : the child.
    offset : b of its filter (1 for harmonics, the mapping's own for a rig's modes).
    swing : the motion also reaches −φ (a rig's modes oscillate), so that side is measured.

    Returns
    -------
    float in [0, 1].
    """
    k = len(dancer.frequencies)
    music = child.play(spectrogram, song_times(spectrogram), k, offset=0.0)  # a·(Σ g̃ + kick)
    targets = np.flatnonzero(np.abs(music).max(axis=0) > 0)
    if not len(targets):
        return 1.0
    rms = frame_motion(music[:, targets], motion_gram(dancer, targets))
    scale = min(1.0, PEAK_MOTION * dancer.diagonal / max(rms.max(), 1e-300))
    loudest = music[np.argsort(rms)[-MEASURED_FRAMES:]]
    rest = np.asarray(dancer.vertices, dtype=np.float64)
    still = dancer.displacements(np.full((1, k), offset))
    fields = np.concatenate([dancer.displacements(offset + sign * scale * loudest) - still
                             for sign in ((1, -1) if swing else (1,))])

    def fits(alpha: float) -> bool:
        return bool(box_growth(rest, rest + alpha * fields).max() <= BOX_AIM)

    if fits(1.0):
        return scale
    low, high = 0.0, 1.0
    for _ in range(12):
        middle = (low + high) / 2
        low, high = (middle, high) if fits(middle) else (low, middle)
    return scale * low


def bounded_children(dancer, spectrogram, children, rig: bool = False) -> list[Mapping]:
    """The children with their amplifications scaled by `child_scale`, so that over the song
    none grows past BOX_LIMIT × the rest shape's bounding box (a quiet child is left as bred).

    Parameters
    ----------
    dancer : the model the children dance on (a `HarmonicBasis`, or a rig's `RigDancer`).
    spectrogram : the song they dance to.
    children : the bred mappings (`breed`).
    rig : the dancer is a rig's modes (offset b: the mapping's; the modes swing to −φ).

    Returns
    -------
    list of Mapping (same names, seeds and genes but the amplification's scale).
    """
    bounded = []
    for child in children:
        alpha = child_scale(dancer, spectrogram, child, child.offset if rig else 1.0, rig)
        bounded.append(child if alpha >= 1.0 else
                       replace(child, amplification=child.amplification * alpha))
    return bounded
