"""The HTTP API and the static web app (Starlette); routes are listed in `eigendance.server`.

Every route is a module-level function (`server.routes`: the library's; `server.rig_routes`:
the rigs'); the state it serves is the `Library` on ``request.app.state.library``. Requests
pass `server.guard` first (Host, origin, content type). Work heavier than a lookup (parsing a
JSON body, decoding, galleries, breeding, rig analysis, bundles, answers of many numbers) runs
in a worker thread (`server.workers`), never on the event loop. Every error is one line of
JSON, ``{"error": "…"}``: 4xx for bad input, 500 for a failure of ours; messages call uploads
by their names, never by where they are stored.
"""

from __future__ import annotations

import asyncio
import os
from importlib import resources

from starlette.applications import Starlette
from starlette.exceptions import HTTPException
from starlette.middleware import Middleware
from starlette.requests import Request
from starlette.responses import HTMLResponse, JSONResponse
from starlette.routing import Mount, Route
from starlette.staticfiles import StaticFiles

from eigendance.errors import InputError, disk_full, one_line
from eigendance.presets.store import PresetStore, default_folder
from eigendance.server.export_route import download_export, export_clip
from eigendance.server.guard import DEFAULT_HOST, Guard
from eigendance.server.library import Library
from eigendance.server.lookup import library_of
from eigendance.server.preset_routes import (
    change_preset,
    delete_preset,
    export_preset,
    get_preset,
    list_presets,
    preset_thumbnail,
    save_preset,
)
from eigendance.server.rig_routes import (
    get_rig,
    get_rig_bundle,
    get_rig_look,
    get_rig_skeleton,
    rig_gallery_route,
    rig_pose,
    rig_reset,
    rig_stiffness,
)
from eigendance.server.routes import (
    UPLOADS_AT_ONCE,
    breed_route,
    gallery,
    get_audio,
    get_basis,
    get_config,
    get_job,
    get_library,
    get_mapping,
    get_mesh,
    get_mesh_look,
    get_spectrogram,
    job_events,
    removal,
    save_mapping,
    take,
    upload,
)
from eigendance.server.show_routes import (
    show_clock,
    show_control,
    show_events,
    show_page,
    show_state,
)
from eigendance.server.surface_routes import get_rig_surface, rig_surface_gallery
from eigendance.show.state import ShowState


def static_folder() -> str | None:
    """The built front end inside the package.

    Returns
    -------
    str, the folder of static/index.html, or None when the front end was never built.
    """
    path = os.fspath(resources.files("eigendance") / "static")
    return path if os.path.isfile(os.path.join(path, "index.html")) else None


async def api_missing(request: Request):
    """Any /api/ path that no route answers.

    Parameters
    ----------
    request : the request.

    Returns
    -------
    Never: HTTPException 404 naming the path.
    """
    raise HTTPException(404, f"no API route {request.url.path}")


async def no_front_end(request: Request):
    """The page when the front end was never built.

    Parameters
    ----------
    request : the request.

    Returns
    -------
    HTMLResponse 503 saying how to build it.
    """
    return HTMLResponse("<!doctype html><title>eigendance</title><p>The web app is not built: "
                        "run <code>make web</code> (npm ci + vite build).", status_code=503)


# --- errors ---------------------------------------------------------------------------------------

def error_response(request: Request, status: int, message: str) -> JSONResponse:
    """One line of JSON; uploads called by their names, no path of the library folder.

    Parameters
    ----------
    request : the request that failed.
    status : the HTTP status.
    message : what went wrong.

    Returns
    -------
    JSONResponse {"error": message}.
    """
    return JSONResponse({"error": one_line(library_of(request).public(message))},
                        status_code=status)


async def on_http_error(request: Request, problem: HTTPException):
    """Starlette's errors (404, 405, and ours raised as HTTPException) as one line of JSON.

    Parameters
    ----------
    request : the request that failed.
    problem : the exception.

    Returns
    -------
    JSONResponse with its status.
    """
    return error_response(request, problem.status_code, str(problem.detail))


async def on_input_error(request: Request, problem: InputError):
    """An `InputError` as one line of JSON with its status (400 by default).

    Parameters
    ----------
    request : the request that failed.
    problem : the exception.

    Returns
    -------
    JSONResponse with its status.
    """
    return error_response(request, problem.status, str(problem))


async def on_os_error(request: Request, problem: OSError):
    """A full disk (or quota) under the library as one line of JSON, 507; any other OSError
    goes on to the guard (500, one line).

    Parameters
    ----------
    request : the request that failed.
    problem : the exception.

    Returns
    -------
    JSONResponse 507.
    """
    if not disk_full(problem):
        raise problem
    return error_response(request, 507, "the library's disk is full (no space left for the "
                                        "file); free some space or remove items")


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
    Route("/api/takes", take, methods=["POST"]),
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
    Route("/api/rigs/{id}/surface.bin", get_rig_surface),
    Route("/api/rig-surface-gallery", rig_surface_gallery, methods=["POST"]),
    Route("/api/export", export_clip, methods=["POST"]),
    Route("/api/exports/{id}", download_export),
    Route("/api/presets", list_presets),
    Route("/api/presets", save_preset, methods=["POST"]),
    Route("/api/presets/{name}", get_preset),
    Route("/api/presets/{name}", change_preset, methods=["PATCH"]),
    Route("/api/presets/{name}", delete_preset, methods=["DELETE"]),
    Route("/api/presets/{name}/thumbnail.png", preset_thumbnail),
    Route("/api/presets/{name}/file", export_preset),
    Route("/api/show/state", show_state),
    Route("/api/show/events", show_events),
    Route("/api/show/control", show_control, methods=["POST"]),
    Route("/api/show/clock", show_clock, methods=["POST"]),
    Route("/api/{rest:path}", api_missing, methods=["GET", "POST", "PUT", "DELETE"]),
]


def create_app(library: Library, host: str = DEFAULT_HOST, port: int | None = None,
               presets: PresetStore | None = None, show: ShowState | None = None) -> Starlette:
    """The web app serving `library` (see `eigendance.server` for the routes).

    Parameters
    ----------
    library : the items it serves.
    host : the --host it listens on (the Host headers it answers, `server.guard`).
    port : the port it listens on (None: any port).
    presets : the presets folder (default: the user's, `presets.default_folder`).
    show : the show's state (default: no set list; the page can still drive /show).

    Returns
    -------
    Starlette app: the API routes, the built front end, the guard middleware.
    """
    static = static_folder()
    front_end = Mount("/", StaticFiles(directory=static, html=True)) if static else \
        Route("/", no_front_end)
    app = Starlette(routes=[*API_ROUTES, Route("/show", show_page), front_end],
                    middleware=[Middleware(Guard, host=host, port=port, scrub=library.public)],
                    exception_handlers={HTTPException: on_http_error, InputError: on_input_error,
                                        OSError: on_os_error})
    app.state.library = library
    app.state.uploads = asyncio.Semaphore(UPLOADS_AT_ONCE)
    app.state.presets = presets or PresetStore(default_folder())
    app.state.show = show or ShowState()
    app.state.static = static
    return app
