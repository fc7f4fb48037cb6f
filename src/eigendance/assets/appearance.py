"""A model's look: materials, images and the drawn vertices (docs/design.md#appearance).

The *drawn* vertices are the file's vertices as it draws them: split wherever a UV seam, a hard
edge or a change of material splits them. The analysis (harmonics, modes) runs on the *welded*
surface, where drawn vertices at the same position (within `WELD_TOLERANCE` of the bounding-box
diagonal) are one vertex. `Appearance.welded[i]` is drawn vertex i's welded vertex, and a drawn
vertex follows it: at any time drawn vertex i is at its welded vertex's position
(`Appearance.drawn`). Everything else here is what the file says about the look.

Conventions: colours are linear RGB(A) as glTF stores them (sRGB textures are decoded by the
viewer); UVs are glTF's, (0, 0) the top-left corner of the image (an OBJ's v is flipped on
reading); normals are unit vectors in the model file's coordinates. sRGB colours (an MTL's
Kd, a vertex colour, a hex colour) become linear with `srgb_to_linear`, and back with
`linear_to_srgb`; both clip to [0, 1] first (docs/design.md#appearance).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

# Drawn vertices closer than this fraction of the bounding-box diagonal are one welded vertex.
WELD_TOLERANCE = 1e-7
ALPHA_MODES = ("OPAQUE", "MASK", "BLEND")


def srgb_to_linear(srgb) -> np.ndarray:
    """sRGB components → linear (IEC 61966-2-1), clipped to [0, 1] first: glTF's colour
    factors are linear and within [0, 1], whatever a file wrote (an MTL's Kd of 1.2).

    Parameters
    ----------
    srgb : components, nominally in [0, 1].

    Returns
    -------
    array of the same shape, in [0, 1].

    Example
    -------
    >>> srgb_to_linear([0.0, 0.5, 1.0, 1.2]).round(4).tolist()
    [0.0, 0.214, 1.0, 1.0]
    """
    c = np.clip(np.asarray(srgb, dtype=np.float64), 0.0, 1.0)
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def linear_to_srgb(linear) -> np.ndarray:
    """Linear components → sRGB (the inverse of `srgb_to_linear`), clipped to [0, 1] first.

    Parameters
    ----------
    linear : components, nominally in [0, 1].

    Returns
    -------
    array of the same shape, in [0, 1].
    """
    c = np.clip(np.asarray(linear, dtype=np.float64), 0.0, 1.0)
    return np.where(c <= 0.0031308, c * 12.92, 1.055 * c ** (1 / 2.4) - 0.055)


@dataclass
class Image:
    """The bytes of one texture image, as the file holds them.

    Parameters
    ----------
    name : how the file names it ('' if it does not).
    mime_type : "image/png" or "image/jpeg" (the formats glTF 2.0 core allows).
    data : the encoded file (PNG or JPEG bytes), never decoded here.
    """

    name: str
    mime_type: str
    data: bytes

    @property
    def suffix(self) -> str:
        """'.png' or '.jpg': the suffix of a file holding these bytes."""
        return ".png" if self.mime_type == "image/png" else ".jpg"


@dataclass
class Texture:
    """A material's use of an image (glTF textureInfo).

    Parameters
    ----------
    image : index into `Appearance.images`.
    tex_coord : which UV set it reads (0: TEXCOORD_0, 1: TEXCOORD_1).
    scale : the normal map's scale, the occlusion map's strength; 1 for other textures.
    offset, rotation, uv_scale : KHR_texture_transform (identity by default): the UV read is
        T·R·S·(u, v, 1) with T the offset, R the rotation (radians, counter-clockwise in UV
        space as the extension defines it) and S the scale.
    sampler : glTF sampler fields {"magFilter", "minFilter", "wrapS", "wrapT"} (WebGL enums;
        absent: the viewer's default, repeat and linear).
    """

    image: int
    tex_coord: int = 0
    scale: float = 1.0
    offset: tuple[float, float] = (0.0, 0.0)
    rotation: float = 0.0
    uv_scale: tuple[float, float] = (1.0, 1.0)
    sampler: dict = field(default_factory=dict)

    @property
    def transformed(self) -> bool:
        """Whether KHR_texture_transform changes the UVs."""
        return self.offset != (0.0, 0.0) or self.rotation != 0.0 or self.uv_scale != (1.0, 1.0)

    def to_json(self) -> dict:
        """The texture as the page reads it (glTF's camelCase names).

        Returns
        -------
        dict.
        """
        return {"image": self.image, "texCoord": self.tex_coord, "scale": self.scale,
                "offset": list(self.offset), "rotation": self.rotation,
                "uvScale": list(self.uv_scale), "sampler": dict(self.sampler)}


@dataclass
class Material:
    """glTF 2.0 metallic-roughness material, with KHR_materials_unlit.

    Factors multiply their textures as glTF defines: base colour = base_color · texture ·
    vertex colour (linear RGBA); metallic, roughness = factors · the texture's B, G channels;
    emissive = emissive · texture (linear RGB). Defaults are glTF's (a material the file does not
    give is white, metallic 1, roughness 1).

    Parameters
    ----------
    name, base_color, base_color_texture, metallic, roughness, metallic_roughness_texture,
    normal_texture, occlusion_texture, emissive, emissive_texture, alpha_mode, alpha_cutoff,
    double_sided, unlit : glTF's fields of the same names (colours linear).
    """

    name: str = ""
    base_color: tuple = (1.0, 1.0, 1.0, 1.0)
    base_color_texture: Texture | None = None
    metallic: float = 1.0
    roughness: float = 1.0
    metallic_roughness_texture: Texture | None = None
    normal_texture: Texture | None = None
    occlusion_texture: Texture | None = None
    emissive: tuple = (0.0, 0.0, 0.0)
    emissive_texture: Texture | None = None
    alpha_mode: str = "OPAQUE"
    alpha_cutoff: float = 0.5
    double_sided: bool = False
    unlit: bool = False

    TEXTURES = ("base_color_texture", "metallic_roughness_texture", "normal_texture",
                "occlusion_texture", "emissive_texture")

    def textures(self) -> dict[str, Texture]:
        """{field name: texture} of the textures this material uses.

        Returns
        -------
        dict.
        """
        return {name: getattr(self, name) for name in self.TEXTURES
                if getattr(self, name) is not None}

    def to_json(self) -> dict:
        """JSON-ready fields (camelCase, as glTF and the page name them).

        Returns
        -------
        dict.
        """
        textures = {_camel(name): texture.to_json() for name, texture in self.textures().items()}
        return {"name": self.name, "baseColor": list(self.base_color), "metallic": self.metallic,
                "roughness": self.roughness, "emissive": list(self.emissive),
                "alphaMode": self.alpha_mode, "alphaCutoff": self.alpha_cutoff,
                "doubleSided": self.double_sided, "unlit": self.unlit, **textures}


def _camel(name: str) -> str:
    first, *rest = name.split("_")
    return first + "".join(word.title() for word in rest)


@dataclass
class Part:
    """The drawn triangles of one material: `triangles` (m, 3) int64 index drawn vertices.

    Parameters
    ----------
    material : index into `Appearance.materials`.
    triangles : (m, 3) int64.
    """

    material: int
    triangles: np.ndarray


@dataclass
class Appearance:
    """How a model is drawn: drawn vertices, their attributes, parts, materials and images.

    Parameters
    ----------
    welded : (n_d,) int64, drawn vertex i's vertex of the analysis mesh (≥ 0).
    parts : the triangles of each material, one `Part` per material used.
    materials : every material the parts use (indices into this list).
    images : the texture images (`Texture.image` indexes them).
    normals : (n_d, 3) the file's unit normals (or normals computed per piece of a file without
        them), at rest.
    uvs : one (n_d, 2) array per UV set (TEXCOORD_0, TEXCOORD_1, …), glTF's convention.
    colors : (n_d, 4) linear RGBA vertex colours (COLOR_0), or None (white).
    tangents : (n_d, 4) glTF tangents (xyz, w the bitangent's sign), or None (the viewer
        derives them).

    Example
    -------
    >>> look = Appearance(welded=np.array([0, 1, 2, 0]), parts=[Part(0, np.array([[0, 1, 2]]))],
    ...                   materials=[Material("red", base_color=(1.0, 0.0, 0.0, 1.0))])
    >>> look.drawn(np.eye(3)).tolist()           # drawn vertex 3 sits on welded vertex 0
    [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0]]
    """

    welded: np.ndarray
    parts: list[Part]
    materials: list[Material]
    images: list[Image] = field(default_factory=list)
    normals: np.ndarray | None = None
    uvs: list[np.ndarray] = field(default_factory=list)
    colors: np.ndarray | None = None
    tangents: np.ndarray | None = None

    @property
    def n(self) -> int:
        """Number of drawn vertices."""
        return len(self.welded)

    @property
    def triangles(self) -> np.ndarray:
        """(m, 3) every drawn triangle, the parts one after the other."""
        return np.concatenate([part.triangles for part in self.parts]) if self.parts else \
            np.zeros((0, 3), dtype=np.int64)

    def drawn(self, positions: np.ndarray) -> np.ndarray:
        """Positions of the drawn vertices (…, n_d, 3) from the welded ones (…, n, 3).

        Parameters
        ----------
        positions : (…, n, 3) welded positions.

        Returns
        -------
        (…, n_d, 3).
        """
        return np.asarray(positions)[..., self.welded, :]

    def textured(self) -> bool:
        """Whether some material uses an image.

        Returns
        -------
        bool.
        """
        return any(material.textures() for material in self.materials)

    def describe(self) -> str:
        """A short phrase: '3 materials, 2 textures, 1,204 drawn vertices'.

        Returns
        -------
        str.
        """
        what = [f"{len(self.materials)} material{'s' * (len(self.materials) != 1)}"]
        if self.images:
            what.append(f"{len(self.images)} image{'s' * (len(self.images) != 1)}")
        if self.colors is not None:
            what.append("vertex colours")
        return ", ".join(what + [f"{self.n:,} drawn vertices"])

    def to_json(self) -> dict:
        """The description part 2's page reads: materials and images (size and type), the
        arrays' names and shapes (`arrays` gives them).

        Returns
        -------
        dict, ready for json.dump.
        """
        return {"materials": [m.to_json() for m in self.materials],
                "images": [{"name": i.name, "mimeType": i.mime_type, "bytes": len(i.data)}
                           for i in self.images],
                "parts": [{"material": p.material, "triangles": len(p.triangles)}
                          for p in self.parts],
                "drawn": self.n, "uvSets": len(self.uvs),
                "colors": self.colors is not None, "tangents": self.tangents is not None}

    def arrays(self) -> dict[str, np.ndarray]:
        """The per-vertex and per-part arrays by name: welded, normals, uv0, uv1, colors,
        tangents, triangles<p> (one per part).

        Returns
        -------
        {name: array}.
        """
        found = {"welded": self.welded}
        optional = {"normals": self.normals, "colors": self.colors, "tangents": self.tangents,
                    **{f"uv{index}": uv for index, uv in enumerate(self.uvs)}}
        found.update({name: value for name, value in optional.items() if value is not None})
        found.update({f"triangles{index}": part.triangles for index, part in
                      enumerate(self.parts)})
        return found

    def kept(self, keep_vertices: np.ndarray, welded: np.ndarray) -> Appearance:
        """A copy with only the drawn vertices `keep_vertices` (bool (n_d,)), renumbered, and a
        new welded map for them (`welded` (n_d,) before selection); triangles that used a
        dropped vertex are dropped, and parts left empty.

        Parameters
        ----------
        keep_vertices : (n_d,) bool.
        welded : (n_d,) int64.

        Returns
        -------
        Appearance.
        """
        renumber = np.full(self.n, -1, dtype=np.int64)
        renumber[keep_vertices] = np.arange(int(keep_vertices.sum()))
        parts = []
        for part in self.parts:
            triangles = renumber[part.triangles]
            triangles = triangles[(triangles >= 0).all(axis=1)]
            if len(triangles):
                parts.append(Part(part.material, triangles))

        def select(values):
            return None if values is None else values[keep_vertices]

        return Appearance(welded[keep_vertices], parts, self.materials, self.images,
                          select(self.normals), [uv[keep_vertices] for uv in self.uvs],
                          select(self.colors), select(self.tangents))
