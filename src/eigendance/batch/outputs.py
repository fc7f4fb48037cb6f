"""The files a batch writes in its output folder, and the plans refused for them
(docs/design.md#batch).

A job `{model}-{song}-{item}` writes `{stem}.{ext}` for each format and, beside an export, the
song (`{stem}.wav` …), a point cache's rest mesh and its materials (`{stem}.obj`, `{stem}.mtl`)
and the images of a look (`{stem}_texture0.png` …). Before anything is read or written, a plan
is refused in one line, `--force` or not, when two of these names are the same ignoring case
(as macOS and Windows see them), or when one of them is an input of the plan: a model, a file a
model names (an MTL, an image, a glTF's buffer), a song, a mapping, the plan itself, or the
record or the report of the folder.
"""

from __future__ import annotations

import os
import re

from eigendance.batch.content import referenced_files
from eigendance.batch.plan import FORMATS, Job, Plan
from eigendance.batch.record import RECORD, REPORT
from eigendance.errors import InputError
from eigendance.writes import same_file

# A look's image beside an export (`export.look_files.texture_files`), its stem the group.
TEXTURES = re.compile(r"(.+)_texture[0-9]+\.[a-z0-9]+")


def written_names(job: Job, format: str) -> list[str]:
    """The names an output of a job writes in the output folder: its file, the song beside an
    export, a point cache's rest mesh and its materials (the images of a look are named after
    the stem: TEXTURES).

    Parameters
    ----------
    job : the job.
    format : one of FORMATS.

    Returns
    -------
    list of file names, the output's first.
    """
    names = [job.stem + FORMATS[format]]
    if format in ("glb", "pc2", "usd"):
        names.append(job.stem + os.path.splitext(job.song.path)[1].lower())
    if format == "pc2":
        names += [job.stem + ".obj", job.stem + ".mtl"]
    return names


def inputs_of(plan: Plan) -> list[str]:
    """Every file a plan reads or keeps: the plan, its models and the files they name, its
    songs and mappings, and the output folder's record and report.

    Parameters
    ----------
    plan : the plan.

    Returns
    -------
    list of paths.
    """
    files = [plan.path, os.path.join(plan.out, RECORD), os.path.join(plan.out, REPORT)]
    for model in plan.models:
        if os.path.isfile(model.path):  # not a built-in rig
            files += [model.path, *referenced_files(model.path)]
    files += [song.path for song in plan.songs]
    files += [item.path for item in plan.items if item.path is not None]
    return files


def check_outputs(plan: Plan) -> None:
    """InputError, before any work and whatever `--force` says, for two outputs of one name
    (ignoring case) or an output that would replace an input (module docstring). The names of a
    job all start with its stem, so the stems are compared, and each input in the output folder
    with the names of the job whose stem its name starts with.

    Parameters
    ----------
    plan : the plan.
    """
    stems: dict[str, Job] = {}
    for job in plan.jobs():
        other = stems.setdefault(job.stem.lower(), job)
        if other is not job:
            raise InputError(f"{plan.path}: jobs {other.stem} and {job.stem} would write the "
                             "same files (names differ only in case); rename an input")
    textures = bool(set(plan.outputs) & {"pc2", "usd"})  # a look's images beside them
    for path in inputs_of(plan):
        if not _in_folder(path, plan.out):
            continue
        name = os.path.basename(path).lower()
        job = stems.get(os.path.splitext(name)[0])
        written = job is not None and name in {written.lower() for format in plan.outputs
                                               for written in written_names(job, format)}
        image = TEXTURES.fullmatch(name)
        if not written and image is not None and textures:
            job = stems.get(image.group(1))
            written = job is not None
        if written:
            raise InputError(f"{plan.path}: job {job.stem} would write over {path}, an input "
                             "of the plan; an input is never overwritten: give another out "
                             "folder")


def _in_folder(path: str, folder: str) -> bool:
    """Whether `path` lies directly in `folder` (by identity where both exist)."""
    return same_file(os.path.dirname(os.path.abspath(path)), folder)
