"""The filter of band values, as a `Mapping` defines it (docs/design.md#mapping): which target
each band drives (`harmonic_indices`, ν(ξ) = min(k − 1, ⌊t(ξ)·k⌋)), the amplification resampled
to k targets (`resample_amplification`), and φ for many mappings and frames in one call
(`filters`, which `Mapping.filter` and `Mapping.play` take).
"""

from __future__ import annotations

import numpy as np

from eigendance.errors import InputError


def harmonic_indices(transfer, k: int) -> np.ndarray:
    """ν(ξ) = min(k − 1, ⌊t(ξ)·k⌋), int64, for transfers of any shape.

    Parameters
    ----------
    transfer : values in [0, 1], any shape.
    k : the targets.

    Returns
    -------
    int64 of the transfer's shape.
    """
    transfer = np.asarray(transfer, dtype=np.float64)
    return np.minimum(k - 1, np.floor(transfer * k)).astype(np.int64)


def resample_amplification(amplification, k: int) -> np.ndarray:
    """a_k(ν) = a(min(K − 1, ⌊(ν + ½)·K/k⌋)) along the last axis (identity when K = k).

    Parameters
    ----------
    amplification : (…, K).
    k : the targets.

    Returns
    -------
    (…, k).
    """
    amplification = np.asarray(amplification, dtype=np.float64)
    K = amplification.shape[-1]
    if K == k:
        return amplification
    index = np.minimum(K - 1, np.floor((np.arange(k) + 0.5) * K / k)).astype(np.int64)
    return amplification[..., index]


def filters(mappings, values, k: int, offset: float = 1.0, kicks=None) -> np.ndarray:
    """φ = a·(Σ g̃ + kick) + offset for S mappings and band values (…, B) in one call →
    (S, …, k). kicks: (S, …) amount·p(t) of each mapping's pulse, added on its range (None: 0).

    The scatter-add Σ_{ξ: ν(ξ)=ν} g̃(ξ) (= g̃ @ P_s with the one-hot (B, k) matrix P_s of
    mapping s) is one np.bincount over (mapping, frame, harmonic) for all mappings and frames:
    no BLAS call (whose thread start-up dominated for small batches) and O(S·F·B) work.

    Parameters
    ----------
    mappings : S mappings with the same bands.
    values : (…, B).
    k : the targets.
    offset : b.
    kicks : (S, …) or broadcastable, amount·p(t) of each mapping's pulse; None: no pulse.

    Returns
    -------
    (S, …, k).
    """
    values = np.asarray(values, dtype=np.float64)
    mappings = list(mappings)
    bands = values.shape[-1]
    for mapping in mappings:
        if mapping.bands != bands:
            raise InputError(f"{mapping.name}: the mapping has {mapping.bands} bands; the "
                             f"spectrogram has {bands}")
    if not mappings:
        return np.zeros((0, *values.shape[:-1], k))
    count = len(mappings)
    indices = harmonic_indices(np.stack([m.transfer for m in mappings]), k)  # (S, B)
    amplification = np.stack([m.amplification_for(k) for m in mappings])  # (S, k)
    flat = values.reshape(-1, bands)  # (F, B)
    frames = len(flat)
    # Flat target index of (s, f, ν(s, ξ)) in an (S, F, k) array, for every (s, f, ξ).
    rows = (np.arange(count)[:, None] * frames + np.arange(frames)[None, :]) * k  # (S, F)
    target = rows[:, :, None] + indices[:, None, :]  # (S, F, B)
    sums = np.bincount(target.ravel(), weights=np.broadcast_to(flat, target.shape).ravel(),
                       minlength=count * frames * k).reshape(count, frames, k)
    if kicks is not None:
        routed = np.stack([m.pulse.routed(k) for m in mappings])  # (S, k)
        kicks = np.broadcast_to(np.asarray(kicks, dtype=np.float64),
                                (count, *values.shape[:-1])).reshape(count, frames)
        sums += kicks[:, :, None] * routed[:, None, :]
    phi = amplification[:, None, :] * sums + offset
    return phi.reshape(len(mappings), *values.shape[:-1], k)


