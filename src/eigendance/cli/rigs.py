"""The rig commands: `modes` and `animate-rig` (docs/design.md#modal-motion)."""

from __future__ import annotations

import math
import sys
import time
from dataclasses import replace

import numpy as np

from eigendance.cli.options import (
    RIG_HELP,
    add_fps,
    add_output,
    add_palette_options,
    add_rig_options,
    add_window_options,
    number,
    progress_bar,
    say_note,
)
from eigendance.cli.surface import add_surface_options, surface_of
from eigendance.errors import InputError
from eigendance.inputs.mapping import read_mapping
from eigendance.inputs.model import read_model
from eigendance.inputs.song import read_song
from eigendance.limits import check_disk, check_memory
from eigendance.modal.model import ModalModel
from eigendance.modal.motion import parse_modes, save_animation
from eigendance.modal.rig import Rig
from eigendance.modal.skeleton_file import read_joint_stiffness
from eigendance.modal.surface import surface_share
from eigendance.music.spectrogram import frame_times
from eigendance.window import Window
from eigendance.writes import refuse_overwrite


def rig_from(args) -> Rig:
    """The rig of `args.rig` with the stiffness options (--joints, --stiffness) applied.

    Parameters
    ----------
    args : the parsed command line.

    Returns
    -------
    Rig (float32 modal skin, as the page plays it); the loader's notes go to stderr.
    """
    skeleton = read_model(args.rig, kind="rig").skeleton
    for note in skeleton.notes:
        print(f"{skeleton.name}: {note}", file=sys.stderr)
    values = read_joint_stiffness(args.joints) if args.joints else {}
    if values or args.stiffness != 1.0:
        skeleton = skeleton.with_stiffness(values, scale=args.stiffness)
    return Rig(skeleton)


def add_modes(parser):
    """The options of `eigendance modes`.

    Parameters
    ----------
    parser : the command's parser.
    """
    parser.add_argument("rig", help=RIG_HELP)
    add_rig_options(parser)
    parser.add_argument("--show", type=number(0, integer=True), default=30,
                        help="modes listed (default 30)")
    add_output(parser, "modal file to write (.npz)")


def mode_table(model: ModalModel, top: int = 3, limit: int | None = None) -> list[str]:
    """Lines: index, frequency (Hz) and the bodies carrying most of each mode's energy.

    Parameters
    ----------
    model : the rig's modes.
    top : bodies named per mode.
    limit : modes listed at most (None: all).

    Returns
    -------
    list of str, one per line.
    """
    energy = model.body_energy()
    lines = [f"{'mode':>5} {'frequency Hz':>13}  bodies that move most (share of energy)"]
    count = model.n_modes if limit is None else min(limit, model.n_modes)
    for index in range(count):
        order = np.argsort(energy[:, index])[::-1][:top]
        movers = ", ".join(f"{model.body_names[b]} {energy[b, index]:.0%}" for b in order)
        lines.append(f"{index:>5} {model.frequencies[index]:>13.4f}  {movers}")
    if count < model.n_modes:
        lines.append(f"  … {model.n_modes - count} more (all are in the file)")
    return lines


def run_modes(args) -> None:
    """`eigendance modes`: the modal analysis of a rig, written as a modal file and listed.

    Parameters
    ----------
    args : the parsed command line.
    """
    refuse_overwrite(args.output, args.force)
    start = time.perf_counter()
    rig = rig_from(args)
    skeleton, model = rig.skeleton, rig.model
    model.save(args.output)
    print("\n".join(mode_table(model, limit=args.show)))
    if model.n_modes:
        palette = rig.palette
        played = model.frequencies[palette.selected] * palette.time_scale
        print(f"default palette: modes {', '.join(str(m) for m in palette.selected)}, time "
              f"scale {palette.time_scale:.3g} (they play at "
              f"{', '.join(f'{f:.2f}' for f in played)} Hz)")
    print(f"{args.output}: {skeleton.n_bodies} bodies, {len(skeleton.joints)} joints, "
          f"{model.constraint_rows} constraint rows (rank {model.constraint_rank}), "
          f"{model.nullspace_dim} admissible motions = {model.rigid_modes} rigid + "
          f"{model.n_modes} vibration modes, {time.perf_counter() - start:.1f} s")


def add_animate_rig(parser):
    """The options of `eigendance animate-rig`.

    Parameters
    ----------
    parser : the command's parser.
    """
    parser.add_argument("rig", help=RIG_HELP)
    parser.add_argument("audio", nargs="?", help="audio file (any format `spectrum` reads) or "
                        "spectrogram file (.npz) whose bands drive the modes; without it every "
                        "chosen mode moves steadily (music off)")
    parser.add_argument("--mapping", help="mapping JSON: bands to modes, gain, smoothing, offset "
                                          "and palette (default: bands in order over the "
                                          "palette's modes, low sounds to low modes, "
                                          "calibrated to the song)")
    add_palette_options(parser)
    add_fps(parser)
    add_window_options(parser, "default: to the audio's end, or 4 s without audio")
    parser.add_argument("--bands", type=number(1, 1024, integer=True), default=64,
                        help="bands of the audio's spectrogram without a mapping (default 64)")
    add_rig_options(parser)
    add_surface_options(parser)
    parser.add_argument("--save-mapping", metavar="JSON",
                        help="also write the mapping that made the motion, every setting "
                             "explicit (the page and the exports play it the same)")
    add_output(parser, "animation file to write (.npz)")


def run_animate_rig(args) -> None:
    """`eigendance animate-rig`: move a rig in its modes to a song (or a part of it) and write the
    animation file (and the mapping that made it).

    Parameters
    ----------
    args : the parsed command line.
    """
    refuse_overwrite(args.output, args.force)
    if args.save_mapping:
        refuse_overwrite(args.save_mapping, args.force)
    began = time.perf_counter()
    mapping = read_mapping(args.mapping) if args.mapping else None
    rig = rig_from(args)
    skeleton, model = rig.skeleton, rig.model
    if model.n_modes == 0:
        raise InputError(f"{skeleton.name}: the rig has no vibration mode (no elastic joint); "
                         "nothing to animate")
    spectrogram = read_song(args.audio, mapping.bands if mapping else args.bands) \
        if args.audio else None
    window = Window.of(args.start, args.duration if args.audio or args.duration else 4.0,
                       spectrogram.duration if spectrogram is not None else math.inf,
                       args.audio or "the rig")
    say_note(args.output, window.note)
    times = frame_times(window.duration, args.fps)
    mapping = rig.mapping(spectrogram, mapping, selected=parse_modes(args.modes, model.n_modes),
                          amplitude=args.amplitude, time_scale=args.time_scale,
                          offset=args.offset, bands=args.bands,
                          tempo=args.tempo)
    palette = rig.palette_of(mapping)
    check_rig_animation(rig, len(times), args.output)
    coefficients = rig.coefficients(spectrogram, mapping, window.start + times)
    surface = surface_of(args, rig, spectrogram, mapping)
    ripple = None if surface is None else \
        (lambda first, stop: surface.displacements(window.start + times[first:stop]))
    bar, update = progress_bar(len(times), "frames", unit="frame")
    with bar:
        arrays = rig.animation(times, coefficients, palette, args.skinning, progress=update,
                               surface=ripple)
    save_animation(args.output, arrays)
    if args.save_mapping:  # with the surface genes that played
        replace(mapping, surface=None if surface is None else surface.mapping).save(
            args.save_mapping)
    scaled = model.frequencies[palette.selected] * palette.time_scale
    print(f"{args.output}: {len(times)} frames at {args.fps:g} fps, "
          f"{len(skeleton.vertices)} vertices, {skeleton.n_bodies} bodies, modes "
          f"{', '.join(str(m) for m in palette.selected)} playing at "
          f"{', '.join(f'{f:.2f}' for f in scaled)} Hz (time scale "
          f"{palette.time_scale:.3g}), {'music' if spectrogram is not None else 'steady'} "
          f"drive, {time.perf_counter() - began:.1f} s")
    if surface is not None:
        print(surface_line(rig, surface, arrays, args.skinning))


def surface_line(rig: Rig, surface, arrays: dict, skinning: str) -> str:
    """What the surface did: its harmonics and its share of the skin's motion
    (`modal.surface.surface_share`, measured on at most 64 frames spread over the animation).

    Parameters
    ----------
    rig : the rig.
    surface : its `SurfaceDance`.
    arrays : the animation's arrays (`Rig.animation`).
    skinning : "modal" or "lbs".

    Returns
    -------
    str.
    """
    frames = np.unique(np.linspace(0, len(arrays["times"]) - 1, 64).astype(int))
    bones = rig.positions(arrays["coefficients"][frames], skinning)
    share = surface_share(bones, arrays["positions"][frames], rig.skeleton.vertices)
    return (f"surface: {surface.mapping.name}, {len(surface.driven())} of "
            f"{surface.harmonics.k} harmonics of the skin, gain {surface.mapping.gain:.3g}: "
            f"{share:.0%} of the skin's motion (RMS)")


def check_rig_animation(rig: Rig, frames: int, output: str) -> None:
    """InputError unless a rig animation of `frames` frames fits the memory and the disk.

    Parameters
    ----------
    rig : the rig.
    frames : how many frames.
    output : the file to write.
    """
    skeleton = rig.skeleton
    # Bytes per frame of the arrays `Rig.animation` holds and writes: float32 positions (12 per
    # vertex), body rotations, centres and transforms (≈ 300 per body), coefficients (8 per
    # mode); half again for the intermediates.
    per_frame = 1.5 * (12 * len(skeleton.vertices) + 300 * skeleton.n_bodies
                       + 8 * rig.model.n_modes)
    what = f"{frames} frames of {len(skeleton.vertices)} vertices"
    check_memory(per_frame * frames, what)
    check_disk(output, per_frame * frames, what)
