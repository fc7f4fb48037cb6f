"""The HTTP API and the static web app (Starlette); routes are listed in `eigendance.server`.

Every route is a module-level function; the state it serves is the `Library` on
``request.app.state.library``. Requests pass `server.guard` first (Host, origin, content type).
Work heavier than a lookup (parsing a JSON body, decoding, galleries, breeding, rig analysis,
bundles, answers of many numbers) runs in a worker thread (`server.workers`), never on the
event loop. Every error is one line of JSON, ``{"error": "…"}``: 4xx for bad input, 500 for a
failure of ours; messages call uploads by their names, never by where they are stored.
"""

from __future__ import annotations

import asyncio
import hashlib
import json
import os
import tempfile
from importlib import resources

from starlette.applications import Starlette
from starlette.exceptions import HTTPException
from starlette.middleware import Middleware
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

from eigendance.errors import InputError, one_line
from eigendance.files import JSON_INTEGER_DIGITS, kind_of, suffix_of
from eigendance.modal.motion import default_mapping
from eigendance.modal.rig import rig_gallery
from eigendance.music.breeding import breed
from eigendance.music.gallery import (
    DEFAULT_GALLERY,
    MAX_GALLERY,
    MIN_GALLERY,
    check_gallery_size,
    initial_gallery,
)
from eigendance.music.mapping import Mapping
from eigendance.server.archive import is_archive
from eigendance.server.binary import rig_meta
from eigendance.server.guard import DEFAULT_HOST, Guard
from eigendance.server.library import Library, RigItem, check_mapping_size
from eigendance.server.workers import in_worker

AUDIO_TYPES = {".wav": "audio/wav", ".mp3": "audio/mpeg", ".ogg": "audio/ogg",
               ".oga": "audio/ogg", ".opus": "audio/ogg", ".flac": "audio/flac",
               ".m4a": "audio/mp4"}
JSON_LIMIT = 8 << 20  # bytes of a JSON request body
UPLOADS_AT_ONCE = 2  # uploads decoded at the same time (each may take hundreds of MB)


def static_folder() -> str | None:
    """The built front end inside the package, or None when it was never built."""
    path = os.fspath(resources.files("eigendance") / "static")
    return path if os.path.isfile(os.path.join(path, "index.html")) else None


def sniff(name: str, head: bytes) -> str | None:
    """Why the first bytes of an upload do not match its suffix, or None if they do."""
    suffix = suffix_of(name)
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
        ".zip": head[:2] == b"PK",  # a model in several files (server.archive)
        # read through Blender when it is installed; else the reader says how to convert them
        ".fbx": True, ".blend": True, ".dae": True, ".3ds": True,
    }
    if suffix not in checks:
        return f"unknown file type '{suffix}'"
    if not head:
        return "the file is empty"
    return None if checks[suffix] else f"the content is not a {suffix[1:].upper()} file"


# --- helpers ----------------------------------------------------------------------------------

def library_of(request: Request) -> Library:
    return request.app.state.library


def item_of(request: Request, kind: str, item_id):
    """The library's item of `kind` with `item_id`; 404 if there is none."""
    item = library_of(request).get(kind, str(item_id))
    if item is None:
        raise HTTPException(404, f"no {kind} with id '{one_line(str(item_id), 40)}'")
    return item


def mesh_of(request: Request, mesh_id: str):
    return item_of(request, "mesh", mesh_id)


def song_of(request: Request, song_id: str):
    return item_of(request, "song", song_id)


def ready_basis(request: Request, mesh_id: str):
    """The mesh item of `mesh_id` once its basis is ready; 409 while it is being computed."""
    item = mesh_of(request, mesh_id)
    if item.basis is None:
        state = item.job.state if item.job else "missing"
        message = item.job.message if item.job and item.job.message else \
            f"the basis of '{item.name}' is not ready ({state})"
        raise HTTPException(409, message)
    return item


async def json_body(request: Request):
    """The request's JSON document: Content-Type application/json, at most JSON_LIMIT bytes
    (refused before they are read), parsed in a thread by `parse_json`."""
    content_type = request.headers.get("content-type", "").split(";")[0].strip().lower()
    if content_type != "application/json":
        raise HTTPException(415, "send the request body as application/json")
    too_large = HTTPException(413, f"the request body is larger than {JSON_LIMIT >> 20} MiB")
    declared = request.headers.get("content-length", "")
    if declared.isdigit() and int(declared) > JSON_LIMIT:
        raise too_large
    chunks, size = [], 0
    async for chunk in request.stream():
        size += len(chunk)
        if size > JSON_LIMIT:
            raise too_large
        chunks.append(chunk)
    return await in_worker(parse_json, b"".join(chunks))


def _json_integer(text: str) -> int:
    if len(text) > JSON_INTEGER_DIGITS:
        raise InputError(f"the request body holds an integer of {len(text.lstrip('-'))} "
                         f"digits (at most {JSON_INTEGER_DIGITS})")
    return int(text)


def _json_constant(name: str):
    raise InputError(f"the request body holds {name}, which JSON does not allow")


def parse_json(body: bytes):
    """A JSON document with the rules of `files.read_json`: UTF-8, nesting within Python's
    recursion limit, integers of at most JSON_INTEGER_DIGITS digits; no NaN or Infinity."""
    try:
        return json.loads(body, parse_int=_json_integer, parse_constant=_json_constant)
    except InputError:
        raise
    except RecursionError:
        raise InputError("the request body is nested too deeply") from None
    except ValueError:  # UnicodeDecodeError and JSONDecodeError
        raise InputError("the request body is not valid JSON") from None


def json_answer(document, status: int = 200) -> Response:
    """A JSON response (rendered as JSONResponse does); call it in a worker thread when the
    document is large."""
    return Response(json.dumps(document, ensure_ascii=False, allow_nan=False,
                               separators=(",", ":")).encode(),
                    status_code=status, media_type="application/json")


async def answer(make, status: int = 200) -> Response:
    """make() → a JSON document, built and rendered in a worker thread."""
    return await in_worker(lambda: json_answer(make(), status))


def gallery_size(value) -> int:
    try:
        return check_gallery_size(value)
    except InputError as problem:
        raise HTTPException(400, str(problem)) from None


# --- routes -------------------------------------------------------------------------------------

async def get_config(request: Request):
    """Rules the page shares with the library: gallery sizes."""
    return JSONResponse({"gallery": {"min": MIN_GALLERY, "max": MAX_GALLERY,
                                     "default": DEFAULT_GALLERY}})


async def get_library(request: Request):
    return JSONResponse(library_of(request).as_json())


async def get_mesh(request: Request):
    return JSONResponse(mesh_of(request, request.path_params["id"]).as_json())


async def get_basis(request: Request):
    """The basis bundle; ?dtype=float16 sends the harmonics as float16 (half the bytes)."""
    item = ready_basis(request, request.path_params["id"])
    dtype = request.query_params.get("dtype", "float32")
    if dtype not in ("float32", "float16"):
        raise HTTPException(400, "dtype must be float32 or float16")
    if dtype == "float16":
        bundle = await in_worker(library_of(request).half_bundle, item)
    else:
        bundle = item.bundle
    return Response(bundle, media_type="application/octet-stream",
                    headers={"Cache-Control": "no-cache"})


async def get_mesh_look(request: Request):
    """The mesh's appearance bundle (docs/web.md#appearance-bundle): drawn vertices, materials,
    images; ready before its basis. 404 for a mesh without materials (drawn in clay)."""
    item = mesh_of(request, request.path_params["id"])
    return bundle_response(await in_worker(library_of(request).look_bundle, item))


async def get_spectrogram(request: Request):
    item = song_of(request, request.path_params["id"])
    return Response(item.bundle, media_type="application/octet-stream")


async def get_audio(request: Request):
    item = song_of(request, request.path_params["id"])
    media_type = AUDIO_TYPES.get(suffix_of(item.name), "application/octet-stream")
    return FileResponse(item.path, media_type=media_type)


def job_of(request: Request):
    job = library_of(request).jobs.get(request.path_params["id"])
    if job is None:
        raise HTTPException(404, f"no job with id '{one_line(request.path_params['id'], 40)}'")
    return job


async def get_job(request: Request):
    return JSONResponse(job_of(request).as_json())


async def job_events(request: Request):
    """Server-sent events with the job's state until it is done or failed (or the server
    stops)."""
    job = job_of(request)
    stopping = library_of(request).stopping

    async def stream():
        last = None
        while True:
            state = job.as_json()
            if state != last:
                yield f"data: {json.dumps(state)}\n\n"
                last = state
            if state["state"] in ("done", "error"):
                return
            if stopping.is_set() or await request.is_disconnected():
                return
            await asyncio.sleep(0.1)

    return StreamingResponse(stream(), media_type="text/event-stream",
                             headers={"Cache-Control": "no-cache"})


async def upload(request: Request):
    """A raw file body named by ?name=FILE: a mesh, an audio file, a mapping or skeleton JSON.
    201 with the new item; 200 with the item already there when the same content was."""
    library = library_of(request)
    name = os.path.basename(request.query_params.get("name", "").replace("\\", "/"))
    if not name or name.startswith("."):
        raise HTTPException(400, "upload needs ?name=FILE with a file name and suffix")
    kind = "mesh" if is_archive(name) else kind_of(name)
    stored, digest, head = await receive_file(request, library, name)
    try:
        if (why := sniff(name, head)) is not None:
            raise HTTPException(415, f"{name}: {why}")
        async with request.app.state.uploads:
            item, new = await in_worker(library.add_upload, stored, name, kind, digest)
    finally:
        if os.path.exists(stored):
            os.unlink(stored)
    if isinstance(item, RigItem):  # a skeleton JSON
        kind = "rig"
    reply = {"kind": "song" if kind == "audio" else kind, "item": item.as_json()}
    if kind == "mesh":
        reply["job"] = item.job.as_json()
        if item.rig in library.rigs:  # a glTF with a skin is a rig too
            reply["rig"] = library.rigs[item.rig].as_json()
    return JSONResponse(reply, status_code=201 if new else 200)


async def receive_file(request: Request, library: Library, name: str):
    """Stream the body into a temporary file of the library folder, within the upload limit
    (413 as soon as it is passed): (its path, its SHA-256, its first 4096 bytes)."""
    limit = library.max_upload_bytes
    too_large = HTTPException(413, f"{name}: larger than the {limit >> 20} MiB upload limit")
    declared = request.headers.get("content-length", "")
    if declared.isdigit() and int(declared) > limit:
        raise too_large
    os.makedirs(library.folder, exist_ok=True)  # a /tmp cleaner may have removed it meanwhile
    handle, path = tempfile.mkstemp(dir=library.folder, prefix=".incoming-")
    digest, head, size = hashlib.sha256(), b"", 0
    try:
        with os.fdopen(handle, "wb") as file:
            async for chunk in request.stream():
                size += len(chunk)
                if size > limit:
                    raise too_large
                digest.update(chunk)
                file.write(chunk)
                head += chunk[:4096 - len(head)]
    except BaseException:
        os.unlink(path)
        raise
    return path, digest.hexdigest(), head


async def gallery(request: Request):
    """The initial gallery of a mesh for a song: {mesh, song, size} → {mappings}."""
    body = await json_body(request)
    if not isinstance(body, dict):
        raise HTTPException(400, "expected a JSON object {mesh, song, size}")
    item = ready_basis(request, str(body.get("mesh")))
    song = song_of(request, str(body.get("song")))
    size = gallery_size(body.get("size", DEFAULT_GALLERY))
    return await answer(lambda: {"mappings": [
        m.to_json() for m in initial_gallery(item.basis, song.spectrogram, size)]})


async def breed_route(request: Request):
    """Children of the selected mappings: {parents, size, seed} → {mappings}."""
    body = await json_body(request)
    if not isinstance(body, dict) or not isinstance(body.get("parents"), list):
        raise HTTPException(400, "expected a JSON object {parents: [mappings], size, seed}")
    size = gallery_size(body.get("size", DEFAULT_GALLERY))
    seed = body.get("seed", 0)
    if not isinstance(seed, int) or isinstance(seed, bool) or not 0 <= seed < 2**32:
        raise HTTPException(400, "seed must be an integer from 0 to 2³² − 1")
    if not body["parents"]:
        raise HTTPException(400, "select at least one parent to breed")
    if len(body["parents"]) > MAX_GALLERY:
        raise HTTPException(400, f"select at most {MAX_GALLERY} parents to breed")
    for index, data in enumerate(body["parents"]):
        check_mapping_size(data, f"parent {index + 1}")

    def make():
        parents = [Mapping.from_json(data, f"parent {index + 1}")
                   for index, data in enumerate(body["parents"])]
        return {"mappings": [m.to_json() for m in breed(parents, size, seed)]}

    return await answer(make)


async def get_mapping(request: Request):
    item = item_of(request, "mapping", request.path_params["id"])
    return await answer(lambda: item.data)


async def save_mapping(request: Request):
    """A mapping document → 201 with the new item (200 with the same mapping already there)."""
    body = await json_body(request)
    name = os.path.basename(str(request.query_params.get("name", "mapping.json"))) or \
        "mapping.json"
    item, new = await in_worker(library_of(request).add_mapping, body, name)
    return JSONResponse(item.as_json(), status_code=201 if new else 200)


def removal(kind: str):
    """The DELETE route of an item of `kind`: {removed: [ids]} (a mesh takes the rig of its
    skin with it); 404 for an unknown id, 409 for a built-in rig."""
    async def remove(request: Request):
        removed = library_of(request).remove(kind, request.path_params["id"])
        return JSONResponse({"removed": removed})

    remove.__name__ = f"remove_{kind}"
    return remove


# --- rigs (docs/web.md#rig-api) -----------------------------------------------------------------

def rig_of(request: Request) -> RigItem:
    return item_of(request, "rig", request.path_params["id"])


def bundle_response(bundle: bytes) -> Response:
    return Response(bundle, media_type="application/octet-stream",
                    headers={"Cache-Control": "no-cache"})


async def ready_rig(request: Request) -> RigItem:
    """The rig of the path's id, analysed (built-in rigs are analysed on first use)."""
    return await in_worker(library_of(request).ready_rig, rig_of(request))


async def get_rig(request: Request):
    """The rig's description: the rig bundle's `meta` and the item's state."""
    item = await ready_rig(request)
    return await answer(lambda: {**item.as_json(), **rig_meta(item.rig, item.name,
                                                              item.revision)})


async def get_rig_bundle(request: Request):
    return bundle_response((await ready_rig(request)).bundle)


async def get_rig_look(request: Request):
    """The appearance bundle of the rig's skin; 404 for a skin without materials."""
    item = await ready_rig(request)
    return bundle_response(await in_worker(library_of(request).look_bundle, item))


async def get_rig_skeleton(request: Request):
    """The current skeleton as a skeleton JSON document (the edits included)."""
    item = await ready_rig(request)
    return await answer(item.rig.skeleton.to_dict)


async def rig_stiffness(request: Request):
    """{joints: {name: number | [per free row] | "auto"}, scale?} → the new rig bundle."""
    rig_of(request)
    body = await json_body(request)
    if not isinstance(body, dict) or not isinstance(body.get("joints", {}), dict):
        raise HTTPException(400, "expected a JSON object {joints: {joint name: stiffness}, "
                                 "scale}")
    scale = body.get("scale", 1.0)
    if isinstance(scale, bool) or not isinstance(scale, int | float):
        raise HTTPException(400, "scale must be a number ≥ 0")
    item = await ready_rig(request)
    values = body.get("joints", {})
    bundle = await in_worker(library_of(request).edit_rig, item,
                                     lambda skeleton: skeleton.with_stiffness(values, scale))
    return bundle_response(bundle)


async def rig_pose(request: Request):
    """{joint: name or index, rotation: [3 numbers, radians]} → the new rig bundle."""
    rig_of(request)
    body = await json_body(request)
    if not isinstance(body, dict) or "joint" not in body or \
            not isinstance(body.get("rotation"), list):
        raise HTTPException(400, "expected a JSON object {joint, rotation: [x, y, z] radians}")
    joint, rotation = body["joint"], body["rotation"]
    if isinstance(joint, bool) or not isinstance(joint, str | int):
        raise HTTPException(400, "joint must be a joint name or index")
    if len(rotation) != 3 or any(isinstance(v, bool) or not isinstance(v, int | float)
                                 for v in rotation):
        raise HTTPException(400, "rotation must be 3 numbers (a rotation vector, radians)")
    item = await ready_rig(request)
    bundle = await in_worker(library_of(request).edit_rig, item,
                                     lambda skeleton: skeleton.rotate_joint(joint, rotation))
    return bundle_response(bundle)


async def rig_reset(request: Request):
    """The rig as loaded again (pose and stiffness) → its bundle."""
    item = await ready_rig(request)
    return bundle_response(await in_worker(library_of(request).reset_rig, item))


async def rig_gallery_route(request: Request):
    """The initial gallery of mode mappings: {rig, song, size} → {mappings, default}."""
    body = await json_body(request)
    if not isinstance(body, dict):
        raise HTTPException(400, "expected a JSON object {rig, song, size}")
    library = library_of(request)
    item = item_of(request, "rig", body.get("rig"))
    song = song_of(request, str(body.get("song")))
    size = gallery_size(body.get("size", DEFAULT_GALLERY))
    await in_worker(library.ready_rig, item)
    rig = item.rig
    if rig.palette is None:
        raise HTTPException(409, f"{item.name}: the rig has no vibration mode; nothing to "
                                 "dance")

    def make():
        dancer = rig.dancer(band_edges=song.spectrogram.band_edges)
        items = rig_gallery(dancer, song.spectrogram, size)
        default = default_mapping(song.spectrogram, len(rig.palette.selected))
        return {"mappings": [m.to_json() for m in items], "default": default.to_json()}

    return await answer(make)


async def api_missing(request: Request):
    raise HTTPException(404, f"no API route {request.url.path}")


async def no_front_end(request: Request):
    return HTMLResponse("<!doctype html><title>eigendance</title><p>The web app is not built: "
                        "run <code>make web</code> (npm ci + vite build).", status_code=503)


# --- errors ---------------------------------------------------------------------------------------

def error_response(request: Request, status: int, message: str) -> JSONResponse:
    """One line of JSON; uploads called by their names, no path of the library folder."""
    return JSONResponse({"error": one_line(library_of(request).public(message))},
                        status_code=status)


async def on_http_error(request: Request, problem: HTTPException):
    return error_response(request, problem.status_code, str(problem.detail))


async def on_input_error(request: Request, problem: InputError):
    return error_response(request, problem.status, str(problem))


API_ROUTES = [
    Route("/api/config", get_config),
    Route("/api/library", get_library),
    Route("/api/meshes/{id}", get_mesh),
    Route("/api/meshes/{id}", removal("mesh"), methods=["DELETE"]),
    Route("/api/meshes/{id}/basis.bin", get_basis),
    Route("/api/meshes/{id}/appearance.bin", get_mesh_look),
    Route("/api/songs/{id}/spectrogram.bin", get_spectrogram),
    Route("/api/songs/{id}/audio", get_audio),
    Route("/api/jobs/{id}", get_job),
    Route("/api/jobs/{id}/events", job_events),
    Route("/api/upload", upload, methods=["POST"]),
    Route("/api/gallery", gallery, methods=["POST"]),
    Route("/api/breed", breed_route, methods=["POST"]),
    Route("/api/mappings", save_mapping, methods=["POST"]),
    Route("/api/mappings/{id}", get_mapping),
    Route("/api/mappings/{id}", removal("mapping"), methods=["DELETE"]),
    Route("/api/songs/{id}", removal("song"), methods=["DELETE"]),
    Route("/api/rigs/{id}", get_rig),
    Route("/api/rigs/{id}", removal("rig"), methods=["DELETE"]),
    Route("/api/rigs/{id}/rig.bin", get_rig_bundle),
    Route("/api/rigs/{id}/appearance.bin", get_rig_look),
    Route("/api/rigs/{id}/skeleton.json", get_rig_skeleton),
    Route("/api/rigs/{id}/stiffness", rig_stiffness, methods=["POST"]),
    Route("/api/rigs/{id}/pose", rig_pose, methods=["POST"]),
    Route("/api/rigs/{id}/reset", rig_reset, methods=["POST"]),
    Route("/api/rig-gallery", rig_gallery_route, methods=["POST"]),
    Route("/api/{rest:path}", api_missing, methods=["GET", "POST", "PUT", "DELETE"]),
]


def create_app(library: Library, host: str = DEFAULT_HOST, port: int | None = None) -> Starlette:
    """The web app serving `library` (see `eigendance.server` for the routes) on `host`:`port`
    (the Host headers it answers; port None: any port)."""
    static = static_folder()
    front_end = Mount("/", StaticFiles(directory=static, html=True)) if static else \
        Route("/", no_front_end)
    app = Starlette(routes=[*API_ROUTES, front_end],
                    middleware=[Middleware(Guard, host=host, port=port, scrub=library.public)],
                    exception_handlers={HTTPException: on_http_error, InputError: on_input_error})
    app.state.library = library
    app.state.uploads = asyncio.Semaphore(UPLOADS_AT_ONCE)
    return app
