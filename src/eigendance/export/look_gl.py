"""A model's materials in the video's renderer (docs/design.md#rendering): the drawn vertices,
one draw per material, the images as textures.

Each material is drawn by the shared surface shader (`eigendance.shaders`, the page's own GLSL)
with the defines, uniforms and textures `shaders.material_shading` gives it. Drawn vertex i sits
at its welded vertex's position (`Appearance.welded`), so the positions of a frame are gathered
from the welded ones; its normal is its rest normal, or, when the dance turns normals (a rig),
its rest normal turned by the rotation that turns its welded vertex's normal (hard edges stay
hard). Order as three.js draws one mesh: the opaque and masked parts, then (after the contact
shadow) the blended parts without writing depth.
"""

from __future__ import annotations

import ctypes
import io

import moderngl
import numpy as np

from eigendance.errors import InputError
from eigendance.shaders.programs import material_shading, program

GL_SRGB8_ALPHA8 = 0x8C43
GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T = 0x0DE1, 0x2802, 0x2803
CLAMP_TO_EDGE, MIRRORED_REPEAT = 33071, 33648
MIPMAPPED = (9984, 9985, 9986, 9987)  # the *_MIPMAP_* minification filters


def turned_normals(drawn: np.ndarray, rest: np.ndarray, turned: np.ndarray) -> np.ndarray:
    """Drawn normals turned by the smallest rotation taking each `rest` normal to its `turned`
    one (Rodrigues: v·c + k × v + k·(k·v)/(1 + c), k = a × b, c = a·b).

    Parameters
    ----------
    drawn : (n_d, 3) unit rest normals of the drawn vertices.
    rest, turned : (n_d, 3) unit normals of their welded vertices at rest and now.

    Returns
    -------
    (n_d, 3) float32.

    Example
    -------
    >>> up, side = np.array([[0.0, 1.0, 0.0]]), np.array([[1.0, 0.0, 0.0]])
    >>> turned_normals(np.array([[0.0, 0.0, 1.0]]), up, side).round(6).tolist()  # about z
    [[0.0, 0.0, 1.0]]
    >>> turned_normals(up, up, side).round(6).tolist()
    [[1.0, 0.0, 0.0]]
    """
    k = np.cross(rest, turned)
    c = np.einsum("ij,ij->i", rest, turned)[:, None]
    out = drawn * c + np.cross(k, drawn) + k * (np.einsum("ij,ij->i", k, drawn)[:, None]
                                               / np.maximum(1.0 + c, 1e-6))
    opposite = (1.0 + c[:, 0]) < 1e-6  # turned half a turn: no unique rotation; take it
    out[opposite] = turned[opposite]
    return out.astype(np.float32)


class MaterialLook:
    """The GPU side of an `assets.Appearance` for one OpenGL context.

    Parameters
    ----------
    context : the renderer's moderngl context.
    appearance : the model's look (drawn vertices, parts, materials, images).
    rest_normals : (n, 3) the welded vertices' rest normals (for turning drawn normals).
    """

    def __init__(self, context: moderngl.Context, appearance, rest_normals: np.ndarray):
        self.context = context
        self.appearance = look = appearance
        self.welded = np.asarray(look.welded, dtype=np.int64)
        self.rest_welded = np.asarray(rest_normals, dtype=np.float64)[self.welded]
        self.rest_drawn = np.asarray(look.normals, dtype=np.float64) if look.normals is not None \
            else self.rest_welded
        n = look.n
        self.positions = context.buffer(reserve=n * 12, dynamic=True)
        self.normals = context.buffer(self.rest_drawn.astype(np.float32).tobytes(), dynamic=True)
        self.turned = False
        uvs = look.uvs or [np.zeros((n, 2))]
        attributes = {"displaced": (self.positions, "3f"), "normal": (self.normals, "3f"),
                      "texcoord0": (self._buffer(uvs[0]), "2f")}
        if len(uvs) > 1:
            attributes["texcoord1"] = (self._buffer(uvs[1]), "2f")
        if look.colors is not None:
            attributes["vertexColor"] = (self._buffer(look.colors), "4f")
        self.textures: dict = {}
        self.programs: dict = {}
        self.parts = [self._part(part, attributes) for part in look.parts if len(part.triangles)]

    def _buffer(self, values: np.ndarray):
        return self.context.buffer(np.ascontiguousarray(values, dtype=np.float32).tobytes())

    def _part(self, part, attributes) -> dict:
        """One material's draw: its program, vertex array, uniforms and textures."""
        look = self.appearance
        shading = material_shading(look.materials[part.material], len(look.uvs),
                                   look.colors is not None)
        defines = {"CPU_PATH": 1, **shading["defines"]}
        key = tuple(sorted((name, str(value)) for name, value in defines.items()))
        if key not in self.programs:
            self.programs[key] = self.context.program(
                vertex_shader=program("surface.vert", defines),
                fragment_shader=program("surface.frag", defines))
        shader = self.programs[key]
        members = set(shader._members)
        content = [(buffer, layout, name) for name, (buffer, layout) in attributes.items()
                   if name in members]
        indices = self.context.buffer(np.ascontiguousarray(part.triangles, dtype=np.uint32))
        textures = [(name, self._texture(**info)) for name, info in shading["textures"].items()
                    if name in members]
        return {"program": shader, "members": members, "shading": shading, "textures": textures,
                "array": self.context.vertex_array(shader, content, indices)}

    def _texture(self, image: int, srgb: bool, sampler: dict) -> moderngl.Texture:
        """The texture of image `image` (decoded once per colour space and sampler)."""
        key = (image, srgb, tuple(sorted(sampler.items())))
        if key in self.textures:
            return self.textures[key]
        pixels = decoded(self.appearance.images[image].data,
                         self.context.info["GL_MAX_TEXTURE_SIZE"])
        height, width = pixels.shape[:2]
        texture = self.context.texture((width, height), 4, pixels.tobytes(),
                                       internal_format=GL_SRGB8_ALPHA8 if srgb else None)
        mipmapped = sampler["minFilter"] in MIPMAPPED
        if mipmapped:
            texture.build_mipmaps()
        texture.filter = (sampler["minFilter"] if mipmapped or sampler["minFilter"] in
                          (moderngl.NEAREST, moderngl.LINEAR) else moderngl.LINEAR,
                          sampler["magFilter"])
        texture.repeat_x = sampler["wrapS"] != CLAMP_TO_EDGE
        texture.repeat_y = sampler["wrapT"] != CLAMP_TO_EDGE
        if MIRRORED_REPEAT in (sampler["wrapS"], sampler["wrapT"]):
            _mirror(texture, sampler["wrapS"] == MIRRORED_REPEAT,
                    sampler["wrapT"] == MIRRORED_REPEAT)
        self.textures[key] = texture
        return texture

    def update(self, positions: np.ndarray, normals: np.ndarray | None) -> None:
        """Move the drawn vertices to their welded vertices' positions.

        Parameters
        ----------
        positions : (n, 3) the welded vertices.
        normals : (n, 3) the welded vertices' turned normals, or None (the rest normals hold).
        """
        self.positions.write(np.ascontiguousarray(positions[self.welded], dtype=np.float32))
        if normals is not None:
            now = np.asarray(normals, dtype=np.float64)[self.welded]
            now /= np.maximum(np.linalg.norm(now, axis=1, keepdims=True), 1e-12)
            self.normals.write(turned_normals(self.rest_drawn, self.rest_welded, now).tobytes())
            self.turned = True
        elif self.turned:
            self.normals.write(self.rest_drawn.astype(np.float32).tobytes())
            self.turned = False

    def draw(self, matrices: dict, normal_weight: float, blended: bool) -> None:
        """Draw the opaque and masked parts (`blended` False) or the blended ones (True).

        Parameters
        ----------
        matrices : {"modelViewMatrix", "projectionMatrix", "normalMatrix"}: column-major bytes.
        normal_weight : the flat normal's weight (thesis Fig. 6.4(d)).
        blended : which parts.
        """
        context = self.context
        for part in self.parts:
            shading = part["shading"]
            if shading["blend"] != blended:
                continue
            shader = part["program"]
            for name, value in matrices.items():
                shader[name].write(value)
            values = {"deformedNormalWeight": normal_weight, **shading["uniforms"]}
            for name, value in values.items():
                if name in part["members"]:
                    _set(shader[name], value)
            for unit, (name, texture) in enumerate(part["textures"]):
                texture.use(unit)
                shader[name].value = unit
            if shading["doubleSided"]:
                context.disable(moderngl.CULL_FACE)
            else:
                context.enable(moderngl.CULL_FACE)
            if blended:
                context.enable(moderngl.BLEND)
                context.blend_func = (moderngl.SRC_ALPHA, moderngl.ONE_MINUS_SRC_ALPHA,
                                      moderngl.ONE, moderngl.ONE_MINUS_SRC_ALPHA)
                context.depth_mask = False
            part["array"].render(moderngl.TRIANGLES)
        context.disable(moderngl.CULL_FACE)
        if blended:
            context.disable(moderngl.BLEND)
            context.depth_mask = True

    @property
    def has_blended(self) -> bool:
        """Whether some part is drawn blended (alpha mode BLEND)."""
        return any(part["shading"]["blend"] for part in self.parts)


def decoded(data: bytes, largest: int) -> np.ndarray:
    """An image's pixels, top row first (glTF's UV origin), at most `largest` pixels on a side
    (as three.js resizes what the GPU cannot hold).

    Parameters
    ----------
    data : PNG or JPEG bytes.
    largest : the GPU's largest texture side.

    Returns
    -------
    (height, width, 4) uint8 RGBA; InputError for an image that cannot be decoded.
    """
    from PIL import Image as PillowImage  # imported when a textured model is drawn

    try:
        with PillowImage.open(io.BytesIO(data)) as image:
            image = image.convert("RGBA")
            if max(image.size) > largest:
                factor = largest / max(image.size)
                image = image.resize((max(1, int(image.width * factor)),
                                      max(1, int(image.height * factor))))
            return np.asarray(image, dtype=np.uint8)
    except Exception as error:  # noqa: BLE001 - Pillow's many kinds; the reader checked it
        raise InputError(f"a texture image cannot be decoded ({type(error).__name__})") from None


def _set(uniform, value) -> None:
    """A uniform from a number or a list (9 numbers: a column-major mat3)."""
    if isinstance(value, list):
        uniform.write(np.asarray(value, dtype=np.float32).tobytes())
    else:
        uniform.value = value


def _mirror(texture: moderngl.Texture, s: bool, t: bool) -> None:
    """MIRRORED_REPEAT wrapping, which moderngl does not name: set on the texture through GL."""
    try:
        gl = ctypes.CDLL("libGL.so.1")
    except OSError:
        return  # repeat instead: the nearest moderngl offers
    texture.use(0)
    for wrap, mirrored in ((GL_TEXTURE_WRAP_S, s), (GL_TEXTURE_WRAP_T, t)):
        if mirrored:
            gl.glTexParameteri(GL_TEXTURE_2D, wrap, MIRRORED_REPEAT)
