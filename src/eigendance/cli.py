"""The `eigendance` command line (DESIGN §8).

Each sub-command is a function `run_<name>(args)` registered in `COMMANDS` with a function that
adds its arguments. Errors in the input print one line `eigendance: error: …` and exit 1.
"""

from __future__ import annotations

import argparse
import os
import sys
import time

from eigendance.errors import EigendanceError


def progress_bar(total: int | None, description: str, unit: str = "pair"):
    """A tqdm bar on stderr (silent when stderr is not a terminal) and a callable(done).

    total None: the count is not known in advance (the bar shows a running count).
    """
    from tqdm import tqdm

    bar = tqdm(total=total, desc=description, unit=unit, file=sys.stderr,
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


def add_serve(parser):
    from eigendance.server import DEFAULT_HOST, DEFAULT_PORT

    parser.add_argument("files", nargs="*", metavar="MESH|AUDIO|MAPPING",
                        help="meshes (OBJ, PLY, OFF, STL, glTF), audio (WAV, MP3, Ogg, FLAC) "
                             "and mapping JSON files to put in the library")
    parser.add_argument("--host", default=DEFAULT_HOST,
                        help=f"address to listen on (default {DEFAULT_HOST}: this machine only)")
    parser.add_argument("--port", type=int, default=DEFAULT_PORT,
                        help=f"port (default {DEFAULT_PORT})")
    parser.add_argument("-k", type=int, default=150,
                        help="harmonics per mesh basis (default 150)")
    parser.add_argument("--max-upload-mb", type=int, default=64,
                        help="largest file a page may upload, MiB (default 64)")


def run_serve(args) -> None:
    from eigendance.server import run, terminal_progress
    from eigendance.server.app import create_app

    library = _library(args)
    for path in args.files:
        library.add_path(path)
    terminal_progress(library)
    run(create_app(library=library), args.host, args.port,
        announce=f"eigendance: serving on {_url(args.host, args.port)}")


def add_demo(parser):
    from eigendance.server import DEFAULT_HOST, DEFAULT_PORT, DEMO_K

    parser.add_argument("--host", default=DEFAULT_HOST,
                        help=f"address to listen on (default {DEFAULT_HOST})")
    parser.add_argument("--port", type=int, default=DEFAULT_PORT,
                        help=f"port (default {DEFAULT_PORT})")
    parser.add_argument("-k", type=int, default=DEMO_K,
                        help=f"harmonics of the demo mesh (default {DEMO_K})")
    parser.add_argument("--max-upload-mb", type=int, default=64,
                        help="largest file a page may upload, MiB (default 64)")


def run_demo(args) -> None:
    from eigendance.server import demo_paths, run, terminal_progress
    from eigendance.server.app import create_app

    library = _library(args)
    terminal_progress(library)
    for path in demo_paths():
        library.add_path(path)
    run(create_app(library=library), args.host, args.port,
        announce=f"eigendance demo: open {_url(args.host, args.port)} in a browser")


def _library(args):
    import tempfile

    from eigendance.server.library import Library

    return Library(tempfile.mkdtemp(prefix="eigendance-library-"), k=args.k,
                   max_upload_bytes=args.max_upload_mb << 20)


def _url(host: str, port: int) -> str:
    shown = "127.0.0.1" if host in ("0.0.0.0", "") else host
    shown = f"[{shown}]" if ":" in shown else shown
    return f"http://{shown}:{port}/"
def add_spectrum(parser):
    parser.add_argument("audio", help="audio file: WAV, FLAC, OGG, MP3, M4A/AAC, Opus, …")
    parser.add_argument("--rate", type=float, default=100.0,
                        help="analysis frames per second (default 100)")
    parser.add_argument("--bands", type=int, default=64, help="number of bands (default 64)")
    parser.add_argument("-o", "--output", required=True, help="spectrogram file to write (.npz)")
    parser.add_argument("--png", help="also draw the spectrogram into this picture (.png)")
    parser.add_argument("--force", action="store_true", help="overwrite existing outputs")


def run_spectrum(args) -> None:
    from eigendance.audio import Spectrogram
    from eigendance.files import refuse_overwrite

    refuse_overwrite(args.output, args.force)
    if args.png:
        refuse_overwrite(args.png, args.force)
    start = time.perf_counter()
    spectrogram = Spectrogram.from_file(args.audio, rate=args.rate, bands=args.bands)
    spectrogram.save(args.output)
    if args.png:
        spectrogram.save_png(args.png, title=os.path.basename(args.audio))
    print(f"{args.output}: {len(spectrogram.times)} frames × {spectrogram.bands} bands, "
          f"{spectrogram.duration:.2f} s at {spectrogram.sample_rate} Hz, "
          f"{time.perf_counter() - start:.1f} s")


def add_gallery(parser):
    parser.add_argument("basis", help="basis file (.npz) or mesh file (solved with -k)")
    parser.add_argument("spectrogram", help="spectrogram file (.npz) or audio file")
    parser.add_argument("-n", "--size", type=int, default=8,
                        help="number of gallery items (default 8; even for an initial gallery)")
    parser.add_argument("--seed", type=int, default=0, help="breeding seed (default 0)")
    parser.add_argument("--breed", nargs="+", metavar="MAPPING",
                        help="breed children of these mapping files instead of the initial "
                             "gallery")
    parser.add_argument("--calibration", choices=("strongest", "each"), default="strongest",
                        help="initial gallery: one M_a so the strongest item moves 5%% of the "
                             "diagonal (default, DESIGN §4), or each item its own")
    parser.add_argument("-k", type=int, default=300,
                        help="harmonics when BASIS is a mesh file (default 300)")
    parser.add_argument("-o", "--output", required=True, help="folder for 0.json, 1.json, …")
    parser.add_argument("--force", action="store_true", help="overwrite existing mappings")


def run_gallery(args) -> None:
    from eigendance.animate import basis_from_path, spectrogram_from_path
    from eigendance.files import refuse_overwrite
    from eigendance.mapping import Mapping, breed, initial_gallery

    if args.size < 1:
        raise EigendanceError(f"-n must be a positive integer, got {args.size}")
    paths = [os.path.join(args.output, f"{i}.json") for i in range(args.size)]
    for path in paths:
        refuse_overwrite(path, args.force)
    if args.breed:
        parents = [Mapping.load(path) for path in args.breed]
        items = breed(parents, args.size, args.seed)
    else:
        basis = basis_from_path(args.basis, args.k)
        spectrogram = spectrogram_from_path(args.spectrogram)
        items = initial_gallery(basis, spectrogram, args.size, calibration=args.calibration)
    for item, path in zip(items, paths, strict=True):
        item.save(path)
    what = f"children of {len(args.breed)} parents" if args.breed else "initial gallery"
    print(f"{args.output}: {len(items)} mappings ({what})")


def add_animate(parser):
    parser.add_argument("mesh", help="mesh file, or basis file (.npz)")
    parser.add_argument("audio", help="audio file, or spectrogram file (.npz)")
    parser.add_argument("--mapping", help="mapping JSON (default: the initial-gallery item of "
                                          "8 that moves the mesh most)")
    parser.add_argument("--fps", type=float, default=30.0, help="frames per second (default 30)")
    parser.add_argument("-k", type=int, default=300,
                        help="harmonics when MESH is a mesh file (default 300)")
    parser.add_argument("-o", "--output", required=True, help="animation file to write (.npz)")
    parser.add_argument("--force", action="store_true", help="overwrite an existing output")


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


def run_animate(args) -> None:

    from eigendance.animate import basis_from_path, spectrogram_from_path, write_animation
    from eigendance.files import refuse_overwrite
    from eigendance.mapping import Mapping, strongest_item

    refuse_overwrite(args.output, args.force)
    start = time.perf_counter()
    mapping = Mapping.load(args.mapping) if args.mapping else None
    bar, update = progress_bar(args.k, "eigenpairs")
    with bar:
        basis = basis_from_path(args.mesh, args.k, progress=update)
    spectrogram = spectrogram_from_path(args.audio, bands=mapping.bands if mapping else 64)
    if mapping is None:
        mapping = strongest_item(basis, spectrogram)
    frames, update = progress_bar(None, "frames", unit="frame")
    with frames:
        count = write_animation(args.output, basis, spectrogram, mapping, args.fps,
                                progress=update)
    print(f"{args.output}: {count} frames of {basis.n} vertices at {args.fps:g} fps, "
          f"{time.perf_counter() - start:.1f} s")


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
    bar, update = progress_bar(len(times), "frames", unit="frame")
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
    "serve": (add_serve, run_serve, "serve the web app: live player and animated gallery"),
    "demo": (add_demo, run_demo, "serve the web app with the built-in mesh and music"),
    "spectrum": (add_spectrum, run_spectrum, "compute the banded loudness spectrogram of music"),
    "gallery": (add_gallery, run_gallery, "write an initial or bred gallery of mappings"),
    "animate": (add_animate, run_animate, "compute vertex positions of a mesh dancing to music"),
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
