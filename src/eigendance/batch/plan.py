"""The plan of a batch: a TOML file listing models, songs and what to make of each pair, checked
whole before any work starts and expanded into jobs (docs/design.md#batch).

Every problem is one `InputError` naming the plan file and the key ("plan.toml: fps must be
greater than 0 and at most 240, not 0"): an unknown key, a value of the wrong type or out of
range (the command line's ranges, through `checks.number`), a glob that matches nothing, a file
that cannot be read or is of the wrong kind, a mapping file that is not a mapping. Paths are
relative to the plan's folder. A glob never takes a file the output folder's record lists (a
rest mesh or a song copy of an earlier run in the inputs' own folder stays an output).
"""

from __future__ import annotations

import glob
import os
from dataclasses import dataclass, field

from eigendance import checks
from eigendance.batch.names import unique_parts
from eigendance.batch.record import recorded_files
from eigendance.errors import InputError, one_line
from eigendance.export.video import check_size, parse_size
from eigendance.files import (
    AUDIO_SUFFIXES,
    MESH_SUFFIXES,
    check_readable,
    read_toml,
    suffix_of,
)
from eigendance.harmonic.construction import CONSTRUCTIONS
from eigendance.inputs.defaults import DEFAULT_FPS, DEFAULT_K
from eigendance.inputs.mapping import read_mapping, shared_choice
from eigendance.inputs.model import model_kind
from eigendance.modal.sample_rigs import SAMPLE_RIGS
from eigendance.music.gallery import MAX_GALLERY, MIN_GALLERY
from eigendance.music.mapping import Mapping

# What a job can make, and the suffix of each.
FORMATS = {"mp4": ".mp4", "glb": ".glb", "usd": ".usd", "pc2": ".pc2", "npz": ".npz"}
# The command line's ranges (cli.options: -k, render's --fps, --start, --duration, --size).
HARMONICS = (1, 20000)
FPS = (0, 240)
SECONDS = (0, 24 * 3600)
KEYS = ("models", "songs", "outputs", "gallery", "mappings", "out", "size", "fps", "k",
        "construction", "start", "duration", "cache", "surface")

EXAMPLE = """\
# eigendance batch plan (TOML; paths relative to this file; docs/design.md#batch)
models = ["meshes/*.obj", "characters/hero.glb", "loop8"]  # meshes, rigs, built-in rigs
songs = ["songs/*.ogg", "single.mp3"]                       # audio files or globs
outputs = ["mp4", "glb"]          # any of mp4, glb, usd, pc2, npz
gallery = 4                       # an initial gallery of 4 items per pair ...
# mappings = ["calm.json", "wild.json"]   # ... or these mapping files instead
out = "renders"                   # {model}-{song}-{item}.{ext} are written here
size = "1280x720"                 # video size (optional)
fps = 30                          # frames per second (optional, default 30)
k = 150                           # harmonics of a mesh (optional; default: the k the
                                  # mappings were made on, else 150)
# construction = "exact"          # a mesh's basis, "exact" or "reduced" (optional; default:
                                  # the one the mappings were made on, else the rule)
start = 30.0                      # the clip's start in each song, s (optional, default 0)
duration = 15.0                   # the clip's length, s (optional, default: to the end)
# cache = "/shared/eigendance-cache"  # the content cache (optional; a cluster: shared storage)
# surface = "ripple.json"         # rigs' skins also ripple by this mapping, or "auto" (optional)
"""


@dataclass(frozen=True)
class Model:
    """A model of the plan.

    Parameters
    ----------
    name : its part of the output names.
    path : its file (absolute), or a built-in rig's name.
    kind : "mesh" or "rig".
    """

    name: str
    path: str
    kind: str


@dataclass(frozen=True)
class Song:
    """A song of the plan.

    Parameters
    ----------
    name : its part of the output names.
    path : its audio file (absolute).
    """

    name: str
    path: str


@dataclass(frozen=True)
class Item:
    """What a pair plays: an item of the initial gallery, or a mapping file.

    Parameters
    ----------
    name : its part of the output names.
    index, gallery : the gallery's item and size (None for a mapping file).
    mapping : the mapping file's `Mapping` (None for a gallery's item).
    path : the mapping file (absolute), or None.
    """

    name: str
    index: int | None = None
    gallery: int | None = None
    mapping: Mapping | None = field(default=None, compare=False)
    path: str | None = None


@dataclass(frozen=True)
class Job:
    """One (model, song, item), whose outputs are `{stem}.{ext}` in the plan's folder `out`.

    Parameters
    ----------
    model, song, item : what it plays.
    stem : `{model}-{song}-{item}`.
    """

    model: Model
    song: Song
    item: Item
    stem: str

    def path(self, out: str, format: str) -> str:
        """The output of `format` ("mp4", "glb", …) in the folder `out`.

        Parameters
        ----------
        out : the plan's output folder.
        format : one of FORMATS.

        Returns
        -------
        str.
        """
        return os.path.join(out, self.stem + FORMATS[format])


@dataclass
class Plan:
    """A checked plan (`read_plan`): inputs expanded, settings in range, paths absolute.

    Parameters
    ----------
    path : the plan file; out : the output folder; models, songs, items : the inputs;
    outputs : formats; size : (width, height) px; fps; k, construction, samples : a mesh's
    basis (`settle_basis`); start, duration : s (duration None: to the song's end); cache :
    the content cache's folder, or None (the default); surface : the rigs' surface mapping
    (docs/design.md#surface-of-a-rig), "auto", or None; asked : the plan's `k` and
    `construction` (None where it has none); notes : one line for each mapping made on another
    basis than the plan's (`settle_basis`).
    """

    path: str
    out: str
    models: list[Model]
    songs: list[Song]
    items: list[Item]
    outputs: tuple[str, ...]
    size: tuple[int, int] = (1280, 720)
    fps: float = DEFAULT_FPS
    k: int = DEFAULT_K
    start: float = 0.0
    duration: float | None = None
    cache: str | None = None
    surface: Mapping | str | None = None
    construction: str = "auto"
    samples: int | None = None
    asked: tuple = (None, None)
    notes: list[str] = field(default_factory=list)

    def settle_basis(self) -> list[str]:
        """Set the meshes' basis (k, construction, samples) from what the plan asks and what its
        items' mappings record (`inputs.mapping.shared_choice`): the basis they were made on
        unless the plan says otherwise, as on the command line.

        Returns
        -------
        `notes`: the command line's line (`inputs.mapping.basis_choice`) for each mapping made
        on another basis.

        Raises
        ------
        InputError
            When the plan asks for no k (construction) and the mappings record different ones.
        """
        choice, self.notes = shared_choice([item.mapping for item in self.items
                                            if item.mapping is not None], *self.asked)
        self.k, self.construction, self.samples = choice.k, choice.construction, choice.samples
        return self.notes

    def jobs(self) -> list[Job]:
        """Every (model, song, item), song by song (a song's inputs are needed together).

        Returns
        -------
        list of Job.
        """
        return [Job(model, song, item, f"{model.name}-{song.name}-{item.name}")
                for song in self.songs for model in self.models for item in self.items]


def read_plan(path: str | os.PathLike) -> Plan:
    """Read and check a plan file (module docstring).

    Parameters
    ----------
    path : the TOML file.

    Returns
    -------
    Plan; InputError naming the file and the key for anything wrong.
    """
    path = os.fspath(path)
    reader = _Reader(path, read_toml(path, "TOML plan"))
    return reader.plan()


class _Reader:
    """Checks one plan document key by key; every message starts with the plan's path."""

    def __init__(self, path: str, document: dict):
        self.path, self.document = path, document
        self.folder = os.path.dirname(os.path.abspath(path))
        unknown = sorted(set(document) - set(KEYS))
        if unknown:
            self.fail(unknown[0], f"is not a plan key (the keys: {', '.join(KEYS)})")

    def fail(self, key: str, problem: str):
        raise InputError(f"{self.path}: {key} {problem}")

    def plan(self) -> Plan:
        out = self.folder_of("out")
        self.recorded = recorded_files(out) if os.path.isdir(out) else set()
        outputs = self.outputs()
        items = self.items()
        songs = self.songs(outputs)
        plan = Plan(self.path, out, self.models(), songs, items, outputs)
        if "size" in self.document:
            plan.size = self.size()
        plan.fps = self.number("fps", DEFAULT_FPS, *FPS, above=True)
        plan.asked = (self.number("k", None, *HARMONICS, integer=True), self.construction())
        try:
            plan.settle_basis()
        except InputError as error:
            self.fail("mappings", f"{error}".removeprefix("the mappings "))
        plan.start = self.number("start", 0.0, *SECONDS)
        plan.duration = self.number("duration", None, *SECONDS, above=True)
        plan.cache = self.folder_of("cache", required=False)
        plan.surface = self.surface()
        return plan

    def surface(self) -> Mapping | str | None:
        value = self.document.get("surface")
        if value is None or value == "auto":
            return value
        if not isinstance(value, str) or not value:
            self.fail("surface", f"must be a mapping file or \"auto\", not {checks.shown(value)}")
        file = self.files("surface", value)[0]
        try:
            return Mapping.load(file)
        except InputError as error:
            self.fail("surface", f"{file}: {error}")

    def construction(self) -> str | None:
        value = self.document.get("construction")
        if value is not None and value not in CONSTRUCTIONS[1:]:
            self.fail("construction", f"must be \"exact\" or \"reduced\", not "
                                      f"{checks.shown(value)}")
        return value

    def number(self, key, default, low, high, integer=False, above=False):
        if key not in self.document:
            return default
        return checks.number(self.document[key], f"{self.path}: {key}", low, high, integer,
                             above)

    def strings(self, key: str, required: bool = True) -> list[str]:
        value = self.document.get(key)
        if value is None and not required:
            return []
        if isinstance(value, str):
            value = [value]
        if not isinstance(value, list) or not value or \
                not all(isinstance(entry, str) and entry for entry in value):
            self.fail(key, f"must be a non-empty list of strings, not {checks.shown(value)}")
        if any("\0" in entry for entry in value):
            self.fail(key, "holds a NUL character, which no path may hold")
        return value

    def files(self, key: str, pattern: str) -> list[str]:
        """The files a pattern names (a glob, or one file), sorted, absolute; a glob never takes
        what a batch wrote in the output folder (`record.recorded_files`)."""
        full = os.path.join(self.folder, os.path.expanduser(pattern))
        if glob.has_magic(pattern):
            found = sorted(found for found in glob.glob(full, recursive=True)
                           if os.path.isfile(found) and
                           os.path.normpath(os.path.abspath(found)) not in self.recorded)
            if not found:
                self.fail(key, f"{pattern!r} matches no file")
        else:
            found = [full]
        for file in found:
            try:
                check_readable(file)
                with open(file, "rb"):
                    pass
            except (InputError, OSError) as error:
                self.fail(key, f"{pattern!r}: {one_line(error)}")
        return [os.path.normpath(file) for file in found]

    def models(self) -> list[Model]:
        paths, kinds = [], []
        for pattern in self.strings("models"):
            if pattern in SAMPLE_RIGS and not os.path.exists(os.path.join(self.folder, pattern)):
                found = [(pattern, "rig")]
            else:
                found = [(file, self.model_kind(file)) for file in self.files("models", pattern)]
            for file, kind in found:
                if file not in paths:
                    paths.append(file)
                    kinds.append(kind)
        names = unique_parts(paths, "model")
        return [Model(*fields) for fields in zip(names, paths, kinds, strict=True)]

    def model_kind(self, file: str) -> str:
        try:  # the one rule of every front end: a skinned glTF is a rig, as served
            kind = model_kind(file)
        except InputError as error:
            self.fail("models", f"{one_line(error)} (meshes: {' '.join(MESH_SUFFIXES)}; rigs: "
                                f".json .glb .gltf, or {', '.join(SAMPLE_RIGS)})")
        if kind == "basis":
            self.fail("models", f"{file}: a basis file; give the mesh it was solved from")
        return kind

    def songs(self, outputs) -> list[Song]:
        paths = []
        for pattern in self.strings("songs"):
            for file in self.files("songs", pattern):
                if suffix_of(file) not in AUDIO_SUFFIXES:
                    self.fail("songs", f"{file}: unknown audio format "
                                       f"{suffix_of(file) or '(none)'!r}")
                if suffix_of(file) == ".mp4" and "mp4" in outputs and \
                        set(outputs) & {"glb", "pc2", "usd"}:
                    self.fail("songs", f"{file}: the copy of an .mp4 song beside the exports "
                                       "would take the video's name; convert the song")
                if file not in paths:
                    paths.append(file)
        names = unique_parts(paths, "song")
        return [Song(name, path) for name, path in zip(names, paths, strict=True)]

    def outputs(self) -> tuple[str, ...]:
        formats = self.strings("outputs")
        for format in formats:
            if format not in FORMATS:
                self.fail("outputs", f"lists {format!r}; the formats are "
                                     f"{', '.join(FORMATS)}")
        return tuple(dict.fromkeys(formats))

    def items(self) -> list[Item]:
        has_gallery, has_mappings = "gallery" in self.document, "mappings" in self.document
        if has_gallery == has_mappings:
            self.fail("gallery", "or mappings: give one of them (gallery = N: the initial "
                                 "gallery's N items; mappings = [files])")
        if has_gallery:
            size = checks.number(self.document["gallery"], f"{self.path}: gallery",
                                 MIN_GALLERY, MAX_GALLERY, integer=True)
            return [Item(str(index), index, size) for index in range(size)]
        paths = []
        for pattern in self.strings("mappings"):
            paths += [file for file in self.files("mappings", pattern) if file not in paths]
        items = []
        for name, file in zip(unique_parts(paths, "mapping"), paths, strict=True):
            try:
                mapping = read_mapping(file)
            except InputError as error:
                self.fail("mappings", f"{file}: {error}")
            items.append(Item(name, mapping=mapping, path=file))
        return items

    def size(self) -> tuple[int, int]:
        value = self.document["size"]
        try:
            if isinstance(value, str):
                return parse_size(value)
            if isinstance(value, list) and len(value) == 2:
                width, height = (checks.number(side, "size", integer=True) for side in value)
                check_size(width, height)
                return width, height
        except InputError as error:
            self.fail("size", f"is wrong: {error}")
        self.fail("size", f"must be \"WIDTHxHEIGHT\" or [width, height], not "
                          f"{checks.shown(value)}")

    def folder_of(self, key: str, required: bool = True) -> str | None:
        value = self.document.get(key)
        if value is None and not required:
            return None
        if not isinstance(value, str) or not value or "\0" in value:
            self.fail(key, f"must be a folder's path, not {checks.shown(value)}")
        folder = os.path.normpath(os.path.join(self.folder, os.path.expanduser(value)))
        if os.path.exists(folder) and not os.path.isdir(folder):
            self.fail(key, f"{folder} is a file, not a folder")
        existing = folder
        while not os.path.isdir(existing):
            existing = os.path.dirname(existing)
        if not os.access(existing, os.W_OK | os.X_OK):
            self.fail(key, f"{folder}: cannot write there (no permission)")
        return folder
