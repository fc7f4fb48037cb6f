"""The audio/mapping functions the web server needs, from their owning modules when present.

`eigendance.audio`, `eigendance.demo_music`, `eigendance.mapping` and `eigendance.animate` are
built on another branch; until they are merged, `eigendance.server.standin` supplies the same
names (DESIGN §3–§4). `USING_STANDIN` says which is in use.
"""

from __future__ import annotations

try:  # pragma: no cover - depends on which branches are merged
    from eigendance.animate import positions_at
    from eigendance.audio import Spectrogram
    from eigendance.mapping import Mapping, breed, initial_gallery

    USING_STANDIN = False
except ImportError:  # pragma: no cover
    from eigendance.server.standin import (
        Mapping,
        Spectrogram,
        breed,
        initial_gallery,
        positions_at,
    )

    USING_STANDIN = True


def demo_track():
    """(samples, sample_rate) of the built-in procedural music."""
    try:
        from eigendance import demo_music
    except ImportError:
        from eigendance.server.standin import demo_music as track

        return track()
    for name in ("generate", "demo_music", "render", "track", "samples"):
        function = getattr(demo_music, name, None)
        if callable(function):
            return function()
    raise ImportError("eigendance.demo_music has no generator function")


def write_wav(path, samples, sample_rate):
    from eigendance.server.standin import write_wav as write

    write(path, samples, sample_rate)


def mapping_to_json(mapping) -> dict:
    for name in ("to_json", "to_dict", "as_json"):
        function = getattr(mapping, name, None)
        if callable(function):
            data = function()
            if isinstance(data, str):
                import json

                data = json.loads(data)
            return data
    return {"format": "eigendance.mapping", "version": 1, "bands": len(mapping.transfer),
            "transfer": list(map(float, mapping.transfer)),
            "amplification": list(map(float, mapping.amplification)),
            "seed": getattr(mapping, "seed", None)}


def mapping_from_json(data):
    for name in ("from_json", "from_dict"):
        function = getattr(Mapping, name, None)
        if callable(function):
            return function(data)
    raise ImportError("Mapping has no from_json")


__all__ = ["Mapping", "Spectrogram", "USING_STANDIN", "breed", "demo_track", "initial_gallery",
           "mapping_from_json", "mapping_to_json", "positions_at", "write_wav"]
