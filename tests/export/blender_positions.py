"""Evaluated vertex positions of an exported dance in Blender (the `bpy` wheel), run by
tests/export/test_blender.py in Blender's own Python (docs/design.md#exports).

    python blender_positions.py KIND FILE FPS OUT.npz FRAME…

KIND: glb (glTF importer: shape keys or an armature), pc2 (FILE's .obj beside it imported
without axis conversion, plus a Mesh Cache modifier reading FILE) or usd (USD importer). Writes
`frames` (F, n, 3), the evaluated mesh at each frame in Blender's world coordinates (Z up), and
Blender's `version`.
"""

import os
import sys

import bpy
import numpy as np


def evaluated(obj, depsgraph) -> np.ndarray:
    """World positions of the evaluated (modifiers, shape keys, armature) mesh."""
    moved = obj.evaluated_get(depsgraph)
    mesh = moved.to_mesh()
    positions = np.empty(len(mesh.vertices) * 3)
    mesh.vertices.foreach_get("co", positions)
    matrix = np.array(moved.matrix_world)
    moved.to_mesh_clear()
    positions = positions.reshape(-1, 3)
    return positions @ matrix[:3, :3].T + matrix[:3, 3]


def main(kind: str, path: str, fps: float, out: str, frames: list[int]) -> None:
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.fps, scene.render.fps_base = round(fps), round(fps) / fps
    if kind == "glb":
        bpy.ops.import_scene.gltf(filepath=path)
    elif kind == "pc2":
        bpy.ops.wm.obj_import(filepath=os.path.splitext(path)[0] + ".obj", forward_axis="Y",
                              up_axis="Z")
        obj = next(o for o in scene.objects if o.type == "MESH")
        cache = obj.modifiers.new("dance", "MESH_CACHE")
        cache.cache_format, cache.filepath = "PC2", path
        cache.frame_start, cache.frame_scale = 0.0, 1.0
    elif kind == "usd":
        bpy.ops.wm.usd_import(filepath=path)
    else:
        raise SystemExit(f"unknown kind {kind}")
    # The glTF importer adds a small icosphere as the bones' display shape: take the dance.
    obj = max((o for o in scene.objects if o.type == "MESH"), key=lambda o: len(o.data.vertices))
    positions = []
    for frame in frames:
        scene.frame_set(frame)
        depsgraph = bpy.context.evaluated_depsgraph_get()
        positions.append(evaluated(obj, depsgraph))
    np.savez(out, frames=np.array(positions), version=bpy.app.version_string)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], float(sys.argv[3]), sys.argv[4],
         [int(frame) for frame in sys.argv[5:]])
    sys.stdout.flush()
    os._exit(0)  # bpy 4.2 crashes while the interpreter shuts down (the results are written)
