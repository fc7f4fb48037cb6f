"""OSC out from a live input (docs/design.md#show): the page's reports, queued until the picture
reaches them, sent over real UDP on 127.0.0.1; a bad report is one 400 line."""

from __future__ import annotations

import threading
import time

import pytest
from pythonosc.dispatcher import Dispatcher
from pythonosc.osc_server import ThreadingOSCUDPServer
from starlette.testclient import TestClient

from eigendance.errors import InputError
from eigendance.presets.store import PresetStore
from eigendance.server.app import create_app
from eigendance.server.serve import library_session
from eigendance.show.live_out import LiveHeard
from eigendance.show.osc import OscOut
from eigendance.show.state import ShowState


def test_reports_wait_for_the_picture_and_late_ones_go_at_once():
    heard = LiveHeard()
    heard.report({"take": 1, "beats": [[0, 0.5], [1, 1.0]], "onsets": [0.49, 0.99],
                  "bands": [[0.5, [0.1] * 64], [0.6, [0.2] * 64]]})
    assert heard.due(0.4) == ([], [], None)
    beats, onsets, bands = heard.due(0.75)
    assert (beats, onsets, bands) == ([(0, 0.5)], [0.49], [0.2] * 64)  # the newest frame
    assert heard.due(1.2)[0] == [(1, 1.0)]
    heard.report({"take": 1, "beats": [[2, 1.1]]})  # came after the picture passed it
    assert heard.due(1.21)[0] == [(2, 1.1)]
    heard.report({"take": 2, "beats": [[0, 0.1]]})  # a new take: the old one's queue goes
    assert heard.due(5.0)[0] == [(0, 0.1)]


@pytest.mark.parametrize("report", [
    None, {"beats": []}, {"take": True}, {"take": 1, "beats": [[0, -1]]},
    {"take": 1, "beats": [[0.5, 1.0]]}, {"take": 1, "onsets": [float("nan")]},
    {"take": 1, "bands": [[0.1, [0.5] * 63]]}, {"take": 1, "onsets": [0.1] * 300},
])
def test_a_bad_report_is_refused(report):
    with pytest.raises(InputError):
        LiveHeard().report(report)


def test_the_clock_route_takes_a_live_report_and_refuses_a_bad_one(tmp_path):
    with library_session(k=12) as library:
        state = ShowState()
        client = TestClient(create_app(library, presets=PresetStore(tmp_path), show=state),
                            base_url="http://127.0.0.1:8765")
        clock = {"song": None, "time": 1.0, "playing": True}
        good = client.post("/api/show/clock", json={**clock, "live": {
            "take": "a", "beats": [[0, 0.9]], "onsets": [], "bands": []}})
        assert good.status_code == 200
        assert state.live.due(1.0)[0] == [(0, 0.9)]
        bad = client.post("/api/show/clock", json={**clock, "live": {"take": "a",
                                                                     "beats": "many"}})
        assert bad.status_code == 400 and "\n" not in bad.json()["error"]


def test_osc_out_sends_the_live_beats_as_the_picture_reaches_them():
    received = []
    dispatcher = Dispatcher()
    for address in ("/eigendance/beat", "/eigendance/bands", "/eigendance/onset"):
        dispatcher.map(address, lambda a, *args: received.append((time.monotonic(), a, args)))
    listener = ThreadingOSCUDPServer(("127.0.0.1", 0), dispatcher)
    threading.Thread(target=listener.serve_forever, daemon=True).start()
    state = ShowState()
    sender = OscOut(state, "127.0.0.1", listener.server_address[1], lambda song: None)
    try:
        state.heard(None, 0.0, True)  # a live input drawn from take time 0 on
        started = state.song_clock["at"]
        state.live.report({"take": 7, "beats": [[0, 0.3], [1, 0.8]], "onsets": [0.29],
                           "bands": [[0.3, [0.5] * 64]]})
        time.sleep(1.2)
    finally:
        sender.stop()
        listener.shutdown()
    beats = [(at - started, args) for at, a, args in received if a == "/eigendance/beat"]
    assert [args[0] for _, args in beats] == [0, 1]
    for arrival, (_, t) in beats:
        assert arrival >= t - 0.01  # not before the picture shows it
    assert any(a == "/eigendance/bands" and len(args) == 64 for _, a, args in received)
