"""Fixtures of the show's tests: a show served in-process, with OSC in on a free port."""

from __future__ import annotations

from types import SimpleNamespace

import pytest
from starlette.testclient import TestClient

from eigendance.presets.store import PresetStore
from eigendance.server.app import create_app
from eigendance.server.serve import library_session
from eigendance.show.osc import OscIn
from eigendance.show.state import ShowState


@pytest.fixture
def served_show(tmp_path):
    """A `ShowState` behind the app (`client`) and OSC in on 127.0.0.1 (`osc.port`)."""
    with library_session(k=12) as library:
        state = ShowState()
        client = TestClient(create_app(library, presets=PresetStore(tmp_path), show=state),
                            base_url="http://127.0.0.1:8765")
        osc = OscIn(state, "127.0.0.1", 0)
        try:
            yield SimpleNamespace(state=state, client=client, osc=osc)
        finally:
            osc.stop()
