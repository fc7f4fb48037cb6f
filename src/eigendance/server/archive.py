"""A model that comes as several files — a .gltf with its .bin and textures, an OBJ with its
MTL and images — uploaded as one .zip (the page zips several files dropped together), unpacked
into one folder of the library and read from there like any model file (docs/design.md#server).

What a zip may hold, checked before anything is written: its end record (read here, before
`zipfile` parses the directory) lists at most MAX_MEMBERS entries in a directory of at most
MAX_DIRECTORY bytes, so a zip listing a million entries is refused in microseconds; at most
MAX_MEMBERS members of at most `limit` bytes unpacked in all (a zip bomb is refused before it is
extracted, and each member is counted again as it is written: a header cannot lie about its
size); relative paths that stay inside the folder (no absolute path, drive, `..` or link), of at
most MAX_DEPTH folders, MAX_PATH characters and NAME_MAX bytes a name, none both a file and a
folder; no encryption; model files, the files models name (buffers, MTLs, images) and documents
(licence, read-me), which are skipped. Anything else is refused in one line naming it. The model
read is the zip's one model file — the first kind found of glTF, OBJ, PLY/OFF/STL, then what
Blender converts (a zip holding one model in several formats); two of that kind are refused.
"""

from __future__ import annotations

import os
import posixpath
import stat
import zipfile
import zlib

from eigendance.errors import InputError, disk_full
from eigendance.files import ARCHIVE_SUFFIXES, COMPANION_SUFFIXES, MESH_SUFFIXES, suffix_of

MAX_MEMBERS = 256
MAX_DIRECTORY = MAX_MEMBERS << 12  # bytes of the central directory: 4 KiB an entry
MAX_DEPTH, MAX_PATH, NAME_MAX = 32, 1024, 255  # a member's folders, characters, bytes a name
# Files an artist's zip carries that are no part of the model: skipped.
DOCUMENT_SUFFIXES = (".txt", ".md", ".pdf", ".html", ".htm", ".url", ".rtf", ".json")
SKIPPED_NAMES = (".ds_store", "thumbs.db", "desktop.ini")
# Which model file a zip is read as, first kind first.
MODEL_PREFERENCE = ((".glb", ".gltf"), (".obj",), (".ply", ".off", ".stl"),
                    (".fbx", ".blend", ".dae", ".3ds"))
CHUNK = 1 << 20


def is_archive(name: str) -> bool:
    """Whether a file name is a model archive (.zip).

    Parameters
    ----------
    name : a file name.

    Returns
    -------
    bool.
    """
    return suffix_of(name) in ARCHIVE_SUFFIXES


def members(archive: zipfile.ZipFile, name: str, limit: int) -> list[tuple[zipfile.ZipInfo,
                                                                             str]]:
    """The members to unpack and their safe relative paths; InputError (one line naming the
    zip and the member) for anything refused.

    Parameters
    ----------
    archive : the open zip.
    name : how messages call it.
    limit : the most bytes its members may unpack to, in all.

    Returns
    -------
    [(member, relative POSIX path)] of the model, companion files (documents skipped).
    """
    infos = archive.infolist()  # `check_end_record` bounded it
    if len(infos) > MAX_MEMBERS:
        raise InputError(f"{name}: holds {len(infos)} files; at most {MAX_MEMBERS}", status=413)
    total = sum(info.file_size for info in infos)
    if total > limit:
        raise InputError(f"{name}: unpacks to {total >> 20} MiB; at most {limit >> 20} MiB",
                         status=413)
    kept, folders = [], set()
    for info in infos:
        path = safe_path(info, name)
        if path is None:
            continue
        pieces = path.split("/")
        folders.update("/".join(pieces[:index]) for index in range(1, len(pieces)))
        suffix = suffix_of(path)
        if info.flag_bits & 0x1:
            raise InputError(f"{name}: {path} is encrypted")
        if suffix in MESH_SUFFIXES or suffix in COMPANION_SUFFIXES:
            kept.append((info, path))
        elif suffix not in DOCUMENT_SUFFIXES:
            raise InputError(
                f"{name}: {path} is of a kind a model does not use ('{suffix or '(none)'}'); a "
                f"zip may hold a model ({' '.join(MESH_SUFFIXES)}), its files "
                f"({' '.join(COMPANION_SUFFIXES)}) and documents", status=415)
    clash = next((path for _, path in kept if path in folders), None)
    if clash is not None:
        raise InputError(f"{name}: '{clash[:80]}' is both a file and a folder")
    return kept


def check_end_record(file, name: str) -> None:
    """InputError (413) when a zip's end record (zip64's where it has one) lists more than
    MAX_MEMBERS entries or a directory larger than MAX_DIRECTORY bytes; read before `zipfile`
    parses the directory, which it reads whole, entry by entry, in Python.

    Parameters
    ----------
    file : the zip, open for reading in binary.
    name : how messages call it.
    """
    try:
        end = zipfile._EndRecData(file)  # the end record, zip64's fields in place where given
    except OSError:
        end = None
    if end is None:
        raise InputError(f"{name}: not a zip file (or a damaged one)")
    entries, size = end[zipfile._ECD_ENTRIES_TOTAL], end[zipfile._ECD_SIZE]
    if entries > MAX_MEMBERS:
        raise InputError(f"{name}: holds {entries} files; at most {MAX_MEMBERS}", status=413)
    if size > MAX_DIRECTORY:
        raise InputError(f"{name}: its directory takes {size} bytes; at most {MAX_DIRECTORY}",
                         status=413)


def safe_path(info: zipfile.ZipInfo, name: str) -> str | None:
    """A member's path relative to the folder.

    Parameters
    ----------
    info : the member.
    name : how messages call the zip.

    Returns
    -------
    str (POSIX, relative), or None for a member to skip (a folder, a system file);
    InputError for a path that would leave the folder (absolute, a drive, `..`) or a link.
    """
    raw = info.filename.replace("\\", "/")
    if info.is_dir() or raw.endswith("/"):
        return None
    parts = raw.split("/")
    if raw.startswith("/") or (len(parts[0]) == 2 and parts[0][1] == ":") or ".." in parts:
        raise InputError(f"{name}: the member '{raw[:80]}' would be written outside its folder")
    if stat.S_ISLNK(info.external_attr >> 16):
        raise InputError(f"{name}: the member '{raw[:80]}' is a link")
    path = posixpath.normpath("/".join(part for part in parts if part not in ("", ".")))
    if path.count("/") >= MAX_DEPTH or len(path) > MAX_PATH or \
            max(len(part.encode("utf-8", "replace")) for part in path.split("/")) > NAME_MAX:
        raise InputError(f"{name}: the member '{raw[:80]}…' has a path too long or too deep "
                         f"(at most {MAX_DEPTH} folders, {MAX_PATH} characters, {NAME_MAX} "
                         "bytes a name)")
    if parts[0] == "__MACOSX" or parts[-1].lower() in SKIPPED_NAMES or \
            parts[-1].startswith("._"):
        return None
    return path


def model_member(paths: list[str], name: str) -> str:
    """The zip's model file (module docstring: the first kind found, in MODEL_PREFERENCE).

    Parameters
    ----------
    paths : the members' relative paths.
    name : how messages call the zip.

    Returns
    -------
    str, one of `paths`; InputError if there is none, or two of the first kind found.
    """
    for kinds in MODEL_PREFERENCE:
        found = [path for path in paths if suffix_of(path) in kinds]
        if len(found) == 1:
            return found[0]
        if found:
            shown = ", ".join(sorted(found)[:4])
            raise InputError(f"{name}: holds {len(found)} models ({shown}); add them one at a "
                             "time")
    raise InputError(f"{name}: holds no model file ({' '.join(MESH_SUFFIXES)})")


def unpack(path: str, folder: str, limit: int, name: str) -> str:
    """Unpack a model's zip into `folder` (made here; must not exist) and return the path of
    its model file.

    Parameters
    ----------
    path : the zip.
    folder : where its files go (inside the library's folder).
    limit : the most bytes its members may unpack to, in all.
    name : how messages call the zip.

    Returns
    -------
    str, the model file's path inside `folder`.
    """
    try:
        with open(path, "rb") as file:
            check_end_record(file, name)
            archive = zipfile.ZipFile(path)
    except (zipfile.BadZipFile, OSError, ValueError, EOFError) as error:
        if isinstance(error, InputError):
            raise
        raise InputError(f"{name}: not a zip file (or a damaged one)") from None
    with archive:
        kept = members(archive, name, limit)
        model = model_member([relative for _, relative in kept], name)
        os.makedirs(folder)
        written = 0
        for info, relative in kept:
            written += _extract(archive, info, os.path.join(folder, *relative.split("/")),
                                limit - written, name)
    return os.path.join(folder, *model.split("/"))


def _extract(archive: zipfile.ZipFile, info: zipfile.ZipInfo, target: str, room: int,
             name: str) -> int:
    """Write one member (never over an existing file, never through a link), counting its
    bytes as they come: InputError past its declared size or the room left, or for a member
    the file system refuses (a full disk is the OSError itself: 507). Its size."""
    flags = os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_NOFOLLOW", 0)
    size = 0
    try:
        os.makedirs(os.path.dirname(target), exist_ok=True)
        with archive.open(info) as source, os.fdopen(os.open(target, flags, 0o600), "wb") as out:
            while chunk := source.read(CHUNK):
                size += len(chunk)
                if size > info.file_size or size > room:
                    raise InputError(f"{name}: {info.filename[:80]} unpacks to more than it "
                                     "says", status=413)
                out.write(chunk)
    except FileExistsError:
        raise InputError(f"{name}: names {info.filename[:80]} twice") from None
    except (zipfile.BadZipFile, EOFError, RuntimeError, NotImplementedError, zlib.error,
            OSError) as error:
        if disk_full(error):
            raise
        raise InputError(f"{name}: {info.filename[:80]} cannot be unpacked "
                         f"({getattr(error, 'strerror', None) or type(error).__name__})") \
            from None
    return size
