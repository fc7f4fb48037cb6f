"""The rig commands: `modes` and `animate-rig` (docs/design.md#modal-motion)."""

from __future__ import annotations

import sys
import time

import numpy as np

from eigendance.cli.options import (
    FPS,
    RIG_HELP,
    add_output,
    add_palette_options,
    add_rig_options,
    number,
    progress_bar,
    spectrogram_from,
)
from eigendance.errors import InputError
from eigendance.files import refuse_overwrite
from eigendance.limits import check_disk, check_memory
from eigendance.modal.model import ModalModel
from eigendance.modal.motion import (
    animate_rig,
    mapping_palette,
    parse_modes,
    rig_coefficients,
    rig_mapping,
    save_animation,
)
from eigendance.modal.palette import default_palette
from eigendance.modal.sample_rigs import load_rig
from eigendance.modal.skeleton_file import read_joint_stiffness
from eigendance.music.mapping import Mapping
from eigendance.music.spectrogram import frame_times


def rig_from(args):
    """The rig of `args.rig` with the stiffness options applied, and its modal model."""
    skeleton = load_rig(args.rig)
    for note in skeleton.notes:
        print(f"{skeleton.name}: {note}", file=sys.stderr)
    values = read_joint_stiffness(args.joints) if args.joints else {}
    if values or args.stiffness != 1.0:
        skeleton = skeleton.with_stiffness(values, scale=args.stiffness)
    return skeleton, ModalModel.from_skeleton(skeleton)


def add_modes(parser):
    parser.add_argument("rig", help=RIG_HELP)
    add_rig_options(parser)
    parser.add_argument("--show", type=number(0, integer=True), default=30,
                        help="modes listed (default 30)")
    add_output(parser, "modal file to write (.npz)")


def mode_table(model: ModalModel, top: int = 3, limit: int | None = None) -> list[str]:
    """Lines: index, frequency (Hz) and the bodies carrying most of each mode's energy."""
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
    refuse_overwrite(args.output, args.force)
    start = time.perf_counter()
    skeleton, model = rig_from(args)
    model.save(args.output)
    print("\n".join(mode_table(model, limit=args.show)))
    if model.n_modes:
        palette = default_palette(model)
        played = model.frequencies[palette.selected] * palette.time_scale
        print(f"default palette: modes {', '.join(str(m) for m in palette.selected)}, time "
              f"scale {palette.time_scale:.3g} (they play at "
              f"{', '.join(f'{f:.2f}' for f in played)} Hz)")
    print(f"{args.output}: {skeleton.n_bodies} bodies, {len(skeleton.joints)} joints, "
          f"{model.constraint_rows} constraint rows (rank {model.constraint_rank}), "
          f"{model.nullspace_dim} admissible motions = {model.rigid_modes} rigid + "
          f"{model.n_modes} vibration modes, {time.perf_counter() - start:.1f} s")


def add_animate_rig(parser):
    parser.add_argument("rig", help=RIG_HELP)
    parser.add_argument("audio", nargs="?", help="audio file (any format `spectrum` reads) or "
                        "spectrogram file (.npz) whose bands drive the modes; without it every "
                        "chosen mode moves steadily (music off)")
    parser.add_argument("--mapping", help="mapping JSON: bands to modes, gain, smoothing, offset "
                                          "and palette (default: bands in order over the "
                                          "palette's modes, low sounds to low modes, "
                                          "calibrated to the song)")
    add_palette_options(parser)
    parser.add_argument("--fps", type=FPS, default=30.0, help="frames per second (default 30)")
    parser.add_argument("--duration", type=number(0, 24 * 3600, above=True), default=None,
                        help="seconds (default: the audio's length, or 4 s without audio)")
    parser.add_argument("--bands", type=number(1, 1024, integer=True), default=64,
                        help="bands of the audio's spectrogram without a mapping (default 64)")
    add_rig_options(parser)
    parser.add_argument("--save-mapping", metavar="JSON",
                        help="also write the mapping that made the motion, every setting "
                             "explicit (the page and the exports play it the same)")
    add_output(parser, "animation file to write (.npz)")


def run_animate_rig(args) -> None:
    refuse_overwrite(args.output, args.force)
    if args.save_mapping:
        refuse_overwrite(args.save_mapping, args.force)
    start = time.perf_counter()
    mapping = Mapping.load(args.mapping) if args.mapping else None
    skeleton, model = rig_from(args)
    if model.n_modes == 0:
        raise InputError(f"{skeleton.name}: the rig has no vibration mode (no elastic joint); "
                         "nothing to animate")
    spectrogram, times = None, frame_times(args.duration or 4.0, args.fps)
    if args.audio:
        spectrogram = spectrogram_from(args.audio, mapping.bands if mapping else args.bands)
        times = frame_times(args.duration or spectrogram.duration, args.fps)
    mapping = rig_mapping(model, spectrogram, mapping, parse_modes(args.modes, model.n_modes),
                          args.amplitude, args.time_scale, args.offset, args.bands)
    palette = mapping_palette(model, mapping)
    # Bytes per frame of the arrays animate_rig holds and writes: float32 positions (12 per
    # vertex), body rotations, centres and transforms (≈ 300 per body), coefficients (8 per
    # mode); half again for the intermediates.
    per_frame = 1.5 * (12 * len(skeleton.vertices) + 300 * skeleton.n_bodies + 8 * model.n_modes)
    what = f"{len(times)} frames of {len(skeleton.vertices)} vertices"
    check_memory(per_frame * len(times), what)
    check_disk(args.output, per_frame * len(times), what)
    coefficients = rig_coefficients(model, spectrogram, mapping, times)
    bar, update = progress_bar(len(times), "frames", unit="frame")
    with bar:
        arrays = animate_rig(skeleton, model, times, coefficients, palette, args.skinning,
                             progress=update)
    save_animation(args.output, arrays)
    if args.save_mapping:
        mapping.save(args.save_mapping)
    scaled = model.frequencies[palette.selected] * palette.time_scale
    print(f"{args.output}: {len(times)} frames at {args.fps:g} fps, "
          f"{len(skeleton.vertices)} vertices, {skeleton.n_bodies} bodies, modes "
          f"{', '.join(str(m) for m in palette.selected)} playing at "
          f"{', '.join(f'{f:.2f}' for f in scaled)} Hz (time scale "
          f"{palette.time_scale:.3g}), {'music' if spectrogram is not None else 'steady'} "
          f"drive, {time.perf_counter() - start:.1f} s")
