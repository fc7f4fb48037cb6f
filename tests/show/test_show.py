"""Show mode without a browser (docs/design.md#show): the set list, the state every control
changes, OSC in and out over real UDP on 127.0.0.1, and Ableton Link with two real peers."""

from __future__ import annotations

import threading
import time
from types import SimpleNamespace

import mir_eval
import numpy as np
import pytest
from pythonosc.dispatcher import Dispatcher
from pythonosc.osc_server import ThreadingOSCUDPServer
from pythonosc.udp_client import SimpleUDPClient

from eigendance.cli.main import main
from eigendance.errors import InputError
from eigendance.modal.rig import Rig
from eigendance.modal.sample_rigs import load_rig
from eigendance.music.spectrogram import Spectrogram
from eigendance.presets.store import PresetStore
from eigendance.server.serve import library_session
from eigendance.show.osc import OscIn, OscOut, parse_address
from eigendance.show.session import ModeAmplitudes, cue_items
from eigendance.show.setlist import read_set
from eigendance.show.state import ShowState
from helpers import fixture_path, wait_for

CAT = fixture_path("meshes", "teapot.obj")
KICK = fixture_path("audio", "beatnet_808kick120bpm.mp3")


def write_set(folder, text: str) -> str:
    (folder / "model.obj").write_bytes(open(CAT, "rb").read())
    (folder / "kick.mp3").write_bytes(open(KICK, "rb").read())
    path = folder / "set.toml"
    path.write_text(text)
    return str(path)


SET = """
[set]
name = "Friday"
loop = true
fade_beats = 2
slots = ["Kick"]

[[cue]]
model = "model.obj"
song = "kick.mp3"
preset = "Kick"
bars = 4

[[cue]]
name = "live"
model = "model.obj"
live = "mic"
until = "section"
fade_beats = 8
"""


def test_a_set_reads_its_cues(tmp_path):
    setlist = read_set(write_set(tmp_path, SET))
    assert (setlist.name, setlist.loop, setlist.slots) == ("Friday", True, ["Kick"])
    first, second = setlist.cues
    assert (first.name, first.until, first.bars, first.fade_beats) == ("Kick", "bars", 4, 2.0)
    assert first.song == str(tmp_path / "kick.mp3")
    assert (second.live, second.until, second.fade_beats, second.song) == \
        ("mic", "section", 8.0, None)


@pytest.mark.parametrize("cue, message", [
    ('model = "model.obj"', "give a song file or a live input"),
    ('model = "model.obj"\nsong = "kick.mp3"\nlive = "mic"', "give a song file or a live"),
    ('model = "model.obj"\nsong = "kick.mp3"\nuntil = "bars"', "bars must be"),
    ('model = "model.obj"\nsong = "kick.mp3"\ncolour = 1', "unknown key 'colour'"),
    ('model = "gone.obj"\nsong = "kick.mp3"', r"set.toml: cue 1: .*gone.obj: no such file"),
    ('model = "model.obj"\nsong = "gone.mp3"', r"set.toml: cue 1: .*gone.mp3: no such file"),
    ('model = "model.obj"\nsong = "kick.mp3"\npreset = "../x"', "preset name"),
    ('model = "model.obj"\nsong = "kick.mp3"\nbars = true', "wrong type"),
])
def test_a_bad_cue_is_one_line_naming_it(tmp_path, cue, message):
    path = write_set(tmp_path, f"[[cue]]\n{cue}\n")
    with pytest.raises(InputError, match=message) as error:
        read_set(path)
    assert "cue 1" in str(error.value)  # a missing file too (was its path alone)
    assert "\n" not in str(error.value)


def state_of(tmp_path, text=SET, clock=time.monotonic) -> ShowState:
    setlist = read_set(write_set(tmp_path, text))
    return ShowState(setlist, slots=lambda: ["Kick", "Drift"], clock=clock)


def test_next_and_previous_loop_the_set_and_a_page_ends_a_cue_once(tmp_path):
    state = state_of(tmp_path)
    assert state.snapshot()["next"] == 1
    assert state.act("next")["cue"] == 1
    assert state.act("next")["cue"] == 0  # loop = true
    assert state.act("prev")["cue"] == 1
    assert state.act("next", {"from": 1})["cue"] == 0
    assert state.act("next", {"from": 1})["cue"] == 0  # a second output page: no second step
    state.act("loop_set", False)
    assert state.act("prev")["cue"] == 0  # the first cue: nowhere before it
    assert state.snapshot()["preset"] == "Kick"


def test_tapping_at_half_second_intervals_is_120_bpm(tmp_path):
    now = [100.0]
    state = state_of(tmp_path, clock=lambda: now[0])
    for _ in range(4):
        state.act("tap")
        now[0] += 0.5
    assert state.snapshot()["tempo"] == pytest.approx(120.0)
    now[0] += 5  # a long pause starts a new count
    state.act("tap")
    now[0] += 0.4
    assert state.act("tap")["tempo"] == pytest.approx(150.0)


@pytest.mark.parametrize("action, value", [("gain", -1), ("gain", float("nan")), ("gain", "2"),
                                           ("cue", 5), ("slot", 3), ("dance", None),
                                           ("_go", 0), ("control", {"id": "a b", "value": 1})])
def test_bad_actions_are_refused(tmp_path, action, value):
    with pytest.raises(InputError):
        state_of(tmp_path).act(action, value)


def test_slots_and_controls(tmp_path):
    state = state_of(tmp_path)
    assert state.act("slot", 2)["preset"] == "Drift"
    assert state.act("control", {"id": "rig-scale", "value": 0.5})["controls"] == \
        {"rig-scale": 0.5}
    assert state.act("blackout")["blackout"] is True
    assert state.act("blackout")["blackout"] is False


def test_an_osc_message_changes_the_gain_the_api_reports(served_show):
    state, client = served_show.state, served_show.client
    sender = SimpleUDPClient("127.0.0.1", served_show.osc.port)
    delays = []
    for gain in (2.5, 0.5, 3.0, 1.25, 2.0):
        sent = time.monotonic()
        sender.send_message("/eigendance/gain", gain)
        assert wait_for(lambda g=gain: client.get("/api/show/state").json()["gain"] == g)
        delays.append(time.monotonic() - sent)
    # the bound (200 ms) on the best of five: one busy moment of the shared machine may
    # delay any single message
    assert min(delays) < 0.2, delays
    sender.send_message("/eigendance/preset", "Kick")
    sender.send_message("/eigendance/control/smoothing", 0.25)
    sender.send_message("/eigendance/play", [])
    assert wait_for(lambda: state.playing and state.preset == "Kick"
                    and state.controls == {"smoothing": 0.25})


def test_malformed_osc_is_ignored_with_one_line(capfd):
    state = ShowState()
    osc = OscIn(state, "127.0.0.1", 0)
    try:
        import socket
        with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as raw:
            raw.sendto(b"\x00garbage", ("127.0.0.1", osc.port))
        time.sleep(0.3)
        sender = SimpleUDPClient("127.0.0.1", osc.port)
        sender.send_message("/eigendance/gain", "loud")  # a string where a number goes
        sender.send_message("/eigendance/gain", 1.5)
        assert wait_for(lambda: state.gain == 1.5)
    finally:
        osc.stop()
    lines = capfd.readouterr().err.strip().splitlines()
    assert lines and all(line.startswith("eigendance: OSC in:") for line in lines)
    assert "not OSC" in lines[0]
    assert state.version == 1


def test_osc_in_listens_on_loopback_by_default():
    osc = OscIn(ShowState())
    try:
        assert osc.socket.getsockname()[0] == "127.0.0.1"
    finally:
        osc.stop()


def test_osc_out_sends_the_beats_at_the_song_time_drawn():
    spectrogram = Spectrogram.from_file(KICK)
    received = []
    dispatcher = Dispatcher()
    dispatcher.map("/eigendance/beat",
                   lambda address, index, t: received.append((time.monotonic(), index, t)))
    listener = ThreadingOSCUDPServer(("127.0.0.1", 0), dispatcher)
    threading.Thread(target=listener.serve_forever, daemon=True).start()
    state = ShowState()
    sender = OscOut(state, "127.0.0.1", listener.server_address[1], lambda song: spectrogram)
    try:
        state.heard("kick", 0.0, True)
        started = state.song_clock["at"]
        time.sleep(4.2)
        state.heard("kick", time.monotonic() - started, False)
        time.sleep(0.1)
    finally:
        sender.stop()
        listener.shutdown()
    beats = spectrogram.rhythm.beats
    expected = beats[(beats > 0.05) & (beats < 4.1)]
    arrivals = np.array([at - started for at, _, _ in received])  # song time when they came
    times = np.array([t for _, _, t in received])
    assert mir_eval.beat.f_measure(expected, times) >= 0.95
    # timed with the picture: none before the song reaches it (how soon after, a matter of a
    # shared machine's load, is measured by benchmarks/bench_show.py)
    assert np.all(arrivals >= times - 0.01), arrivals - times
    assert [index for _, index, _ in received] == \
        [int(np.abs(beats - t).argmin()) for t in times]  # OSC sends float32


def test_osc_out_takes_host_and_port():
    assert parse_address("127.0.0.1:9000") == ("127.0.0.1", 9000)
    assert parse_address("[::1]:9000") == ("::1", 9000)
    for bad in ("9000", "host:", "host:99999", "host:²"):
        with pytest.raises(InputError, match="HOST:PORT"):
            parse_address(bad)


def test_two_link_peers_agree_on_the_tempo():
    pytest.importorskip("aalink")
    from eigendance.show.link import LinkSync

    leader_state, follower_state = ShowState(), ShowState()
    leader_state.act("tempo", 133.0)
    leader = LinkSync(leader_state, "lead")
    follower = LinkSync(follower_state, "follow")
    try:
        assert wait_for(lambda: leader.peers >= 1 and follower.peers >= 1, 5.0)
        assert wait_for(lambda: follower_state.tempo is not None
                        and abs(follower_state.tempo - 133.0) < 0.01, 5.0), follower_state.tempo
        leader_state.act("tap")  # the leader's tempo changes: the follower's follows
        leader_state.act("tempo", 96.0)
        assert wait_for(lambda: abs(follower_state.tempo - 96.0) < 0.01, 5.0)
    finally:
        leader.stop()
        follower.stop()


def test_osc_out_sends_the_mode_coefficients_of_the_rig_on_screen(tmp_path):
    rig = Rig(load_rig("loop4"), np.float64)
    spectrogram = Spectrogram.from_file(fixture_path("audio", "kevin_macleod_vibe_ace_20s-24s.ogg"))
    items = {("rig", "r"): SimpleNamespace(rig=rig, revision=0),
             ("song", "s"): SimpleNamespace(spectrogram=spectrogram)}
    library = SimpleNamespace(get=lambda kind, id: items.get((kind, id)))
    setlist = read_set(write_set(tmp_path, '[[cue]]\nmodel = "model.obj"\nsong = "kick.mp3"\n'))
    state = ShowState(setlist, [{"model": {"kind": "rig", "id": "r"}, "song": "s"}])
    modes = ModeAmplitudes(library, state, PresetStore(tmp_path / "presets"))
    t = 1.234
    frame = round(t * spectrogram.rate)
    expected = rig.coefficients(spectrogram, None, spectrogram.times[frame:frame + 1])[0]
    assert np.allclose(modes("s", t), expected)
    assert len(expected) == rig.model.n_modes and np.abs(expected).max() > 0
    mesh = ShowState(setlist, [{"model": {"kind": "mesh", "id": "m"}, "song": "s"}])
    assert ModeAmplitudes(library, mesh, PresetStore(tmp_path))("s", t) is None


def test_show_with_a_bad_set_is_one_line(tmp_path, capsys):
    path = write_set(tmp_path, "[[cue]]\nmodel = \"model.obj\"\n")
    assert main(["show", path, "--port", "0"]) == 1
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("eigendance: error:") and "cue 1" in err
    assert main(["show", str(tmp_path / "none.toml")]) == 1
    assert main(["serve", "--osc-out", "nowhere"]) == 1
    assert "HOST:PORT" in capsys.readouterr().err


def test_a_cue_may_dance_a_built_in_rig_as_the_commands_take_it(tmp_path):
    setlist = read_set(write_set(tmp_path, '[[cue]]\nmodel = "hand"\nsong = "kick.mp3"\n'))
    assert setlist.cues[0].model == "hand"
    with library_session(k=12) as library:
        items = cue_items(library, setlist)
        rig = library.get("rig", items[0]["model"]["id"])
        assert (items[0]["model"]["kind"], rig.origin, rig.source) == ("rig", "built-in", "hand")
        assert library.add_path("hand") is rig  # `serve hand` too
    (tmp_path / "hand").write_bytes(b"")  # a file of that name beside the set is the file
    with pytest.raises(InputError, match="hand"):
        read_set(tmp_path / "set.toml")
    with pytest.raises(InputError, match="nowhere"):
        read_set(write_set(tmp_path, '[[cue]]\nmodel = "nowhere"\nsong = "kick.mp3"\n'))


def test_osc_out_sends_bands_again_when_the_song_plays_again_from_the_start():
    spectrogram = Spectrogram.from_file(KICK)
    received = []
    dispatcher = Dispatcher()
    dispatcher.map("/eigendance/bands", lambda address, *values: received.append(values))
    listener = ThreadingOSCUDPServer(("127.0.0.1", 0), dispatcher)
    threading.Thread(target=listener.serve_forever, daemon=True).start()
    state = ShowState()
    sender = OscOut(state, "127.0.0.1", listener.server_address[1], lambda song: spectrogram)
    try:
        state.heard("kick", 8.0, True)  # played up to 8 s …
        assert wait_for(lambda: len(received) >= 3)
        state.heard("kick", 8.3, False)
        time.sleep(0.1)
        received.clear()
        state.heard("kick", 0.0, True)  # … then again from the start
        assert wait_for(lambda: len(received) >= 3, 2.0), received
    finally:
        sender.stop()
        listener.shutdown()
        listener.server_close()
