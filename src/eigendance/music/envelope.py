"""How a mapping shapes the music before the filter: envelopes and the pulse
(docs/design.md#mapping, mapping file version 3).

Envelope (per band ξ, over the spectrogram's frames j at `rate` frames/s, after the mapping's
`smoothing`), in this order:

1. auto-range (song-relative): v ← clip((v − P5_ξ)/(P95_ξ − P5_ξ), 0, 1), P5_ξ and P95_ξ the
   5th and 95th percentiles (linear interpolation, numpy's default) of band ξ over the song;
   a band whose P95 − P5 ≤ 10⁻⁶ carries nothing and becomes 0;
2. threshold θ_ξ ∈ [0, 1]: v < θ_ξ → 0 (Blender's bake sound);
3. attack A_ξ and release R_ξ (s), Blender's envelope follower:
   e_j = v_j + m·(e_{j−1} − v_j), m = exp(−1/(rate·A_ξ)) while v_j > e_{j−1} (rising) and
   exp(−1/(rate·R_ξ)) otherwise (m = 0 for a time of 0), e_{−1} = 0.

The defaults (no auto-range, thresholds 0, attacks and releases 0) leave the values unchanged:
mappings of versions 1 and 2 play as before. Between frames the shaped values are interpolated
linearly (`Spectrogram.at`).

Pulse: the song's beats (or onsets) kick the targets of a range. At time t, with e the last
event at or before t, p(t) = w(e)·exp(−(t − e)/decay) (0 before the first event, and for a song
without rhythm or beats), where w(e) is the bar's accent at a beat (`Rhythm.downbeat_accent`:
1 + DOWNBEAT_ACCENT on a bar's first beat, 1 on the others and for a song without bars, as the
rig's tempo lock accents it) and 1 at an onset; target ν of k is in the range [low, high] when
low ≤ (ν + ½)/k ≤ high. The filter adds `amount`·p(t) to the band sum of every target in the
range (`eigendance.music.filter.filters`).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from eigendance.checks import number, shown
from eigendance.errors import InputError

AUTO_RANGE = (5.0, 95.0)  # percentiles of each band that auto-range maps to 0 and 1
FLAT_BAND = 1e-6  # a band whose percentiles differ by less carries nothing
MAX_TIME = 60.0  # s: the longest attack, release or decay
PULSE_SOURCES = ("beats", "onsets")


@dataclass
class Envelope:
    """Per band: attack and release (s), threshold in [0, 1]; auto_range (module docstring).

    Arrays hold one value per band, or one value for all (broadcast when applied).

    Parameters
    ----------
    attack, release : (B,) or (1,) s, in [0, MAX_TIME] (0: follows at once).
    threshold : (B,) or (1,) in [0, 1] (0: no gate).
    auto_range : map each band's [P5, P95] over the song to [0, 1] first.
    """

    attack: np.ndarray = field(default_factory=lambda: np.zeros(1))
    release: np.ndarray = field(default_factory=lambda: np.zeros(1))
    threshold: np.ndarray = field(default_factory=lambda: np.zeros(1))
    auto_range: bool = False

    def __post_init__(self):
        for key, high in (("attack", MAX_TIME), ("release", MAX_TIME), ("threshold", 1.0)):
            value = np.atleast_1d(np.asarray(getattr(self, key), dtype=np.float64))
            if value.ndim != 1 or not len(value) or not np.all(np.isfinite(value)) or \
                    np.any(value < 0) or np.any(value > high):
                raise InputError(f"envelope.{key} must be numbers in [0, {high:g}]")
            setattr(self, key, value)
        self.auto_range = bool(self.auto_range)

    @property
    def is_identity(self) -> bool:
        """Whether it leaves the values unchanged (the defaults: versions 1 and 2)."""
        return not self.auto_range and not (np.any(self.attack) or np.any(self.release)
                                            or np.any(self.threshold))

    def key(self) -> tuple:
        """A hashable summary (for caches of shaped spectrograms).

        Returns
        -------
        tuple of auto_range and the arrays' bytes.
        """
        return (self.auto_range, self.attack.tobytes(), self.release.tobytes(),
                self.threshold.tobytes())

    def for_bands(self, bands: int, name: str = "mapping") -> Envelope:
        """The envelope with one value per band (InputError if a length is neither 1 nor B).

        Parameters
        ----------
        bands : B.
        name : how messages call the mapping.

        Returns
        -------
        Envelope with (B,) arrays.
        """
        values = {}
        for key in ("attack", "release", "threshold"):
            value = getattr(self, key)
            if len(value) not in (1, bands):
                raise InputError(f"{name}: envelope.{key} has {len(value)} values for "
                                 f"{bands} bands")
            values[key] = np.broadcast_to(value, (bands,)).copy()
        return Envelope(values["attack"], values["release"], values["threshold"],
                        self.auto_range)

    def to_json(self) -> dict:
        """The `envelope` field of a mapping document (version 3).

        Returns
        -------
        {"attack", "release", "threshold": lists of numbers, "auto_range": bool}.
        """
        return {"attack": [float(x) for x in self.attack],
                "release": [float(x) for x in self.release],
                "threshold": [float(x) for x in self.threshold],
                "auto_range": self.auto_range}

    @classmethod
    def from_json(cls, data, name: str) -> Envelope:
        """The `envelope` field of a mapping document, checked.

        Parameters
        ----------
        data : the field (a dict).
        name : how messages call the mapping.

        Returns
        -------
        Envelope; InputError naming the field.
        """
        if not isinstance(data, dict):
            raise InputError(f"{name}: envelope must be an object")
        values = {}
        for key in ("attack", "release", "threshold"):
            value = data.get(key, 0.0)
            if not isinstance(value, list):
                value = [value]
            if not value:
                raise InputError(f"{name}: envelope.{key} must be a number or a list of numbers")
            values[key] = np.array([number(x, f"{name}: envelope.{key}") for x in value])
        auto = data.get("auto_range", False)
        if not isinstance(auto, bool):
            raise InputError(f"{name}: envelope.auto_range must be true or false")
        try:
            return cls(values["attack"], values["release"], values["threshold"], auto)
        except InputError as error:
            raise InputError(f"{name}: {error}") from None


def follower_memory(times: np.ndarray, rate: float) -> np.ndarray:
    """The follower's memory m = exp(−1/(rate·τ)) per band, 0 where τ = 0.

    Parameters
    ----------
    times : (B,) time constants τ, s.
    rate : frames per second.

    Returns
    -------
    (B,) in [0, 1).
    """
    times = np.asarray(times, dtype=np.float64)
    with np.errstate(divide="ignore"):
        return np.where(times > 0, np.exp(-1.0 / (rate * np.maximum(times, 1e-300))), 0.0)


def auto_ranged(values: np.ndarray) -> np.ndarray:
    """Each band (last axis) mapped from its [P5, P95] over the frames (axis −2) to [0, 1].

    Parameters
    ----------
    values : (T, B) band values.

    Returns
    -------
    (T, B) in [0, 1]; 0 for a flat band.
    """
    low, high = np.percentile(values, AUTO_RANGE, axis=-2, keepdims=True)
    span = high - low
    flat = span <= FLAT_BAND
    scaled = (values - low) / np.where(flat, 1.0, span)
    return np.where(flat, 0.0, np.clip(scaled, 0.0, 1.0))


def shape_values(values, rate: float, envelope: Envelope) -> np.ndarray:
    """The envelope (module docstring) applied to band values (T, B) at `rate` frames/s →
    (T, B) float64 in [0, 1]. Sequential over the frames, vectorised over the bands.

    Parameters
    ----------
    values : (T, B) band values in [0, 1].
    rate : frames per second.
    envelope : the envelope.

    Returns
    -------
    (T, B) float64 (the values themselves when the envelope is the identity).

    Example
    -------
    >>> steps = np.repeat([[0.0], [1.0], [0.0]], 3, axis=0)      # off, on, off: 3 frames each
    >>> slow = Envelope(attack=[0.01], release=[0.02])           # at 100 frames/s: m = e⁻¹, e^−½
    >>> shape_values(steps, 100.0, slow).ravel().round(3).tolist()
    [0.0, 0.0, 0.0, 0.632, 0.865, 0.95, 0.576, 0.35, 0.212]
    """
    values = np.asarray(values, dtype=np.float64)
    if envelope.is_identity:
        return values
    bands = values.shape[-1]
    envelope = envelope.for_bands(bands)
    if envelope.auto_range:
        values = auto_ranged(values)
    values = np.where(values < envelope.threshold, 0.0, values)
    rise = follower_memory(envelope.attack, rate)
    fall = follower_memory(envelope.release, rate)
    if not (np.any(rise) or np.any(fall)):
        return values
    out = np.empty_like(values)
    state = np.zeros(values.shape[1:])
    for j, frame in enumerate(values):
        memory = np.where(frame > state, rise, fall)
        state = frame + memory * (state - frame)
        out[j] = state
    return out


@dataclass
class Pulse:
    """Kicks on the song's beats or onsets, routed to a range of targets (module docstring).

    source: "beats" or "onsets"; amount: what a kick adds to the band sum of each target in
    the range (in band-loudness units, ≥ 0; 0: no pulse); decay: s (> 0); low, high: the range
    of normalised targets, 0 ≤ low ≤ high ≤ 1.

    Parameters
    ----------
    amount, decay, low, high, source : as above.
    """

    amount: float = 0.0
    decay: float = 0.15
    low: float = 0.0
    high: float = 1.0
    source: str = "beats"

    def __post_init__(self):
        for key, low, high in (("amount", 0.0, 1e6), ("decay", 1e-3, MAX_TIME),
                               ("low", 0.0, 1.0), ("high", 0.0, 1.0)):
            setattr(self, key, number(getattr(self, key), f"pulse.{key}", low, high))
        if self.low > self.high:
            raise InputError(f"pulse.range must have low ≤ high, got [{self.low:g}, "
                             f"{self.high:g}]")
        if self.source not in PULSE_SOURCES:
            raise InputError(f"pulse.source must be one of {', '.join(PULSE_SOURCES)}, not "
                             f"{shown(self.source)}")

    def routed(self, k: int) -> np.ndarray:
        """Which of k targets the pulse kicks: those whose centre (ν + ½)/k is in the range.

        Parameters
        ----------
        k : the targets.

        Returns
        -------
        (k,) float64: 1 in the range, 0 elsewhere.
        """
        centres = (np.arange(k) + 0.5) / k
        return ((centres >= self.low) & (centres <= self.high)).astype(np.float64)

    def events(self, rhythm) -> np.ndarray:
        """The event times that kick: the rhythm's beats or onsets (none without one).

        Parameters
        ----------
        rhythm : the song's `Rhythm`, or None.

        Returns
        -------
        (E,) s, ascending (empty without a pulse, a rhythm or beats).
        """
        if rhythm is None or not self.amount > 0:
            return np.zeros(0)
        if self.source == "beats":
            return rhythm.beats if rhythm.has_beats else np.zeros(0)
        return rhythm.onsets

    def accents(self, rhythm, events) -> np.ndarray:
        """w(e): how strong each event's kick is, the bar's accent at a beat
        (`Rhythm.downbeat_accent`: 1 + DOWNBEAT_ACCENT on a bar's first beat, else 1), 1 at an
        onset.

        Parameters
        ----------
        rhythm : the song's `Rhythm` (the events are its).
        events : (E,) s, `events`.

        Returns
        -------
        (E,) ≥ 1.
        """
        if self.source != "beats" or not len(events):
            return np.ones(len(events))
        return rhythm.downbeat_accent(events)

    def signal(self, rhythm, times) -> np.ndarray:
        """p(t) = w(e)·exp(−(t − e)/decay) after the last event e ≤ t (`accents`), else 0.

        Parameters
        ----------
        rhythm : the song's `Rhythm`, or None.
        times : (…,) s.

        Returns
        -------
        (…,) in [0, 1 + DOWNBEAT_ACCENT].
        """
        times = np.asarray(times, dtype=np.float64)
        events = self.events(rhythm)
        if not len(events):
            return np.zeros(times.shape)
        last = np.searchsorted(events, times, side="right") - 1
        since = times - events[np.maximum(last, 0)]
        weight = self.accents(rhythm, events)[np.maximum(last, 0)]
        return np.where(last >= 0, weight * np.exp(-np.maximum(since, 0.0) / self.decay), 0.0)

    def to_json(self) -> dict:
        """The `pulse` field of a mapping document (version 3).

        Returns
        -------
        {"source", "amount", "decay", "range": [low, high]}.
        """
        return {"source": self.source, "amount": self.amount, "decay": self.decay,
                "range": [self.low, self.high]}

    @classmethod
    def from_json(cls, data, name: str) -> Pulse:
        """The `pulse` field of a mapping document, checked.

        Parameters
        ----------
        data : the field (a dict).
        name : how messages call the mapping.

        Returns
        -------
        Pulse; InputError naming the field.
        """
        if not isinstance(data, dict):
            raise InputError(f"{name}: pulse must be an object")
        span = data.get("range", [0.0, 1.0])
        if not isinstance(span, list) or len(span) != 2:
            raise InputError(f"{name}: pulse.range must be [low, high]")
        try:
            return cls(data.get("amount", 0.0), data.get("decay", 0.15), span[0], span[1],
                       data.get("source", "beats"))
        except InputError as error:
            raise InputError(f"{name}: {error}") from None
