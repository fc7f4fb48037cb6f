"""A show's set list, from TOML (docs/design.md#show).

```toml
[set]
name = "Friday"        # optional
loop = true            # after the last cue, the first again (default false: stay on the last)
fade_beats = 4         # crossfade of a change, beats (default 4; 0: a cut)
slots = ["Kick", "Drift"]   # presets on the keys 1–9 (default: the favourites)

[[cue]]
name = "intro"         # optional (default: the preset's or the model's name)
model = "cat.obj"      # a mesh or rig file, relative to the set file, or a built-in rig
                       # ("hand", "chain", "loop4", …: what the commands take)
song = "kick.mp3"      # or live = "mic" / "tab"
preset = "Kick"        # a preset's name (optional: the model's first gallery tile)
bars = 8               # or until = "section" / "told" (the default)
loop = false           # stay on this cue when it ends
fade_beats = 2         # this cue's own crossfade (default: the set's)
```
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field

from eigendance.errors import InputError, one_line
from eigendance.files import check_readable, read_toml
from eigendance.inputs.model import model_source
from eigendance.presets.store import check_name

UNTIL = ("bars", "section", "told")
LIVE = ("mic", "tab")
MAX_CUES = 999


@dataclass
class Cue:
    """One cue of a set.

    Parameters
    ----------
    name : shown on the control page.
    model : the model file (absolute path), or a built-in rig's name.
    song : the audio file (absolute path), or None with `live`.
    live : "mic" or "tab" (a live input instead of a song), or None.
    preset : a preset's name, or None.
    until : "bars" (after `bars` bars), "section" (at the song's next section), "told".
    bars : the cue's length in bars when until == "bars".
    loop : stay on this cue when it ends.
    fade_beats : crossfade into this cue, beats.
    """

    name: str
    model: str
    song: str | None = None
    live: str | None = None
    preset: str | None = None
    until: str = "told"
    bars: int = 0
    loop: bool = False
    fade_beats: float = 4.0

    def as_json(self) -> dict:
        """The cue as the pages see it (files by their names).

        Returns
        -------
        dict.
        """
        return {"name": self.name, "model": os.path.basename(self.model),
                "song": None if self.song is None else os.path.basename(self.song),
                "live": self.live, "preset": self.preset, "until": self.until,
                "bars": self.bars, "loop": self.loop, "fade_beats": self.fade_beats}


@dataclass
class SetList:
    """A show's cues and how they run.

    Parameters
    ----------
    name : the set's name.
    cues : the cues, in order.
    loop : after the last cue, the first again.
    fade_beats : the default crossfade, beats.
    slots : preset names on the keys 1–9 (empty: the favourites).
    """

    name: str
    cues: list[Cue]
    loop: bool = False
    fade_beats: float = 4.0
    slots: list[str] = field(default_factory=list)


def _get(table: dict, key: str, kinds, where: str, default=None):
    value = table.get(key, default)
    kinds = kinds if isinstance(kinds, tuple) else (kinds,)
    if value is not None and (not isinstance(value, kinds)
                              or isinstance(value, bool) and bool not in kinds):
        raise InputError(f"{where}: {key} has the wrong type ({type(value).__name__})")
    return value


def _named(name, where: str) -> str:
    try:
        return check_name(name)
    except InputError as error:
        raise InputError(f"{where}: {error}") from None


def _fade(table: dict, where: str, default: float) -> float:
    value = _get(table, "fade_beats", (int, float), where, default)
    if not 0 <= value <= 64:
        raise InputError(f"{where}: fade_beats must be within 0–64 beats")
    return float(value)


def _cue(table, index: int, folder: str, fade: float, path: str) -> Cue:
    where = f"{path}: cue {index + 1}"
    if not isinstance(table, dict):
        raise InputError(f"{where}: a cue must be a table")
    unknown = set(table) - {"name", "model", "song", "live", "preset", "bars", "until", "loop",
                            "fade_beats"}
    if unknown:
        raise InputError(f"{where}: unknown key {sorted(unknown)[0]!r}")
    model = _get(table, "model", str, where)
    if not model:
        raise InputError(f"{where}: give the model file (model = \"…\")")
    song, live = _get(table, "song", str, where), _get(table, "live", str, where)
    if (song is None) == (live is None):
        raise InputError(f"{where}: give a song file or a live input (live = \"mic\" or \"tab\")")
    if live is not None and live not in LIVE:
        raise InputError(f"{where}: live must be \"mic\" or \"tab\", got {one_line(live, 20)!r}")
    preset = _get(table, "preset", str, where)
    if preset is not None:
        _named(preset, where)
    bars = _get(table, "bars", int, where)
    until = _get(table, "until", str, where, "bars" if bars is not None else "told")
    if until not in UNTIL:
        raise InputError(f"{where}: until must be one of {', '.join(UNTIL)}")
    if until == "bars" and (bars is None or not 1 <= bars <= 10000):
        raise InputError(f"{where}: bars must be a whole number of bars, 1–10000")
    try:
        model = model_source(model, folder)  # a file, or a built-in rig as the commands take it
        song = None if song is None else os.path.abspath(check_readable(os.path.join(folder,
                                                                                     song)))
    except InputError as error:  # which cue of which set names the file
        raise InputError(f"{where}: {error}", status=error.status) from None
    name = _get(table, "name", str, where) or preset or os.path.basename(model)
    return Cue(one_line(name, 60), model, song, live, preset, until,
               bars or 0, bool(_get(table, "loop", bool, where, False)), _fade(table, where, fade))


def read_set(path: str | os.PathLike) -> SetList:
    """Read and check a set file.

    Parameters
    ----------
    path : the TOML file.

    Returns
    -------
    SetList; InputError naming the file, the cue and the key for anything wrong.
    """
    path = os.fspath(path)
    document = read_toml(path, "TOML set list")
    unknown = set(document) - {"set", "cue"}
    if unknown:
        raise InputError(f"{path}: unknown table {sorted(unknown)[0]!r} (a set has [set] and "
                         "[[cue]])")
    head = document.get("set", {})
    if not isinstance(head, dict):
        raise InputError(f"{path}: [set] must be a table")
    fade = _fade(head, f"{path}: [set]", 4.0)
    slots = _get(head, "slots", list, f"{path}: [set]", [])
    for slot in slots[:9]:
        _named(slot, f"{path}: [set] slots")
    cues = document.get("cue", [])
    if not isinstance(cues, list) or not 1 <= len(cues) <= MAX_CUES:
        raise InputError(f"{path}: a set needs 1–{MAX_CUES} cues ([[cue]] tables)")
    folder = os.path.dirname(os.path.abspath(path))
    return SetList(one_line(_get(head, "name", str, f"{path}: [set]", "") or
                            os.path.splitext(os.path.basename(path))[0], 60),
                   [_cue(table, i, folder, fade, path) for i, table in enumerate(cues)],
                   bool(_get(head, "loop", bool, f"{path}: [set]", False)), fade, slots[:9])
