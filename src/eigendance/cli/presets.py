"""`--preset NAME` and `--presets DIR` for the commands that play a mapping (animate, export,
render, batch) and the servers (docs/design.md#presets)."""

from __future__ import annotations

import os
import re

from eigendance.batch.plan import Item
from eigendance.errors import InputError
from eigendance.inputs.mapping import read_mapping
from eigendance.music.mapping import Mapping
from eigendance.presets.resample import fit_mapping
from eigendance.presets.store import PresetStore, default_folder


def add_presets_folder(parser) -> None:
    """--presets DIR.

    Parameters
    ----------
    parser : the command's parser.
    """
    parser.add_argument("--presets", metavar="DIR", default=None,
                        help="the presets folder (default: $EIGENDANCE_PRESETS_DIR, else "
                             f"{default_folder()})")


def add_preset_options(parser) -> None:
    """--preset NAME (instead of --mapping) and --presets DIR.

    Parameters
    ----------
    parser : the command's parser.
    """
    parser.add_argument("--preset", metavar="NAME",
                        help="play this preset (saved in the page or by POST /api/presets) "
                             "instead of a mapping file; fitted to the model by harmonic "
                             "frequency (a mesh) or mode rank (a rig)")
    add_presets_folder(parser)


def presets_folder(args) -> str:
    """The folder --presets names, else the default.

    Parameters
    ----------
    args : the parsed command line.

    Returns
    -------
    str.
    """
    return args.presets or default_folder()


def mapping_option(args) -> Mapping | None:
    """The mapping --mapping or --preset names (None: neither); the preset's model's eigenvalues
    are kept on args for `fitted`.

    Parameters
    ----------
    args : the parsed command line.

    Returns
    -------
    Mapping or None; InputError when both are given or the preset is missing.
    """
    args.preset_eigenvalues = None
    given = getattr(args, "mapping", None)  # batch has no --mapping
    if getattr(args, "preset", None) is None:
        return read_mapping(given) if given else None
    if given:
        raise InputError("give --mapping or --preset, not both")
    preset = PresetStore(presets_folder(args)).load(args.preset)
    args.preset_eigenvalues = preset.eigenvalues
    return preset.mapping


def fitted(args, mapping: Mapping | None, basis=None, mode_count: int | None = None):
    """A --preset's mapping fitted to the model it plays on (else `mapping` unchanged).

    Parameters
    ----------
    args : the parsed command line (after `mapping_option`).
    mapping : the mapping, or None.
    basis : the mesh's `HarmonicBasis`, or None.
    mode_count : the rig's number of modes, or None.

    Returns
    -------
    Mapping or None.
    """
    if mapping is None or getattr(args, "preset", None) is None:
        return mapping
    return fit_mapping(mapping, getattr(args, "preset_eigenvalues", None),
                       None if basis is None else basis.eigenvalues, mode_count)


def preset_items(args) -> list[Item] | None:
    """A batch's items when --preset replaces the plan's gallery or mappings.

    Parameters
    ----------
    args : the parsed command line.

    Returns
    -------
    [Item] playing the preset, or None without --preset.
    """
    if getattr(args, "preset", None) is None:
        return None
    mapping = mapping_option(args)
    name = re.sub(r"[^\w.-]+", "_", args.preset).strip("_") or "preset"
    path = os.path.join(presets_folder(args), args.preset + ".json")
    return [Item(name, mapping=mapping, path=path)]
