"""Models: a mesh moved by its harmonics, or a rig moved by its vibration modes
(docs/design.md#inputs).

One rule says what a file is, by its content (`classify`): a skeleton JSON (its "format" says
"eigendance.skeleton") is a rig and any other JSON a mapping; a glTF with a skin is a rig (as
the page shows it), any other model file a mesh; a built-in rig's name is that rig; a .npz is a
basis file. `read_model` reads a model once into the value the work takes — a mesh's
`HarmonicProblem` (which the server's reading worker saves for its solve's), a rig's
`Skeleton` or a basis — and `published_suffixes` is what the page is told to accept
(`GET /api/config`).
"""

from __future__ import annotations

import dataclasses
import os
from dataclasses import dataclass

from eigendance.assets.gltf import document_json
from eigendance.errors import InputError
from eigendance.files import (
    ARCHIVE_SUFFIXES,
    AUDIO_SUFFIXES,
    BASIS_SUFFIXES,
    COMPANION_SUFFIXES,
    MAPPING_SUFFIXES,
    MESH_SUFFIXES,
    RIG_SUFFIXES,
    check_readable,
    kind_of,
    read_json,
    suffix_of,
)
from eigendance.harmonic.basis import HarmonicBasis, HarmonicProblem
from eigendance.harmonic.mesh import load_mesh
from eigendance.modal.sample_rigs import SAMPLE_RIGS, load_rig
from eigendance.modal.skeleton import Skeleton
from eigendance.modal.skeleton_file import FORMAT as SKELETON_FORMAT

GLTF_SUFFIXES = (".glb", ".gltf")
MODEL_KINDS = ("mesh", "rig", "basis")


@dataclass
class Model:
    """A model read once: exactly one of `problem` (a mesh), `skeleton` (a rig) and `basis`
    (a basis file) is set, as `kind` says.

    Parameters
    ----------
    kind : "mesh", "rig" or "basis".
    name : how messages and outputs call it.
    problem : a mesh's `HarmonicProblem`.
    skeleton : a rig's `Skeleton`, with its skin.
    basis : a basis file's `HarmonicBasis`.
    """

    kind: str
    name: str
    problem: HarmonicProblem | None = None
    skeleton: Skeleton | None = None
    basis: HarmonicBasis | None = None


def built_in(source: str | os.PathLike, folder: str | os.PathLike = "") -> bool:
    """Whether `source` names a built-in rig (and no file of that name exists).

    Parameters
    ----------
    source : a path or a rig's name.
    folder : where a relative path is (a set list's folder; default: the working folder).

    Returns
    -------
    bool.
    """
    return os.fspath(source) in SAMPLE_RIGS and not os.path.exists(os.path.join(folder, source))


def model_source(source: str, folder: str | os.PathLike) -> str:
    """A model named in a file (a set list's cue): a built-in rig's name, as the commands take
    it, else the file relative to `folder`.

    Parameters
    ----------
    source : what the file says.
    folder : the file's folder.

    Returns
    -------
    The rig's name, or the file's absolute path; InputError for a file that is not there.
    """
    if built_in(source, folder):
        return source
    return os.path.abspath(check_readable(os.path.join(folder, source)))


def classify(path: str | os.PathLike, name: str | None = None) -> tuple[str, object]:
    """What a file is, by its content: the one rule of every front end (module docstring).

    Parameters
    ----------
    path : the file, or a built-in rig's name.
    name : how messages call it (default: the file's name); its suffix is the file's.

    Returns
    -------
    (kind, document): kind "mesh", "rig", "mapping", "audio" or "basis"; document the parsed
    JSON of a .json file (read once, for `read_model` or the mapping), else None.

    Raises
    ------
    InputError
        For a missing, empty or unreadable file, a JSON that is not JSON, and a suffix of no
        kind (status 415).
    """
    if built_in(path):
        return "rig", None
    path = check_readable(path)
    name = name or os.path.basename(path)
    suffix = suffix_of(name)
    if suffix in BASIS_SUFFIXES:
        return "basis", None
    kind = kind_of(name)
    if kind == "mapping":
        document = read_json(path, name)
        skeleton = isinstance(document, dict) and document.get("format") == SKELETON_FORMAT
        return ("rig" if skeleton else "mapping"), document
    if kind == "mesh" and suffix in GLTF_SUFFIXES and (document_json(path, name) or {}).get(
            "skins"):
        return "rig", None
    return kind, None


def model_kind(path: str | os.PathLike, as_mesh: bool = False) -> str:
    """What a model file is (`classify`), for the commands that take one.

    Parameters
    ----------
    path : the file, or a built-in rig's name.
    as_mesh : the person asked for a skinned glTF's harmonics (--mesh), not its skeleton.

    Returns
    -------
    "mesh", "rig" or "basis".

    Raises
    ------
    InputError
        As `classify`; for a mapping or an audio file given as the model; for `as_mesh` with
        a skeleton JSON or a built-in rig (they have no mesh of their own).
    """
    kind, _ = classify(path)
    name = os.path.basename(os.fspath(path))
    if kind not in MODEL_KINDS:
        raise InputError(f"{name}: {'a mapping' if kind == 'mapping' else 'an audio file'}, "
                         "not a model (a mesh, a rig or a basis file)")
    if as_mesh and kind == "rig":
        if suffix_of(path) not in GLTF_SUFFIXES:
            raise InputError(f"{name}: a skeleton has no mesh of its own to move by its "
                             "harmonics; --mesh is for a glTF with a skin")
        return "mesh"
    return kind


def read_model(path: str | os.PathLike, name: str | None = None, kind: str | None = None,
               document=None, **problem) -> Model:
    """A model read once into the value the work takes (`Model`).

    Parameters
    ----------
    path : the file, or a built-in rig's name.
    name : how messages call it (default: the file's or the rig's name).
    kind : "mesh", "rig" or "basis" (default `model_kind`: a skinned glTF is a rig).
    document : a skeleton JSON's document, already parsed by `classify`.
    **problem : the options of a mesh's `HarmonicProblem` (laplacian, construction, samples,
        solver, cache).

    Returns
    -------
    Model.

    Raises
    ------
    InputError
        As `model_kind`; and what the reader of the kind raises: `load_mesh` (an unreadable or
        degenerate mesh), `load_rig` (a skeleton or skin that cannot be analysed),
        `HarmonicBasis.load` (a basis file at fault), `HarmonicProblem` (an unknown
        construction or Laplacian).
    """
    kind = kind or model_kind(path)
    name = name or os.path.basename(os.fspath(path))
    if kind == "rig":
        return Model(kind, name, skeleton=load_rig(path, name, document))
    if kind == "basis":
        return Model(kind, name, basis=HarmonicBasis.load(path))
    mesh = dataclasses.replace(load_mesh(path), name=name)
    return Model(kind, name, problem=HarmonicProblem(mesh, **problem))


def published_suffixes() -> dict[str, list[str]]:
    """The suffixes of each input kind, as the page is told them (`GET /api/config`): what it
    may upload, and which files of a model it zips together.

    Returns
    -------
    {"mesh", "rig", "audio", "mapping", "archive", "companion": [suffix, …]}.
    """
    return {"mesh": list(MESH_SUFFIXES), "rig": list(RIG_SUFFIXES),
            "audio": list(AUDIO_SUFFIXES), "mapping": list(MAPPING_SUFFIXES),
            "archive": list(ARCHIVE_SUFFIXES), "companion": list(COMPANION_SUFFIXES)}
