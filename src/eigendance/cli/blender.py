"""The Blender commands (docs/design.md#blender-add-on): `blender-addon` writes the add-on (an
extension zip), and `bake` writes what the add-on reads back, a mesh's dance vertex for vertex
in the order of the mesh file given (its vertices that faces use: mesh readers drop the
others): morph targets (.npz) or a point cache (.pc2).

The add-on runs `eigendance bake` in a subprocess (Blender has numpy but not scipy), so the
dance it bakes is the one `eigendance animate` computes.
"""

from __future__ import annotations

import os
import time
import zipfile
from importlib.resources import files

import numpy as np

from eigendance import __version__
from eigendance.cli.options import (
    FPS,
    HARMONICS,
    add_output,
    add_window_options,
    number,
    progress_bar,
    say_note,
)
from eigendance.errors import InputError
from eigendance.export.dance import HarmonicDance
from eigendance.export.pointcache import pc2_header
from eigendance.files import suffix_of
from eigendance.inputs.defaults import DEFAULT_FPS, DEFAULT_K
from eigendance.inputs.mapping import basis_choice, read_mapping
from eigendance.inputs.model import read_model
from eigendance.inputs.song import read_song
from eigendance.music.gallery import DEFAULT_GALLERY, initial_gallery, strongest_item
from eigendance.music.mapping import Mapping
from eigendance.music.spectrogram import frame_times
from eigendance.writes import atomic_save_npz, atomic_write, refuse_overwrite

ADDON = "eigendance_blender"  # the add-on's package, beside this package's modules
BLENDER_MIN = "4.2.0"

MANIFEST = """schema_version = "1.0.0"

id = "eigendance"
version = "{version}"
name = "eigendance"
tagline = "Bake a mesh's or a rig's dance to a song into the scene"
maintainer = "eigendance authors"
type = "add-on"
license = ["SPDX:MIT"]
blender_version_min = "{blender}"
tags = ["Animation", "Mesh", "Rigging"]

[permissions]
files = "Writes the selected mesh and reads the dance in a temporary folder"
"""


def addon_files() -> dict[str, bytes]:
    """The add-on's files as they go into the zip: its Python modules and the manifest.

    Returns
    -------
    {name in the zip: bytes}, blender_manifest.toml at the zip's root.
    """
    folder = files("eigendance") / "blender" / ADDON
    found = {entry.name: entry.read_bytes() for entry in folder.iterdir()
             if entry.name.endswith(".py")}
    if "__init__.py" not in found:
        raise InputError(f"the add-on's sources are missing from this install ({folder})")
    # The extension's version: a semantic version (0.1.0.dev0 → 0.1.0).
    version = ".".join(__version__.split(".")[:3]).split("+")[0]
    version = "".join(c for c in version if c.isdigit() or c == ".") or "0.0.0"
    found["blender_manifest.toml"] = MANIFEST.format(version=version,
                                                     blender=BLENDER_MIN).encode()
    return found


def add_blender_addon(parser) -> None:
    """The options of `eigendance blender-addon`.

    Parameters
    ----------
    parser : the command's parser.
    """
    add_output(parser, "the add-on to write (.zip; install it in Blender: Edit > Preferences > "
                       "Get Extensions > Install from Disk)")


def run_blender_addon(args) -> None:
    """`eigendance blender-addon`: write the Blender add-on as an extension zip.

    Parameters
    ----------
    args : the parsed command line.
    """
    if suffix_of(args.output) != ".zip":
        raise InputError(f"{args.output}: the add-on is a .zip; name the output .zip")
    refuse_overwrite(args.output, args.force)
    contents = addon_files()

    def write(file):
        with zipfile.ZipFile(file, "w", zipfile.ZIP_DEFLATED) as archive:
            for name, data in sorted(contents.items()):
                archive.writestr(f"{name}", data)

    atomic_write(args.output, write)
    print(f"{args.output}: Blender add-on (extension for Blender {BLENDER_MIN} and later), "
          f"{len(contents) - 1} modules; install it from disk in Blender's preferences")


def add_bake(parser) -> None:
    """The options of `eigendance bake`.

    Parameters
    ----------
    parser : the command's parser.
    """
    parser.add_argument("mesh", help="mesh file (OBJ, PLY, OFF, STL, glTF); the output keeps "
                                     "its vertices, in its order")
    parser.add_argument("audio", help="audio file, or spectrogram file (.npz)")
    which = parser.add_mutually_exclusive_group()
    which.add_argument("--mapping", help="mapping JSON (default: the initial-gallery item of 8 "
                                         "that moves the mesh most)")
    which.add_argument("--item", type=number(1, DEFAULT_GALLERY, integer=True),
                       help=f"the initial-gallery item, 1 to {DEFAULT_GALLERY}, as the page "
                            "numbers them")
    parser.add_argument("-k", type=HARMONICS, default=None,
                        help="harmonics (default: the k the mapping was made on, else "
                             f"{DEFAULT_K})")
    parser.add_argument("--fps", type=FPS, default=DEFAULT_FPS,
                        help=f"frames per second (default {DEFAULT_FPS:g})")
    add_window_options(parser)
    add_output(parser, "morph targets (.npz: rest, targets, weights, times) or point cache "
                       "(.pc2) to write")


def mapping_of(args, basis, spectrogram) -> Mapping:
    """The mapping `bake` plays: --mapping, --item of the initial gallery, or the strongest item.

    Parameters
    ----------
    args : the parsed command line.
    basis, spectrogram : the mesh's harmonics and the song.

    Returns
    -------
    Mapping.
    """
    if args.mapping:
        return read_mapping(args.mapping)
    if args.item is None:
        return strongest_item(basis, spectrogram)
    return initial_gallery(basis, spectrogram, DEFAULT_GALLERY)[args.item - 1]


def run_bake(args) -> None:
    """`eigendance bake`: a mesh's dance for a 3D tool, vertex for vertex in the file's order
    (of the vertices that faces use; a vertex the clean-up merged moves with its twin, one it
    dropped stays at rest).

    The .npz holds `rest` (n, 3) (the file's vertices, for the reader to check its order),
    `targets` (J, n, 3) and `weights` (T, J) in [−1, 1], `harmonics` (J,) and `times` (T,) s:
    the dance at times[i] is rest + Σ_j weights[i, j]·targets[j] (exact: the motion is linear
    in φ, `HarmonicDance.morphs`, each target scaled by its largest |weight|). The .pc2 holds
    the positions themselves.

    Parameters
    ----------
    args : the parsed command line.
    """
    kind = suffix_of(args.output)
    if kind not in (".npz", ".pc2"):
        raise InputError(f"{args.output}: bake writes .npz (morph targets) or .pc2 (point "
                         "cache); name the output so")
    refuse_overwrite(args.output, args.force)
    began = time.perf_counter()
    mapping = read_mapping(args.mapping) if args.mapping else None
    spectrogram = read_song(args.audio, mapping.bands if mapping else 64)
    choice = basis_choice(mapping, args.k)  # the basis the mapping was made on, unless -k
    say_note(args.output, choice.note)
    problem = read_model(args.mesh, kind="mesh", construction="exact").problem
    mesh = problem.mesh  # exact: the file's own vertices (vertex_map), not samples of them
    bar, update = progress_bar(choice.k, "eigenpairs")
    with bar:
        basis = problem.basis(choice.k, progress=update)
    mapping = mapping_of(args, basis, spectrogram)
    dance = HarmonicDance(basis, spectrogram, mapping, None, os.path.basename(args.mesh))
    dance = dance.window(args.start, args.duration)
    say_note(args.output, dance.note)
    times = frame_times(dance.duration, args.fps)
    order = np.where(mesh.vertex_map >= 0, mesh.vertex_map, 0)
    rest = dance.rest[order]
    dropped = mesh.vertex_map < 0
    if kind == ".pc2":
        write_positions(args.output, dance, times, order, dropped)
    else:
        morphs = dance.morphs(times)
        scale = np.abs(morphs.weights).max(axis=0, initial=0.0)
        scale = np.where(scale > 0, scale, 1.0)
        targets = morphs.targets[:, order] * scale[:, None, None]
        targets[:, dropped] = 0.0
        atomic_save_npz(args.output, rest=rest, targets=targets.astype(np.float32),
                        weights=(morphs.weights / scale).astype(np.float32),
                        harmonics=morphs.harmonics.astype(np.int64), times=times,
                        fps=np.float64(args.fps), start=np.float64(dance.start))
    print(f"{args.output}: {len(times)} frames of {len(rest)} vertices at {args.fps:g} fps, "
          f"mapping {mapping.name}, {time.perf_counter() - began:.1f} s")


def write_positions(path: str, dance: HarmonicDance, times, order, dropped) -> None:
    """Write the point cache of `dance` in the mesh file's vertex order.

    Parameters
    ----------
    path : the .pc2.
    dance : the dance.
    times : (T,) s.
    order : (n,) the dance's vertex of each file vertex.
    dropped : (n,) bool, file vertices the clean-up dropped (they stay at rest).
    """
    rest = dance.rest[order].astype("<f4")
    bar, update = progress_bar(len(times), "frames", unit="frame")

    def write(file):
        file.write(pc2_header(len(order), len(times)))
        for first, positions, _ in dance.frames(times):
            chunk = positions[:, order].astype("<f4")
            chunk[:, dropped] = rest[dropped]
            file.write(np.ascontiguousarray(chunk).tobytes())
            update(first + len(positions))

    with bar:
        atomic_write(path, write, sync=False)
