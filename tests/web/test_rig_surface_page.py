"""The rig player's surface in headless Chromium (docs/design.md#surface-of-a-rig): off by
default; on, the skin's harmonics ripple on the GPU (and the CPU path) as the Python's
`SurfaceDance` says, added to the modal skin.

Select with `pytest -m web`; skipped where /usr/bin/chromium is missing.
"""

from __future__ import annotations

import numpy as np
import pytest
from web_helpers import pinned_gpu_app, rig_ids_at

from eigendance.modal.motion import rig_coefficients
from eigendance.modal.rig import Rig
from eigendance.modal.sample_rigs import sample_rig
from eigendance.modal.surface import SurfaceDance, surface_share
from eigendance.music.gallery import initial_gallery
from eigendance.music.mapping import Mapping
from eigendance.music.spectrogram import Spectrogram

pytestmark = pytest.mark.web
TIMES = (0.4, 1.3, 2.9)
SWITCH = """(on) => { const box = document.getElementById('rig-surface');
  box.checked = on; box.dispatchEvent(new Event('change')); }"""


@pytest.fixture(scope="module")
def page(browser, live_server):
    with pinned_gpu_app(browser, live_server["url"]) as page:
        yield page


def test_the_surface_ripples_the_skin_on_the_gpu_as_python_does(page, live_server, web_files):
    hand = rig_ids_at(live_server["url"])["hand"]
    assert page.evaluate(f"window.eigendance.rig.open('{hand}')") is None
    assert page.evaluate("document.getElementById('rig-surface').checked") is False  # off
    diagonal = page.evaluate("window.eigendance.rig.info()")["diagonal"]
    rig = Rig.from_skeleton(sample_rig("hand"), dtype=np.float64)
    song = Spectrogram.from_file(web_files["song"])
    mapping = Mapping.from_json(page.evaluate("window.eigendance.rig.playerMapping()"))
    bones = rig.skin.positions(rig_coefficients(rig.model, song, mapping, TIMES))
    off = np.array(page.evaluate(f"window.eigendance.rig.readPositions('player', {TIMES[1]})"))
    np.testing.assert_allclose(off.reshape(-1, 3), bones[1], atol=1e-4 * diagonal)
    page.evaluate(SWITCH, True)
    page.wait_for_function("!document.getElementById('rig-surface-dance').disabled")
    ripple = SurfaceDance(rig.surface(), song, initial_gallery(rig.surface().basis, song, 8)[0])
    expected = bones + ripple.displacements(TIMES)  # first order, as the page's modal skin
    for i, t in enumerate(TIMES):
        for path in ("readPositions", "cpuPositions"):
            shown = np.array(page.evaluate(f"window.eigendance.rig.{path}('player', {t})"))
            np.testing.assert_allclose(shown.reshape(-1, 3), expected[i], atol=1e-4 * diagonal)
    assert np.abs(expected - bones).max() > 1e-3 * diagonal  # it ripples
    # The share shown beside the gain: `surface_share` over 16 moments spread over the song.
    moments = (np.arange(16) + 0.5) * song.duration / 16
    still = rig.skin.positions(rig_coefficients(rig.model, song, mapping, moments))
    share = surface_share(still, still + ripple.displacements(moments), rig.skeleton.vertices)
    shown = page.evaluate("document.getElementById('rig-surface-share').textContent")
    assert shown.endswith("% of the motion") and 0 < share < 1, shown
    assert abs(int(shown.split("%")[0]) - 100 * share) <= 1, (shown, share)  # float32, rounding
    page.evaluate(SWITCH, False)
    page.wait_for_function("document.getElementById('rig-surface-dance').disabled")
    back = np.array(page.evaluate(f"window.eigendance.rig.readPositions('player', {TIMES[1]})"))
    np.testing.assert_allclose(back.reshape(-1, 3), bones[1], atol=1e-4 * diagonal)
