"""What a show is doing now: the one state keys, clicks, MIDI and OSC change (docs/design.md#show).

Every control goes through `ShowState.act(action, value)` (the control page's POST, an OSC
message, a Link peer); the pages follow the state (`GET /api/show/state`, its events) and the
output page applies a change of cue or preset on the next downbeat. `version` counts the
changes, so a page waits for a larger one.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable

from eigendance.errors import InputError
from eigendance.files import finite_number
from eigendance.presets.store import check_name
from eigendance.show.beat_clock import BeatGrid, grid_from_taps
from eigendance.show.live_out import LiveHeard
from eigendance.show.setlist import SetList

GAIN_RANGE = (0.0, 8.0)
TAP_GAP = 2.0  # s: a longer pause between taps starts a new count
TEMPO_RANGE = (20.0, 400.0)
CONTROL_ID_LENGTH = 64


def _number(value, what: str, low: float, high: float) -> float:
    if isinstance(value, bool) or not isinstance(value, int | float) or not finite_number(value) \
            or not low <= value <= high:
        raise InputError(f"{what} must be a number in [{low:g}, {high:g}]")
    return float(value)


def _flag(value, current: bool) -> bool:
    if value is None:
        return not current
    if not isinstance(value, bool | int) or value not in (0, 1):
        raise InputError("give true, false or nothing (to toggle)")
    return bool(value)


class ShowState:
    """The show's state, shared by the routes, the OSC thread and Link (thread-safe).

    Parameters
    ----------
    setlist : the set (None: `serve` with OSC, no cues).
    items : per cue, the library ids the pages load: {"model": {"kind", "id"}, "song": id}.
    slots : () → the presets on the keys 1–9 (the set's slots, else the favourites).
    clock : the time source (time.monotonic).
    """

    def __init__(self, setlist: SetList | None = None, items: list[dict] | None = None,
                 slots: Callable[[], list[str]] = list, clock=time.monotonic):
        self.lock = threading.Lock()
        self.setlist, self.items, self.slots, self.clock = setlist, items or [], slots, clock
        cues = setlist.cues if setlist else []
        self.cue = 0 if cues else None
        self.preset = cues[0].preset if cues else None
        self.gain, self.playing, self.blackout = 1.0, False, False
        self.loop_set = bool(setlist and setlist.loop)
        self.loop_cue = [cue.loop for cue in cues]
        self.fade_beats = cues[0].fade_beats if cues else 4.0
        self.tempo: float | None = None
        self.taps: list[float] = []
        self.tap_count = 0  # taps in this count (the kept `taps` are its last eight)
        self.grid: BeatGrid | None = None  # the show's own beat clock (show.beat_clock)
        self.controls: dict[str, float] = {}
        self.song_clock: dict | None = None  # the output page's {song, time, at, playing}
        self.live = LiveHeard()  # a live input's events, as the output page reports them
        self.version = 0

    # -- actions --------------------------------------------------------------------------------

    def act(self, action: str, value=None) -> dict:
        """Do one control action and count the change.

        Parameters
        ----------
        action : "next", "prev", "cue" (value: index), "gain" (value: 0–8), "preset" (value: a
            name), "slot" (value: 1–9), "tap", "play", "stop", "toggle", "blackout", "loop_cue",
            "loop_set" (value: bool, or None to toggle), "fade" (value: beats), "tempo" (value:
            BPM), "auto" (back to the song's own beats: forget the taps and typed tempo),
            "control" (value: {"id", "value"}: one slider or switch of the page).
            "next" and "prev" take value {"from": index}: only from that cue (the output page
            ending a cue, once however many pages follow).
        value : as above.

        Returns
        -------
        dict, the new state (`snapshot`); InputError (400) for an unknown action or value.
        """
        handler = getattr(self, f"_{action}", None) if isinstance(action, str) and \
            action.isidentifier() and not action.startswith("_") else None
        if handler is None:
            raise InputError(f"unknown show action {str(action)[:40]!r}")
        with self.lock:
            handler(value)
            self.version += 1
        return self.snapshot()

    def _move(self, step: int, value) -> None:
        if self.cue is None:
            raise InputError("this server has no set list (start it with eigendance show SET)")
        if isinstance(value, dict) and value.get("from") not in (None, self.cue):
            return  # another page ended that cue already
        count = len(self.setlist.cues)
        target = self.cue + step
        if not 0 <= target < count:
            target = target % count if self.loop_set else self.cue
        self._go(target)

    def _go(self, index: int) -> None:
        self.cue = index
        self.preset = self.setlist.cues[index].preset
        self.fade_beats = self.setlist.cues[index].fade_beats

    def _next(self, value) -> None:
        self._move(1, value)

    def _prev(self, value) -> None:
        self._move(-1, value)

    def _cue(self, value) -> None:
        if self.cue is None:
            raise InputError("this server has no set list")
        if isinstance(value, bool) or not isinstance(value, int) or \
                not 0 <= value < len(self.setlist.cues):
            raise InputError(f"cue must be an index 0–{len(self.setlist.cues) - 1}")
        self._go(value)

    def _gain(self, value) -> None:
        self.gain = _number(value, "gain", *GAIN_RANGE)

    def _preset(self, value) -> None:
        self.preset = check_name(value)

    def _slot(self, value) -> None:
        slot = int(_number(value, "slot", 1, 9))
        slots = self.slots()
        if slot > len(slots):
            raise InputError(f"no preset on slot {slot} (mark favourites, or list slots in the "
                             "set)")
        self.preset = slots[slot - 1]

    def _tap(self, value) -> None:
        now = self.clock()
        if self.taps and now - self.taps[-1] > TAP_GAP:
            self.taps, self.tap_count = [], 0
        self.taps = [*self.taps[-7:], now]
        self.tap_count += 1
        grid = grid_from_taps(self.taps, self.tap_count - len(self.taps))
        if grid is not None:
            bpm = min(max(grid.bpm, TEMPO_RANGE[0]), TEMPO_RANGE[1])
            self.grid = BeatGrid(bpm, grid.anchor, grid.beats_per_bar, "tap")
            self.tempo = bpm

    def _tempo(self, value) -> None:
        self.tempo = _number(value, "tempo", *TEMPO_RANGE)
        now = self.clock()
        self.grid = self.grid.with_bpm(self.tempo, now) if self.grid else BeatGrid(self.tempo, now)

    def _auto(self, value) -> None:
        self.grid, self.taps, self.tap_count, self.tempo = None, [], 0, None

    def set_grid(self, grid: BeatGrid) -> bool:
        """Take a beat clock from elsewhere (a Link session), counted as a change only when it
        differs (`BeatGrid.differs`): pages are told of a new tempo or phase, not of each look.

        Parameters
        ----------
        grid : the new grid.

        Returns
        -------
        bool, whether it changed.
        """
        with self.lock:
            if not grid.differs(self.grid):
                return False
            self.grid, self.tempo = grid, grid.bpm
            self.version += 1
        return True

    def _play(self, value) -> None:
        self.playing = True

    def _stop(self, value) -> None:
        self.playing = False

    def _toggle(self, value) -> None:
        self.playing = not self.playing

    def _blackout(self, value) -> None:
        self.blackout = _flag(value, self.blackout)

    def _loop_set(self, value) -> None:
        self.loop_set = _flag(value, self.loop_set)

    def _loop_cue(self, value) -> None:
        if self.cue is None:
            raise InputError("this server has no set list")
        self.loop_cue[self.cue] = _flag(value, self.loop_cue[self.cue])

    def _fade(self, value) -> None:
        self.fade_beats = _number(value, "fade", 0, 64)

    def _control(self, value) -> None:
        if not isinstance(value, dict) or not isinstance(value.get("id"), str) or \
                not value["id"].replace("-", "").isalnum() or \
                len(value["id"]) > CONTROL_ID_LENGTH:
            raise InputError("control takes {\"id\": a control's id, \"value\": a number}")
        self.controls[value["id"]] = _number(value.get("value"), "control value", -1e6, 1e6)

    # -- the output page's clock ------------------------------------------------------------------

    def heard(self, song, song_time: float, playing: bool, tempo=None, age: float = 0.0) -> None:
        """The output page's clock: song time `song_time` is drawn now (OSC out follows it).

        Parameters
        ----------
        song : the song's library id (None: a live input).
        song_time : the song time drawn, s.
        playing : whether it plays.
        tempo : the song's tempo, BPM (reported as the show's tempo when nobody tapped).
        age : how long ago the page drew it, s (its report's time on the way).
        """
        with self.lock:
            self.song_clock = {"song": song, "time": float(song_time), "at": self.clock() - age,
                               "playing": bool(playing)}
            if tempo is not None and self.grid is None and finite_number(tempo) and tempo > 0:
                self.tempo = float(tempo)

    # -- what the pages see ---------------------------------------------------------------------

    def snapshot(self) -> dict:
        """The state as `GET /api/show/state` answers it.

        Returns
        -------
        dict: set, cues, cue, next, preset, gain, playing, tempo, grid (the show's beat clock:
        {bpm, beats_per_bar, source, downbeat: a downbeat's time, ms since 1970}, or None),
        blackout, loop_cue, loop_set, fade_beats, controls, version.
        """
        with self.lock:
            cues = self.setlist.cues if self.setlist else []
            following = None
            if self.cue is not None:
                following = self.cue + 1 if self.cue + 1 < len(cues) else (
                    0 if self.loop_set else None)
            return {"set": self.setlist.name if self.setlist else None,
                    "cues": [{**cue.as_json(), **self._items(i), "loop": self.loop_cue[i]}
                             for i, cue in enumerate(cues)],
                    "cue": self.cue, "next": following, "preset": self.preset,
                    "gain": self.gain, "playing": self.playing, "tempo": self.tempo,
                    "grid": self._grid_json(),
                    "blackout": self.blackout, "loop_set": self.loop_set,
                    "loop_cue": None if self.cue is None else self.loop_cue[self.cue],
                    "fade_beats": self.fade_beats,
                    "controls": dict(self.controls), "version": self.version}

    def _grid_json(self) -> dict | None:
        grid = self.grid
        if grid is None:
            return None
        wall = time.time() + grid.anchor - self.clock()  # the page's clock: ms since 1970
        return {"bpm": grid.bpm, "beats_per_bar": grid.beats_per_bar, "source": grid.source,
                "downbeat": wall * 1000.0}

    def _items(self, index: int) -> dict:
        return self.items[index] if index < len(self.items) else {}
