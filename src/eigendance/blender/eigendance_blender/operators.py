"""The add-on's operators: `eigendance.dance_mesh`, `eigendance.dance_rig` and
`eigendance.cancel`.

Each runs the eigendance command in a subprocess. Invoked (a button), it runs in the
background: a timer polls the job, the status bar shows its progress, Esc or Cancel kills it.
Executed (a script, background mode), it waits for the job and bakes before it returns. A bake
is one undo step; every failure is one line in Blender's report.
"""

import os
import shutil
import tempfile

import bpy
import numpy as np
from bpy.props import EnumProperty

from . import keys, meshes, props, rigs, runner

STOP = {"requested": False}  # the Cancel button's request, read by the running operator


class Refused(Exception):
    """A bake that cannot start or end: its message is the report's one line."""


def preferences(context):
    """The add-on's preferences (the command).

    Parameters
    ----------
    context : Blender's context.

    Returns
    -------
    the preferences, or None when the add-on is not registered under its package.
    """
    addon = context.preferences.addons.get(__package__)
    return addon.preferences if addon else None


def command(context) -> list[str]:
    """The eigendance command line, from the preferences (default: `eigendance` on PATH).

    Parameters
    ----------
    context : Blender's context.

    Returns
    -------
    list of str.
    """
    settings = preferences(context)
    try:
        return runner.command_words(settings.command if settings else "eigendance")
    except runner.CommandMissing as error:
        raise Refused(str(error)) from None


def song_path(song: str) -> str:
    """The song's absolute path (Blender's // paths resolved), refused when it is no file.

    Parameters
    ----------
    song : as given.

    Returns
    -------
    str.
    """
    path = os.path.abspath(bpy.path.abspath(song)) if song else ""
    if not os.path.isfile(path):
        raise Refused(f"song: no such file: {song or '(none chosen)'}")
    return path


def window_words(op) -> list[str]:
    """--fps, --start (a whole number of frames) and --duration of an operator's settings.

    Parameters
    ----------
    op : the operator.

    Returns
    -------
    list of str.
    """
    start = round(op.start * op.fps) / op.fps
    words = ["--fps", str(op.fps), "--start", repr(start)]
    return words + (["--duration", repr(op.duration)] if op.duration > 0 else [])


class Bake:
    """What both dance operators share: the job, its folder, background or not."""

    bl_options = {"REGISTER", "UNDO"}

    song: props.SONG
    fps: props.FPS
    start: props.START
    duration: props.DURATION

    def execute(self, context):
        try:
            self.begin(context)
        except Refused as error:
            return self.fail(context, str(error))
        self.job.wait()
        return self.end(context)

    def invoke(self, context, event):
        if context.window is None:  # no window to run in (background mode): bake now
            return self.execute(context)
        try:
            self.begin(context)
        except Refused as error:
            return self.fail(context, str(error))
        STOP["requested"] = False
        manager = context.window_manager
        self.timer = manager.event_timer_add(0.25, window=context.window)
        manager.modal_handler_add(self)
        manager.progress_begin(0.0, 1.0)
        return {"RUNNING_MODAL"}

    def modal(self, context, event):
        if event.type == "ESC" or STOP["requested"]:
            self.job.kill()
            return self.fail(context, "eigendance: cancelled", "WARNING")
        if event.type != "TIMER":
            return {"PASS_THROUGH"}
        if self.job.poll() is None:
            text, fraction = self.job.status()
            if context.workspace is not None:
                context.workspace.status_text_set(text)
            if fraction is not None:
                context.window_manager.progress_update(fraction)
            return {"PASS_THROUGH"}
        return self.end(context)

    def begin(self, context) -> None:
        self.job = self.timer = None
        self.folder = tempfile.mkdtemp(prefix="eigendance-")
        try:
            self.start_job(context)
        except BaseException:
            self.cleanup(context)
            raise

    def end(self, context):
        if self.job.poll() != 0:
            return self.fail(context, self.job.error())
        try:
            message = self.bake(context)
        except Refused as error:
            return self.fail(context, str(error))
        except (OSError, ValueError, KeyError) as error:  # an output we cannot read
            return self.fail(context, f"eigendance: the dance could not be read ({error})")
        self.cleanup(context)
        self.report({"INFO"}, message)
        return {"FINISHED"}

    def fail(self, context, message: str, level: str = "ERROR"):
        self.cleanup(context)
        self.report({level}, message)
        return {"CANCELLED"}

    def cleanup(self, context) -> None:
        job = getattr(self, "job", None)
        if job is not None:
            job.kill()
        if getattr(self, "timer", None) is not None:
            context.window_manager.event_timer_remove(self.timer)
            context.window_manager.progress_end()
            if context.workspace is not None:
                context.workspace.status_text_set(None)
            self.timer = None
        folder = getattr(self, "folder", None)
        if folder:
            shutil.rmtree(folder, ignore_errors=True)
            self.folder = None

    def run(self, words: list[str]) -> None:
        try:
            self.job = runner.Job(words)
        except runner.CommandMissing as error:
            raise Refused(str(error)) from None

    def finish_scene(self, context, count: int, song: str) -> str:
        first, last = keys.set_timing(context.scene, self.fps, count)
        strip = keys.add_song(context.scene, song, round(self.start * self.fps) / self.fps,
                              self.fps)
        said = "" if strip is not None else "; Blender cannot play the song, no sound strip"
        return f"frames {first}–{last} at {self.fps} fps{said}"


FORMS = [("AUTO", "Automatic", "Shape keys up to "
          f"{meshes.SHAPE_KEY_VERTICES:,} vertices, a Mesh Cache beyond"),
         ("SHAPE_KEYS", "Shape keys", "A shape key per driven harmonic, keyframed (kept in the "
                                      ".blend)"),
         ("MESH_CACHE", "Mesh Cache", "A point cache (.pc2) beside the saved .blend, read by a "
                                      "Mesh Cache modifier")]


class EIGENDANCE_OT_dance_mesh(Bake, bpy.types.Operator):
    """Bake the selected mesh's dance to the song onto the mesh itself (shape keys or a Mesh
    Cache), with the song as a sound strip"""

    bl_idname = "eigendance.dance_mesh"
    bl_label = "Dance (mesh)"

    mapping: props.MAPPING
    item: props.ITEM
    k: props.K
    form: EnumProperty(name="Form", items=FORMS, default="AUTO",
                       description="How the dance is kept")

    def start_job(self, context) -> None:
        obj = context.active_object
        if obj is None or obj.type != "MESH":
            raise Refused("eigendance: select a mesh object to make it dance")
        words = command(context)
        song = song_path(self.song)
        self.object_name, self.song_file = obj.name, song
        n = len(obj.data.vertices)
        cache = self.form == "MESH_CACHE" or (self.form == "AUTO" and
                                              n > meshes.SHAPE_KEY_VERTICES)
        if cache and not bpy.data.filepath:
            raise Refused(f"{obj.name}: {n} vertices bake to a point cache beside the .blend; "
                          "save the .blend first")
        if len(obj.data.polygons) == 0:
            raise Refused(f"{obj.name}: the mesh has no faces to dance with")
        source = os.path.join(self.folder, "mesh.obj")
        self.used = meshes.write_obj(obj, source)
        if cache and len(self.used) < n:
            raise Refused(f"{obj.name}: {n - len(self.used)} vertices are in no face; a Mesh "
                          "Cache needs them all (delete them, or bake shape keys)")
        self.output = os.path.join(self.folder, "dance.npz")
        if cache:
            folder = os.path.join(os.path.dirname(bpy.data.filepath), "eigendance")
            os.makedirs(folder, exist_ok=True)
            self.output = os.path.join(folder, f"{bpy.path.clean_name(obj.name)}.pc2")
        which = ["--mapping", os.path.abspath(bpy.path.abspath(self.mapping))] \
            if self.mapping else (["--item", str(self.item)] if self.item else [])
        self.run([*words, "bake", source, song, "-k", str(self.k), *which,
                  *window_words(self), "-o", self.output, *(["--force"] if cache else [])])

    def bake(self, context) -> str:
        obj = bpy.data.objects.get(self.object_name)
        if obj is None or obj.type != "MESH":
            raise Refused(f"{self.object_name}: the object is gone; nothing baked")
        name = f"eigendance {os.path.basename(self.song_file)}"
        if self.output.endswith(".pc2"):
            count = (os.path.getsize(self.output) - 32) // (12 * len(obj.data.vertices))
            meshes.add_mesh_cache(obj, bpy.path.relpath(self.output), context.scene.frame_start)
            what = f"a Mesh Cache ({os.path.basename(self.output)})"
        else:
            with np.load(self.output) as file:
                baked = {key: file[key] for key in file.files}
            problem = meshes.check_rest(obj, baked["rest"], self.used)
            if problem:
                raise Refused(problem)
            count = len(baked["times"])
            keys_added = meshes.add_shape_keys(obj, baked, self.used, context.scene.frame_start,
                                               name)
            what = f"{keys_added} shape keys"
        return f"eigendance: {obj.name} dances as {what}, " + \
            self.finish_scene(context, int(count), self.song_file)


class EIGENDANCE_OT_dance_rig(Bake, bpy.types.Operator):
    """Bake the selected armature's dance to the song as an Action on its bones (the skinned
    meshes follow), with the song as a sound strip"""

    bl_idname = "eigendance.dance_rig"
    bl_label = "Dance (rig)"

    rig_file: props.RIG_FILE
    modes: props.MODES
    amplitude: props.AMPLITUDE
    time_scale: props.TIME_SCALE
    on_beat: props.ON_BEAT
    options: props.OPTIONS

    def start_job(self, context) -> None:
        armature = context.active_object
        if armature is not None and armature.type == "MESH":
            armature = armature.find_armature()
        if armature is None or armature.type != "ARMATURE":
            raise Refused("eigendance: select an armature (or a mesh it deforms)")
        words = command(context)
        song = song_path(self.song)
        rig = self.rig_file or armature.get("eigendance_rig", "")
        rig = os.path.abspath(bpy.path.abspath(rig)) if rig else ""
        if not os.path.isfile(rig):
            raise Refused(f"{armature.name}: choose the rig file (the .glb the armature was "
                          "imported from)")
        self.object_name, self.song_file, self.rig_path = armature.name, song, rig
        palette = (["--modes", self.modes] if self.modes else []) + \
            (["--amplitude", repr(self.amplitude)] if self.amplitude else []) + \
            (["--time-scale", repr(self.time_scale)] if self.time_scale else []) + \
            ["--tempo", "beat" if self.on_beat else "free"]
        self.output = os.path.join(self.folder, "rig.npz")
        extra = self.options.split()
        self.run([*words, "animate-rig", rig, song, "--skinning", "lbs", *palette, *extra,
                  *window_words(self), "-o", self.output])

    def bake(self, context) -> str:
        armature = bpy.data.objects.get(self.object_name)
        if armature is None or armature.type != "ARMATURE":
            raise Refused(f"{self.object_name}: the armature is gone; nothing baked")
        with np.load(self.output) as file:
            names, transforms = file["body_names"], file["body_transforms"]
            rest = file["rest_vertices"]
        found = [str(name) for name in names if str(name) in armature.data.bones]
        skinned = rigs.skinned_positions(armature)
        if not found or len(skinned) == 0:
            raise Refused(f"{armature.name}: its bones or skinned meshes are not those of "
                          f"{os.path.basename(self.rig_path)}; import that file")
        space, error = rigs.fit_space(rest, skinned)
        if error > 1e-3:
            raise Refused(f"{armature.name}: its skinned meshes are not "
                          f"{os.path.basename(self.rig_path)}'s at rest; import that file")
        armature["eigendance_rig"] = self.rig_path
        rigs.clear_pose(armature)
        bases = rigs.pose_bases(armature, names, transforms, space)
        rigs.key_bones(armature, bases, context.scene.frame_start,
                       f"eigendance {os.path.basename(self.song_file)}")
        return f"eigendance: {armature.name} dances with {len(bases)} bones, " + \
            self.finish_scene(context, len(transforms), self.song_file)


class EIGENDANCE_OT_cancel(bpy.types.Operator):
    """Stop the bake that is running (Esc does too)"""

    bl_idname = "eigendance.cancel"
    bl_label = "Cancel"

    def execute(self, context):
        STOP["requested"] = True
        runner.kill_all()
        return {"FINISHED"}


CLASSES = (EIGENDANCE_OT_dance_mesh, EIGENDANCE_OT_dance_rig, EIGENDANCE_OT_cancel)
