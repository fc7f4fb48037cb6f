"""A rig's palette in a mapping: how its vibration modes move besides the filter
(docs/design.md#modal-motion, docs/design.md#mapping-file: the `modes` field).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from eigendance.checks import finite_vector, number, numbers, shown
from eigendance.errors import InputError

TEMPO_MODES = ("beat", "free")  # a rig's palette: locked to the song's beats, or free-running


@dataclass
class ModeSettings:
    """How a rig's vibration modes move besides the filter: the palette (design.md#modal-motion).

    Every field may be None: the default rule of `eigendance.modal.motion` then decides.
    selected: indices of the modes that move; amplitudes: per selected mode, its largest body
    rotation at φ = 1, radians; phases: per selected mode, γ in radians; time_scale: s;
    tempo: "beat" (locked to the song's beats, docs/design.md#tempo-lock) or "free" (the
    thesis's free-running sinusoids); None: "beat" when the song has beats.

    Parameters
    ----------
    selected, amplitudes, phases, time_scale, tempo : as above.
    """

    selected: np.ndarray | None = None
    amplitudes: np.ndarray | None = None
    phases: np.ndarray | None = None
    time_scale: float | None = None
    tempo: str | None = None

    def to_json(self) -> dict:
        """The `modes` field of a mapping document.

        Returns
        -------
        dict; null for the fields left to the default rule.
        """
        return {"selected": _listed(self.selected, int),
                "amplitudes": _listed(self.amplitudes), "phases": _listed(self.phases),
                "time_scale": None if self.time_scale is None else float(self.time_scale),
                "tempo": self.tempo}

    @classmethod
    def from_json(cls, data, name: str) -> ModeSettings:
        """The `modes` field of a mapping document, checked.

        Parameters
        ----------
        data : the field (a dict).
        name : how messages call the mapping.

        Returns
        -------
        ModeSettings; InputError naming the field.
        """
        if not isinstance(data, dict):
            raise InputError(f"{name}: modes must be an object or null")
        selected = data.get("selected")
        if selected is not None:
            if not isinstance(selected, list) or not selected or not all(
                    isinstance(i, int) and not isinstance(i, bool) and 0 <= i < 1 << 20
                    for i in selected):
                raise InputError(f"{name}: modes.selected must be a non-empty list of mode "
                                 "indices or null")
            if len(set(selected)) != len(selected):
                raise InputError(f"{name}: modes.selected lists a mode twice")
        vectors = {}
        for key in ("amplitudes", "phases"):
            value = data.get(key)
            vectors[key] = None if value is None else \
                np.array(numbers(value, f"{name}: modes.{key}"), dtype=np.float64)
            if vectors[key] is not None:
                finite_vector(vectors[key], f"{name}: modes.{key}")
                if selected is not None and len(vectors[key]) != len(selected):
                    raise InputError(f"{name}: modes.{key} has {len(vectors[key])} values for "
                                     f"{len(selected)} selected modes")
        if vectors["amplitudes"] is not None and np.any(vectors["amplitudes"] < 0):
            raise InputError(f"{name}: modes.amplitudes must be ≥ 0")
        time_scale = data.get("time_scale")
        if time_scale is not None:
            time_scale = number(time_scale, f"{name}: modes.time_scale")
        if time_scale is not None and not time_scale > 0:
            raise InputError(f"{name}: modes.time_scale must be positive")
        tempo = data.get("tempo")
        if tempo is not None and tempo not in TEMPO_MODES:
            raise InputError(f"{name}: modes.tempo must be one of {', '.join(TEMPO_MODES)} or "
                             f"null, got {shown(tempo)}")
        return cls(None if selected is None else np.array(selected, dtype=np.int64),
                   vectors["amplitudes"], vectors["phases"], time_scale, tempo)


def _listed(array, kind=float) -> list | None:
    return None if array is None else [kind(x) for x in array]
