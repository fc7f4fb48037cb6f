"""The page's export: part of a song as an MP4 video with its sound, or a glTF (.glb), rendered
by the server (docs/web.md#http-api, docs/design.md#server).

`POST /api/export` (its route in `server.app` reads the body and finds the items) checks the
request and starts a job (`Job`, kind "export": its progress is
the frames done, read like a basis solve's by `GET /api/jobs/{id}` and its server-sent
events); the rendering runs in a thread of its own, never on the event loop. `GET
/api/exports/{id}` then downloads the file. One export runs at a time (a second one is refused
with 409 until it ends), its file lives in the library's folder, and only the latest one is
kept.
"""

from __future__ import annotations

import math
import os
import shutil
import threading

from starlette.exceptions import HTTPException
from starlette.requests import Request
from starlette.responses import FileResponse, JSONResponse

from eigendance import checks
from eigendance.errors import EigendanceError, one_line
from eigendance.export.dance import HarmonicDance
from eigendance.export.files import export_dance
from eigendance.export.renderer import Look
from eigendance.export.rig_dance import rig_dance
from eigendance.export.video import parse_size, render_video
from eigendance.inputs.defaults import DEFAULT_FPS
from eigendance.inputs.mapping import check_mapping_size, mapping_from
from eigendance.modal.surface import SurfaceDance
from eigendance.server.items import Job, new_id
from eigendance.server.library import Library
from eigendance.server.lookup import item_of, library_of, ready_basis, song_of
from eigendance.server.requests import json_body
from eigendance.server.solver import Stopped
from eigendance.server.workers import in_worker
from eigendance.window import Window

FORMATS = {"mp4": "video/mp4", "glb": "model/gltf-binary"}
MAX_SECONDS = 300.0  # the longest part of a song the page exports (s): a few minutes of CPU
MAX_PIXELS = 1920 * 1080  # the largest video frame
DEFAULT_SIZE, MAX_FPS = "1280x720", 60.0


class Exports:
    """The library's export jobs: the one running, and the files of those done.

    Parameters
    ----------
    library : the server's library (its jobs, folder and stopping event).
    """

    def __init__(self, library: Library):
        self.library = library
        self.lock = threading.Lock()
        self.running: Job | None = None
        self.files: dict[str, tuple[str, str]] = {}  # job id → (path, media type)

    def start(self, job: Job, work, path: str, media: str) -> None:
        """Run work(progress) for `job` in a daemon thread; 409 while another export runs.

        Parameters
        ----------
        job : the export's job (listed with the library's jobs for its progress).
        work : callable(progress) writing the file at `path`.
        path : the file written, kept for the download until a newer export.
        media : its media type.
        """
        with self.lock:
            if self.running is not None and self.running.busy:
                raise HTTPException(409, "an export is running: wait for it to finish")
            for old, _ in self.files.values():  # only the latest file is kept
                _remove(old)
            self.files.clear()
            self.running = job
        self.library.jobs[job.id] = job
        threading.Thread(target=self._run, args=(job, work, path, media), daemon=True,
                         name=f"export-{job.id}").start()

    def _run(self, job: Job, work, path: str, media: str) -> None:
        stopping = self.library.stopping

        def progress(done: int, total: int) -> None:
            if stopping.is_set():
                raise Stopped("the server is stopping")
            job.update(state="running", done=done, total=total)

        job.update(state="running")
        try:
            work(progress)
        except Stopped:
            job.update(state="error", message="the export stopped: the server is stopping")
        except EigendanceError as error:
            job.update(state="error", message=self.library.public(one_line(error)))
        except Exception as error:  # noqa: BLE001 - said in one line, never a traceback
            job.update(state="error", message=f"the export failed: {one_line(error)}")
        else:
            with self.lock:
                self.files[job.id] = (path, media)
            job.update(state="done", done=job.total)


def _remove(path: str) -> None:
    try:
        os.unlink(path)
    except FileNotFoundError:
        pass


def _own_link(path: str, link: str) -> str:
    """A second name of `path` (a hard link; a copy where links fail), held by one export."""
    try:
        try:
            os.link(path, link)
        except OSError:
            shutil.copyfile(path, link)
    except OSError as error:
        raise HTTPException(409, f"the song's file cannot be read ({error.strerror})") from None
    return link


def exports_of(request: Request) -> Exports:
    """The app's `Exports` (made on first use).

    Parameters
    ----------
    request : any request of the app.

    Returns
    -------
    Exports.
    """
    state = request.app.state
    if getattr(state, "exports", None) is None:
        state.exports = Exports(state.library)
    return state.exports


def _number(body: dict, key: str, default: float, low: float, high: float) -> float:
    return checks.number(body.get(key, default), key, low, high)  # 400 naming the field


def _size(body: dict) -> tuple[int, int]:
    width, height = parse_size(body.get("size", DEFAULT_SIZE))  # the command line's grammar
    if width * height > MAX_PIXELS:
        raise HTTPException(400, f"size {width}x{height}: at most {MAX_PIXELS} pixels "
                                 "(1920x1080)")
    return width, height


async def start_export(request: Request, body: dict, item, song) -> JSONResponse:
    """{mesh | rig, song, mapping, format: mp4 | glb, start, duration, size?, fps?} → 202
    {job}: the dance the player shows, from `start` for `duration` seconds, rendered in a
    thread; its progress is the job's (`GET /api/jobs/{id}`, `/events`).

    Parameters
    ----------
    request : the HTTP request (its app holds the library).
    body : the parsed JSON body.
    item : the mesh item (its basis ready) or the rig item (analysed) of the body's id.
    song : the song item.

    Returns
    -------
    202 JSON {job}: the export's job; 400 for a bad field, 409 while another export runs.
    """
    if not isinstance(body.get("mapping"), dict):
        raise HTTPException(400, "expected a JSON object {mesh or rig, song, mapping, format, "
                                 "start, duration}")
    format = body.get("format", "mp4")
    if not isinstance(format, str) or format not in FORMATS:
        raise HTTPException(400, f"format must be one of {', '.join(FORMATS)}")
    window = Window.of(_number(body, "start", 0.0, 0.0, 1e6),
                       _number(body, "duration", 15.0, 0.01, MAX_SECONDS),
                       float(song.spectrogram.duration), song.name)
    start, duration = window.start, window.duration
    fps = _number(body, "fps", DEFAULT_FPS, 1.0, MAX_FPS)
    size = _size(body) if format == "mp4" else None
    check_mapping_size(body["mapping"], "mapping")
    library = library_of(request)
    audio = song.path if format == "mp4" else None  # a glb comes alone; it names the song
    if "rig" in body and item.rig.palette is None:
        raise HTTPException(409, f"{item.name}: the rig has no vibration mode")
    stem = os.path.splitext(item.name)[0] or "dance"

    def clip():
        mapping = mapping_from(body["mapping"], "mapping")
        if "rig" in body:  # its skin ripples by the mapping's surface genes, if any
            rig = item.rig
            surface = None if mapping.surface is None else SurfaceDance(
                rig.surface(), song.spectrogram, mapping.surface)
            whole = rig_dance(rig, song.spectrogram, rig.mapping(song.spectrogram, mapping),
                              "modal", audio, stem, surface=surface)
        else:
            whole = HarmonicDance(item.basis, song.spectrogram, mapping, audio, stem)
        part = whole.window(start, duration)
        part.info["song"] = song.name
        return part, Look.of(mapping)

    dance, look = await in_worker(clip)  # a bad mapping is a 400 now, not a failed job
    job = Job(new_id(), "export", max(1, math.ceil(duration * fps)), name=item.name)
    path = os.path.join(library.folder, f"export-{job.id}.{format}")

    # The song's file as the export began: a link of its own, so that removing the song from
    # the library while ffmpeg reads it does not fail the export.
    sound = _own_link(song.path, f"{path}-song{os.path.splitext(song.path)[1]}") \
        if format == "mp4" else None

    def work(progress):
        try:
            if format == "mp4":
                render_video(path, [dance], [look], sound, fps, size, progress=progress)
            else:
                export_dance(dance, path, "glb", fps, progress=progress)
        finally:
            if sound is not None:
                _remove(sound)

    try:
        exports_of(request).start(job, work, path, FORMATS[format])
    except HTTPException:
        if sound is not None:
            _remove(sound)
        raise
    return JSONResponse({"job": job.as_json()}, status_code=202)


async def export_clip(request: Request):
    """POST /api/export: part of a song as MP4 or glb.

    Parameters
    ----------
    request : JSON body {mesh | rig, song, mapping, format, start, duration, size?, fps?}.

    Returns
    -------
    202 JSON {job} (`start_export`); 400/404/409 JSON errors.
    """
    body = await json_body(request)
    if not isinstance(body, dict):
        raise HTTPException(400, "expected a JSON object {mesh or rig, song, mapping, format, "
                                 "start, duration}")
    song = song_of(request, str(body.get("song")))
    if "rig" in body:
        item = item_of(request, "rig", body.get("rig"))
        await in_worker(library_of(request).ready_rig, item)
    else:
        item = ready_basis(request, str(body.get("mesh")))
    return await start_export(request, body, item, song)


async def download_export(request: Request):
    """GET /api/exports/{id}: the file of a finished export.

    Parameters
    ----------
    request : path parameter id, the export's job id.

    Returns
    -------
    the file (404 before it is done, or after a newer one).
    """
    exports = exports_of(request)
    with exports.lock:
        found = exports.files.get(request.path_params["id"])
    if found is None or not os.path.isfile(found[0]):
        raise HTTPException(404, "no finished export with this id (only the latest is kept)")
    path, media = found
    return FileResponse(path, media_type=media,
                        filename=f"eigendance{os.path.splitext(path)[1]}")


