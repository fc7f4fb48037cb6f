"""STAND-IN for the audio branch's modules, used by the web server only when they are missing.

The real implementations belong to `eigendance.audio` (Spectrogram), `eigendance.demo_music`,
`eigendance.mapping` (Mapping, initial_gallery, breed) and `eigendance.animate` (positions_at),
owned by another branch. `eigendance.server.deps` imports those when present and falls back to
this file otherwise, so the web app and its tests run either way. Everything here follows
DESIGN §3–§4 in its simplest form: WAV input only, no PyAV.
"""

from __future__ import annotations

import io
import json
import math
import wave

import numpy as np

from eigendance.errors import EigendanceError


# --- spectrum (DESIGN §3) ------------------------------------------------------------------
class Spectrogram:
    def __init__(self, times, values, band_edges, rate, sample_rate, duration):
        self.times = np.asarray(times, dtype=np.float64)
        self.values = np.asarray(values, dtype=np.float32)
        self.band_edges = np.asarray(band_edges, dtype=np.float64)
        self.rate = float(rate)
        self.sample_rate = int(sample_rate)
        self.duration = float(duration)

    @classmethod
    def from_samples(cls, samples, sample_rate, rate=100, bands=64, floor=-80.0, tau=0.08):
        from scipy.signal import get_window

        samples = np.asarray(samples, dtype=np.float64)
        if samples.ndim == 2:
            samples = samples.mean(axis=1)
        sr = int(sample_rate)
        duration = len(samples) / sr
        size = 1 << math.ceil(math.log2(0.046 * sr))
        window = get_window("hann", size)
        frames = int(math.floor(duration * rate)) + 1
        centres = np.round(np.arange(frames) * sr / rate).astype(np.int64)
        padded = np.concatenate([np.zeros(size), samples, np.zeros(size)])
        index = centres[:, None] - size // 2 + np.arange(size)[None, :] + size
        magnitude = np.abs(np.fft.rfft(padded[index] * window, axis=1)) * 2 / window.sum()
        fmax = min(16000.0, sr / 2)
        edges = np.geomspace(20.0, fmax, bands + 1)
        freqs = np.arange(magnitude.shape[1]) * sr / size
        values = np.empty((frames, bands))
        for band in range(bands):
            inside = (freqs >= edges[band]) & (freqs < edges[band + 1])
            if inside.any():
                values[:, band] = magnitude[:, inside].max(axis=1)
            else:
                centre = math.sqrt(edges[band] * edges[band + 1])
                values[:, band] = [np.interp(centre, freqs, row) for row in magnitude]
        with np.errstate(divide="ignore"):
            loud = np.clip((20 * np.log10(values) - floor) / -floor, 0, 1)
        m = math.exp(-1 / (rate * tau))
        smooth = np.empty_like(loud)
        state = np.zeros(bands)
        for j in range(frames):
            state = m * state + (1 - m) * loud[j]
            smooth[j] = state
        return cls(np.arange(frames) / rate, smooth, edges, rate, sr, duration)

    @classmethod
    def from_file(cls, path, rate=100, bands=64, **options):
        samples, sr = read_wav(path)
        return cls.from_samples(samples, sr, rate=rate, bands=bands, **options)

    def at(self, times):
        times = np.asarray(times, dtype=np.float64)
        position = np.clip(times * self.rate, 0, len(self.times) - 1)
        low = np.floor(position).astype(np.int64)
        high = np.minimum(low + 1, len(self.times) - 1)
        fraction = (position - low)[..., None]
        return (1 - fraction) * self.values[low] + fraction * self.values[high]


def read_wav(path):
    try:
        with wave.open(str(path), "rb") as file:
            channels, width, sr = file.getnchannels(), file.getsampwidth(), file.getframerate()
            raw = file.readframes(file.getnframes())
    except (wave.Error, EOFError, OSError) as error:
        raise EigendanceError(f"{path}: cannot decode audio ({error})") from None
    if width == 2:
        samples = np.frombuffer(raw, "<i2").astype(np.float64) / 32768
    elif width == 4:
        samples = np.frombuffer(raw, "<i4").astype(np.float64) / 2**31
    elif width == 1:
        samples = (np.frombuffer(raw, np.uint8).astype(np.float64) - 128) / 128
    else:
        raise EigendanceError(f"{path}: unsupported WAV sample width {width}")
    if len(samples) == 0:
        raise EigendanceError(f"{path}: the audio is empty")
    return samples.reshape(-1, channels).mean(axis=1), sr


# --- procedural music -----------------------------------------------------------------------
def demo_music(seconds=30.0, sample_rate=22050):
    """A short procedural track: kick, snare, hats, bass line and chords at 120 bpm."""
    rng = np.random.default_rng(2012)
    t = np.arange(int(seconds * sample_rate)) / sample_rate
    out = np.zeros_like(t)
    beat = 0.5
    for start in np.arange(0, seconds, beat):
        i = int(start * sample_rate)
        n = min(len(t) - i, int(0.4 * sample_rate))
        local = t[:n]
        out[i:i + n] += 0.9 * np.sin(2 * np.pi * (50 + 80 * np.exp(-local * 30)) * local) \
            * np.exp(-local * 8)
        j = int((start + beat / 2) * sample_rate)
        m = min(len(t) - j, int(0.05 * sample_rate))
        if m > 0:
            decay = np.exp(-np.arange(m) / (0.01 * sample_rate))
            out[j:j + m] += 0.15 * rng.standard_normal(m) * decay
        if int(start / beat) % 2 == 1:
            m = min(len(t) - i, int(0.2 * sample_rate))
            decay = np.exp(-np.arange(m) / (0.04 * sample_rate))
            out[i:i + m] += 0.3 * rng.standard_normal(m) * decay
    roots = [55.0, 65.41, 49.0, 73.42]
    for bar in range(int(seconds / 2) + 1):
        root = roots[bar % 4]
        i, n = int(bar * 2 * sample_rate), int(2 * sample_rate)
        local = t[:max(0, min(n, len(t) - i))]
        env = np.exp(-(local % 0.5) * 3)
        chord = sum(np.sin(2 * np.pi * root * 4 * r * local) for r in (1, 1.26, 1.5))
        out[i:i + len(local)] += 0.25 * np.sin(2 * np.pi * root * local) * env + 0.06 * chord
    out /= np.abs(out).max() * 1.05
    return out.astype(np.float32), sample_rate


def write_wav(path, samples, sample_rate):
    data = (np.clip(samples, -1, 1) * 32767).astype("<i2").tobytes()
    buffer = io.BytesIO()
    with wave.open(buffer, "wb") as file:
        file.setnchannels(1)
        file.setsampwidth(2)
        file.setframerate(sample_rate)
        file.writeframes(data)
    from eigendance.files import atomic_write

    atomic_write(path, lambda f: f.write(buffer.getvalue()))


# --- mappings (DESIGN §4) -------------------------------------------------------------------
class Mapping:
    def __init__(self, transfer, amplification, seed=None):
        self.transfer = np.asarray(transfer, dtype=np.float64)
        self.amplification = np.asarray(amplification, dtype=np.float64)
        self.seed = seed

    @property
    def bands(self):
        return len(self.transfer)

    def resampled(self, k):
        K = len(self.amplification)
        if K == k:
            return self
        index = np.minimum(K - 1, np.floor((np.arange(k) + 0.5) / k * K).astype(np.int64))
        return Mapping(self.transfer, self.amplification[index], self.seed)

    def filter(self, values):
        values = np.asarray(values, dtype=np.float64)
        k = len(self.amplification)
        nu = np.minimum(k - 1, np.floor(self.transfer * k).astype(np.int64))
        sums = np.zeros(values.shape[:-1] + (k,))
        for band in range(self.bands):
            sums[..., nu[band]] += values[..., band]
        return self.amplification * sums + 1

    def to_json(self):
        return {"format": "eigendance.mapping", "version": 1, "bands": self.bands,
                "transfer": self.transfer.tolist(), "amplification": self.amplification.tolist(),
                "seed": self.seed}

    @classmethod
    def from_json(cls, data):
        if isinstance(data, str | bytes):
            data = json.loads(data)
        if not isinstance(data, dict) or data.get("format") != "eigendance.mapping":
            raise EigendanceError("not an eigendance mapping (format must be eigendance.mapping)")
        try:
            transfer = np.asarray(data["transfer"], dtype=np.float64)
            amplification = np.asarray(data["amplification"], dtype=np.float64)
        except (KeyError, TypeError, ValueError) as error:
            raise EigendanceError(f"malformed mapping ({error})") from None
        if (transfer.ndim != 1 or amplification.ndim != 1 or len(transfer) == 0
                or len(amplification) == 0 or not np.all(np.isfinite(transfer))
                or not np.all(np.isfinite(amplification))
                or transfer.min() < 0 or transfer.max() > 1):
            raise EigendanceError("malformed mapping: transfer in [0,1] and finite amplification")
        return cls(transfer, amplification, data.get("seed"))


def _direct_transfer(basis, spectrogram):
    edges = spectrogram.band_edges
    centres = np.sqrt(edges[:-1] * edges[1:])
    k = basis.k
    ratio = np.sqrt(np.maximum(basis.eigenvalues, 0) / basis.eigenvalues[-1])
    nu = np.searchsorted(ratio, centres / centres[-1] - 1e-12, side="left")
    nu = np.minimum(nu, k - 1)
    return (nu + 0.5) / k, (k - 1 - nu + 0.5) / k


def initial_gallery(basis, spectrogram, size=8, full_scale=1.0):
    k, bands = basis.k, spectrogram.values.shape[1]
    t_ini, t_rev = _direct_transfer(basis, spectrogram)
    half = max(1, size // 2)
    epsilons = [0.0] + [2 * i / size for i in range(half - 1)]
    epsilons = [0.0, 1.0] + [2 * i / size for i in range(1, half - 1)]
    items = []
    positions = np.arange(k) / k
    xi = np.arange(bands)
    for i in range(size):
        eps = epsilons[(i // 2) % len(epsilons)]
        base = t_ini if i % 2 == 0 else t_rev
        transfer = base[np.minimum(bands - 1, (eps * xi).astype(np.int64))]
        lo = (2 * (i % half) / size) ** 2
        hi = ((2 * (i % half) + 2) / size) ** 2
        sign = 1.0 if i < half else -1.0
        amplification = np.where((positions >= lo) & (positions < hi), sign, 0.0)
        if not amplification.any():
            amplification[min(k - 1, int(lo * k))] = sign
        items.append(Mapping(transfer, amplification))
    # Calibrate M_a: the strongest item moves vertices by ~5% of the diagonal (RMS) at full scale.
    diagonal = np.linalg.norm(basis.vertices.max(0) - basis.vertices.min(0))
    strongest = 0.0
    for item in items:
        phi = item.filter(np.full((1, bands), full_scale))[0]
        moved = basis.filter_positions(phi) - basis.vertices
        strongest = max(strongest, float(np.sqrt((moved ** 2).sum(1).mean())))
    gain = 0.05 * diagonal / strongest if strongest > 0 else 1.0
    for item in items:
        item.amplification = item.amplification * gain
    return items


def _cross(first, second, rng, mean_fraction=0.25):
    length = len(first)
    out = np.empty(length)
    p = 1 / max(1.0, mean_fraction * length)
    filled = 0
    while filled < length:
        n = min(length - filled, int(rng.geometric(p)))
        r = rng.uniform()
        out[filled:filled + n] = r * first[filled:filled + n] + (1 - r) * second[filled:filled + n]
        filled += n
    return out


def breed(parents, size=8, seed=None):
    if not parents:
        raise EigendanceError("breeding needs at least one selected parent")
    rng = np.random.default_rng(seed)
    children = []
    for _ in range(size):
        a = parents[rng.integers(len(parents))]
        b = parents[rng.integers(len(parents))]
        if rng.uniform() < 0.5:
            transfer = np.clip(_cross(a.transfer, b.transfer, rng), 0, 1)
        else:
            transfer = (a if rng.uniform() < 0.5 else b).transfer.copy()
        amp_b = b.resampled(len(a.amplification)).amplification
        if rng.uniform() < 0.5:
            amplification = _cross(a.amplification, amp_b, rng)
        else:
            amplification = (a.amplification if rng.uniform() < 0.5 else amp_b).copy()
        children.append(Mapping(transfer, amplification, seed))
    return children


def positions_at(basis, spectrogram, mapping, times):
    mapping = mapping.resampled(basis.k)
    phi = mapping.filter(spectrogram.at(np.atleast_1d(times)))
    return basis.filter_positions(phi)
