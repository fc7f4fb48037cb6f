"""The rig's surface in the page (docs/design.md#surface-of-a-rig): the skin's harmonics packed
as the page's positions pass reads them, and a gallery of surface dances on a song."""

from __future__ import annotations

import numpy as np
from starlette.requests import Request

from eigendance.music.gallery import initial_gallery
from eigendance.server.binary import pack, packed_harmonics
from eigendance.server.lookup import bundle_response, ready_rig
from eigendance.server.requests import answer
from eigendance.server.rig_routes import gallery_inputs
from eigendance.server.workers import in_worker


def surface_bundle(rig) -> bytes:
    """The skin's harmonics of a rig for the page (`Rig.surface`), all float32.

    Parameters
    ----------
    rig : the `Rig`.

    Returns
    -------
    bytes: meta {kind "rig-surface", n, k, groups}; arrays harmonics (n, 4·⌈k/4⌉) four per
    texel, on the rig's skin vertices (0 on one the clean-up dropped), coefficients (k, 3)
    X̃·scale in the rig's units, frequencies (k,).
    """
    skin = rig.surface()
    basis = skin.basis
    vectors = basis.harmonics(np.arange(basis.k))
    kept = skin.vertex_map >= 0
    harmonics = np.zeros((skin.n, basis.k))
    harmonics[kept] = vectors[skin.vertex_map[kept]]
    packed = packed_harmonics(harmonics)
    return pack({"kind": "rig-surface", "n": skin.n, "k": basis.k,
                 "groups": packed.shape[1] // 4},
                {"harmonics": packed, "coefficients": basis.coefficients * basis.scale,
                 "frequencies": basis.frequencies})


async def get_rig_surface(request: Request):
    """GET /api/rigs/{id}/surface.bin: the skin's harmonics (`surface_bundle`).

    Parameters
    ----------
    request : path parameter id.

    Returns
    -------
    Response, the bundle.
    """
    item = await ready_rig(request)
    rig = item.rig
    return bundle_response(await in_worker(surface_bundle, rig))


async def rig_surface_gallery(request: Request):
    """POST /api/rig-surface-gallery {rig, song, size}: the initial gallery of the skin's
    harmonics on the song (`music.gallery.initial_gallery`), each item a surface mapping.

    Parameters
    ----------
    request : the JSON body.

    Returns
    -------
    JSON response {"mappings": [size mapping documents]}.
    """
    item, song, size = await gallery_inputs(request)
    rig = item.rig

    def make():
        items = initial_gallery(rig.surface().basis, song.spectrogram, size)
        return {"mappings": [m.to_json() for m in items]}

    return await answer(make)
