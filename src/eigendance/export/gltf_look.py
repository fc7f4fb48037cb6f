"""A model's look written into a glTF: materials, textures, samplers and embedded images, and
the drawn vertices' attributes (docs/design.md#exports).

`write_look` adds an `Appearance`'s materials and images (embedded in the binary buffer) to a
document being built, and gives the attribute arrays every primitive shares (drawn positions
come from the dance, per drawn vertex through the welded map).
"""

from __future__ import annotations

import numpy as np
import pygltflib

from eigendance.assets.appearance import Appearance, Material, Texture


def write_look(appearance: Appearance, builder) -> list[int]:
    """Add the appearance's images, samplers, textures and materials to `builder.gltf`;
    returns the glTF material index of each appearance material.

    Parameters
    ----------
    appearance : the look.
    builder : the glb being built.

    Returns
    -------
    list of int.
    """
    gltf = builder.gltf
    images = []
    for image in appearance.images:
        images.append(len(gltf.images))
        gltf.images.append(pygltflib.Image(name=image.name or None, mimeType=image.mime_type,
                                           bufferView=builder.view(image.data)))
    indices = []
    for material in appearance.materials:
        indices.append(len(gltf.materials))
        gltf.materials.append(_material(material, images, gltf))
    return indices


def _material(material: Material, images: list[int], gltf) -> pygltflib.Material:
    def info(texture: Texture | None, kind=pygltflib.TextureInfo):
        return None if texture is None else _texture_info(texture, images, gltf, kind)

    extensions = {}
    if material.unlit:
        extensions["KHR_materials_unlit"] = {}
        _use(gltf, "KHR_materials_unlit")
    normal = info(material.normal_texture, pygltflib.NormalMaterialTexture)
    if normal is not None:
        normal.scale = material.normal_texture.scale
    occlusion = info(material.occlusion_texture, pygltflib.OcclusionTextureInfo)
    if occlusion is not None:
        occlusion.strength = material.occlusion_texture.scale
    return pygltflib.Material(
        name=material.name or None, extensions=extensions,
        pbrMetallicRoughness=pygltflib.PbrMetallicRoughness(
            baseColorFactor=[float(c) for c in material.base_color],
            baseColorTexture=info(material.base_color_texture),
            metallicFactor=float(material.metallic), roughnessFactor=float(material.roughness),
            metallicRoughnessTexture=info(material.metallic_roughness_texture)),
        normalTexture=normal, occlusionTexture=occlusion,
        emissiveFactor=[float(c) for c in material.emissive],
        emissiveTexture=info(material.emissive_texture),
        alphaMode=material.alpha_mode,
        alphaCutoff=float(material.alpha_cutoff) if material.alpha_mode == "MASK" else None,
        doubleSided=bool(material.double_sided))


def _texture_info(texture: Texture, images: list[int], gltf, kind):
    sampler = None
    if texture.sampler:
        sampler = len(gltf.samplers)
        gltf.samplers.append(pygltflib.Sampler(**texture.sampler))
    gltf.textures.append(pygltflib.Texture(source=images[texture.image], sampler=sampler))
    info = kind(index=len(gltf.textures) - 1, texCoord=texture.tex_coord)
    if texture.transformed:
        info.extensions = {"KHR_texture_transform": {
            "offset": list(texture.offset), "rotation": texture.rotation,
            "scale": list(texture.uv_scale)}}
        _use(gltf, "KHR_texture_transform")
    return info


def _use(gltf, extension: str) -> None:
    if extension not in gltf.extensionsUsed:
        gltf.extensionsUsed.append(extension)


def drawn_attributes(appearance: Appearance, builder, attributes) -> None:
    """Set the drawn vertices' NORMAL, TANGENT, TEXCOORD_n and COLOR_0 on `attributes`.

    Parameters
    ----------
    appearance : the look.
    builder : the glb being built.
    attributes : the primitive's attributes (set in place).
    """
    target = pygltflib.ARRAY_BUFFER
    if appearance.normals is not None:
        attributes.NORMAL = builder.accessor(_unit(appearance.normals).astype("<f4"), 3, target)
    if appearance.tangents is not None:
        tangents = appearance.tangents.copy()
        tangents[:, :3] = _unit(tangents[:, :3])
        tangents[:, 3] = np.where(tangents[:, 3] < 0, -1.0, 1.0)
        attributes.TANGENT = builder.accessor(tangents.astype("<f4"), 4, target)
    for index, uv in enumerate(appearance.uvs):
        setattr(attributes, f"TEXCOORD_{index}", builder.accessor(uv.astype("<f4"), 2, target))
    if appearance.colors is not None:
        attributes.COLOR_0 = builder.accessor(np.clip(appearance.colors, 0, 1).astype("<f4"), 4,
                                              target)


def _unit(vectors: np.ndarray) -> np.ndarray:
    """Unit vectors; a zero vector becomes +z (glTF wants every normal of unit length)."""
    length = np.linalg.norm(vectors, axis=1, keepdims=True)
    unit = np.divide(vectors, length, out=np.zeros_like(vectors, dtype=float), where=length > 0)
    unit[length[:, 0] <= 0] = (0.0, 0.0, 1.0)
    return unit
