"""The show's routes (docs/design.md#show): the `ShowState` on ``app.state.show``.

GET /api/show/state (JSON: cue, preset, gain, playing, tempo, …), GET /api/show/events (the
state as server-sent events, one per change), POST /api/show/control {"action", "value"} (what
a key, a click or a MIDI control does; OSC comes in by `show.osc`), POST /api/show/clock
{"song", "time", "playing", "tempo"} (the output page's clock, which OSC out follows), and
GET /show, the output page (the web app in show mode).
"""

from __future__ import annotations

import asyncio
import json
import os
import time

from starlette.exceptions import HTTPException
from starlette.requests import Request
from starlette.responses import FileResponse, StreamingResponse

from eigendance.errors import InputError
from eigendance.files import finite_number
from eigendance.server.lookup import library_of
from eigendance.server.requests import json_answer, json_body
from eigendance.show.state import ShowState

EVENTS_EVERY = 0.01  # s between looks at the state's version


def show_of(request: Request) -> ShowState:
    """The app's show state.

    Parameters
    ----------
    request : any request.

    Returns
    -------
    ShowState.
    """
    return request.app.state.show


async def show_state(request: Request):
    """GET /api/show/state.

    Parameters
    ----------
    request : the request.

    Returns
    -------
    JSON `ShowState.snapshot`.
    """
    return json_answer(show_of(request).snapshot())


async def show_events(request: Request):
    """GET /api/show/events: the state as server-sent events, one per change, until the page
    leaves or the server stops.

    Parameters
    ----------
    request : the request.

    Returns
    -------
    StreamingResponse, text/event-stream.
    """
    state, stopping = show_of(request), library_of(request).stopping

    async def stream():
        version, idle = None, 0.0
        while not stopping.is_set():
            if state.version != version:
                snapshot = state.snapshot()
                version = snapshot["version"]
                yield f"data: {json.dumps(snapshot)}\n\n"
                idle = 0.0
            elif idle >= 15:
                yield ": still here\n\n"  # a comment: proxies keep the stream open
                idle = 0.0
            if await request.is_disconnected():
                return
            await asyncio.sleep(EVENTS_EVERY)
            idle += EVENTS_EVERY

    return StreamingResponse(stream(), media_type="text/event-stream",
                             headers={"Cache-Control": "no-cache"})


async def show_control(request: Request):
    """POST /api/show/control: one control action (`ShowState.act`).

    Parameters
    ----------
    request : JSON {"action", "value"?}.

    Returns
    -------
    JSON, the new state; 400 for an unknown action or a bad value.
    """
    data = await json_body(request)
    if not isinstance(data, dict) or not isinstance(data.get("action"), str):
        raise InputError("send {\"action\": …, \"value\": …}")
    return json_answer(show_of(request).act(data["action"], data.get("value")))


async def show_clock(request: Request):
    """POST /api/show/clock: the song time the output page draws now.

    Parameters
    ----------
    request : JSON {"song": id or null, "time": s, "playing": bool, "tempo": BPM or null,
        "wall": when the page drew it, ms since 1970 (same machine: the report's time on the
        way is taken off; a clock more than a second off is not believed), "live": a live
        input's new events (`show.live_out.LiveHeard.report`), optional}.

    Returns
    -------
    JSON {"ok": true}.
    """
    data = await json_body(request)
    if not isinstance(data, dict) or not finite_number(data.get("time")) or \
            isinstance(data.get("time"), bool) or not isinstance(data.get("playing"), bool):
        raise InputError("send {\"song\", \"time\": seconds, \"playing\": true or false}")
    song = data.get("song")
    if data.get("live") is not None:
        show_of(request).live.report(data["live"])
    tempo, wall = data.get("tempo"), data.get("wall")
    age = time.time() - wall / 1000 if finite_number(wall) and not isinstance(wall, bool) else 0
    show_of(request).heard(song if isinstance(song, str) else None, float(data["time"]),
                           data["playing"], tempo if finite_number(tempo) else None,
                           age if 0 <= age < 1 else 0.0)
    return json_answer({"ok": True})


async def show_page(request: Request):
    """GET /show: the output page (the web app, which starts in show mode on this path).

    Parameters
    ----------
    request : the request.

    Returns
    -------
    FileResponse of the built index.html; 503 when the front end was never built.
    """
    static = request.app.state.static
    if static is None:
        raise HTTPException(503, "the web app is not built: run make web")
    return FileResponse(os.path.join(static, "index.html"), media_type="text/html")
