"""The `eigendance` command line (DESIGN §8).

Each sub-command is a function `run_<name>(args)` registered in `COMMANDS` with a function that
adds its arguments. Errors in the input print one line `eigendance: error: …` and exit 1.
"""

from __future__ import annotations

import argparse
import sys
import time

from eigendance.errors import EigendanceError


def progress_bar(total: int, description: str):
    """A tqdm bar on stderr (silent when stderr is not a terminal) and a callable(done)."""
    from tqdm import tqdm

    bar = tqdm(total=total, desc=description, unit="pair", file=sys.stderr,
               disable=not sys.stderr.isatty(), leave=False)

    def update(done):
        bar.update(max(0, done - bar.n))

    return bar, update


def add_basis(parser):
    from eigendance.eigen import SOLVERS
    from eigendance.laplacian import LAPLACIANS

    parser.add_argument("mesh", help="mesh file: OBJ, PLY, OFF, STL, glTF or GLB")
    parser.add_argument("-k", type=int, default=300, help="number of harmonics (default 300)")
    parser.add_argument("--laplacian", choices=LAPLACIANS, default="cotan",
                        help="cotan (default, thesis) or robust (intrinsic Delaunay; "
                             "for non-manifold meshes)")
    parser.add_argument("--solver", choices=SOLVERS, default="bands",
                        help="bands (default, spectrum slicing) or eigsh (naive baseline)")
    parser.add_argument("--no-cache", action="store_true", help="solve even if cached")
    parser.add_argument("-o", "--output", required=True, help="basis file to write (.npz)")
    parser.add_argument("--force", action="store_true", help="overwrite an existing output")


def run_basis(args) -> None:
    from eigendance.files import refuse_overwrite
    from eigendance.harmonics import HarmonicBasis
    from eigendance.mesh import load_mesh

    refuse_overwrite(args.output, args.force)
    start = time.perf_counter()
    mesh = load_mesh(args.mesh)
    if cleaned := mesh.describe_cleanup():
        print(f"{mesh.name}: removed {cleaned}", file=sys.stderr)
    bar, update = progress_bar(args.k, "eigenpairs")
    with bar:
        basis = HarmonicBasis.from_mesh(mesh, args.k, laplacian=args.laplacian,
                                        solver=args.solver, cache=not args.no_cache,
                                        progress=update)
    basis.save(args.output)
    print(f"{args.output}: n = {basis.n} vertices, k = {basis.k} harmonics, "
          f"largest eigenvalue {basis.eigenvalues[-1]:.6g}, "
          f"{time.perf_counter() - start:.1f} s")


def add_modes(parser):
    parser.add_argument("rig", help="skeleton JSON, glTF 2.0 skin (.glb/.gltf), or a built-in "
                                    "sample rig: loop4, loop8, loop16, chain")
    parser.add_argument("-o", "--output", required=True, help="modal file to write (.npz)")
    parser.add_argument("--stiffness", type=float, default=1.0,
                        help="multiply every joint stiffness (default 1; frequencies scale "
                             "with its square root)")
    parser.add_argument("--show", type=int, default=30, help="modes listed (default 30)")
    parser.add_argument("--force", action="store_true", help="overwrite an existing output")


def run_modes(args) -> None:
    from eigendance.modal import ModalModel
    from eigendance.rig_animation import load_rig, mode_table

    refuse_overwrite_rig(args)
    start = time.perf_counter()
    skeleton = load_rig(args.rig)
    for note in skeleton.notes:
        print(f"{skeleton.name}: {note}", file=sys.stderr)
    model = ModalModel.from_skeleton(skeleton, stiffness=args.stiffness)
    model.save(args.output)
    print("\n".join(mode_table(model, limit=args.show)))
    print(f"{args.output}: {skeleton.n_bodies} bodies, {len(skeleton.joints)} joints, "
          f"{model.constraint_rows} constraint rows (rank {model.constraint_rank}), "
          f"{model.nullspace_dim} admissible motions = {model.rigid_modes} rigid + "
          f"{model.n_modes} vibration modes, {time.perf_counter() - start:.1f} s")


def add_animate_rig(parser):
    parser.add_argument("rig", help="skeleton JSON, glTF 2.0 skin (.glb/.gltf), or a built-in "
                                    "sample rig: loop4, loop8, loop16, chain")
    parser.add_argument("audio", nargs="?", help="sound file (WAV, FLAC, OGG; read with "
                        "soundfile) whose band loudness drives the modes; without it every "
                        "chosen mode moves steadily")
    parser.add_argument("--modes", help="mode indices, e.g. 0,2,5-8 (default: the 8 lowest)")
    parser.add_argument("--fps", type=float, default=30.0, help="frames per second (default 30)")
    parser.add_argument("--duration", type=float, default=None,
                        help="seconds (default: the audio's length, or 4 s without audio)")
    parser.add_argument("--amplitude", type=float, default=0.3,
                        help="largest body rotation of each mode at full drive, radians "
                             "(default 0.3)")
    parser.add_argument("--time-scale", type=float, default=1.0,
                        help="multiply the natural frequencies (default 1)")
    parser.add_argument("--bands", type=int, default=16,
                        help="loudness bands of the audio, shared out over the modes in "
                             "order (default 16)")
    parser.add_argument("--skinning", choices=("modal", "lbs"), default="modal",
                        help="modal (default, first-order, as live) or lbs (exact body "
                             "transforms, linear blend)")
    parser.add_argument("--stiffness", type=float, default=1.0,
                        help="multiply every joint stiffness (default 1)")
    parser.add_argument("-o", "--output", required=True, help="animation file to write (.npz)")
    parser.add_argument("--force", action="store_true", help="overwrite an existing output")


def run_animate_rig(args) -> None:
    import numpy as np

    from eigendance.modal import ModalModel, band_drive
    from eigendance.rig_animation import (
        animate_rig,
        band_loudness,
        load_rig,
        parse_modes,
        read_audio,
        save_animation,
    )

    refuse_overwrite_rig(args)
    if not args.fps > 0 or (args.duration is not None and not args.duration > 0):
        raise EigendanceError("--fps and --duration must be positive")
    if args.bands < 1:
        raise EigendanceError("--bands must be at least 1")
    start = time.perf_counter()
    skeleton = load_rig(args.rig)
    model = ModalModel.from_skeleton(skeleton, stiffness=args.stiffness)
    if model.n_modes == 0:
        raise EigendanceError(f"{skeleton.name}: the rig has no vibration mode (no elastic "
                              "joint); nothing to animate")
    modes = parse_modes(args.modes, model.n_modes)
    drive = None
    if args.audio:
        samples, rate = read_audio(args.audio)
        duration = args.duration or len(samples) / rate
    else:
        duration = args.duration or 4.0
    times = np.arange(int(round(duration * args.fps)) + 1) / args.fps
    if args.audio:
        drive = band_drive(band_loudness(samples, rate, times, args.bands), len(modes))
    bar, update = progress_bar(len(times), "frames")
    with bar:
        arrays = animate_rig(skeleton, model, times, modes, args.amplitude, args.time_scale,
                             drive, args.skinning, progress=update)
    save_animation(args.output, arrays)
    print(f"{args.output}: {len(times)} frames at {args.fps:g} fps, "
          f"{len(skeleton.vertices)} vertices, {skeleton.n_bodies} bodies, modes "
          f"{', '.join(str(m) for m in modes)} "
          f"({', '.join(f'{model.frequencies[m]:.3g}' for m in modes)} Hz), "
          f"{'audio drive' if drive is not None else 'steady drive'}, "
          f"{time.perf_counter() - start:.1f} s")


def refuse_overwrite_rig(args) -> None:
    from eigendance.files import refuse_overwrite

    refuse_overwrite(args.output, args.force)


COMMANDS = {
    "basis": (add_basis, run_basis, "compute the manifold-harmonic basis of a mesh"),
    "modes": (add_modes, run_modes, "modal analysis of a rig: natural vibration modes"),
    "animate-rig": (add_animate_rig, run_animate_rig,
                    "move a rig in its vibration modes (driven by audio) and skin its mesh"),
}


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="eigendance", description="Make 3D models dance to music.")
    from eigendance import __version__

    parser.add_argument("--version", action="version", version=f"eigendance {__version__}")
    commands = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    for name, (add, run, summary) in COMMANDS.items():
        command = commands.add_parser(name, help=summary, description=summary)
        add(command)
        command.set_defaults(run=run)
    return parser


def main(argv=None) -> int:
    args = build_parser().parse_args(argv)
    try:
        args.run(args)
    except EigendanceError as error:
        print(f"eigendance: error: {error}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print("eigendance: interrupted", file=sys.stderr)
        return 130
    except MemoryError:
        print("eigendance: error: out of memory; try a smaller -k or mesh", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
