"""OSC in and out (python-osc; docs/design.md#show).

In: a UDP socket (127.0.0.1 unless told) whose messages become `ShowState.act` calls:
`/eigendance/gain f`, `/preset s`, `/next`, `/prev`, `/tap`, `/auto`, `/play`, `/stop`,
`/blackout [i]`, `/cue i`, `/slot i`, `/fade f`, `/tempo f`, and `/eigendance/control/<id> f`
for each slider or switch of the page (its element id: `gain`, `smoothing`, `facets`,
`rig-scale`, …). A packet that does not parse, an unknown address or a bad value is dropped
with one line on stderr (at most one a second, with the count of the others).

Out: what the dance hears, at the song time the output page draws (its clock, reported to the
server), from the song or from the live input (its events as the page reports them:
`show.live_out`): `/eigendance/beat (index, time)`, `/eigendance/downbeat (index, time)`,
`/eigendance/onset time`, `/eigendance/tempo f` (when it changes), `/eigendance/bands` (64
floats, 30 times a second) and, while a rig dances a song, `/eigendance/modes` (its mode
coefficients, radians, as often). While the show's own beat clock is set (taps, a typed tempo,
Link: `show.beat_clock`), /beat and /downbeat are its beats (index: the count from its downbeat;
time: the song's time) in place of the song's or the input's.
"""

from __future__ import annotations

import socket
import sys
import threading
import time

import numpy as np
from pythonosc import osc_packet
from pythonosc.udp_client import SimpleUDPClient

from eigendance.errors import InputError, one_line
from eigendance.show.state import ShowState

PREFIX = "/eigendance/"
# address → (action, how many arguments it takes at most)
ACTIONS = {"gain": 1, "preset": 1, "next": 0, "prev": 0, "tap": 0, "auto": 0, "play": 0,
           "stop": 0, "blackout": 1, "cue": 1, "slot": 1, "fade": 1, "tempo": 1, "loop_cue": 1,
           "loop_set": 1}
BANDS_EVERY = 1 / 30  # s between /bands messages
TICK = 0.004  # s: how finely the sender waits for the next event
SEEK = 1.0  # s: a clock that jumps back further was sought (smaller steps: the page's jitter)
LATE = 4.0  # s: events this far behind (a busy machine) are still sent; further on, a seek


class Complaints:
    """One line on stderr per problem, at most one a second (the rest counted).

    Parameters
    ----------
    what : how the lines start ("OSC in").
    """

    def __init__(self, what: str):
        self.what, self.last, self.quiet = what, -1e9, 0

    def __call__(self, message: str) -> None:
        """Say `message`, or count it when a line was written less than a second ago.

        Parameters
        ----------
        message : the problem.
        """
        now = time.monotonic()
        if now - self.last < 1.0:
            self.quiet += 1
            return
        more = f" (and {self.quiet} more)" if self.quiet else ""
        print(f"eigendance: {self.what}: {one_line(message, 200)}, ignored{more}",
              file=sys.stderr, flush=True)
        self.last, self.quiet = now, 0


def handle(state: ShowState, address: str, arguments: list) -> None:
    """Do what one OSC message asks.

    Parameters
    ----------
    state : the show.
    address : the message's address.
    arguments : its arguments.
    """
    if not address.startswith(PREFIX):
        raise InputError(f"unknown address {address}")
    name = address[len(PREFIX):]
    if name.startswith("control/"):
        if len(arguments) != 1:
            raise InputError(f"{address} takes one number")
        state.act("control", {"id": name[len("control/"):], "value": arguments[0]})
        return
    if name not in ACTIONS or len(arguments) > ACTIONS[name]:
        raise InputError(f"unknown address {address} or too many arguments")
    value = arguments[0] if arguments else None
    if name in ("cue", "slot") and isinstance(value, float) and value.is_integer():
        value = int(value)
    if name in ("gain", "fade", "tempo") and isinstance(value, int) and not isinstance(value, bool):
        value = float(value)
    state.act(name, value)


class OscIn:
    """A thread reading OSC packets from a UDP socket into the show.

    Parameters
    ----------
    state : the show.
    host, port : where to listen (port 0: any free port, see `port`).
    """

    def __init__(self, state: ShowState, host: str = "127.0.0.1", port: int = 0):
        family = socket.AF_INET6 if ":" in host else socket.AF_INET
        self.socket = socket.socket(family, socket.SOCK_DGRAM)
        try:
            self.socket.bind((host, port))
        except OSError as error:
            self.socket.close()
            raise InputError(f"OSC: cannot listen on {host}:{port} ({error.strerror})") from None
        self.socket.settimeout(0.2)
        self.port = self.socket.getsockname()[1]
        self.state, self.complain = state, Complaints("OSC in")
        self.stopping = threading.Event()
        self.thread = threading.Thread(target=self._run, name="osc-in", daemon=True)
        self.thread.start()

    def _run(self) -> None:
        while not self.stopping.is_set():
            try:
                data, _ = self.socket.recvfrom(65536)
            except TimeoutError:
                continue
            except OSError:
                return
            try:
                packet = osc_packet.OscPacket(data)
            except Exception as error:  # noqa: BLE001 - python-osc raises ParseError and others
                self.complain(f"a packet that is not OSC ({len(data)} bytes: "
                              f"{type(error).__name__})")
                continue
            for timed in packet.messages:
                try:
                    handle(self.state, timed.message.address, list(timed.message.params))
                except InputError as error:
                    self.complain(f"{timed.message.address}: {error}")

    def stop(self) -> None:
        """Stop listening."""
        self.stopping.set()
        self.socket.close()


class OscOut:
    """A thread sending what the dance hears, at the output page's clock.

    Parameters
    ----------
    state : the show (its `song_clock`).
    host, port : where to send.
    spectrogram_of : song id → its `Spectrogram` (with rhythm), or None.
    modes_of : (song id, t) → the rig's mode coefficients at t, or None (no rig); None: never.
    """

    def __init__(self, state: ShowState, host: str, port: int, spectrogram_of, modes_of=None):
        self.client = SimpleUDPClient(host, port)
        self.state, self.spectrogram_of, self.modes_of = state, spectrogram_of, modes_of
        self.live_bands_at = -1.0  # the live take's time of the last /bands sent
        self.grid_at: float | None = None  # the show's clock when its grid was last looked at
        self.stopping = threading.Event()
        self.thread = threading.Thread(target=self._run, name="osc-out", daemon=True)
        self.thread.start()

    def now(self) -> tuple[str | None, float] | None:
        """The song and its time drawn now, or None when nothing plays.

        Returns
        -------
        (song id, s) or None.
        """
        clock = self.state.song_clock
        if clock is None or not clock["playing"]:
            return None
        return clock["song"], clock["time"] + self.state.clock() - clock["at"]

    def _run(self) -> None:
        last_time, last_song, next_bands, tempo = None, None, 0.0, None
        while not self.stopping.wait(TICK):
            heard = self.now()
            if heard is None:
                last_time = self.grid_at = None
                continue
            song, t = heard
            if self.state.tempo is not None and self.state.tempo != tempo:
                tempo = self.state.tempo
                self.client.send_message(PREFIX + "tempo", float(tempo))
            gridded = self._grid(t)  # the show's own beats, in place of the song's or the input's
            if song is None:  # a live input: what the page reported, once the picture shows it
                self._live(t, not gridded)
                continue
            spectrogram = self.spectrogram_of(song)
            if spectrogram is None:
                continue
            if song != last_song or last_time is None or not -SEEK < t - last_time < LATE:
                # a new song, a seek, a replay: from here on (bands too: a replay from 0 does
                # not wait for the time where the last play stopped)
                last_time, last_song, next_bands = t, song, t
                continue
            self._events(spectrogram.rhythm, last_time, t, not gridded)
            if t >= next_bands:
                frame = min(len(spectrogram.values) - 1, max(0, round(t * spectrogram.rate)))
                self.client.send_message(PREFIX + "bands",
                                         [float(v) for v in spectrogram.values[frame]])
                modes = self.modes_of(song, t) if self.modes_of else None
                if modes is not None:
                    self.client.send_message(PREFIX + "modes", [float(c) for c in modes])
                next_bands = t + BANDS_EVERY
            last_time = max(last_time, t)

    def _grid(self, t: float) -> bool:
        """Send the beats and downbeats of the show's beat clock (`show.beat_clock`) the clock
        passed since the last look, at their song time; whether there is one."""
        grid, now = self.state.grid, self.state.clock()
        if grid is None or self.grid_at is None or not 0 <= now - self.grid_at < LATE:
            self.grid_at = now
            return grid is not None
        times, counts = grid.beats_between(self.grid_at, now)
        for when, count in zip(times, counts, strict=True):
            event = [int(count), float(t + when - now)]  # the grid's count, the song's time
            self.client.send_message(PREFIX + "beat", event)
            if count % grid.beats_per_bar == 0:
                self.client.send_message(PREFIX + "downbeat", event)
        self.grid_at = now
        return True

    def _live(self, t: float, beats: bool = True) -> None:
        """Send the live take's beats (unless the show's clock sends its own), onsets and bands
        the picture reached (`LiveHeard`)."""
        heard, onsets, bands = self.state.live.due(t)
        for index, time_ in heard if beats else ():
            self.client.send_message(PREFIX + "beat", [index, time_])
        for time_ in onsets:
            self.client.send_message(PREFIX + "onset", time_)
        if bands is not None and abs(t - self.live_bands_at) >= BANDS_EVERY:  # a new take: back
            self.client.send_message(PREFIX + "bands", bands)
            self.live_bands_at = t

    def _events(self, rhythm, start: float, end: float, beats: bool = True) -> None:
        """Send the beats and downbeats (unless the show's clock sends its own) and the onsets
        in (start, end]."""
        if rhythm is None:
            return
        for address, times in (("beat", rhythm.beats), ("downbeat", rhythm.downbeats)) \
                if beats else ():
            times = np.asarray(times, dtype=np.float64)
            for index in np.flatnonzero((times > start) & (times <= end)):
                self.client.send_message(PREFIX + address, [int(index), float(times[index])])
        onsets = np.asarray(rhythm.onsets, dtype=np.float64)
        for index in np.flatnonzero((onsets > start) & (onsets <= end)):
            self.client.send_message(PREFIX + "onset", float(onsets[index]))

    def stop(self) -> None:
        """Stop sending."""
        self.stopping.set()


def parse_address(text: str) -> tuple[str, int]:
    """HOST:PORT of --osc-out.

    Parameters
    ----------
    text : e.g. "127.0.0.1:9000" or "[::1]:9000".

    Returns
    -------
    (host, port); InputError for anything else.
    """
    host, _, port = text.rpartition(":")
    host = host.strip("[]")
    if not host or not port.isascii() or not port.isdigit() or not 0 < int(port) < 65536:
        raise InputError(f"--osc-out {one_line(text, 60)}: give HOST:PORT, e.g. 127.0.0.1:9000")
    return host, int(port)
