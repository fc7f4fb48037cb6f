"""Mapping sound to motion: transfer, amplification, filter, initial gallery, breeding (DESIGN §4).

A `Mapping` holds a transfer t (B,) — band ξ ↦ normalised mesh frequency in [0, 1] — and an
amplification a (K,). For a basis of k harmonics:

    ν(ξ) = min(k − 1, ⌊t(ξ)·k⌋),   φ(ν) = a_k(ν) · Σ_{ξ: ν(ξ)=ν} g̃(ξ) + 1,

where a_k is a resampled to length k by normalised index: a_k(ν) = a(min(K − 1, ⌊(ν + ½)·K/k⌋))
(each harmonic takes the amplification of the cell its centre falls in; a_k = a when K = k).

The random parts (breeding) use `Mulberry32`, a tiny uint32 generator that a browser can port
bit for bit; see `breed` for the exact order of draws.
"""

from __future__ import annotations

import json
import math
import os
from dataclasses import dataclass, field

import numpy as np

from eigendance.errors import EigendanceError

FORMAT = "eigendance.mapping"
VERSION = 1
DEFAULT_GALLERY_SIZE = 8
TARGET_MOTION = 0.05  # strongest initial item: RMS displacement / bounding-box diagonal


@dataclass
class Mapping:
    """A sound-to-motion mapping: transfer (B,) in [0, 1], amplification (K,), seed or None."""

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

    def filter(self, values, k: int) -> np.ndarray:
        """φ for band values (…, B) → (…, k); see `filters` for many mappings at once."""
        return filters([self], values, k)[0]

    # JSON (DESIGN §8) -----------------------------------------------------------------------

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
            raise EigendanceError(f"{name}: a mapping must be a JSON object")
        if data.get("format") != FORMAT:
            raise EigendanceError(f"{name}: format must be \"{FORMAT}\", "
                                  f"got {json.dumps(data.get('format'))}")
        if data.get("version") != VERSION or isinstance(data.get("version"), bool):
            raise EigendanceError(f"{name}: version must be {VERSION}, "
                                  f"got {json.dumps(data.get('version'))}")
        bands = data.get("bands")
        if not isinstance(bands, int) or isinstance(bands, bool) or bands < 1:
            raise EigendanceError(f"{name}: bands must be a positive integer, "
                                  f"got {json.dumps(bands)}")
        transfer = _number_list(data.get("transfer"), "transfer", name)
        if len(transfer) != bands:
            raise EigendanceError(f"{name}: transfer has {len(transfer)} values; bands says "
                                  f"{bands}")
        amplification = _number_list(data.get("amplification"), "amplification", name)
        seed = data.get("seed")
        if seed is not None and (not isinstance(seed, int) or isinstance(seed, bool)):
            raise EigendanceError(f"{name}: seed must be an integer or null, "
                                  f"got {json.dumps(seed)}")
        return cls(np.array(transfer), np.array(amplification), seed, name)

    def save(self, path: str | os.PathLike) -> None:
        """Write the mapping as JSON, atomically."""
        from eigendance.files import atomic_write

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
            raise EigendanceError(f"{path}: no such file") from None
        except (UnicodeDecodeError, json.JSONDecodeError) as error:
            message = " ".join(str(error).split())
            raise EigendanceError(f"{name}: not valid JSON ({message})") from None
        except OSError as error:
            raise EigendanceError(f"{path}: cannot read ({error.strerror})") from None
        return cls.from_json(data, name)


def _number_list(value, field_name: str, name: str) -> list:
    if not isinstance(value, list) or not value:
        raise EigendanceError(f"{name}: {field_name} must be a non-empty list of numbers")
    for index, x in enumerate(value):
        if not isinstance(x, int | float) or isinstance(x, bool):
            raise EigendanceError(f"{name}: {field_name}[{index}] is not a number "
                                  f"({json.dumps(x)})")
    return value


def _check_vector(vector: np.ndarray, field_name: str, name: str, unit: bool = False) -> None:
    if vector.ndim != 1 or len(vector) == 0:
        raise EigendanceError(f"{name}: {field_name} must be a non-empty vector, "
                              f"got shape {vector.shape}")
    bad = np.flatnonzero(~np.isfinite(vector))
    if len(bad):
        raise EigendanceError(f"{name}: {field_name}[{bad[0]}] is not finite ({vector[bad[0]]})")
    if unit:
        bad = np.flatnonzero((vector < 0) | (vector > 1))
        if len(bad):
            raise EigendanceError(f"{name}: {field_name}[{bad[0]}] = {vector[bad[0]]:g} is "
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


def filters(mappings, values, k: int) -> np.ndarray:
    """φ for S mappings and band values (…, B) in one vectorised call → (S, …, k).

    The scatter-add Σ_{ξ: ν(ξ)=ν} g̃(ξ) (= g̃ @ P_s with the one-hot (B, k) matrix P_s of
    mapping s) is one np.bincount over (mapping, frame, harmonic) for all mappings and frames:
    no BLAS call (whose thread start-up dominated for small batches) and O(S·F·B) work.
    """
    values = np.asarray(values, dtype=np.float64)
    mappings = list(mappings)
    bands = values.shape[-1]
    for mapping in mappings:
        if mapping.bands != bands:
            raise EigendanceError(f"{mapping.name}: the mapping has {mapping.bands} bands; the "
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
    phi = amplification[:, None, :] * sums + 1.0
    return phi.reshape(len(mappings), *values.shape[:-1], k)


# ---------------------------------------------------------------------------------------------
# Transfers and the initial gallery


def initial_indices(eigenvalues, band_edges, positions=None) -> np.ndarray:
    """ν_ini at (possibly fractional) band positions x (default 0 … B−1), int64.

    ν_ini(x) = the smallest ν with f_x / f_{B−1} ≤ √(λ_ν / λ_{k−1}), where f_x is the geometric
    centre of band x. Band edges are geometric, so f_x / f_{B−1} = (e_B / e_0)^((x − B + 1)/B)
    exactly, which also defines f_x between bands (the gallery's t(εξ)).
    """
    eigenvalues = np.maximum(np.asarray(eigenvalues, dtype=np.float64), 0.0)
    band_edges = np.asarray(band_edges, dtype=np.float64)
    bands = len(band_edges) - 1
    if positions is None:
        positions = np.arange(bands, dtype=np.float64)
    if not eigenvalues[-1] > 0:
        raise EigendanceError("the basis has no positive eigenvalue; cannot build transfers")
    ratio = (band_edges[-1] / band_edges[0]) ** ((np.asarray(positions) - bands + 1) / bands)
    levels = np.sqrt(eigenvalues / eigenvalues[-1])  # non-decreasing, ends at 1
    index = np.searchsorted(levels, ratio, side="left")
    return np.minimum(index, len(eigenvalues) - 1).astype(np.int64)


def direct_transfer(eigenvalues, band_edges, positions=None) -> np.ndarray:
    """t_ini = (ν_ini + ½)/k: low sounds drive low harmonics (thesis 6-4)."""
    k = len(eigenvalues)
    return (initial_indices(eigenvalues, band_edges, positions) + 0.5) / k


def reversed_transfer(eigenvalues, band_edges, positions=None) -> np.ndarray:
    """t_rev = (k − 1 − ν_ini + ½)/k: low sounds drive high harmonics."""
    k = len(eigenvalues)
    return (k - 1 - initial_indices(eigenvalues, band_edges, positions) + 0.5) / k


def gallery_epsilons(size: int) -> np.ndarray:
    """The S/2 compressions ε of the transfers: 0, 1, 2/S, 4/S, …"""
    half = size // 2
    return np.array([0.0, 1.0, *[2 * i / size for i in range(1, half - 1)]])[:half]


def gallery_intervals(size: int) -> np.ndarray:
    """The S/2 normalised amplification intervals I_ε = [ε², (ε + 2/S)²], ε = 0, 2/S, … (S/2, 2).
    """
    eps = 2 * np.arange(size // 2) / size
    return np.stack([eps ** 2, (eps + 2 / size) ** 2], axis=1)


CALIBRATIONS = ("strongest", "each")


def initial_gallery(basis, spectrogram, size: int = DEFAULT_GALLERY_SIZE,
                    amplitude: float | None = None,
                    calibration: str = "strongest") -> list[Mapping]:
    """The S items of the initial gallery (thesis 6.2.2, DESIGN §4), S even ≥ 2.

    Item i < S/2: transfer t_ini(ε_i·ξ), amplification +M_a on interval I_i, 0 elsewhere.
    Item S/2 + i: transfer t_rev(ε_i·ξ), amplification −M_a on interval I_i.
    ε_i = 0, 1, 2/S, 4/S, … ; I_i = [(2i/S)², ((2i+2)/S)²] of the normalised harmonic range:
    harmonic ν is in I_i when its cell centre (ν + ½)/k lies in [lower, upper) (the last one
    closed).
    M_a (unless `amplitude` is given) is calibrated so that the strongest item at full-scale input
    (g̃ ≡ 1) moves the vertices by TARGET_MOTION (5%) of the bounding-box diagonal, RMS (DESIGN).
    calibration="each" (not in DESIGN; an option) gives every item that moves at all its own M_a,
    so that each moves by 5%: with one shared M_a the ε = 0 items, which send all B bands to one
    harmonic, are tens to hundreds of times stronger than the others, which then hardly move.
    `spectrogram` may be a Spectrogram or its band edges (B+1,).
    """
    if calibration not in CALIBRATIONS:
        raise EigendanceError(f"unknown calibration '{calibration}' (expected one of "
                              f"{', '.join(CALIBRATIONS)})")
    if not isinstance(size, int | np.integer) or size < 2 or size % 2:
        raise EigendanceError(f"the gallery size must be an even number ≥ 2, got {size}")
    edges = getattr(spectrogram, "band_edges", spectrogram)
    edges = np.asarray(edges, dtype=np.float64)
    bands = len(edges) - 1
    k = basis.k
    half = size // 2
    xi = np.arange(bands, dtype=np.float64)
    centres = (np.arange(k) + 0.5) / k
    intervals = gallery_intervals(size)
    transfers, shapes = [], []
    for sign, transfer in ((1.0, direct_transfer), (-1.0, reversed_transfer)):
        for i, eps in enumerate(gallery_epsilons(size)):
            transfers.append(transfer(basis.eigenvalues, edges, eps * xi))
            lower, upper = intervals[i]
            inside = (centres >= lower) & ((centres < upper) if i < half - 1 else centres <= upper)
            shapes.append(sign * inside.astype(np.float64))
    if amplitude is not None:
        amplitudes = np.full(size, float(amplitude))
    elif calibration == "strongest":
        amplitudes = np.full(size, calibrate_amplitude(basis, transfers, shapes))
    else:
        motion = full_scale_motion(basis, [Mapping(t, a) for t, a in zip(transfers, shapes,
                                                                          strict=True)])
        if not motion.max() > 1e-12:
            raise EigendanceError("no initial gallery item moves this mesh (too few "
                                  "harmonics?); use a larger -k")
        target = TARGET_MOTION * bounding_box_diagonal(basis)
        # Items that cannot move (transfer and amplification never meet) keep M_a = 0 · shape.
        amplitudes = np.where(motion > 1e-9 * motion.max(), target / np.maximum(motion, 1e-300),
                              0.0)
    return [Mapping(t, m * a, None, f"gallery item {i}")
            for i, (t, a, m) in enumerate(zip(transfers, shapes, amplitudes, strict=True))]


def full_scale_motion(basis, mappings) -> np.ndarray:
    """RMS vertex displacement of each mapping at full-scale input g̃ ≡ 1, normalised units (S,)."""
    k = basis.k
    bands = mappings[0].bands
    phi = filters(mappings, np.ones(bands), k)  # (S, k)
    weights = (phi - 1.0)[:, :, None] * basis.coefficients[None]  # (S, k, 3)
    moved = basis.eigenvectors @ weights.transpose(1, 0, 2).reshape(k, -1)  # (n, 3S)
    squared = (moved ** 2).reshape(basis.n, len(mappings), 3).sum(axis=2)
    return np.sqrt(squared.mean(axis=0))


def bounding_box_diagonal(basis) -> float:
    vertices = basis.vertices
    return float(np.linalg.norm(vertices.max(axis=0) - vertices.min(axis=0)))


def calibrate_amplitude(basis, transfers, shapes) -> float:
    """M_a such that the strongest of the items (transfer, a = M_a·shape) moves 5% of the diagonal.
    """
    unit = [Mapping(t, a) for t, a in zip(transfers, shapes, strict=True)]
    motion = full_scale_motion(basis, unit)
    strongest = float(motion.max())
    if not strongest > 1e-12:
        raise EigendanceError("no initial gallery item moves this mesh (too few harmonics?); "
                              "use a larger -k")
    return TARGET_MOTION * bounding_box_diagonal(basis) / strongest


def strongest_item(basis, spectrogram, size: int = DEFAULT_GALLERY_SIZE) -> Mapping:
    """The initial-gallery item that moves the mesh most at full-scale input (the default)."""
    gallery = initial_gallery(basis, spectrogram, size, calibration="strongest")
    index = int(np.argmax(full_scale_motion(basis, gallery)))
    return gallery[index]


# ---------------------------------------------------------------------------------------------
# Breeding


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
    """

    MASK = 0xFFFFFFFF

    def __init__(self, seed: int):
        self.state = int(seed) & self.MASK

    def next_uint32(self) -> int:
        M = self.MASK
        self.state = (self.state + 0x6D2B79F5) & M
        a = self.state
        t = ((a ^ (a >> 15)) * (a | 1)) & M
        t = ((t + (((t ^ (t >> 7)) * (t | 61)) & M)) & M) ^ t
        return (t ^ (t >> 14)) & M

    def uniform(self) -> float:
        """A float in [0, 1): next_uint32() / 2^32."""
        return self.next_uint32() / 4294967296.0

    def below(self, count: int) -> int:
        """An integer in [0, count): ⌊uniform()·count⌋."""
        return min(count - 1, int(math.floor(self.uniform() * count)))


def cross(first, second, random: Mulberry32, mean_segment: float | None = None) -> np.ndarray:
    """Segment-wise convex combination of two vectors of length L (thesis 6.2.1).

    Until L entries are filled: draw the segment length n — n = 1, then while n < (entries left)
    draw u and stop if u < p, else n += 1 (a Geometric(p) length truncated to what is left, one
    uniform per trial), p = min(1, 1/mean_segment), mean_segment = L/4 by default; then draw
    r = uniform() and fill the next n entries with r·first + (1 − r)·second.
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


def breed(parents, size: int = DEFAULT_GALLERY_SIZE, seed: int = 0,
          mean_segment: float | None = None) -> list[Mapping]:
    """S children of the selected parents (thesis 6.2.1, DESIGN §4); deterministic for a seed.

    One Mulberry32(seed) stream; per child, in this order:
      1. parents: i = below(P), then j = below(P − 1), j += 1 if j ≥ i (so i ≠ j); with a single
         parent no draw is made and i = j = 0;
      2. transfer: u = uniform(); if u < ½, cross(parent_i.transfer, parent_j.transfer);
         else draw u = uniform() and copy parent i's transfer if u < ½, else parent j's;
      3. amplification: the same as 2 with the amplifications (an independent coin).
    Amplifications of other lengths than parent 0's are first resampled to its length K; child
    transfers are clipped to [0, 1] (a convex combination can overshoot 1 by one rounding).
    Children carry `seed` in their JSON.
    """
    parents = list(parents)
    if not parents:
        raise EigendanceError("breeding needs at least one parent mapping")
    if not isinstance(size, int | np.integer) or size < 1:
        raise EigendanceError(f"the gallery size must be a positive integer, got {size}")
    bands = parents[0].bands
    K = len(parents[0].amplification)
    for parent in parents:
        if parent.bands != bands:
            raise EigendanceError(f"{parent.name}: {parent.bands} bands, but "
                                  f"{parents[0].name} has {bands}; parents must agree")
    transfers = [p.transfer for p in parents]
    amplifications = [resample_amplification(p.amplification, K) for p in parents]
    random = Mulberry32(seed)
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
        children.append(Mapping(transfer, genes[1], int(seed), f"child {c}"))
    return children
