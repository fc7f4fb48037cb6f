"""A mapping saved in the page, run through `eigendance animate` with no option but the mapping,
dances as the page showed it (issue 29): the mapping records the basis the page played on (k,
exact or reduced), and the command line solves that basis instead of its own default."""

from __future__ import annotations

import numpy as np
import pytest
from web_helpers import CAT, E2E_K, open_app

from eigendance.cli import main
from eigendance.harmonic.basis import HarmonicBasis
from eigendance.harmonic.construction import BasisRecord
from eigendance.harmonic.motion import load_animation
from eigendance.inputs.defaults import DEFAULT_K
from eigendance.music.mapping import Mapping

pytestmark = pytest.mark.web


def assert_player_shows(page, animation, basis, frames=(4, 37, 150)):
    """The page's player shows the animation's positions at its frames' times, within 1e-4 of
    the model's diagonal (`basis`: the page's, for the normalisation and the size)."""
    diagonal = np.linalg.norm(np.ptp(basis.to_original(basis.vertices), axis=0))
    for frame in frames:
        t = float(animation["times"][frame])
        shown = np.array(page.evaluate(f"window.eigendance.readPositions('player', {t})"))
        error = np.abs(basis.to_original(shown.reshape(-1, 3))
                       - animation["positions"][frame]).max() / diagonal
        assert error < 1e-4, f"frame {frame} (t = {t:.2f} s): {error:.2e} of the diagonal"


def test_a_mapping_saved_in_the_page_dances_the_same_under_animate(browser, live_server,
                                                                   web_files, tmp_path,
                                                                   monkeypatch, capsys):
    assert E2E_K != DEFAULT_K  # the server's k is not the command line's default
    monkeypatch.setenv("EIGENDANCE_CACHE_DIR", web_files["cache"])
    page = open_app(browser, live_server["url"], "?render&size=4")
    page.evaluate("window.eigendance.open(1)")
    with page.expect_download() as download:
        page.click("#save-mapping")
    path = tmp_path / "from-page.json"
    download.value.save_as(path)
    assert Mapping.load(path).basis == BasisRecord(E2E_K, "exact", None)

    output = tmp_path / "dance.npz"
    assert main(["animate", CAT, web_files["song"], "--mapping", str(path),
                 "-o", str(output)]) == 0
    assert "note" not in capsys.readouterr().err  # the mapping's own basis: nothing to say
    basis = HarmonicBasis.from_mesh(CAT, E2E_K)  # the page's (the shared cache's), for the size
    assert_player_shows(page, load_animation(output), basis)

    # told otherwise, it says in one line how the dance will differ
    assert main(["animate", CAT, web_files["song"], "--mapping", str(path), "-k", "30",
                 "--duration", "0.5", "-o", str(tmp_path / "other.npz")]) == 0
    notes = [line for line in capsys.readouterr().err.splitlines() if "note" in line]
    assert len(notes) == 1 and f"made on k = {E2E_K} harmonics (exact)" in notes[0] \
        and "k = 30" in notes[0], notes
    assert not page.errors, page.errors
    page.close()
