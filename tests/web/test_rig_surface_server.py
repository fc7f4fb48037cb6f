"""The rig's surface in the API (docs/design.md#surface-of-a-rig): the skin's harmonics as the
page's positions pass reads them, and the gallery of surface dances."""

from __future__ import annotations

import numpy as np
import pytest
from starlette.testclient import TestClient
from web_helpers import write_song

from eigendance.modal.rig import Rig
from eigendance.modal.sample_rigs import sample_rig
from eigendance.modal.surface import SurfaceDance
from eigendance.music.gallery import initial_gallery
from eigendance.music.mapping import Mapping
from eigendance.server.app import create_app
from eigendance.server.binary import unpack
from eigendance.server.library import Library


@pytest.fixture
def client(tmp_path):
    library = Library(str(tmp_path / "library"), k=8, max_upload_bytes=2_000_000)
    library.add_path(write_song(tmp_path / "tune.wav", 3.0))
    with TestClient(create_app(library), base_url="http://localhost") as test_client:
        test_client.library = library
        yield test_client
    library.close()


def ids(client) -> tuple[str, str]:
    data = client.get("/api/library").json()
    return (next(r["id"] for r in data["rigs"] if r["name"] == "hand"),
            data["songs"][0]["id"])


def test_the_skins_harmonics_and_its_gallery_play_the_python_ripple(client):
    """Per vertex, Σ_texels W·texel with W = (φ − 1)·X̃ (what the page adds to the modal
    skin's texels) is `SurfaceDance.displacements` within 1e-6 of the diagonal (float32)."""
    hand, song = ids(client)
    response = client.get(f"/api/rigs/{hand}/surface.bin")
    assert response.status_code == 200, response.text
    meta, arrays = unpack(response.content)
    rig = Rig.from_skeleton(sample_rig("hand"), dtype=np.float64)
    skin = rig.surface()
    assert meta["kind"] == "rig-surface" and meta["k"] == skin.k
    assert arrays["harmonics"].shape == (len(rig.skeleton.vertices), 4 * meta["groups"])
    answer = client.post("/api/rig-surface-gallery",
                         json={"rig": hand, "song": song, "size": 4}).json()
    spectrogram = client.library.songs[song].spectrogram
    expected = initial_gallery(skin.basis, spectrogram, 4)
    assert answer["mappings"] == [m.to_json() for m in expected]
    mapping = Mapping.from_json(answer["mappings"][1])
    dance = SurfaceDance(skin, spectrogram, mapping)
    times = np.array([0.5, 1.5, 2.5])
    phi = dance.phi(times)
    U = arrays["harmonics"][:, :meta["k"]].astype(float)
    moved = np.einsum("nk,tk,kd->tnd", U, phi - 1, arrays["coefficients"].astype(float))
    diagonal = np.linalg.norm(np.ptp(rig.skeleton.vertices, axis=0))
    reference = dance.displacements(times)
    np.testing.assert_allclose(moved, reference, atol=1e-6 * diagonal)
    assert np.abs(reference).max() > 1e-3 * diagonal
    assert client.get("/api/rigs/nope/surface.bin").status_code == 404
    assert client.post("/api/rig-surface-gallery",
                       json={"rig": hand, "song": "nope"}).status_code == 404
