"""The player's recording is seekable (issue 13 item 5): the WebM that the record button offers
carries its duration, so a player shows a seek bar and jumps into it. Checked with FFmpeg's
demuxer (PyAV) and with Chromium's own <video> element. It is the player's view alone, at its
size (issue 22): not the whole window with the page's bars as empty bands."""

from __future__ import annotations

import base64
import time

import av
import numpy as np
import pytest

RECORD_SECONDS = 2.0


@pytest.fixture(scope="module")
def recording(browser, live_server, tmp_path_factory):
    """(bytes of a ~2 s recording of the player, seconds between the two clicks, page)."""
    page = browser.new_page(viewport={"width": 640, "height": 480}, accept_downloads=True)
    page.goto(live_server["url"] + "?test&size=4&path=cpu")
    page.wait_for_function("window.eigendance && window.eigendance.ready", timeout=60_000)
    page.evaluate("window.eigendance.ready")
    page.click("#tab-player")
    box = page.eval_on_selector("#player-area", "a => { const r = a.getBoundingClientRect(); "
                                                "return [r.width, r.height]; }")
    started = time.monotonic()
    page.click("#record")  # starts playback too
    page.wait_for_timeout(RECORD_SECONDS * 1000)
    with page.expect_download(timeout=30_000) as download:
        page.click("#record")
        span = time.monotonic() - started
    assert download.value.suggested_filename == "cat_lowres-dance.webm"
    path = tmp_path_factory.mktemp("recording") / "eigendance.webm"
    download.value.save_as(path)
    page.recorded_view = box
    yield path.read_bytes(), span, page
    page.close()


def test_the_recording_has_its_duration_and_seeks_in_ffmpeg(recording, tmp_path):
    data, span, _ = recording
    path = tmp_path / "recording.webm"
    path.write_bytes(data)
    with av.open(str(path)) as container:
        assert container.duration is not None  # MediaRecorder alone writes none
        duration = container.duration / av.time_base
        assert RECORD_SECONDS - 0.3 < duration <= span + 0.3, (duration, span)
        ends = [float((packet.pts + (packet.duration or 0)) * packet.time_base)
                for packet in container.demux() if packet.pts is not None]
    assert abs(max(ends) - duration) < 0.25, (max(ends), duration)  # the duration is the file's
    with av.open(str(path)) as container:
        middle = duration / 2
        container.seek(int(middle * av.time_base), backward=True)
        frame = next(container.decode(video=0))  # decodes from where the seek landed
        assert frame.time is not None and frame.time <= middle + 0.1
        later = [f.time for f in container.decode(video=0)]
    assert later and max(later) >= middle  # and plays on past the middle


def test_the_recording_is_the_players_view_at_its_size(recording, tmp_path):
    """Frames of the view's size (even sides), holding the model in its studio: no row or
    column of the bare page's colour (#15171c), the empty bands where the header and the
    controls lie when the whole window was recorded."""
    data, _, page = recording
    path = tmp_path / "recording.webm"
    path.write_bytes(data)
    width, height = page.recorded_view
    with av.open(str(path)) as container:
        frames = [frame.to_ndarray(format="rgb24") for _, frame in
                  zip(range(12), container.decode(video=0), strict=False)]
    frame = frames[-1].astype(int)
    assert abs(frame.shape[1] - width) <= 2 and abs(frame.shape[0] - height) <= 2, \
        (frame.shape, width, height)
    bare = np.abs(frame - [21, 23, 28]).max(axis=-1) <= 2
    rows, columns = bare.mean(axis=1), bare.mean(axis=0)
    assert rows.max() < 0.5 and columns.max() < 0.5, \
        f"empty bands: rows {np.flatnonzero(rows >= 0.5)}, columns {np.flatnonzero(columns >= 0.5)}"
    clay = ((frame[..., 0] > 120) & (frame[..., 0] > frame[..., 2] + 30)).mean()
    assert clay > 0.02, f"the model covers only {clay:.1%} of the recording"


def test_the_recording_seeks_in_the_browsers_video_element(recording):
    data, _, page = recording
    result = page.evaluate("""async (data) => {
        const bytes = Uint8Array.from(atob(data), (c) => c.charCodeAt(0));
        const video = document.createElement("video");
        video.muted = true;
        video.src = URL.createObjectURL(new Blob([bytes], { type: "video/webm" }));
        await new Promise((resolve, reject) => {
            video.onloadedmetadata = resolve; video.onerror = () => reject(video.error); });
        const duration = video.duration;
        const target = duration / 2;
        await new Promise((resolve) => { video.onseeked = resolve; video.currentTime = target; });
        return { duration, target, time: video.currentTime,
                 seekable: video.seekable.length ? video.seekable.end(0) : 0 };
    }""", base64.b64encode(data).decode())
    assert result["duration"] == pytest.approx(result["seekable"], abs=0.25)
    assert 0 < result["duration"] < 60  # finite: not the live stream's Infinity
    assert result["time"] == pytest.approx(result["target"], abs=0.05)
