"""The server's third round of hardening (issue 34): a failed solve can be retried by the same
upload, a bad zip or a full disk is one line of 4xx/507 JSON, a zip's directory is judged from
its end record, analyses have a deadline, and songs are decoded in a worker process; and a
mesh's parse crosses a process boundary once (issue 29)."""

from __future__ import annotations

import errno
import io
import os
import struct
import time

import pytest
from starlette.testclient import TestClient
from web_helpers import write_icosphere, write_song, zipped

import eigendance.server.intake as intake_module
import eigendance.server.routes as routes_module
import eigendance.server.solver as solver_module
from eigendance.server import analysis, archive
from eigendance.server import workers as workers_module
from eigendance.server.app import create_app
from eigendance.server.library import Library
from eigendance.server.memory import footprint
from helpers import fixture_path

LOCAL = "http://127.0.0.1:8765"


@pytest.fixture
def library(tmp_path):
    library = Library(str(tmp_path / "library"), k=8, max_upload_bytes=2_000_000)
    yield library
    library.close()


@pytest.fixture
def client(library):
    with TestClient(create_app(library, "127.0.0.1", 8765), base_url=LOCAL) as test_client:
        yield test_client


def error_of(response, status):
    assert response.status_code == status, response.text
    body = response.json()
    assert set(body) == {"error"} and body["error"] and "\n" not in body["error"]
    return body["error"]


def job_end(client, job_id: str, seconds: float = 120.0) -> dict:
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        state = client.get(f"/api/jobs/{job_id}").json()
        if state["state"] in ("done", "error"):
            return state
        time.sleep(0.1)
    raise AssertionError(f"job {job_id} did not end")


def test_a_solve_whose_worker_was_killed_is_retried_by_the_same_upload(client, tmp_path,
                                                                      monkeypatch):
    """kill -9 of the solve's worker process fails its job; the same bytes again start a new
    solve (201, a new item) instead of answering the failed item, which is removed."""
    with open(write_icosphere(tmp_path / "ball.obj", 1), "rb") as file:
        body = file.read()
    run = solver_module.workers.run

    def killed_at_start(function, *arguments, started=None, **options):
        if function is not analysis.solve_basis:  # reading the file
            return run(function, *arguments, started=started, **options)

        def start(process):
            started(process)
            process.kill()  # what the OOM killer or a segfault does
        return run(function, *arguments, started=start, **options)

    monkeypatch.setattr(solver_module.workers, "run", killed_at_start)
    first = client.post("/api/upload?name=ball.obj", content=body)
    assert first.status_code == 201, first.text
    failed = job_end(client, first.json()["job"]["id"])
    assert failed["state"] == "error" and "died" in failed["message"]

    monkeypatch.setattr(solver_module.workers, "run", run)
    again = client.post("/api/upload?name=ball.obj", content=body)
    assert again.status_code == 201, again.text
    assert again.json()["item"]["id"] != first.json()["item"]["id"]
    assert job_end(client, again.json()["job"]["id"])["state"] == "done"
    meshes = client.get("/api/library").json()["meshes"]
    assert [mesh["id"] for mesh in meshes] == [again.json()["item"]["id"]]
    # Solved now: the same bytes answer it (200), as for any content already there.
    assert client.post("/api/upload?name=ball.obj", content=body).status_code == 200


# --- zips the file system or zlib refuse, a full disk ----------------------------------------

@pytest.fixture(scope="module")
def ball(tmp_path_factory) -> bytes:
    with open(write_icosphere(tmp_path_factory.mktemp("ball") / "ball.obj", 1), "rb") as file:
        return file.read()


def corrupt_deflate(ball: bytes) -> bytes:
    """A zip whose member's deflate stream is damaged (its CRC and sizes left as they were)."""
    data = bytearray(zipped({"ball.obj": ball}))
    start = 30 + len("ball.obj")  # the first local header's data
    data[start + 40:start + 80] = b"\xff" * 40
    return bytes(data)


@pytest.mark.parametrize(("members", "words"), [
    ({"x" * 300 + ".png": b"png"}, "too long"),
    ({"a/" * 2100 + "t.png": b"png"}, "too deep"),
    ({"tex.png": b"png", "tex.png/x.png": b"png"}, "both a file and a folder"),
])
def test_a_zip_the_file_system_would_refuse_is_one_line(client, library, ball, members, words):
    message = error_of(client.post("/api/upload?name=m.zip",
                                   content=zipped({"ball.obj": ball, **members})), 400)
    assert words in message and "m.zip" in message
    assert not [name for name in os.listdir(library.folder) if name != ".lock"]


def test_a_zip_with_a_corrupt_deflate_stream_is_one_line(client, library, ball):
    message = error_of(client.post("/api/upload?name=m.zip", content=corrupt_deflate(ball)), 400)
    assert "ball.obj cannot be unpacked" in message
    assert not os.listdir(library.folder)


def test_an_upload_to_a_full_disk_is_507(client, library, ball, monkeypatch):
    """ENOSPC while the upload is written (mocked): one line, 507, nothing left behind."""
    real = routes_module.os.fdopen

    class Full(io.RawIOBase):
        def __init__(self, handle, *arguments, **options):
            self.file = real(handle, *arguments, **options)

        def write(self, data):
            raise OSError(errno.ENOSPC, "No space left on device")

        def close(self):
            self.file.close()

    monkeypatch.setattr(routes_module.os, "fdopen", Full)
    for name, body in (("ball.obj", ball), ("m.zip", zipped({"ball.obj": ball}))):
        assert "disk is full" in error_of(client.post(f"/api/upload?name={name}",
                                                      content=body), 507)
    monkeypatch.undo()
    assert not os.listdir(library.folder)


def test_unpacking_onto_a_full_disk_is_507(library, ball, tmp_path, monkeypatch):
    """ENOSPC while a member is written (mocked): the OSError itself, which the app answers
    with 507 (above), not 'cannot be unpacked'."""
    path = tmp_path / "m.zip"
    path.write_bytes(zipped({"ball.obj": ball}))
    real = archive.os.fdopen

    def full(handle, *arguments, **options):
        real(handle).close()
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(archive.os, "fdopen", full)
    with pytest.raises(OSError) as raised:
        archive.unpack(str(path), str(tmp_path / "out"), 1 << 20, "m.zip")
    assert raised.value.errno == errno.ENOSPC


# --- a zip's directory judged from its end record ---------------------------------------------

def end_record(entries: int, size: int) -> bytes:
    """An end-of-central-directory record (APPNOTE 4.3.16) listing `entries` in `size` bytes."""
    return struct.pack("<4s4H2LH", b"PK\x05\x06", 0, 0, min(entries, 0xFFFF),
                       min(entries, 0xFFFF), size, 0, 0)


def zip64_end(entries: int, size: int) -> bytes:
    """A zip64 end record and its locator (APPNOTE 4.3.14-15) before a classic one of 0xFFFF."""
    record = struct.pack("<4sQ2H2L4Q", b"PK\x06\x06", 44, 45, 45, 0, 0, entries, entries, size,
                         0)
    locator = struct.pack("<4sLQL", b"PK\x06\x07", 0, 0, 1)
    return record + locator + struct.pack("<4s4H2LH", b"PK\x05\x06", 0, 0, 0xFFFF, 0xFFFF,
                                          0xFFFFFFFF, 0xFFFFFFFF, 0)


@pytest.mark.parametrize(("tail", "words"), [
    (end_record(300, 300 * 46), "holds 300 files"),
    (zip64_end(1_100_000, 60 << 20), "holds 1100000 files"),
    (end_record(3, 50 << 20), "its directory takes"),
], ids=["300 entries", "zip64 1.1 M entries", "50 MB directory"])
def test_a_zip_listing_too_much_is_refused_from_its_end_record(client, library, monkeypatch,
                                                               tail, words):
    """zipfile.ZipFile, which parses the whole directory in Python (7-13 s and +500 MB for 1.1 M
    entries), is never reached."""
    head = zipped({"ball.obj": b"v 0 0 0\n"})[:-22]  # a real zip without its end record

    def never(*arguments, **options):
        raise AssertionError("zipfile parsed the directory")

    monkeypatch.setattr(archive.zipfile, "ZipFile", never)
    message = error_of(client.post("/api/upload?name=big.zip", content=head + tail), 413)
    assert words in message
    assert not os.listdir(library.folder)


# --- analyses: a deadline, songs in a worker process charged before decoding -----------------

def test_an_analysis_past_its_deadline_is_stopped_in_one_line(client, tmp_path, monkeypatch):
    """The deadline grows with the file (ANALYSIS_SECONDS + size / ANALYSIS_BYTES_PER_SECOND);
    set to nothing here, the reading's worker is killed at once: 422, and the upload slot and
    the content are free again."""
    with open(write_icosphere(tmp_path / "ball.obj", 1), "rb") as file:
        body = file.read()
    monkeypatch.setattr(intake_module, "ANALYSIS_SECONDS", 0.0)
    monkeypatch.setattr(intake_module, "ANALYSIS_BYTES_PER_SECOND", 1e18)
    message = error_of(client.post("/api/upload?name=ball.obj", content=body), 422)
    assert message.startswith("ball.obj: the analysis took more than its 0 s")
    monkeypatch.undo()
    answer = client.post("/api/upload?name=ball.obj", content=body)
    assert answer.status_code == 201, answer.text


@pytest.fixture
def worker_calls(monkeypatch):
    """The functions run in worker processes (`workers.run`), in order."""
    run, called = workers_module.run, []

    def noted(function, *arguments, **options):
        called.append(function.__name__)
        return run(function, *arguments, **options)

    monkeypatch.setattr(workers_module, "run", noted)
    return called


def test_a_song_is_decoded_in_a_worker_process(client, tmp_path, worker_calls):
    with open(write_song(tmp_path / "tune.wav", 1.0), "rb") as file:
        answer = client.post("/api/upload?name=tune.wav", content=file.read())
    assert answer.status_code == 201, answer.text
    assert worker_calls == ["song_seconds", "read_song"]
    assert answer.json()["item"]["duration"] == pytest.approx(1.0, abs=0.01)


def test_a_song_too_long_for_the_budget_is_refused_before_decoding(tmp_path, worker_calls):
    """60 s of spectrogram (6,001 frames × 64 bands, about 3.5 MB) in a budget of 1 MB: 413
    from the length in the header, nothing decoded."""
    library = Library(str(tmp_path / "library"), k=8, memory_budget=1 << 20)
    try:
        with TestClient(create_app(library, "127.0.0.1", 8765), base_url=LOCAL) as client:
            with open(write_song(tmp_path / "long.wav", 60.0), "rb") as file:
                message = error_of(client.post("/api/upload?name=long.wav",
                                               content=file.read()), 413)
        assert "long.wav" in message and "budget" in message
        assert worker_calls == ["song_seconds"]
        assert library.budget.used == 0 and not library.songs
    finally:
        library.close()


def test_a_songs_length_is_read_without_decoding(tmp_path):
    path = write_song(tmp_path / "tune.wav", 2.5)
    assert analysis.song_seconds(path, "tune.wav") == pytest.approx(2.5, abs=1e-3)
    assert analysis.song_seconds(str(tmp_path / "none.ogg"), "none.ogg") == 0.0
    assert analysis.song_bytes(60.0, {}) > 6001 * 64 * 8


# --- a mesh's parse crosses a process boundary once (issue 29) --------------------------------

@pytest.mark.parametrize("model", ["ball.obj", "kenney_cakeBirthday.glb"])
def test_a_meshs_parse_never_passes_through_the_server(client, library, tmp_path, monkeypatch,
                                                       model):
    """What goes to and comes back from each worker process (`workers.run`), counted as the
    bytes of the arrays, bytes and strings it holds (`footprint`; a few hundred for names): the
    reading worker answers only the mesh's look and its counts (`ReadMesh`; the 642 vertices
    and 1280 triangles of the ball are 46 kB), the solve's worker is given a file name, and
    only the solved basis
    comes back, without a second copy of the look (the item's is given to it). Before, the
    `HarmonicProblem` came back from the reading worker and went on to the solve's."""
    path = write_icosphere(tmp_path / model, 3) if model.endswith(".obj") else \
        fixture_path("textured", model)
    crossings, run = [], workers_module.run

    def noted(function, *arguments, **options):
        result = run(function, *arguments, **options)
        crossings.append((function.__name__, footprint(arguments), result))
        return result

    monkeypatch.setattr(workers_module, "run", noted)
    with open(path, "rb") as file:
        answer = client.post(f"/api/upload?name={model}", content=file.read())
    assert answer.status_code == 201, answer.text
    assert job_end(client, answer.json()["job"]["id"])["state"] == "done"
    item = library.meshes[answer.json()["item"]["id"]]
    assert [name for name, _, _ in crossings] == ["read_file", "solve_basis"]
    assert all(sent < 2048 for _, sent, _ in crossings)
    (kind, read), (basis, bundle) = [result for _, _, result in crossings]
    assert kind == "mesh" and read.vertices == item.vertices == basis.n
    assert footprint(read) - footprint(item.appearance) < 2048  # the look; no vertex
    if model.endswith(".glb"):
        assert item.appearance is not None and footprint(item.appearance) > 0
    assert basis.appearance is item.appearance and item.basis is basis
    assert item.held() == footprint(basis, bundle)  # the look charged once
    assert not [name for name in os.listdir(library.folder) if name.startswith("parsed-")]
