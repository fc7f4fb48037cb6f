"""What the commands share: argument types that check every number, the output and progress
options, the inputs read from a file or computed (docs/design.md#cli)."""

from __future__ import annotations

import argparse
import math
import os
import sys

from tqdm import tqdm

from eigendance import checks
from eigendance.errors import InputError
from eigendance.files import BASIS_SUFFIXES, suffix_of
from eigendance.harmonic.basis import HarmonicBasis
from eigendance.inputs.defaults import DEFAULT_FPS, DEFAULT_K
from eigendance.inputs.mapping import basis_choice, record_note
from eigendance.inputs.model import read_model
from eigendance.modal.sample_rigs import SAMPLE_RIGS
from eigendance.music.gallery import MAX_GALLERY, MIN_GALLERY, check_gallery_size
from eigendance.writes import refuse_input

RIG_HELP = ("skeleton JSON, glTF 2.0 skin (.glb/.gltf), or a built-in rig: "
            + ", ".join(SAMPLE_RIGS))


def number(low: float = -math.inf, high: float = math.inf, integer: bool = False,
           above: bool = False):
    """An argparse type for finite numbers in [low, high] (or (low, high] with `above`): the
    text read as a number, then the library's one check of numbers (`checks.number`).

    Parameters
    ----------
    low, high : the range.
    integer : an integer is wanted.
    above : the value must be greater than `low`.

    Returns
    -------
    callable(text) → int or float, raising argparse.ArgumentTypeError (argparse names the
    flag); `.bounds` is (low, high), for the tests that try every flag with absurd values.
    """
    def parse(text: str):
        try:
            value = int(text) if integer else float(text)
        except ValueError:
            raise argparse.ArgumentTypeError(
                f"expected {'an integer' if integer else 'a number'}, got {text!r}") from None
        try:
            return checks.number(value, "the value", low, high, integer, above)
        except InputError as error:
            raise argparse.ArgumentTypeError(str(error)) from None
    parse.bounds = (low, high)
    return parse


HARMONICS = number(1, 20000, integer=True)
FPS = number(0, 1000, above=True)


def add_fps(parser, high: float = 1000) -> None:
    """--fps, the one default of every command (`defaults.DEFAULT_FPS`).

    Parameters
    ----------
    parser : the command's parser.
    high : the most frames per second.
    """
    parser.add_argument("--fps", type=number(0, high, above=True), default=DEFAULT_FPS,
                        help=f"frames per second (default {DEFAULT_FPS:g})")
PORT = number(0, 65535, integer=True)


def add_construction(parser) -> None:
    """--reduced / --exact (docs/design.md#reduced-basis); args.construction None: the rule.

    Parameters
    ----------
    parser : the command's parser.
    """
    construction = parser.add_mutually_exclusive_group()
    construction.add_argument("--reduced", dest="construction", action="store_const",
                              const="reduced", help="the reduced basis (samples and sparse "
                              "interpolation: large meshes); default: exact when it fits the "
                              "time and memory rule, else reduced")
    construction.add_argument("--exact", dest="construction", action="store_const",
                              const="exact", help="the exact basis, whatever the mesh's size")


def add_output(parser, what: str) -> None:
    """-o/--output and --force, as every command that writes has them.

    Parameters
    ----------
    parser : the command's parser.
    what : what the output is, for --help.
    """
    parser.add_argument("-o", "--output", required=True, help=what)
    parser.add_argument("--force", action="store_true",
                        help="overwrite an existing output (never one of the inputs)")


# The arguments that name files a command writes; every other argument naming a file is an input.
OUTPUT_ARGUMENTS = ("output", "png", "save_mapping")


def input_files(args) -> list[str]:
    """The existing files the command line names as inputs (never overwritten, `--force` or
    not: `writes.refuse_overwrite`).

    Parameters
    ----------
    args : the parsed command line.

    Returns
    -------
    list of paths.
    """
    found = []
    for name, value in vars(args).items():
        if name in OUTPUT_ARGUMENTS or name.startswith("_"):
            continue
        for item in value if isinstance(value, list) else [value]:
            if isinstance(item, str) and item and os.path.isfile(item):
                found.append(item)
    return found


def check_outputs(args) -> None:
    """InputError when an output of the command line is one of its inputs.

    Parameters
    ----------
    args : the parsed command line.
    """
    inputs = input_files(args)
    for name in OUTPUT_ARGUMENTS:
        path = getattr(args, name, None)
        if isinstance(path, str) and path:
            refuse_input(path, inputs)


def progress_bar(total: int | None, description: str, unit: str = "pair", initial: int = 0):
    """A tqdm bar on stderr (silent when stderr is not a terminal) and a callable(done).

    Parameters
    ----------
    total : the count to reach; None when it is not known in advance (the bar shows a running
        count).
    description : the bar's label.
    unit : what is counted.
    initial : the count done already (not counted in the rate, nor so in the ETA).

    Returns
    -------
    (bar, update): the bar (a context manager) and update(done), which moves it to `done`.
    """
    # No monitor thread (tqdm starts one even for a disabled bar): a single-threaded command
    # forks its eigensolver's workers; a fork server's children may print a bootstrap traceback
    # when Ctrl-C tears the pool down while they start.
    tqdm.monitor_interval = 0
    bar = tqdm(total=total, desc=description, unit=unit, file=sys.stderr,
               disable=not sys.stderr.isatty(), leave=False, initial=initial)

    def update(done):
        bar.update(max(0, done - bar.n))

    return bar, update


def add_harmonics(parser, what: str = "when MODEL is a mesh file") -> None:
    """-k, --reduced and --exact of a command that solves a mesh's basis for a mapping: by
    default the basis the mapping was made on (`inputs.mapping.basis_choice`).

    Parameters
    ----------
    parser : the command's parser.
    what : when -k counts, for --help.
    """
    parser.add_argument("-k", type=HARMONICS, default=None,
                        help=f"harmonics {what} (default: the k the --mapping was made on, "
                             f"else {DEFAULT_K})")
    add_construction(parser)


def basis_for(path: str, mapping=None, k: int | None = None, construction: str | None = None,
              output: str = "eigendance") -> HarmonicBasis:
    """A basis file (.npz) as is, or a model's mesh (a skinned glTF's too) solved, with a
    progress bar, on the basis `mapping` was made on unless -k, --exact or --reduced ask for
    another (`basis_choice`; then one line on stderr says how the dance differs). The Laplacian
    is `laplacian.laplacian_for` the mesh (robust for non-manifold edges), as the server's.

    Parameters
    ----------
    path : a basis file or a model file.
    mapping : the mapping the basis is for, or None.
    k : the -k asked for, or None.
    construction : --exact / --reduced asked for, or None.
    output : the file the command writes, naming the note.

    Returns
    -------
    HarmonicBasis.

    Raises
    ------
    InputError
        As `inputs.model.read_model` and `HarmonicProblem.basis`.
    """
    if suffix_of(path) in BASIS_SUFFIXES:
        basis = read_model(path, kind="basis").basis
        say_note(output, record_note(mapping, basis.record))
        return basis
    choice = basis_choice(mapping, k, construction)
    say_note(output, choice.note)
    problem = read_model(path, kind="mesh", construction=choice.construction,
                         samples=choice.samples).problem
    bar, update = progress_bar(choice.k, "eigenpairs")
    with bar:
        basis = problem.basis(choice.k, progress=update)
    if choice.note is None:  # the mapping's own basis: say if it did not come out the same
        say_note(output, record_note(mapping, basis.record))
    return basis


def gallery_size(text: str) -> int:
    """The gallery size: an argparse type applying the library's one rule (`check_gallery_size`).

    Parameters
    ----------
    text : the flag's value.

    Returns
    -------
    int, 2 … 16; argparse.ArgumentTypeError otherwise.
    """
    try:
        value = int(text)
    except ValueError:
        value = text
    try:
        return check_gallery_size(value)
    except InputError as error:
        raise argparse.ArgumentTypeError(str(error)) from None


gallery_size.bounds = (MIN_GALLERY, MAX_GALLERY)  # for the tests of every numeric flag


STIFFNESS = number(0, 1e12, above=True)


def add_palette_options(parser) -> None:
    """How a rig's modes play, over its mapping's palette: `animate-rig`, `export`, `render`.

    Parameters
    ----------
    parser : the command's parser.
    """
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
    group.add_argument("--tempo", choices=("beat", "free"), default=None,
                       help="beat: the sway turns on the song's beats; free: the thesis's "
                            "free-running modes (default: the mapping's, else beat)")
    group.add_argument("--skinning", choices=("modal", "lbs"), default="modal",
                       help="modal (default, first-order, as live) or lbs (exact body "
                            "transforms, linear blend: what a glTF skin plays exactly)")


def add_rig_options(parser) -> None:
    """The rig's joint stiffness (--stiffness, --joints), shared by `modes` and `animate-rig`.

    Parameters
    ----------
    parser : the command's parser.
    """
    parser.add_argument("--stiffness", type=STIFFNESS, default=1.0,
                        help="multiply every joint stiffness (default 1; frequencies scale "
                             "with its square root)")
    parser.add_argument("--joints", metavar="JSON",
                        help="per-joint stiffness: a JSON object {joint name: number, list (one "
                             "per free row) or \"auto\"} applied before --stiffness")


SECONDS = number(0, 24 * 3600)


def add_window_options(parser, duration_help: str = "default: to the song's end") -> None:
    """--start and --duration: the part of the song a command plays (docs/design.md#window).

    Parameters
    ----------
    parser : the command's parser.
    duration_help : what --duration means without a value.
    """
    group = parser.add_argument_group("part of the song (the clip plays from its time 0)")
    group.add_argument("--start", type=SECONDS, default=0.0,
                       help="where the clip starts in the song, seconds (default 0)")
    group.add_argument("--duration", type=number(0, 24 * 3600, above=True), default=None,
                       help=f"the clip's length, seconds ({duration_help}; a clip past the "
                            "song's end is cut there, with a note)")


def say_note(output: str, note: str | None) -> None:
    """Print a window's note (what was clamped) on stderr, naming the output.

    Parameters
    ----------
    output : the file the command writes.
    note : the note, or None (nothing printed).
    """
    if note:
        print(f"{output}: note: {note}", file=sys.stderr)
