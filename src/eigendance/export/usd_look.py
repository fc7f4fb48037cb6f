"""A model's look in a USD stage: UsdPreviewSurface materials bound per material subset, with
their textures (docs/design.md#exports).

The mesh keeps the welded points (the ones that move); what the drawn vertices add is
face-varying: `primvars:st` (and `st1` for a second UV set) indexed by the drawn triangles'
corners, `primvars:displayColor` likewise for vertex colours. Each material is a
`UsdShade.Material` under /Dance/Materials with a UsdPreviewSurface (diffuseColor, metallic,
roughness, emissiveColor, opacity and, for MASK, opacityThreshold; an unlit material emits its
colour), fed by UsdUVTexture nodes reading the image files written beside the stage (the factor
as the texture's scale; normal maps with scale 2, bias −1; sRGB for colours, raw otherwise),
bound to a GeomSubset of the faces (familyName materialBind). KHR_texture_transform is not
carried over (UsdTransform2d differs in its conventions): such a texture is drawn untransformed.
"""

from __future__ import annotations

import os

import numpy as np
from pxr import Gf, Sdf, Tf, UsdGeom, UsdShade, Vt

from eigendance.assets.appearance import Appearance, Material, Texture
from eigendance.export.look_files import material_names

COLOR_INPUTS = {"base_color_texture": ("diffuseColor", "rgb", "sRGB"),
                "emissive_texture": ("emissiveColor", "rgb", "sRGB"),
                "normal_texture": ("normal", "rgb", "raw"),
                "occlusion_texture": ("occlusion", "r", "raw")}


def bind_look(stage, mesh: UsdGeom.Mesh, appearance: Appearance, textures: list[str]) -> None:
    """Face-varying UVs and colours on `mesh`, and its materials bound per subset; `textures`
    are the image files (their names, beside the stage, are the asset paths).

    Parameters
    ----------
    stage : the USD stage.
    mesh : its mesh.
    appearance : the look.
    textures : the image files.
    """
    corners = np.concatenate([part.triangles for part in appearance.parts]).ravel()
    primvars = UsdGeom.PrimvarsAPI(mesh)
    for index, uv in enumerate(appearance.uvs):
        st = primvars.CreatePrimvar("st" if index == 0 else f"st{index}",
                                    Sdf.ValueTypeNames.TexCoord2fArray,
                                    UsdGeom.Tokens.faceVarying)
        st.Set(Vt.Vec2fArray.FromNumpy(np.column_stack([uv[:, 0], 1 - uv[:, 1]])
                                       .astype(np.float32)))
        st.SetIndices(Vt.IntArray.FromNumpy(corners.astype(np.int32)))
    if appearance.colors is not None:
        color = primvars.CreatePrimvar("displayColor", Sdf.ValueTypeNames.Color3fArray,
                                       UsdGeom.Tokens.faceVarying)
        color.Set(Vt.Vec3fArray.FromNumpy(appearance.colors[:, :3].astype(np.float32)))
        color.SetIndices(Vt.IntArray.FromNumpy(corners.astype(np.int32)))
    names = [Tf.MakeValidIdentifier(name) for name in material_names(appearance)]
    UsdShade.MaterialBindingAPI.Apply(mesh.GetPrim())
    UsdGeom.Xform.Define(stage, "/Dance/Materials")
    first = 0
    for index, part in enumerate(appearance.parts):
        material = _material(stage, f"/Dance/Materials/{names[part.material]}",
                             appearance.materials[part.material], textures)
        faces = np.arange(first, first + len(part.triangles), dtype=np.int32)
        first += len(part.triangles)
        subset = UsdGeom.Subset.CreateGeomSubset(
            mesh, f"part{index}", UsdGeom.Tokens.face,
            Vt.IntArray.FromNumpy(faces), "materialBind", UsdGeom.Tokens.partition)
        UsdShade.MaterialBindingAPI.Apply(subset.GetPrim()).Bind(material)


def _material(stage, path: str, material: Material, textures: list[str]) -> UsdShade.Material:
    if stage.GetPrimAtPath(path):
        return UsdShade.Material(stage.GetPrimAtPath(path))
    usd = UsdShade.Material.Define(stage, path)
    surface = UsdShade.Shader.Define(stage, f"{path}/Surface")
    surface.CreateIdAttr("UsdPreviewSurface")
    color = Gf.Vec3f(*(float(c) for c in material.base_color[:3]))
    emissive = Gf.Vec3f(*(float(c) for c in material.emissive))
    if material.unlit:
        color, emissive = Gf.Vec3f(0, 0, 0), color
    inputs = {"diffuseColor": (Sdf.ValueTypeNames.Color3f, color),
              "emissiveColor": (Sdf.ValueTypeNames.Color3f, emissive),
              "metallic": (Sdf.ValueTypeNames.Float, float(material.metallic)),
              "roughness": (Sdf.ValueTypeNames.Float, float(material.roughness)),
              "opacity": (Sdf.ValueTypeNames.Float, float(material.base_color[3]))}
    if material.alpha_mode == "MASK":
        inputs["opacityThreshold"] = (Sdf.ValueTypeNames.Float, float(material.alpha_cutoff))
    for name, (kind, value) in inputs.items():
        surface.CreateInput(name, kind).Set(value)
    for field, texture in material.textures().items():
        _texture(stage, path, surface, field, texture, material, textures)
    usd.CreateSurfaceOutput().ConnectToSource(surface.ConnectableAPI(), "surface")
    return usd


def _texture(stage, path, surface, field, texture: Texture, material: Material, textures):
    node = UsdShade.Shader.Define(stage, f"{path}/{field}")
    node.CreateIdAttr("UsdUVTexture")
    node.CreateInput("file", Sdf.ValueTypeNames.Asset).Set(
        Sdf.AssetPath(os.path.basename(textures[texture.image])))
    reader = UsdShade.Shader.Define(stage, f"{path}/{field}_st")
    reader.CreateIdAttr("UsdPrimvarReader_float2")
    reader.CreateInput("varname", Sdf.ValueTypeNames.String).Set(
        "st" if texture.tex_coord == 0 else f"st{texture.tex_coord}")
    node.CreateInput("st", Sdf.ValueTypeNames.Float2).ConnectToSource(
        reader.ConnectableAPI(), "result")
    node.CreateInput("wrapS", Sdf.ValueTypeNames.Token).Set("repeat")
    node.CreateInput("wrapT", Sdf.ValueTypeNames.Token).Set("repeat")
    if field == "metallic_roughness_texture":  # glTF: roughness in G, metallic in B
        node.CreateInput("sourceColorSpace", Sdf.ValueTypeNames.Token).Set("raw")
        node.CreateInput("scale", Sdf.ValueTypeNames.Float4).Set(
            Gf.Vec4f(1, material.roughness, material.metallic, 1))
        for name, channel in (("roughness", "g"), ("metallic", "b")):
            surface.CreateInput(name, Sdf.ValueTypeNames.Float).ConnectToSource(
                node.CreateOutput(channel, Sdf.ValueTypeNames.Float))
        return
    target, channel, space = COLOR_INPUTS[field]
    if material.unlit and field == "base_color_texture":
        target = "emissiveColor"
    node.CreateInput("sourceColorSpace", Sdf.ValueTypeNames.Token).Set(space)
    scale, bias = _scale_bias(field, texture, material)
    node.CreateInput("scale", Sdf.ValueTypeNames.Float4).Set(scale)
    node.CreateInput("bias", Sdf.ValueTypeNames.Float4).Set(bias)
    kind = Sdf.ValueTypeNames.Float if channel == "r" else Sdf.ValueTypeNames.Float3
    value_kind = Sdf.ValueTypeNames.Float if channel == "r" else \
        (Sdf.ValueTypeNames.Normal3f if target == "normal" else Sdf.ValueTypeNames.Color3f)
    surface.CreateInput(target, value_kind).ConnectToSource(node.CreateOutput(channel, kind))
    if field == "base_color_texture" and material.alpha_mode != "OPAQUE":
        surface.CreateInput("opacity", Sdf.ValueTypeNames.Float).ConnectToSource(
            node.CreateOutput("a", Sdf.ValueTypeNames.Float))


def _scale_bias(field: str, texture: Texture, material: Material):
    if field == "normal_texture":
        s = float(texture.scale)
        return Gf.Vec4f(2 * s, 2 * s, 2, 1), Gf.Vec4f(-s, -s, -1, 0)
    if field == "base_color_texture":
        return Gf.Vec4f(*(float(c) for c in material.base_color)), Gf.Vec4f(0, 0, 0, 0)
    if field == "emissive_texture":
        return Gf.Vec4f(*(float(c) for c in material.emissive), 1), Gf.Vec4f(0, 0, 0, 0)
    strength = float(texture.scale)  # occlusion: 1 + strength·(texel − 1)
    return Gf.Vec4f(strength, strength, strength, 1), Gf.Vec4f(1 - strength, 1 - strength,
                                                               1 - strength, 0)
