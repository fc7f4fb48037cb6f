"""The presets folder: one JSON file per preset and its PNG thumbnail (docs/design.md#presets).

`NAME.json` holds `{"format": "eigendance.preset", "version": 1, "name", "tags", "favourite",
"mapping", "eigenvalues", "thumbnail"}`; in the folder the thumbnail is the file `NAME.png`
beside it, in an exported file it is inline (base64), so one file carries the whole preset.
Files are written atomically (`writes.atomic_write`); a name is checked before it becomes a
file name.
"""

from __future__ import annotations

import base64
import binascii
import json
import os
import re
import threading
from dataclasses import dataclass, field

import platformdirs

from eigendance.errors import InputError
from eigendance.files import read_json
from eigendance.music.mapping import Mapping
from eigendance.music.mode_settings import ModeSettings
from eigendance.writes import atomic_write

FORMAT = "eigendance.preset"
VERSION = 1
NAME_PATTERN = re.compile(r"[^\W_][\w .()+'-]{0,63}")
MAX_TAGS = 32
MAX_THUMBNAIL = 1 << 20  # bytes of PNG
PNG = b"\x89PNG\r\n\x1a\n"
# A rig palette alone becomes this mapping: no band moves anything but the palette.
BANDS = 64


def default_folder() -> str:
    """Where presets live without --presets: $EIGENDANCE_PRESETS_DIR, else the user's data folder
    (platformdirs, as the cache).

    Returns
    -------
    str, a folder path (made when the first preset is saved).
    """
    return os.environ.get("EIGENDANCE_PRESETS_DIR") or os.path.join(
        platformdirs.user_data_dir("eigendance"), "presets")


def check_name(name) -> str:
    """A preset's name, checked: 1–64 letters, digits, spaces and ``.()+'-_``, starting with a
    letter or digit, not ending with a space or dot.

    Parameters
    ----------
    name : the name asked for.

    Returns
    -------
    str, the name; InputError (400) saying what is allowed.

    Example
    -------
    >>> check_name("Kick pulse (slow)")
    'Kick pulse (slow)'
    """
    if not isinstance(name, str) or not NAME_PATTERN.fullmatch(name) or name[-1] in " .":
        shown = name if isinstance(name, str) and len(name) < 70 else type(name).__name__
        raise InputError(f"preset name {json.dumps(shown)}: use 1–64 letters, digits, spaces "
                         "and .()+'-_, starting with a letter or digit")
    return name


def check_tags(tags) -> list[str]:
    """Tags: a list of at most 32 short strings (each 1–32 characters, no control character).

    Parameters
    ----------
    tags : the list (None: none).

    Returns
    -------
    list of str, without repeats, in order.
    """
    if tags is None:
        return []
    if not isinstance(tags, list) or len(tags) > MAX_TAGS or not all(
            isinstance(tag, str) and 0 < len(tag.strip()) <= 32 and tag.isprintable()
            for tag in tags):
        raise InputError(f"tags must be a list of at most {MAX_TAGS} words of 1–32 characters")
    return list(dict.fromkeys(tag.strip() for tag in tags))


@dataclass
class Preset:
    """A named dance (docs/design.md#presets).

    Parameters
    ----------
    name : checked by `check_name`.
    mapping : the mapping, with its look and (for a rig) its palette in `modes`.
    tags : words to search by.
    favourite : marked as a favourite.
    eigenvalues : the eigenvalues of the model it was made on (fitting it to another model by
        harmonic frequency), or None.
    thumbnail : PNG bytes, or None.
    """

    name: str
    mapping: Mapping
    tags: list[str] = field(default_factory=list)
    favourite: bool = False
    eigenvalues: list[float] | None = None
    thumbnail: bytes | None = None

    def summary(self) -> dict:
        """What `GET /api/presets` lists of it.

        Returns
        -------
        dict: name, tags, favourite, kind ("rig" when it has a palette, else "mesh"),
        thumbnail (bool).
        """
        return {"name": self.name, "tags": self.tags, "favourite": self.favourite,
                "kind": "rig" if self.mapping.modes is not None else "mesh",
                "thumbnail": self.thumbnail is not None}

    def to_json(self, inline_thumbnail: bool = False) -> dict:
        """The preset document.

        Parameters
        ----------
        inline_thumbnail : put the PNG in (base64; an exported file) instead of a bool.

        Returns
        -------
        dict.
        """
        thumbnail = self.thumbnail is not None
        if inline_thumbnail and self.thumbnail is not None:
            thumbnail = base64.b64encode(self.thumbnail).decode()
        return {"format": FORMAT, "version": VERSION, "name": self.name, "tags": self.tags,
                "favourite": self.favourite, "mapping": self.mapping.to_json(),
                "eigenvalues": self.eigenvalues, "thumbnail": thumbnail}

    @classmethod
    def from_json(cls, data, where: str = "preset") -> Preset:
        """A preset document (a file, an import, a POST), checked.

        Parameters
        ----------
        data : the parsed JSON: {"name", "mapping" or "palette", "tags", "favourite",
            "eigenvalues", "thumbnail" (base64 PNG, or a data: URL)}; "format" optional.
        where : how messages call it.

        Returns
        -------
        Preset; InputError naming the field.
        """
        if not isinstance(data, dict):
            raise InputError(f"{where}: a preset must be a JSON object")
        if data.get("format", FORMAT) != FORMAT:
            raise InputError(f"{where}: format must be \"{FORMAT}\"")
        name = check_name(data.get("name"))
        if data.get("mapping") is not None:
            mapping = Mapping.from_json(data["mapping"], f"{where}: mapping")
        elif data.get("palette") is not None:
            palette = ModeSettings.from_json(data["palette"], f"{where}: palette")
            mapping = Mapping([0.5] * BANDS, [1.0], modes=palette, offset=1.0)
        else:
            raise InputError(f"{where}: give a \"mapping\" or a \"palette\"")
        favourite = data.get("favourite", False)
        if not isinstance(favourite, bool):
            raise InputError(f"{where}: favourite must be true or false")
        return cls(name, mapping, check_tags(data.get("tags")), favourite,
                   _eigenvalues(data.get("eigenvalues"), where),
                   _thumbnail(data.get("thumbnail"), where))


def _eigenvalues(values, where: str) -> list[float] | None:
    if values is None:
        return None
    if not isinstance(values, list) or not 0 < len(values) <= 20000 or not all(
            isinstance(v, int | float) and not isinstance(v, bool) and 0 <= v < 1e300
            for v in values):
        raise InputError(f"{where}: eigenvalues must be a list of at most 20000 numbers ≥ 0")
    return [float(v) for v in values]


def _thumbnail(value, where: str) -> bytes | None:
    if value is None or isinstance(value, bool):
        return None
    if not isinstance(value, str) or len(value) > MAX_THUMBNAIL * 4 // 3 + 64:
        raise InputError(f"{where}: thumbnail must be a PNG of at most 1 MiB, in base64")
    try:
        png = base64.b64decode(value.removeprefix("data:image/png;base64,"), validate=True)
    except (binascii.Error, ValueError):
        raise InputError(f"{where}: thumbnail is not base64") from None
    if not png.startswith(PNG):
        raise InputError(f"{where}: thumbnail is not a PNG")
    return png


class PresetStore:
    """The presets in a folder (made when the first is saved); safe to share between threads.

    Parameters
    ----------
    folder : where the files are.
    """

    def __init__(self, folder: str | os.PathLike):
        self.folder = os.fspath(folder)
        self.lock = threading.Lock()
        self._check_folder()

    def _check_folder(self) -> None:
        """InputError when something other than a folder stands where the presets live."""
        if os.path.exists(self.folder) and not os.path.isdir(self.folder):
            raise InputError(f"{self.folder}: the presets folder is a file, not a folder")

    def _path(self, name: str, suffix: str = ".json") -> str:
        return os.path.join(self.folder, check_name(name) + suffix)

    def names(self) -> list[str]:
        """Every preset's name, sorted case-insensitively.

        Returns
        -------
        list of str.
        """
        try:
            files = os.listdir(self.folder)
        except FileNotFoundError:
            return []
        except NotADirectoryError:  # made a file since
            self._check_folder()
            raise
        names = [f[:-5] for f in files if f.endswith(".json") and NAME_PATTERN.fullmatch(f[:-5])]
        return sorted(names, key=str.casefold)

    def load(self, name: str) -> Preset:
        """Read one preset.

        Parameters
        ----------
        name : its name.

        Returns
        -------
        Preset; InputError 404 when there is none of that name.
        """
        path = self._path(name)
        if not os.path.isfile(path):
            raise InputError(f"no preset named {json.dumps(name)}", status=404)
        data = read_json(path, f"preset {name}")
        if isinstance(data, dict):
            data = {**data, "name": name, "thumbnail": None}
        preset = Preset.from_json(data, f"preset {name}")
        png = self._path(name, ".png")
        if os.path.isfile(png):
            with open(png, "rb") as file:
                preset.thumbnail = file.read(MAX_THUMBNAIL + 1)[:MAX_THUMBNAIL] or None
        return preset

    def listing(self, search: str = "", favourites: bool = False) -> list[dict]:
        """Summaries of the presets whose name or a tag contains `search` (any case).

        Parameters
        ----------
        search : words to look for ('' : all).
        favourites : only the favourites.

        Returns
        -------
        list of dict (`Preset.summary`); files that no longer read are left out.
        """
        found, needle = [], search.casefold().strip()
        for name in self.names():
            try:
                preset = self.load(name)
            except InputError:
                continue
            words = [preset.name, *preset.tags]
            if needle and not any(needle in word.casefold() for word in words):
                continue
            if not favourites or preset.favourite:
                found.append(preset.summary())
        return found

    def save(self, preset: Preset, replace: bool = True) -> None:
        """Write a preset (and its thumbnail) atomically.

        Parameters
        ----------
        preset : the preset.
        replace : overwrite one of the same name (False: 409 if there is one).
        """
        path = self._path(preset.name)
        with self.lock:
            if not replace and os.path.exists(path):
                raise InputError(f"a preset named {json.dumps(preset.name)} exists already",
                                 status=409)
            if preset.thumbnail is not None:
                atomic_write(self._path(preset.name, ".png"),
                             lambda file: file.write(preset.thumbnail), alone=True)
            elif os.path.exists(self._path(preset.name, ".png")):
                os.unlink(self._path(preset.name, ".png"))
            text = json.dumps(preset.to_json(), indent=1).encode()
            atomic_write(path, lambda file: file.write(text), alone=True)

    def delete(self, name: str) -> None:
        """Remove a preset and its thumbnail.

        Parameters
        ----------
        name : its name; InputError 404 when there is none.
        """
        with self.lock:
            path = self._path(name)
            if not os.path.isfile(path):
                raise InputError(f"no preset named {json.dumps(name)}", status=404)
            os.unlink(path)
            if os.path.exists(self._path(name, ".png")):
                os.unlink(self._path(name, ".png"))

    def rename(self, name: str, new_name: str) -> Preset:
        """Give a preset another name (409 when that name is taken).

        Parameters
        ----------
        name : its name.
        new_name : the new one.

        Returns
        -------
        Preset, renamed.
        """
        preset = self.load(name)
        if check_name(new_name) == name:
            return preset
        preset.name = new_name
        self.save(preset, replace=False)
        self.delete(name)
        return preset
