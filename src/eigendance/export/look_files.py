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

from eigendance.assets.appearance import Appearance, Material

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


def linear_to_srgb(linear) -> np.ndarray:
    """Linear components in [0, 1] → sRGB (what an MTL's Kd means to its readers).

    Parameters
    ----------
    linear : components in [0, 1].

    Returns
    -------
    array of the same shape.
    """
    c = np.clip(np.asarray(linear, dtype=np.float64), 0.0, 1.0)
    return np.where(c <= 0.0031308, c * 12.92, 1.055 * c ** (1 / 2.4) - 0.055)


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


def obj_text(vertices: np.ndarray, appearance: Appearance, mtl: str, comment: str = "") -> str:
    """Wavefront OBJ of the rest mesh with its look: the welded `vertices` in order, the drawn
    UVs, the drawn triangles by material on their welded vertices.

    Parameters
    ----------
    vertices : (n, 3) welded, at rest.
    appearance : the look.
    mtl : the MTL file beside it.
    comment : a first comment line.

    Returns
    -------
    str.
    """
    lines = [f"# {comment}" if comment else "#", f"mtllib {os.path.basename(mtl)}"]
    text = "\n".join(lines) + "\n"
    text += ("v %.9g %.9g %.9g\n" * len(vertices)) % tuple(np.asarray(vertices, float).ravel())
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
