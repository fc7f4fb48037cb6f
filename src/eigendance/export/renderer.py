"""Offscreen rendering of dances with the player's look (docs/design.md#exports).

OpenGL 3.3 through moderngl on an EGL context (Mesa's llvmpipe when there is no GPU), drawing
into an RGBA8 framebuffer that is read back as RGBA rows for the encoder. The look is the page's
(web/src/shaders.ts, web/src/viewer.ts), ported line for line:

- background #15171c; tile colours TILE_COLORS, converted from sRGB to linear as three.js does
  for a colour uniform, and written out unconverted, as the page's ShaderMaterial does;
- per fragment, the flat normal of the deformed triangle (screen derivatives of the view-space
  position) blended with the vertex normal by the normal-blend weight (0 for flat shading), a key
  and a fill light, a rim and a specular term; wireframe draws the edges in the flat colour;
- cameras as the page frames a mesh: looking at the centre of the bounding box from direction
  (0.55, 0.35, 1) at distance 1.15·r/sin 16° (r the largest distance of a rest vertex from the
  centre), with a vertical field of view of 35° and 0.95 of that distance in the player, 32° in a
  gallery tile; near and far planes 0.05 and 50 in units of the mesh's half size.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import moderngl
import numpy as np

from eigendance.errors import InputError, one_line

BACKGROUND = (0x15, 0x17, 0x1C)
TILE_COLORS = (0xE8A87C, 0x85CDCA, 0xD8C35B, 0xC38D9E, 0x8FB4E3, 0xA3D96B, 0xF2B5D4, 0xB8A1E6,
               0xE6C189, 0x7FD1B9, 0xF28F6B, 0x9CB4CC)
DIRECTION = np.array([0.55, 0.35, 1.0]) / np.linalg.norm([0.55, 0.35, 1.0])
PLAYER_FOV, TILE_FOV = 35.0, 32.0
GALLERY_PADDING, GALLERY_GAP = 10, 6  # pixels, as the page's tiles grid

VERTEX = """
#version 330
uniform mat4 modelView;
uniform mat4 projection;
uniform mat3 normalMatrix;
in vec3 position;
in vec3 normal;
out vec3 vViewPosition;
out vec3 vNormal;
void main() {
  vec4 mv = modelView * vec4(position, 1.0);
  vViewPosition = -mv.xyz;
  vNormal = normalize(normalMatrix * normal);
  gl_Position = projection * mv;
}
"""

# web/src/shaders.ts SURFACE_FRAGMENT without the harmonics explorer.
FRAGMENT = """
#version 330
uniform vec3 baseColor;
uniform float normalBlend;
uniform bool wire;
in vec3 vViewPosition;
in vec3 vNormal;
out vec4 fragColor;
void main() {
  vec3 color = baseColor;
  if (wire) { fragColor = vec4(color, 1.0); return; }
  vec3 flatNormal = normalize(cross(dFdx(vViewPosition), dFdy(vViewPosition)));
  vec3 smoothNormal = normalize(vNormal);
  if (dot(smoothNormal, flatNormal) < 0.0) smoothNormal = -smoothNormal;
  vec3 n = normalize(mix(flatNormal, smoothNormal, normalBlend));
  vec3 view = normalize(vViewPosition);
  vec3 key = normalize(vec3(0.5, 0.8, 0.6));
  vec3 fill = normalize(vec3(-0.7, -0.2, 0.4));
  float diffuse = max(dot(n, key), 0.0) * 0.75 + max(dot(n, fill), 0.0) * 0.25;
  // pow(x, 3) and pow(x, 40) by multiplication: the same numbers, cheaper on a software GPU.
  float edge = 1.0 - max(dot(n, view), 0.0);
  float rim = edge * edge * edge * 0.25;
  float h = max(dot(n, normalize(key + view)), 0.0);
  float h5 = h * h * h * h * h, h10 = h5 * h5, h20 = h10 * h10;
  float spec = h20 * h20 * 0.25;
  fragColor = vec4(color * (0.22 + diffuse) + vec3(spec + rim), 1.0);
}
"""


@dataclass
class Look:
    """How a surface is shaded: shading "smooth" | "flat" | "wireframe", the weight of the
    vertex normal against the deformed triangle's flat normal, and the tile colour's index."""

    shading: str = "smooth"
    normal_blend: float = 0.4
    color_index: int = 0

    @property
    def color(self) -> np.ndarray:
        """The colour uniform: TILE_COLORS[index] from sRGB to linear (three.js Color)."""
        value = TILE_COLORS[self.color_index % len(TILE_COLORS)]
        srgb = np.array([(value >> 16) & 255, (value >> 8) & 255, value & 255]) / 255
        return np.where(srgb <= 0.04045, srgb / 12.92, ((srgb + 0.055) / 1.055) ** 2.4)


@dataclass
class Camera:
    """A perspective camera: view (4, 4) world → view and projection (4, 4), OpenGL style."""

    view: np.ndarray
    projection: np.ndarray

    @classmethod
    def framing(cls, center, radius: float, scale: float, aspect: float,
                player: bool = True) -> Camera:
        """The page's camera for a mesh: centre, largest distance r of a vertex from it and
        half size `scale`; the player's (35°, 0.95 of the distance) or a tile's (32°)."""
        fov = PLAYER_FOV if player else TILE_FOV
        distance = radius * 1.15 / math.sin(math.radians(16)) * (0.95 if player else 1.0)
        eye = np.asarray(center, dtype=np.float64) + DIRECTION * distance
        z = DIRECTION
        x = np.cross([0.0, 1.0, 0.0], z)
        x /= np.linalg.norm(x)
        y = np.cross(z, x)
        view = np.eye(4)
        view[:3, :3] = np.stack([x, y, z])
        view[:3, 3] = -view[:3, :3] @ eye
        near, far = 0.05 * scale, 50 * scale
        top = 1 / math.tan(math.radians(fov) / 2)
        projection = np.array([[top / aspect, 0, 0, 0], [0, top, 0, 0],
                               [0, 0, (far + near) / (near - far), 2 * far * near / (near - far)],
                               [0, 0, -1, 0]])
        return cls(view, projection)


def gallery_cells(count: int, width: int, height: int) -> list[tuple[int, int, int, int]]:
    """Viewports (x, y from the bottom, w, h) of `count` tiles in the page's grid: ⌈√(1.5·S)⌉
    columns, rows as needed, row-major from the top left."""
    columns = math.ceil(math.sqrt(count * 1.5))
    rows = math.ceil(count / columns)
    cell_w = (width - 2 * GALLERY_PADDING - (columns - 1) * GALLERY_GAP) / columns
    cell_h = (height - 2 * GALLERY_PADDING - (rows - 1) * GALLERY_GAP) / rows
    if cell_w < 8 or cell_h < 8:
        raise InputError(f"{width}×{height} pixels is too small for a gallery of {count} tiles")
    cells = []
    for index in range(count):
        row, column = divmod(index, columns)
        left = round(GALLERY_PADDING + column * (cell_w + GALLERY_GAP))
        top = round(GALLERY_PADDING + row * (cell_h + GALLERY_GAP))
        right = round(GALLERY_PADDING + column * (cell_w + GALLERY_GAP) + cell_w)
        bottom = round(GALLERY_PADDING + row * (cell_h + GALLERY_GAP) + cell_h)
        cells.append((left, height - bottom, right - left, bottom - top))
    return cells


_started = {"gl": False}  # set once this process has started OpenGL


def gl_started() -> bool:
    """Whether this process has created an OpenGL context. llvmpipe keeps its threads in a
    process-wide screen: a process forked after that inherits the state without the threads and
    hangs at its first draw, so only a process that never drew may fork renderers."""
    return _started["gl"]


def create_context() -> moderngl.Context:
    """A headless OpenGL 3.3 context (EGL; Mesa's llvmpipe without a GPU)."""
    _started["gl"] = True
    try:
        return moderngl.create_standalone_context(backend="egl", libgl="libGL.so.1",
                                                  libegl="libEGL.so.1")
    except Exception as error:  # noqa: BLE001 - moderngl raises plain Exceptions
        raise InputError("rendering needs offscreen OpenGL through EGL, which failed here "
                         f"({one_line(error)}); on Debian: apt-get install libegl1 libgl1 "
                         "libegl-mesa0 libgl1-mesa-dri") from None


class Renderer:
    """Draws meshes into an offscreen frame of `width`×`height` pixels and reads it back.

    Parameters
    ----------
    width, height : the frame's size in pixels.
    faces : (m, 3) triangles of the mesh every draw uses.
    normals : (n, 3) its vertex normals (replaced per draw when a dance turns them).
    """

    def __init__(self, width: int, height: int, faces: np.ndarray, normals: np.ndarray):
        self.width, self.height = int(width), int(height)
        self.context = context = create_context()
        self.framebuffer = context.framebuffer(
            color_attachments=[context.renderbuffer((self.width, self.height))],
            depth_attachment=context.depth_renderbuffer((self.width, self.height)))
        self.program = context.program(vertex_shader=VERTEX, fragment_shader=FRAGMENT)
        self.n = len(normals)
        self.positions = context.buffer(reserve=self.n * 12, dynamic=True)
        self.rest_normals = np.ascontiguousarray(normals, dtype=np.float32)
        self.normals = context.buffer(self.rest_normals.tobytes(), dynamic=True)
        self.indices = context.buffer(np.ascontiguousarray(faces, dtype=np.uint32).tobytes())
        self.vertex_array = context.vertex_array(
            self.program, [(self.positions, "3f", "position"), (self.normals, "3f", "normal")],
            self.indices)
        self.turned = False
        self.framebuffer.use()

    def clear(self) -> None:
        self.framebuffer.use()
        self.context.scissor = None
        self.framebuffer.clear(*(c / 255 for c in BACKGROUND), 1.0, depth=1.0)
        self.context.enable(moderngl.DEPTH_TEST)

    def draw(self, positions: np.ndarray, camera: Camera, look: Look,
             viewport: tuple[int, int, int, int] | None = None,
             normals: np.ndarray | None = None) -> None:
        """Draw the mesh at `positions` (n, 3) into `viewport` (default: the whole frame)."""
        viewport = viewport or (0, 0, self.width, self.height)
        self.framebuffer.viewport = viewport
        self.context.scissor = viewport
        self.positions.write(np.ascontiguousarray(positions, dtype=np.float32))
        if normals is not None:
            self.normals.write(np.ascontiguousarray(normals, dtype=np.float32))
            self.turned = True
        elif self.turned:
            self.normals.write(self.rest_normals)
            self.turned = False
        normal_matrix = np.linalg.inv(camera.view[:3, :3]).T
        program = self.program
        program["modelView"].write(camera.view.T.astype(np.float32).tobytes())
        program["projection"].write(camera.projection.T.astype(np.float32).tobytes())
        program["normalMatrix"].write(normal_matrix.T.astype(np.float32).tobytes())
        program["baseColor"].value = tuple(float(c) for c in look.color)
        program["normalBlend"].value = 0.0 if look.shading == "flat" else float(look.normal_blend)
        program["wire"].value = look.shading == "wireframe"
        self.context.wireframe = look.shading == "wireframe"
        self.vertex_array.render(moderngl.TRIANGLES)

    def read(self) -> bytes:
        """The frame as RGBA rows from the bottom up (OpenGL's order), 4·width·height bytes
        (RGBA, the framebuffer's own layout, reads back faster than RGB: 5 against 8 ms at
        1280×720 on llvmpipe)."""
        return self.framebuffer.read(components=4, alignment=1)

    def image(self) -> np.ndarray:
        """The frame as an (height, width, 3) uint8 RGB array, top row first."""
        frame = np.frombuffer(self.read(), np.uint8).reshape(self.height, self.width, 4)
        return frame[::-1, :, :3]

    def release(self) -> None:
        self.context.release()
