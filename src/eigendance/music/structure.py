"""Bars and sections of a song from its beats (docs/design.md#rhythm).

Both work on beat-synchronous features of `music.onset.BeatFeatures` (librosa's mel dB and
chroma at 22050/512 frames per second), beat i spanning frames f_i … f_{i+1} − 1.

Bars: each beat gets an accent a_i, the sum of three features standardised over the song
(z-scores): the low-frequency onset (the largest mean rise of the mel bands below LOW_HZ within
a frame before and two after f_i: the kick drum and the bass note that start bars), the harmonic
change (the cosine distance between the mean chroma of beat i and that of beat i − 1: chords
change at bar lines) and the onset strength (the largest mean rise over all mel bands there).
For each meter m ∈ METERS and phase p < m, the bar score is Welch's t of the accents of the
beats i ≡ p (mod m) against the others; the meter and phase with the largest score give the
downbeats i = p, p + m, p + 2m, …

Sections: librosa's agglomerative segmentation (librosa.segment.agglomerative: clustering under
the constraint that each cluster is a run of consecutive beats) of the beat-synchronous chroma
(median per beat) stacked with 13 MFCCs of the mel dB (mean per beat), each row standardised,
into K = min(round(duration / SECTION_SECONDS), MAX_SECTIONS) parts (none below 2); the sections
are the start times of the parts after the first, less those within MIN_SECTION of the song's
start or end or of the section kept before.
"""

from __future__ import annotations

import numpy as np

from eigendance.music.onset import FRAME_RATE, SR

LOW_HZ = 150.0  # Hz: mel bands centred below this carry the bar's low accent
METERS = (3, 4)  # beats per bar considered
SECTION_SECONDS = 20.0  # s: one section per this much of the song
MAX_SECTIONS = 24  # parts at most, however long the song
MIN_BARS = 2  # fewer bars' worth of beats: no downbeats
MIN_SECTION = 4.0  # s: a part shorter than this (after the song's start) is merged into the last


def _standard(values: np.ndarray) -> np.ndarray:
    spread = values.std()
    return (values - values.mean()) / spread if spread > 0 else np.zeros_like(values)


def _rise(decibels: np.ndarray, frames: np.ndarray, bands) -> np.ndarray:
    """Largest mean rise (dB) over `bands` within frames f − 1 … f + 2 of each beat frame f."""
    flux = np.maximum(np.diff(decibels[:, bands], axis=0, prepend=decibels[:1, bands]), 0)
    level = flux.mean(axis=1)
    window = np.clip(frames[:, None] + np.arange(-1, 3), 0, len(level) - 1)
    return level[window].max(axis=1)


def accents(frames, decibels: np.ndarray, chroma: np.ndarray) -> np.ndarray:
    """a_i of every beat (module docstring).

    Parameters
    ----------
    frames : (n,) beat frames f_i (ascending, < T).
    decibels : (T, mels) mel dB.
    chroma : (T, 12) chroma.

    Returns
    -------
    (n,) accents (z-score sums).
    """
    import librosa  # heavy (numba): only when a song is analysed

    frames = np.asarray(frames, dtype=np.int64)
    centres = librosa.mel_frequencies(decibels.shape[1] + 2, fmin=0.0, fmax=SR / 2)[1:-1]
    low = np.flatnonzero(centres < LOW_HZ)
    bounds = np.append(frames, len(chroma))
    means = np.stack([chroma[a:max(b, a + 1)].mean(axis=0)
                      for a, b in zip(bounds[:-1], bounds[1:], strict=True)])
    norms = np.maximum(np.linalg.norm(means, axis=1), 1e-9)
    similarity = np.einsum("ij,ij->i", means[1:], means[:-1]) / (norms[1:] * norms[:-1])
    change = np.concatenate([[0.0], 1 - similarity])
    everything = slice(None)
    return (_standard(_rise(decibels, frames, low)) + _standard(change)
            + _standard(_rise(decibels, frames, everything)))


def bar_scores(accent: np.ndarray) -> dict:
    """Welch's t of the accents on each meter's phase against the rest.

    Parameters
    ----------
    accent : (n,) a_i.

    Returns
    -------
    dict (meter, phase) → score (−inf where a group is too small).
    """
    scores = {}
    index = np.arange(len(accent))
    for meter in METERS:
        for phase in range(meter):
            on = accent[index % meter == phase]
            off = accent[index % meter != phase]
            if len(on) < MIN_BARS or len(off) < MIN_BARS:
                scores[meter, phase] = -np.inf
                continue
            spread = np.sqrt(on.var(ddof=1) / len(on) + off.var(ddof=1) / len(off))
            scores[meter, phase] = (on.mean() - off.mean()) / spread if spread > 0 else 0.0
    return scores


def bars(frames, decibels: np.ndarray, chroma: np.ndarray) -> np.ndarray:
    """The indices of the beats that start a bar (module docstring).

    Parameters
    ----------
    frames : (n,) beat frames.
    decibels : (T, mels) mel dB.
    chroma : (T, 12) chroma.

    Returns
    -------
    (d,) int indices into the beats, every m-th from the phase p; empty with fewer than
    MIN_BARS bars of the longest meter.
    """
    frames = np.asarray(frames, dtype=np.int64)
    if len(frames) < MIN_BARS * max(METERS) + 1:
        return np.zeros(0, dtype=np.int64)
    scores = bar_scores(accents(frames, decibels, chroma))
    meter, phase = max(scores, key=scores.get)
    return np.arange(phase, len(frames), meter)


def sections(frames, decibels: np.ndarray, chroma: np.ndarray, duration: float) -> np.ndarray:
    """The start times (s) of the song's parts after the first (module docstring).

    Parameters
    ----------
    frames : (n,) beat frames.
    decibels : (T, mels) mel dB.
    chroma : (T, 12) chroma.
    duration : the song's, s.

    Returns
    -------
    (K − 1,) s, ascending (empty for a song too short to hold two parts).
    """
    import librosa  # heavy (numba): only when a song is analysed

    frames = np.asarray(frames, dtype=np.int64)
    parts = int(np.clip(round(duration / SECTION_SECONDS), 1, MAX_SECTIONS))
    if parts < 2 or len(frames) < 2 * parts:
        return np.zeros(0)
    mfcc = librosa.feature.mfcc(S=decibels.T, n_mfcc=13)
    bounds = librosa.util.fix_frames(frames, x_min=0, x_max=len(decibels))
    tone = librosa.util.sync(chroma.T, bounds, aggregate=np.median)
    timbre = librosa.util.sync(mfcc, bounds, aggregate=np.mean)
    stacked = np.vstack([tone, timbre])
    spread = stacked.std(axis=1, keepdims=True)
    stacked = (stacked - stacked.mean(axis=1, keepdims=True)) / np.where(spread > 0, spread, 1)
    starts = librosa.segment.agglomerative(stacked, parts)
    kept: list[float] = []
    for time in bounds[starts[1:]] / FRAME_RATE:
        if time - (kept[-1] if kept else 0.0) >= MIN_SECTION and duration - time >= MIN_SECTION:
            kept.append(float(time))
    return np.asarray(kept)
