"""Content keys of a batch: what an output depends on, as one SHA-256 (docs/design.md#batch).

An output's key covers the model's content (its file and the files it names: an OBJ's MTL files
and their images, a .gltf's buffers and images), the song's content (its file), the item (the
gallery's size and index, or the mapping file's content), the settings that output depends on
(k for a mesh, fps, the window, the size of a video) and the version of the code and of the
record. Renaming or moving an input keeps its key; changing a byte of it changes the key.
"""

from __future__ import annotations

import hashlib
import json
import os

from eigendance import __version__
from eigendance.batch.plan import Item, Job, Model, Plan
from eigendance.files import file_digest, read_json, suffix_of

# Bump when what a job writes changes without a new eigendance version (2: the rhythm,
# mapping v3: gallery items with envelopes and beat pulses).
RECORD_VERSION = 2


def referenced_files(path: str) -> list[str]:
    """The files a model file names that exist beside it: an OBJ's `mtllib` files and the
    images their `map_*`/`bump`/`disp`/`refl` lines name, a .gltf's buffers and images (not
    data: URIs).

    Parameters
    ----------
    path : a model file.

    Returns
    -------
    list of paths, in the order they are named.
    """
    folder = os.path.dirname(path)
    names: list[str] = []
    suffix = suffix_of(path)
    try:
        if suffix == ".obj":
            for line in _lines(path):
                if line.startswith("mtllib "):
                    names += [os.path.join(folder, name) for name in line.split()[1:]]
            for material in list(names):
                names += [os.path.join(os.path.dirname(material), line.split()[-1])
                          for line in _lines(material)
                          if line.split()[:1] and line.split()[0].lower().startswith(
                              ("map_", "bump", "disp", "decal", "refl"))]
        elif suffix == ".gltf":
            document = read_json(path)
            for entry in document.get("buffers", []) + document.get("images", []):
                uri = entry.get("uri") if isinstance(entry, dict) else None
                if isinstance(uri, str) and not uri.startswith("data:"):
                    names.append(os.path.join(folder, uri))
    except Exception:  # noqa: BLE001 - an unreadable model fails in its job, with its reason
        return []
    return [name for name in dict.fromkeys(names) if os.path.isfile(name)]


def _lines(path: str) -> list[str]:
    with open(path, encoding="utf-8", errors="replace") as file:
        return [line.strip() for line in file]


def model_digest(model: Model) -> str:
    """The content of a model: its file and the files it names, or a built-in rig's name.

    Parameters
    ----------
    model : a model of the plan.

    Returns
    -------
    str, SHA-256.
    """
    if not os.path.isfile(model.path):  # a built-in rig: the code makes it
        return hashlib.sha256(f"built-in {model.path}".encode()).hexdigest()
    parts = [file_digest(model.path)] + [f"{os.path.basename(name)}:{file_digest(name)}"
                                         for name in referenced_files(model.path)]
    return hashlib.sha256(" ".join(parts).encode()).hexdigest()


def item_identity(item: Item) -> str:
    """What an item is: the gallery's size and index, or the mapping file's content.

    Parameters
    ----------
    item : an item of the plan.

    Returns
    -------
    str.
    """
    if item.path is None:
        return f"gallery {item.gallery} item {item.index}"
    return f"mapping {file_digest(item.path)}"


def output_key(plan: Plan, job: Job, format: str, digests: dict[str, str]) -> str:
    """The key of one output of a job: everything its bytes depend on (module docstring).

    Parameters
    ----------
    plan : the plan (settings).
    job : the job.
    format : the output's format.
    digests : {input path: its content digest} (`model_digest`, `file_digest`,
        `item_identity`), for every model, song and mapping of the job.

    Returns
    -------
    str, SHA-256.
    """
    settings = {"format": format, "fps": plan.fps, "start": plan.start,
                "duration": plan.duration, "kind": job.model.kind}
    if job.model.kind == "mesh":
        settings["k"] = plan.k
        if plan.construction != "auto":  # the rule's choice follows from the model and k
            settings["basis"] = [plan.construction, plan.samples]
    elif plan.surface is not None:  # a rig's rippling skin (docs/design.md#surface-of-a-rig)
        settings["surface"] = plan.surface if isinstance(plan.surface, str) else \
            plan.surface.to_json()
    if format == "mp4":
        settings["size"] = list(plan.size)
    identity = {"eigendance": __version__, "record": RECORD_VERSION, "stem": job.stem,
                "model": digests[job.model.path], "song": digests[job.song.path],
                "item": digests[item_key(job.item)], "settings": settings}
    return hashlib.sha256(json.dumps(identity, sort_keys=True).encode()).hexdigest()


def item_key(item: Item) -> str:
    """The entry of an item in the digests of `output_key`.

    Parameters
    ----------
    item : an item.

    Returns
    -------
    str.
    """
    return item.path or f"gallery:{item.gallery}:{item.index}"
