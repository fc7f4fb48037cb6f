"""A mesh object's dance: its base mesh written for the command, and the dance the command
bakes put back on the same object, as shape keys or a Mesh Cache modifier.

The OBJ is the object's base mesh in object space (no axis conversion, vertices in Blender's
order, Blender's own triangles): `eigendance bake` answers vertex for vertex in that order, so
the dance lands on the object itself, with its materials, UVs, modifiers and transform.
"""

import numpy as np

from . import keys

PREFIX = "eigendance "  # the shape keys a bake adds (a new bake replaces them)
CACHE = "eigendance"  # the Mesh Cache modifier's name
# Past this many vertices a bake is a point cache (.pc2 beside the .blend) read by a Mesh
# Cache modifier: up to 64 shape keys of as many vertices would make the .blend too large.
SHAPE_KEY_VERTICES = 50_000


def base_positions(obj) -> np.ndarray:
    """The object's base mesh (its reference shape key, if it has shape keys), object space.

    Parameters
    ----------
    obj : a mesh object.

    Returns
    -------
    (n, 3) float32.
    """
    mesh = obj.data
    source = mesh.shape_keys.reference_key.data if mesh.shape_keys else mesh.vertices
    positions = np.empty(3 * len(mesh.vertices), dtype=np.float32)
    source.foreach_get("co", positions)
    return positions.reshape(-1, 3)


def write_obj(obj, path: str) -> np.ndarray:
    """Write the object's base mesh as an OBJ: its vertices that a face uses, in order (mesh
    readers drop the others: they stay at rest), and Blender's triangles.

    Parameters
    ----------
    obj : a mesh object.
    path : the .obj to write.

    Returns
    -------
    (m,) int64, the object's vertex of each vertex written.
    """
    mesh = obj.data
    mesh.calc_loop_triangles()
    triangles = np.empty(3 * len(mesh.loop_triangles), dtype=np.int64)
    mesh.loop_triangles.foreach_get("vertices", triangles)
    used = np.unique(triangles)
    renumber = np.zeros(len(mesh.vertices), dtype=np.int64)
    renumber[used] = np.arange(len(used))
    # repr of each float32 as a float64: the shortest text that reads back exactly.
    lines = ["# the base mesh of a Blender object, object space, for eigendance"]
    lines += [f"v {float(x)!r} {float(y)!r} {float(z)!r}"
              for x, y, z in base_positions(obj)[used]]
    lines += [f"f {a} {b} {c}" for a, b, c in renumber[triangles].reshape(-1, 3) + 1]
    with open(path, "w", encoding="utf-8") as file:
        file.write("\n".join(lines) + "\n")
    return used


def remove_dance(obj) -> None:
    """Remove an earlier bake from the object: its shape keys and its Mesh Cache modifier.

    Parameters
    ----------
    obj : a mesh object.
    """
    cache = obj.modifiers.get(CACHE)
    if cache is not None:
        obj.modifiers.remove(cache)
    if obj.data.shape_keys is None:
        return
    for key in list(obj.data.shape_keys.key_blocks):
        if key.name.startswith(PREFIX):
            obj.shape_key_remove(key)
    if len(obj.data.shape_keys.key_blocks) == 1:  # only the basis we added is left
        obj.shape_key_remove(obj.data.shape_keys.key_blocks[0])


def check_rest(obj, rest: np.ndarray, used: np.ndarray) -> str | None:
    """Why the baked dance does not fit the object (its vertices changed), or None.

    Parameters
    ----------
    obj : the mesh object.
    rest : (m, 3) the vertices the command solved.
    used : (m,) the object's vertex of each (`write_obj`).

    Returns
    -------
    str or None.
    """
    here = base_positions(obj)
    if used.max(initial=-1) >= len(here):
        return f"{obj.name}: the mesh changed while the dance was baked; bake again"
    here = here[used]
    if here.shape != rest.shape:
        return (f"{obj.name}: the mesh has {len(here)} vertices, the dance {len(rest)}; bake "
                "again")
    diagonal = float(np.linalg.norm(here.max(axis=0) - here.min(axis=0))) or 1.0
    if np.abs(here - rest).max() > 1e-5 * diagonal:
        return f"{obj.name}: the mesh changed while the dance was baked; bake again"
    return None


def add_shape_keys(obj, baked, used, first: int, name: str) -> int:
    """The dance as shape keys (one per driven harmonic, its range [−1, 1]) with a keyframe per
    sample from frame `first`.

    Parameters
    ----------
    obj : the mesh object.
    baked : the command's .npz (rest, targets, weights, harmonics).
    used : (m,) the object's vertex of each vertex baked (the others stay at rest).
    first : the frame of sample 0.
    name : the action's name.

    Returns
    -------
    int, shape keys added.
    """
    remove_dance(obj)
    targets, weights = baked["targets"], baked["weights"]
    if obj.data.shape_keys is None:
        obj.shape_key_add(name="Basis", from_mix=False)
    block = obj.data.shape_keys
    base = base_positions(obj)
    frames = first + np.arange(len(weights))
    keys.fresh_action(block, name)
    for index, harmonic in enumerate(baked["harmonics"]):
        key = obj.shape_key_add(name=f"{PREFIX}{int(harmonic)}", from_mix=False)
        key.slider_min, key.slider_max = -1.0, 1.0
        moved = base.copy()
        moved[used] += targets[index]
        key.data.foreach_set("co", moved.ravel())
        keys.key_samples(block, key, "value", -1, frames, weights[:, index])
    keys.name_action(block)
    return len(baked["harmonics"])


def add_mesh_cache(obj, path: str, first: int) -> None:
    """The dance as a Mesh Cache modifier reading a point cache, first in the stack (where
    shape keys would act), from frame `first`.

    Parameters
    ----------
    obj : the mesh object.
    path : the .pc2 (object space, the mesh's vertex order).
    first : the frame of sample 0.
    """
    remove_dance(obj)
    cache = obj.modifiers.new(CACHE, "MESH_CACHE")
    cache.cache_format, cache.filepath = "PC2", path
    cache.frame_start, cache.frame_scale = float(first), 1.0
    while obj.modifiers[0] != cache:
        index = list(obj.modifiers).index(cache)
        obj.modifiers.move(index, index - 1)
