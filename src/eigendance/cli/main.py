"""The `eigendance` command line (docs/design.md#cli).

Each sub-command is a pair of functions, `add_<name>(parser)` and `run_<name>(args)`, listed in
`COMMANDS`. Errors print one line `eigendance: error: …`: exit status 1 for bad input (with a
hint naming the flag that may help), 2 for a failure of eigendance itself (a bug to report).
"""

from __future__ import annotations

import argparse
import os
import signal
import sys
import threading
import warnings

from eigendance import __version__
from eigendance.cli.batch import add_batch, run_batch
from eigendance.cli.blender import add_bake, add_blender_addon, run_bake, run_blender_addon
from eigendance.cli.exports import add_export, add_render, is_rig, run_export, run_render
from eigendance.cli.harmonics import (
    add_animate,
    add_basis,
    add_gallery,
    add_spectrum,
    run_animate,
    run_basis,
    run_gallery,
    run_spectrum,
)
from eigendance.cli.options import check_outputs
from eigendance.cli.rigs import add_animate_rig, add_modes, run_animate_rig, run_modes
from eigendance.cli.show import add_show, run_show
from eigendance.cli.web import add_demo, add_serve, run_demo, run_serve
from eigendance.errors import EigendanceError, InputError, ModelWarning, one_line
from eigendance.writes import all_or_nothing


class Parser(argparse.ArgumentParser):
    """argparse with the project's errors: one line, exit status 1 (bad input).

    Parameters
    ----------
    *args, **kwargs : those of argparse.ArgumentParser.
    """

    def error(self, message):
        """End with one line naming the problem and where --help is, exit status 1.

        Parameters
        ----------
        message : argparse's message.
        """
        self.exit(1, f"eigendance: error: {one_line(message)} (see {self.prog} --help)\n")


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
    "show": (add_show, run_show, "play a set list on stage: cues change on the downbeat, an "
                                 "output page for the projector (/show), MIDI, OSC, Link"),
    "batch": (add_batch, run_batch, "make many songs × many models from a plan (TOML), on "
                                    "local processes or Ray; resumable"),
    "blender-addon": (add_blender_addon, run_blender_addon,
                      "write the Blender add-on (an extension .zip for Blender 4.2 and later)"),
    "bake": (add_bake, run_bake, "write a mesh's dance in its file's vertex order, as morph "
                                 "targets (.npz) or a point cache (.pc2): what the add-on reads"),
}


def build_parser() -> argparse.ArgumentParser:
    """The argument parser of every command (`COMMANDS`).

    Returns
    -------
    argparse.ArgumentParser; each sub-command sets `run`, the function that runs it.
    """
    parser = Parser(prog="eigendance", description="Make 3D models dance to music.")
    parser.add_argument("--version", action="version", version=f"eigendance {__version__}")
    commands = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    for name, (add, run_command, summary) in COMMANDS.items():
        command = commands.add_parser(name, help=summary, description=summary)
        add(command)
        command.set_defaults(run=run_command)
    return parser


# Commands that run on and write as they go (a server's cache, a batch's record and outputs):
# not all-or-nothing as a whole.
SERVING = ("serve", "demo", "show", "batch")

# How a remedy ({parameter: value}) reads on the command line.
FLAGS = {"k": "-k"}


def hint(remedy: dict) -> str:
    """How a remedy reads on the command line: '; try --solver eigsh' for {"solver": "eigsh"}.

    Parameters
    ----------
    remedy : {parameter: value} (an error's `remedy`).

    Returns
    -------
    str, '' for no remedy.
    """
    if remedy.get("force"):
        reason = remedy["force"] if isinstance(remedy["force"], str) else "overwrite it"
        return f"; pass --force to {reason}"
    flags = [FLAGS.get(name, "--" + name.replace("_", "-")) + ("" if value is True else f" {value}")
             for name, value in remedy.items()]
    return f"; try {' '.join(flags)}" if flags else ""


def show_warning(message, category, *_, **__) -> None:
    """A warning as one line on stderr: `eigendance: warning: …`.

    Parameters
    ----------
    message : the warning.
    category : its class.
    *_, **__ : the rest of warnings.showwarning's arguments.
    """
    print(f"eigendance: warning: {one_line(str(message))}", file=sys.stderr)


# Control characters (C0, DEL, C1): a name from a file (a skeleton's body, a glTF node, a mesh
# file's name) printed as it is could set the terminal's title or clear it.
CONTROL = {code: None for code in [*range(32), *range(127, 160)]}


class Printable:
    """A text stream that drops every control character but those in `keep` from what is
    written to it (docs/design.md#errors).

    Parameters
    ----------
    stream : the stream written to (sys.stdout, sys.stderr).
    keep : the control characters kept ("\\n\\t", and "\\r" for progress bars).

    Example
    -------
    >>> import io
    >>> out = io.StringIO()
    >>> _ = Printable(out, "\\n").write("up\\x1b]0;title\\x07\\n")
    >>> out.getvalue()
    'up]0;title\\n'
    """

    def __init__(self, stream, keep: str):
        self.stream = stream
        self.table = {code: None for code in CONTROL if chr(code) not in keep}

    def write(self, text: str) -> int:
        """Write `text` without its control characters.

        Parameters
        ----------
        text : what to write.

        Returns
        -------
        int, the length of `text` (as a stream's write returns).
        """
        self.stream.write(text.translate(self.table))
        return len(text)

    def __getattr__(self, name):
        return getattr(self.stream, name)


class Terminated(KeyboardInterrupt):
    """SIGTERM, turned into an exception like Ctrl-C's so that every cleanup runs: temporary
    outputs removed, workers and encoders stopped (docs/design.md#errors)."""


def _terminate(number, frame):
    raise Terminated()


def memory_advice(args) -> str:
    """What may make a command that ran out of memory fit: it depends on what it computes.

    Parameters
    ----------
    args : the parsed command line.

    Returns
    -------
    str.
    """
    try:
        rig = args.command in ("modes", "animate-rig") or (
            args.command in ("export", "render", "animate") and is_rig(args))
    except InputError:
        rig = False
    if rig:
        return "try a rig of fewer bodies and joints, or a shorter part of the song"
    if args.command in ("spectrum",):
        return "try a shorter song or fewer bands"
    if args.command in ("gallery", "animate", "export", "render", "basis", "bake"):
        return "try a smaller -k or mesh, or a shorter part of the song"
    return "try smaller inputs"


def main(argv=None) -> int:
    """Run one command.

    Parameters
    ----------
    argv : the arguments (default: sys.argv[1:]).

    Returns
    -------
    int, the exit status: 0 done, 1 bad input, 2 a bug, 130 interrupted (Ctrl-C), 143
    terminated (SIGTERM).
    """
    args = build_parser().parse_args(argv)
    previous = None
    if threading.current_thread() is threading.main_thread() and \
            signal.getsignal(signal.SIGTERM) == signal.SIG_DFL:
        previous = signal.signal(signal.SIGTERM, _terminate)
    streams = sys.stdout, sys.stderr
    sys.stdout, sys.stderr = Printable(sys.stdout, "\n\t"), Printable(sys.stderr, "\n\t\r")
    try:
        return _run(args)
    finally:
        sys.stdout, sys.stderr = streams
        if previous is not None:
            signal.signal(signal.SIGTERM, previous)


def _run(args) -> int:
    """Run the parsed command: its exit status, its error on one line."""
    try:
        with warnings.catch_warnings():
            if not os.environ.get("EIGENDANCE_DEBUG"):
                # Library warnings (numpy's floating-point ones, pygltflib's about odd files)
                # would only add lines around the one line a command ends with; outputs are
                # checked finite instead (writes.check_finite).
                warnings.simplefilter("ignore")
            warnings.simplefilter("always", ModelWarning)  # what a model file loses: one line
            warnings.showwarning = show_warning
            check_outputs(args)
            if args.command in SERVING:  # their writes are their own (a cache, a record)
                args.run(args)
            else:
                with all_or_nothing():  # a command that fails leaves none of its outputs
                    args.run(args)
    except InputError as error:
        print(f"eigendance: error: {error}{hint(error.remedy)}", file=sys.stderr)
        return 1
    except Terminated:
        print("eigendance: terminated", file=sys.stderr)
        return 143
    except KeyboardInterrupt:
        print("eigendance: interrupted", file=sys.stderr)
        return 130
    except MemoryError:
        print(f"eigendance: error: out of memory; {memory_advice(args)}", file=sys.stderr)
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
