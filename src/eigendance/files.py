"""Files: kinds by suffix, checked reads of .npz and JSON (docs/design.md#files).

One table says which suffixes are meshes, audio, rigs and mappings; the CLI, the server and the
loaders all ask `kind_of`. Reading checks every field a file holds (`checked_array`,
`read_json`); writing is `eigendance.writes`.
"""

from __future__ import annotations

import hashlib
import json
import math
import os

import numpy as np

try:
    import tomllib
except ModuleNotFoundError:  # Python 3.10: the same parser, as a package
    import tomli as tomllib

from eigendance.errors import InputError, one_line
from eigendance.reads import read_npz
from eigendance.writes import check_finite

MESH_SUFFIXES = (".obj", ".ply", ".off", ".stl", ".gltf", ".glb",
                 ".fbx", ".blend", ".dae", ".3ds")  # the last four through Blender's bpy
# libsndfile reads the first group itself; PyAV (FFmpeg) reads everything.
AUDIO_SUFFIXES = (".wav", ".wave", ".flac", ".ogg", ".oga", ".mp3", ".aif", ".aiff", ".opus",
                  ".m4a", ".aac", ".mp4", ".webm", ".mka")
RIG_SUFFIXES = (".json", ".gltf", ".glb")
MAPPING_SUFFIXES = (".json",)
BASIS_SUFFIXES = SPECTROGRAM_SUFFIXES = (".npz",)  # eigendance's own files
ARCHIVE_SUFFIXES = (".zip",)  # a model in several files (server.archive)
# Files a model names beside it (glTF buffers and images, an OBJ's MTL and its maps).
COMPANION_SUFFIXES = (".bin", ".mtl", ".png", ".jpg", ".jpeg", ".webp", ".ktx2", ".tga",
                      ".bmp", ".tif", ".tiff")
KINDS = {"mesh": MESH_SUFFIXES, "audio": AUDIO_SUFFIXES, "mapping": MAPPING_SUFFIXES}


def suffix_of(path: str | os.PathLike) -> str:
    """The lower-case suffix of a path, with its dot ('' if none).

    Parameters
    ----------
    path : a path.

    Returns
    -------
    str, e.g. ".obj".
    """
    return os.path.splitext(os.fspath(path))[1].lower()


def kind_of(name: str | os.PathLike, kinds: tuple[str, ...] = ("mesh", "audio", "mapping")) -> str:
    """'mesh', 'audio' or 'mapping' by suffix, among `kinds`; InputError for any other.

    Parameters
    ----------
    name : a file name.
    kinds : the kinds accepted.

    Returns
    -------
    str; InputError (415 when any kind would do) for another suffix.
    """
    suffix = suffix_of(name)
    for kind in kinds:
        if suffix in KINDS[kind]:
            return kind
    name = os.path.basename(os.fspath(name))
    if len(kinds) == 1:
        raise InputError(f"{name}: unknown {kinds[0]} format '{suffix or '(none)'}' (expected "
                         f"one of {', '.join(KINDS[kinds[0]])})", status=415)
    words = {"mesh": ("a model", "models"), "audio": ("a song", "songs"),
             "mapping": ("a mapping", "mappings")}
    what = [words[kind][0] for kind in kinds]
    known = "; ".join(f"{words[kind][1]}: {' '.join(KINDS[kind])}" for kind in kinds)
    raise InputError(f"{name}: unknown file type '{suffix or '(none)'}': not "
                     f"{', '.join(what[:-1])} or {what[-1]} ({known})", status=415)


def check_suffix(path: str | os.PathLike, kind: str) -> None:
    """InputError unless `path` has one of the suffixes of `kind`.

    Parameters
    ----------
    path : a path.
    kind : "mesh", "audio", "rig" or "mapping".
    """
    kind_of(path, (kind,))


def check_readable(path: str | os.PathLike) -> str:
    """The path as a string; InputError if it is not an existing, non-empty regular file.

    Parameters
    ----------
    path : a path.

    Returns
    -------
    str (404 InputError for a missing file).
    """
    path = os.fspath(path)
    if not os.path.exists(path):
        raise InputError(f"{path}: no such file", status=404)
    if not os.path.isfile(path):
        raise InputError(f"{path}: not a regular file")
    if os.path.getsize(path) == 0:
        raise InputError(f"{os.path.basename(path)}: the file is empty")
    return path


def file_digest(path: str | os.PathLike) -> str:
    """SHA-256 of a file's bytes, read in blocks of 1 MiB (the server's and a batch's content
    keys).

    Parameters
    ----------
    path : the file.

    Returns
    -------
    str, 64 hexadecimal digits.
    """
    digest = hashlib.sha256()
    with open(path, "rb") as file:
        while block := file.read(1 << 20):
            digest.update(block)
    return digest.hexdigest()


def load_npz(path, required: tuple[str, ...]) -> dict:
    """Every array of an .npz file, checking that the `required` keys are present.

    Parameters
    ----------
    path : an .npz file.
    required : the keys it must hold.

    Returns
    -------
    {name: array}; InputError for an unreadable file or a missing key.
    """
    path = check_readable(path)
    arrays = read_npz(path)
    missing = [name for name in required if name not in arrays]
    if missing:
        raise InputError(f"{path}: missing {', '.join(missing)} (not an eigendance file "
                         "of this kind)")
    return arrays


def checked_array(arrays: dict, name: str, path, kind: str = "float",
                  shape: tuple = ()) -> np.ndarray:
    """arrays[name] from a file, checked: InputError naming the file and the field otherwise.

    kind: "float" (real numbers, all finite; returned as float64), "int" (integers; int64) or
    "str" (one string; returned as str). shape: the expected shape, None for any length.

    Parameters
    ----------
    arrays : the file's arrays.
    name : the field.
    path : the file, for messages.
    kind : "float", "int" or "str".
    shape : the expected shape (None in it: any length there).

    Returns
    -------
    The array (or str).
    """
    array = arrays[name]
    label = f"{os.fspath(path)}: {name}"
    if kind == "str":
        if array.dtype.kind != "U" or array.shape != ():
            raise InputError(f"{label} must be a string, not {array.dtype} {array.shape}")
        return str(array)
    numbers = "iu" if kind == "int" else "iuf"
    if array.dtype.kind not in numbers:
        raise InputError(f"{label} must hold {'integers' if kind == 'int' else 'real numbers'}, "
                         f"not {array.dtype}")
    if array.ndim != len(shape) or any(want is not None and want != got for want, got
                                       in zip(shape, array.shape, strict=False)):
        expected = "(" + ", ".join("any" if d is None else str(d) for d in shape) + \
            ("," if len(shape) == 1 else "") + ")"
        raise InputError(f"{label} has shape {array.shape}; expected {expected}")
    if kind == "int":
        if array.dtype.kind == "u" and array.size and array.max() > np.iinfo(np.int64).max:
            raise InputError(f"{label} holds integers beyond 2⁶³")
        return array.astype(np.int64)
    array = array.astype(np.float64)
    check_finite(array, label)
    return array


# Integers in a JSON document longer than this are refused before Python converts them (which
# takes time quadratic in the length, and a float of them overflows).
JSON_INTEGER_DIGITS = 40


class _LongInteger(ValueError):
    pass


def _json_integer(text: str) -> int:
    if len(text) > JSON_INTEGER_DIGITS:
        raise _LongInteger(f"an integer of {len(text.lstrip('-'))} digits")
    return int(text)


def finite_number(value) -> bool:
    """Whether a number from a JSON document is finite as a float (an int too large for a float
    is not: math.isfinite would raise OverflowError).

    Parameters
    ----------
    value : an int or a float (anything else — null, a string, a list — is not a number: False).

    Returns
    -------
    bool.
    """
    try:
        return math.isfinite(value)
    except (OverflowError, TypeError):
        return False


def read_json(path: str | os.PathLike, name: str | None = None):
    """The parsed JSON document of a file; InputError naming the file for anything unreadable.

    Refused: a missing file, text that is not UTF-8 or not JSON, nesting deeper than Python's
    recursion limit, integers of more than JSON_INTEGER_DIGITS digits. Messages call the file
    `name` (default: its base name; an upload's own name rather than where it is stored).

    Parameters
    ----------
    path : the file.
    name : how messages call it.

    Returns
    -------
    The document (dict, list, str, number, bool or None).
    """
    path = os.fspath(path)
    name = name or os.path.basename(path)
    try:
        with open(path, encoding="utf-8") as file:
            return json.load(file, parse_int=_json_integer)
    except FileNotFoundError:
        raise InputError(f"{path}: no such file", status=404) from None
    except IsADirectoryError:
        raise InputError(f"{path}: is a folder, not a JSON file") from None
    except json.JSONDecodeError as error:
        raise InputError(f"{name}: malformed JSON at line {error.lineno} column {error.colno} "
                         f"({error.msg})") from None
    except UnicodeDecodeError:
        raise InputError(f"{name}: not a JSON file (the text is not UTF-8)") from None
    except _LongInteger as error:
        raise InputError(f"{name}: {error} is out of range") from None
    except RecursionError:
        raise InputError(f"{name}: the JSON is nested too deeply") from None
    except OSError as error:
        raise InputError(f"{path}: cannot read ({error.strerror or one_line(error)})") from None


def read_toml(path: str | os.PathLike, what: str) -> dict:
    """The parsed TOML document of a file (a batch plan, a show's set list); InputError naming
    the file for anything unreadable.

    Parameters
    ----------
    path : the file.
    what : what it should be, for the message ("TOML plan").

    Returns
    -------
    dict.
    """
    path = os.fspath(path)
    check_readable(path)
    try:
        with open(path, "rb") as file:
            return tomllib.load(file)
    except tomllib.TOMLDecodeError as error:
        raise InputError(f"{path}: not a {what} ({one_line(error)})") from None
    except RecursionError:
        raise InputError(f"{path}: not a {what} (nested too deeply)") from None
    except (OSError, UnicodeDecodeError) as error:
        raise InputError(f"{path}: cannot read ({one_line(error)})") from None
