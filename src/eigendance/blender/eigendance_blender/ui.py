"""The add-on's preferences (the command), the scene's dance settings and the sidebar panel
(View3D > Sidebar > eigendance)."""

import bpy
from bpy.props import PointerProperty, StringProperty

from . import gallery, meshes, props, runner


class EigendancePreferences(bpy.types.AddonPreferences):
    """Where the eigendance command is."""

    bl_idname = __package__

    command: StringProperty(
        name="eigendance command", default="eigendance",
        description="The eigendance command: its name on PATH, its path, or a command line "
                    "such as '/path/to/python -m eigendance' (install it with "
                    "`pip install eigendance`)")

    def draw(self, context):
        self.layout.prop(self, "command")
        try:
            words = runner.command_words(self.command)
            self.layout.label(text=f"Found: {words[0]}", icon="CHECKMARK")
        except runner.CommandMissing as error:
            self.layout.label(text=str(error), icon="ERROR")


class EigendanceSettings(bpy.types.PropertyGroup):
    """The panel's settings, kept with the scene (the operators take them as parameters)."""

    song: props.SONG
    mapping: props.MAPPING
    item: props.ITEM
    k: props.K
    fps: props.FPS
    start: props.START
    duration: props.DURATION
    rig_file: props.RIG_FILE
    modes: props.MODES
    amplitude: props.AMPLITUDE
    time_scale: props.TIME_SCALE
    on_beat: props.ON_BEAT
    options: props.OPTIONS


SHARED = ("song", "fps", "start", "duration")


class EIGENDANCE_PT_panel(bpy.types.Panel):
    """The sidebar panel: song, settings, bake, gallery."""

    bl_label = "eigendance"
    bl_idname = "EIGENDANCE_PT_panel"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "eigendance"

    def draw(self, context):
        layout, settings = self.layout, context.scene.eigendance
        obj = context.active_object
        for name in SHARED:
            layout.prop(settings, name)
        if runner.RUNNING:
            layout.operator("eigendance.cancel", icon="CANCEL")
        if obj is not None and obj.type == "MESH" and obj.find_armature() is None:
            self.draw_mesh(layout, settings, obj)
        elif obj is not None and obj.type in ("ARMATURE", "MESH"):
            self.draw_rig(layout, settings)
        else:
            layout.label(text="Select a mesh or an armature", icon="INFO")

    def draw_mesh(self, layout, settings, obj):
        for name in ("mapping", "item", "k"):
            layout.prop(settings, name)
        if len(obj.data.vertices) > meshes.SHAPE_KEY_VERTICES:
            layout.label(text="A large mesh: bakes to a Mesh Cache beside the .blend")
        op = layout.operator("eigendance.dance_mesh", icon="PLAY_SOUND")
        for name in (*SHARED, "mapping", "item", "k"):
            setattr(op, name, getattr(settings, name))
        if gallery.SERVER["job"] is None:
            page = layout.operator("eigendance.gallery", icon="WORLD")
            page.song, page.k = settings.song, settings.k
        else:
            layout.label(text=f"Gallery: {gallery.SERVER['url']}", icon="WORLD")
            layout.operator("eigendance.gallery_stop", icon="CANCEL")

    def draw_rig(self, layout, settings):
        for name in ("rig_file", "modes", "amplitude", "time_scale", "on_beat", "options"):
            layout.prop(settings, name)
        op = layout.operator("eigendance.dance_rig", icon="ARMATURE_DATA")
        for name in (*SHARED, "rig_file", "modes", "amplitude", "time_scale", "on_beat", "options"):
            setattr(op, name, getattr(settings, name))


CLASSES = (EigendancePreferences, EigendanceSettings, EIGENDANCE_PT_panel)


def register_settings() -> None:
    """Give every scene its dance settings."""
    bpy.types.Scene.eigendance = PointerProperty(type=EigendanceSettings)


def unregister_settings() -> None:
    """Take the settings back."""
    del bpy.types.Scene.eigendance
