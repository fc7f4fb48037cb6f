"""Part of a song: the clip from `start` for `duration` seconds (docs/design.md#window).

A window is checked once, here, for every caller (the command line's --start and --duration,
the server, the library): both finite, start ≥ 0 and before the song's end, duration > 0;
a window reaching past the end is clamped to it, with a note saying so. The clip's time t is
the song's time start + t: `Dance.window` moves a dance by it, and the song's audio is cut to
the same part (`export.song.cut_song`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from eigendance.checks import number
from eigendance.errors import InputError


@dataclass(frozen=True)
class Window:
    """A checked part of a song, in seconds.

    Parameters
    ----------
    start : where the clip starts in the song, s (≥ 0).
    duration : how long it lasts, s (> 0).
    note : what was changed to fit the song ("clamped to the song's end …"), or None.

    Example
    -------
    >>> clip = Window.of(10.0, 15.0, length=20.0)
    >>> clip.start, clip.duration, clip.note
    (10.0, 10.0, 'the song ends 10 s after 10 s: the clip lasts 10 s, not 15 s')
    """

    start: float = 0.0
    duration: float = math.inf
    note: str | None = None

    @classmethod
    def of(cls, start: float | None, duration: float | None, length: float,
           name: str = "the song") -> Window:
        """The window of `start` and `duration` within a song of `length` seconds.

        Parameters
        ----------
        start : s from the song's start (None: 0).
        duration : s (None: to the song's end).
        length : the song's duration, s (math.inf: no end, a rig moving without a song).
        name : how messages call the song.

        Returns
        -------
        Window, clamped to the song's end (with a `note`); InputError for a start that is not
        finite, negative or not before the end, or a duration that is not finite and positive.
        """
        start = 0.0 if start is None else number(start, "the start", 0.0)
        if duration is not None:
            duration = number(duration, "the duration", 0.0, above=True)
        if not start < length:
            raise InputError(f"{name} lasts {length:.3g} s: a clip cannot start at "
                             f"{start:g} s", remedy={"start": 0})
        left = length - start
        if duration is None:
            return cls(start, left)
        if duration > left:
            return cls(start, left, f"{name} ends {left:.3g} s after {start:g} s: the clip "
                                    f"lasts {left:.3g} s, not {duration:g} s")
        return cls(start, duration)
