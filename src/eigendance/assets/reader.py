"""`read_model`: one reader for every model file (docs/design.md#appearance).

The harmonic pipeline (`harmonic.mesh.load_mesh`), the modal one (`modal.gltf_skin`) and the
exports read models here. Whatever a file holds that cannot be kept (points, lines, morph
targets of its own, unreadable images) is listed once in `Model.warnings`, and `read_model`
issues it as one `ModelWarning`.
"""

from __future__ import annotations

import os

from eigendance.assets.gltf import GltfFile
from eigendance.assets.materials import Images, gltf_materials
from eigendance.assets.model import Model, combine
from eigendance.assets.other_formats import CONVERTIBLE, converted, read_with_trimesh
from eigendance.assets.scene import read_scene
from eigendance.errors import InputError, one_line
from eigendance.files import check_readable, suffix_of

GLTF_SUFFIXES = (".gltf", ".glb")


def read_model(path: str | os.PathLike, name: str | None = None, warn: bool = True) -> Model:
    """Read a model file: glTF (.glb, .gltf), OBJ (with its MTL and images), PLY (with vertex
    colours), OFF, STL; FBX, .blend, .dae, .3ds through Blender when its `bpy` can be imported.

    Parameters
    ----------
    path : the file.
    name : how messages call it (default: the file's name).
    warn : issue the model's warnings as one `ModelWarning`.

    Returns
    -------
    Model; InputError (one line naming the file) when it cannot be read.

    Example
    -------
    >>> from importlib.resources import files
    >>> cat = read_model(files("eigendance") / "data" / "cat_lowres.obj")
    >>> len(cat.positions), len(cat.triangles), cat.styled
    (7949, 15894, False)
    """
    path = check_readable(path)
    name = name or os.path.basename(path)
    suffix = suffix_of(path)
    if suffix in CONVERTIBLE:
        dropped: list[str] = []
        with converted(path, name, dropped) as glb:
            model = read_gltf(glb, name)
        model.warnings[:0] = dropped
    elif suffix in GLTF_SUFFIXES:
        model = read_gltf(path, name)
    else:
        model = read_with_trimesh(path, name)
    if warn:
        model.warn()
    return model


def read_gltf(path: str, name: str) -> Model:
    """A glTF file's default scene as a `Model`.

    Parameters
    ----------
    path : a .glb or .gltf file.
    name : how messages call it.

    Returns
    -------
    Model.
    """
    gltf = GltfFile(path, name)
    try:
        images = Images()
        materials = gltf_materials(gltf, images)
        scene = read_scene(gltf)
    except InputError:
        raise
    except (IndexError, KeyError, ValueError, TypeError, AttributeError) as error:
        raise InputError(f"{name}: malformed glTF ({one_line(error, 150)})") from None
    if not scene.pieces:
        raise InputError(f"{name}: the file holds no triangles (no mesh in its scene)")
    problems = scene.notes + images.problems
    return combine(name, scene.pieces, materials, images.images, scene.skin, problems)
