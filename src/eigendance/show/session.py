"""A server's show: its presets, its set's cues in the library, OSC in and out, and Link
(docs/design.md#show).
"""

from __future__ import annotations

import contextlib
import sys

from eigendance.errors import InputError
from eigendance.presets.resample import fit_mapping
from eigendance.presets.store import PresetStore
from eigendance.show.link import LinkSync
from eigendance.show.osc import OscIn, OscOut, parse_address
from eigendance.show.setlist import SetList
from eigendance.show.state import ShowState


def cue_items(library, setlist: SetList) -> list[dict]:
    """Put every cue's model and song in the library.

    Parameters
    ----------
    library : the server's `Library`.
    setlist : the set.

    Returns
    -------
    list, per cue: {"model": {"kind": "mesh" or "rig", "id"}, "song": id or None}.
    """
    items = []
    for cue in setlist.cues:
        model = library.add_path(cue.model)
        kind = type(model).__name__.removesuffix("Item").lower()
        if kind not in ("mesh", "rig"):
            raise InputError(f"{cue.model}: cue '{cue.name}' needs a model (a mesh or a rig)")
        song = library.add_path(cue.song) if cue.song else None
        if song is not None and type(song).__name__ != "SongItem":
            raise InputError(f"{cue.song}: cue '{cue.name}' needs a song (WAV, MP3, Ogg, FLAC)")
        items.append({"model": {"kind": kind, "id": model.id},
                      "song": None if song is None else song.id})
    return items


def favourite_slots(store: PresetStore, setlist: SetList | None):
    """The presets on the keys 1–9: the set's slots, else the favourites by name.

    Parameters
    ----------
    store : the presets.
    setlist : the set, or None.

    Returns
    -------
    () → list of preset names.
    """
    def slots() -> list[str]:
        if setlist is not None and setlist.slots:
            return setlist.slots
        return [p["name"] for p in store.listing(favourites=True)][:9]
    return slots


@contextlib.contextmanager
def show_session(library, presets: str, setlist: SetList | None = None,
                 osc: int | None = None, osc_host: str = "127.0.0.1",
                 osc_out: str | None = None, link: str | None = None):
    """The presets and show state a server gives its app, with OSC and Link running.

    Parameters
    ----------
    library : the server's `Library` (the cues' files are added to it).
    presets : the presets folder.
    setlist : the set of `eigendance show`, or None.
    osc : the UDP port OSC comes in on (None: no OSC in).
    osc_host : the address it listens on.
    osc_out : HOST:PORT to send the analysis to (None: none).
    link : "follow" or "lead" an Ableton Link session (None: no Link).

    Yields
    ------
    (PresetStore, ShowState).
    """
    store = PresetStore(presets)
    items = cue_items(library, setlist) if setlist else []
    state = ShowState(setlist, items, favourite_slots(store, setlist))
    running = []
    try:
        if osc is not None:
            running.append(OscIn(state, osc_host, osc))
            print(f"eigendance: OSC in on {osc_host}:{running[-1].port}", file=sys.stderr)
        if osc_out is not None:
            host, port = parse_address(osc_out)
            running.append(OscOut(state, host, port, lambda song: spectrogram_of(library, song),
                                  ModeAmplitudes(library, state, store)))
        if link is not None:
            running.append(LinkSync(state, link))
        yield store, state
    finally:
        for part in running:
            part.stop()


def spectrogram_of(library, song_id: str):
    """The spectrogram of a library song, or None (removed, not decoded yet).

    Parameters
    ----------
    library : the `Library`.
    song_id : its id.

    Returns
    -------
    Spectrogram or None.
    """
    item = library.get("song", song_id)
    return None if item is None else item.spectrogram


class ModeAmplitudes:
    """The mode coefficients c_κ(t) of the rig the show plays (OSC out's /eigendance/modes):
    the current cue's rig with the show's preset (its palette fitted by rank), computed for the
    whole song once per rig, edit, preset and song.

    Parameters
    ----------
    library : the `Library`.
    state : the show.
    store : the presets.
    """

    def __init__(self, library, state: ShowState, store: PresetStore):
        self.library, self.state, self.store = library, state, store
        self.key, self.coefficients = None, None

    def __call__(self, song: str, t: float):
        """c(t) of the rig on screen, or None (a mesh, no set, nothing analysed yet).

        Parameters
        ----------
        song : the song's id.
        t : the song time, s.

        Returns
        -------
        (modes,) float64 or None.
        """
        state = self.state
        if state.cue is None or state.cue >= len(state.items):
            return None
        model = state.items[state.cue]["model"]
        item = self.library.get("rig", model["id"]) if model["kind"] == "rig" else None
        spectrogram = spectrogram_of(self.library, song)
        if item is None or item.rig is None or spectrogram is None:
            return None
        key = (model["id"], item.revision, state.preset, song)
        if key != self.key:
            mapping = None
            if state.preset is not None:
                try:
                    mapping = self.store.load(state.preset).mapping
                except InputError:
                    return None  # said by the page that plays it
                mapping = fit_mapping(mapping, None, None, item.rig.model.n_modes)
            self.coefficients = item.rig.coefficients(spectrogram, mapping, spectrogram.times)
            self.key = key
        frame = min(len(self.coefficients) - 1, max(0, round(t * spectrogram.rate)))
        return self.coefficients[frame]
