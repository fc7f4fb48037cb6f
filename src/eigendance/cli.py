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


def run_animate(args) -> None:
    from tqdm import tqdm

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
    frames = tqdm(desc="frames", unit="frame", file=sys.stderr, disable=not sys.stderr.isatty(),
                  leave=False)
    with frames:
        count = write_animation(args.output, basis, spectrogram, mapping, args.fps,
                                progress=lambda done: frames.update(done - frames.n))
    print(f"{args.output}: {count} frames of {basis.n} vertices at {args.fps:g} fps, "
          f"{time.perf_counter() - start:.1f} s")


COMMANDS = {
    "basis": (add_basis, run_basis, "compute the manifold-harmonic basis of a mesh"),
    "spectrum": (add_spectrum, run_spectrum, "compute the banded loudness spectrogram of music"),
    "gallery": (add_gallery, run_gallery, "write an initial or bred gallery of mappings"),
    "animate": (add_animate, run_animate, "compute vertex positions of a mesh dancing to music"),
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
