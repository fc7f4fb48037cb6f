"""The show's own beat clock (docs/design.md#show): taps and a typed tempo set a grid the show
follows, and Ableton Link's phase, followed and led, with two real peers on 127.0.0.1."""

from __future__ import annotations

import asyncio
import threading
import time

import pytest
from pythonosc.dispatcher import Dispatcher
from pythonosc.osc_server import ThreadingOSCUDPServer
from pythonosc.udp_client import SimpleUDPClient

from eigendance.music.spectrogram import Spectrogram
from eigendance.show.beat_clock import BeatGrid
from eigendance.show.osc import OscOut
from eigendance.show.state import ShowState
from helpers import fixture_path, wait_for


def off_grid(t: float, anchor: float, period: float) -> float:
    """How far t is from the nearest of anchor + i·period, s."""
    offset = (t - anchor) % period
    return min(offset, period - offset)


def test_four_taps_at_120_bpm_set_the_beat_clock():
    now = [50.0]
    state = ShowState(clock=lambda: now[0])
    for jitter in (0.0, 0.004, -0.003, 0.001):  # a hand's few milliseconds
        now[0] += jitter
        state.act("tap")
        now[0] += 0.5 - jitter
    grid = state.grid
    assert grid.bpm == pytest.approx(120.0, abs=1.0)
    assert state.snapshot()["tempo"] == grid.bpm
    # the first tap of the count is a downbeat: the fitted line through (0, 50.000),
    # (1, 50.504), (2, 50.997), (3, 51.501) meets count 0 at 50.0011 (by hand: mean time
    # 50.7505 at count 1.5, slope Σ(c − 1.5)(t − 50.7505)/Σ(c − 1.5)² = 2.498/5 = 0.4996)
    assert grid.anchor == pytest.approx(50.0011, abs=2e-4)
    assert grid.bpm == pytest.approx(60 / 0.4996, abs=0.01)
    times, counts = grid.beats_between(51.9, 54.1)
    assert list(counts) == [4, 5, 6, 7, 8]  # 52.0 is count 4, a downbeat
    assert times[0] == pytest.approx(52.0, abs=0.01)
    assert state.snapshot()["grid"]["beats_per_bar"] == 4


def test_a_typed_tempo_keeps_the_phase_and_auto_gives_the_song_back():
    now = [10.0]
    state = ShowState(clock=lambda: now[0])
    for _ in range(4):
        state.act("tap")
        now[0] += 0.5
    now[0] = 13.0  # beat 6 of the 120-BPM count that started at 10.0
    state.act("tempo", 100.0)
    assert state.grid.bpm == 100.0
    assert state.grid.beat_at(13.0) == pytest.approx(6.0)
    assert state.grid.beat_at(13.6) == pytest.approx(7.0)  # 0.6 s a beat from here on
    state.heard("song", 1.0, True, tempo=97.0)
    assert state.tempo == 100.0  # a song's tempo does not override the show's clock
    assert state.act("auto")["grid"] is None
    state.heard("song", 1.0, True, tempo=97.0)
    assert state.tempo == 97.0


def test_four_taps_over_osc_make_the_state_120_bpm(served_show):
    sender = SimpleUDPClient("127.0.0.1", served_show.osc.port)
    start = time.monotonic()
    sent = []
    for i in range(4):
        time.sleep(max(0.0, start + 0.5 * i - time.monotonic()))
        sent.append(time.monotonic())
        sender.send_message("/eigendance/tap", [])
    assert wait_for(lambda: served_show.state.tap_count == 4)
    answer = served_show.client.get("/api/show/state").json()
    # sleeps on a shared machine: the taps land within a few ms of 0.5 s apart
    assert all(abs(b - a - 0.5) < 0.02 for a, b in zip(sent, sent[1:], strict=False)), sent
    assert answer["tempo"] == pytest.approx(120.0, abs=2.5)
    assert answer["grid"]["source"] == "tap" and answer["grid"]["bpm"] == answer["tempo"]


def link_pair():
    pytest.importorskip("aalink")
    from eigendance.show.link import LinkSync
    return LinkSync


def test_following_link_takes_its_phase():
    LinkSync = link_pair()
    from aalink import Link

    loop = asyncio.new_event_loop()
    leader = Link(128.0, loop)
    leader.quantum = 4
    leader.enabled = True
    state = ShowState()
    follower = LinkSync(state, "follow")
    try:
        assert wait_for(lambda: follower.peers >= 1 and leader.num_peers >= 1)
        # (when two sessions meet, either's tempo may win: the leader sets it once joined)
        leader.tempo = 128.0
        leader.force_beat(0.0)  # the session's bar starts now, for every peer
        forced = time.monotonic()
        bar = 4 * 60.0 / 128.0
        assert wait_for(lambda: state.grid is not None and state.grid.source == "link"
                        and abs(state.grid.bpm - 128.0) < 0.01
                        and off_grid(state.grid.anchor, forced, bar) < 0.01, 5.0), \
            (state.grid, forced)
        # the follower's beats land on the leader's grid
        times, counts = state.grid.beats_between(time.monotonic(), time.monotonic() + 4)
        assert all(off_grid(t, forced, 60 / 128.0) < 0.01 for t in times)
        assert all(off_grid(t, forced, bar) < 0.01 for t in times[counts % 4 == 0])
    finally:
        follower.stop()
        leader.enabled = False
        loop.close()


def test_leading_link_gives_the_session_the_tapped_phase():
    LinkSync = link_pair()
    leader_state, follower_state = ShowState(), ShowState()
    tapped = time.monotonic() - 0.3
    leader_state.set_grid(BeatGrid(120.0, tapped, 4, "tap"))
    leader = LinkSync(leader_state, "lead")
    follower = LinkSync(follower_state, "follow")
    try:
        assert wait_for(lambda: leader.peers >= 1 and follower.peers >= 1)
        assert wait_for(lambda: follower_state.grid is not None
                        and abs(follower_state.grid.bpm - 120.0) < 0.01
                        and off_grid(follower_state.grid.anchor, tapped, 2.0) < 0.01, 5.0), \
            (follower_state.grid, tapped)
        # and the session's own phase, read from the follower's Link: beats since the tap
        link = follower.link
        beat, now = float(link.phase), time.monotonic()
        expected = ((now - tapped) * 2.0) % 4
        assert min(abs(beat - expected), 4 - abs(beat - expected)) < 0.02
    finally:
        leader.stop()
        follower.stop()


def test_osc_out_sends_the_show_s_beats_while_its_clock_is_set():
    spectrogram = Spectrogram.from_file(fixture_path("audio", "beatnet_808kick120bpm.mp3"))
    received = []
    dispatcher = Dispatcher()
    for address in ("/eigendance/beat", "/eigendance/downbeat"):
        dispatcher.map(address, lambda a, *args: received.append((a, *args)))
    listener = ThreadingOSCUDPServer(("127.0.0.1", 0), dispatcher)
    threading.Thread(target=listener.serve_forever, daemon=True).start()
    state = ShowState()
    sender = OscOut(state, "127.0.0.1", listener.server_address[1], lambda song: spectrogram)
    try:
        state.heard("kick", 0.0, True)  # song time 0 drawn now
        start = state.song_clock["at"]
        state.set_grid(BeatGrid(120.0, start + 0.13, 4, "tap"))  # off the song's own beats
        time.sleep(1.4)
        state.heard("kick", time.monotonic() - start, False)
        time.sleep(0.05)
    finally:
        sender.stop()
        listener.shutdown()
        listener.server_close()
    beats = [args for address, *args in received if address == "/eigendance/beat"]
    downbeats = [args for address, *args in received if address == "/eigendance/downbeat"]
    assert [count for count, _ in beats] == [0, 1, 2]
    # song times 0.13, 0.63, 1.13 (float32 over OSC; the song's own beats are elsewhere)
    assert [t for _, t in beats] == pytest.approx([0.13, 0.63, 1.13], abs=1e-3)
    assert downbeats == [beats[0]]
