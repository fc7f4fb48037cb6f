"""Models that are not glTF: OBJ (with its MTL and images), PLY (with vertex colours), OFF and
STL through trimesh; FBX, .blend, .dae and .3ds through Blender when its `bpy` can be imported
in this interpreter (the optional `blender` extra), else one line saying how to convert them
(docs/design.md#appearance).

Files an OBJ names (its MTL, the MTL's images) are read only from the model's own folder.
"""

from __future__ import annotations

import contextlib
import importlib.util
import io
import os

import numpy as np

from eigendance.assets.appearance import srgb_to_linear
from eigendance.assets.materials import Images, check_image_header, trimesh_material
from eigendance.assets.model import Model, combine
from eigendance.assets.primitives import Piece
from eigendance.assets.text_meshes import (
    check_off,
    check_ply,
    check_stl_length,
    checked_obj,
    obj_with_absolute_indices,
    read_text,
)
from eigendance.errors import InputError, one_line
from eigendance.writes import swept_locked_folder

# Formats Blender imports and we do not: converted through bpy when it can be imported.
CONVERTIBLE = {".fbx": "import_scene.fbx", ".blend": None, ".dae": "wm.collada_import",
               ".3ds": "import_scene.max3ds"}
# The converter's temporary folders: each holds its lock while Blender converts; the next
# conversion sweeps those that killed processes left (`writes.swept_locked_folder`).
CONVERT_PREFIX = "eigendance-convert-"


def read_with_trimesh(path: str, name: str) -> Model:
    """An OBJ, PLY, OFF or STL file as a `Model` (one piece per material).

    Parameters
    ----------
    path : the file.
    name : how messages call it.

    Returns
    -------
    Model.
    """
    import trimesh  # heavy (≈0.8 s): imported when a mesh file is read

    obj = path.lower().endswith(".obj")
    text = checked_obj(path, name) if obj else None  # relative indices made absolute
    if path.lower().endswith(".off"):
        check_off(path, name)
    if path.lower().endswith(".ply"):
        check_ply(path, name)

    def source():
        return (io.BytesIO(text), "obj") if text is not None else (path, None)

    try:
        resolver = _FolderResolver(path, name)
        loaded = trimesh.load(*source(), process=False, resolver=resolver)
        geometries = list(loaded.geometry.values()) if isinstance(loaded, trimesh.Scene) \
            else [loaded]
        styled = any(_styled(geometry) for geometry in geometries)
        if not styled:  # exactly the vertices and triangles eigendance has always read
            geometries = [trimesh.load(*source(), force="mesh", process=False)]
    except InputError:
        raise
    except Exception as error:  # trimesh raises many types for malformed files
        if obj:  # which line is at fault, where it is an index
            obj_with_absolute_indices(read_text(path, name), name)
        raise InputError(f"{name}: cannot read the mesh ({one_line(error, 200)})") from None
    geometries = [g for g in geometries if len(getattr(g, "faces", None) if
                                                hasattr(g, "faces") else []) > 0]
    if not geometries:
        if path.lower().endswith(".stl"):
            check_stl_length(path, name)
        raise InputError(f"{name}: the file holds no triangles (a point cloud or empty mesh)")
    images = Images()
    pieces, materials = [], []
    for geometry in geometries:
        pieces.append(_piece(geometry, materials, images, name, styled))
    model = combine(name, pieces, materials, images.images,
                    problems=resolver.problems + images.problems)
    model.styled = styled
    return model


def _styled(geometry) -> bool:
    """Whether trimesh found a material (an MTL) or vertex colours."""
    visual = getattr(geometry, "visual", None)
    kind = getattr(visual, "kind", None)
    return kind == "texture" and getattr(visual, "material", None) is not None or \
        kind == "vertex"


def _piece(geometry, materials: list, images: Images, name: str, styled: bool) -> Piece:
    vertices = np.asarray(geometry.vertices, dtype=np.float64)
    faces = np.asarray(geometry.faces, dtype=np.int64)
    visual = geometry.visual
    uvs, colors, material = [], None, -1
    if styled and visual.kind == "texture":
        uv = getattr(visual, "uv", None)
        if uv is not None and len(uv) == len(vertices):
            uvs = [np.column_stack([uv[:, 0], 1.0 - uv[:, 1]])]  # OBJ's v points up
        materials.append(trimesh_material(visual.material, images, name))
        material = len(materials) - 1
    elif styled and visual.kind == "vertex":
        rgba = np.asarray(visual.vertex_colors, dtype=np.float64) / 255.0
        colors = np.column_stack([srgb_to_linear(rgba[:, :3]), rgba[:, 3]])
    normals = np.asarray(geometry.vertex_normals, dtype=np.float64) if styled else None
    return Piece(vertices, faces, normals, None, uvs, colors, material)


class _FolderResolver:
    """trimesh's file resolver, reading only regular files inside the model's folder (an MTL or
    image named with `..` or an absolute path is not read: trimesh then goes on without it),
    and no image whose header declares too many pixels (`materials.check_image_header`: trimesh
    would decode it whole; it goes on without it, and the model's warning says why)."""

    def __init__(self, path: str, model: str = ""):
        self.folder = os.path.dirname(os.path.abspath(path))
        self.model = model
        self.problems: list[str] = []

    def get(self, name: str) -> bytes:
        parts = str(name).replace("\\", "/").split("/")
        path = os.path.realpath(os.path.join(self.folder, *parts))
        if os.path.isabs(name) or ".." in parts or not path.startswith(
                os.path.realpath(self.folder) + os.sep) or not os.path.isfile(path):
            raise FileNotFoundError(name)
        with open(path, "rb") as file:
            data = file.read()
        if not name.lower().endswith(".mtl"):
            try:
                check_image_header(data)
            except InputError as error:
                self.problems.append(f"{name}: {error}")
                raise FileNotFoundError(name) from None
        return data

    __getitem__ = get

    def namespaced(self, namespace: str) -> _FolderResolver:
        return self

    def write(self, name, data):
        raise PermissionError("read only")


def blender_available() -> bool:
    """Whether Blender's Python module (`bpy`, the `blender` extra) can be imported here.

    Returns
    -------
    bool.
    """
    return importlib.util.find_spec("bpy") is not None


@contextlib.contextmanager
def converted(path: str, name: str, problems: list | None = None):
    """A temporary .glb of a file Blender imports (FBX, .blend, .dae, .3ds), made with bpy;
    without bpy, one InputError saying how to convert it. Images whose headers declare too
    many pixels are dropped before Blender decodes any (`large_images`).

    Parameters
    ----------
    path : the file.
    name : how messages call it.
    problems : where the dropped images are said (the model's warnings), or None.

    Yields
    ------
    str, the temporary .glb, in a locked folder of its own (removed afterwards; the folders of
    killed conversions are removed at the next: `writes.swept_locked_folder`).
    """
    suffix = os.path.splitext(path)[1].lower()
    how = "open it" if suffix == ".blend" else f"File › Import › {suffix[1:].upper()}"
    if not blender_available():  # one line of the page at 1100 px (a long name aside)
        raise InputError(f"{name}: {suffix} needs Blender ({how}, then File › Export › glTF "
                         "2.0) or pip install 'eigendance[blender]'", status=415)
    with swept_locked_folder(CONVERT_PREFIX) as folder:
        glb = os.path.join(folder, "converted.glb")
        _blender_export(path, glb, CONVERTIBLE[suffix], name,
                        problems if problems is not None else [])
        yield glb


def large_images(images, absolute) -> list[tuple[object, str]]:
    """The images of a Blender file whose headers declare too many pixels
    (`materials.check_image_header`), read from their packed bytes or their files: nothing is
    decoded.

    Parameters
    ----------
    images : Blender's images (`bpy.data.images`): each with `name`, `packed_file` (None, or
        with `data`) and `filepath`.
    absolute : Blender's path → an absolute path (`bpy.path.abspath`).

    Returns
    -------
    [(image, its problem in one line)].
    """
    found = []
    for image in images:
        packed = getattr(image, "packed_file", None)
        try:
            if packed is not None:
                data = bytes(packed.data)
            else:
                with open(absolute(image.filepath), "rb") as file:
                    data = file.read()
        except (OSError, ValueError, TypeError):  # not there: Blender goes on without it
            continue
        try:
            check_image_header(data)
        except InputError as error:
            found.append((image, f"{image.name}: {error}"))
    return found


def _blender_export(path: str, glb: str, operator: str | None, name: str,
                    problems: list) -> None:
    import bpy  # optional: the `blender` extra

    try:
        if operator is None:
            bpy.ops.wm.open_mainfile(filepath=path)
        else:
            bpy.ops.wm.read_factory_settings(use_empty=True)
            group, action = operator.split(".")
            importer = getattr(getattr(bpy.ops, group), action)
            if not importer.poll():
                raise RuntimeError(f"this Blender ({bpy.app.version_string}) has no importer")
            importer(filepath=path)
        for image, problem in large_images(list(bpy.data.images), bpy.path.abspath):
            problems.append(problem)
            bpy.data.images.remove(image)  # before the exporter decodes it
        bpy.ops.export_scene.gltf(filepath=glb, export_format="GLB", export_animations=False)
    except Exception as error:  # noqa: BLE001 - Blender raises RuntimeError with its report
        raise InputError(f"{name}: Blender could not convert it ({one_line(error, 200)})") \
            from None
