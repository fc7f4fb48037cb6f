"""Mapping sound to motion: transfer, amplification and the filter (docs/design.md#mapping).

A `Mapping` holds a transfer t (B,) — band ξ ↦ normalised frequency in [0, 1] — and an
amplification a (K,). For k targets (the harmonics of a mesh, or the vibration modes of a rig):

    ν(ξ) = min(k − 1, ⌊t(ξ)·k⌋),   φ(ν) = a_k(ν) · Σ_{ξ: ν(ξ)=ν} g̃(ξ) + b,

where a_k is a resampled to length k by normalised index: a_k(ν) = a(min(K − 1, ⌊(ν + ½)·K/k⌋))
(each target takes the amplification of the cell its centre falls in; a_k = a when K = k), and
the offset b is 1 for harmonics (thesis 6-1: a ≡ 0 leaves the mesh still) and the mapping's
own for modes. Version 3 shapes g̃ first (envelopes, auto-range: `eigendance.music.envelope`)
and adds a pulse on the beats to a range of targets:

    φ(ν) = gain·g(t)·a_k(ν)·(Σ_{ξ: ν(ξ)=ν} e(ξ, t) + amount·p(t)·[ν in the pulse's range]) + b,

g(t) the section gene (optional `sections`: per part of the song a gain factor, cycled; the song's
parts are `Rhythm.sections`): g(t) = sections[s mod len(sections)] with s the number of section
starts ≤ t, and g ≡ 1 without the gene or without sections (docs/design.md#mapping).

`Mapping.play` is the one path from a song to φ that every caller takes (animate, export,
render, the rig motion, the gallery).
"""

from __future__ import annotations

import json
import os
from dataclasses import dataclass, field, replace

import numpy as np

from eigendance.checks import finite_vector, number, numbers, shown
from eigendance.errors import InputError
from eigendance.files import read_json
from eigendance.harmonic.construction import BasisRecord
from eigendance.music.envelope import Envelope, Pulse, shape_values
from eigendance.music.filter import filters, harmonic_indices, resample_amplification
from eigendance.music.mode_settings import ModeSettings
from eigendance.writes import atomic_write

FORMAT = "eigendance.mapping"
VERSION = 3  # written; versions 1 (transfer, amplification, seed) and 2 are still read
READABLE_VERSIONS = (1, 2, 3)
MAX_SECTIONS = 64  # the most gain factors a section gene holds
MAX_SECTION_GAIN = 10.0


SHADINGS = ("smooth", "flat", "wireframe")


@dataclass
class Mapping:
    """A sound-to-motion mapping, with everything the player applies (docs/design.md#mapping).

    Parameters
    ----------
    transfer : (B,) values in [0, 1]: band ξ drives target ⌊t(ξ)·k⌋ of k.
    amplification : (K,) finite values, resampled to the k targets by normalised index.
    seed : the breeding seed that made it, or None.
    name : how messages call it (a file name).
    gain : ≥ 0, multiplies the amplification (the player's gain slider).
    smoothing : ≥ 0 s, extra exponential smoothing of the spectrogram (`Spectrogram.smoothed`).
    offset : b, added to the filter of a rig's modes (0: silence is the rest pose; 1: the
        thesis's idle sway). Harmonics always add 1.
    modes : a rig's palette (`ModeSettings`), or None.
    deformed_normal_weight : weight of the deformed triangle's flat normal against the original
        vertex normal, in [0, 1] (thesis Fig. 6.4(d): 0.4).
    shading : "smooth", "flat" or "wireframe".
    materials : draw a model that has materials in them (False: in the clay studio look);
        a model without materials is drawn in clay either way (docs/design.md#mapping-file).
    envelope : per-band attack, release, threshold and auto-range (`Envelope`; version 3).
    pulse : kicks on the beats routed to a range of targets (`Pulse`; version 3).
    surface : a rig's surface genes: the mapping its skin's harmonics play while its modes
        follow this one (docs/design.md#surface-of-a-rig), or None.
    basis : the basis of a mesh it was made on (`BasisRecord`: k, construction, samples), or
        None (a rig's, or a mapping from before the record: the commands take the default k).
    sections : the section gene, a gain factor in [0, 10] per part of the song (cycled), or
        None (the dance keeps its gain throughout; `section_gain`).

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
    gain: float = 1.0
    smoothing: float = 0.0
    offset: float = 0.0
    modes: ModeSettings | None = None
    deformed_normal_weight: float = 0.4
    shading: str = "smooth"
    materials: bool = True
    envelope: Envelope = field(default_factory=Envelope)
    pulse: Pulse = field(default_factory=Pulse)
    surface: Mapping | None = None
    basis: BasisRecord | None = None
    sections: tuple | None = None

    def __post_init__(self):
        self.transfer = np.asarray(self.transfer, dtype=np.float64)
        self.amplification = np.asarray(self.amplification, dtype=np.float64)
        finite_vector(self.transfer, f"{self.name}: transfer", unit=True)
        finite_vector(self.amplification, f"{self.name}: amplification")
        for key, low, high in (("gain", 0.0, 1e6), ("smoothing", 0.0, 60.0),
                               ("offset", -1e6, 1e6), ("deformed_normal_weight", 0.0, 1.0)):
            setattr(self, key, number(getattr(self, key), f"{self.name}: {key}", low, high))
        if self.shading not in SHADINGS:
            raise InputError(f"{self.name}: shading must be one of {', '.join(SHADINGS)}, got "
                             f"{self.shading!r}")
        if not isinstance(self.materials, bool | np.bool_):
            raise InputError(f"{self.name}: look.materials must be true or false, got "
                             f"{shown(self.materials)}")
        self.materials = bool(self.materials)
        self.envelope = self.envelope.for_bands(self.bands, self.name)
        if self.sections is not None:
            self.sections = _section_gene(self.sections, self.name)
        if self.surface is not None and self.surface.surface is not None:
            raise InputError(f"{self.name}: a surface mapping has no surface of its own")

    @property
    def bands(self) -> int:
        """B, the transfer's length."""
        return len(self.transfer)

    def harmonic_indices(self, k: int) -> np.ndarray:
        """ν(ξ) = min(k − 1, ⌊t(ξ)·k⌋) for each band, int64 (B,).

        Parameters
        ----------
        k : the targets.

        Returns
        -------
        (B,).
        """
        return harmonic_indices(self.transfer, k)

    def driven(self, k: int) -> np.ndarray:
        """The targets the mapping moves: ν(ξ) of some band with a non-zero amplification
        (every other φ_ν stays at the offset), ascending.

        Parameters
        ----------
        k : the targets.

        Returns
        -------
        (J,) int64, J ≤ B.
        """
        targets = np.unique(self.harmonic_indices(k))
        return targets[self.amplification_for(k)[targets] != 0]

    def amplification_for(self, k: int) -> np.ndarray:
        """The amplification resampled to k targets, times the gain.

        Parameters
        ----------
        k : the targets.

        Returns
        -------
        (k,).
        """
        return self.gain * resample_amplification(self.amplification, k)

    def filter(self, values, k: int, offset: float = 1.0) -> np.ndarray:
        """φ = gain·a_k·Σ g̃ + offset for band values (…, B) → (…, k).

        offset: 1 for harmonics (a ≡ 0 leaves a mesh still), `self.offset` for a rig's modes.
        `filters` evaluates many mappings at once.

        Parameters
        ----------
        values : (…, B) band values in [0, 1].
        k : the targets.
        offset : b.

        Returns
        -------
        (…, k).
        """
        return filters([self], values, k, offset)[0]

    def play(self, spectrogram, times, k: int, offset: float = 1.0) -> np.ndarray:
        """φ of this mapping on a song: the one path from a song to the filter (module
        docstring). The spectrogram is smoothed by `smoothing`, shaped by the envelope
        (`shaped`), interpolated at the times, and the pulse (the song's rhythm) added.

        Parameters
        ----------
        spectrogram : the song (`Spectrogram`, its `rhythm` for the pulse).
        times : (T,) s of the song.
        k : the targets.
        offset : b.

        Returns
        -------
        (T, k).

        Example
        -------
        >>> from eigendance.music.spectrogram import Spectrogram
        >>> song = Spectrogram([0.0, 0.5], [20.0, 200.0, 2000.0], np.float32([[0, 1], [1, 1]]),
        ...                    2.0, 8000, 1.0)
        >>> Mapping([0.0, 0.9], [1.0]).play(song, [0.0, 0.25], 2).tolist()
        [[1.0, 2.0], [1.5, 2.0]]
        """
        return self.player(spectrogram)(times, k, offset)

    def player(self, spectrogram):
        """`play` with the song shaped once, for callers that ask for many chunks of times.

        Parameters
        ----------
        spectrogram : the song.

        Returns
        -------
        function (times (T,) s, k, offset=1.0) → φ (T, k).
        """
        shaped = self.shaped(spectrogram)

        def phi(times, k: int, offset: float = 1.0) -> np.ndarray:
            times = np.asarray(times, dtype=np.float64)
            phi = filters([self], shaped.at(times), k, offset,
                          self.kicks(spectrogram, times)[None])[0]
            if self.sections is None:
                return phi
            return offset + np.asarray(self.section_gain(spectrogram, times))[..., None] * (
                phi - offset)

        return phi

    def with_genes(self, transfer, amplification, seed: int | None, name: str) -> Mapping:
        """A mapping with other transfer and amplification and this one's other settings.

        Parameters
        ----------
        transfer : (B,).
        amplification : (K,).
        seed : the breeding seed, or None.
        name : how it is called.

        Returns
        -------
        Mapping.
        """
        return replace(self, transfer=transfer, amplification=amplification, seed=seed,
                       name=name)

    def shaped(self, spectrogram):
        """The spectrogram as this mapping hears it: smoothed by `smoothing`, then shaped by
        the envelope (values cast to float32, as stored and as the page holds them).

        Parameters
        ----------
        spectrogram : the song.

        Returns
        -------
        Spectrogram (the smoothed one itself when the envelope is the identity).
        """
        smoothed = spectrogram.smoothed(self.smoothing)
        if self.envelope.is_identity:
            return smoothed
        values = shape_values(smoothed.values, smoothed.rate, self.envelope)
        return replace(smoothed, values=values.astype(np.float32))

    def kicks(self, spectrogram, times) -> np.ndarray:
        """amount·p(t): the pulse at `times` (0 without a pulse or beats).

        Parameters
        ----------
        spectrogram : the song (its `rhythm`).
        times : (T,) s.

        Returns
        -------
        (T,) in band-loudness units.
        """
        times = np.asarray(times, dtype=np.float64)
        if not self.pulse.amount > 0:
            return np.zeros(times.shape)
        rhythm = getattr(spectrogram, "rhythm", None)
        return self.pulse.amount * self.pulse.signal(rhythm, times)

    def section_gain(self, spectrogram, times) -> np.ndarray:
        """g(t): the section gene's factor for the part of the song at each time (module
        docstring; 1 without the gene or without the song's sections).

        Parameters
        ----------
        spectrogram : the song (its `rhythm.sections`).
        times : (T,) s.

        Returns
        -------
        (T,) ≥ 0.
        """
        times = np.asarray(times, dtype=np.float64)
        starts = getattr(getattr(spectrogram, "rhythm", None), "sections", np.zeros(0))
        if self.sections is None or not len(starts):
            return np.ones(times.shape)
        part = np.searchsorted(starts, times, side="right")
        return np.asarray(self.sections, dtype=np.float64)[part % len(self.sections)]

    # JSON (docs/design.md#mapping-file) ------------------------------------------------------

    def to_json(self) -> dict:
        """The mapping document, version 3 (docs/design.md#mapping-file).

        Returns
        -------
        dict, ready for json.dump.
        """
        document = {"format": FORMAT, "version": VERSION, "bands": self.bands,
                "transfer": [float(x) for x in self.transfer],
                "amplification": [float(x) for x in self.amplification],
                "seed": None if self.seed is None else int(self.seed),
                "gain": self.gain, "smoothing": self.smoothing, "offset": self.offset,
                "modes": None if self.modes is None else self.modes.to_json(),
                "look": {"deformed_normal_weight": self.deformed_normal_weight,
                         "shading": self.shading, "materials": self.materials},
                "envelope": self.envelope.to_json(), "pulse": self.pulse.to_json(),
                "basis": None if self.basis is None else self.basis.to_json()}
        if self.surface is not None:  # only a rig's dance with a rippling skin has it
            document["surface"] = self.surface.to_json()
        if self.sections is not None:  # written only with the gene: older readers see as before
            document["sections"] = list(self.sections)
        return document

    @classmethod
    def from_json(cls, data, name: str = "mapping") -> Mapping:
        """Validate a parsed mapping document (version 1, 2 or 3); every problem is a one-line
        error naming the field.

        Parameters
        ----------
        data : the parsed document.
        name : how messages call it.

        Returns
        -------
        Mapping.
        """
        if not isinstance(data, dict):
            raise InputError(f"{name}: a mapping must be a JSON object")
        if data.get("format") != FORMAT:
            raise InputError(f"{name}: format must be \"{FORMAT}\", "
                             f"got {shown(data.get('format'))}")
        version = data.get("version")
        if version not in READABLE_VERSIONS or isinstance(version, bool):
            raise InputError(f"{name}: version must be one of {READABLE_VERSIONS}, "
                             f"got {shown(version)}")
        bands = data.get("bands")
        if not isinstance(bands, int) or isinstance(bands, bool) or not 1 <= bands <= 1 << 16:
            raise InputError(f"{name}: bands must be a positive integer, got {shown(bands)}")
        transfer = numbers(data.get("transfer"), f"{name}: transfer")
        if len(transfer) != bands:
            raise InputError(f"{name}: transfer has {len(transfer)} values; bands says {bands}")
        amplification = numbers(data.get("amplification"), f"{name}: amplification")
        seed = data.get("seed")
        if seed is not None and (not isinstance(seed, int) or isinstance(seed, bool)
                                 or not 0 <= seed < 1 << 64):
            raise InputError(f"{name}: seed must be an integer or null (0 to 2⁶⁴ − 1), "
                             f"got {shown(seed)}")
        settings = {}
        if version >= 2:
            for key in ("gain", "smoothing", "offset"):
                if key in data:
                    settings[key] = number(data[key], f"{name}: {key}")
            if data.get("modes") is not None:
                settings["modes"] = ModeSettings.from_json(data["modes"], name)
            look = data.get("look", {})
            if not isinstance(look, dict):
                raise InputError(f"{name}: look must be an object")
            if "deformed_normal_weight" in look:
                settings["deformed_normal_weight"] = number(
                    look["deformed_normal_weight"], f"{name}: look.deformed_normal_weight")
            if "shading" in look:
                settings["shading"] = look["shading"]
            if "materials" in look:
                settings["materials"] = look["materials"]
        if version >= 3:
            if data.get("envelope") is not None:
                settings["envelope"] = Envelope.from_json(data["envelope"], name)
            if data.get("pulse") is not None:
                settings["pulse"] = Pulse.from_json(data["pulse"], name)
            if data.get("surface") is not None:
                settings["surface"] = Mapping.from_json(data["surface"], f"{name}: surface")
            if data.get("basis") is not None:
                settings["basis"] = BasisRecord.from_json(data["basis"], name)
            if data.get("sections") is not None:
                settings["sections"] = data["sections"]
        return cls(np.array(transfer, dtype=np.float64), np.array(amplification, dtype=np.float64),
                   seed, name, **settings)

    def save(self, path: str | os.PathLike) -> None:
        """Write the mapping as JSON, atomically (one field per line).

        Parameters
        ----------
        path : the .json to write.
        """
        fields = [f" {json.dumps(key)}: {json.dumps(value)}" for key, value in
                  self.to_json().items()]
        text = "{\n" + ",\n".join(fields) + "\n}\n"
        atomic_write(path, lambda file: file.write(text.encode()))

    @classmethod
    def load(cls, path: str | os.PathLike) -> Mapping:
        """Read a mapping file (any readable version).

        Parameters
        ----------
        path : a mapping file.

        Returns
        -------
        Mapping.
        """
        return cls.from_json(read_json(path), os.path.basename(os.fspath(path)))


def _section_gene(values, name: str) -> tuple:
    """The section gene checked: 1 … MAX_SECTIONS numbers in [0, MAX_SECTION_GAIN]."""
    if isinstance(values, tuple | np.ndarray):
        values = [float(x) for x in values]
    values = numbers(values, f"{name}: sections")
    if len(values) > MAX_SECTIONS or not all(0 <= x <= MAX_SECTION_GAIN for x in values):
        raise InputError(f"{name}: sections must be 1 to {MAX_SECTIONS} gain factors in "
                         f"[0, {MAX_SECTION_GAIN:g}]")
    return tuple(float(x) for x in values)
