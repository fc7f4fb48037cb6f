"""The server's third round of hardening (issue 34): a failed solve can be retried by the same
upload, a bad zip or a full disk is one line of 4xx/507 JSON, a zip's directory is judged from
its end record, analyses have a deadline, and songs are decoded in a worker process."""

from __future__ import annotations

import time

import pytest
from starlette.testclient import TestClient
from web_helpers import write_icosphere

import eigendance.server.solver as solver_module
from eigendance.server.app import create_app
from eigendance.server.library import Library

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

    def killed_at_start(*arguments, started=None, **options):
        if started is None:  # not the solve: reading the file
            return run(*arguments, **options)

        def start(process):
            started(process)
            process.kill()  # what the OOM killer or a segfault does
        return run(*arguments, started=start, **options)

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
