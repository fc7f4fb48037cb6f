"""Show mode benchmark: the latency from an OSC message to the frame it changes, and how close
OSC out's beats come to the song's.

Serves a set on the shared kick track (120 BPM) with `eigendance show --osc PORT --osc-out
127.0.0.1:PORT`, opens the output page (/show) in headless Chromium (SwiftShader WebGL2) while
the song plays, then N times sends `/eigendance/gain g` from python-osc and measures, on the
machine's wall clock (Python's time.time() and the page's performance.timeOrigin + now()):
  - OSC → state: until `GET /api/show/state` reports the gain (polled every ms);
  - OSC → page: until the output page hears the new state (server-sent events);
  - OSC → frame: until the output page starts the first frame drawn with it.
And for OSC out: each /eigendance/beat's arrival against its song time (the page's clock, the
report's time on the way taken off), as offsets (median, 95th percentile) and mir_eval's
F-measure at ±70 ms. With --live, a set whose cue is the live input (Chromium's fake microphone
playing the kick track): each live /eigendance/beat's arrival against the moment the output
page's picture reached it (its drawn time and wall clock, read together at the end). Not run
by CI.

    python benchmarks/bench_show.py [--messages 20] [--seconds 8] [--live]
"""

from __future__ import annotations

import argparse
import os
import sys
import tempfile
import time

import mir_eval
import numpy as np
from playwright.sync_api import sync_playwright
from pythonosc.udp_client import SimpleUDPClient

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "tests"))
sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "tests", "web"))

from chromium import AUTOPLAY, FAKE, GRANT, launch  # noqa: E402 - the tests' Chromium
from show_helpers import (  # noqa: E402 - the tests' helpers, found above
    KICK,
    control,
    open_output,
    osc_listener,
    show_server,
    state,
    write_set,
)
from web_helpers import CAT, fake_clip  # noqa: E402

from eigendance.music.mapping import Mapping  # noqa: E402
from eigendance.presets.store import Preset, PresetStore  # noqa: E402


def stats(values) -> str:
    values = np.asarray(values) * 1000
    return (f"median {np.median(values):6.1f} ms, p95 {np.percentile(values, 95):6.1f} ms, "
            f"max {values.max():6.1f} ms")


def gain_latency(page, url, osc_port, count):
    """Send `count` gain messages; per message (to state, to page, to frame) in seconds."""
    sender = SimpleUDPClient("127.0.0.1", osc_port)
    rows = []
    for i in range(count):
        gain = round(0.5 + (i % 7) * 0.25, 2)
        if state(url)["gain"] == gain:
            gain += 0.01
        seen = page.evaluate("window.eigendanceShow.output.gains.length")
        sent = time.time()
        sender.send_message("/eigendance/gain", gain)
        while state(url)["gain"] != gain:
            time.sleep(0.001)
        to_state = time.time() - sent
        page.wait_for_function(
            f"window.eigendanceShow.output.gains.length > {seen} && "
            "window.eigendanceShow.output.gains.at(-1).drawn !== null", timeout=10_000)
        heard, drawn = page.evaluate(
            "[window.eigendanceShow.output.gains.at(-1).heard,"
            " window.eigendanceShow.output.gains.at(-1).drawn]")
        rows.append((to_state, heard / 1000 - sent, drawn / 1000 - sent))
        time.sleep(0.15)
    return np.array(rows)


def live_offsets(playwright, folder) -> np.ndarray:
    """The live input's beats over OSC out: arrival − when the picture reached them, s."""
    path = os.path.join(folder, "live.toml")
    with open(path, "w") as file:
        file.write(f'[[cue]]\nmodel = "{os.path.abspath(CAT)}"\nlive = "mic"\n')
    clip = fake_clip(folder, KICK, seconds=10)
    with osc_listener() as (listen, received), \
            show_server(path, folder, os.path.join(folder, "presets"), listen) as server:
        chromium = launch(playwright.chromium, *FAKE, GRANT,
                          f"--use-file-for-fake-audio-capture={clip}%noloop")
        page = open_output(chromium, server["url"], width=1280, height=720)
        page.wait_for_function("window.eigendanceShow.output.app.transport.now() > 9",
                               timeout=90_000)
        t, wall = page.evaluate("""() => [window.eigendanceShow.output.app.viewer.time(),
            performance.timeOrigin + performance.now()]""")
        beats = [(at, beat) for at, _, _, beat in list(received)]
        chromium.close()
    return np.array([at - (wall / 1000 + beat - t) for at, beat in beats])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--messages", type=int, default=20)
    parser.add_argument("--seconds", type=float, default=8.0)
    parser.add_argument("--live", action="store_true", help="the live input's beats too")
    args = parser.parse_args()
    folder = tempfile.mkdtemp(prefix="bench-show-")
    presets = os.path.join(folder, "presets")
    PresetStore(presets).save(Preset("Wide", Mapping(np.linspace(0, 0.5, 64), np.full(24, 0.5))))
    with osc_listener() as (listen, received), \
            show_server(write_set(folder), folder, presets, listen) as server, \
            sync_playwright() as playwright:
        chromium = launch(playwright.chromium, *AUTOPLAY)
        url = server["url"]
        page = open_output(chromium, url, width=1280, height=720)
        control(url, "play")
        started = time.time()
        rows = gain_latency(page, url, server["osc"], args.messages)
        time.sleep(max(0.0, args.seconds - (time.time() - started)))
        control(url, "stop")
        beats = [(at, t) for at, address, _, t in list(received)]
        chromium.close()
        live = live_offsets(playwright, folder) if args.live else None
    print(f"OSC /eigendance/gain → /api/show/state: {stats(rows[:, 0])}")
    print(f"OSC /eigendance/gain → output page:     {stats(rows[:, 1])}")
    print(f"OSC /eigendance/gain → its first frame: {stats(rows[:, 2])}")
    if len(beats) >= 4:
        arrivals, times = (np.array(column) for column in zip(*beats, strict=True))
        # the song's time 0 on the wall clock, from the median of every beat's
        offsets = arrivals - times
        zero = np.median(offsets)
        print(f"OSC out: {len(beats)} beats, arrival − song time − median: "
              f"{stats(np.abs(offsets - zero))}; F(±70 ms) = "
              f"{mir_eval.beat.f_measure(times, arrivals - zero):.3f}")
    if live is not None and len(live):
        print(f"OSC out, live input: {len(live)} beats, arrival − the picture's: median "
              f"{np.median(live) * 1000:.1f} ms, p95 {np.percentile(live, 95) * 1000:.1f} ms, "
              f"min {live.min() * 1000:.1f} ms")
    print(f"load average: {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")


if __name__ == "__main__":
    main()
