"""The library's routes: meshes, songs, jobs, uploads, galleries, breeding, mappings and
removal (docs/web.md#http-api). Each is a module-level function of the request; work heavier
than a lookup runs in a worker thread (`server.workers`).
"""

from __future__ import annotations

import asyncio
import hashlib
import json
import os
import tempfile

from starlette.exceptions import HTTPException
from starlette.requests import Request
from starlette.responses import (
    FileResponse,
    JSONResponse,
    Response,
    StreamingResponse,
)

from eigendance.files import kind_of, suffix_of
from eigendance.music.breeding import breed
from eigendance.music.gallery import DEFAULT_GALLERY, MAX_GALLERY, MIN_GALLERY, initial_gallery
from eigendance.music.mapping import Mapping
from eigendance.server.items import RigItem
from eigendance.server.library import Library
from eigendance.server.lookup import item_of, job_of, library_of, mesh_of, ready_basis, song_of
from eigendance.server.requests import (
    answer,
    check_mapping_size,
    gallery_size,
    json_body,
)
from eigendance.server.workers import in_worker

AUDIO_TYPES = {".wav": "audio/wav", ".mp3": "audio/mpeg", ".ogg": "audio/ogg",
               ".oga": "audio/ogg", ".opus": "audio/ogg", ".flac": "audio/flac",
               ".m4a": "audio/mp4"}
UPLOADS_AT_ONCE = 2  # uploads decoded at the same time (each may take hundreds of MB)


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
    }
    if suffix not in checks:
        return f"unknown file type '{suffix}'"
    if not head:
        return "the file is empty"
    return None if checks[suffix] else f"the content is not a {suffix[1:].upper()} file"


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


async def get_spectrogram(request: Request):
    item = song_of(request, request.path_params["id"])
    return Response(item.bundle, media_type="application/octet-stream")


async def get_audio(request: Request):
    item = song_of(request, request.path_params["id"])
    media_type = AUDIO_TYPES.get(suffix_of(item.name), "application/octet-stream")
    return FileResponse(item.path, media_type=media_type)


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
    kind = kind_of(name)
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
