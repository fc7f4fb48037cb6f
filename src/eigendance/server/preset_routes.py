"""The presets' routes (docs/design.md#presets): the `PresetStore` on ``app.state.presets``.

GET /api/presets (?q= words of a name or tag, ?favourites=1), POST /api/presets (a preset
document: save, or import an exported file; 409 when the name is taken unless "replace" is
true), GET/PATCH/DELETE /api/presets/{name} (PATCH: {"name", "tags", "favourite"}: rename,
retag, mark), GET /api/presets/{name}/thumbnail.png and /file (the one-file export).
"""

from __future__ import annotations

from urllib.parse import quote

from starlette.exceptions import HTTPException
from starlette.requests import Request
from starlette.responses import Response

from eigendance.errors import InputError
from eigendance.presets.resample import fit_mapping
from eigendance.presets.store import Preset, PresetStore, check_name, check_tags
from eigendance.server.lookup import item_of
from eigendance.server.requests import answer, json_answer, json_body


def store_of(request: Request) -> PresetStore:
    """The app's presets.

    Parameters
    ----------
    request : any request.

    Returns
    -------
    PresetStore.
    """
    return request.app.state.presets


def _name(request: Request) -> str:
    return check_name(request.path_params["name"])


async def list_presets(request: Request):
    """GET /api/presets: summaries of the presets, sorted by name.

    Parameters
    ----------
    request : ?q= filters by name or tag, ?favourites=1 keeps the favourites.

    Returns
    -------
    JSON list of {name, tags, favourite, kind, thumbnail}.
    """
    search = request.query_params.get("q", "")[:200]
    favourites = request.query_params.get("favourites") in ("1", "true")
    return await answer(lambda: store_of(request).listing(search, favourites))


async def save_preset(request: Request):
    """POST /api/presets: save a preset (or import an exported preset file).

    Parameters
    ----------
    request : JSON {"name", "mapping" or "palette", "tags", "favourite", "thumbnail" (base64
        PNG), "mesh" (a library mesh id: its basis's eigenvalues are kept, to fit the preset to
        other meshes by frequency), "replace" (true: overwrite a preset of that name)}.

    Returns
    -------
    201 JSON, the preset's summary; 409 when the name is taken.
    """
    data = await json_body(request)
    if not isinstance(data, dict):
        raise InputError("a preset must be a JSON object")
    mesh_id = data.get("mesh")
    if mesh_id is not None:
        item = item_of(request, "mesh", mesh_id)
        if item.basis is not None:
            data = {**data, "eigenvalues": [float(v) for v in item.basis.eigenvalues]}
    replace = data.get("replace", False) is True

    def save():
        preset = Preset.from_json(data, "preset")
        store_of(request).save(preset, replace=replace)
        return preset.summary()

    return await answer(save, status=201)


async def get_preset(request: Request):
    """GET /api/presets/{name}: the preset document, its mapping fitted to a model.

    Parameters
    ----------
    request : ?mesh=ID fits the mapping to that mesh's harmonics by frequency (when both
        eigenvalues are known), ?rig=ID the palette to that rig's modes by rank.

    Returns
    -------
    JSON preset (thumbnail: a bool), 404 when there is none.
    """
    name = _name(request)
    mesh_id, rig_id = request.query_params.get("mesh"), request.query_params.get("rig")
    target = mode_count = None
    if mesh_id is not None:
        basis = item_of(request, "mesh", mesh_id).basis
        target = None if basis is None else basis.eigenvalues
    if rig_id is not None:
        rig = item_of(request, "rig", rig_id).rig
        mode_count = None if rig is None else mode_count_of(rig)

    def fitted():
        preset = store_of(request).load(name)
        preset.mapping = fit_mapping(preset.mapping, preset.eigenvalues, target, mode_count)
        return preset.to_json()

    return await answer(fitted)


def mode_count_of(rig) -> int | None:
    """How many vibration modes an analysed rig has.

    Parameters
    ----------
    rig : the rig item's `Rig`.

    Returns
    -------
    int.
    """
    return int(rig.model.n_modes)


async def change_preset(request: Request):
    """PATCH /api/presets/{name}: rename it, set its tags or its favourite mark.

    Parameters
    ----------
    request : JSON {"name"?, "tags"?, "favourite"?}.

    Returns
    -------
    JSON, the preset's summary (409 when the new name is taken).
    """
    name = _name(request)
    data = await json_body(request)
    if not isinstance(data, dict):
        raise InputError("send a JSON object")
    favourite = data.get("favourite")
    if favourite is not None and not isinstance(favourite, bool):
        raise InputError("favourite must be true or false")
    tags = None if "tags" not in data else check_tags(data["tags"])

    def change():
        store = store_of(request)
        preset = store.rename(name, data["name"]) if "name" in data else store.load(name)
        if favourite is not None:
            preset.favourite = favourite
        if tags is not None:
            preset.tags = tags
        store.save(preset)
        return preset.summary()

    return await answer(change)


async def delete_preset(request: Request):
    """DELETE /api/presets/{name}.

    Parameters
    ----------
    request : the request.

    Returns
    -------
    JSON {"deleted": name}; 404 when there is none.
    """
    name = _name(request)
    store_of(request).delete(name)
    return json_answer({"deleted": name})


async def preset_thumbnail(request: Request):
    """GET /api/presets/{name}/thumbnail.png.

    Parameters
    ----------
    request : the request.

    Returns
    -------
    image/png; 404 when the preset has none.
    """
    preset = store_of(request).load(_name(request))
    if preset.thumbnail is None:
        raise HTTPException(404, f"preset '{preset.name}' has no thumbnail")
    return Response(preset.thumbnail, media_type="image/png")


async def export_preset(request: Request):
    """GET /api/presets/{name}/file: the preset as one file to share (thumbnail inline).

    Parameters
    ----------
    request : the request.

    Returns
    -------
    application/json as an attachment named NAME.preset.json.
    """
    preset = store_of(request).load(_name(request))
    response = json_answer(preset.to_json(inline_thumbnail=True))
    response.headers["content-disposition"] = \
        f"attachment; filename*=UTF-8''{quote(preset.name)}.preset.json"
    return response
