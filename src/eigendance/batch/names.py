"""Output names of a batch: `{model}-{song}-{item}.{ext}`, safe and unique
(docs/design.md#batch).

A name part is the input's file name without its suffix, reduced to ASCII letters, digits and
`_` (accents dropped, every other run of characters one `_`), at most 60 characters, so the dash
only ever separates the three parts and a name is the same on every file system. Inputs of one
kind whose parts would collide (ignoring case, as macOS and Windows do) are told apart by their
suffix first (`bunny_obj`, `bunny_ply`), then by their folders (`a_bunny`, `b_bunny`), then by
their position in the plan (`bunny_2`, the first number no other part holds): distinct
ignoring case by construction.
"""

from __future__ import annotations

import os
import re
import unicodedata

LONGEST = 60  # characters of one part


def safe_part(text: str, fallback: str = "item") -> str:
    """`text` as a part of an output name: ASCII letters, digits and `_`, at most LONGEST.

    Parameters
    ----------
    text : a file's name without its suffix, or a built-in rig's name.
    fallback : the part when nothing of `text` is left.

    Returns
    -------
    str.

    Example
    -------
    >>> safe_part("Café del Mar (remix)"), safe_part("..."), safe_part("a-b.c")
    ('Cafe_del_Mar_remix', 'item', 'a_b_c')
    """
    ascii_text = unicodedata.normalize("NFKD", text).encode("ascii", "ignore").decode()
    part = re.sub(r"[^A-Za-z0-9]+", "_", ascii_text).strip("_")[:LONGEST].strip("_")
    return part or fallback


def unique_parts(paths: list[str], fallback: str) -> list[str]:
    """The name part of each input, told apart where they would collide (module docstring).

    Parameters
    ----------
    paths : the inputs as the plan resolved them (files or built-in names), each once.
    fallback : the part of a name with nothing safe in it ("model", "song", "item").

    Returns
    -------
    list of str, one per path, distinct ignoring case.

    Example
    -------
    >>> unique_parts(["a/bunny.obj", "a/bunny.ply", "b/cat.obj", "c/cat.obj", "x.obj"], "model")
    ['bunny_obj', 'bunny_ply', 'b_cat', 'c_cat', 'x']
    >>> unique_parts(["d1/a/b/c/bunny.obj", "d2/a/b/c/bunny.obj", "a_b_c_bunny_2.obj"], "model")
    ['a_b_c_bunny', 'a_b_c_bunny_3', 'a_b_c_bunny_2']
    """
    def stem(path):
        return safe_part(os.path.splitext(os.path.basename(path))[0], fallback)

    def with_suffix(path):
        return safe_part(os.path.basename(path), fallback)

    def with_folders(path, depth):
        pieces = os.path.normpath(os.path.splitext(path)[0]).split(os.sep)[-depth - 1:]
        return safe_part("_".join(pieces), fallback)

    parts = [stem(path) for path in paths]
    for rename in [with_suffix] + [lambda path, d=d: with_folders(path, d) for d in (1, 2, 3)]:
        clashing = _clashes(parts)
        if not clashing:
            return parts
        parts = [rename(path) if index in clashing else part
                 for index, (path, part) in enumerate(zip(paths, parts, strict=True))]
    # Still the same: numbered in the plan's order, each number checked against every part
    # taken (`d1/…/bunny`, `d2/…/bunny` and `bunny_2` give bunny, bunny_3, bunny_2).
    clashing = _clashes(parts)
    taken = {part.lower() for index, part in enumerate(parts) if index not in clashing}
    for index in sorted(clashing):
        part, count = parts[index], 1
        while parts[index].lower() in taken:
            count += 1
            parts[index] = f"{part}_{count}"
        taken.add(parts[index].lower())
    return parts


def _clashes(parts: list[str]) -> set[int]:
    """Indices of the parts another part equals, ignoring case."""
    groups: dict[str, list[int]] = {}
    for index, part in enumerate(parts):
        groups.setdefault(part.lower(), []).append(index)
    return {index for group in groups.values() if len(group) > 1 for index in group}
