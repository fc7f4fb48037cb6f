"""eigendance for Blender: bake a mesh's dance (shape keys, or a Mesh Cache) or a rig's dance (an
Action on its bones) to a song, with the song as a sound strip (docs/design.md#blender-add-on).

The add-on runs the eigendance command (a preference: `eigendance` on PATH by default) in a
subprocess and reads back what it writes: Blender has numpy but not scipy. Written by
`eigendance blender-addon -o eigendance_blender.zip`; install the zip from disk.
"""

import bpy

from . import gallery, operators, runner, ui

CLASSES = (*ui.CLASSES, *operators.CLASSES, *gallery.CLASSES)


def register():
    """Register the add-on's classes and the scene's settings."""
    for cls in CLASSES:
        bpy.utils.register_class(cls)
    ui.register_settings()


def unregister():
    """End every running job, then unregister."""
    runner.kill_all()
    gallery.stop()
    ui.unregister_settings()
    for cls in reversed(CLASSES):
        bpy.utils.unregister_class(cls)
