"""Ableton Link (aalink, an optional extra: `pip install eigendance[link]`; docs/design.md#show).

`follow`: the show's tempo is the Link session's (another program leads). `lead`: the show's
tempo (tapped, set, or the song's) becomes the session's. Link runs on an asyncio loop of its
own in a daemon thread; the show's state is read and changed through `ShowState.act`.
"""

from __future__ import annotations

import asyncio
import threading

from eigendance.errors import InputError
from eigendance.show.state import ShowState

MODES = ("follow", "lead")
POLL = 0.05  # s between looks at the session's tempo
CHANGE = 0.01  # BPM: smaller differences are the same tempo


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
    """A Link peer that follows or leads the show's tempo.

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
        self.thread = threading.Thread(target=self._run, name="link", daemon=True)
        self.thread.start()
        self.ready.wait(5)

    def _run(self) -> None:
        asyncio.set_event_loop(self.loop)
        self.loop.run_until_complete(self._follow())

    async def _follow(self) -> None:
        self.link = self.Link(self.state.tempo or 120.0)  # on this thread's running loop
        self.link.enabled = True
        self.ready.set()
        while not self.stopping.is_set():
            ours, theirs = self.state.tempo, float(self.link.tempo)
            if ours is None or abs(ours - theirs) > CHANGE:
                if self.mode == "follow" or ours is None:
                    self.state.act("tempo", min(max(theirs, 20.0), 400.0))
                else:
                    self.link.tempo = ours
            await asyncio.sleep(POLL)
        self.link.enabled = False

    @property
    def peers(self) -> int:
        """How many other Link peers are in the session."""
        return 0 if self.link is None else int(self.link.num_peers)

    def stop(self) -> None:
        """Leave the session."""
        self.stopping.set()
        self.thread.join(2)
