"""The checks of a mesh file's own structure before trimesh reads it (docs/design.md#errors):
OBJ face indices, OFF and ASCII PLY counts, an STL's length.

trimesh reads what these formats allow in ways that are wrong without a word: an OBJ's face
index 0 as the last vertex, a relative (negative) index as counted from the end of the file,
an OFF or ASCII PLY whose faces stop short of the count its header declares as a smaller
mesh. Each check
here turns such a file into one `InputError` naming the file, the line and what is wrong, or
into the text trimesh reads right (relative indices made absolute).
"""

from __future__ import annotations

import os
import re

from eigendance.errors import InputError
from eigendance.reads import open_regular

# An OBJ face corner whose vertex index is 0 (OBJ counts from 1; trimesh would read 0 as −1, the
# last vertex). Only the vertex index, the first number of a corner v/vt/vn, is looked at.
OBJ_ZERO_INDEX = re.compile(rb"^[ \t]*f[ \t](?:[^\n]*?[ \t])?[+-]?0+(?=[/ \t\r\n]|$)", re.M)
# A face with a relative index (−1: the last vertex, texture coordinate or normal so far).
OBJ_RELATIVE = re.compile(rb"^[ \t]*f[ \t][^\n]*?[ \t/]-\d", re.M)
# The statements an OBJ face's corner indices count: v, vt and vn.
OBJ_ELEMENTS = (b"v", b"vt", b"vn")
# A line that holds nothing once its comment is cut off (what OFF's counts do not count).
OFF_EMPTY_LINE = re.compile(rb"^[ \t\r\x0b\x0c]*(?:#[^\n]*)?$", re.M)


def read_text(path: str, name: str) -> bytes:
    """The bytes of a mesh file, an unreadable one (or not a file) an InputError naming it
    (`reads.open_regular`).

    Parameters
    ----------
    path : the file.
    name : how messages call it.

    Returns
    -------
    bytes.
    """
    with open_regular(path, name) as file:
        return file.read()


def checked_obj(path: str, name: str) -> bytes | None:
    """InputError for an OBJ face that uses vertex index 0, or an index past the elements the
    file holds; an OBJ with relative (negative) indices as the same text with absolute ones.

    Parameters
    ----------
    path : the .obj file.
    name : how messages call it.

    Returns
    -------
    bytes, the OBJ for trimesh to read instead of the file; None: read the file as it is.
    """
    data = read_text(path, name)
    found = OBJ_ZERO_INDEX.search(data)
    if found:
        line = data.count(b"\n", 0, found.start()) + 1
        raise InputError(f"{name}: line {line}: a face uses vertex index 0 (OBJ counts vertices "
                         "from 1)")
    return obj_with_absolute_indices(data, name) if OBJ_RELATIVE.search(data) else None


def obj_with_absolute_indices(data: bytes, name: str) -> bytes:
    """An OBJ's text with every face index absolute and checked in range (line by line: for a
    file with relative indices, or one trimesh could not read).

    Parameters
    ----------
    data : the OBJ's bytes.
    name : how messages call it.

    Returns
    -------
    bytes.

    Raises
    ------
    InputError
        For a face index past the vertices (texture coordinates, normals) of the file, or a
        relative one before its first, naming the line.
    """
    lines = data.split(b"\n")
    totals = [0, 0, 0]
    for line in lines:
        head = line.split(None, 1)[:1]
        if head and head[0] in OBJ_ELEMENTS:
            totals[OBJ_ELEMENTS.index(head[0])] += 1
    seen = [0, 0, 0]
    for number, line in enumerate(lines):
        words = line.split()
        if words and words[0] in OBJ_ELEMENTS:
            seen[OBJ_ELEMENTS.index(words[0])] += 1
        elif words and words[0] == b"f":
            corners = [b"/".join(_absolute(part, kind, seen, totals, name, number + 1)
                                 for kind, part in enumerate(corner.split(b"/")))
                       for corner in words[1:]]
            lines[number] = b"f " + b" ".join(corners)
    return b"\n".join(lines)


def _absolute(part: bytes, kind: int, seen: list, totals: list, name: str, line: int) -> bytes:
    """One index of a face corner (v, vt or vn by `kind`) made absolute and checked."""
    if not part:
        return part
    what, plural = (("vertex", "vertices"), ("texture coordinate", "texture coordinates"),
                    ("normal", "normals"))[kind]
    try:
        index = int(part)
    except ValueError:
        raise InputError(f"{name}: line {line}: a face's {what} index is not an integer "
                         f"({part.decode(errors='replace')!r})") from None
    absolute = seen[kind] + index + 1 if index < 0 else index
    if not 1 <= absolute <= totals[kind]:
        raise InputError(f"{name}: line {line}: a face uses {what} {index}, but the file holds "
                         f"{totals[kind]} {plural}" + (f" ({seen[kind]} before the face)"
                                                      if index < 0 else ""))
    return str(absolute).encode()


def check_off(path: str, name: str) -> None:
    """InputError for an OFF file that holds fewer vertices or faces than its header declares
    (a file cut short: trimesh reads the faces there are as a smaller mesh).

    Parameters
    ----------
    path : the .off file.
    name : how messages call it.
    """
    data = read_text(path, name)
    lines = []  # the first two lines that hold something (the header), read lazily
    for found in re.finditer(rb"[^\n]+", data):
        words = found.group().split(b"#", 1)[0].split()
        if words:
            lines.append(words)
            if len(lines) == 2:
                break
    if not lines or not lines[0][0].endswith(b"OFF"):
        return  # not a header trimesh reads: its own message says so
    counts = lines[0][1:] or (lines[1] if len(lines) > 1 else [])
    try:
        vertices, faces = int(counts[0]), int(counts[1])
    except (IndexError, ValueError):
        raise InputError(f"{name}: the OFF header must give the numbers of vertices and faces "
                         "after OFF") from None
    filled = data.count(b"\n") + 1 - sum(1 for _ in OFF_EMPTY_LINE.finditer(data))
    body = filled - (1 if lines[0][1:] else 2)
    if vertices < 0 or faces < 0 or body < vertices + faces:
        held = max(0, min(body, vertices))
        raise InputError(f"{name}: the OFF header declares {vertices} vertices and {faces} faces; "
                         f"the file holds {held} vertices and {max(0, body - vertices)} faces "
                         "(a file cut short?)")


def check_ply(path: str, name: str) -> None:
    """InputError for a PLY file that holds less than the elements its header declares (a file
    cut short): an ASCII one fewer lines (trimesh read the faces there were as a smaller mesh),
    a binary one fewer bytes (`check_binary_ply`).

    Parameters
    ----------
    path : the .ply file.
    name : how messages call it.
    """
    data = read_text(path, name)
    end = data.find(b"end_header")
    if not data.startswith(b"ply") or end < 0:
        return  # not a header trimesh reads: its own message says so
    header = [line.split() for line in data[:end].decode("ascii", "replace").splitlines()]
    try:
        elements = [(words[1], int(words[2])) for words in header if words[:1] == ["element"]]
    except (IndexError, ValueError):
        raise InputError(f"{name}: a PLY element must give its name and count") from None
    if ["format", "ascii", "1.0"] not in header:
        check_binary_ply(data[data.find(b"\n", end) + 1:], header, elements, name)
        return
    body = sum(1 for line in data[end:].split(b"\n")[1:] if line.strip())
    declared = sum(max(0, count) for _, count in elements)
    if body < declared:
        held, left = [], body
        for _, count in elements:
            held.append(min(left, count))
            left -= held[-1]
        raise InputError(f"{name}: the PLY header declares "
                         + " and ".join(f"{count} {kind}" for kind, count in elements)
                         + " elements; the file holds " + " and ".join(map(str, held))
                         + " (a file cut short?)")


# Bytes of each PLY scalar type (the PLY format's names and their sized aliases).
PLY_SIZES = {"char": 1, "uchar": 1, "int8": 1, "uint8": 1, "short": 2, "ushort": 2, "int16": 2,
             "uint16": 2, "int": 4, "uint": 4, "int32": 4, "uint32": 4, "float": 4,
             "float32": 4, "double": 8, "float64": 8}


def check_binary_ply(body: bytes, header: list, elements: list, name: str) -> None:
    """InputError for a binary PLY whose body is shorter than its header's elements need: the
    fixed-size properties exactly, a list at least its count (and three indices for a face's
    vertex list: a face has three corners or more). trimesh said only "PLY is unexpected
    length!". A header this cannot size (an unknown type) is left to trimesh.

    Parameters
    ----------
    body : the bytes after the header's end_header line.
    header : the header's lines, split in words.
    elements : (name, count) of each element, in order.
    name : how messages call the file.
    """
    needs, current = {}, None
    for words in header:
        if words[:1] == ["element"]:
            current = words[1]
            needs[current] = 0
        elif words[:1] == ["property"] and current is not None:
            if words[1:2] == ["list"] and len(words) >= 5:
                least = 3 if words[4] in ("vertex_indices", "vertex_index") else 0
                sizes = PLY_SIZES.get(words[2]), PLY_SIZES.get(words[3])
                if None in sizes:
                    return
                needs[current] += sizes[0] + least * sizes[1]
            elif len(words) >= 3 and words[1] in PLY_SIZES:
                needs[current] += PLY_SIZES[words[1]]
            else:
                return
    need = sum(needs.get(kind, 0) * max(0, count) for kind, count in elements)
    if len(body) < need:
        raise InputError(f"{name}: the PLY header declares "
                         + " and ".join(f"{count} {kind}" for kind, count in elements)
                         + f" elements, at least {need} bytes; the file holds {len(body)} "
                         "after its header (a file cut short?)")


def check_stl_length(path: str, name: str) -> None:
    """InputError for a binary STL shorter than the triangle count of its header says, or an
    ASCII STL without its closing `endsolid` (cut short: trimesh reads none of its triangles).

    Parameters
    ----------
    path : the .stl file.
    name : how messages call it.
    """
    size = os.path.getsize(path)
    with open(path, "rb") as file:
        head = file.read(84)
    if head.lstrip().startswith(b"solid") and b"facet" in head:
        if b"endsolid" not in read_text(path, name)[-4096:]:
            raise InputError(f"{name}: an ASCII STL cut short (it does not end in endsolid)")
        return
    if len(head) < 84:
        return
    count = int.from_bytes(head[80:84], "little")
    if 84 + 50 * count > size:
        raise InputError(f"{name}: truncated binary STL: the header announces {count} "
                         f"triangles, the file holds {(size - 84) // 50}")
