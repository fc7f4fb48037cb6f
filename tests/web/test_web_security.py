"""The server against other web pages and bad requests (docs/design.md#server): Host and origin
checks, content types, body limits, one-line JSON errors, one item per content, the memory
budget, removal, heavy work off the event loop, and the end of the process (the temporary
folder removed, a solve stopped at Ctrl-C)."""

from __future__ import annotations

import asyncio
import fcntl
import json
import os
import signal
import subprocess
import sys
import threading
import time

import httpx
import numpy as np
import pytest
import trimesh
from starlette.testclient import TestClient
from web_helpers import free_port, write_icosphere, write_song

import eigendance.server.requests as requests_module
import eigendance.server.rig_routes as rig_routes_module
import eigendance.server.routes as routes_module
from eigendance.errors import InputError, InternalError
from eigendance.inputs.mapping import MAX_HARMONICS
from eigendance.server import analysis, workers
from eigendance.server.app import create_app
from eigendance.server.guard import exposure_warning
from eigendance.server.items import MeshItem
from eigendance.server.library import Library
from eigendance.server.requests import JSON_LIMIT
from eigendance.server.serve import (
    FOLDER_PREFIX,
    LOCK_NAME,
    sweep_library_folders,
    terminal_progress,
)
from eigendance.server.workers import Workers
from helpers import alive, descendants, fixture_path, start

PORT = 8765
LOCAL = f"http://127.0.0.1:{PORT}"
JSON = {"Content-Type": "application/json"}


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    folder = tmp_path_factory.mktemp("security-files")
    return {"mesh": write_icosphere(folder / "ball.obj", 1),
            "song": write_song(folder / "tune.wav", 1.0), "folder": folder}


def new_library(tmp_path, **options) -> Library:
    return Library(str(tmp_path / "library"), k=8, max_upload_bytes=200_000, **options)


@pytest.fixture
def library(files, tmp_path):
    library = new_library(tmp_path)
    for path in (files["mesh"], files["song"]):
        library.add_path(path)
    assert library.wait(60)
    yield library
    library.close()


@pytest.fixture
def client(library):
    """A client of the app listening on 127.0.0.1:8765, as `eigendance serve` does."""
    with TestClient(create_app(library, "127.0.0.1", PORT), base_url=LOCAL) as test_client:
        yield test_client


def error_of(response, status):
    assert response.status_code == status, response.text
    assert response.headers["content-type"] == "application/json"
    body = response.json()
    assert set(body) == {"error"} and body["error"] and "\n" not in body["error"]
    assert response.text.count("\n") == 0
    return body["error"]


def mesh_bytes(files, tag: str = "") -> bytes:
    """The ball's OBJ, made distinct content by a comment (the same geometry)."""
    with open(files["mesh"], "rb") as file:
        return file.read() + (f"# {tag}\n".encode() if tag else b"")


def stored_files(library) -> list[str]:
    return sorted(name for name in os.listdir(library.folder) if not name.startswith(".lock"))


# --- Host -------------------------------------------------------------------------------------

@pytest.mark.parametrize("host", ["127.0.0.1:8765", "localhost:8765", "[::1]:8765",
                                  "LOCALHOST:8765"])
def test_the_listening_address_is_answered(client, host):
    assert client.get("/api/library", headers={"Host": host}).status_code == 200


@pytest.mark.parametrize("host", ["evil.example:8765", "evil.example", "127.0.0.1:9999",
                                  "localhost", "127.0.0.1.evil.example:8765", "localhost:80x",
                                  "[::1", ""])
def test_other_host_names_are_refused_on_every_route(client, host):
    """DNS rebinding: a site whose name resolves to 127.0.0.1 sends its own name."""
    for path in ("/api/library", "/", "/index.html"):
        assert "Host" in error_of(client.get(path, headers={"Host": host}), 400)
    error_of(client.post("/api/upload?name=x.obj", content=b"v 0 0 0",
                         headers={"Host": host}), 400)


def test_host_flag_widens_the_names_deliberately(library):
    def status(app, host):
        with TestClient(app) as test_client:
            return test_client.get("/api/library", headers={"Host": host}).status_code

    everywhere = create_app(library, "0.0.0.0", PORT)
    assert status(everywhere, f"192.168.1.7:{PORT}") == 200  # any IP address: not rebindable
    assert status(everywhere, f"[fe80::1]:{PORT}") == 200
    assert status(everywhere, f"localhost:{PORT}") == 200
    assert status(everywhere, f"evil.example:{PORT}") == 400
    one = create_app(library, "192.168.1.5", PORT)
    assert status(one, f"192.168.1.5:{PORT}") == 200
    assert status(one, f"127.0.0.1:{PORT}") == 200
    assert status(one, f"10.0.0.1:{PORT}") == 400


def test_listening_beyond_this_machine_prints_a_warning_naming_the_risk():
    assert exposure_warning("127.0.0.1") is None and exposure_warning("localhost") is None
    assert exposure_warning("::1") is None and exposure_warning("127.0.0.2") is None
    for host in ("0.0.0.0", "::", "192.168.1.5"):
        warning = exposure_warning(host)
        assert warning.startswith("eigendance: warning: listening on ")
        assert "upload files" in warning and "no password" in warning and "\n" not in warning


def test_serve_prints_the_warning_before_serving(tmp_path):
    env = dict(os.environ, EIGENDANCE_CACHE_DIR=str(tmp_path / "cache"), TMPDIR=str(tmp_path))
    process = start([sys.executable, "-m", "eigendance.cli", "serve", "--host",
                                "0.0.0.0", "--port", "0"], env=env, stdout=subprocess.PIPE,
                    stderr=subprocess.PIPE, text=True)
    try:
        assert "serving on http://127.0.0.1:" in process.stdout.readline()
    finally:
        process.send_signal(signal.SIGINT)
        _, errors = process.communicate(timeout=20)
    assert "warning: listening on every address of this machine" in errors.splitlines()[0]


# --- origin, fetch metadata, content types ----------------------------------------------------

def library_ids(client) -> list[str]:
    data = client.get("/api/library").json()
    return sorted(item["id"] for kind in ("meshes", "songs", "mappings", "rigs")
                  for item in data[kind])


@pytest.mark.parametrize("headers", [
    {"Origin": "https://evil.example"},
    {"Origin": "null"},
    {"Origin": "http://127.0.0.1:9999"},  # another local server: another origin
    {"Origin": "http://localhost:8765"},  # the same server under another name: another origin
    {"Sec-Fetch-Site": "cross-site"},
    {"Sec-Fetch-Site": "same-site"},
    {"Origin": LOCAL, "Sec-Fetch-Site": "cross-site"},
    {"Sec-Fetch-Site": "same-origin, cross-site"},  # joined by a proxy: each value counts
    {"Sec-Fetch-Site": "same-origin,same-site"},
])
def test_state_changing_requests_from_other_sites_are_refused(client, files, headers):
    before, folder = library_ids(client), stored_files(client.app.state.library)
    error_of(client.post("/api/upload?name=x.obj", content=mesh_bytes(files, "x"),
                         headers=headers), 403)
    error_of(client.post("/api/mappings", content=b"{}", headers={**headers, **JSON}), 403)
    mesh = client.get("/api/library").json()["meshes"][0]["id"]
    error_of(client.delete(f"/api/meshes/{mesh}", headers=headers), 403)
    assert library_ids(client) == before and stored_files(client.app.state.library) == folder


@pytest.mark.parametrize("content_type", ["text/plain", "text/plain;charset=UTF-8",
                                          "application/x-www-form-urlencoded",
                                          "multipart/form-data; boundary=x", "text/html"])
def test_form_and_text_bodies_are_refused_without_an_origin(client, files, content_type):
    """What an HTML form or a "simple" fetch of another page sends, even where a browser sends
    no Origin."""
    before = library_ids(client)
    message = error_of(client.post("/api/upload?name=x.obj", content=mesh_bytes(files, "x"),
                                   headers={"Content-Type": content_type}), 415)
    assert "application/octet-stream" in message
    error_of(client.post("/api/breed", content=b'{"parents": []}',
                         headers={"Content-Type": content_type}), 415)
    assert library_ids(client) == before


def test_the_page_itself_is_served_and_answered(client, files):
    """What the page sends: its own Origin, Sec-Fetch-Site same-origin; a file's own type."""
    page = {"Origin": LOCAL, "Sec-Fetch-Site": "same-origin"}
    for content_type in ("model/obj", "application/octet-stream", None):  # None: no known type
        headers = dict(page, **({"Content-Type": content_type} if content_type else {}))
        answer = client.post("/api/upload?name=z.obj", content=mesh_bytes(files, str(content_type)),
                             headers=headers)
        assert answer.status_code == 201, answer.text
    data = client.get("/api/library").json()
    gallery = client.post("/api/gallery", json={"mesh": data["meshes"][0]["id"],
                                                "song": data["songs"][0]["id"], "size": 2})
    answer = client.post("/api/breed", content=json.dumps({"parents": gallery.json()["mappings"]}),
                         headers={**page, "Content-Type": "application/json; charset=utf-8"})
    assert answer.status_code == 200, answer.text
    # A link from another site opens the app (a navigation), but reads nothing from the API.
    assert client.get("/", headers={"Sec-Fetch-Site": "cross-site"}).status_code == 200
    error_of(client.get("/api/library", headers={"Sec-Fetch-Site": "cross-site"}), 403)


def test_json_routes_ask_for_json(client):
    message = error_of(client.post("/api/breed", content=b'{"parents": []}'), 415)
    assert "application/json" in message


# --- errors: one line of JSON -----------------------------------------------------------------

@pytest.mark.parametrize("path", ["/index.html%00.png", "/%00", "/api/meshes/%00",
                                  "/%1b%5b31mred", "/api/%7f"])
def test_control_characters_in_a_path_are_a_400(client, path):
    assert "control characters" in error_of(client.get(path), 400)


@pytest.mark.parametrize("path", ["/no-such-file.png", "/" + "a" * 5000, "/api/nope"])
def test_missing_files_are_a_404(client, path):
    error_of(client.get(path), 404)


def test_wrong_methods_are_a_405(client):
    error_of(client.patch("/api/library", content=b"{}", headers=JSON), 405)
    error_of(client.post("/index.html", content=b"{}", headers=JSON), 405)


DEEP = b"[" * 100_000 + b"]" * 100_000
BAD_BODIES = [
    (DEEP, "nested too deeply"),
    (b'{"size": ' + b"9" * 4000 + b"}", "integer of 4000 digits"),
    (b'{"seed": -' + b"9" * 4000 + b"}", "integer of 4000 digits"),
    (b'{"size": NaN}', "NaN"),
    (b'{"size": -Infinity}', "-Infinity"),
    (b'{"size": "\xc3\x28"}', "not valid JSON"),  # not UTF-8
    (b"", "not valid JSON"),
]


@pytest.mark.parametrize(("body", "words"), BAD_BODIES)
@pytest.mark.parametrize("route", ["/api/gallery", "/api/breed", "/api/mappings",
                                   "/api/rig-gallery", "rig:stiffness", "rig:pose"])
def test_malformed_json_bodies_are_a_400(client, route, body, words):
    if route.startswith("rig:"):
        rig = client.get("/api/library").json()["rigs"][0]["id"]
        route = f"/api/rigs/{rig}/{route[4:]}"
    assert words in error_of(client.post(route, content=body, headers=JSON), 400)


def test_json_bodies_are_limited_before_they_are_read(client):
    big = b'{"parents": [' + b" " * JSON_LIMIT + b"]}"
    assert "larger than" in error_of(client.post("/api/breed", content=big, headers=JSON), 413)
    chunks = (b" " * (1 << 20) for _ in range(JSON_LIMIT // (1 << 20) + 2))  # no length given
    assert "larger than" in error_of(client.post("/api/breed", content=chunks, headers=JSON), 413)


def test_breeding_answers_a_bounded_size(client):
    """1.3 million amplification values (2.6 MB of JSON) froze the server for 10 s and answered
    83 MB; mappings hold at most MAX_HARMONICS values, and at most 16 parents."""
    parent = {"format": "eigendance.mapping", "version": 2, "bands": 4,
              "transfer": [0.5] * 4, "amplification": [1] * 1_300_000}
    message = error_of(client.post("/api/breed", json={"parents": [parent], "size": 16}), 400)
    assert f"amplification has 1300000 values; at most {MAX_HARMONICS}" in message
    parent["amplification"] = [1.0] * 8
    error_of(client.post("/api/breed", json={"parents": [parent] * 17}), 400)
    parent["modes"] = {"selected": list(range(MAX_HARMONICS + 1))}
    assert "modes.selected" in error_of(client.post("/api/mappings", json=parent), 400)
    del parent["modes"]
    parent["amplification"] = [1] * (MAX_HARMONICS + 1)  # and as a file
    message = error_of(client.post("/api/upload?name=long.json", content=json.dumps(parent)), 400)
    assert message.startswith("long.json: amplification has 20001 values")


def test_a_failure_of_ours_is_one_line_of_json_without_library_paths(client, library,
                                                                     monkeypatch, capsys):
    stored = os.path.join(library.folder, "upload-0123456789abcdef.obj")

    async def broken(scope, receive, send):
        raise RuntimeError(f"cannot open {stored}\nin {library.folder}")

    route = next(r for r in client.app.routes if getattr(r, "path", "") == "/api/config")
    monkeypatch.setattr(route, "app", broken)
    message = error_of(client.get("/api/config"), 500)
    assert "RuntimeError" in message and library.folder not in message
    assert "upload-0123456789abcdef" not in message
    printed = capsys.readouterr().err
    assert printed.count("\n") == 1 and "Traceback" not in printed and "/api/config" in printed


# --- what uploads show ------------------------------------------------------------------------

def test_upload_errors_call_files_by_their_names(client, library):
    message = error_of(client.post("/api/upload?name=bad.obj", content=b"v 1 2\nf 1 2 3\n"), 400)
    assert message.startswith("bad.obj:")
    assert "upload-" not in message and library.folder not in message
    message = error_of(client.post("/api/upload?name=noise.wav",
                                   content=b"RIFF\x10\x00\x00\x00WAVEjunkjunkjunk"), 400)
    assert message.startswith("noise.wav:") and library.folder not in message
    assert stored_files(library) == []


def test_upload_names_reach_the_terminal_without_escape_sequences(client, library, files,
                                                                  capsys):
    terminal_progress(library)
    name = "%1b%5b2J%1b%5b31mred%07.obj"  # clear the screen, red, bell
    answer = client.post(f"/api/upload?name={name}", content=mesh_bytes(files, "red"))
    assert answer.status_code == 201
    assert library.wait(60)
    printed = capsys.readouterr().err
    assert "red" in printed and "\x1b" not in printed and "\x07" not in printed


# --- one copy per content, the memory budget, removal -----------------------------------------

def test_identical_uploads_share_one_item_one_basis_and_one_file(client, library, files):
    first = client.post("/api/upload?name=one.obj", content=mesh_bytes(files, "same"))
    second = client.post("/api/upload?name=two.obj", content=mesh_bytes(files, "same"))
    assert (first.status_code, second.status_code) == (201, 200)
    assert first.json()["item"]["id"] == second.json()["item"]["id"]
    assert second.json()["item"]["name"] == "one.obj"
    assert library.wait(60)
    assert [m["name"] for m in client.get("/api/library").json()["meshes"]] == ["ball.obj",
                                                                                 "one.obj"]
    assert len(stored_files(library)) == 1
    # the file given to the server and a mapping saved twice are one item each, too
    again = client.post("/api/upload?name=ball-again.obj", content=mesh_bytes(files))
    assert again.status_code == 200 and again.json()["item"]["name"] == "ball.obj"
    assert len(stored_files(library)) == 1
    mapping = client.post("/api/gallery", json={"mesh": first.json()["item"]["id"], "song":
                          client.get("/api/library").json()["songs"][0]["id"], "size": 2}) \
        .json()["mappings"][0]
    saved = [client.post("/api/mappings?name=m.json", json=mapping) for _ in range(2)]
    assert [s.status_code for s in saved] == [201, 200]
    assert saved[0].json()["id"] == saved[1].json()["id"]


def test_the_least_recently_used_items_go_beyond_the_memory_budget(client, library, files):
    data = client.get("/api/library").json()
    client.delete(f"/api/songs/{data['songs'][0]['id']}")
    ball = data["meshes"][0]["id"]
    solved = library.meshes[ball].held()  # what a solved ball keeps
    planned = MeshItem("", "", "", 8, 42).held()  # what a ball is charged until it is solved
    assert 0 < solved < planned and library.budget.used == solved
    library.budget.limit = solved + planned  # room for one more ball
    ids = []
    for tag in ("a", "b"):
        answer = client.post(f"/api/upload?name={tag}.obj", content=mesh_bytes(files, tag))
        ids.append(answer.json()["item"]["id"])
        assert library.wait(60)
        assert library.budget.used <= library.budget.limit
    # "b" did not fit beside the ball and "a": the ball, least recently used, went
    assert [m["id"] for m in client.get("/api/library").json()["meshes"]] == ids
    error_of(client.get(f"/api/meshes/{ball}"), 404)
    client.get(f"/api/meshes/{ids[0]}/basis.bin")  # "a" used: "b" is the oldest now
    client.post("/api/upload?name=c.obj", content=mesh_bytes(files, "c"))
    assert library.wait(60)
    meshes = [m["id"] for m in client.get("/api/library").json()["meshes"]]
    assert meshes[0] == ids[0] and ids[1] not in meshes and len(meshes) == 2
    assert len(stored_files(library)) == 2  # the file of a removed upload is deleted
    memory = client.get("/api/library").json()["memory"]
    assert memory == {"used": library.budget.used, "budget": library.budget.limit}
    assert memory["used"] <= memory["budget"]


def test_an_item_larger_than_the_budget_is_refused(files, tmp_path):
    library = new_library(tmp_path, memory_budget=4096)
    with TestClient(create_app(library), base_url="http://localhost") as client:
        message = error_of(client.post("/api/upload?name=big.obj", content=mesh_bytes(files)),
                           413)
        assert message.startswith("big.obj: a basis of 8 harmonics of 42 vertices would take")
        assert "budget of 4.1 kB" in message
        assert client.get("/api/library").json()["meshes"] == []
        assert stored_files(library) == []
    library.close()


def test_items_can_be_removed(client, library, files):
    data = client.get("/api/library").json()
    mesh, song = data["meshes"][0]["id"], data["songs"][0]["id"]
    upload = client.post("/api/upload?name=gone.obj", content=mesh_bytes(files, "gone")).json()
    assert library.wait(60) and len(stored_files(library)) == 1
    gone = upload["item"]["id"]
    assert client.delete(f"/api/meshes/{gone}").json() == {"removed": [gone]}
    assert stored_files(library) == [] and gone not in library.budget.sizes
    error_of(client.get(f"/api/meshes/{gone}"), 404)
    error_of(client.get(f"/api/jobs/{upload['job']['id']}"), 404)
    error_of(client.delete(f"/api/meshes/{gone}"), 404)
    assert client.delete(f"/api/songs/{song}").json() == {"removed": [song]}
    error_of(client.get(f"/api/songs/{song}/audio"), 404)
    mapping = client.post("/api/gallery", json={"mesh": mesh, "song": song, "size": 2})
    assert mapping.status_code == 404  # the song is gone
    hand = next(r["id"] for r in data["rigs"] if r["name"] == "hand")
    assert "built-in" in error_of(client.delete(f"/api/rigs/{hand}"), 409)
    assert [m["id"] for m in client.get("/api/library").json()["meshes"]] == [mesh]


def test_a_skinned_gltf_goes_with_its_rig(client, library):
    """A skinned glTF is a rig (listed once): removing it removes its stored file."""
    with open(fixture_path("rigged", "SimpleSkin.gltf"), "rb") as file:
        answer = client.post("/api/upload?name=skin.gltf", content=file.read()).json()
    assert answer["kind"] == "rig"
    rig = answer["item"]["id"]
    removed = client.delete(f"/api/rigs/{rig}").json()["removed"]
    assert removed == [rig]
    error_of(client.get(f"/api/rigs/{rig}"), 404)
    assert stored_files(library) == []


def test_removing_a_mesh_stops_its_solve(client, library, tmp_path):
    path = tmp_path / "big.obj"
    trimesh.creation.icosphere(5).export(path)  # 10242 vertices, 900 harmonics: a long solve
    library.k, library.max_upload_bytes = 900, 1 << 20
    answer = client.post("/api/upload?name=big.obj", content=path.read_bytes()).json()
    job = library.jobs[answer["job"]["id"]]
    deadline = time.time() + 60
    while job.state != "running" and time.time() < deadline:
        time.sleep(0.05)
    client.delete(f"/api/meshes/{answer['item']['id']}")
    with job.changed:
        job.changed.wait_for(lambda: not job.busy, timeout=60)
    assert job.state == "error" and "removed from the library" in job.message
    assert library.solving is None


# --- heavy work is done in threads ------------------------------------------------------------

def test_heavy_work_never_runs_on_the_event_loop(client, library, files, monkeypatch):
    """Breeding, galleries, parsing, uploads, rig analysis and bundles are called where no event
    loop runs (a worker thread)."""
    seen = {}

    def off_the_loop(name, function):
        def wrapped(*args, **kwargs):
            try:
                asyncio.get_running_loop()
                seen[name] = "event loop"
            except RuntimeError:
                seen[name] = "thread"
            return function(*args, **kwargs)
        return wrapped

    for module, name in ((routes_module, "breed"), (routes_module, "initial_gallery"),
                         (rig_routes_module, "rig_gallery"), (requests_module, "parse_json"),
                         (rig_routes_module, "rig_meta"), (requests_module, "json_answer")):
        monkeypatch.setattr(module, name, off_the_loop(name, getattr(module, name)))
    for name in ("add_upload", "add_mapping", "half_bundle", "ready_rig", "edit_rig"):
        monkeypatch.setattr(library, name, off_the_loop(name, getattr(library, name)))
    data = client.get("/api/library").json()
    mesh, song = data["meshes"][0]["id"], data["songs"][0]["id"]
    hand = next(r["id"] for r in data["rigs"] if r["name"] == "hand")
    mappings = client.post("/api/gallery", json={"mesh": mesh, "song": song, "size": 2}).json()
    client.post("/api/breed", json={"parents": mappings["mappings"], "size": 2})
    client.post("/api/mappings", json=mappings["mappings"][0])
    client.post("/api/upload?name=t.obj", content=mesh_bytes(files, "t"))
    client.get(f"/api/meshes/{mesh}/basis.bin?dtype=float16")
    client.get(f"/api/rigs/{hand}")
    client.post("/api/rig-gallery", json={"rig": hand, "song": song, "size": 2})
    client.post(f"/api/rigs/{hand}/stiffness", json={"scale": 2})
    assert seen == dict.fromkeys(seen, "thread") and len(seen) == 11, seen


def test_worker_threads_hand_back_results_and_errors_and_never_hold_the_process():
    workers = Workers(2)
    assert workers.submit(sum, [1, 2, 3]).result(timeout=10) == 6
    with pytest.raises(ValueError, match="bad"):
        workers.submit(int, "bad").result(timeout=10)
    busy = [thread for thread in threading.enumerate() if thread.name.startswith("worker-")]
    assert busy and all(thread.daemon for thread in busy)


def test_worker_processes_hand_back_results_and_errors_whole_and_die_when_stopped(tmp_path):
    """`workers.run`: arrays and large bytes come back equal (out of band, `server.transfer`),
    arrays writable; an InputError keeps its status; a stopped process is an InternalError."""
    values = np.arange(300_000, dtype=np.float64).reshape(-1, 3)
    big = bytes(range(256)) * 8192  # 2 MiB: out of band
    back = workers.run(tuple, [values, big, "small", b"tiny"])
    assert np.array_equal(back[0], values) and back[0].dtype == values.dtype
    assert back[0].flags.writeable and back[1:] == (big, "small", b"tiny")
    with pytest.raises(InputError, match="missing.obj") as caught:
        workers.run(analysis.read_file, str(tmp_path / "missing.obj"), "missing.obj",
                    str(tmp_path / "parsed.npz"), 8)
    assert caught.value.status in (400, 404)
    failed = []

    def sleep():
        try:
            workers.run(time.sleep, 60)
        except InternalError as error:
            failed.append(str(error))

    thread = threading.Thread(target=sleep)
    thread.start()
    deadline = time.monotonic() + 30
    while not workers.RUNNING and time.monotonic() < deadline:
        time.sleep(0.02)
    workers.stop()
    thread.join(30)
    assert failed and "died" in failed[0] and not workers.RUNNING


# --- the end of the server --------------------------------------------------------------------

def start_server(tmp_path, *files, k=8, command="serve"):
    """`eigendance serve` (or `show`) with its temporary folder in tmp_path/tmp; (process, that
    folder)."""
    temporary = tmp_path / "tmp"
    temporary.mkdir(exist_ok=True)
    env = dict(os.environ, EIGENDANCE_CACHE_DIR=str(tmp_path / "cache"), TMPDIR=str(temporary))
    process = start([sys.executable, "-m", "eigendance.cli", command, *map(str, files),
                                "-k", str(k), "--port", str(free_port())], env=env,
                    stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                    start_new_session=True)
    assert ("serving on" if command == "serve" else "control page") in process.stdout.readline()
    return process, temporary


def library_folders(temporary) -> list[str]:
    return [name for name in os.listdir(temporary) if name.startswith(FOLDER_PREFIX)]


def command_line(pid: int) -> str:
    try:
        with open(f"/proc/{pid}/cmdline", "rb") as file:
            return file.read().replace(b"\0", b" ").decode(errors="replace")
    except OSError:
        return ""


def ends_with_its_helpers(process, sent) -> str:
    """Signal a started server; it exits within a generous bound, and its fork server, resource
    tracker and workers have ended before it did (none outlives it: a supervisor waiting for
    the process group, or a pipe's reader, is not kept waiting); its stderr."""
    try:
        helpers = descendants(process.pid)
        assert any("multiprocessing.forkserver" in command_line(pid) for pid in helpers), helpers
        process.send_signal(sent)
        process.wait(timeout=10)
        left = {pid: command_line(pid) for pid in alive(helpers)}  # at once: nothing may be left
        _, errors = process.communicate(timeout=10)
    finally:
        if process.poll() is None:  # a failed check leaves no server running
            os.killpg(process.pid, signal.SIGKILL)
            process.wait()
    assert left == {}, f"outlived the server: {left}"
    return errors


@pytest.mark.parametrize(("sent", "status"), [(signal.SIGINT, 130), (signal.SIGTERM, 143),
                                              (signal.SIGHUP, 129)])
def test_the_server_ends_with_its_helpers_and_temporary_folder(tmp_path, files, sent, status):
    process, temporary = start_server(tmp_path, files["mesh"])
    folder = temporary / library_folders(temporary)[0]
    port = process.args[-1]
    answer = httpx.post(f"http://127.0.0.1:{port}/api/upload?name=up.obj",
                        content=mesh_bytes(files, "up"))  # an upload lands in the folder
    names = os.listdir(folder)  # the lock, the file (and its saved problem while queued)
    assert answer.status_code == 201 and ".lock" in names
    assert [name for name in names if name.startswith("upload-")]
    assert folder.is_dir()
    errors = ends_with_its_helpers(process, sent)
    assert process.returncode == status, errors
    assert "Traceback" not in errors
    assert library_folders(temporary) == []
    assert os.listdir(temporary) == []  # multiprocessing's folder (the fork server's socket) too


def test_a_show_ends_with_its_helpers_at_sigterm(tmp_path, files):
    show = tmp_path / "set.toml"
    show.write_text(f'[[cue]]\nname = "one"\nmodel = {json.dumps(str(files["mesh"]))}\n'
                    f'song = {json.dumps(str(files["song"]))}\n')
    process, temporary = start_server(tmp_path, show, command="show")
    errors = ends_with_its_helpers(process, signal.SIGTERM)
    assert process.returncode == 143 and "Traceback" not in errors, errors
    assert os.listdir(temporary) == []


def test_ctrl_c_during_a_solve_ends_the_server_at_once(tmp_path):
    ball = tmp_path / "ball.obj"
    trimesh.creation.icosphere(5).export(ball)  # 900 harmonics of 10242 vertices: ≈ 100 s
    process, temporary = start_server(tmp_path, ball, k=900)
    deadline = time.time() + 60
    while len(workers := descendants(process.pid)) < 3:  # fork server + two band workers
        assert process.poll() is None and time.time() < deadline, "no band workers started"
        time.sleep(0.1)
    started = time.time()
    process.send_signal(signal.SIGINT)  # to the server only (a terminal signals its group)
    _, errors = process.communicate(timeout=30)
    assert process.returncode == 130 and "interrupted" in errors and "Traceback" not in errors
    assert time.time() - started < 5
    time.sleep(1)
    assert not alive(workers)
    assert library_folders(temporary) == []


def test_folders_of_killed_servers_are_swept_by_the_next_one(tmp_path):
    def folder(name, lock=True, age=3600):
        path = tmp_path / f"{FOLDER_PREFIX}{name}"
        path.mkdir()
        (path / "upload-x.obj").write_text("v 0 0 0\n")
        if lock:
            (path / LOCK_NAME).write_bytes(b"")
        os.utime(path, (time.time() - age, time.time() - age))
        return path

    killed, running, foreign, fresh = folder("killed"), folder("running"), \
        folder("foreign", lock=False), folder("fresh", age=0)
    with open(running / LOCK_NAME, "rb") as held:
        fcntl.flock(held, fcntl.LOCK_EX)
        assert sweep_library_folders(str(tmp_path)) == 1
    assert not killed.exists() and running.exists() and foreign.exists() and fresh.exists()
