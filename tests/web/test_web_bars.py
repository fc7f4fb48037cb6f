"""Bars and sections on the page's spectrum strip (docs/design.md#rhythm): a song made of two
real excerpts joined end to end (a country song, then Vibe Ace), served by `eigendance serve`;
the strip marks a section start near the join, its top edge ticks twice as bright on a
downbeat as on another beat, and its tooltip names the meter and the number of sections.

Select with `pytest -m web`; skipped where /usr/bin/chromium is missing.
"""

from __future__ import annotations

import json
import os
import urllib.request
from dataclasses import replace

import numpy as np
import pytest
import soundfile
from web_helpers import CAT, open_app, running_server

from eigendance.harmonic.basis import HarmonicBasis
from eigendance.harmonic.motion import positions_at
from eigendance.music.decode import mono, read_audio
from eigendance.music.gallery import initial_gallery
from eigendance.music.spectrogram import Spectrogram
from eigendance.server.binary import unpack
from helpers import fixture_path

pytestmark = pytest.mark.web
SR = 22050
K = 12
PARTS = [fixture_path("audio", "emegeme_country_20s-45s.ogg"),  # CC0, 25 s
         fixture_path("audio", "kevin_macleod_vibe_ace_0s-21s.ogg")]  # CC BY 3.0, 21 s


@pytest.fixture(scope="module")
def served(web_files, tmp_path_factory):
    """The two excerpts at 22.05 kHz joined into a WAV file (and analysed), served with the
    cat, a mapping whose section gene is [1, 0] (the dance stops in every other part of the
    song) and k = 12: {url, ..., join (s), song, mapping}."""
    folder = tmp_path_factory.mktemp("bars")
    pieces = []
    for path in PARTS:
        samples, rate = read_audio(path)
        assert rate == SR
        pieces.append(mono(samples))
    soundfile.write(folder / "joined.wav", np.concatenate(pieces), SR, subtype="PCM_16")
    song = Spectrogram.from_file(folder / "joined.wav")  # as the server analyses it
    mapping = replace(initial_gallery(HarmonicBasis.from_mesh(CAT, K), song, size=4)[0],
                      sections=[1.0, 0.0], name="sections.json")
    mapping.save(folder / "sections.json")
    with running_server([CAT, str(folder / "joined.wav"), str(folder / "sections.json"), "-k",
                         str(K)], folder, web_files["cache"]) as server:
        yield {**server, "join": len(pieces[0]) / SR, "song": song, "mapping": mapping}


def strip_state(page, t):
    page.evaluate(f"window.eigendance.renderAt({t})")
    return page.evaluate("""() => { const s = document.getElementById('spectrum');
      return { beat: Number(s.style.getPropertyValue('--beat')), title: s.title,
        marks: [...s.querySelectorAll('i.section')].map((m) => parseFloat(m.style.left)) }; }""")


def test_the_strip_shows_downbeats_and_sections(browser, served):
    server, join = served, served["join"]
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


def test_a_section_gene_changes_the_dance_at_a_section_as_in_python(browser, served, web_files):
    """Gene [1, 0]: the dance as without the gene in the first part, the mesh at rest in the
    second (φ − 1 = 0·(…), by hand), and the page's positions equal Python's at both."""
    os.environ["EIGENDANCE_CACHE_DIR"] = web_files["cache"]
    basis = HarmonicBasis.from_mesh(CAT, K)  # the server's, cached
    song, mapping = served["song"], served["mapping"]
    starts = song.rhythm.sections
    assert len(starts) >= 1
    before, after = starts[0] - 1.0, starts[0] + 1.0
    rest = basis.to_original(basis.vertices)
    diagonal = np.linalg.norm(np.ptp(rest, axis=0))
    expected = {t: positions_at(basis, song, mapping, t) for t in (before, after)}
    plain = positions_at(basis, song, replace(mapping, sections=None), before)
    np.testing.assert_allclose(expected[before], plain, atol=1e-9 * diagonal)
    assert np.abs(expected[before] - rest).max() > 1e-3 * diagonal
    np.testing.assert_allclose(expected[after], rest, atol=1e-9 * diagonal)
    with urllib.request.urlopen(served["url"] + "api/library") as answer:
        mapping_id = next(m["id"] for m in json.load(answer)["mappings"])
    page = open_app(browser, served["url"], f"?render&view=player&mapping={mapping_id}")
    try:
        page.wait_for_function("window.eigendance.info().k > 0", timeout=120_000)
        assert page.evaluate("window.eigendance.playerMapping()")["sections"] == [1.0, 0.0]
        for t in (before, after):
            found = np.array(page.evaluate(f"window.eigendance.cpuPositions('player', {t})"))
            error = np.abs(basis.to_original(found.reshape(-1, 3)) - expected[t]).max()
            assert error < 1e-4 * diagonal, (t, error / diagonal)
        assert not page.errors, page.errors
    finally:
        page.close()
