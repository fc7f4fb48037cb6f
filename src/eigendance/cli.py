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
    for path in demo_paths(library.folder):
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


COMMANDS = {
    "basis": (add_basis, run_basis, "compute the manifold-harmonic basis of a mesh"),
    "serve": (add_serve, run_serve, "serve the web app: live player and animated gallery"),
    "demo": (add_demo, run_demo, "serve the web app with the built-in mesh and music"),
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
