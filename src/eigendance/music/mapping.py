"""Mapping sound to motion: transfer, amplification and the filter (docs/design.md#mapping).

A `Mapping` holds a transfer t (B,) — band ξ ↦ normalised frequency in [0, 1] — and an
amplification a (K,). For k targets (the harmonics of a mesh, or the vibration modes of a rig):

    ν(ξ) = min(k − 1, ⌊t(ξ)·k⌋),   φ(ν) = a_k(ν) · Σ_{ξ: ν(ξ)=ν} g̃(ξ) + b,

where a_k is a resampled to length k by normalised index: a_k(ν) = a(min(K − 1, ⌊(ν + ½)·K/k⌋))
(each target takes the amplification of the cell its centre falls in; a_k = a when K = k), and
the offset b is 1 for harmonics (thesis 6-1: a ≡ 0 leaves the mesh still) and the mapping's
own for modes.
"""

from __future__ import annotations

import json
import os
from dataclasses import dataclass, field

import numpy as np

from eigendance.errors import InputError, one_line
from eigendance.files import atomic_write

FORMAT = "eigendance.mapping"
VERSION = 1


@dataclass
class Mapping:
    """A sound-to-motion mapping.

    Parameters
    ----------
    transfer : (B,) values in [0, 1]: band ξ drives target ⌊t(ξ)·k⌋ of k.
    amplification : (K,) finite values, resampled to the k targets by normalised index.
    seed : the breeding seed that made it, or None.
    name : how messages call it (a file name).

    Example
    -------
    >>> mapping = Mapping(transfer=[0.1, 0.1, 0.9], amplification=[2.0, 0.0, -1.0])
    >>> mapping.filter([0.5, 0.25, 1.0], k=3).tolist()   # 2·(0.5 + 0.25) + 1, 1, −1·1 + 1
    [2.5, 1.0, 0.0]
    >>> Mapping.from_json(mapping.to_json()).to_json() == mapping.to_json()
    True
    """

    transfer: np.ndarray
    amplification: np.ndarray
    seed: int | None = None
    name: str = field(default="mapping", compare=False)

    def __post_init__(self):
        self.transfer = np.asarray(self.transfer, dtype=np.float64)
        self.amplification = np.asarray(self.amplification, dtype=np.float64)
        _check_vector(self.transfer, "transfer", self.name, unit=True)
        _check_vector(self.amplification, "amplification", self.name)

    @property
    def bands(self) -> int:
        return len(self.transfer)

    def harmonic_indices(self, k: int) -> np.ndarray:
        """ν(ξ) = min(k − 1, ⌊t(ξ)·k⌋) for each band, int64 (B,)."""
        return harmonic_indices(self.transfer, k)

    def amplification_for(self, k: int) -> np.ndarray:
        """The amplification resampled to k harmonics (see the module docstring)."""
        return resample_amplification(self.amplification, k)

    def filter(self, values, k: int, offset: float = 1.0) -> np.ndarray:
        """φ = a_k·Σ g̃ + offset for band values (…, B) → (…, k).

        offset: 1 for harmonics (a ≡ 0 leaves a mesh still), the rig's b for modes.
        `filters` evaluates many mappings at once.
        """
        return filters([self], values, k, offset)[0]

    # JSON (docs/design.md#mapping-file) ------------------------------------------------------

    def to_json(self) -> dict:
        return {"format": FORMAT, "version": VERSION, "bands": self.bands,
                "transfer": [float(x) for x in self.transfer],
                "amplification": [float(x) for x in self.amplification],
                "seed": None if self.seed is None else int(self.seed)}

    @classmethod
    def from_json(cls, data, name: str = "mapping") -> Mapping:
        """Validate a parsed mapping document; every problem is a one-line error naming the field.
        """
        if not isinstance(data, dict):
            raise InputError(f"{name}: a mapping must be a JSON object")
        if data.get("format") != FORMAT:
            raise InputError(f"{name}: format must be \"{FORMAT}\", "
                                  f"got {json.dumps(data.get('format'))}")
        if data.get("version") != VERSION or isinstance(data.get("version"), bool):
            raise InputError(f"{name}: version must be {VERSION}, "
                                  f"got {json.dumps(data.get('version'))}")
        bands = data.get("bands")
        if not isinstance(bands, int) or isinstance(bands, bool) or bands < 1:
            raise InputError(f"{name}: bands must be a positive integer, "
                                  f"got {json.dumps(bands)}")
        transfer = _number_list(data.get("transfer"), "transfer", name)
        if len(transfer) != bands:
            raise InputError(f"{name}: transfer has {len(transfer)} values; bands says "
                                  f"{bands}")
        amplification = _number_list(data.get("amplification"), "amplification", name)
        seed = data.get("seed")
        if seed is not None and (not isinstance(seed, int) or isinstance(seed, bool)):
            raise InputError(f"{name}: seed must be an integer or null, "
                                  f"got {json.dumps(seed)}")
        return cls(np.array(transfer), np.array(amplification), seed, name)

    def save(self, path: str | os.PathLike) -> None:
        """Write the mapping as JSON, atomically."""
        fields = [f" {json.dumps(key)}: {json.dumps(value)}" for key, value in
                  self.to_json().items()]
        text = "{\n" + ",\n".join(fields) + "\n}\n"  # one field per line
        atomic_write(path, lambda file: file.write(text.encode()))

    @classmethod
    def load(cls, path: str | os.PathLike) -> Mapping:
        path = os.fspath(path)
        name = os.path.basename(path)
        try:
            with open(path, encoding="utf-8") as file:
                data = json.load(file)
        except FileNotFoundError:
            raise InputError(f"{path}: no such file") from None
        except (UnicodeDecodeError, json.JSONDecodeError) as error:
            raise InputError(f"{name}: not valid JSON ({one_line(error)})") from None
        except OSError as error:
            raise InputError(f"{path}: cannot read ({error.strerror})") from None
        return cls.from_json(data, name)


def _number_list(value, field_name: str, name: str) -> list:
    if not isinstance(value, list) or not value:
        raise InputError(f"{name}: {field_name} must be a non-empty list of numbers")
    for index, x in enumerate(value):
        if not isinstance(x, int | float) or isinstance(x, bool):
            raise InputError(f"{name}: {field_name}[{index}] is not a number "
                                  f"({json.dumps(x)})")
    return value


def _check_vector(vector: np.ndarray, field_name: str, name: str, unit: bool = False) -> None:
    if vector.ndim != 1 or len(vector) == 0:
        raise InputError(f"{name}: {field_name} must be a non-empty vector, "
                              f"got shape {vector.shape}")
    bad = np.flatnonzero(~np.isfinite(vector))
    if len(bad):
        raise InputError(f"{name}: {field_name}[{bad[0]}] is not finite ({vector[bad[0]]})")
    if unit:
        bad = np.flatnonzero((vector < 0) | (vector > 1))
        if len(bad):
            raise InputError(f"{name}: {field_name}[{bad[0]}] = {vector[bad[0]]:g} is "
                                  "outside [0, 1]")


# ---------------------------------------------------------------------------------------------
# Filter


def harmonic_indices(transfer, k: int) -> np.ndarray:
    """ν(ξ) = min(k − 1, ⌊t(ξ)·k⌋), int64, for transfers of any shape."""
    transfer = np.asarray(transfer, dtype=np.float64)
    return np.minimum(k - 1, np.floor(transfer * k)).astype(np.int64)


def resample_amplification(amplification, k: int) -> np.ndarray:
    """a_k(ν) = a(min(K − 1, ⌊(ν + ½)·K/k⌋)) along the last axis (identity when K = k)."""
    amplification = np.asarray(amplification, dtype=np.float64)
    K = amplification.shape[-1]
    if K == k:
        return amplification
    index = np.minimum(K - 1, np.floor((np.arange(k) + 0.5) * K / k)).astype(np.int64)
    return amplification[..., index]


def filters(mappings, values, k: int, offset: float = 1.0) -> np.ndarray:
    """φ = a·Σ g̃ + offset for S mappings and band values (…, B) in one call → (S, …, k).

    The scatter-add Σ_{ξ: ν(ξ)=ν} g̃(ξ) (= g̃ @ P_s with the one-hot (B, k) matrix P_s of
    mapping s) is one np.bincount over (mapping, frame, harmonic) for all mappings and frames:
    no BLAS call (whose thread start-up dominated for small batches) and O(S·F·B) work.
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
    phi = amplification[:, None, :] * sums + offset
    return phi.reshape(len(mappings), *values.shape[:-1], k)


