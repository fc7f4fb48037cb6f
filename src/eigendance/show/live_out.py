"""What a live input heard, as the output page reports it, for OSC out (docs/design.md#show).

The page analyses a live input itself (web/src/live-*.ts): its beats, onsets, tempo and band
values reach the server with the page's clock (`POST /api/show/clock`, its `live`), as soon as
the page has them. They are queued here in the take's time until OSC out's clock (the time the
page draws) reaches them; an event that comes after the picture showed it goes at once. A new
take (another `take` id) starts the queues again.
"""

from __future__ import annotations

import threading
from collections import deque

from eigendance.errors import InputError
from eigendance.files import finite_number

MAX_EVENTS = 256  # per report
MAX_BANDS = 64  # frames per report
BANDS = 64
KEPT = 4096  # queued events or frames at most (a page that reports but draws nothing)


def _times(values, what: str) -> list[float]:
    if not isinstance(values, list) or len(values) > MAX_EVENTS or not all(
            finite_number(v) and not isinstance(v, bool) and v >= 0 for v in values):
        raise InputError(f"live.{what} must be a list of at most {MAX_EVENTS} times ≥ 0 s")
    return [float(v) for v in values]


def _beats(values) -> list[tuple[int, float]]:
    if not isinstance(values, list) or len(values) > MAX_EVENTS or not all(
            isinstance(v, list) and len(v) == 2 and isinstance(v[0], int)
            and not isinstance(v[0], bool) and 0 <= v[0] < 2**31 and finite_number(v[1])
            and not isinstance(v[1], bool) and v[1] >= 0 for v in values):
        raise InputError(f"live.beats must be a list of at most {MAX_EVENTS} [index, time]")
    return [(v[0], float(v[1])) for v in values]


def _bands(values) -> list[tuple[float, list[float]]]:
    if not isinstance(values, list) or len(values) > MAX_BANDS or not all(
            isinstance(v, list) and len(v) == 2 and finite_number(v[0]) and v[0] >= 0
            and isinstance(v[1], list) and len(v[1]) == BANDS
            and all(finite_number(b) and not isinstance(b, bool) for b in v[1])
            for v in values):
        raise InputError(f"live.bands must be a list of at most {MAX_BANDS} [time, "
                         f"[{BANDS} numbers]]")
    return [(float(v[0]), [float(b) for b in v[1]]) for v in values]


class LiveHeard:
    """The queues of a live take's events, filled by the page's reports, emptied by OSC out."""

    def __init__(self):
        self.lock = threading.Lock()
        self.take = None
        self.beats: deque = deque(maxlen=KEPT)
        self.onsets: deque = deque(maxlen=KEPT)
        self.bands: deque = deque(maxlen=KEPT)

    def report(self, data) -> None:
        """Queue one report of the page.

        Parameters
        ----------
        data : {"take": the take's id (a number or a string), "beats": [[index, time]],
            "onsets": [time], "bands": [[time, [64 values]]]}, times in the take's seconds.
            InputError (400) for anything else.
        """
        if not isinstance(data, dict) or not isinstance(data.get("take"), int | float | str) \
                or isinstance(data.get("take"), bool):
            raise InputError("live must be {\"take\", \"beats\", \"onsets\", \"bands\"}")
        beats, onsets = _beats(data.get("beats", [])), _times(data.get("onsets", []), "onsets")
        bands = _bands(data.get("bands", []))
        with self.lock:
            if data["take"] != self.take:
                self.take = data["take"]
                self.beats.clear(), self.onsets.clear(), self.bands.clear()
            self.beats.extend(beats)
            self.onsets.extend(onsets)
            self.bands.extend(bands)

    def due(self, t: float) -> tuple[list, list, list | None]:
        """Take the events the picture reached: those at or before t.

        Parameters
        ----------
        t : the take's time drawn now, s.

        Returns
        -------
        (beats [(index, time)], onsets [time], the newest band values at or before t or
        None).
        """
        with self.lock:
            beats = _until(self.beats, t, lambda beat: beat[1])
            onsets = _until(self.onsets, t, lambda onset: onset)
            frames = _until(self.bands, t, lambda frame: frame[0])
        return beats, onsets, frames[-1][1] if frames else None


def _until(queue: deque, t: float, time_of) -> list:
    out = []
    while queue and time_of(queue[0]) <= t:
        out.append(queue.popleft())
    return out
