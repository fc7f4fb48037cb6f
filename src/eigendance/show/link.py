"""Ableton Link (aalink, an optional extra: `pip install eigendance[link]`; docs/design.md#show).

`follow`: the show's beat clock is the Link session's, tempo and phase (another program
leads): its beats and downbeats (quantum = the bar's beats) are the ones cue changes,
crossfades and the dance's beat lock follow; a tap changes the session's tempo, as any Link
peer may. `lead`: the show's beat clock (tapped or typed) becomes the session's, tempo and
phase (its downbeat on the session's bar); without one, the song's tempo. Link runs on an
asyncio loop of its own in a daemon thread; the show's state is read and changed through
`ShowState`.
"""

from __future__ import annotations

import asyncio
import threading

from eigendance.errors import InputError
from eigendance.show.beat_clock import BEATS_PER_BAR, BeatGrid
from eigendance.show.state import TEMPO_RANGE, ShowState

MODES = ("follow", "lead")
POLL = 0.05  # s between looks at the session
CHANGE = 0.01  # BPM: smaller differences are the same tempo
PHASE = 0.005  # s: a lead's phase further off the session's is forced on it


def link_class():
    """aalink's `Link`, or an InputError saying how to install it.

    Returns
    -------
    type.
    """
    try:
        from aalink import Link  # optional extra: only `--link` needs it
    except ImportError:
        raise InputError("--link needs aalink: pip install 'eigendance[link]'") from None
    return Link


class LinkSync:
    """A Link peer that follows or leads the show's beat clock.

    Parameters
    ----------
    state : the show.
    mode : "follow" or "lead".
    """

    def __init__(self, state: ShowState, mode: str):
        if mode not in MODES:
            raise InputError(f"--link must be one of {', '.join(MODES)}")
        self.state, self.mode, self.Link = state, mode, link_class()
        self.loop = asyncio.new_event_loop()
        self.stopping = threading.Event()
        self.ready = threading.Event()
        self.link = None
        self.sent: BeatGrid | None = None  # the tapped grid last given to the session
        self.thread = threading.Thread(target=self._run, name="link", daemon=True)
        self.thread.start()
        self.ready.wait(5)

    def _run(self) -> None:
        asyncio.set_event_loop(self.loop)
        self.loop.run_until_complete(self._session())

    async def _session(self) -> None:
        self.link = self.Link(self.state.tempo or 120.0)  # on this thread's running loop
        self.link.quantum = BEATS_PER_BAR
        self.link.enabled = True
        self.ready.set()
        while not self.stopping.is_set():
            if self.mode == "follow":
                self._follow()
            else:
                self._lead()
            await asyncio.sleep(POLL)
        self.link.enabled = False

    def _follow(self) -> None:
        link, grid = self.link, self.state.grid
        if grid is not None and grid.source == "tap" and grid is not self.sent:
            link.tempo = grid.bpm  # tapped here: the session's new tempo
            self.sent = grid
        bpm = min(max(float(link.tempo), TEMPO_RANGE[0]), TEMPO_RANGE[1])
        beat, now = float(link.beat), self.state.clock()  # read together: beat b is now
        self.state.set_grid(BeatGrid(bpm, now - beat * 60.0 / bpm, BEATS_PER_BAR, "link"))

    def _lead(self) -> None:
        link, grid, ours = self.link, self.state.grid, self.state.tempo
        if grid is not None:
            # the session's tempo and phase are the show's: set again when they drift (another
            # peer, or a session met that kept its own)
            if abs(grid.bpm - float(link.tempo)) > CHANGE:
                link.tempo = grid.bpm
            phase, now = float(link.phase), self.state.clock()
            ahead = (phase - grid.beat_at(now)) % BEATS_PER_BAR
            if min(ahead, BEATS_PER_BAR - ahead) * grid.period > PHASE:
                link.force_beat(grid.beat_at(self.state.clock()))
        elif ours is not None and abs(ours - float(link.tempo)) > CHANGE:
            link.tempo = ours  # the song's tempo (its phase is the page's: not sent)

    @property
    def peers(self) -> int:
        """How many other Link peers are in the session."""
        return 0 if self.link is None else int(self.link.num_peers)

    def stop(self) -> None:
        """Leave the session."""
        self.stopping.set()
        self.thread.join(2)
