"""Exports of a dance to files other tools open: glTF (.glb), point cache (.pc2 + .obj) and USD
(docs/design.md#exports).

`export_dance` samples the dance at t_i = i/fps, i = 0 … ⌊duration·fps⌋, writes the chosen
format and puts the song beside it (named after the export, the song's suffix kept), all or
nothing (`output.Outputs`). The dance may be a window of its song (`Dance.window`,
docs/design.md#window): the files then start at its time 0, and the song beside them is cut to
the same part (`export.song`). This is the one call the command line and the server make:

    export_dance(HarmonicDance(basis, spectrogram, mapping, "song.ogg").window(30, 15),
                 "clip.glb")
"""

from __future__ import annotations

import filecmp
import os

import numpy as np

from eigendance.errors import InputError
from eigendance.export.dance import Dance
from eigendance.export.gltf import glb_size, write_glb
from eigendance.export.look_files import mtl_text, obj_text, texture_files, write_textures
from eigendance.export.output import Outputs
from eigendance.export.pointcache import pc2_size, write_pc2
from eigendance.export.rig_dance import RigDance
from eigendance.export.song import cut_song
from eigendance.export.usd import write_usd
from eigendance.files import suffix_of
from eigendance.inputs.defaults import DEFAULT_FPS
from eigendance.limits import check_memory, check_output
from eigendance.music.spectrogram import frame_times

FORMATS = {"glb": (".glb",), "pc2": (".pc2",), "usd": (".usd", ".usdc", ".usda")}


def format_of(path: str | os.PathLike, format: str | None = None) -> str:
    """The export format: `format` if given (checked against the suffix), else by suffix.

    Parameters
    ----------
    path : the file to write.
    format : "glb", "pc2" or "usd", or None.

    Returns
    -------
    str, the format; InputError for an unknown suffix or one that is not the format's.
    """
    suffix = suffix_of(path)
    if format is None:
        for name, suffixes in FORMATS.items():
            if suffix in suffixes:
                return name
        known = ", ".join(s for suffixes in FORMATS.values() for s in suffixes)
        raise InputError(f"{os.fspath(path)}: unknown export format '{suffix or '(none)'}' "
                         f"(expected one of {known})")
    if format not in FORMATS:
        raise InputError(f"unknown export format {format!r} (expected one of "
                         f"{', '.join(FORMATS)})")
    if suffix not in FORMATS[format]:
        raise InputError(f"{os.fspath(path)}: a {format} file must end in "
                         f"{' or '.join(FORMATS[format])}")
    return format


def companion_paths(path: str | os.PathLike, format: str, audio: str | None,
                    clipped: bool = False, appearance=None) -> dict:
    """The files an export writes.

    Parameters
    ----------
    path : the main file.
    format : "glb", "pc2" or "usd".
    audio : the song's file, or None.
    clipped : the song is cut to a window (it is written anew, never the song itself).
    appearance : the model's look (`assets.Appearance`), or None.

    Returns
    -------
    {"main", "mesh" (pc2's rest OBJ), "song", and with a look outside a glb "materials" (pc2's
    MTL) and "texture<i>" (each image)}: paths, None for a file not written (a whole song
    already there under that name, from an earlier export, is not written again).
    """
    path = os.fspath(path)
    stem = os.path.splitext(path)[0]
    song = None
    if audio is not None:
        song = stem + suffix_of(audio)
        same = os.path.abspath(song) == os.path.abspath(audio)
        if clipped and same:
            raise InputError(f"{path}: the clip's song would replace {os.path.basename(audio)} "
                             "itself; give the export another name")
        if not clipped and (same or (os.path.isfile(song)
                                     and filecmp.cmp(song, audio, shallow=False))):
            song = None  # the song is already there under that name (an earlier export's)
    paths = {"main": path, "mesh": stem + ".obj" if format == "pc2" else None, "song": song}
    if appearance is not None and format != "glb":
        paths["materials"] = stem + ".mtl" if format == "pc2" else None
        paths.update({f"texture{index}": texture for index, texture in
                      enumerate(texture_files(path, appearance))})
    return paths


def export_dance(dance: Dance, path: str | os.PathLike, format: str | None = None,
                 fps: float = DEFAULT_FPS, force: bool = False, progress=None, inputs=()) -> dict:
    """Write `dance` as glTF, point cache or USD, with its song beside it.

    Parameters
    ----------
    dance : a `HarmonicDance` or a `RigDance`, or a window of one (`Dance.window`).
    path : the file to write; its suffix names the format unless `format` does.
    format : "glb", "pc2" or "usd" (None: by suffix).
    fps : samples per second.
    force : overwrite existing files (never one of `inputs`).
    progress : optional callable(frames done, frames in all).
    inputs : the files the export reads (the model, the mapping): never written over.

    Returns
    -------
    {"format", "files" (written), "frames", "fps", "bytes" (of the main file),
    "point_cache_bytes" (the same motion as a .pc2), "skinning_difference" (glb of a
    modal-skinned rig: the largest distance between its linear blend skinning and the modal
    skinning, model units; else None), "diagonal"}.
    """
    format = format_of(path, format)
    if not (np.isfinite(fps) and 0 < fps <= 1000):
        raise InputError(f"frames per second must be in (0, 1000], got {fps}")
    times = frame_times(dance.duration, fps)
    look = dance.appearance
    paths = companion_paths(path, format, dance.audio, dance.clipped, look)
    written = [p for p in paths.values() if p is not None]
    textures = [p for name, p in paths.items() if name.startswith("texture")]
    song_name = None if dance.audio is None else \
        os.path.basename(os.path.splitext(paths["main"])[0] + suffix_of(dance.audio))
    if paths["song"] is None and dance.audio is not None and \
            os.path.abspath(dance.audio) == os.path.abspath(paths["main"]):
        song_name = os.path.basename(dance.audio)

    planned = planned_bytes(dance, format, len(times), paths)
    what = f"{os.path.basename(paths['main'])}: {len(times)} frames of {dance.n} vertices"

    def step(done):
        if progress is not None:
            progress(done, len(times))

    outputs = Outputs(written, force, [*inputs, dance.audio])
    check_output(paths["main"], planned, what, force)  # the free disk, and --force beyond 4 GB
    if format == "usd":  # usd-core keeps every time sample (12 bytes a vertex) in memory
        check_memory(12.0 * dance.n * (len(times) + 1), f"{what} in USD")
    with outputs:
        main = outputs.temporary(paths["main"])
        difference = _write(format, dance, times, fps, main, song_name, step, textures)
        if format == "pc2":
            _write_obj(outputs, paths, dance, os.path.basename(path), textures)
        if textures:
            write_textures(outputs, look, textures)
        if paths["song"] and dance.clipped:
            cut_song(dance.audio, outputs.temporary(paths["song"]), dance.start, dance.duration)
        elif paths["song"]:
            outputs.copy(dance.audio, paths["song"])
        size = os.path.getsize(main)
    return {"format": format, "files": written, "frames": len(times), "fps": fps,
            "bytes": size, "point_cache_bytes": pc2_size(dance.n, len(times)),
            "skinning_difference": difference, "diagonal": dance.diagonal}


# Bytes per vertex and frame of a .usda (text: three numbers of about ten characters each).
USDA_BYTES = 36


def planned_bytes(dance: Dance, format: str, frames: int, paths: dict) -> float:
    """About how many bytes an export writes, known before it is written (checked against the
    free disk, and beyond 4 GB only with `--force`: `limits.check_output`).

    Point cache: exactly its size, plus the rest OBJ (about 40 bytes a vertex and 30 a
    triangle). USD: 12 bytes a vertex and frame (.usdc, .usd) or `USDA_BYTES` (.usda), plus the
    rest points and the faces. glb of a harmonic dance: `gltf.glb_size` (the skin of a reduced
    basis, else the morph targets); of a rig: its mesh and the skin's animation (28 bytes a body
    and frame). Plus the song when it is written beside.

    Parameters
    ----------
    dance : the dance.
    format : "glb", "pc2" or "usd".
    frames : how many frames.
    paths : `companion_paths`.

    Returns
    -------
    float, bytes.
    """
    n = dance.n
    if format == "pc2":
        planned = pc2_size(n, frames) + 40.0 * n + 30.0 * len(dance.faces)
    elif format == "usd":
        per_vertex = USDA_BYTES if suffix_of(paths["main"]) == ".usda" else 12
        planned = float(per_vertex) * n * (frames + 1) + 12.0 * len(dance.faces)
    elif isinstance(dance, RigDance):
        planned = 60.0 * n + 12.0 * len(dance.faces) + 28.0 * len(dance.body_names) * frames
    else:
        sizes = glb_size(dance, frames)
        planned = float(sizes.get("skin", sizes["morph targets"]))
    if paths.get("song") and dance.audio is not None and os.path.isfile(dance.audio):
        planned += os.path.getsize(dance.audio)
    return planned


def _write(format: str, dance: Dance, times, fps: float, path: str, song_name: str | None,
           step, textures) -> float | None:
    """Write the main file of an export; the skinning difference of a modal-skinned rig's glb
    (else None)."""
    if format == "glb":
        extras = {"audio": song_name, "fps": fps, "frames": len(times),
                  "duration": dance.duration, "start": dance.start, **dance.info}
        with open(path, "wb") as file:
            write_glb(file, dance, times, extras)
        step(len(times))
        if isinstance(dance, RigDance) and dance.skinning == "modal":
            return skinning_difference(dance, times)
    elif format == "pc2":
        with open(path, "wb") as file:
            write_pc2(file, dance, times, step)
    else:
        write_usd(path, dance, times, fps, song_name, step, textures)
    return None


def _write_obj(outputs, paths, dance: Dance, name: str, textures) -> None:
    """The rest mesh beside a point cache (with its MTL when the dance has a look)."""
    comment = f"eigendance: rest mesh of {name}"
    with open(outputs.temporary(paths["mesh"]), "w", encoding="utf-8") as file:
        file.write(obj_text(dance.rest, dance.faces, comment, dance.appearance,
                            paths.get("materials", "")))
    if dance.appearance is not None:
        with open(outputs.temporary(paths["materials"]), "w", encoding="utf-8") as file:
            file.write(mtl_text(dance.appearance, textures))


def skinning_difference(dance: RigDance, times) -> float:
    """The largest distance between a rig's modal skinning and the linear blend skinning of
    the same body transforms (what a glTF skin plays) over `times`, model units.

    Parameters
    ----------
    dance : a modal-skinned `RigDance`.
    times : (T,) s.

    Returns
    -------
    float.
    """
    largest = 0.0
    for first, positions, _ in dance.frames(times):
        blended = dance.blend_positions(times[first:first + len(positions)])
        largest = max(largest, float(np.linalg.norm(positions - blended, axis=-1).max()))
    return largest
