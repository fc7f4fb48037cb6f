"""The web app's commands: `serve` and `demo` (docs/design.md#server)."""

from __future__ import annotations

import sys

from eigendance.cli.options import HARMONICS, PORT, add_construction, number, say_note
from eigendance.cli.presets import add_presets_folder, presets_folder
from eigendance.inputs.defaults import DEFAULT_K
from eigendance.inputs.mapping import read_mapping, shared_choice
from eigendance.inputs.model import classify
from eigendance.server.app import create_app
from eigendance.server.guard import exposure_warning
from eigendance.server.serve import (
    DEFAULT_HOST,
    DEFAULT_PORT,
    demo_paths,
    library_session,
    listen,
    run,
    terminal_progress,
)
from eigendance.show.link import MODES
from eigendance.show.session import show_session


def add_server_options(parser, k_help: str, k_help2: str = "") -> None:
    """The options `serve` and `demo` share: where to listen, -k and the limits.

    Parameters
    ----------
    parser : the command's parser.
    k_help : what -k is for, for --help.
    k_help2 : what its default is before `DEFAULT_K`, for --help.
    """
    parser.add_argument("--host", default=DEFAULT_HOST,
                        help=f"address to listen on (default {DEFAULT_HOST}: this machine only; "
                             "another address lets other machines use the server, with no "
                             "password)")
    parser.add_argument("--port", type=PORT, default=DEFAULT_PORT,
                        help=f"port (default {DEFAULT_PORT}; 0: any free port)")
    parser.add_argument("-k", type=HARMONICS, default=None, help=f"{k_help} (default {k_help2}"
                        f"{DEFAULT_K})")
    parser.add_argument("--max-upload-mb", type=number(1, 4096, integer=True), default=64,
                        help="largest file a page may upload, MiB (default 64)")
    parser.add_argument("--max-memory-mb", type=number(16, 1 << 22, integer=True), default=4096,
                        help="memory the library's meshes, songs and rigs may keep, MiB; the "
                             "least recently used are removed beyond it (default 4096)")
    add_construction(parser)
    add_show_options(parser)


def add_serve(parser):
    """The options of `eigendance serve`.

    Parameters
    ----------
    parser : the command's parser.
    """
    parser.add_argument("files", nargs="*", metavar="MESH|AUDIO|MAPPING|RIG",
                        help="meshes (OBJ, PLY, OFF, STL, glTF), audio (WAV, MP3, Ogg, FLAC), "
                             "mapping JSON and skeleton JSON files to put in the library (a "
                             "glTF with a skin is a rig too; the built-in rigs are always "
                             "there)")
    add_server_options(parser, "harmonics per mesh basis",
                       "the k the MAPPING files were made on, else ")


def run_serve(args) -> None:
    """`eigendance serve`: the web app with the given files in its library.

    Parameters
    ----------
    args : the parsed command line.
    """
    serve(args, lambda: args.files, "eigendance: serving on {url}")


def add_demo(parser):
    """The options of `eigendance demo`.

    Parameters
    ----------
    parser : the command's parser.
    """
    add_server_options(parser, "harmonics of the demo mesh")


def run_demo(args) -> None:
    """`eigendance demo`: the web app with the built-in cat and music.

    Parameters
    ----------
    args : the parsed command line.
    """
    serve(args, demo_paths, "eigendance demo: open {url} in a browser")


def serve(args, paths, announce: str, setlist=None) -> None:
    """Listen, fill a temporary library with the files of paths() and serve it until interrupted;
    the library's folder is removed at the end (docs/design.md#server).

    Parameters
    ----------
    args : the parsed command line (--host, --port, -k, the limits).
    paths : () → the files to put in the library.
    announce : the line printed once it serves, with {url}.
    setlist : the set of `eigendance show` (None: no cues; OSC and /show still work).
    """
    listening = listen(args.host, args.port)
    port = listening.getsockname()[1]
    files = paths()
    mappings = [read_mapping(path) for path in files if classify(path)[0] == "mapping"]
    choice, notes = shared_choice(mappings, args.k, args.construction)  # as they were made
    for note in notes:
        say_note("eigendance", note)
    if warning := exposure_warning(args.host):
        print(warning, file=sys.stderr)
    with library_session(k=choice.k, max_upload_bytes=args.max_upload_mb << 20,
                         memory_budget=args.max_memory_mb << 20,
                         construction=choice.construction, samples=choice.samples) as library:
        terminal_progress(library)
        for path in files:
            library.add_path(path)
        with show_session(library, presets_folder(args), setlist, args.osc, args.osc_host,
                          args.osc_out, args.link) as (presets, show):
            app = create_app(library, args.host, port, presets, show)
            run(app, listening, on_exit=library.stop,
                announce=announce.format(url=url(args.host, port)))


def url(host: str, port: int) -> str:
    """The URL a browser opens for a server listening on host:port.

    Parameters
    ----------
    host : the address listened on ("0.0.0.0": any, shown as 127.0.0.1).
    port : the port.

    Returns
    -------
    str, e.g. "http://127.0.0.1:8765/".
    """
    shown = "127.0.0.1" if host in ("0.0.0.0", "") else host
    shown = f"[{shown}]" if ":" in shown else shown
    return f"http://{shown}:{port}/"


def add_show_options(parser) -> None:
    """OSC in and out, Ableton Link and the presets folder, for `serve`, `demo` and `show`.

    Parameters
    ----------
    parser : the command's parser.
    """
    parser.add_argument("--osc", type=PORT, metavar="PORT", default=None,
                        help="listen for OSC control messages on this UDP port "
                             "(/eigendance/gain f, /preset s, /next, /prev, /tap, /play, /stop, "
                             "/control/ID f)")
    parser.add_argument("--osc-host", default="127.0.0.1",
                        help="address OSC listens on (default 127.0.0.1: this machine only)")
    parser.add_argument("--osc-out", metavar="HOST:PORT", default=None,
                        help="send what the dance hears as OSC: /eigendance/beat, /downbeat, "
                             "/onset, /tempo, /bands")
    parser.add_argument("--link", choices=MODES, default=None,
                        help="join an Ableton Link session: follow its tempo, or lead it "
                             "(needs pip install 'eigendance[link]')")
    add_presets_folder(parser)
