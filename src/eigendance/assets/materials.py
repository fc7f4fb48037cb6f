"""Materials as `appearance.Material`: from a glTF document, or from trimesh's visuals of an
OBJ with its MTL (docs/design.md#appearance).

An image that cannot be read (missing, truncated, neither PNG nor JPEG) costs only its
texture: the material keeps its factors, and the image is listed in the model's warning.
"""

from __future__ import annotations

import io
import warnings

import numpy as np

from eigendance import checks
from eigendance.assets.appearance import ALPHA_MODES, Image, Material, Texture, srgb_to_linear
from eigendance.assets.gltf import GltfFile
from eigendance.errors import InputError

SAMPLER_FIELDS = ("magFilter", "minFilter", "wrapS", "wrapT")

# The largest texture read: WebGL2 implementations allow 4096 to 16384 texels a side, and
# 64 M pixels are 256 MB decoded as RGBA.
MAX_IMAGE_SIDE, MAX_IMAGE_PIXELS = 16384, 1 << 26


class Images:
    """The images a model's materials use, read once each, in the order first used."""

    def __init__(self):
        self.images: list[Image] = []
        self.index: dict = {}  # the source's key (glTF image index, file path) → our index
        self.problems: list[str] = []

    def add(self, key, read) -> int | None:
        """Our index of the image with `key`, reading it with read() → (name, mime, bytes) the
        first time; None (and a problem noted) if it cannot be read.

        Parameters
        ----------
        key : what identifies the image in the file (an index, a path).
        read : () → (name, mime type, bytes).

        Returns
        -------
        int or None.
        """
        if key not in self.index:
            try:
                name, mime, data = read()
                _check_decodes(data)
            except InputError as error:
                self.problems.append(str(error))
                self.index[key] = None
            else:
                self.index[key] = len(self.images)
                self.images.append(Image(name, mime, data))
        return self.index[key]


def check_image_header(data: bytes) -> None:
    """InputError when an image's header declares more than MAX_IMAGE_SIDE pixels a side or
    MAX_IMAGE_PIXELS in all, read before a pixel is decoded (a PNG of a few kB may declare
    100,000 × 100,000 pixels); nothing for bytes Pillow does not take for an image (they fail
    where they are decoded). Every path that reads a model's images calls it first: glTF
    (`Images.add`), OBJ/MTL and PLY (`other_formats`' resolver), Blender's formats.

    Parameters
    ----------
    data : the image file's bytes.
    """
    from PIL import Image as PillowImage  # imported when a textured model is read

    limits = f"at most {MAX_IMAGE_SIDE} a side and {MAX_IMAGE_PIXELS >> 20} M pixels"
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", PillowImage.DecompressionBombWarning)
            with PillowImage.open(io.BytesIO(data)) as image:
                width, height = image.size
    except PillowImage.DecompressionBombError:  # Pillow's own limit, above ours
        raise InputError(f"an image of more than {2 * PillowImage.MAX_IMAGE_PIXELS >> 20} M "
                         f"pixels ({limits})") from None
    except Exception:  # noqa: BLE001 - not an image Pillow reads: said where it is decoded
        return
    if max(width, height) > MAX_IMAGE_SIDE or width * height > MAX_IMAGE_PIXELS:
        raise InputError(f"an image of {width} × {height} pixels ({limits})")


def _check_decodes(data: bytes) -> None:
    """InputError unless the image's size is within the limits (`check_image_header`) and
    Pillow can read its header and structure."""
    from PIL import Image as PillowImage  # imported when a textured model is read

    check_image_header(data)
    try:
        with PillowImage.open(io.BytesIO(data)) as image:
            image.verify()
    except Exception as error:  # noqa: BLE001 - Pillow raises many kinds on broken images
        raise InputError(f"a broken image ({type(error).__name__})") from None


def gltf_materials(gltf: GltfFile, images: Images) -> list[Material]:
    """Every material of the document, in order (KHR_materials_unlit and
    KHR_texture_transform included).

    Parameters
    ----------
    gltf : the file.
    images : the images read so far (added to).

    Returns
    -------
    list of Material.
    """
    return [_gltf_material(gltf, index, item, images)
            for index, item in enumerate(gltf.document.materials or [])]


def _gltf_material(gltf: GltfFile, index: int, item, images: Images) -> Material:
    pbr = item.pbrMetallicRoughness

    def texture(info, scale_field=None):
        return _texture(gltf, info, images, scale_field, f"material {index}")

    extensions = item.extensions or {}
    label = f"{gltf.name}: material {index}"
    emissive = _numbers(item.emissiveFactor, 3, (0.0, 0.0, 0.0), f"{label} emissiveFactor")
    strength = (extensions.get("KHR_materials_emissive_strength") or {}).get(
        "emissiveStrength")
    strength = 1.0 if strength is None else \
        checks.number(strength, f"{label} emissiveStrength", 0.0)
    emissive = tuple(float(c) * strength for c in emissive)
    mode = item.alphaMode if item.alphaMode in ALPHA_MODES else "OPAQUE"
    cutoff = item.alphaCutoff if isinstance(item.alphaCutoff, int | float) else 0.5
    return Material(
        name=str(item.name or f"material {index}"),
        base_color=_numbers(getattr(pbr, "baseColorFactor", None), 4, (1.0, 1.0, 1.0, 1.0),
                            f"{label} baseColorFactor"),
        base_color_texture=texture(getattr(pbr, "baseColorTexture", None)),
        metallic=_number(getattr(pbr, "metallicFactor", None), 1.0, f"{label} metallicFactor"),
        roughness=_number(getattr(pbr, "roughnessFactor", None), 1.0,
                          f"{label} roughnessFactor"),
        metallic_roughness_texture=texture(getattr(pbr, "metallicRoughnessTexture", None)),
        normal_texture=texture(item.normalTexture, "scale"),
        occlusion_texture=texture(item.occlusionTexture, "strength"),
        emissive=emissive, emissive_texture=texture(item.emissiveTexture),
        alpha_mode=mode, alpha_cutoff=float(cutoff), double_sided=bool(item.doubleSided),
        unlit="KHR_materials_unlit" in extensions)


def _texture(gltf: GltfFile, info, images: Images, scale_field, what) -> Texture | None:
    """A textureInfo as a `Texture`, or None when absent or its image cannot be read."""
    if info is None:
        return None
    textures = gltf.document.textures or []
    index = getattr(info, "index", None)
    if not isinstance(index, int) or not 0 <= index < len(textures):
        raise gltf.message(f"{what} names texture {index!r}, which does not exist")
    texture = textures[index]
    source = texture.source
    if source is None:  # only an extension's image (KTX2, WebP): not one we read
        images.problems.append(f"texture {index}: no PNG or JPEG source")
        return None
    image = images.add(("gltf", source), lambda: gltf.image(source))
    if image is None:
        return None
    sampler = {}
    if isinstance(texture.sampler, int) and 0 <= texture.sampler < len(gltf.document.samplers):
        item = gltf.document.samplers[texture.sampler]
        sampler = {name: getattr(item, name) for name in SAMPLER_FIELDS
                   if isinstance(getattr(item, name, None), int)}
    transform = (getattr(info, "extensions", None) or {}).get("KHR_texture_transform") or {}
    tex_coord = transform.get("texCoord", getattr(info, "texCoord", 0) or 0)
    scale = getattr(info, scale_field, None) if scale_field else None
    label = f"{gltf.name}: {what} texture {index}"
    return Texture(image=image, tex_coord=int(tex_coord) if isinstance(tex_coord, int) else 0,
                   scale=_number(scale, 1.0, f"{label} {scale_field}"),
                   offset=_numbers(transform.get("offset"), 2, (0.0, 0.0), f"{label} offset"),
                   rotation=_number(transform.get("rotation"), 0.0, f"{label} rotation"),
                   uv_scale=_numbers(transform.get("scale"), 2, (1.0, 1.0), f"{label} scale"),
                   sampler=sampler)


def _number(value, default: float, label: str) -> float:
    """A material's number: the format's `default` when the file gives none (glTF: an absent
    factor), else checked by `checks.number` — text, a bool, NaN or ±∞ is an InputError naming
    the file and the field, never silently the default."""
    return default if value is None else checks.number(value, label)


def _numbers(values, count: int, default: tuple, label: str) -> tuple:
    """`count` numbers of a material (`_number`'s rule for each): `default` when absent."""
    if values is None:
        return default
    if not isinstance(values, list | tuple) or len(values) != count:
        raise InputError(f"{label} must be a list of {count} numbers, not {checks.shown(values)}")
    return tuple(checks.number(value, f"{label}[{i}]") for i, value in enumerate(values))


# --- trimesh (OBJ + MTL, PLY) -------------------------------------------------------------------

def trimesh_material(material, images: Images, name: str) -> Material:
    """A trimesh material (SimpleMaterial from an MTL, or PBRMaterial) as a `Material`.

    An MTL's Kd is an sRGB colour (as Blender's importer reads it): it becomes the linear base
    colour; `map_Kd` the base colour texture, `d` the alpha (BLEND below 1).

    Parameters
    ----------
    material : the trimesh material.
    images : the images read so far (added to).
    name : the model's name, for messages.

    Returns
    -------
    Material.
    """
    pbr = material.to_pbr() if hasattr(material, "to_pbr") else material
    color = getattr(pbr, "baseColorFactor", None)
    rgba = np.ones(4) if color is None else np.asarray(color, dtype=float).reshape(-1)[:4]
    if rgba.max() > 1.0:  # trimesh keeps colours as bytes
        rgba = rgba / 255.0
    rgba = np.concatenate([srgb_to_linear(rgba[:3]), rgba[3:4] if len(rgba) > 3 else [1.0]])
    texture = None
    image = getattr(pbr, "baseColorTexture", None)
    if image is not None:
        index = images.add(("trimesh", id(image)), lambda: _pillow_bytes(image, name))
        texture = None if index is None else Texture(index)
    return Material(name=str(getattr(material, "name", "") or "material"),
                    base_color=tuple(float(c) for c in rgba), base_color_texture=texture,
                    metallic=_number(getattr(pbr, "metallicFactor", None), 0.0,
                                     f"{name}: metallic"),
                    roughness=_number(getattr(pbr, "roughnessFactor", None), 0.8,
                                      f"{name}: roughness"),
                    alpha_mode="BLEND" if rgba[3] < 1 else "OPAQUE")


def _pillow_bytes(image, name: str) -> tuple[str, str, bytes]:
    """(name, mime, bytes) of a Pillow image trimesh decoded: its original file's bytes when
    Pillow kept them (PNG, JPEG), else re-encoded as PNG."""
    form = getattr(image, "format", None)
    filename = getattr(image, "filename", "") or ""
    if form in ("PNG", "JPEG") and filename:
        with open(filename, "rb") as file:
            return filename.rsplit("/", 1)[-1], f"image/{form.lower()}", file.read()
    buffer = io.BytesIO()
    try:
        image.save(buffer, format="PNG")
    except Exception as error:  # noqa: BLE001 - Pillow's kinds
        raise InputError(f"{name}: a texture cannot be encoded ({type(error).__name__})") \
            from None
    return "texture.png", "image/png", buffer.getvalue()
