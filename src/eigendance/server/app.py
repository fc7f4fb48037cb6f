"""The HTTP API and static web app (Starlette). See `eigendance.server` for the route list."""

from __future__ import annotations

import asyncio
import json
import os
import tempfile
from importlib import resources

from starlette.applications import Starlette
from starlette.exceptions import HTTPException
from starlette.requests import Request
from starlette.responses import (
    FileResponse,
    HTMLResponse,
    JSONResponse,
    Response,
    StreamingResponse,
)
from starlette.routing import Mount, Route
from starlette.staticfiles import StaticFiles

from eigendance.errors import EigendanceError
from eigendance.server.library import Library, kind_of

AUDIO_TYPES = {".wav": "audio/wav", ".mp3": "audio/mpeg", ".ogg": "audio/ogg",
               ".oga": "audio/ogg", ".opus": "audio/ogg", ".flac": "audio/flac",
               ".m4a": "audio/mp4"}
# The gallery-size rule the page follows (GET /api/config); `?size=` outside it falls back to
# DEFAULT_GALLERY with a message.
MIN_GALLERY = 2
MAX_GALLERY = 16
DEFAULT_GALLERY = 8


def static_folder() -> str | None:
    folder = resources.files("eigendance") / "static"
    path = os.fspath(folder)
    return path if os.path.isfile(os.path.join(path, "index.html")) else None


def error(status: int, message: str) -> JSONResponse:
    return JSONResponse({"error": message}, status_code=status)


def sniff(name: str, head: bytes) -> str | None:
    """Why the first bytes of an upload do not match its suffix, or None if they do."""
    suffix = os.path.splitext(name)[1].lower()
    text_like = b"\0" not in head[:4096]
    checks = {
        ".obj": text_like, ".off": text_like and head.lstrip()[:4].upper().endswith(b"OFF")
        or text_like and b"OFF" in head[:64].upper(),
        ".ply": head.startswith(b"ply"), ".gltf": head.lstrip()[:1] == b"{",
        ".glb": head.startswith(b"glTF"), ".stl": len(head) >= 84,
        ".wav": head[:4] == b"RIFF" and head[8:12] == b"WAVE",
        ".mp3": head[:3] == b"ID3" or (len(head) > 1 and head[0] == 0xFF
                                       and head[1] & 0xE0 == 0xE0),
        ".ogg": head[:4] == b"OggS", ".oga": head[:4] == b"OggS", ".opus": head[:4] == b"OggS",
        ".flac": head[:4] == b"fLaC", ".m4a": head[4:8] == b"ftyp",
        ".json": text_like and head.lstrip()[:1] == b"{",
    }
    if suffix not in checks:
        return f"unknown file type '{suffix}'"
    if not head:
        return "the file is empty"
    return None if checks[suffix] else f"the content is not a {suffix[1:].upper()} file"


def create_app(paths=(), library: Library | None = None, folder: str | None = None,
               k: int = 150, max_upload_bytes: int = 64 << 20) -> Starlette:
    """The web app serving `library` (made from `paths` when not given)."""
    if library is None:
        library = Library(folder or tempfile.mkdtemp(prefix="eigendance-library-"), k=k,
                          max_upload_bytes=max_upload_bytes)
        for path in paths:
            library.add_path(os.fspath(path))

    def mesh_of(mesh_id: str):
        item = library.meshes.get(mesh_id)
        if item is None:
            raise HTTPException(404, f"no mesh with id '{mesh_id}'")
        return item

    def song_of(song_id: str):
        item = library.songs.get(song_id)
        if item is None:
            raise HTTPException(404, f"no song with id '{song_id}'")
        return item

    def ready_basis(mesh_id: str):
        item = mesh_of(mesh_id)
        if item.basis is None:
            state = item.job.state if item.job else "missing"
            message = item.job.message if item.job and item.job.message else \
                f"the basis of '{item.name}' is not ready ({state})"
            raise HTTPException(409, message)
        return item

    async def json_body(request: Request, limit: int = 4 << 20):
        body = await request.body()
        if len(body) > limit:
            raise HTTPException(413, "request body too large")
        try:
            return json.loads(body)
        except ValueError:
            raise HTTPException(400, "the request body is not valid JSON") from None

    async def get_config(request):
        return JSONResponse({"gallery": {"min": MIN_GALLERY, "max": MAX_GALLERY,
                                         "default": DEFAULT_GALLERY}})

    async def get_library(request):
        return JSONResponse(library.as_json())

    async def get_mesh(request):
        return JSONResponse(mesh_of(request.path_params["id"]).as_json())

    async def get_basis(request):
        """?dtype=float16 sends the harmonics as float16 (half the bytes)."""
        from eigendance.server.binary import basis_bundle

        item = ready_basis(request.path_params["id"])
        dtype = request.query_params.get("dtype", "float32")
        if dtype not in ("float32", "float16"):
            raise HTTPException(400, "dtype must be float32 or float16")
        if dtype == "float16":
            if item.half_bundle is None:
                item.half_bundle = await asyncio.to_thread(basis_bundle, item.basis, item.name,
                                                           True)
            bundle = item.half_bundle
        else:
            bundle = item.bundle
        return Response(bundle, media_type="application/octet-stream",
                        headers={"Cache-Control": "no-cache"})

    async def get_spectrogram(request):
        item = song_of(request.path_params["id"])
        return Response(item.bundle, media_type="application/octet-stream")

    async def get_audio(request):
        item = song_of(request.path_params["id"])
        suffix = os.path.splitext(item.name)[1].lower()
        media_type = AUDIO_TYPES.get(suffix, "application/octet-stream")
        return FileResponse(item.path, media_type=media_type)

    async def get_job(request):
        job = library.jobs.get(request.path_params["id"])
        if job is None:
            raise HTTPException(404, f"no job with id '{request.path_params['id']}'")
        return JSONResponse(job.as_json())

    async def job_events(request):
        job = library.jobs.get(request.path_params["id"])
        if job is None:
            raise HTTPException(404, f"no job with id '{request.path_params['id']}'")

        async def stream():
            last = None
            while True:
                state = job.as_json()
                if state != last:
                    yield f"data: {json.dumps(state)}\n\n"
                    last = state
                if state["state"] in ("done", "error"):
                    return
                if await request.is_disconnected():
                    return
                await asyncio.sleep(0.1)

        return StreamingResponse(stream(), media_type="text/event-stream",
                                 headers={"Cache-Control": "no-cache"})

    async def upload(request):
        name = os.path.basename(request.query_params.get("name", "").replace("\\", "/"))
        if not name or name.startswith("."):
            raise HTTPException(400, "upload needs ?name=FILE with a file name and suffix")
        try:
            kind = kind_of(name)
        except EigendanceError as problem:
            raise HTTPException(415, str(problem)) from None
        declared = request.headers.get("content-length")
        if declared and declared.isdigit() and int(declared) > library.max_upload_bytes:
            raise HTTPException(413, f"{name}: larger than the "
                                     f"{library.max_upload_bytes >> 20} MiB upload limit")
        chunks, size = [], 0
        async for chunk in request.stream():
            size += len(chunk)
            if size > library.max_upload_bytes:
                raise HTTPException(413, f"{name}: larger than the "
                                         f"{library.max_upload_bytes >> 20} MiB upload limit")
            chunks.append(chunk)
        data = b"".join(chunks)
        if (why := sniff(name, data[:4096])) is not None:
            raise HTTPException(415, f"{name}: {why}")
        suffix = os.path.splitext(name)[1].lower()
        stored = os.path.join(library.folder, f"upload-{os.urandom(6).hex()}{suffix}")
        with open(stored, "wb") as file:
            file.write(data)
        try:
            if kind == "mesh":
                item = await asyncio.to_thread(library.add_mesh, stored, name, None)
                return JSONResponse({"kind": "mesh", "item": item.as_json(),
                                     "job": item.job.as_json()}, status_code=201)
            if kind == "song":
                item = await asyncio.to_thread(library.add_song, stored, name)
            else:
                item = library.add_mapping_file(stored, name)
        except EigendanceError:
            os.unlink(stored)
            raise
        return JSONResponse({"kind": kind, "item": item.as_json()}, status_code=201)

    async def gallery(request):
        from eigendance.mapping import initial_gallery

        body = await json_body(request)
        if not isinstance(body, dict):
            raise HTTPException(400, "expected a JSON object {mesh, song, size}")
        item = ready_basis(str(body.get("mesh")))
        song = song_of(str(body.get("song")))
        size = body.get("size", 8)
        if not isinstance(size, int) or not 1 <= size <= MAX_GALLERY:
            raise HTTPException(400, f"size must be an integer from 1 to {MAX_GALLERY}")
        items = await asyncio.to_thread(initial_gallery, item.basis, song.spectrogram, size=size)
        return JSONResponse({"mappings": [m.to_json() for m in items]})

    async def breed_route(request):
        from eigendance.mapping import Mapping, breed

        body = await json_body(request)
        if not isinstance(body, dict) or not isinstance(body.get("parents"), list):
            raise HTTPException(400, "expected a JSON object {parents: [mappings], size, seed}")
        size, seed = body.get("size", 8), body.get("seed", 0)
        if not isinstance(size, int) or not 1 <= size <= MAX_GALLERY:
            raise HTTPException(400, f"size must be an integer from 1 to {MAX_GALLERY}")
        if not isinstance(seed, int) or isinstance(seed, bool) or not 0 <= seed < 2**32:
            raise HTTPException(400, "seed must be an integer from 0 to 2³² − 1")
        if not body["parents"]:
            raise HTTPException(400, "select at least one parent to breed")
        parents = [Mapping.from_json(data, f"parent {index + 1}")
                   for index, data in enumerate(body["parents"])]
        children = breed(parents, size=size, seed=seed)
        return JSONResponse({"mappings": [m.to_json() for m in children]})

    async def get_mapping(request):
        item = library.mappings.get(request.path_params["id"])
        if item is None:
            raise HTTPException(404, f"no mapping with id '{request.path_params['id']}'")
        return JSONResponse(item.data)

    async def save_mapping(request):
        body = await json_body(request)
        name = os.path.basename(str(request.query_params.get("name", "mapping.json")))
        item = library.add_mapping(body, name)
        return JSONResponse(item.as_json(), status_code=201)

    async def api_missing(request):
        raise HTTPException(404, f"no API route {request.url.path}")

    async def no_front_end(request):
        return HTMLResponse("<!doctype html><title>eigendance</title><p>The web app is not built:"
                            " run <code>make setup</code> (npm ci + vite build).", status_code=503)

    async def on_http_error(request, problem: HTTPException):
        return error(problem.status_code, str(problem.detail))

    async def on_user_error(request, problem: EigendanceError):
        return error(400, str(problem))

    routes = [
        Route("/api/config", get_config),
        Route("/api/library", get_library),
        Route("/api/meshes/{id}", get_mesh),
        Route("/api/meshes/{id}/basis.bin", get_basis),
        Route("/api/songs/{id}/spectrogram.bin", get_spectrogram),
        Route("/api/songs/{id}/audio", get_audio),
        Route("/api/jobs/{id}", get_job),
        Route("/api/jobs/{id}/events", job_events),
        Route("/api/upload", upload, methods=["POST"]),
        Route("/api/gallery", gallery, methods=["POST"]),
        Route("/api/breed", breed_route, methods=["POST"]),
        Route("/api/mappings", save_mapping, methods=["POST"]),
        Route("/api/mappings/{id}", get_mapping),
        Route("/api/{rest:path}", api_missing, methods=["GET", "POST", "PUT", "DELETE"]),
    ]
    static = static_folder()
    if static:
        routes.append(Mount("/", StaticFiles(directory=static, html=True)))
    else:
        routes.append(Route("/", no_front_end))
    app = Starlette(routes=routes, exception_handlers={HTTPException: on_http_error,
                                                       EigendanceError: on_user_error})
    app.state.library = library
    return app
