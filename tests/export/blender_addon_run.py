"""The add-on driven in Blender (the `bpy` wheel), run by tests/export/test_blender_addon.py in
Blender's own Python (docs/design.md#blender-add-on).

    python blender_addon_run.py PLAN.json OUT.npz

PLAN: {"zip", "command", "song", "fps", "start", "duration", "k", "cat": {"obj", "mapping"},
"textured": {"obj", "item"}, "fox": {"glb"}, "samples"}. Installs the zip as an extension,
bakes the cat (made from the OBJ's numbers, vertex order kept), the textured model (Blender's
OBJ importer, materials) and the Fox (glTF importer), then tries a bad song and a missing
command; writes, per case, the evaluated positions at the sample frames and what the scene
holds.
"""

import json
import os
import sys
import time
import urllib.request

import bpy
import numpy as np

ADDON = "bl_ext.user_default.eigendance"


def read_obj(path):
    vertices, faces = [], []
    with open(path, encoding="utf-8") as file:
        for line in file:
            words = line.split()
            if words and words[0] == "v":
                vertices.append([float(w) for w in words[1:4]])
            elif words and words[0] == "f":
                faces.append([int(w.split("/")[0]) - 1 for w in words[1:]])
    return vertices, faces


def select(obj):
    for other in bpy.context.scene.objects:
        other.select_set(False)
    obj.select_set(True)
    bpy.context.view_layer.objects.active = obj


def evaluated(obj, frames, world=False):
    scene, found = bpy.context.scene, []
    for frame in frames:
        scene.frame_set(int(frame))
        moved = obj.evaluated_get(bpy.context.evaluated_depsgraph_get())
        mesh = moved.to_mesh()
        points = np.empty(3 * len(mesh.vertices))
        mesh.vertices.foreach_get("co", points)
        points = points.reshape(-1, 3)
        if world:
            matrix = np.array(moved.matrix_world)
            points = points @ matrix[:3, :3].T + matrix[:3, 3]
        moved.to_mesh_clear()
        found.append(points)
    return np.array(found)


def call(operator, **settings):
    """Run an operator as a script does: (result, the error's text or '')."""
    try:
        return sorted(operator(**settings)), ""
    except RuntimeError as error:
        return ["ERROR"], str(error)


def scene_facts(out, name):
    scene = bpy.context.scene
    editor = scene.sequence_editor
    strips = [] if editor is None else list(
        editor.strips_all if hasattr(editor, "strips_all") else editor.sequences_all)
    sound = [s for s in strips if s.type == "SOUND"]
    out[f"{name}_strip"] = np.array([bpy.path.abspath(sound[0].sound.filepath),
                                     sound[0].frame_final_start] if sound else [], dtype=str)
    out[f"{name}_timing"] = np.array([scene.frame_start, scene.frame_end, scene.render.fps])


def bake_mesh(plan, out, name, obj, **settings):
    select(obj)
    materials = [slot.material.name for slot in obj.material_slots if slot.material]
    rest = np.array([v.co[:] for v in obj.data.vertices])
    obj.data.calc_loop_triangles()
    out[f"{name}_triangles"] = np.array([t.vertices[:] for t in obj.data.loop_triangles])
    out[f"{name}_rest"] = rest
    bpy.ops.ed.undo_push(message="before the bake")
    result, error = call(bpy.ops.eigendance.dance_mesh, song=plan["song"], k=plan["k"],
                         fps=plan["fps"], start=plan["start"], duration=plan["duration"],
                         **settings)
    assert result == ["FINISHED"], error
    first = bpy.context.scene.frame_start
    out[f"{name}_frames"] = evaluated(obj, [first + i for i in plan["samples"]])
    out[f"{name}_materials"] = np.array([materials, [
        slot.material.name for slot in obj.material_slots if slot.material]], dtype=str)
    out[f"{name}_keys"] = len(obj.data.shape_keys.key_blocks)
    scene_facts(out, name)
    # Blender pushes an operator's undo step when a button runs it; background mode does not,
    # so push it as the UI would, then undo it.
    bpy.ops.ed.undo_push(message="eigendance bake")
    label = obj.name
    bpy.ops.ed.undo()
    out[f"{name}_undone"] = bpy.context.scene.objects[label].data.shape_keys is None
    return label


def gallery_round_trip(plan):
    """Open the gallery for the cat, save a mapping as the page does (POST /api/mappings),
    and return the mapping the scene's settings now name (the timer's polls, run here: a
    background Blender runs no timers)."""
    gallery = sys.modules[ADDON + ".gallery"]
    preferences = bpy.context.preferences.addons[ADDON].preferences
    preferences.command = plan["command"]
    select(bpy.context.scene.objects["cat"])
    result, error = call(bpy.ops.eigendance.gallery, song=plan["song"], k=20)
    assert result == ["FINISHED"], error
    for _ in range(300):
        gallery.poll()
        if gallery.SERVER["known"] is not None:
            break
        time.sleep(0.5)
    with open(plan["cat"]["mapping"], "rb") as file:
        saved = urllib.request.Request(gallery.SERVER["url"] + "/api/mappings?name=mine.json",
                                       data=file.read(), method="POST",
                                       headers={"Content-Type": "application/json"})
    urllib.request.urlopen(saved, timeout=30).close()
    gallery.poll()
    gallery.stop()
    return bpy.context.scene.eigendance.mapping


def main(plan_path, out_path):
    with open(plan_path, encoding="utf-8") as file:
        plan = json.load(file)
    out = {"version": bpy.app.version_string}
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.extensions.package_install_files(filepath=plan["zip"], repo="user_default",
                                             enable_on_install=True)
    bpy.ops.eigendance.dance_mesh.get_rna_type()  # registered, or this raises
    preferences = bpy.context.preferences.addons[ADDON].preferences
    preferences.command = plan["command"]

    vertices, faces = read_obj(plan["cat"]["obj"])
    mesh = bpy.data.meshes.new("cat")
    # A loose vertex too (in no face): mesh readers drop it, the bake keeps it at rest.
    mesh.from_pydata([*vertices, [0.0, 0.0, 2.0]], [], faces)
    cat = bpy.data.objects.new("cat", mesh)
    bpy.context.scene.collection.objects.link(cat)
    cat.location = (1.0, 2.0, 3.0)  # a transform of its own: kept, the dance is object space
    bake_mesh(plan, out, "cat", cat, mapping=plan["cat"]["mapping"])

    before = set(bpy.context.scene.objects)
    bpy.ops.wm.obj_import(filepath=plan["textured"]["obj"], forward_axis="Y", up_axis="Z")
    model = max(set(bpy.context.scene.objects) - before, key=lambda o: len(o.data.vertices))
    label = bake_mesh(plan, out, "textured", model, item=plan["textured"]["item"])

    # The same as a point cache beside the saved .blend, read by a Mesh Cache modifier; the
    # cat's loose vertex is refused there (a cache needs every vertex).
    bpy.ops.wm.save_as_mainfile(filepath=plan["blend"])
    model = bpy.context.scene.objects[label]
    select(model)
    result, error = call(bpy.ops.eigendance.dance_mesh, song=plan["song"], k=plan["k"],
                         fps=plan["fps"], start=plan["start"], duration=plan["duration"],
                         item=plan["textured"]["item"], form="MESH_CACHE")
    assert result == ["FINISHED"], error
    out["cache_modifiers"] = np.array([m.type for m in model.modifiers])
    out["cache_frames"] = evaluated(model, [bpy.context.scene.frame_start + i
                                            for i in plan["samples"]])
    select(bpy.context.scene.objects["cat"])
    out["cat_cache"] = call(bpy.ops.eigendance.dance_mesh, song=plan["song"], k=20,
                            form="MESH_CACHE")[1]

    bpy.ops.import_scene.gltf(filepath=plan["fox"]["glb"])
    armature = next(o for o in bpy.context.scene.objects if o.type == "ARMATURE")
    skinned = next(o for o in bpy.context.scene.objects
                   if o.type == "MESH" and o.find_armature() == armature)
    armature.data.pose_position = "REST"  # the importer plays the glb's own first animation
    out["fox_rest"] = evaluated(skinned, [bpy.context.scene.frame_start], world=True)[0]
    armature.data.pose_position = "POSE"
    select(armature)
    result, error = call(bpy.ops.eigendance.dance_rig, song=plan["song"], fps=plan["fps"],
                         start=plan["start"], duration=plan["duration"],
                         rig_file=plan["fox"]["glb"])
    assert result == ["FINISHED"], error
    first = bpy.context.scene.frame_start
    out["fox_frames"] = evaluated(skinned, [first + i for i in plan["samples"]], world=True)
    scene_facts(out, "fox")

    select(bpy.context.scene.objects["cat"])
    out["bad_song"] = call(bpy.ops.eigendance.dance_mesh, song=plan["cat"]["mapping"], k=20)[1]
    preferences.command = "eigendance-not-installed-here"
    out["no_command"] = call(bpy.ops.eigendance.dance_mesh, song=plan["song"], k=20)[1]
    out["gallery_mapping"] = gallery_round_trip(plan)
    np.savez(out_path, **out)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
    sys.stdout.flush()
    os._exit(0)  # bpy 4.2 crashes while the interpreter shuts down (the results are written)
