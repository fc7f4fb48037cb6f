"""The GLSL both renderers compile, and how a material becomes a shader (docs/design.md#rendering).

One source for the page (web/src imports the `.glsl` files of this folder with Vite's `?raw`;
three.js puts `#version 300 es` and the defines before them) and the video
(`eigendance.export.renderer`: `program` puts `#version 330` and the defines before them). The
files hold no `#version` line: GLSL ES 3.00 and GLSL 3.30 read the rest alike (precision
qualifiers are accepted and ignored by desktop GLSL).

`material_shading` is the one rule from a glTF material (`assets.Material`) to the surface
shader's defines, uniforms and textures: the server sends it to the page with the appearance
bundle (docs/web.md#appearance-bundle) and the video's renderer applies it, so both draw a
material the same way.
"""

from __future__ import annotations

import math
from functools import cache
from importlib import resources

GLSL_VERSION = "#version 330"  # desktop OpenGL 3.3 core (moderngl on EGL)
# Each texture of a glTF material: the shader's sampler name, its define and whether its image
# holds sRGB colours (decoded to linear by the sampler) or linear data.
MAPS = {
    "base_color_texture": ("baseMap", "BASE_MAP", True),
    "metallic_roughness_texture": ("metallicRoughnessMap", "METALLIC_ROUGHNESS_MAP", False),
    "normal_texture": ("normalMap", "NORMAL_MAP", False),
    "occlusion_texture": ("occlusionMap", "OCCLUSION_MAP", False),
    "emissive_texture": ("emissiveMap", "EMISSIVE_MAP", True),
}
# glTF sampler defaults (WebGL enums): linear magnification, trilinear minification, repeat.
LINEAR, LINEAR_MIPMAP_LINEAR, REPEAT = 9729, 9987, 10497


@cache
def source(name: str) -> str:
    """The text of a shader file of this package.

    Parameters
    ----------
    name : "surface.vert", "surface.frag", "backdrop.vert", "backdrop.frag", "shadow.vert" or
        "shadow.frag".

    Returns
    -------
    str, the GLSL without a version line.
    """
    return (resources.files("eigendance.shaders") / f"{name}.glsl").read_text(encoding="utf-8")


def program(name: str, defines: dict | None = None) -> str:
    """A shader for desktop OpenGL 3.3: the version line, the defines, then `source(name)`.

    Parameters
    ----------
    name : as for `source`.
    defines : {name: value} written as `#define NAME VALUE` (three.js writes its `defines` so).

    Returns
    -------
    str, GLSL 3.30.

    Example
    -------
    >>> program("shadow.frag", {"CPU_PATH": 1}).splitlines()[:2]
    ['#version 330', '#define CPU_PATH 1']
    """
    lines = [GLSL_VERSION] + [f"#define {key} {value}" for key, value in (defines or {}).items()]
    return "\n".join(lines) + "\n" + source(name)


def texture_transform(texture) -> list[float]:
    """KHR_texture_transform as the shader's mat3, column-major: T·R·S with T the offset, S the
    scale and R the rotation as the Khronos glTF Sample Viewer and three.js turn UVs
    (u' = cos·u + sin·v, v' = −sin·u + cos·v).

    Parameters
    ----------
    texture : an `assets.Texture`.

    Returns
    -------
    9 floats, column-major (GLSL `mat3`, three.js `Matrix3.fromArray`).

    Example
    -------
    >>> from eigendance.assets.appearance import Texture
    >>> texture_transform(Texture(0, offset=(0.5, 0.25), uv_scale=(2.0, 3.0)))
    [2.0, 0.0, 0.0, 0.0, 3.0, 0.0, 0.5, 0.25, 1.0]
    """
    (ox, oy), (sx, sy) = texture.offset, texture.uv_scale
    c, s = math.cos(texture.rotation), math.sin(texture.rotation)
    # rows: u' = c·sx·u + s·sy·v + ox, v' = −s·sx·u + c·sy·v + oy
    matrix = [c * sx, -s * sx, 0.0, s * sy, c * sy, 0.0, ox, oy, 1.0]
    return [float(value) + 0.0 for value in matrix]  # + 0.0: no −0.0 in the page's JSON


def material_shading(material, uv_sets: int, colors: bool) -> dict:
    """How the surface shader draws a material: the same for the page and the video.

    Parameters
    ----------
    material : an `assets.Material`.
    uv_sets : how many UV sets the drawn vertices have (a texture reading a set they lack
        reads set 0).
    colors : whether the drawn vertices have colours (COLOR_0).

    Returns
    -------
    {"defines": {name: value}, "uniforms": {name: number or list}, "textures": {sampler name:
    {"image", "srgb", "sampler": {magFilter, minFilter, wrapS, wrapT}}}, "blend": bool (alpha
    BLEND: drawn after the opaque parts without writing depth), "doubleSided": bool}. Uniform
    lists of 9 are column-major mat3.

    Example
    -------
    >>> from eigendance.assets.appearance import Material
    >>> shading = material_shading(Material(alpha_mode="MASK", unlit=True), 1, False)
    >>> shading["defines"], shading["uniforms"]["alphaCutoff"]
    ({'MATERIAL': 1, 'ALPHA_MASK': 1, 'UNLIT': 1}, 0.5)
    """
    defines: dict = {"MATERIAL": 1}
    uniforms: dict = {"baseColorFactor": [float(c) for c in material.base_color],
                      "metallicFactor": float(material.metallic),
                      "roughnessFactor": float(material.roughness),
                      "emissiveFactor": [float(c) for c in material.emissive],
                      "alphaCutoff": float(material.alpha_cutoff)}
    textures = {}
    for field, texture in material.textures().items():
        name, define, srgb = MAPS[field]
        second = texture.tex_coord == 1 and uv_sets > 1
        defines[define] = 1
        defines[f"{define}_UV"] = "vUv1" if second else "vUv0"
        if second:
            defines["UV1"] = 1
        uniforms[f"{name}Transform"] = texture_transform(texture)
        sampler = {"magFilter": LINEAR, "minFilter": LINEAR_MIPMAP_LINEAR, "wrapS": REPEAT,
                   "wrapT": REPEAT, **texture.sampler}
        textures[name] = {"image": texture.image, "srgb": srgb, "sampler": sampler}
    if "normalMap" in textures:  # y flipped: glTF's v runs down the image (three.js's rule)
        scale = float(material.normal_texture.scale)
        uniforms["normalScale"] = [scale, -scale]
    if "occlusionMap" in textures:
        uniforms["occlusionStrength"] = float(material.occlusion_texture.scale)
    if colors:
        defines["VERTEX_COLOR"] = 1
    if material.alpha_mode in ("MASK", "BLEND"):
        defines[f"ALPHA_{material.alpha_mode}"] = 1
    if material.unlit:
        defines["UNLIT"] = 1
    return {"defines": defines, "uniforms": uniforms, "textures": textures,
            "blend": material.alpha_mode == "BLEND", "doubleSided": bool(material.double_sided)}
