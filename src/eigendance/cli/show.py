"""`eigendance show SET.toml` and the show options of the servers (docs/design.md#show)."""

from __future__ import annotations

from eigendance.cli.web import add_server_options, serve
from eigendance.server.serve import demo_paths
from eigendance.show.setlist import read_set


def add_show(parser):
    """The options of `eigendance show`.

    Parameters
    ----------
    parser : the command's parser.
    """
    parser.add_argument("set", metavar="SET.toml",
                        help="the set list: cues of a model, a song (or live input) and a "
                             "preset, each lasting N bars, to the next section, or until told "
                             "(see docs/design.md#show)")
    add_server_options(parser, 150, "harmonics per mesh basis")


def run_show(args) -> None:
    """`eigendance show`: the server in show mode; the control page at /, the output at /show.

    Parameters
    ----------
    args : the parsed command line.
    """
    setlist = read_set(args.set)
    # a set of live inputs only: the demo's music in the library too, so that the page starts
    # (its galleries are calibrated on a song) before the live input takes over
    songs = list if any(cue.song for cue in setlist.cues) else lambda: demo_paths()[1:]
    serve(args, songs, "eigendance show: control page {url}, output {url}show", setlist=setlist)
