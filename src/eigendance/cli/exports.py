"""The export commands: `export` (glTF, point cache, USD) and `render` (MP4)
(docs/design.md#exports)."""

from __future__ import annotations

import argparse
import os
import time

import numpy as np

from eigendance.cli.options import (
    RIG_HELP,
    STIFFNESS,
    add_fps,
    add_harmonics,
    add_output,
    add_palette_options,
    add_window_options,
    basis_for,
    input_files,
    number,
    progress_bar,
    say_note,
)
from eigendance.cli.presets import add_preset_options, fitted, mapping_option
from eigendance.cli.surface import add_surface_options, surface_of
from eigendance.errors import InputError
from eigendance.export.dance import Dance, HarmonicDance
from eigendance.export.files import FORMATS as EXPORT_FORMATS
from eigendance.export.files import companion_paths, export_dance, format_of
from eigendance.export.gltf import glb_size
from eigendance.export.renderer import Look
from eigendance.export.rig_dance import rig_dance
from eigendance.export.video import parse_size, render_video
from eigendance.files import suffix_of
from eigendance.inputs.mapping import read_mapping
from eigendance.inputs.model import model_kind, read_model
from eigendance.inputs.song import is_spectrogram_file, read_song
from eigendance.modal.motion import parse_modes
from eigendance.modal.rig import Rig
from eigendance.modal.sample_rigs import SAMPLE_RIGS
from eigendance.music.breeding import bounded_children, breed
from eigendance.music.gallery import (
    DEFAULT_GALLERY,
    check_gallery_size,
    initial_gallery,
    strongest_item,
)
from eigendance.music.mapping import Mapping
from eigendance.writes import refuse_overwrite

# --- exports: files for other tools, and video (docs/design.md#exports) ----------------------

def add_dance_inputs(parser, audio_help: str) -> None:
    """The inputs of `export` and `render`: a mesh (+ mapping) or a rig, the song, the palette and
    the part of the song.

    Parameters
    ----------
    parser : the command's parser.
    audio_help : what AUDIO is for this command, for --help.
    """
    parser.add_argument("model", help="mesh file (OBJ, PLY, OFF, STL, glTF) or basis file "
                        "(.npz), or a rig moved by its vibration modes: " + RIG_HELP +
                        " (a glTF with a skin is a rig, as in the page)")
    parser.add_argument("audio", help=audio_help)
    parser.add_argument("--mapping", help="mapping JSON (default: for a mesh, the initial-"
                        "gallery item of 8 that moves it most; for a rig, bands in order)")
    kind = parser.add_mutually_exclusive_group()
    kind.add_argument("--rig", action="store_true",
                      help="MODEL must be a rig (an error otherwise)")
    kind.add_argument("--mesh", dest="as_mesh", action="store_true",
                      help="a glTF with a skin moves by its mesh's harmonics, not its skeleton")
    add_harmonics(parser)
    add_fps(parser, 240)
    add_preset_options(parser)
    add_palette_options(parser)
    parser.add_argument("--stiffness", type=STIFFNESS, default=1.0,
                        help="multiply every joint stiffness of a rig (default 1)")
    add_window_options(parser)
    add_surface_options(parser)


def is_rig(args) -> bool:
    """Whether MODEL is a rig, by the one rule of every front end (`inputs.model.model_kind`:
    a built-in rig, a skeleton JSON, a glTF with a skin unless --mesh).

    Parameters
    ----------
    args : the parsed command line.

    Returns
    -------
    bool.

    Raises
    ------
    InputError
        As `model_kind`; with --rig, for a model that is not a rig.
    """
    rig = model_kind(getattr(args, "model", None) or args.mesh, args.as_mesh) == "rig"
    if getattr(args, "rig", False) is True and not rig:
        raise InputError(f"{args.model}: --rig, but it is not a rig (a skeleton JSON, a glTF "
                         f"with a skin, or one of {', '.join(SAMPLE_RIGS)})")
    return rig


def song_of(args) -> str | None:
    """The song's audio file, or None when AUDIO is a spectrogram file.

    Parameters
    ----------
    args : the parsed command line.

    Returns
    -------
    str or None.
    """
    return None if is_spectrogram_file(args.audio) else args.audio


def dance_from(args, mapping: Mapping | None) -> Dance:
    """The dance `export` and `render` write: a mesh by its harmonics or a rig by its modes,
    the part of the song --start and --duration ask for (`Dance.window`).

    Parameters
    ----------
    args : the parsed command line.
    mapping : the --mapping, or None.

    Returns
    -------
    HarmonicDance or RigDance, windowed; its note (a clamped window) printed on stderr.
    """
    name = os.path.splitext(os.path.basename(args.output))[0]
    if is_rig(args):
        skeleton = read_model(args.model, kind="rig").skeleton
        if args.stiffness != 1.0:
            skeleton = skeleton.with_stiffness({}, scale=args.stiffness)
        rig = Rig(skeleton, np.float64)
        if rig.model.n_modes == 0:
            raise InputError(f"{skeleton.name}: the rig has no vibration mode (no elastic "
                             "joint); nothing to move")
        spectrogram = read_song(args.audio, mapping.bands if mapping else 64)
        mapping = fitted(args, mapping, mode_count=rig.model.n_modes)
        mapping = rig.mapping(spectrogram, mapping,
                              selected=parse_modes(args.modes, rig.model.n_modes),
                              amplitude=args.amplitude, time_scale=args.time_scale,
                              offset=args.offset, tempo=args.tempo)
        dance = rig_dance(rig, spectrogram, mapping, args.skinning, song_of(args), name,
                          surface=surface_of(args, rig, spectrogram, mapping))
    else:
        if getattr(args, "surface", None):
            raise InputError("--surface ripples a rig's skin; a mesh ripples in its "
                             "harmonics anyway (use --mapping)")
        basis, spectrogram = harmonic_inputs(args, mapping)
        mapping = fitted(args, mapping, basis) or strongest_item(basis, spectrogram)
        dance = HarmonicDance(basis, spectrogram, mapping, song_of(args), name)
    dance = dance.window(args.start, args.duration)
    say_note(args.output, dance.note)
    return dance


def harmonic_inputs(args, mapping: Mapping | None):
    """The mesh's basis (`options.basis_for`: the one the mapping was made on unless -k,
    --exact or --reduced ask for another) and the song's spectrogram.

    Parameters
    ----------
    args : the parsed command line (MODEL, AUDIO, -k, --exact, --reduced).
    mapping : the mapping (its bands are the spectrogram's), or None.

    Returns
    -------
    (HarmonicBasis, Spectrogram).
    """
    basis = basis_for(args.model, mapping, args.k, args.construction, args.output)
    return basis, read_song(args.audio, mapping.bands if mapping else 64)


def add_export(parser):
    """The options of `eigendance export`.

    Parameters
    ----------
    parser : the command's parser.
    """
    add_dance_inputs(parser, "the song: audio file (copied beside the export), or "
                             "spectrogram file (.npz)")
    parser.add_argument("--format", choices=tuple(EXPORT_FORMATS),
                        help="glb (glTF 2.0: morph targets, or a skin), pc2 (+ the rest mesh "
                             "as OBJ, for Blender's Mesh Cache), usd (time-sampled points); "
                             "default: by the output's suffix")
    add_output(parser, "file to write: .glb, .pc2 or .usd/.usdc/.usda")


def run_export(args) -> None:
    """`eigendance export`: write the dance as glTF, point cache or USD with its song beside it, and
    say what was written.

    Parameters
    ----------
    args : the parsed command line.
    """
    format = format_of(args.output, args.format)
    began = time.perf_counter()
    mapping = mapping_option(args)
    clipped = args.start > 0 or args.duration is not None
    inputs = input_files(args)
    for path in companion_paths(args.output, format, song_of(args), clipped).values():
        if path is not None:  # before any work: the export would stop at the end
            refuse_overwrite(path, args.force, inputs)
    dance = dance_from(args, mapping)
    bar, update = progress_bar(None, "frames", unit="frame")
    with bar:
        def step(done, total):
            bar.total = total
            update(done)
        report = export_dance(dance, args.output, format, args.fps, args.force, step, inputs)
    size, cache = report["bytes"], report["point_cache_bytes"]
    compared = "" if format == "pc2" else \
        f" (as a point cache: {cache / 1e6:.2f} MB, {cache / size:.1f}× the size)"
    print(f"{args.output}: {report['frames']} frames of {dance.n} vertices at {args.fps:g} "
          f"fps, {size / 1e6:.2f} MB{compared}, {time.perf_counter() - began:.1f} s")
    if format == "glb" and getattr(getattr(dance, "basis", None), "reduced", None) is not None:
        morphs = glb_size(dance, report["frames"])["morph targets"]
        print(f"{args.output}: a skin on the {dance.basis.reduced.count} samples of the reduced "
              f"basis; as morph targets it would be about {morphs / 1e6:.2f} MB")
    if report["skinning_difference"] is not None:
        print(f"{args.output}: the skin plays linear blend skinning; modal skinning differs "
              f"by at most {report['skinning_difference']:.4g} "
              f"({report['skinning_difference'] / report['diagonal']:.2%} of the diagonal)")
    for path in report["files"][1:]:
        print(f"{path}: written beside it")


def add_render(parser):
    """The options of `eigendance render`.

    Parameters
    ----------
    parser : the command's parser.
    """
    add_dance_inputs(parser, "the song (audio file), muxed into the video as AAC")
    parser.add_argument("--size", type=video_size, default=(1280, 720),
                        help="WIDTHxHEIGHT in pixels, even (default 1280x720)")
    parser.add_argument("--gallery", type=int, metavar="N",
                        help="render a gallery of N tiles as the page's grid: the initial "
                             "gallery, or N children of the --breed parents")
    parser.add_argument("--breed", nargs="+", metavar="MAPPING",
                        help="with --gallery: breed the tiles from these mapping files")
    parser.add_argument("--seed", type=number(0, 2**32 - 1, integer=True), default=0,
                        help="breeding seed (default 0)")
    add_output(parser, "video to write (.mp4)")


def video_size(text: str) -> tuple[int, int]:
    """--size: an argparse type for WIDTHxHEIGHT (`export.video.parse_size`).

    Parameters
    ----------
    text : the flag's value.

    Returns
    -------
    (width, height) in pixels; argparse.ArgumentTypeError otherwise.
    """
    try:
        return parse_size(text)
    except InputError as error:
        raise argparse.ArgumentTypeError(str(error)) from None


def run_render(args) -> None:
    """`eigendance render`: draw the dance (or a gallery of dances) with its song into an MP4.

    Parameters
    ----------
    args : the parsed command line.
    """
    if suffix_of(args.output) != ".mp4":
        raise InputError(f"{args.output}: the video is an MP4; name it .mp4")
    if song_of(args) is None:
        raise InputError(f"{args.audio}: a video needs the song itself, not its spectrogram")
    refuse_overwrite(args.output, args.force)
    if args.breed and args.gallery is None:
        raise InputError("breeding parents were given without a gallery size",
                         remedy={"gallery": DEFAULT_GALLERY})
    began = time.perf_counter()
    mapping = mapping_option(args)
    if args.gallery is not None:
        dances, looks = gallery_dances(args, mapping)
    else:
        dances = [dance_from(args, mapping)]
        looks = [Look.of(mapping)]
    bar, update = progress_bar(None, "frames", unit="frame")
    with bar:
        def step(done, total):
            bar.total = total
            update(done)
        report = render_video(args.output, dances, looks, args.audio, args.fps, args.size,
                              args.force, step, inputs=input_files(args))
    seconds = time.perf_counter() - began
    print(f"{args.output}: {report['frames']} frames, {args.size[0]}x{args.size[1]} at "
          f"{args.fps:g} fps, {report['duration']:.2f} s of video with the song, "
          f"{len(dances)} {'tiles' if len(dances) > 1 else 'dancer'}, {seconds:.1f} s "
          f"({report['duration'] / seconds:.2f}× real time)")


def gallery_dances(args, mapping: Mapping | None) -> tuple[list, list]:
    """The tiles of `render --gallery N`: the initial gallery, or N children of the --breed
    parents, each windowed as --start and --duration ask.

    Parameters
    ----------
    args : the parsed command line.
    mapping : the --mapping (refused: a gallery makes its own), or None.

    Returns
    -------
    (dances, looks): one HarmonicDance and one `Look` per tile.
    """
    size = check_gallery_size(args.gallery)
    if is_rig(args):
        raise InputError(f"{args.model}: a gallery breeds mappings of a mesh's harmonics; "
                         "render a rig on its own")
    if mapping is not None:
        raise InputError(f"{args.mapping}: a gallery makes its own mappings; breed from it "
                         "instead", remedy={"breed": args.mapping})
    items = breed([read_mapping(path) for path in args.breed], size, args.seed) \
        if args.breed else None
    basis, spectrogram = harmonic_inputs(args, items[0] if items else None)
    items = bounded_children(basis, spectrogram, items) if items else \
        initial_gallery(basis, spectrogram, size)
    name = os.path.splitext(os.path.basename(args.output))[0]
    dances = [HarmonicDance(basis, spectrogram, item, song_of(args), name).window(
        args.start, args.duration) for item in items]
    say_note(args.output, dances[0].note)
    return dances, [Look.of(item) for item in items]
