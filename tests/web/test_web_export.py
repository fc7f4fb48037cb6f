"""The page's export route (issue 22 item 3): part of a song as a glb or an MP4, rendered in a
job with progress, then downloaded; guarded and limited like every route.

The clip is checked against numbers made without the window code: the glb's morph weights at
clip time t are the mapping's filter of the song at start + t (`Mapping.filter` of the
spectrogram read there), the MP4's streams last the clip, not the song.
"""

from __future__ import annotations

import io
import json
import os
import time

import av
import numpy as np
import pygltflib
import pytest
from starlette.testclient import TestClient
from web_helpers import write_icosphere, write_song

from eigendance.harmonic.motion import positions_at
from eigendance.modal.rig import Rig
from eigendance.modal.sample_rigs import sample_rig
from eigendance.music.gallery import initial_gallery
from eigendance.music.spectrogram import Spectrogram
from eigendance.server.app import create_app
from eigendance.server.library import Library

SONG_SECONDS = 3.0


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    folder = tmp_path_factory.mktemp("export-files")
    return {"mesh": write_icosphere(folder / "ball.obj", 2),
            "song": write_song(folder / "tune.wav", SONG_SECONDS)}


@pytest.fixture(scope="module")
def client(files, tmp_path_factory):
    library = Library(str(tmp_path_factory.mktemp("library")), k=12)
    for path in (files["mesh"], files["song"]):
        library.add_path(path)
    app = create_app(library)
    assert library.wait(60)
    with TestClient(app, base_url="http://localhost") as test_client:
        data = test_client.get("/api/library").json()
        test_client.ids = {"mesh": data["meshes"][0]["id"], "song": data["songs"][0]["id"],
                           "loop4": next(r["id"] for r in data["rigs"] if r["name"] == "loop4")}
        test_client.library = library
        yield test_client
    library.close()


@pytest.fixture(scope="module")
def mapping(client, files):
    """An initial-gallery item of the mesh on the song: one that moves."""
    library = client.library
    mesh = library.get("mesh", client.ids["mesh"])
    song = Spectrogram.from_file(files["song"])
    return initial_gallery(mesh.basis, song, 4)[1]


def finished(client, job: dict, seconds: float = 120.0) -> dict:
    """The job once done (or failed), polled as the page's fallback does."""
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        state = client.get(f"/api/jobs/{job['id']}").json()
        if state["state"] in ("done", "error"):
            return state
        time.sleep(0.1)
    raise AssertionError(f"export job {job['id']} did not finish: {state}")


def export(client, **fields) -> tuple[dict, bytes]:
    response = client.post("/api/export", json=fields)
    assert response.status_code == 202, response.text
    state = finished(client, response.json()["job"])
    assert state["state"] == "done", state
    assert state["done"] == state["total"] > 0
    download = client.get(f"/api/exports/{state['id']}")
    assert download.status_code == 200
    return state, download.content


def test_a_glb_of_part_of_the_song_moves_as_the_song_does_there(client, mapping, files):
    start, duration, fps = 1.2, 1.0, 10
    _, data = export(client, mesh=client.ids["mesh"], song=client.ids["song"],
                     mapping=mapping.to_json(), format="glb", start=start, duration=duration,
                     fps=fps)
    gltf = pygltflib.GLTF2.load_from_bytes(data)
    assert gltf.extras["eigendance"]["start"] == pytest.approx(start)
    assert gltf.extras["eigendance"]["duration"] == pytest.approx(duration)
    sampler = gltf.animations[0].samplers[0]
    times = read_accessor(gltf, sampler.input)
    np.testing.assert_allclose(times, np.arange(11) / fps, atol=1e-6)  # the clip's own clock
    primitive = gltf.meshes[0].primitives[0]
    rest = read_accessor(gltf, primitive.attributes.POSITION).reshape(-1, 3)
    targets = np.stack([read_accessor(gltf, target["POSITION"]).reshape(-1, 3)
                        for target in primitive.targets])
    weights = read_accessor(gltf, sampler.output).reshape(len(times), len(targets))
    played = rest[None] + np.einsum("tj,jnc->tnc", weights, targets)  # as a glTF player does
    basis = client.library.get("mesh", client.ids["mesh"]).basis
    song = Spectrogram.from_file(files["song"])
    expected = positions_at(basis, song, mapping, start + times)  # the song at start + t
    np.testing.assert_allclose(played, expected, atol=1e-5)
    whole = positions_at(basis, song, mapping, times)
    assert not np.allclose(played, whole, atol=1e-3)  # not the song's first second


def read_accessor(gltf, index: int) -> np.ndarray:
    accessor = gltf.accessors[index]
    view = gltf.bufferViews[accessor.bufferView]
    blob = gltf.binary_blob()
    width = {"SCALAR": 1, "VEC3": 3, "VEC4": 4}[accessor.type]
    start = view.byteOffset + (accessor.byteOffset or 0)
    return np.frombuffer(blob, "<f4", accessor.count * width, start).copy()


def test_an_mp4_of_part_of_the_song_lasts_the_clip_with_its_sound(client, mapping):
    state, data = export(client, mesh=client.ids["mesh"], song=client.ids["song"],
                         mapping=mapping.to_json(), format="mp4", start=2.0, duration=0.5,
                         size="160x120", fps=20)
    assert state["total"] == 10  # frames: ⌈0.5 s × 20 fps⌉
    with av.open(io.BytesIO(data)) as container:
        video = container.streams.video[0]
        audio = container.streams.audio[0]
        assert (video.codec_context.width, video.codec_context.height) == (160, 120)
        assert video.frames == 10
        seconds = float(audio.duration * audio.time_base)
    assert 0.4 <= seconds <= 0.6, seconds  # that part's sound, not the song's 3 s


def test_a_rig_exports_its_clip_too(client):
    mapping = {"format": "eigendance.mapping", "version": 2, "bands": 64,
               "transfer": [0.5] * 64, "amplification": [0.05], "offset": 1.0}
    _, data = export(client, rig=client.ids["loop4"], song=client.ids["song"], mapping=mapping,
                     format="glb", start=0.5, duration=1.0, fps=10)
    gltf = pygltflib.GLTF2.load_from_bytes(data)
    assert gltf.skins and gltf.extras["eigendance"]["start"] == pytest.approx(0.5)
    times = read_accessor(gltf, gltf.animations[0].samplers[0].input)
    assert times.max() == pytest.approx(1.0)


def test_a_rig_with_surface_genes_exports_its_ripple_as_morph_targets(client, files):
    """The page exports what its player plays: a rig mapping's surface genes ripple the skin
    (docs/design.md#surface-of-a-rig), the glb's morph targets under the skin, one per driven
    harmonic, with the genes in its extras."""
    rig = Rig.from_skeleton(sample_rig("loop4"))
    song = Spectrogram.from_file(files["song"])
    genes = initial_gallery(rig.surface().basis, song, 4)[0]
    bones = {"format": "eigendance.mapping", "version": 2, "bands": 64,
             "transfer": [0.5] * 64, "amplification": [0.05], "offset": 1.0}
    whole = {**bones, "version": 3, "surface": genes.to_json()}  # as the page saves it
    _, data = export(client, rig=client.ids["loop4"], song=client.ids["song"], mapping=whole,
                     format="glb", start=0.5, duration=1.0, fps=10)
    gltf = pygltflib.GLTF2.load_from_bytes(data)
    driven = len(genes.driven(rig.surface().k))  # the harmonics its bands reach
    assert gltf.skins and len(gltf.meshes[0].primitives[0].targets) == driven > 0
    played = gltf.extras["eigendance"]["surface"]["mapping"]
    np.testing.assert_allclose(played["amplification"], genes.amplification)
    _, plain = export(client, rig=client.ids["loop4"], song=client.ids["song"], mapping=bones,
                      format="glb", start=0.5, duration=1.0, fps=10)
    assert not pygltflib.GLTF2.load_from_bytes(plain).meshes[0].primitives[0].targets


@pytest.mark.parametrize(("fields", "status", "words"), [
    ({"format": "avi"}, 400, "format"),
    ({"start": 3.5}, 400, "cannot start at 3.5 s"),
    ({"start": -1}, 400, "start"),
    ({"duration": 0}, 400, "duration"),
    ({"duration": 301}, 400, "duration"),
    ({"size": "3840x2160"}, 400, "pixels"),
    ({"size": "big"}, 400, "size"),
    ({"size": "32²x240"}, 400, "size"),  # isdigit() takes '²', int() does not
    ({"size": "１２８０x７２０"}, 400, "size"),  # full-width digits
    ({"format": ["mp4"]}, 400, "format"),
    ({"format": {"mp4": 1}}, 400, "format"),
    ({"fps": 0}, 400, "fps"),
    ({"mesh": "nothing"}, 404, "no mesh"),
    ({"mapping": {"transfer": [2]}}, 400, "mapping"),
])
def test_bad_requests_get_one_clear_line(client, mapping, fields, status, words):
    body = {"mesh": client.ids["mesh"], "song": client.ids["song"],
            "mapping": mapping.to_json(), "format": "mp4", "start": 0, "duration": 1,
            **fields}
    response = client.post("/api/export", json=body)
    assert response.status_code == status, response.text
    assert words in response.json()["error"]


def test_the_route_is_guarded_like_every_route(client, mapping):
    body = json.dumps({"mesh": client.ids["mesh"], "song": client.ids["song"],
                       "mapping": mapping.to_json(), "format": "glb"})
    assert client.post("/api/export", content=body,
                       headers={"Content-Type": "text/plain"}).status_code == 415
    assert client.post("/api/export", content=body, headers={
        "Content-Type": "application/json", "Origin": "http://evil.example"}).status_code == 403
    assert client.get("/api/exports/nothing").status_code == 404


def test_one_export_at_a_time(client):
    """A second export while one runs is refused (409): the CPU and the disk stay bounded."""
    import threading

    from starlette.exceptions import HTTPException

    from eigendance.server.export_route import Exports
    from eigendance.server.items import Job

    exports = Exports(client.library)
    release = threading.Event()
    exports.start(Job("first", "export", 1), lambda progress: release.wait(10), "/nonexistent",
                  "model/gltf-binary")
    with pytest.raises(HTTPException) as refused:
        exports.start(Job("second", "export", 1), lambda progress: None, "/nonexistent",
                      "model/gltf-binary")
    assert refused.value.status_code == 409
    release.set()


def test_removing_the_song_during_its_mp4_export_leaves_the_export_whole(client, mapping, tmp_path,
                                                                        monkeypatch):
    """The export holds the song's file of its own: removed from the library while ffmpeg is
    about to read it, the video is still made, with its sound (issue 34 case 12)."""
    import eigendance.server.export_route as export_route

    with open(write_song(tmp_path / "gone.wav", 2.0), "rb") as file:  # a song of its own
        song = client.post("/api/upload?name=gone.wav", content=file.read())
    assert song.status_code == 201, song.text
    song_id = song.json()["item"]["id"]
    render = export_route.render_video

    def render_after_removal(*arguments, **options):
        assert client.delete(f"/api/songs/{song_id}").status_code == 200
        return render(*arguments, **options)

    monkeypatch.setattr(export_route, "render_video", render_after_removal)
    state, data = export(client, mesh=client.ids["mesh"], song=song_id,
                         mapping=mapping.to_json(), format="mp4", start=0.5, duration=0.5,
                         size="160x120", fps=20)
    with av.open(io.BytesIO(data)) as container:
        assert container.streams.audio and container.streams.video[0].frames == 10
    folder = client.library.folder
    assert not [name for name in os.listdir(folder) if "-song" in name]  # its link is gone
