"""The rig routes: a rig's description, bundle and skeleton, its edits (stiffness, pose, reset)
and its gallery of mode mappings (docs/web.md#rig-api).
"""

from __future__ import annotations

from starlette.exceptions import HTTPException
from starlette.requests import Request

from eigendance.checks import number, vector
from eigendance.modal.motion import default_mapping
from eigendance.modal.rig_gallery import rig_gallery
from eigendance.music.gallery import DEFAULT_GALLERY
from eigendance.server.binary import rig_meta
from eigendance.server.lookup import (
    bundle_response,
    item_of,
    library_of,
    ready_rig,
    rig_of,
    song_of,
)
from eigendance.server.requests import (
    answer,
    gallery_size,
    json_body,
)
from eigendance.server.workers import in_worker


async def get_rig(request: Request):
    """GET /api/rigs/{id}: the rig's description.

    Parameters
    ----------
    request : path parameter id.

    Returns
    -------
    JSON response: the item's state and the rig bundle's `meta` (`binary.rig_meta`).
    """
    item = await ready_rig(request)
    return await answer(lambda: {**item.as_json(), **rig_meta(item.rig, item.name,
                                                              item.revision, item.edited)})


async def get_rig_bundle(request: Request):
    """GET /api/rigs/{id}/rig.bin: the rig bundle (docs/web.md#rig-bundle).

    Parameters
    ----------
    request : path parameter id.

    Returns
    -------
    Response, the bundle of the current rig (edits included).
    """
    return bundle_response((await ready_rig(request)).bundle)


async def get_rig_look(request: Request):
    """GET /api/rigs/{id}/appearance.bin: the appearance bundle of the rig's skin.

    Parameters
    ----------
    request : path parameter id.

    Returns
    -------
    Response, the bundle (`binary.appearance_bundle`); 404 for a skin without materials.
    """
    item = await ready_rig(request)
    return bundle_response(await in_worker(library_of(request).look_bundle, item))


async def get_rig_skeleton(request: Request):
    """GET /api/rigs/{id}/skeleton.json: the current skeleton (the edits included).

    Parameters
    ----------
    request : path parameter id.

    Returns
    -------
    JSON response, a skeleton JSON document.
    """
    item = await ready_rig(request)
    return await answer(item.rig.skeleton.to_dict)


async def rig_stiffness(request: Request):
    """POST /api/rigs/{id}/stiffness {joints: {name: number | [per free row] | "auto"}, scale?}.

    Parameters
    ----------
    request : path parameter id, the JSON body.

    Returns
    -------
    Response, the new rig bundle (`Skeleton.with_stiffness`); 400 naming a bad value.
    """
    rig_of(request)
    body = await json_body(request)
    if not isinstance(body, dict) or not isinstance(body.get("joints", {}), dict):
        raise HTTPException(400, "expected a JSON object {joints: {joint name: stiffness}, "
                                 "scale}")
    scale = number(body.get("scale", 1.0), "scale", 0.0)
    item = await ready_rig(request)
    values = body.get("joints", {})
    bundle = await in_worker(library_of(request).edit_rig, item,
                                     lambda skeleton: skeleton.with_stiffness(values, scale))
    return bundle_response(bundle)


async def rig_pose(request: Request):
    """POST /api/rigs/{id}/pose {joint: name or index, rotation: [3 numbers, radians]}.

    Parameters
    ----------
    request : path parameter id, the JSON body.

    Returns
    -------
    Response, the new rig bundle (`Skeleton.rotate_joint`); 400 for a joint closing a loop.
    """
    rig_of(request)
    body = await json_body(request)
    if not isinstance(body, dict) or "joint" not in body or \
            not isinstance(body.get("rotation"), list):
        raise HTTPException(400, "expected a JSON object {joint, rotation: [x, y, z] radians}")
    joint, rotation = body["joint"], body["rotation"]
    if isinstance(joint, bool) or not isinstance(joint, str | int):
        raise HTTPException(400, "joint must be a joint name or index")
    rotation = vector(rotation, "rotation (a rotation vector, radians)").tolist()
    item = await ready_rig(request)
    bundle = await in_worker(library_of(request).edit_rig, item,
                                     lambda skeleton: skeleton.rotate_joint(joint, rotation))
    return bundle_response(bundle)


async def rig_reset(request: Request):
    """POST /api/rigs/{id}/reset: the rig as loaded again (pose and stiffness).

    Parameters
    ----------
    request : path parameter id.

    Returns
    -------
    Response, its bundle.
    """
    item = await ready_rig(request)
    return bundle_response(await in_worker(library_of(request).reset_rig, item))


async def gallery_inputs(request: Request):
    """The rig (analysed), the song and the size of a gallery request {rig, song, size}.

    Parameters
    ----------
    request : the JSON body.

    Returns
    -------
    (RigItem, SongItem, size); 400 for a body that is not an object, 404 for unknown ids.
    """
    body = await json_body(request)
    if not isinstance(body, dict):
        raise HTTPException(400, "expected a JSON object {rig, song, size}")
    item = item_of(request, "rig", body.get("rig"))
    song = song_of(request, str(body.get("song")))
    size = gallery_size(body.get("size", DEFAULT_GALLERY))
    await in_worker(library_of(request).ready_rig, item)
    return item, song, size


async def rig_gallery_route(request: Request):
    """POST /api/rig-gallery {rig, song, size}: the initial gallery of mode mappings.

    Parameters
    ----------
    request : the JSON body.

    Returns
    -------
    JSON response {"mappings": [size mapping documents], "default": the default mapping};
    409 for a rig without vibration modes.
    """
    item, song, size = await gallery_inputs(request)
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
