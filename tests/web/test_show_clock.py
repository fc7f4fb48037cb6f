"""The show's beat clock and a live input's OSC out in Chromium (docs/design.md#show), with real
UDP on 127.0.0.1:

- four taps at 120 BPM over OSC make /api/show/state's tempo 120, and the next cue change lands
  on the tapped bar, not on the song's own beats, and on a live input without beats (silence);
- with a live input (Chromium's fake microphone playing the shared 120-BPM kick track),
  --osc-out sends the page's live beats, tempo and bands to a python-osc listener.
"""

from __future__ import annotations

import json
import os
import time

import numpy as np
import pytest
import soundfile
from chromium import FAKE, GRANT, launch
from pythonosc.udp_client import SimpleUDPClient
from show_helpers import (
    KICK,
    control,
    open_output,
    osc_listener,
    show_server,
    sound_chromium,
    state,
)
from web_helpers import CAT, fake_clip

pytestmark = pytest.mark.web


def write_set(folder, cue: str) -> str:
    """A set of two cues on the cat: the first `cue` (its song or live input), until told."""
    path = os.path.join(folder, "set.toml")
    with open(path, "w") as file:
        file.write(f"""[set]
fade_beats = 0

[[cue]]
name = "one"
model = {json.dumps(os.path.abspath(CAT))}
{cue}

[[cue]]
name = "two"
model = {json.dumps(os.path.abspath(CAT))}
{cue}
""")
    return path


def page_clock(page):
    """(song time drawn, the page's wall clock in s) read together."""
    t, wall = page.evaluate("""() => [window.eigendanceShow.output.app.viewer.time(),
        performance.timeOrigin + performance.now()]""")
    return t, wall / 1000


def tap_then_next(page, url, osc_port, first):
    """Four taps over OSC 0.5 s apart from wall time `first`, then `next`: (the line through
    the taps as sent: its period, the state after the taps, the cue change applied, and the
    page's song time minus its wall clock, s)."""
    sender = SimpleUDPClient("127.0.0.1", osc_port)
    before = state(url)["version"]
    sent = []
    for i in range(4):
        time.sleep(max(0.0, first + 0.5 * i - time.time() - 0.02))
        while time.time() < first + 0.5 * i:
            pass  # the last 20 ms spun: a sleep may overshoot on a shared machine
        sent.append(time.time())
        sender.send_message("/eigendance/tap", [])
    deadline = time.time() + 5
    while state(url)["version"] < before + 4 and time.time() < deadline:
        time.sleep(0.02)  # the four taps heard
    answer = state(url)
    control(url, "next")
    page.wait_for_function("window.eigendanceShow.output.applied.some((a) => a.cue === 1)",
                           timeout=20_000)
    applied = page.evaluate("window.eigendanceShow.output.applied.find((a) => a.cue === 1)")
    t, wall = page_clock(page)
    # the taps as sent (a busy machine may still delay one): the line through them, by least
    # squares as the design says; tap 0 a downbeat
    period, first_tap = np.polyfit(np.arange(4), np.array(sent), 1)
    grid = answer["grid"]
    assert grid["source"] == "tap"
    # the server timed the taps as they came (on a shared machine, within some 30 ms of their
    # sending): its grid is the taps' line, give or take that
    assert grid["bpm"] == pytest.approx(60 / period, abs=6.0)
    beat = 60 / grid["bpm"]
    offset = (grid["downbeat"] / 1000 - first_tap) % beat
    assert min(offset, beat - offset) < 0.06, (grid, sent)
    return period, answer, applied, t - wall


def check_on_the_tapped_bar(period, answer, applied, song_minus_wall):
    # the taps were sent 0.5 s apart; a loaded machine may delay one (then their line's period
    # is what the server should have heard)
    assert answer["tempo"] == pytest.approx(60 / period, abs=6.0)
    grid = answer["grid"]  # the show's beat clock the page must follow: its bar in song time
    bar = 4 * 60 / grid["bpm"]
    bars = (applied["t"] - (grid["downbeat"] / 1000 + song_minus_wall)) / bar
    late = (bars - round(bars)) * bar
    # within a frame of the tapped bar (and the taps' own few ms on a shared machine)
    assert -0.03 <= late <= max(applied["frameDt"], 1 / 60) + 0.05, (late, applied)


def test_tapped_beats_move_the_next_cue_change_to_their_bar(browser, tmp_path):
    folder = str(tmp_path)
    with show_server(write_set(folder, f"song = {json.dumps(KICK)}"), folder,
                     tmp_path / "presets") as server, sound_chromium(browser) as chromium:
        url = server["url"]
        page = open_output(chromium, url)
        control(url, "play")
        page.wait_for_function("window.eigendanceShow.output.app.transport.now() > 0.5",
                               timeout=60_000)
        song_beats = np.array(page.evaluate(
            "Array.from(window.eigendanceShow.output.app.motion.spectrum.beats)"))
        assert abs(np.median(np.diff(song_beats)) - 0.5) < 0.02  # the kick track: 120 BPM
        # tap halfway between the song's beats, the first tap 2 s ahead (a slow page.evaluate
        # on a shared machine must not leave it in the past)
        t, wall = page_clock(page)
        target = song_beats[song_beats > t + 2.0][0] + 0.25
        period, answer, applied, downbeat = tap_then_next(page, url, server["osc"],
                                                          wall + (target - t))
    check_on_the_tapped_bar(period, answer, applied, downbeat)
    off_song = np.abs(song_beats - applied["t"]).min()
    assert off_song > 0.15, off_song  # not the song's own beat: halfway between two


def test_taps_drive_a_live_input_without_beats(browser, tmp_path):
    folder = str(tmp_path)
    silence = os.path.join(folder, "silence.wav")
    soundfile.write(silence, np.zeros(44100 * 20), 44100, subtype="PCM_16")
    with show_server(write_set(folder, 'live = "mic"'), folder, tmp_path / "presets") as server:
        launched = launch(browser.browser_type, *FAKE, GRANT,
                          f"--use-file-for-fake-audio-capture={silence}")
        try:
            page = open_output(launched, server["url"])
            page.wait_for_function("window.eigendanceShow.output.app.live.active", timeout=90_000)
            assert page.evaluate("window.eigendanceShow.output.app.motion.spectrum.beats"
                                 ".length") == 0  # silence: no beat of its own
            t, wall = page_clock(page)
            found = tap_then_next(page, server["url"], server["osc"], wall + 2.0)
            assert page.errors == []
        finally:
            launched.close()
    check_on_the_tapped_bar(*found)


def test_live_input_beats_go_out_over_osc(browser, tmp_path):
    folder = str(tmp_path)
    clip = fake_clip(folder, KICK, seconds=10)
    addresses = ("/eigendance/beat", "/eigendance/tempo", "/eigendance/bands",
                 "/eigendance/onset")
    with osc_listener(addresses) as (listen, received), \
            show_server(write_set(folder, 'live = "mic"'), folder, tmp_path / "presets",
                        listen) as server:
        launched = launch(browser.browser_type, *FAKE, GRANT,
                          f"--use-file-for-fake-audio-capture={clip}%noloop")
        try:
            page = open_output(launched, server["url"])
            control(server["url"], "play")
            page.wait_for_function("window.eigendanceShow.output.app.live.active", timeout=90_000)
            page.wait_for_function("window.eigendanceShow.output.app.transport.now() > 9",
                                   timeout=90_000)
            assert page.errors == []
        finally:
            launched.close()
    beats = [args for _, address, *args in list(received) if address == "/eigendance/beat"]
    tempos = [args[0] for _, address, *args in list(received) if address == "/eigendance/tempo"]
    bands = [args for _, address, *args in list(received) if address == "/eigendance/bands"]
    times = np.array([t for _, t in beats])
    assert len(times) >= 8, beats
    assert [index for index, _ in beats] == list(range(len(beats)))  # each once, in order
    assert np.median(np.diff(times)) == pytest.approx(0.5, abs=0.02)  # 120 BPM
    assert tempos and tempos[-1] == pytest.approx(120.0, abs=3.0)
    # with each picture, up to 30 a second: a loaded machine's page draws fewer
    assert len(bands) > 40 and all(len(b) == 64 for b in bands)
