"""The web gallery from Blender: `eigendance.gallery` serves the selected mesh and the song
(`eigendance serve` on a free local port) and opens the page; every mapping the page *saves*
comes back (the add-on polls the server's library, GET /api/library and
GET /api/mappings/{id}) as a file, set as the mapping to bake. `eigendance.gallery_stop` (or
Blender's exit) ends the server.
"""

import json
import os
import socket
import tempfile
import urllib.error
import urllib.request
import webbrowser

import bpy

from . import meshes, operators, props, runner

SERVER = {"job": None, "url": None, "known": None, "folder": None, "scene": None}
POLL_SECONDS = 1.0


def free_port() -> int:
    """A free TCP port on this machine.

    Returns
    -------
    int.
    """
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


def ask(path: str):
    """GET a JSON answer from the gallery's server.

    Parameters
    ----------
    path : the route, e.g. /api/library.

    Returns
    -------
    the decoded JSON.
    """
    with urllib.request.urlopen(SERVER["url"] + path, timeout=2) as answer:
        return json.loads(answer.read(4 << 20))


def mapping_folder() -> str:
    """Where mappings saved in the page go: eigendance/ beside the saved .blend, else a folder
    of the system's temporary files.

    Returns
    -------
    str.
    """
    if bpy.data.filepath:
        folder = os.path.join(os.path.dirname(bpy.data.filepath), "eigendance")
    else:
        folder = os.path.join(tempfile.gettempdir(), "eigendance-mappings")
    os.makedirs(folder, exist_ok=True)
    return folder


def keep(mapping: dict, name: str) -> str:
    """Write a saved mapping as a new file (never over another).

    Parameters
    ----------
    mapping : the mapping document.
    name : its name in the page.

    Returns
    -------
    str, the file.
    """
    stem = bpy.path.clean_name(os.path.splitext(name)[0]) or "mapping"
    folder, number = mapping_folder(), 0
    path = os.path.join(folder, f"{stem}.json")
    while os.path.exists(path):
        number += 1
        path = os.path.join(folder, f"{stem}-{number}.json")
    with open(path, "x", encoding="utf-8") as file:
        json.dump(mapping, file)
    return path


def poll():
    """The timer: open the page once the server answers, then fetch each newly saved mapping.

    Returns
    -------
    float, seconds to the next poll, or None to stop.
    """
    job = SERVER["job"]
    if job is None or job.poll() is not None:
        if job is not None:
            print(f"eigendance gallery: {job.error()}")
        stop()
        return None
    try:
        library = ask("/api/library")
    except (OSError, urllib.error.URLError, ValueError):
        return POLL_SECONDS  # still starting
    ids = {item["id"]: item.get("name", "mapping") for item in library.get("mappings", [])}
    if SERVER["known"] is None:
        SERVER["known"] = set(ids)
        webbrowser.open(SERVER["url"] + "/")
        return POLL_SECONDS
    for identifier in sorted(set(ids) - SERVER["known"]):
        SERVER["known"].add(identifier)
        try:
            path = keep(ask(f"/api/mappings/{identifier}"), ids[identifier])
        except (OSError, urllib.error.URLError, ValueError) as error:
            print(f"eigendance gallery: the saved mapping could not be fetched ({error})")
            continue
        scene = bpy.data.scenes.get(SERVER["scene"] or "")
        if scene is not None:
            scene.eigendance.mapping = path
        print(f"eigendance gallery: mapping saved to {path}; ready to bake")
    return POLL_SECONDS


def stop() -> None:
    """End the gallery's server and forget it."""
    if SERVER["job"] is not None:
        SERVER["job"].kill()
    if bpy.app.timers.is_registered(poll):
        bpy.app.timers.unregister(poll)
    if SERVER["folder"]:
        for name in os.listdir(SERVER["folder"]):
            os.remove(os.path.join(SERVER["folder"], name))
        os.rmdir(SERVER["folder"])
    SERVER.update(job=None, url=None, known=None, folder=None, scene=None)


class EIGENDANCE_OT_gallery(bpy.types.Operator):
    """Open the web gallery for the selected mesh and the song; a mapping saved there comes
    back as the mapping to bake"""

    bl_idname = "eigendance.gallery"
    bl_label = "Open the gallery"

    song: props.SONG
    k: props.K

    def execute(self, context):
        obj = context.active_object
        try:
            if obj is None or obj.type != "MESH":
                raise operators.Refused("eigendance: select a mesh object for the gallery")
            words = operators.command(context)
            song = operators.song_path(self.song)
        except operators.Refused as error:
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        stop()
        folder = tempfile.mkdtemp(prefix="eigendance-gallery-")
        source = os.path.join(folder, f"{bpy.path.clean_name(obj.name) or 'mesh'}.obj")
        meshes.write_obj(obj, source)
        port = free_port()
        try:
            job = runner.Job([*words, "serve", source, song, "-k", str(self.k),
                              "--port", str(port)])
        except runner.CommandMissing as error:
            os.remove(source)
            os.rmdir(folder)
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        SERVER.update(job=job, url=f"http://127.0.0.1:{port}", known=None, folder=folder,
                      scene=context.scene.name)
        bpy.app.timers.register(poll, first_interval=POLL_SECONDS)
        self.report({"INFO"}, f"eigendance: the gallery opens at {SERVER['url']}; save a "
                              "mapping there to bake it here")
        return {"FINISHED"}


class EIGENDANCE_OT_gallery_stop(bpy.types.Operator):
    """Stop the gallery's server"""

    bl_idname = "eigendance.gallery_stop"
    bl_label = "Stop the gallery"

    def execute(self, context):
        stop()
        return {"FINISHED"}


CLASSES = (EIGENDANCE_OT_gallery, EIGENDANCE_OT_gallery_stop)
