"""Live input in the page (docs/web.md#live-input, docs/design.md#live), in Chromium with its
fake capture device playing a real clip as the microphone.

- The live loudness, computed in the AudioWorklet, against `eigendance spectrum` of the same
  clip once their starts are aligned; live onsets against the offline onsets (mir_eval); the
  tempo the page shows against the offline tempo; beats on the spectrum strip; the meshes' and
  a rig's motion following the input.
- Nothing gets stuck: permission denied, no input device, a device unplugged mid-take, a clip at
  96 kHz, switching between the input and songs (no open stream left).
- A take kept as a song (POST api/takes, checked as any upload; Host/Origin still checked).
"""

from __future__ import annotations

import contextlib
import json
import os
import re
import subprocess
import sys
import time
import urllib.error
import urllib.request

import av
import mir_eval
import numpy as np
import pytest
import soundfile
from chromium import FAKE, GRANT, launch
from web_helpers import fake_clip, running_server

from eigendance.music.spectrogram import Spectrogram
from helpers import fixture_path

pytestmark = pytest.mark.web
CLIP = os.path.join(os.path.dirname(__file__), "..", "fixtures", "audio",
                    "kevin_macleod_vibe_ace_0s-21s.ogg")
PARITY = 0.03  # the bound on |live − offline| per band
START = 25  # frames (0.25 s) after the stream's start: before, its first block holds no clip
SEGMENT = 50  # frames re-aligned at once where the capture slipped
SLIP = 30  # frames left out after a slip (a window and 3.75 smoothing time constants)


@contextlib.contextmanager
def chromium(browser, flags, url, query="?test"):
    """Another Chromium (same Playwright) with these flags, the page open at url + query."""
    launched = launch(browser.browser_type, *flags)
    try:
        page = launched.new_page(viewport={"width": 1000, "height": 700}, accept_downloads=True)
        page.errors = []
        page.on("pageerror", lambda error: page.errors.append(str(error)))
        page.goto(url + query)
        page.wait_for_function("window.eigendance && window.eigendance.ready", timeout=60_000)
        page.evaluate("window.eigendance.ready")
        yield page
        assert not page.errors, page.errors
    finally:
        launched.close()


def state(page):
    return page.evaluate("window.eigendance.liveInput.state()")


def wait_for(page, condition, seconds=40):
    """Poll the live state until condition(state) holds; the last state."""
    deadline = time.time() + seconds
    while True:
        now = state(page)
        if condition(now) or time.time() > deadline:
            return now
        time.sleep(0.25)


def aligned(clip, live, dropouts, rate=44100):
    """Where the stream started in the clip (samples), and the live frames re-aligned.

    Chromium's fake capture delivers the file in 10-ms chunks, one analysis hop at 44.1 kHz,
    and starts it where the file's reading stood when the page connected: the start is the
    frame lag that makes the offline loudness closest to the live one. Under load the capture
    can drop or repeat a chunk; each second of live frames is then re-aligned (±3 frames) so that
    a slip of the capture is not counted as a difference of the analysis; the frames within
    SLIP frames after a slip or a dropout the worklet reported (silence the capture inserted:
    the window and the smoothing still hold the stream's own gap, which the file has not) are
    marked to be left out."""
    samples, _ = soundfile.read(clip, dtype="float32")
    whole = Spectrogram.from_samples(samples, rate, rhythm=False).values
    span = min(len(live) - 10, 300)

    def error(lag):
        return np.abs(whole[lag + START:lag + span] - live[START:span]).mean()

    lag = min(range(0, 100), key=error)
    shifted = whole[lag:]
    count = min(len(live) - 3, len(shifted))
    fixed = live[:count].copy()
    kept = np.arange(count) >= START
    previous = 0
    for first in range(START, count, SEGMENT):
        last = min(first + SEGMENT, count)
        best = min(range(-3, 4), key=lambda d: np.abs(
            live[first + d:last + d] - shifted[first:last]).mean())
        fixed[first:last] = live[first + best:last + best]
        if best != previous:  # the capture slipped within the last segment
            kept[max(START, first - SEGMENT):first + SLIP] = False
        previous = best
    for at in dropouts:  # stream samples; frame j is centred on sample j·rate/100
        frame = int(at * 100 // rate)
        kept[max(0, frame - 3):frame + SLIP] = False
    return lag * rate // 100, fixed, kept


@pytest.fixture(scope="module")
def clip(tmp_path_factory):
    return fake_clip(str(tmp_path_factory.mktemp("live")), CLIP, seconds=12)


def test_live_input_matches_the_offline_analysis(browser, live_server, clip, tmp_path):
    """`?source=mic` starts on the default input: the page's live loudness matches `eigendance
    spectrum` of the clip within 0.03 per band (after the start is aligned); live onsets reach
    F ≥ 0.8 against the offline onsets; after 10 s the page shows the offline tempo (within 2%)
    as "NNN BPM"; beats tick on the spectrum strip; the gallery's meshes and a rig move."""
    url = live_server["url"]
    with chromium(browser, FAKE + [GRANT, f"--use-file-for-fake-audio-capture={clip}%noloop"],
                  url, "?test&source=mic&size=2&scale=0.3") as page:
        first = wait_for(page, lambda s: s["seconds"] > 10.5)
        assert first["active"] and first["following"] and first["menu"] == "live:mic"
        assert first["window"] == 2048 and first["sampleRate"] == 44100
        tempo_at_10s = first["tempo"]
        shown = first["info"]
        ticks = page.evaluate("""async () => {  // the strip's beat tick, sampled for 2 s
            const seen = [];
            for (let i = 0; i < 40; i++) {
              seen.push(Number(getComputedStyle(document.getElementById('spectrum'))
                .getPropertyValue('--beat')));
              await new Promise((r) => setTimeout(r, 50));
            }
            return seen; }""")
        t = page.evaluate("window.eigendance.info().time")
        moved = np.abs(np.subtract(page.evaluate(f"window.eigendance.cpuPositions(0, {t})"),
                                   page.evaluate("window.eigendance.cpuPositions(0, 0)"))).max()
        rig = next(r["id"] for r in json.load(urllib.request.urlopen(url + "api/library"))["rigs"]
                   if r["name"] == "loop4")
        assert page.evaluate(f"window.eigendance.rig.open('{rig}')") is None
        t = page.evaluate("window.eigendance.info().time")
        rig_moves = [page.evaluate(f"window.eigendance.rig.coefficients(0, {t - dt})")
                     for dt in (0, 0.15, 0.3)]
        final = wait_for(page, lambda s: s["stats"]["samples"] > 12.3 * 44100, 30)
        live = np.array(page.evaluate("window.eigendance.liveInput.values()"))
        strength = np.array(page.evaluate("window.eigendance.liveInput.onsetStrength()"))
        assert page.evaluate("window.eigendance.info().error") is None

    np.savez(os.environ.get("EIGENDANCE_LIVE_DUMP", tmp_path / "live.npz"), live=live,
             strength=strength, onsets=final["onsets"], beats=final["beats"])
    shift, live, kept = aligned(clip, live, final["stats"]["dropoutsAt"])
    samples, rate = soundfile.read(clip, dtype="float32")
    soundfile.write(tmp_path / "from-start.wav", samples[shift:], rate, subtype="FLOAT")
    subprocess.run([sys.executable, "-m", "eigendance.cli", "spectrum",
                    str(tmp_path / "from-start.wav"), "-o", str(tmp_path / "offline.npz")],
                   check=True, capture_output=True)
    offline = np.load(tmp_path / "offline.npz")
    frames = min(len(offline["values"]), len(live)) - 5
    kept = kept[:frames]
    difference = np.abs(offline["values"][:frames] - live[:frames])[kept]
    per_band = np.percentile(difference, 99, axis=0)
    print(f"\nlive vs offline loudness ({len(difference)} frames, start shifted {shift} samples, "
          f"{frames - START - len(difference)} left out after {final['stats']['dropouts']} "
          f"dropouts and slips of the capture): per band 99th "
          f"percentile ≤ {per_band.max():.4f}, mean {difference.mean():.5f}, max "
          f"{difference.max():.4f} (frames off by more than {PARITY}: "
          f"{int((difference.max(axis=1) > PARITY).sum())})")
    assert len(difference) >= 0.7 * (frames - START), "the capture slipped too often to compare"
    assert per_band.max() <= PARITY
    assert difference.mean() <= PARITY / 10

    seconds = shift / rate
    heard = (frames - 10) / 100
    expected = offline["onsets"][offline["onsets"] < heard - 0.2]
    found = np.array(final["onsets"])  # live frame j and offline frame j: the same samples
    found = found[(found > START / 100) & (found < heard - 0.2)]
    expected = expected[expected > START / 100]
    f_onsets = mir_eval.onset.f_measure(expected, found, window=0.05)[0]
    tempo = float(offline["tempo"])
    print(f"live onsets F = {f_onsets:.3f} ({len(found)} vs {len(expected)} offline); tempo "
          f"after 10 s {tempo_at_10s:.1f} BPM vs offline {tempo:.1f} BPM; shown: {shown!r}; "
          f"clip start {seconds:.3f} s")
    assert f_onsets >= 0.8
    assert abs(tempo_at_10s - tempo) <= 0.02 * tempo
    assert f"{tempo_at_10s:.0f} BPM" in shown
    assert len(final["beats"]) >= 20 and max(ticks) > 0.3 and min(ticks) < max(ticks)
    assert moved > 1e-3  # the first tile dances to the input
    assert np.ptp(np.array(rig_moves), axis=0).max() > 1e-3  # and so does the rig


COUNTRY = fixture_path("audio", "emegeme_country_20s-45s.ogg")  # a real song, CC0


def test_live_tempo_of_a_real_song_is_the_offline_tempo(browser, live_server, tmp_path):
    """A real country song (whose tempo librosa's tracker finds at 72 BPM on this excerpt, and
    a tracker on a 100-frames-per-second envelope at 144): after 20 s the page's tempo is the
    offline tempo of the same samples within 4%, not its double or half."""
    clip = fake_clip(str(tmp_path), COUNTRY, seconds=22)
    with chromium(browser, FAKE + [GRANT, f"--use-file-for-fake-audio-capture={clip}%noloop"],
                  live_server["url"], "?test&source=mic&size=1&scale=0.3") as page:
        final = wait_for(page, lambda s: s["seconds"] > 20.5, 60)
        assert page.evaluate("window.eigendance.info().error") is None
    offline = Spectrogram.from_file(clip, bands=16).rhythm.tempo
    print(f"\nlive tempo {final['tempo']:.1f} BPM, offline {offline:.1f} BPM")
    assert abs(final["tempo"] - offline) <= 0.04 * offline


def test_source_mic_starts_when_the_first_model_is_a_rig(browser, web_files, clip, tmp_path):
    """`?source=mic` with a skinned glTF first in the library: the page opens on the rig and
    still starts the live input (it once returned before starting it), and the rig's tiles
    follow the input."""
    rig = fixture_path("rigged", "RiggedSimple.glb")
    with running_server([rig, web_files["song"]], tmp_path, tmp_path / "cache") as server, \
            chromium(browser, FAKE + [GRANT, f"--use-file-for-fake-audio-capture={clip}"],
                     server["url"], "?test&source=mic&size=2") as page:
        heard = wait_for(page, lambda s: s["seconds"] > 3)
        assert heard["active"] and heard["following"] and heard["menu"] == "live:mic"
        t = page.evaluate("window.eigendance.info().time")
        moves = [page.evaluate(f"window.eigendance.rig.coefficients(0, {t - dt})")
                 for dt in (0, 0.15, 0.3)]
        assert page.evaluate("window.eigendance.info().error") is None
    assert np.ptp(np.array(moves), axis=0).max() > 1e-3


def test_nothing_gets_stuck(browser, live_server, tmp_path):
    """Permission denied and no input device: one clear line, the song plays on; a device
    unplugged mid-take: one line, back to the song, its stream closed; switching between the
    input and songs leaves no stream open; the latency offset is remembered for the input; a
    96 kHz clip plays as any other."""
    url = live_server["url"]
    start = "window.eigendance.liveInput.start('mic')"
    with chromium(browser, [], url) as page:  # headless without a fake device: none
        assert page.evaluate(start) is False
        error = page.evaluate("window.eigendance.info().error")
        assert error.startswith("Live input:") and "\n" not in error, error
        assert not state(page)["following"] and state(page)["liveTracks"] == 0
        page.evaluate("window.eigendance.setView('player')")  # the page still works with files
    with chromium(browser, FAKE, url) as page:  # a device, but the permission is refused
        assert page.evaluate(start) is False
        error = page.evaluate("window.eigendance.info().error")
        assert "permission denied" in error, error
    clip = fake_clip(str(tmp_path), CLIP, 96000, seconds=4)
    with chromium(browser, FAKE + [GRANT, f"--use-file-for-fake-audio-capture={clip}"],
                  url) as page:
        assert page.evaluate(start) is True
        running = wait_for(page, lambda s: s["seconds"] > 1)
        assert running["seconds"] > 1 and running["running"] == 1
        page.evaluate("window.eigendance.liveInput.setOffset(0.12)")  # the delay slider
        assert abs(state(page)["latency"] - running["latency"] - 0.12) < 1e-9
        song = page.evaluate("window.eigendance.info().songId")
        page.select_option("#song", song)  # a song from the menu: the input stops
        stopped = wait_for(page, lambda s: not s["following"], 10)
        assert stopped["running"] == 0 and stopped["liveTracks"] == 0 and not stopped["active"]
        page.select_option("#song", "live:mic")  # and again
        again = wait_for(page, lambda s: s["seconds"] > 0.5)
        assert again["opened"] == 2 and again["running"] == 1
        assert again["offset"] == 0.12  # remembered for this input
        # the device goes away: the browser ends its track ("ended")
        page.evaluate("window.eigendance.liveInput.unplug()")
        after = wait_for(page, lambda s: not s["following"], 10)
        error = page.evaluate("window.eigendance.info().error")
        assert "stopped (unplugged" in error, error
        assert after["running"] == 0 and after["liveTracks"] == 0
        assert page.evaluate("window.eigendance.info().songId") == song
        assert page.eval_on_selector("#song", "menu => menu.value") == song


def test_a_live_take_becomes_a_song(browser, live_server, clip, tmp_path):
    """*save take*: the take so far is a song of the library (decoded and analysed by the
    server like any upload); `record` writes the live sound with the picture; api/takes
    refuses what is not audio, and a foreign Origin."""
    url = live_server["url"]
    with chromium(browser, FAKE + [GRANT, f"--use-file-for-fake-audio-capture={clip}"],
                  url) as page:
        assert page.evaluate("window.eigendance.liveInput.start('mic')") is True
        heard = wait_for(page, lambda s: s["seconds"] > 3)["seconds"]
        song = page.evaluate("window.eigendance.liveInput.save()")
        assert song, page.evaluate("window.eigendance.info().error")
        songs = json.load(urllib.request.urlopen(url + "api/library"))["songs"]
        saved = next(s for s in songs if s["id"] == song)
        assert saved["name"].startswith("live take ") and abs(saved["duration"] - heard) < 1.5
        assert state(page)["following"]  # saving does not stop the input
        page.click("#tab-player")
        page.click("#record")
        page.wait_for_timeout(2000)
        with page.expect_download(timeout=30_000) as download:
            page.click("#record")
        download.value.save_as(tmp_path / "live.webm")
    with av.open(str(tmp_path / "live.webm")) as container:
        assert container.streams.video and container.streams.audio
        sound = np.concatenate([frame.to_ndarray().ravel()
                                for frame in container.decode(audio=0)])
    assert np.sqrt(np.mean(np.square(sound))) > 0.01  # the clip, heard through the input
    for name, origin, status in (("take.obj", None, 415), ("take.webm", "http://evil.example",
                                                             403)):
        request = urllib.request.Request(f"{url}api/takes?name={name}", data=b"\x1aE\xdf\xa3",
                                         method="POST")
        if origin:
            request.add_header("Origin", origin)
        with pytest.raises(urllib.error.HTTPError) as refused:
            urllib.request.urlopen(request)
        assert refused.value.code == status


def test_save_take_downloads_the_take_and_says_where_it_is(browser, live_server, clip, tmp_path):
    """Use (round 3): *save take* said "saving…" for as long as the server analysed the take, and
    no file reached the person. Clicking it now downloads the take at once under a name that
    says what and when (live-take-DATE-TIME.webm), a recording as long as what was heard; the
    status says it was downloaded, then that the take is in the song menu, which lists it."""
    with chromium(browser, FAKE + [GRANT, f"--use-file-for-fake-audio-capture={clip}"],
                  live_server["url"], "?test&size=1&source=mic") as page:
        heard = wait_for(page, lambda s: s["seconds"] > 4)["seconds"]
        with page.expect_download(timeout=30_000) as download:
            page.click("#live-save")
        said = page.text_content("#status")
        name = download.value.suggested_filename
        download.value.save_as(tmp_path / name)
        page.wait_for_function("document.getElementById('status').textContent"
                               ".includes('is in the song menu')", timeout=120_000)
        done = page.text_content("#status")
        listed = page.eval_on_selector_all("#song option", "options => options.map("
                                           "o => o.textContent)")
    assert re.fullmatch(r"live-take-\d{4}-\d\d-\d\d-\d\d-\d\d-\d\d\.(webm|ogg)", name), name
    assert "downloaded" in said and name in said, said
    assert "is in the song menu" in done, done
    assert any(option.startswith("live take ") for option in listed), listed
    with av.open(str(tmp_path / name)) as container:
        seconds = sum(frame.samples / frame.sample_rate for frame in container.decode(audio=0))
    assert abs(seconds - heard) < 2, (seconds, heard)
