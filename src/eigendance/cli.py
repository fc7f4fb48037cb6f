"""The `eigendance` command line (docs/design.md#cli).

Each sub-command is a pair of functions, `add_<name>(parser)` and `run_<name>(args)`, listed in
`COMMANDS`. Errors print one line `eigendance: error: …`: exit status 1 for bad input (with a
hint naming the flag that may help), 2 for a failure of eigendance itself (a bug to report).
"""

from __future__ import annotations

import argparse
import math
import os
import sys
import time
import warnings

import numpy as np
from tqdm import tqdm

from eigendance import __version__
from eigendance.errors import EigendanceError, InputError, ModelWarning, one_line
from eigendance.export.dance import HarmonicDance, rig_dance
from eigendance.export.files import FORMATS as EXPORT_FORMATS
from eigendance.export.files import companion_paths, export_dance, format_of
from eigendance.export.gltf import glb_size
from eigendance.export.renderer import Look
from eigendance.export.video import parse_size, render_video
from eigendance.files import refuse_overwrite, suffix_of
from eigendance.harmonic.basis import HarmonicBasis
from eigendance.harmonic.eigensolver import SOLVERS
from eigendance.harmonic.laplacian import LAPLACIANS
from eigendance.harmonic.mesh import load_mesh
from eigendance.harmonic.motion import write_animation
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
from eigendance.modal.sample_rigs import SAMPLE_RIGS, load_rig
from eigendance.modal.skeleton import read_joint_stiffness
from eigendance.music.breeding import breed
from eigendance.music.gallery import (
    DEFAULT_GALLERY,
    MAX_GALLERY,
    MIN_GALLERY,
    check_gallery_size,
    gallery_correlations,
    gallery_motion,
    initial_gallery,
    strongest_item,
)
from eigendance.music.mapping import Mapping
from eigendance.music.spectrogram import Spectrogram, check_picture_path, frame_times, save_picture
from eigendance.server.app import create_app
from eigendance.server.guard import exposure_warning
from eigendance.server.serve import (
    DEFAULT_HOST,
    DEFAULT_PORT,
    DEMO_K,
    demo_paths,
    library_session,
    listen,
    run,
    terminal_progress,
)

RIG_HELP = ("skeleton JSON, glTF 2.0 skin (.glb/.gltf), or a built-in rig: "
            + ", ".join(SAMPLE_RIGS))


# --- argument types: a bad value is an argparse error naming the flag ------------------------

class Parser(argparse.ArgumentParser):
    """argparse with the project's errors: one line, exit status 1 (bad input)."""

    def error(self, message):
        self.exit(1, f"eigendance: error: {one_line(message)} (see {self.prog} --help)\n")


def number(low: float = -math.inf, high: float = math.inf, integer: bool = False,
           above: bool = False):
    """An argparse type for finite numbers in [low, high] (or (low, high] with `above`)."""
    def parse(text: str):
        try:
            value = int(text) if integer else float(text)
        except ValueError:
            raise argparse.ArgumentTypeError(
                f"expected {'an integer' if integer else 'a number'}, got {text!r}") from None
        if not math.isfinite(value) or value > high or value < low or (above and value <= low):
            bound = f"> {low:g}" if above else f"≥ {low:g}"
            limit = "" if math.isinf(high) else f" and ≤ {high:g}"
            raise argparse.ArgumentTypeError(f"expected a finite number {bound}{limit}, got "
                                             f"{text!r}")
        return value
    parse.bounds = (low, high)  # for the tests that try every flag with absurd values
    return parse


HARMONICS = number(1, 20000, integer=True)
FPS = number(0, 1000, above=True)
PORT = number(0, 65535, integer=True)


def add_output(parser, what: str) -> None:
    """-o/--output (`what` it writes) and --force, as every command that writes has them."""
    parser.add_argument("-o", "--output", required=True, help=what)
    parser.add_argument("--force", action="store_true", help="overwrite an existing output")


def progress_bar(total: int | None, description: str, unit: str = "pair"):
    """A tqdm bar on stderr (silent when stderr is not a terminal) and a callable(done).

    total None: the count is not known in advance (the bar shows a running count).
    """
    bar = tqdm(total=total, desc=description, unit=unit, file=sys.stderr,
               disable=not sys.stderr.isatty(), leave=False)

    def update(done):
        bar.update(max(0, done - bar.n))

    return bar, update


def basis_from(path: str, k: int, progress=None) -> HarmonicBasis:
    """A basis file (.npz) as is, or a mesh file solved for k harmonics (through the cache)."""
    if path.lower().endswith(".npz"):
        return HarmonicBasis.load(path)
    return HarmonicBasis.from_mesh(path, k, progress=progress)


def spectrogram_from(path: str, bands: int = 64) -> Spectrogram:
    """A spectrogram file (.npz) as is, or an audio file analysed into `bands` bands."""
    if path.lower().endswith(".npz"):
        return Spectrogram.load(path)
    return Spectrogram.from_file(path, bands=bands)


# --- commands -------------------------------------------------------------------------------

def add_basis(parser):
    parser.add_argument("mesh", help="mesh file: OBJ, PLY, OFF, STL, glTF or GLB")
    parser.add_argument("-k", type=HARMONICS, default=300, help="number of harmonics (default 300)")
    parser.add_argument("--laplacian", choices=LAPLACIANS, default="cotan",
                        help="cotan (default, thesis) or robust (intrinsic Delaunay; "
                             "for non-manifold meshes)")
    parser.add_argument("--solver", choices=SOLVERS, default="bands",
                        help="bands (default, spectrum slicing) or eigsh (naive baseline)")
    parser.add_argument("--no-cache", action="store_true", help="solve even if cached")
    add_construction(parser)
    parser.add_argument("--samples", type=number(2, 10**7, integer=True), default=None,
                        help="samples of a reduced basis (default 24·k, at least 2000)")
    add_output(parser, "basis file to write (.npz)")


def add_construction(parser) -> None:
    """--reduced / --exact (docs/design.md#reduced-basis); args.construction None: the rule."""
    construction = parser.add_mutually_exclusive_group()
    construction.add_argument("--reduced", dest="construction", action="store_const",
                              const="reduced", help="the reduced basis (samples and sparse "
                              "interpolation: large meshes); default: exact when it fits the "
                              "time and memory rule, else reduced")
    construction.add_argument("--exact", dest="construction", action="store_const",
                              const="exact", help="the exact basis, whatever the mesh's size")


def run_basis(args) -> None:
    refuse_overwrite(args.output, args.force)
    start = time.perf_counter()
    mesh = load_mesh(args.mesh)
    if cleaned := mesh.describe_cleanup():
        print(f"{mesh.name}: removed {cleaned}", file=sys.stderr)
    bar, update = progress_bar(args.k, "eigenpairs")
    with bar:
        basis = HarmonicBasis.from_mesh(mesh, args.k, laplacian=args.laplacian,
                                        solver=args.solver, cache=not args.no_cache,
                                        progress=update,
                                        construction=args.construction or "auto",
                                        samples=args.samples)
    basis.save(args.output)
    how = "exact" if basis.reduced is None else f"reduced, {basis.reduced.count} samples"
    print(f"{args.output}: n = {basis.n} vertices, k = {basis.k} harmonics ({how}), "
          f"largest eigenvalue {basis.eigenvalues[-1]:.6g}, "
          f"{time.perf_counter() - start:.1f} s")


def add_server_options(parser, k: int, k_help: str) -> None:
    parser.add_argument("--host", default=DEFAULT_HOST,
                        help=f"address to listen on (default {DEFAULT_HOST}: this machine only; "
                             "another address lets other machines use the server, with no "
                             "password)")
    parser.add_argument("--port", type=PORT, default=DEFAULT_PORT,
                        help=f"port (default {DEFAULT_PORT}; 0: any free port)")
    parser.add_argument("-k", type=HARMONICS, default=k, help=f"{k_help} (default {k})")
    parser.add_argument("--max-upload-mb", type=number(1, 4096, integer=True), default=64,
                        help="largest file a page may upload, MiB (default 64)")
    parser.add_argument("--max-memory-mb", type=number(16, 1 << 22, integer=True), default=4096,
                        help="memory the library's meshes, songs and rigs may keep, MiB; the "
                             "least recently used are removed beyond it (default 4096)")
    add_construction(parser)


def add_serve(parser):
    parser.add_argument("files", nargs="*", metavar="MESH|AUDIO|MAPPING|RIG",
                        help="meshes (OBJ, PLY, OFF, STL, glTF), audio (WAV, MP3, Ogg, FLAC), "
                             "mapping JSON and skeleton JSON files to put in the library (a "
                             "glTF with a skin is a rig too; the built-in rigs are always "
                             "there)")
    add_server_options(parser, 150, "harmonics per mesh basis")


def run_serve(args) -> None:
    serve(args, lambda: args.files, "eigendance: serving on {url}")


def add_demo(parser):
    add_server_options(parser, DEMO_K, "harmonics of the demo mesh")


def run_demo(args) -> None:
    serve(args, demo_paths, "eigendance demo: open {url} in a browser")


def serve(args, paths, announce: str) -> None:
    """Listen, fill a temporary library with the files of paths() and serve it until
    interrupted; the library's folder is removed at the end (docs/design.md#server)."""
    listening = listen(args.host, args.port)
    port = listening.getsockname()[1]
    if warning := exposure_warning(args.host):
        print(warning, file=sys.stderr)
    with library_session(k=args.k, max_upload_bytes=args.max_upload_mb << 20,
                         memory_budget=args.max_memory_mb << 20,
                         construction=args.construction or "auto") as library:
        terminal_progress(library)
        for path in paths():
            library.add_path(path)
        run(create_app(library, args.host, port), listening, on_exit=library.stop,
            announce=announce.format(url=url(args.host, port)))


def url(host: str, port: int) -> str:
    shown = "127.0.0.1" if host in ("0.0.0.0", "") else host
    shown = f"[{shown}]" if ":" in shown else shown
    return f"http://{shown}:{port}/"


def add_spectrum(parser):
    parser.add_argument("audio", help="audio file: WAV, FLAC, OGG, MP3, M4A/AAC, Opus, …")
    parser.add_argument("--rate", type=number(0, 1000, above=True), default=100.0,
                        help="analysis frames per second (default 100, at most 1000)")
    parser.add_argument("--bands", type=number(1, 1024, integer=True), default=64,
                        help="number of bands (default 64)")
    parser.add_argument("--png", help="also draw the spectrogram into this picture "
                                      "(.png, .svg, .pdf or .jpg)")
    add_output(parser, "spectrogram file to write (.npz)")


def run_spectrum(args) -> None:
    refuse_overwrite(args.output, args.force)
    if args.png:
        check_picture_path(args.png)
        refuse_overwrite(args.png, args.force)
    start = time.perf_counter()
    spectrogram = Spectrogram.from_file(args.audio, rate=args.rate, bands=args.bands)
    spectrogram.save(args.output)
    if args.png:
        save_picture(spectrogram, args.png, title=os.path.basename(args.audio))
    print(f"{args.output}: {len(spectrogram.times)} frames × {spectrogram.bands} bands, "
          f"{spectrogram.duration:.2f} s at {spectrogram.sample_rate} Hz, "
          f"{time.perf_counter() - start:.1f} s")


def add_gallery(parser):
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
    parser.add_argument("-k", type=HARMONICS, default=300,
                        help="harmonics when BASIS is a mesh file (default 300)")
    add_output(parser, "folder for 0.json, 1.json, …")


def gallery_size(text: str) -> int:
    """The gallery size: an argparse type applying the library's one rule (`check_gallery_size`)."""
    try:
        value = int(text)
    except ValueError:
        value = text
    try:
        return check_gallery_size(value)
    except InputError as error:
        raise argparse.ArgumentTypeError(str(error)) from None


gallery_size.bounds = (MIN_GALLERY, MAX_GALLERY)  # for the tests of every numeric flag


def run_gallery(args) -> None:
    size = check_gallery_size(args.size)
    paths = [os.path.join(args.output, f"{i}.json") for i in range(size)]
    for path in paths:
        refuse_overwrite(path, args.force)
    basis = spectrogram = None
    if args.breed:
        parents = [Mapping.load(path) for path in args.breed]
        items = breed(parents, size, args.seed)
    if not args.breed or args.verbose:
        basis = basis_from(args.basis, args.k)
        spectrogram = spectrogram_from(args.spectrogram)
    if not args.breed:
        items = initial_gallery(basis, spectrogram, size)
    for item, path in zip(items, paths, strict=True):
        item.save(path)
    what = f"children of {len(args.breed)} parents" if args.breed else "initial gallery"
    print(f"{args.output}: {len(items)} mappings ({what})")
    if args.verbose:
        print("\n".join(gallery_table(basis, spectrogram, items)))


def gallery_table(basis, spectrogram, items) -> list[str]:
    """Lines of the --verbose table: each item's m and peak motion on the song (percent of the
    bounding-box diagonal) and its main harmonic range, then the largest correlation."""
    lines = [f"{'item':>4} {'m':>7} {'peak':>7}  main harmonics (of k = {basis.k})"]
    for number, measured in enumerate(gallery_motion(basis, spectrogram, items), 1):
        harmonics = "none" if measured.lowest < 0 else \
            f"{measured.lowest}" if measured.lowest == measured.highest else \
            f"{measured.lowest}–{measured.highest}"
        lines.append(f"{number:>4} {100 * measured.motion:>6.2f}% {100 * measured.peak:>6.2f}%"
                     f"  {harmonics}")
    correlations = np.abs(gallery_correlations(basis, spectrogram, items))
    np.fill_diagonal(correlations, 0)
    first, second = np.unravel_index(np.argmax(correlations), correlations.shape)
    lines.append(f"m: 95th percentile over the song's frames of the RMS vertex displacement / "
                 f"bounding-box diagonal; largest correlation between two items: "
                 f"{correlations[first, second]:.3f} (items {first + 1} and {second + 1})")
    return lines


def add_animate(parser):
    parser.add_argument("mesh", help="mesh file, or basis file (.npz)")
    parser.add_argument("audio", help="audio file, or spectrogram file (.npz)")
    parser.add_argument("--mapping", help="mapping JSON (default: the initial-gallery item of "
                                          "8 that moves the mesh most)")
    parser.add_argument("--fps", type=FPS, default=30.0, help="frames per second (default 30)")
    parser.add_argument("-k", type=HARMONICS, default=300,
                        help="harmonics when MESH is a mesh file (default 300)")
    add_output(parser, "animation file to write (.npz)")


def run_animate(args) -> None:
    refuse_overwrite(args.output, args.force)
    start = time.perf_counter()
    mapping = Mapping.load(args.mapping) if args.mapping else None
    bar, update = progress_bar(args.k, "eigenpairs")
    with bar:
        basis = basis_from(args.mesh, args.k, progress=update)
    spectrogram = spectrogram_from(args.audio, bands=mapping.bands if mapping else 64)
    if mapping is None:
        mapping = strongest_item(basis, spectrogram)
    frames, update = progress_bar(None, "frames", unit="frame")
    with frames:
        count = write_animation(args.output, basis, spectrogram, mapping, args.fps,
                                progress=update, force=args.force)
    print(f"{args.output}: {count} frames of {basis.n} vertices at {args.fps:g} fps, "
          f"{time.perf_counter() - start:.1f} s")


STIFFNESS = number(0, 1e12, above=True)


def add_palette_options(parser) -> None:
    """How a rig's modes play, over its mapping's palette: `animate-rig`, `export`, `render`."""
    group = parser.add_argument_group("rigs: the palette (default: the mapping's, else the "
                                      "default rule that makes any rig dance)")
    group.add_argument("--modes", help="mode indices that move, e.g. 0,2,5-8")
    group.add_argument("--amplitude", type=number(0, math.pi), default=None,
                       help="largest body rotation of each chosen mode at full drive, radians")
    group.add_argument("--time-scale", type=number(0, 1000, above=True), default=None,
                       help="multiply the natural frequencies")
    group.add_argument("--offset", type=number(-1e6, 1e6), default=None,
                       help="the filter's offset b: 0 keeps silence still, 1 sways idly "
                            "(default: the mapping's, else 0)")
    group.add_argument("--skinning", choices=("modal", "lbs"), default="modal",
                       help="modal (default, first-order, as live) or lbs (exact body "
                            "transforms, linear blend: what a glTF skin plays exactly)")


def add_rig_options(parser) -> None:
    """The rig and its joints' stiffness, shared by `modes` and `animate-rig`."""
    parser.add_argument("--stiffness", type=STIFFNESS, default=1.0,
                        help="multiply every joint stiffness (default 1; frequencies scale "
                             "with its square root)")
    parser.add_argument("--joints", metavar="JSON",
                        help="per-joint stiffness: a JSON object {joint name: number, list (one "
                             "per free row) or \"auto\"} applied before --stiffness")


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


# --- exports: files for other tools, and video (docs/design.md#exports) ----------------------

def add_dance_inputs(parser, audio_help: str) -> None:
    """The inputs of `export` and `render`: a mesh (+ mapping) or a rig, and the song."""
    parser.add_argument("model", help="mesh file (OBJ, PLY, OFF, STL, glTF) or basis file "
                        "(.npz); with --rig, or a .json or built-in name: " + RIG_HELP)
    parser.add_argument("audio", help=audio_help)
    parser.add_argument("--mapping", help="mapping JSON (default: for a mesh, the initial-"
                        "gallery item of 8 that moves it most; for a rig, bands in order)")
    parser.add_argument("--rig", action="store_true",
                        help="MODEL is a rig moved in its vibration modes (needed for a glTF "
                             "skin; a .json or built-in rig is one anyway)")
    parser.add_argument("-k", type=HARMONICS, default=300,
                        help="harmonics when MODEL is a mesh file (default 300)")
    parser.add_argument("--fps", type=number(0, 240, above=True), default=30.0,
                        help="frames per second (default 30)")
    add_palette_options(parser)
    parser.add_argument("--stiffness", type=STIFFNESS, default=1.0,
                        help="multiply every joint stiffness of a rig (default 1)")


def is_rig(args) -> bool:
    return args.rig or args.model in SAMPLE_RIGS or args.model.lower().endswith(".json")


def song_of(args) -> str | None:
    """The song's audio file, or None when AUDIO is a spectrogram file."""
    return None if args.audio.lower().endswith(".npz") else args.audio


def dance_from(args, mapping: Mapping | None):
    """The dance `export` and `render` write: a mesh by its harmonics or a rig by its modes."""
    name = os.path.splitext(os.path.basename(args.output))[0]
    if is_rig(args):
        skeleton = load_rig(args.model)
        model = ModalModel.from_skeleton(skeleton, stiffness=args.stiffness)
        if model.n_modes == 0:
            raise InputError(f"{skeleton.name}: the rig has no vibration mode (no elastic "
                             "joint); nothing to move")
        spectrogram = spectrogram_from(args.audio, mapping.bands if mapping else 64)
        mapping = rig_mapping(model, spectrogram, mapping, parse_modes(args.modes, model.n_modes),
                              args.amplitude, args.time_scale, args.offset)
        return rig_dance(skeleton, model, spectrogram.duration,
                         lambda times: rig_coefficients(model, spectrogram, mapping, times),
                         args.skinning, song_of(args), name)
    basis, spectrogram = harmonic_inputs(args, mapping.bands if mapping else 64)
    mapping = mapping or strongest_item(basis, spectrogram)
    return HarmonicDance(basis, spectrogram, mapping, song_of(args), name)


def harmonic_inputs(args, bands: int):
    """The mesh's basis (solved with a progress bar, or read) and the song's spectrogram."""
    bar, update = progress_bar(args.k, "eigenpairs")
    with bar:
        basis = basis_from(args.model, args.k, progress=update)
    return basis, spectrogram_from(args.audio, bands)


def add_export(parser):
    add_dance_inputs(parser, "the song: audio file (copied beside the export), or "
                             "spectrogram file (.npz)")
    parser.add_argument("--format", choices=tuple(EXPORT_FORMATS),
                        help="glb (glTF 2.0: morph targets, or a skin), pc2 (+ the rest mesh "
                             "as OBJ, for Blender's Mesh Cache), usd (time-sampled points); "
                             "default: by the output's suffix")
    add_output(parser, "file to write: .glb, .pc2 or .usd/.usdc/.usda")


def run_export(args) -> None:
    format = format_of(args.output, args.format)
    start = time.perf_counter()
    mapping = Mapping.load(args.mapping) if args.mapping else None
    for path in companion_paths(args.output, format, song_of(args)).values():
        if path is not None:  # before any work: the export would stop at the end
            refuse_overwrite(path, args.force)
    dance = dance_from(args, mapping)
    bar, update = progress_bar(None, "frames", unit="frame")
    with bar:
        def step(done, total):
            bar.total = total
            update(done)
        report = export_dance(dance, args.output, format, args.fps, args.force, step)
    size, cache = report["bytes"], report["point_cache_bytes"]
    compared = "" if format == "pc2" else \
        f" (as a point cache: {cache / 1e6:.2f} MB, {cache / size:.1f}× the size)"
    print(f"{args.output}: {report['frames']} frames of {dance.n} vertices at {args.fps:g} "
          f"fps, {size / 1e6:.2f} MB{compared}, {time.perf_counter() - start:.1f} s")
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
    try:
        return parse_size(text)
    except InputError as error:
        raise argparse.ArgumentTypeError(str(error)) from None


def run_render(args) -> None:
    if suffix_of(args.output) != ".mp4":
        raise InputError(f"{args.output}: the video is an MP4; name it .mp4")
    if song_of(args) is None:
        raise InputError(f"{args.audio}: a video needs the song itself, not its spectrogram")
    refuse_overwrite(args.output, args.force)
    if args.breed and args.gallery is None:
        raise InputError("breeding parents were given without a gallery size",
                         remedy={"gallery": DEFAULT_GALLERY})
    start = time.perf_counter()
    mapping = Mapping.load(args.mapping) if args.mapping else None
    if args.gallery is not None:
        size = check_gallery_size(args.gallery)
        if is_rig(args):
            raise InputError(f"{args.model}: a gallery breeds mappings of a mesh's harmonics; "
                             "render a rig on its own")
        if mapping is not None:
            raise InputError(f"{args.mapping}: a gallery makes its own mappings; breed from it "
                             "instead", remedy={"breed": args.mapping})
        items = breed([Mapping.load(path) for path in args.breed], size, args.seed) \
            if args.breed else None
        basis, spectrogram = harmonic_inputs(args, items[0].bands if items else 64)
        items = items or initial_gallery(basis, spectrogram, size)
        name = os.path.splitext(os.path.basename(args.output))[0]
        dances = [HarmonicDance(basis, spectrogram, item, song_of(args), name) for item in items]
        looks = [Look(item.shading, item.deformed_normal_weight) for item in items]
    else:
        dances = [dance_from(args, mapping)]
        looks = [Look(mapping.shading, mapping.deformed_normal_weight) if mapping else Look()]
    bar, update = progress_bar(None, "frames", unit="frame")
    with bar:
        def step(done, total):
            bar.total = total
            update(done)
        report = render_video(args.output, dances, looks, args.audio, args.fps, args.size,
                              args.force, step)
    seconds = time.perf_counter() - start
    print(f"{args.output}: {report['frames']} frames, {args.size[0]}x{args.size[1]} at "
          f"{args.fps:g} fps, {report['duration']:.2f} s of video with the song, "
          f"{len(dances)} {'tiles' if len(dances) > 1 else 'dancer'}, {seconds:.1f} s "
          f"({report['duration'] / seconds:.2f}× real time)")


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
    "export": (add_export, run_export,
               "write the dance for other tools: glTF (.glb), point cache (.pc2 + .obj), USD"),
    "render": (add_render, run_render, "render the dance with its song into a video (.mp4)"),
}


def build_parser() -> argparse.ArgumentParser:
    parser = Parser(prog="eigendance", description="Make 3D models dance to music.")
    parser.add_argument("--version", action="version", version=f"eigendance {__version__}")
    commands = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    for name, (add, run_command, summary) in COMMANDS.items():
        command = commands.add_parser(name, help=summary, description=summary)
        add(command)
        command.set_defaults(run=run_command)
    return parser


# How a remedy ({parameter: value}) reads on the command line.
FLAGS = {"k": "-k"}


def hint(remedy: dict) -> str:
    """'; try --solver eigsh' for {"solver": "eigsh"} ('' for no remedy)."""
    if remedy.get("force"):
        reason = remedy["force"] if isinstance(remedy["force"], str) else "overwrite it"
        return f"; pass --force to {reason}"
    flags = [FLAGS.get(name, '--' + name.replace('_', '-')) + ("" if value is True else f" {value}")
             for name, value in remedy.items()]
    return f"; try {' '.join(flags)}" if flags else ""


def show_warning(message, category, *_, **__) -> None:
    """A warning as one line on stderr: `eigendance: warning: …`."""
    print(f"eigendance: warning: {one_line(str(message))}", file=sys.stderr)


def main(argv=None) -> int:
    """Run one command; the exit status: 0 done, 1 bad input, 2 a bug, 130 interrupted."""
    args = build_parser().parse_args(argv)
    try:
        with warnings.catch_warnings():
            if not os.environ.get("EIGENDANCE_DEBUG"):
                # Library warnings (numpy's floating-point ones, pygltflib's about odd files)
                # would only add lines around the one line a command ends with; outputs are
                # checked finite instead (files.check_finite).
                warnings.simplefilter("ignore")
            warnings.simplefilter("always", ModelWarning)  # what a model file loses: one line
            warnings.showwarning = show_warning
            args.run(args)
    except InputError as error:
        print(f"eigendance: error: {error}{hint(error.remedy)}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print("eigendance: interrupted", file=sys.stderr)
        return 130
    except MemoryError:
        print("eigendance: error: out of memory; try a smaller -k or mesh", file=sys.stderr)
        return 1
    except Exception as error:  # noqa: BLE001 - every failure of ours ends in one line
        if os.environ.get("EIGENDANCE_DEBUG"):
            raise
        what = str(error) if isinstance(error, EigendanceError) else \
            f"{type(error).__name__}: {one_line(error)}"
        remedy = hint(getattr(error, "remedy", {}))
        print(f"eigendance: internal error, a bug to report: {what}{remedy} "
              "(EIGENDANCE_DEBUG=1 shows the traceback)", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
