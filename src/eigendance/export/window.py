"""Part of a song: a dance from `start` for `duration` seconds (docs/design.md#exports).

The clip a person posts is seldom the whole song. `window` gives a dance whose time 0 is the
song's time `start` and which lasts `duration`: every format samples it as it samples a whole
dance (t_i = i/fps from 0), the motion at clip time t is the whole dance's at start + t exactly
(the smoothing of the spectrogram and the framing poses are the whole song's, so the clip shows
what the player showed there), and a video's sound is the song's from `start` (`Dance.start`).
"""

from __future__ import annotations

import math

import numpy as np

from eigendance.errors import InputError
from eigendance.export.dance import Dance, HarmonicDance, RigDance


def check_window(start: float, duration: float | None, length: float) -> tuple[float, float]:
    """(start, duration) of a window of a song `length` seconds long: start in [0, length),
    duration > 0 (None: to the end), cut at the song's end. InputError otherwise."""
    for name, value in (("start", start), ("duration", duration)):
        if value is not None and not (isinstance(value, int | float) and math.isfinite(value)):
            raise InputError(f"{name} must be a number of seconds, got {value!r}")
    if not 0 <= start < length:
        raise InputError(f"start {start:g} s is outside the song (0 to {length:.2f} s)")
    if duration is not None and duration <= 0:
        raise InputError(f"duration must be positive, got {duration:g} s")
    end = length if duration is None else min(length, start + duration)
    return float(start), float(end - start)


class HarmonicWindow(HarmonicDance):
    """A `HarmonicDance` from `start` for `duration` seconds (module docstring)."""

    def __init__(self, whole: HarmonicDance, start: float, duration: float):
        super().__init__(whole.basis, whole.spectrogram, whole.mapping, whole.audio, whole.name)
        self.start, self.duration = start, duration
        self.info = {**whole.info, "start": start, "duration": duration}

    def phi(self, times) -> np.ndarray:
        return super().phi(np.asarray(times, dtype=np.float64) + self.start)

    def loudest_times(self, count: int) -> np.ndarray:
        return super().loudest_times(count) - self.start  # the song's: framed as the page frames

    def frames(self, times):
        yield from super().frames(np.asarray(times, dtype=np.float64) + self.start)


def window(dance: Dance, start: float, duration: float | None = None) -> Dance:
    """`dance` from `start` (s into the song) for `duration` seconds (None: to its end).

    Parameters
    ----------
    dance : a `HarmonicDance` or a `RigDance` of the whole song.
    start, duration : seconds; checked and cut at the song's end (`check_window`).

    Returns
    -------
    A dance of the same kind lasting `duration`, whose time t is the song's start + t.
    """
    start, duration = check_window(start, duration, dance.duration)
    if isinstance(dance, HarmonicDance):
        return HarmonicWindow(dance, start, duration)
    if isinstance(dance, RigDance):
        whole = dance.pose
        clip = RigDance(dance.rest, dance.faces, dance.weights,
                        lambda times: whole(np.asarray(times, dtype=np.float64) + start),
                        dance.rest_frames, dance.body_names, duration, dance.modal, dance.audio,
                        dance.name, {**dance.info, "start": start, "duration": duration})
        clip.start = start
        return clip
    raise InputError(f"cannot take part of a {type(dance).__name__}")
