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

from eigendance.checks import number
from eigendance.files import kind_of, suffix_of
from eigendance.inputs.mapping import check_mapping_size, mapping_from
from eigendance.inputs.model import published_suffixes
from eigendance.music.breeding import bounded_children, breed
from eigendance.music.gallery import DEFAULT_GALLERY, MAX_GALLERY, MIN_GALLERY, initial_gallery
from eigendance.server.archive import is_archive
from eigendance.server.items import RigItem
from eigendance.server.library import Library
from eigendance.server.lookup import (
    bundle_response,
    item_of,
    job_of,
    library_of,
    mesh_of,
    ready_basis,
    song_of,
)
from eigendance.server.requests import answer, gallery_size, json_body
from eigendance.server.workers import in_worker

AUDIO_TYPES = {".wav": "audio/wav", ".mp3": "audio/mpeg", ".ogg": "audio/ogg",
               ".oga": "audio/ogg", ".opus": "audio/ogg", ".flac": "audio/flac",
               ".m4a": "audio/mp4"}
UPLOADS_AT_ONCE = 2  # uploads decoded at the same time (each may take hundreds of MB)


def sniff(name: str, head: bytes) -> str | None:
    """Why the first bytes of an upload do not match its suffix.

    Parameters
    ----------
    name : the name it was uploaded under.
    head : its first 4096 bytes.

    Returns
    -------
    str (the reason), or None when they match.
    """
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
        # Matroska/WebM (EBML): what a browser records, a live take among them
        ".webm": head[:4] == b"\x1aE\xdf\xa3", ".mka": head[:4] == b"\x1aE\xdf\xa3",
        ".json": text_like and head.lstrip()[:1] == b"{",
        ".zip": head[:2] == b"PK",  # a model in several files (server.archive)
        # read through Blender when it is installed; else the reader says how to convert them
        ".fbx": True, ".blend": True, ".dae": True, ".3ds": True,
    }
    if suffix not in checks:
        return f"unknown file type '{suffix}'"
    if not head:
        return "the file is empty"
    name = suffix[1:].upper()
    article = "an" if name[0] in "AEFHILMNORSX" and name != "FLAC" else "a"  # an MP3, a WAV
    return None if checks[suffix] else f"the content is not {article} {name} file"


async def get_config(request: Request):
    """GET /api/config: rules the page shares with the library.

    Parameters
    ----------
    request : the request.

    Returns
    -------
    JSONResponse {"gallery": {"min", "max", "default"}: gallery sizes, "suffixes": the
    suffixes of each input kind (`inputs.model.published_suffixes`: what the page uploads, and
    which files of a model it zips together)}.
    """
    return JSONResponse({"gallery": {"min": MIN_GALLERY, "max": MAX_GALLERY,
                                     "default": DEFAULT_GALLERY},
                         "suffixes": published_suffixes()})


async def get_library(request: Request):
    """GET /api/library: every item and the memory used.

    Parameters
    ----------
    request : the request.

    Returns
    -------
    JSONResponse (`Library.as_json`).
    """
    return JSONResponse(library_of(request).as_json())


async def get_mesh(request: Request):
    """GET /api/meshes/{id}: a mesh item and its basis job.

    Parameters
    ----------
    request : path parameter id.

    Returns
    -------
    JSONResponse (`MeshItem.as_json`); 404 for an unknown id.
    """
    return JSONResponse(mesh_of(request, request.path_params["id"]).as_json())


async def get_basis(request: Request):
    """GET /api/meshes/{id}/basis.bin: the basis bundle.

    Parameters
    ----------
    request : path parameter id; ?dtype=float16 sends the harmonics as float16 (half the bytes).

    Returns
    -------
    Response, the bundle (`binary.basis_bundle`); 409 while the basis is computed.
    """
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
    """GET /api/meshes/{id}/appearance.bin: the mesh's appearance bundle
    (docs/web.md#appearance-bundle), ready before its basis.

    Parameters
    ----------
    request : path parameter id.

    Returns
    -------
    Response, the bundle (`binary.appearance_bundle`); 404 for a mesh without materials.
    """
    item = mesh_of(request, request.path_params["id"])
    return bundle_response(await in_worker(library_of(request).look_bundle, item))


async def get_spectrogram(request: Request):
    """GET /api/songs/{id}/spectrogram.bin: the spectrogram bundle.

    Parameters
    ----------
    request : path parameter id.

    Returns
    -------
    Response, the bundle (`binary.spectrogram_bundle`).
    """
    item = song_of(request, request.path_params["id"])
    return Response(item.bundle, media_type="application/octet-stream")


async def get_audio(request: Request):
    """GET /api/songs/{id}/audio: the song's file, for the page to play.

    Parameters
    ----------
    request : path parameter id.

    Returns
    -------
    FileResponse with the audio's media type.
    """
    item = song_of(request, request.path_params["id"])
    media_type = AUDIO_TYPES.get(suffix_of(item.name), "application/octet-stream")
    return FileResponse(item.path, media_type=media_type)


async def get_job(request: Request):
    """GET /api/jobs/{id}: a basis job's state.

    Parameters
    ----------
    request : path parameter id.

    Returns
    -------
    JSONResponse (`Job.as_json`).
    """
    return JSONResponse(job_of(request).as_json())


async def job_events(request: Request):
    """GET /api/jobs/{id}/events: the job's state as server-sent events, until it is done or failed
    (or the server stops, or the page leaves).

    Parameters
    ----------
    request : path parameter id.

    Returns
    -------
    StreamingResponse, text/event-stream: one `data:` line per change.
    """
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
    """POST /api/upload?name=FILE: a raw file body: a mesh, an audio file, a mapping or a
    skeleton JSON.

    Parameters
    ----------
    request : the body (at most --max-upload-mb) and ?name= with its suffix.

    Returns
    -------
    JSONResponse {"kind", "item", "job"?, "rig"?}: 201 with the new item, 200 with the item
    already there when the same content was; 413 too large, 415 a content that is not its suffix.
    """
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


async def take(request: Request):
    """POST /api/takes?name=FILE: a live take recorded in the page (docs/design.md#live), kept
    as a song of the library: checked as any upload (the size limit, the content against its
    suffix, decoded and analysed), and refused unless it is audio.

    Parameters
    ----------
    request : the recorded audio (WebM/Opus from the page) and ?name= with its suffix.

    Returns
    -------
    JSONResponse as `upload` ({"kind": "song", "item"}); 415 for a name that is not audio.
    """
    name = os.path.basename(request.query_params.get("name", "").replace("\\", "/"))
    if not name or name.startswith("."):
        raise HTTPException(400, "a take needs ?name=FILE with a file name and an audio suffix")
    kind_of(name, ("audio",))  # InputError (415) for anything but audio
    return await upload(request)


async def receive_file(request: Request, library: Library, name: str):
    """Stream the body into a temporary file of the library folder, within the upload limit (413 as
    soon as it is passed).

    Parameters
    ----------
    request : the upload.
    library : the library (its folder and limit).
    name : the name it was uploaded under (for messages).

    Returns
    -------
    (its path, its SHA-256, its first 4096 bytes).
    """
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
    """POST /api/gallery {mesh, song, size}: the initial gallery of a mesh for a song.

    Parameters
    ----------
    request : the JSON body.

    Returns
    -------
    JSONResponse {"mappings": [S mapping documents]} (`initial_gallery`).
    """
    body = await json_body(request)
    if not isinstance(body, dict):
        raise HTTPException(400, "expected a JSON object {mesh, song, size}")
    item = ready_basis(request, str(body.get("mesh")))
    song = song_of(request, str(body.get("song")))
    size = gallery_size(body.get("size", DEFAULT_GALLERY))
    return await answer(lambda: {"mappings": [
        m.to_json() for m in initial_gallery(item.basis, song.spectrogram, size)]})


async def breed_route(request: Request):
    """POST /api/breed {parents, size, seed, mesh | rig?, song?}: children of the selected
    mappings, bounded on the model and song when the body names them (`children_bound`).

    Parameters
    ----------
    request : the JSON body (at most 16 parents, each within the mapping sizes).

    Returns
    -------
    JSONResponse {"mappings": [size children]} (`breed`).
    """
    body = await json_body(request)
    if not isinstance(body, dict) or not isinstance(body.get("parents"), list):
        raise HTTPException(400, "expected a JSON object {parents: [mappings], size, seed}")
    size = gallery_size(body.get("size", DEFAULT_GALLERY))
    seed = number(body.get("seed", 0), "seed", 0, 2**32 - 1, integer=True)
    if not body["parents"]:
        raise HTTPException(400, "select at least one parent to breed")
    if len(body["parents"]) > MAX_GALLERY:
        raise HTTPException(400, f"select at most {MAX_GALLERY} parents to breed")
    for index, data in enumerate(body["parents"]):
        check_mapping_size(data, f"parent {index + 1}")

    bound = await children_bound(request, body)

    def make():
        parents = [mapping_from(data, f"parent {index + 1}")
                   for index, data in enumerate(body["parents"])]
        return {"mappings": [m.to_json() for m in bound(breed(parents, size, seed))]}

    return await answer(make)


async def children_bound(request: Request, body: dict):
    """What bounds the children of a breeding (`bounded_children`): on the model (`mesh` or
    `rig`) and `song` of the body, when it names them; else nothing (children as bred).

    Parameters
    ----------
    request : the breeding request.
    body : its JSON body.

    Returns
    -------
    callable(children) → children.
    """
    if "song" not in body or not ("mesh" in body or "rig" in body):
        return lambda children: children
    song = song_of(request, str(body["song"])).spectrogram
    if "rig" in body:
        item = item_of(request, "rig", str(body["rig"]))
        await in_worker(library_of(request).ready_rig, item)
        rig = item.rig
        return lambda children: [bounded_children(rig.dancer(rig.palette_of(child)), song,
                                                  [child], rig=True)[0] for child in children]
    basis = ready_basis(request, str(body["mesh"])).basis
    return lambda children: bounded_children(basis, song, children)


async def get_mapping(request: Request):
    """GET /api/mappings/{id}: a saved mapping.

    Parameters
    ----------
    request : path parameter id.

    Returns
    -------
    JSON response, the mapping document.
    """
    item = item_of(request, "mapping", request.path_params["id"])
    return await answer(lambda: item.data)


async def save_mapping(request: Request):
    """POST /api/mappings?name=: save a mapping document.

    Parameters
    ----------
    request : the JSON body, ?name= how the library calls it.

    Returns
    -------
    JSONResponse, the item: 201 new, 200 when the same mapping was there.
    """
    body = await json_body(request)
    name = os.path.basename(str(request.query_params.get("name", "mapping.json"))) or \
        "mapping.json"
    item, new = await in_worker(library_of(request).add_mapping, body, name)
    return JSONResponse(item.as_json(), status_code=201 if new else 200)


def removal(kind: str):
    """The DELETE route of an item of `kind`.

    Parameters
    ----------
    kind : "mesh", "song", "mapping" or "rig".

    Returns
    -------
    The route: request → JSONResponse {"removed": [ids]} (a mesh takes the rig of its skin with
    it); 404 for an unknown id, 409 for a built-in rig.
    """
    async def remove(request: Request):
        removed = library_of(request).remove(kind, request.path_params["id"])
        return JSONResponse({"removed": removed})

    remove.__name__ = f"remove_{kind}"
    return remove
