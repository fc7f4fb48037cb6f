"""The show's own beat clock (docs/design.md#show): a tempo and a phase that tapping, a typed
tempo or an Ableton Link session set, which cue changes, crossfades and the dance's beat lock
follow instead of a song's beats.

A grid is beats at `anchor + i·60/bpm` (times on the show's clock, `time.monotonic`), every
`beats_per_bar`-th from the anchor a downbeat (Link's quantum). Taps are fitted by least
squares: beat i of a count of taps at t_i ≈ a + i·p, the count's first tap a downbeat.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

BEATS_PER_BAR = 4  # a tapped count's bar, and Link's quantum (the page's BEATS_PER_BAR)


@dataclass(frozen=True)
class BeatGrid:
    """A tempo and a phase.

    Parameters
    ----------
    bpm : beats per minute.
    anchor : when a downbeat falls, on the show's clock (s).
    beats_per_bar : beats from one downbeat to the next.
    source : "tap" (tapped or typed) or "link" (a Link session's).
    """

    bpm: float
    anchor: float
    beats_per_bar: int = BEATS_PER_BAR
    source: str = "tap"

    @property
    def period(self) -> float:
        """Seconds per beat."""
        return 60.0 / self.bpm

    def beat_at(self, t: float) -> float:
        """Beats counted from the anchor at time t (fractional).

        Parameters
        ----------
        t : a time on the show's clock, s.

        Returns
        -------
        float.
        """
        return (t - self.anchor) / self.period

    def with_bpm(self, bpm: float, now: float) -> BeatGrid:
        """The same beat position at `now`, another tempo from there on (a typed tempo keeps
        the phase, as a DJ's pitch fader does).

        Parameters
        ----------
        bpm : the new tempo.
        now : the show's clock now.

        Returns
        -------
        BeatGrid whose downbeats continue the count.
        """
        beat = self.beat_at(now)
        return replace(self, bpm=bpm, anchor=now - beat * 60.0 / bpm, source="tap")

    def beats_between(self, start: float, end: float) -> tuple[np.ndarray, np.ndarray]:
        """The beats in (start, end] and their counts from the anchor.

        Parameters
        ----------
        start, end : times on the show's clock, s.

        Returns
        -------
        (times, counts): float64 and int64 arrays; a count ≡ 0 (mod beats_per_bar) is a
        downbeat.
        """
        first = int(np.floor(self.beat_at(start))) + 1
        last = int(np.floor(self.beat_at(end)))
        counts = np.arange(first, last + 1, dtype=np.int64)
        return self.anchor + counts * self.period, counts

    def differs(self, other: BeatGrid | None, bpm: float = 0.01, phase: float = 0.005) -> bool:
        """Whether `other` is another grid: a tempo more than `bpm` apart, or downbeats more
        than `phase` seconds apart (modulo a bar).

        Parameters
        ----------
        other : a grid, or None.
        bpm : BPM tolerance.
        phase : seconds tolerance.

        Returns
        -------
        bool.
        """
        if other is None or abs(other.bpm - self.bpm) > bpm or \
                other.beats_per_bar != self.beats_per_bar or other.source != self.source:
            return True
        bar = self.period * self.beats_per_bar
        offset = (other.anchor - self.anchor) % bar
        return min(offset, bar - offset) > phase


def grid_from_taps(taps: list[float], first: int = 0) -> BeatGrid | None:
    """The grid of a count of taps: t_i ≈ a + i·p by least squares.

    Parameters
    ----------
    taps : the taps' times on the show's clock (ascending), the last few of a count.
    first : the count of the first of them (earlier taps of the count were dropped): the
        count's tap 0 is the downbeat.

    Returns
    -------
    BeatGrid, or None for fewer than two taps.
    """
    if len(taps) < 2:
        return None
    counts = np.arange(first, first + len(taps), dtype=np.float64)
    period, start = np.polyfit(counts, np.asarray(taps, dtype=np.float64), 1)
    if not period > 0:
        return None
    return BeatGrid(60.0 / period, float(start), BEATS_PER_BAR, "tap")
