"""Bars and sections on the page's spectrum strip (docs/design.md#rhythm): a song made of two
real excerpts joined end to end (a country song, then Vibe Ace), served by `eigendance serve`;
the strip marks a section start near the join, its top edge ticks twice as bright on a
downbeat as on another beat, and its tooltip names the meter and the number of sections.

Select with `pytest -m web`; skipped where /usr/bin/chromium is missing.
"""

from __future__ import annotations

import json
import urllib.request

import numpy as np
import pytest
import soundfile
from web_helpers import CAT, open_app, running_server

from eigendance.music.decode import mono, read_audio
from eigendance.server.binary import unpack
from helpers import fixture_path

pytestmark = pytest.mark.web
SR = 22050
PARTS = [fixture_path("audio", "emegeme_country_20s-45s.ogg"),  # CC0, 25 s
         fixture_path("audio", "kevin_macleod_vibe_ace_0s-21s.ogg")]  # CC BY 3.0, 21 s


@pytest.fixture(scope="module")
def joined(tmp_path_factory):
    """The two excerpts at 22.05 kHz joined into one WAV; the join's time, s."""
    folder = tmp_path_factory.mktemp("bars")
    pieces = []
    for path in PARTS:
        samples, rate = read_audio(path)
        assert rate == SR
        pieces.append(mono(samples))
    path = folder / "joined.wav"
    soundfile.write(path, np.concatenate(pieces), SR, subtype="PCM_16")
    return folder, str(path), len(pieces[0]) / SR


def strip_state(page, t):
    page.evaluate(f"window.eigendance.renderAt({t})")
    return page.evaluate("""() => { const s = document.getElementById('spectrum');
      return { beat: Number(s.style.getPropertyValue('--beat')), title: s.title,
        marks: [...s.querySelectorAll('i.section')].map((m) => parseFloat(m.style.left)) }; }""")


def test_the_strip_shows_downbeats_and_sections(browser, joined, web_files):
    folder, song, join = joined
    with running_server([CAT, song, "-k", "12"], folder, web_files["cache"]) as server:
        with urllib.request.urlopen(server["url"] + "api/library") as answer:
            song_id = json.load(answer)["songs"][0]["id"]
        with urllib.request.urlopen(server["url"] + f"api/songs/{song_id}/spectrogram.bin") \
                as answer:
            meta, arrays = unpack(answer.read())
        assert meta["meter"] in (3, 4) and len(arrays["downbeats"]) >= 4
        assert set(np.round(arrays["downbeats"], 4)) <= set(np.round(arrays["beats"], 4))
        page = open_app(browser, server["url"], "?render&size=4")
        try:
            downbeat = float(arrays["downbeats"][2])
            other = float(next(b for b in arrays["beats"] if b > downbeat))
            at_downbeat, at_other = strip_state(page, downbeat), strip_state(page, other)
            # the tick's rule: 1 on a downbeat, ½ on another beat, at the event itself
            assert at_downbeat["beat"] == pytest.approx(1.0, abs=2e-3)
            assert at_other["beat"] == pytest.approx(0.5, abs=2e-3)
            marks = np.array(at_downbeat["marks"]) / 100 * meta["duration"]
            assert len(marks) == len(arrays["sections"]) >= 1
            assert np.min(np.abs(marks - join)) <= 3.0, (join, marks)
            title = at_downbeat["title"]
            assert f"in {meta['meter']}/4" in title and f"{len(marks) + 1} sections" in title
            assert not page.errors, page.errors
        finally:
            page.close()
