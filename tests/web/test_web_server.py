"""The HTTP API (Starlette TestClient): library, bundles, jobs, uploads, errors, CLI defaults."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import time
import urllib.request

import numpy as np
import pytest
import trimesh
from starlette.testclient import TestClient
from web_helpers import free_port, write_icosphere, write_song

from eigendance.cli import build_parser, main
from eigendance.music.breeding import breed
from eigendance.music.gallery import initial_gallery
from eigendance.music.mapping import Mapping
from eigendance.server.app import create_app
from eigendance.server.binary import unpack
from eigendance.server.library import Library
from helpers import bumpy_sphere, start


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    folder = tmp_path_factory.mktemp("server-files")
    return {"mesh": write_icosphere(folder / "ball.obj", 2),
            "song": write_song(folder / "tune.wav", 2.0), "folder": folder}


@pytest.fixture
def client(files, tmp_path):
    library = Library(str(tmp_path / "library"), k=12, max_upload_bytes=200_000)
    for path in (files["mesh"], files["song"]):
        library.add_path(path)
    app = create_app(library)
    assert library.wait(60)
    with TestClient(app, base_url="http://localhost") as test_client:
        test_client.library = library
        yield test_client
    library.close()


def ids(client):
    data = client.get("/api/library").json()
    return data["meshes"][0]["id"], data["songs"][0]["id"]


def library_snapshot(client):
    data = client.get("/api/library").json()
    return ([m["id"] for m in data["meshes"]], [s["id"] for s in data["songs"]],
            [m["id"] for m in data["mappings"]])


def test_library_lists_the_files_with_a_ready_basis(client):
    data = client.get("/api/library").json()
    assert [m["name"] for m in data["meshes"]] == ["ball.obj"]
    assert data["meshes"][0]["ready"] and data["meshes"][0]["k"] == 12
    assert data["meshes"][0]["job"]["state"] == "done"
    assert [s["name"] for s in data["songs"]] == ["tune.wav"]
    assert data["songs"][0]["duration"] == pytest.approx(2.0, abs=0.01)


def test_basis_bundle_holds_the_packed_harmonics(client):
    mesh_id, _ = ids(client)
    response = client.get(f"/api/meshes/{mesh_id}/basis.bin")
    assert response.status_code == 200
    meta, arrays = unpack(response.content)
    basis = client.library.meshes[mesh_id].basis
    assert meta["n"] == basis.n == 162 and meta["k"] == 12
    assert arrays["harmonics"].shape == (162, 12)
    np.testing.assert_allclose(arrays["harmonics"], basis.eigenvectors, atol=1e-6)
    np.testing.assert_allclose(arrays["vertices"], basis.vertices, atol=1e-6)
    assert arrays["faces"].dtype == np.uint32 and arrays["faces"].shape == basis.faces.shape


def test_basis_bundle_in_float16_on_request(client):
    mesh_id, _ = ids(client)
    full = client.get(f"/api/meshes/{mesh_id}/basis.bin").content
    half = client.get(f"/api/meshes/{mesh_id}/basis.bin?dtype=float16").content
    _, arrays = unpack(half)
    assert arrays["harmonics"].dtype == np.float16 and len(half) < 0.75 * len(full)
    basis = client.library.meshes[mesh_id].basis
    np.testing.assert_allclose(arrays["harmonics"], basis.eigenvectors, rtol=2**-11, atol=1e-7)
    assert "dtype" in error_of(client.get(f"/api/meshes/{mesh_id}/basis.bin?dtype=int8"), 400)


def test_spectrogram_bundle_and_audio_bytes(client, files):
    _, song_id = ids(client)
    meta, arrays = unpack(client.get(f"/api/songs/{song_id}/spectrogram.bin").content)
    spectrogram = client.library.songs[song_id].spectrogram
    assert meta["rate"] == 100 and meta["bands"] == 64
    np.testing.assert_array_equal(arrays["values"], spectrogram.values)
    np.testing.assert_allclose(arrays["times"], spectrogram.times, atol=1e-6)
    audio = client.get(f"/api/songs/{song_id}/audio")
    assert audio.headers["content-type"] == "audio/wav"
    with open(files["song"], "rb") as file:
        assert audio.content == file.read()


def test_gallery_and_breeding_use_the_python_mapping_module(client):
    mesh_id, song_id = ids(client)
    response = client.post("/api/gallery", json={"mesh": mesh_id, "song": song_id, "size": 6})
    mappings = response.json()["mappings"]
    expected = initial_gallery(client.library.meshes[mesh_id].basis,
                               client.library.songs[song_id].spectrogram, size=6)
    assert mappings == [m.to_json() for m in expected]
    parents = [mappings[1], mappings[4]]
    children = client.post("/api/breed", json={"parents": parents, "size": 6, "seed": 42}).json()
    again = client.post("/api/breed", json={"parents": parents, "size": 6, "seed": 42}).json()
    assert children == again
    direct = breed([Mapping.from_json(p) for p in parents], size=6, seed=42)
    assert children["mappings"] == [m.to_json() for m in direct]


def test_mesh_upload_runs_a_basis_job_with_server_sent_events(client, files):
    with open(write_icosphere(files["folder"] / "up.obj", 1), "rb") as file:
        data = file.read()
    response = client.post("/api/upload?name=small%20ball.obj", content=data)
    assert response.status_code == 201, response.text
    body = response.json()
    assert body["kind"] == "mesh"
    events = []
    with client.stream("GET", f"/api/jobs/{body['job']['id']}/events") as stream:
        for line in stream.iter_lines():
            if line.startswith("data: "):
                events.append(json.loads(line[6:]))
    assert events[-1]["state"] == "done" and events[-1]["done"] == events[-1]["total"]
    mesh = client.get(f"/api/meshes/{body['item']['id']}").json()
    assert mesh["ready"] and mesh["name"] == "small ball.obj" and mesh["vertices"] == 42
    assert client.get(f"/api/meshes/{body['item']['id']}/basis.bin").status_code == 200


def test_song_and_mapping_uploads(client, files):
    mesh_id, song_id = ids(client)
    with open(files["song"], "rb") as file:
        song = file.read()
    response = client.post("/api/upload?name=again.wav", content=song)  # the same bytes
    assert response.status_code == 200 and response.json()["kind"] == "song"
    assert response.json()["item"]["id"] == song_id
    response = client.post("/api/upload?name=other.wav", content=song[:-400])  # 0.01 s shorter
    assert response.status_code == 201 and response.json()["item"]["id"] != song_id
    mapping = client.post("/api/gallery", json={"mesh": mesh_id, "song": song_id,
                                                "size": 2}).json()["mappings"][0]
    response = client.post("/api/upload?name=m.json", content=json.dumps(mapping).encode())
    assert response.status_code == 201 and response.json()["kind"] == "mapping"
    assert client.get(f"/api/mappings/{response.json()['item']['id']}").json() == mapping


def error_of(response, status):
    assert response.status_code == status, response.text
    body = response.json()
    assert set(body) == {"error"} and "\n" not in body["error"] and body["error"]
    return body["error"]


@pytest.mark.parametrize("name", ["../../evil.obj", "..%2F..%2Fevil.obj", "/etc/evil.obj",
                                  "..\\..\\evil.obj"])
def test_path_traversal_in_upload_names_stays_inside_the_library(client, files, tmp_path, name):
    with open(files["mesh"], "rb") as file:
        data = file.read() + f"# {name}\n".encode()  # not the library's ball.obj
    response = client.post(f"/api/upload?name={name}", content=data)
    assert response.status_code == 201
    assert response.json()["item"]["name"] == "evil.obj"
    for root in (tmp_path, tmp_path.parent, files["folder"]):
        assert not os.path.exists(os.path.join(root, "evil.obj"))
    stored = client.library.meshes[response.json()["item"]["id"]].path
    assert os.path.dirname(stored) == client.library.folder


@pytest.mark.parametrize(("name", "content", "status", "words"), [
    ("big.obj", b"v 0 0 0\n" * 40_000, 413, "limit"),
    ("tool.exe", b"MZ\x90\x00", 415, "unknown file type"),
    ("noname", b"v 0 0 0", 415, "unknown file type"),
    ("", b"v 0 0 0", 400, "name"),
    ("..", b"v 0 0 0", 400, "name"),
    ("binary.obj", b"\x00\x01\x02garbage", 415, "not an OBJ"),
    ("points.obj", b"v 0 0 0\nv 1 0 0\n", 400, "triangles"),
    ("empty.obj", b"", 415, "empty"),
    ("fake.wav", b"this is not audio at all", 415, "not a WAV"),
    ("broken.wav", b"RIFF\x10\x00\x00\x00WAVEjunkjunkjunk", 400, "audio"),
    ("fake.glb", b"{}", 415, "not a GLB"),
    ("bad.json", b"{\"format\": \"nope\"}", 400, "format"),
    ("text.json", b"not json", 415, "not a JSON"),
])
def test_bad_uploads_are_one_line_json_errors_and_leave_the_library_intact(
        client, name, content, status, words):
    before = library_snapshot(client)
    message = error_of(client.post(f"/api/upload?name={name}", content=content), status)
    assert words.lower() in message.lower()
    assert library_snapshot(client) == before
    assert not [f for f in os.listdir(client.library.folder) if f.startswith("upload-")]


@pytest.mark.parametrize("path", ["/api/meshes/nope", "/api/meshes/nope/basis.bin",
                                  "/api/songs/nope/spectrogram.bin", "/api/songs/nope/audio",
                                  "/api/jobs/nope", "/api/jobs/nope/events",
                                  "/api/mappings/nope", "/api/no/such/route"])
def test_unknown_ids_are_404_json(client, path):
    assert "no " in error_of(client.get(path), 404)


@pytest.mark.parametrize(("route", "body", "status"), [
    ("/api/gallery", b"{not json", 400),
    ("/api/gallery", b"[]", 400),
    ("/api/gallery", b"{\"mesh\": \"nope\", \"song\": \"nope\"}", 404),
    ("/api/breed", b"{\"parents\": []}", 400),
    ("/api/breed", b"{\"parents\": [{\"format\": \"x\"}]}", 400),
    ("/api/breed", b"{\"parents\": \"x\"}", 400),
])
def test_malformed_requests_are_4xx_json(client, route, body, status):
    before = library_snapshot(client)
    error_of(client.post(route, content=body, headers={"Content-Type": "application/json"}),
             status)
    assert library_snapshot(client) == before


def test_gallery_size_and_breed_seed_are_checked(client):
    mesh_id, song_id = ids(client)
    for size in (0, 17, "8"):
        error_of(client.post("/api/gallery", json={"mesh": mesh_id, "song": song_id,
                                                   "size": size}), 400)
    mapping = client.post("/api/gallery", json={"mesh": mesh_id, "song": song_id,
                                                "size": 2}).json()["mappings"][0]
    for seed in (-1, 2**32, "7", True):
        error_of(client.post("/api/breed", json={"parents": [mapping], "seed": seed}), 400)


def test_every_size_of_the_rule_works_odd_ones_too_and_others_are_refused(files, tmp_path):
    mesh = bumpy_sphere(2)
    path = tmp_path / "bumpy.obj"
    trimesh.Trimesh(mesh.original_vertices, mesh.faces).export(path)
    library = Library(str(tmp_path / "library"), k=40)
    library.add_path(str(path))
    library.add_path(files["song"])
    assert library.wait(60)
    with TestClient(create_app(library), base_url="http://localhost") as test_client:
        data = test_client.get("/api/library").json()
        body = {"mesh": data["meshes"][0]["id"], "song": data["songs"][0]["id"]}
        for size in range(2, 17):
            response = test_client.post("/api/gallery", json={**body, "size": size})
            assert len(response.json()["mappings"]) == size, response.text
        assert len(test_client.post("/api/gallery", json=body).json()["mappings"]) == 8
        for size in (1, 17, 8.5, "x", None):
            assert "2 to 16 items" in error_of(
                test_client.post("/api/gallery", json={**body, "size": size}), 400)
    library.close()


def test_upload_errors_name_the_persons_file_not_the_stored_one(client):
    for name, content in (("my cat.obj", b"v 0 0 0\nv 1 0 0\nf 1 2 3\n"),
                          ("my cat.obj", b"hello\n"), ("tune.wav", b"RIFF\0\0\0\0WAVEjunk")):
        message = error_of(client.post(f"/api/upload?name={name}", content=content), 400)
        assert message.startswith(f"{name}: ") and "upload-" not in message, message
        assert client.library.folder not in message


def test_config_holds_the_gallery_size_rule_and_the_suffixes(client):
    """The page builds its *tiles* menu and checks `?size=` from this, and zips a model's files
    by the suffixes it announces (the page keeps no copy)."""
    config = client.get("/api/config").json()
    assert config["gallery"] == {"min": 2, "max": 16, "default": 8}
    assert ".glb" in config["suffixes"]["mesh"] and ".bin" in config["suffixes"]["companion"]
    assert set(config["suffixes"]) == {"mesh", "rig", "audio", "mapping", "archive",
                                       "companion"}


def test_serves_the_built_front_end(client):
    response = client.get("/")
    assert response.status_code == 200 and "eigendance" in response.text
    assert "<canvas" in response.text


def test_cli_binds_localhost_unless_told_otherwise():
    for command in (["serve"], ["demo"]):
        args = build_parser().parse_args(command)
        assert args.host == "127.0.0.1" and args.port == 8765
    assert build_parser().parse_args(["serve", "--host", "0.0.0.0"]).host == "0.0.0.0"


def test_bad_library_file_on_the_command_line_is_a_one_line_error(tmp_path, capsys):
    bad = tmp_path / "x.exe"
    bad.write_bytes(b"MZ")
    assert main(["serve", str(bad), "--port", "1"]) == 1
    error = capsys.readouterr().err
    assert error.startswith("eigendance: error:") and error.count("\n") == 1


def test_demo_prints_its_url_on_one_line_and_serves_the_cat_and_the_music(tmp_path):
    port = free_port()
    env = dict(os.environ, EIGENDANCE_CACHE_DIR=str(tmp_path / "cache"))
    process = start([sys.executable, "-m", "eigendance.cli", "demo", "-k", "16",
                                "--port", str(port)], env=env, stdout=subprocess.PIPE,
                    stderr=subprocess.PIPE, text=True)
    try:
        line = process.stdout.readline()
        assert line == f"eigendance demo: open http://127.0.0.1:{port}/ in a browser\n"
        url = f"http://127.0.0.1:{port}/api/library"
        deadline = time.time() + 60
        while True:
            library = json.load(urllib.request.urlopen(url))
            if library["meshes"][0]["ready"] or time.time() > deadline:
                break
            time.sleep(0.2)
        assert [m["name"] for m in library["meshes"]] == ["cat_lowres.obj"]
        assert library["meshes"][0]["ready"] and library["meshes"][0]["k"] == 16
        assert library["songs"][0]["duration"] == pytest.approx(30, abs=0.1)
        assert os.path.exists(tmp_path / "cache" / "demo-music" / "eigendance-demo-music.wav")
    finally:
        process.terminate()
        _, errors = process.communicate(timeout=10)
    assert "computing the basis of cat_lowres.obj" in errors
