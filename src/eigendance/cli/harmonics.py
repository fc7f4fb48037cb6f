"""The harmonic commands: `basis`, `spectrum`, `gallery`, `animate` (docs/design.md#cli)."""

from __future__ import annotations

import os
import sys
import time

import numpy as np

from eigendance.cli.options import (
    HARMONICS,
    add_construction,
    add_fps,
    add_harmonics,
    add_output,
    add_palette_options,
    add_rig_options,
    add_window_options,
    basis_for,
    gallery_size,
    number,
    progress_bar,
    say_note,
)
from eigendance.cli.presets import add_preset_options, fitted, mapping_option
from eigendance.cli.rigs import run_animate_rig
from eigendance.errors import InputError
from eigendance.harmonic.eigensolver import SOLVERS
from eigendance.harmonic.laplacian import LAPLACIANS
from eigendance.harmonic.motion import write_animation
from eigendance.inputs.defaults import DEFAULT_K
from eigendance.inputs.mapping import read_mapping
from eigendance.inputs.model import model_kind, read_model
from eigendance.inputs.song import read_song
from eigendance.music.breeding import bounded_children, breed
from eigendance.music.dancer import gallery_correlations, gallery_motion
from eigendance.music.gallery import (
    DEFAULT_GALLERY,
    check_gallery_size,
    initial_gallery,
    strongest_item,
)
from eigendance.music.spectrogram import check_picture_path, save_picture
from eigendance.window import Window
from eigendance.writes import refuse_overwrite


def add_basis(parser):
    """The options of `eigendance basis`.

    Parameters
    ----------
    parser : the command's parser.
    """
    parser.add_argument("mesh", help="mesh file: OBJ, PLY, OFF, STL, glTF or GLB")
    parser.add_argument("-k", type=HARMONICS, default=DEFAULT_K,
                        help=f"number of harmonics (default {DEFAULT_K})")
    parser.add_argument("--laplacian", choices=LAPLACIANS, default="cotan",
                        help="cotan (default, thesis) or robust (intrinsic Delaunay; "
                             "for non-manifold meshes)")
    parser.add_argument("--solver", choices=SOLVERS, default="bands",
                        help="bands (default, spectrum slicing) or eigsh (naive baseline)")
    parser.add_argument("--no-cache", action="store_true", help="solve even if cached")
    add_construction(parser)
    parser.add_argument("--samples", type=number(2, 10**7, integer=True), default=None,
                        help="samples a reduced basis asks for (the grid places about as many; "
                        "default 21·k, at least 2000)")
    add_output(parser, "basis file to write (.npz)")


def run_basis(args) -> None:
    """`eigendance basis`: solve a mesh's harmonics (through the cache) and write the basis file.

    Parameters
    ----------
    args : the parsed command line.
    """
    if args.construction == "exact" and args.samples is not None:
        raise InputError("--samples sets the samples of a reduced basis; it has no meaning "
                         "with --exact")
    refuse_overwrite(args.output, args.force)
    start = time.perf_counter()
    problem = read_model(args.mesh, kind="mesh", laplacian=args.laplacian, solver=args.solver,
                         cache=not args.no_cache, construction=args.construction or "auto",
                         samples=args.samples).problem
    if cleaned := problem.mesh.describe_cleanup():
        print(f"{problem.mesh.name}: removed {cleaned}", file=sys.stderr)
    bar, update = progress_bar(args.k, "eigenpairs")
    with bar:
        basis = problem.basis(args.k, progress=update)
    basis.save(args.output)
    print(f"{args.output}: n = {basis.n} vertices, {basis.record.describe()}, "
          f"largest eigenvalue {basis.eigenvalues[-1]:.6g}, "
          f"{time.perf_counter() - start:.1f} s")


def add_spectrum(parser):
    """The options of `eigendance spectrum`.

    Parameters
    ----------
    parser : the command's parser.
    """
    parser.add_argument("audio", help="audio file: WAV, FLAC, OGG, MP3, M4A/AAC, Opus, …")
    parser.add_argument("--rate", type=number(0, 1000, above=True), default=100.0,
                        help="analysis frames per second (default 100, at most 1000)")
    parser.add_argument("--bands", type=number(1, 1024, integer=True), default=64,
                        help="number of bands (default 64)")
    parser.add_argument("--png", help="also draw the spectrogram into this picture "
                                      "(.png, .svg, .pdf or .jpg)")
    add_output(parser, "spectrogram file to write (.npz)")


def run_spectrum(args) -> None:
    """`eigendance spectrum`: analyse a song into its banded loudness and write it (and a picture).

    Parameters
    ----------
    args : the parsed command line.
    """
    refuse_overwrite(args.output, args.force)
    if args.png:
        check_picture_path(args.png)
        refuse_overwrite(args.png, args.force)
    start = time.perf_counter()
    spectrogram = read_song(args.audio, args.bands, rate=args.rate)
    spectrogram.save(args.output)
    if args.png:
        save_picture(spectrogram, args.png, title=os.path.basename(args.audio))
    print(f"{args.output}: {len(spectrogram.times)} frames × {spectrogram.bands} bands, "
          f"{spectrogram.duration:.2f} s at {spectrogram.sample_rate} Hz, "
          f"{time.perf_counter() - start:.1f} s")
    print(f"{args.output}: {spectrogram.rhythm.summary()}")


def add_gallery(parser):
    """The options of `eigendance gallery`.

    Parameters
    ----------
    parser : the command's parser.
    """
    parser.add_argument("basis", help="basis file (.npz) or mesh file (solved with -k)")
    parser.add_argument("spectrogram", help="spectrogram file (.npz) or audio file: the song "
                                            "the initial items are calibrated on")
    parser.add_argument("-n", "--size", type=gallery_size, default=DEFAULT_GALLERY,
                        help=f"number of gallery items, 2 to 16 (default {DEFAULT_GALLERY})")
    parser.add_argument("--seed", type=number(0, 2**32 - 1, integer=True), default=0,
                        help="breeding seed (default 0)")
    parser.add_argument("--breed", nargs="+", metavar="MAPPING",
                        help="breed children of these mapping files instead of the initial "
                             "gallery")
    parser.add_argument("-v", "--verbose", action="store_true",
                        help="print each item's motion on the song and the harmonics it drives")
    parser.add_argument("-k", type=HARMONICS, default=DEFAULT_K,
                        help=f"harmonics when BASIS is a mesh file (default {DEFAULT_K})")
    add_output(parser, "folder for 0.json, 1.json, …")


def run_gallery(args) -> None:
    """`eigendance gallery`: write the initial gallery, or the children of bred parents, as mapping
    files.

    Parameters
    ----------
    args : the parsed command line.
    """
    size = check_gallery_size(args.size)
    paths = [os.path.join(args.output, f"{i}.json") for i in range(size)]
    for path in paths:
        refuse_overwrite(path, args.force)
    parents = [read_mapping(path) for path in args.breed or []]
    basis = basis_for(args.basis, parents[0] if parents else None, args.k, None, args.output)
    spectrogram = read_song(args.spectrogram)
    # Children are bounded on the model and song, as the first generation is calibrated on them;
    # each item records the basis it was made on.
    items = bounded_children(basis, spectrogram, breed(parents, size, args.seed)) if parents \
        else initial_gallery(basis, spectrogram, size)
    for item, path in zip(items, paths, strict=True):
        item.save(path)
    what = f"children of {len(args.breed)} parents" if args.breed else "initial gallery"
    print(f"{args.output}: {len(items)} mappings ({what})")
    if args.verbose:
        print("\n".join(gallery_table(basis, spectrogram, items)))


def gallery_table(basis, spectrogram, items) -> list[str]:
    """Lines of the --verbose table: each item's m and peak motion on the song (percent of the
    bounding-box diagonal) and its main harmonic range, then the largest correlation.

    Parameters
    ----------
    basis : the mesh's harmonics.
    spectrogram : the song.
    items : the gallery's mappings.

    Returns
    -------
    list of str, one per line.
    """
    lines = [f"{'item':>4} {'m':>7} {'peak':>7}  main harmonics (of k = {basis.k})"]
    for index, measured in enumerate(gallery_motion(basis, spectrogram, items), 1):
        harmonics = "none" if measured.lowest < 0 else \
            f"{measured.lowest}" if measured.lowest == measured.highest else \
            f"{measured.lowest}–{measured.highest}"
        lines.append(f"{index:>4} {100 * measured.motion:>6.2f}% {100 * measured.peak:>6.2f}%"
                     f"  {harmonics}")
    correlations = np.abs(gallery_correlations(basis, spectrogram, items))
    np.fill_diagonal(correlations, 0)
    first, second = np.unravel_index(np.argmax(correlations), correlations.shape)
    lines.append(f"m: 95th percentile over the song's frames of the RMS vertex displacement / "
                 f"bounding-box diagonal; largest correlation between two items: "
                 f"{correlations[first, second]:.3f} (items {first + 1} and {second + 1})")
    return lines


def add_animate(parser):
    """The options of `eigendance animate`.

    Parameters
    ----------
    parser : the command's parser.
    """
    parser.add_argument("mesh", metavar="MODEL",
                        help="mesh file, or basis file (.npz); a rig (a glTF with a skin, a "
                             "skeleton JSON, a built-in rig) moves by its modes as in "
                             "`animate-rig`")
    parser.add_argument("audio", help="audio file, or spectrogram file (.npz)")
    parser.add_argument("--mapping", help="mapping JSON (default: the initial-gallery item of "
                                          "8 that moves the mesh most)")
    parser.add_argument("--mesh", dest="as_mesh", action="store_true",
                        help="a glTF with a skin moves by its mesh's harmonics, not its skeleton")
    add_fps(parser)
    add_harmonics(parser, "when MODEL is a mesh")
    add_preset_options(parser)
    add_window_options(parser)
    add_palette_options(parser)
    add_rig_options(parser)
    add_output(parser, "animation file to write (.npz)")


def run_animate(args) -> None:
    """`eigendance animate`: write the positions of a mesh dancing to a song (or a part of it).

    Parameters
    ----------
    args : the parsed command line.
    """
    if model_kind(args.mesh, args.as_mesh) == "rig":  # as the page: a skin dances by its modes
        args.rig, args.bands, args.save_mapping = args.mesh, 64, None
        run_animate_rig(args)
        return
    refuse_overwrite(args.output, args.force)
    began = time.perf_counter()
    mapping = mapping_option(args)
    spectrogram = read_song(args.audio, bands=mapping.bands if mapping else 64)
    window = Window.of(args.start, args.duration, spectrogram.duration, args.audio)
    say_note(args.output, window.note)
    basis = basis_for(args.mesh, mapping, args.k, args.construction, args.output)
    mapping = fitted(args, mapping, basis) or strongest_item(basis, spectrogram)
    frames, update = progress_bar(None, "frames", unit="frame")
    with frames:
        count = write_animation(args.output, basis, spectrogram, mapping, args.fps,
                                progress=update, window=window, force=args.force)
    print(f"{args.output}: {count} frames of {basis.n} vertices at {args.fps:g} fps, "
          f"{time.perf_counter() - began:.1f} s")
