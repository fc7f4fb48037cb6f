"""--surface: a rig's skin ripples in its harmonics while its bones sway
(docs/design.md#surface-of-a-rig), for `animate-rig`, `export --rig` and `render`."""

from __future__ import annotations

from dataclasses import replace

from eigendance.cli.options import number
from eigendance.errors import InputError
from eigendance.inputs.mapping import read_mapping
from eigendance.inputs.song import read_song
from eigendance.modal.rig import Rig
from eigendance.modal.surface import SURFACE_K, SurfaceDance
from eigendance.music.gallery import strongest_item
from eigendance.music.mapping import Mapping
from eigendance.music.spectrogram import Spectrogram

AUTO = "auto"  # --surface auto: the initial-gallery item that ripples the skin most


def add_surface_options(parser) -> None:
    """--surface MAPPING, --surface-gain and --surface-k.

    Parameters
    ----------
    parser : the command's parser.
    """
    parser.add_argument("--surface", metavar="MAPPING",
                        help="a rig's skin also ripples in its harmonics, driven by this "
                             "surface mapping (JSON, e.g. saved from a mesh's gallery), or "
                             "'auto': the initial-gallery item that ripples it most on the song")
    parser.add_argument("--surface-gain", type=number(0, 1e6), default=1.0,
                        help="multiply the surface mapping's gain: the surface's share of the "
                             "motion (default 1)")
    parser.add_argument("--surface-k", type=number(1, 20000, integer=True), default=SURFACE_K,
                        help=f"harmonics of the rig's skin (default {SURFACE_K})")


def surface_of(args, rig: Rig, spectrogram: Spectrogram | None,
               dance: Mapping | None = None) -> SurfaceDance | None:
    """The skin's ripple the command line asks for: --surface, else the surface genes of the
    rig's mapping (`Mapping.surface`); None without either.

    Parameters
    ----------
    args : the parsed command line (surface, surface_gain, surface_k, audio).
    rig : the rig.
    spectrogram : the song the bones dance to (its bands serve a mapping of as many), or None.
    dance : the rig's mapping (its surface genes play unless --surface is given), or None.

    Returns
    -------
    SurfaceDance or None; InputError without a song.
    """
    genes = None if dance is None else dance.surface
    if not getattr(args, "surface", None) and genes is None:
        return None
    if spectrogram is None or not getattr(args, "audio", None):
        raise InputError("--surface needs a song (AUDIO): the surface mapping plays its bands")
    harmonics = rig.surface(args.surface_k)
    if not getattr(args, "surface", None):
        mapping = replace(genes)
    elif args.surface == AUTO:
        mapping = strongest_item(harmonics.basis, spectrogram)
    else:
        mapping = read_mapping(args.surface)
    if mapping.bands != spectrogram.bands:
        spectrogram = read_song(args.audio, mapping.bands)
    mapping.gain *= args.surface_gain
    return SurfaceDance(harmonics, spectrogram, mapping)
