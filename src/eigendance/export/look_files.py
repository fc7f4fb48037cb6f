"""A model's look beside a point cache or a USD file: texture images as files, and the OBJ of
the rest mesh with its MTL (docs/design.md#exports).

The OBJ keeps the point cache's vertex order: its `v` lines are the welded vertices (the ones
the .pc2 moves), its `vt` lines the drawn vertices' UVs (v flipped: OBJ's points up), and each
face corner names both (`f v/vt`), the faces grouped by material (`usemtl`). The MTL gives each
material its colour (Kd, sRGB), opacity (d), emission (Ke), PBR roughness and metallic (Pr,
Pm, which Blender's importer reads) and its textures (map_Kd, map_Bump for the normal map,
map_Ke).
"""

from __future__ import annotations

import os

import numpy as np

from eigendance.assets.appearance import Appearance, Material, linear_to_srgb

OBJ_TEXTURES = (("map_Kd", "base_color_texture"), ("map_Bump", "normal_texture"),
                ("map_Ke", "emissive_texture"))


def texture_files(path: str, appearance: Appearance | None) -> list[str]:
    """The image files written beside `path`: `<stem>_texture<i>.png|.jpg`, one per image.

    Parameters
    ----------
    path : the export's main file.
    appearance : the look, or None.

    Returns
    -------
    list of str.
    """
    if appearance is None:
        return []
    stem = os.path.splitext(os.fspath(path))[0]
    return [f"{stem}_texture{index}{image.suffix}" for index, image in
            enumerate(appearance.images)]


def material_names(appearance: Appearance) -> list[str]:
    """A unique, space-free name per material (MTL names end at the line's end).

    Parameters
    ----------
    appearance : the look.

    Returns
    -------
    list of str.
    """
    names = []
    for index, material in enumerate(appearance.materials):
        base = "".join(c if c.isalnum() or c in "-_." else "_" for c in material.name) or \
            "material"
        names.append(f"{base}_{index}")
    return names


def mtl_text(appearance: Appearance, textures: list[str]) -> str:
    """The MTL of the appearance's materials; `textures` are the image files' names.

    Parameters
    ----------
    appearance : the look.
    textures : the image files.

    Returns
    -------
    str.
    """
    lines = ["# eigendance: materials of the rest mesh"]
    for name, material in zip(material_names(appearance), appearance.materials, strict=True):
        lines += [f"newmtl {name}", *_mtl_lines(material, textures), ""]
    return "\n".join(lines) + "\n"


def _mtl_lines(material: Material, textures: list[str]) -> list[str]:
    kd = linear_to_srgb(material.base_color[:3])
    ke = linear_to_srgb(material.emissive)
    if material.unlit:  # no lighting: the colour is its own light
        kd, ke = np.zeros(3), kd
    lines = [f"Kd {kd[0]:.6f} {kd[1]:.6f} {kd[2]:.6f}", f"Ke {ke[0]:.6f} {ke[1]:.6f} {ke[2]:.6f}",
             f"d {material.base_color[3]:.6f}", f"Pr {material.roughness:.6f}",
             f"Pm {material.metallic:.6f}", "illum 2"]
    for key, field in OBJ_TEXTURES:
        texture = getattr(material, field)
        if texture is not None:
            target = "map_Ke" if material.unlit and key == "map_Kd" else key
            lines.append(f"{target} {os.path.basename(textures[texture.image])}")
    return lines


def obj_text(vertices: np.ndarray, faces: np.ndarray, comment: str = "",
             appearance: Appearance | None = None, mtl: str = "") -> str:
    """Wavefront OBJ of a rest mesh: `v` lines in the given order (a point cache maps by index),
    then 1-based `f` lines; with a look, its MTL file, the drawn UVs and the drawn triangles by
    material on their welded vertices instead.

    Coordinates carry 9 significant digits (float32 round-trips exactly).

    Parameters
    ----------
    vertices : (n, 3) (welded, with a look).
    faces : (m, 3) 0-based (not written with a look, whose parts say the triangles).
    comment : a first comment line ('' for none).
    appearance : the look, or None.
    mtl : the MTL file beside it (with a look).

    Returns
    -------
    str, the file's text.
    """
    text = f"# {comment}\n" if comment else ""
    if appearance is not None:
        text = (text or "#\n") + f"mtllib {os.path.basename(mtl)}\n"
    # One %-format over all numbers at once: no Python loop over vertices.
    text += ("v %.9g %.9g %.9g\n" * len(vertices)) % tuple(np.asarray(vertices, float).ravel())
    if appearance is None:
        return text + ("f %d %d %d\n" * len(faces)) % tuple((np.asarray(faces, np.int64) + 1)
                                                             .ravel())
    uv = appearance.uvs[0] if appearance.uvs else np.zeros((appearance.n, 2))
    text += ("vt %.9g %.9g\n" * len(uv)) % tuple(np.column_stack([uv[:, 0], 1 - uv[:, 1]])
                                                 .ravel())
    names = material_names(appearance)
    for part in appearance.parts:
        corners = np.stack([appearance.welded[part.triangles] + 1, part.triangles + 1], axis=-1)
        text += f"usemtl {names[part.material]}\n"
        text += ("f %d/%d %d/%d %d/%d\n" * len(corners)) % tuple(corners.ravel())
    return text


def write_textures(outputs, appearance: Appearance | None, files: list[str]) -> None:
    """Each image's bytes into its file (through `outputs`: all or nothing).

    Parameters
    ----------
    outputs : the export's `Outputs`.
    appearance : the look, or None.
    files : the image files (`texture_files`).
    """
    for image, path in zip(appearance.images if appearance else [], files, strict=True):
        with open(outputs.temporary(path), "wb") as file:
            file.write(image.data)
