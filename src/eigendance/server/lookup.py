"""Finding a request's items: the library of the app, and its meshes, songs, jobs and rigs by
the ids in the request (docs/design.md#server). An unknown id is a 404, a basis not ready yet
a 409.
"""

from __future__ import annotations

from starlette.exceptions import HTTPException
from starlette.requests import Request
from starlette.responses import (
    Response,
)

from eigendance.errors import one_line
from eigendance.server.items import RigItem
from eigendance.server.library import Library
from eigendance.server.workers import in_worker


def library_of(request: Request) -> Library:
    """The library the app serves.

    Parameters
    ----------
    request : any request.

    Returns
    -------
    Library.
    """
    return request.app.state.library


def item_of(request: Request, kind: str, item_id):
    """The library's item of `kind` with `item_id`.

    Parameters
    ----------
    request : the request.
    kind : "mesh", "song", "mapping" or "rig".
    item_id : the id it names.

    Returns
    -------
    The item; HTTPException 404 if there is none.
    """
    item = library_of(request).get(kind, str(item_id))
    if item is None:
        raise HTTPException(404, f"no {kind} with id '{one_line(str(item_id), 40)}'")
    return item


def mesh_of(request: Request, mesh_id: str):
    """The mesh item of `mesh_id` (404 if there is none).

    Parameters
    ----------
    request : the request.
    mesh_id : the id.

    Returns
    -------
    MeshItem.
    """
    return item_of(request, "mesh", mesh_id)


def song_of(request: Request, song_id: str):
    """The song item of `song_id` (404 if there is none).

    Parameters
    ----------
    request : the request.
    song_id : the id.

    Returns
    -------
    SongItem.
    """
    return item_of(request, "song", song_id)


def ready_basis(request: Request, mesh_id: str):
    """The mesh item of `mesh_id` once its basis is ready.

    Parameters
    ----------
    request : the request.
    mesh_id : the id.

    Returns
    -------
    MeshItem with its basis; HTTPException 409 while it is computed (or its failure).
    """
    item = mesh_of(request, mesh_id)
    if item.basis is None:
        state = item.job.state if item.job else "missing"
        message = item.job.message if item.job and item.job.message else \
            f"the basis of '{item.name}' is not ready ({state})"
        raise HTTPException(409, message)
    return item


def job_of(request: Request):
    """The job of the path's id (404 if there is none).

    Parameters
    ----------
    request : a request with path parameter id.

    Returns
    -------
    Job.
    """
    job = library_of(request).jobs.get(request.path_params["id"])
    if job is None:
        raise HTTPException(404, f"no job with id '{one_line(request.path_params['id'], 40)}'")
    return job


def rig_of(request: Request) -> RigItem:
    """The rig item of the path's id (404 if there is none), not analysed yet.

    Parameters
    ----------
    request : a request with path parameter id.

    Returns
    -------
    RigItem.
    """
    return item_of(request, "rig", request.path_params["id"])


def bundle_response(bundle: bytes) -> Response:
    """A binary bundle as the page reads it.

    Parameters
    ----------
    bundle : the bundle's bytes.

    Returns
    -------
    Response, application/octet-stream, not cached.
    """
    return Response(bundle, media_type="application/octet-stream",
                    headers={"Cache-Control": "no-cache"})


async def ready_rig(request: Request) -> RigItem:
    """The rig item of the path's id, analysed (built-in rigs are analysed on first use), in a
    worker thread.

    Parameters
    ----------
    request : a request with path parameter id.

    Returns
    -------
    RigItem; 404 for an unknown id, 409 when it cannot be analysed.
    """
    return await in_worker(library_of(request).ready_rig, rig_of(request))
