"""glTF 2.0 binary (.glb) of a dance (docs/design.md#exports), written with pygltflib.

- The model keeps its look: with an `Appearance`, the drawn vertices (each at its welded
  vertex, with the file's normals, UVs, colours and tangents), one primitive per material, the
  materials and the images embedded (`gltf_look`); without, the clay colour.
- A `HarmonicDance` becomes morph targets, one per driven harmonic ν, written so that importers
  which clamp weights to [0, 1] (Blender) play them exactly (`blender_safe`): with the animated
  weights w_ν(t_i) = φ_ν(t_i) − 1 in [lo_ν, hi_ν] (lo = min(0, min w), hi = max(0, max w)), the
  base positions are rest + Σ lo_ν D_ν, target ν is (hi_ν − lo_ν)·D_ν and its weights
  (w_ν − lo_ν)/(hi_ν − lo_ν) ∈ [0, 1] (LINEAR), the mesh's initial weights −lo_ν/(hi_ν − lo_ν)
  (the file at rest shows the rest shape). At every sample base + Σ weight·target = rest +
  Σ w_ν D_ν = X_φ(t_i) exactly (up to float32), since X_φ is linear in φ.
- A `HarmonicDance` of a reduced basis (docs/design.md#reduced-basis) becomes a skin whose joints
  are the samples: joint j at the sample's rest position c_j (inverse bind matrix: translation
  by −c_j), one translation channel c_j + D_j(t_i) each, and every vertex's 8 samples and weights
  as JOINTS_0/1, WEIGHTS_0/1: the joint matrix is a translation by D_j(t), so a viewer plays
  rest + Σ_j w_ij D_j(t) — the reduced dance, with the weights as normalised unsigned shorts
  (whole numbers of 1/65535 summing to exactly 65535 by largest remainders: each within
  1/65535 of P's, so a vertex is within 8/65535 of its largest joint displacement). Its size
  is m·T translations instead of d·n displacements; the translations are computed joint by
  joint as the file is written.
- A `RigDance` with a surface (docs/design.md#surface-of-a-rig) also gets the harmonics' morph
  targets, written as above in the same animation: glTF applies morph targets before the skin,
  so a viewer plays Σ_b w_ib T_b (x + d) — the ripple in the bind pose, skinned.
- A `RigDance` becomes a skin: one joint node per body, bound in the body's rest frame B_b
  (inverse bind matrix B_b⁻¹), animated by translation and rotation channels so that its world
  transform is T_b(t_i)·B_b; a viewer's joint matrix T_b·B_b·B_b⁻¹ = T_b then plays linear blend
  skinning Σ_b w_ib T_b x exactly at every sample (with as many JOINTS_j/WEIGHTS_j sets of four as
  the most-influenced vertex needs).

The song's file name, the sample rate and what moved are in the root `extras.eigendance`.
"""

from __future__ import annotations

import io
import math
import struct

import numpy as np
import pygltflib
from scipy.spatial.transform import Rotation

from eigendance.assets.appearance import srgb_to_linear
from eigendance.errors import InputError
from eigendance.export.dance import Dance, HarmonicDance
from eigendance.export.gltf_look import drawn_attributes, write_look
from eigendance.export.rig_dance import RigDance
from eigendance.harmonic.interpolation import shares

# The models' clay colour on the page (web/src/deform.ts CLAY), as sRGB bytes.
BASE_COLOR = (0xD9, 0xA4, 0x7F)
WEIGHT_EPSILON = 1e-7  # skin weights below this are dropped (then the row is renormalised)
# A reduced basis's weights are normalised unsigned shorts: whole numbers of 1/65535 summing to
# exactly 65535 per vertex (core glTF 2.0), so Σ_j w_j = 1 holds exactly in every viewer.
WEIGHT_UNITS = 65535


class _Builder:
    """Accumulates arrays into one binary buffer (4-byte aligned views) and their accessors."""

    TYPES = {1: "SCALAR", 2: "VEC2", 3: "VEC3", 4: "VEC4", 16: "MAT4"}
    COMPONENTS = {np.dtype("<f4"): pygltflib.FLOAT, np.dtype("<u4"): pygltflib.UNSIGNED_INT,
                  np.dtype("<u2"): pygltflib.UNSIGNED_SHORT,
                  np.dtype("u1"): pygltflib.UNSIGNED_BYTE}

    def __init__(self, gltf: pygltflib.GLTF2):
        self.gltf = gltf
        self.chunks: list = []  # bytes, or callables making them as the file is written
        self.length = 0

    def streamed(self, count: int, width: int, dtype: str, produce) -> int:
        """An accessor of `count` elements whose bytes `produce()` makes only when the file is
        written (long animations are never held in memory)."""
        dtype = np.dtype(dtype)
        length = count * width * dtype.itemsize
        self.gltf.bufferViews.append(pygltflib.BufferView(buffer=0, byteOffset=self.length,
                                                          byteLength=length))
        self.chunks.append(produce)
        self.length += length
        padding = -self.length % 4
        self.chunks.append(b"\0" * padding)
        self.length += padding
        self.gltf.accessors.append(pygltflib.Accessor(
            bufferView=len(self.gltf.bufferViews) - 1, byteOffset=0,
            componentType=self.COMPONENTS[dtype], count=count, type=self.TYPES[width]))
        return len(self.gltf.accessors) - 1

    def accessor(self, array: np.ndarray, width: int, target: int | None = None,
                 bounds: bool = False, normalized: bool = False) -> int:
        """An accessor (and its own buffer view) for `array`, `width` components per element.

        bounds: store min/max (required for POSITION and animation inputs); normalized:
        integers read as fractions of their type's largest value (WEIGHTS as unsigned short)."""
        array = np.ascontiguousarray(array)
        data = array.tobytes()
        view = pygltflib.BufferView(buffer=0, byteOffset=self.length, byteLength=len(data),
                                    target=target)
        self.chunks.append(data)
        self.length += len(data)
        padding = -self.length % 4
        self.chunks.append(b"\0" * padding)
        self.length += padding
        self.gltf.bufferViews.append(view)
        elements = array.reshape(-1, width)
        accessor = pygltflib.Accessor(bufferView=len(self.gltf.bufferViews) - 1, byteOffset=0,
                                      componentType=self.COMPONENTS[array.dtype],
                                      normalized=normalized, count=len(elements),
                                      type=self.TYPES[width])
        if bounds:
            accessor.min = [float(x) for x in elements.min(axis=0)]
            accessor.max = [float(x) for x in elements.max(axis=0)]
        self.gltf.accessors.append(accessor)
        return len(self.gltf.accessors) - 1

    def view(self, data: bytes) -> int:
        """A buffer view (no target) holding `data`, e.g. an embedded image."""
        self.gltf.bufferViews.append(pygltflib.BufferView(buffer=0, byteOffset=self.length,
                                                          byteLength=len(data)))
        padding = -len(data) % 4
        self.chunks.extend([data, b"\0" * padding])
        self.length += len(data) + padding
        return len(self.gltf.bufferViews) - 1

    def write(self, file) -> int:
        """Write the GLB container (header, JSON chunk, binary chunk) to an open binary file,
        making the streamed accessors' bytes one at a time; returns the bytes written."""
        self.gltf.buffers = [pygltflib.Buffer(byteLength=self.length)]
        text = self.gltf.gltf_to_json(separators=(",", ":"), indent=None).encode("utf-8")
        text += b" " * (-len(text) % 4)
        total = 12 + 8 + len(text) + 8 + self.length
        file.write(b"glTF" + struct.pack("<II", 2, total))
        file.write(struct.pack("<I", len(text)) + b"JSON" + text)
        file.write(struct.pack("<I", self.length) + b"BIN\0")
        for chunk in self.chunks:
            data = chunk() if callable(chunk) else chunk
            file.write(data if isinstance(data, bytes) else memoryview(data).cast("B"))
        return total


def glb_bytes(dance: Dance, times, extras: dict) -> bytes:
    """The .glb of `dance` sampled at `times` (s) as bytes (`write_glb` streams it to a file).

    Parameters
    ----------
    dance, times, extras : as for `write_glb`.

    Returns
    -------
    bytes.
    """
    buffer = io.BytesIO()
    write_glb(buffer, dance, times, extras)
    return buffer.getvalue()


def write_glb(file, dance: Dance, times, extras: dict) -> int:
    """Write the .glb of `dance` sampled at `times` (s), with `extras` under extras.eigendance.

    Parameters
    ----------
    file : a binary file open for writing.
    dance : a `HarmonicDance` (morph targets; a skin on its samples for a reduced basis) or a
        `RigDance` (skin).
    times : (T,) sample times, ascending.
    extras : JSON-ready facts stored in the file (the song's name, fps, …).

    Returns
    -------
    The bytes written.
    """
    times = np.asarray(times, dtype=np.float64)
    gltf = pygltflib.GLTF2(asset=pygltflib.Asset(version="2.0", generator="eigendance"))
    gltf.extras = {"eigendance": extras}
    builder = _Builder(gltf)
    look = getattr(dance, "appearance", None)
    welded = look.welded if look is not None else np.arange(dance.n)
    attributes = pygltflib.Attributes()
    parts = _surface(dance, look, builder, attributes)
    mesh = pygltflib.Mesh(name=dance.name, primitives=[
        pygltflib.Primitive(attributes=attributes, material=material, mode=pygltflib.TRIANGLES,
                            indices=builder.accessor(triangles.astype(index_type).ravel(), 1,
                                                     pygltflib.ELEMENT_ARRAY_BUFFER))
        for material, triangles, index_type in parts])
    gltf.meshes.append(mesh)
    gltf.nodes.append(pygltflib.Node(name=dance.name, mesh=0))
    gltf.scenes.append(pygltflib.Scene(name=dance.name, nodes=[0]))
    gltf.scene = 0
    sample_input = builder.accessor(times.astype("<f4"), 1, bounds=True)
    base = dance.rest[welded]
    if isinstance(dance, HarmonicDance) and dance.basis.reduced is not None:
        _sample_skin(dance, times, builder, attributes, welded, sample_input)
    elif isinstance(dance, HarmonicDance):
        base = _morph_targets(dance.morphs(times), dance.rest, builder, mesh, welded,
                              sample_input)
    elif isinstance(dance, RigDance):
        _skin(dance, times, builder, attributes, welded, sample_input)
        if dance.surface is not None:  # the ripple: morph targets, applied before the skin
            base = _morph_targets(dance.morphs(times), dance.rest, builder, mesh, welded,
                                  sample_input)
    else:
        raise TypeError(f"cannot write {type(dance).__name__} as glTF")
    attributes.POSITION = builder.accessor(base.astype("<f4"), 3, pygltflib.ARRAY_BUFFER, True)
    return builder.write(file)


def _surface(dance: Dance, look, builder, attributes) -> list[tuple]:
    """Materials and the drawn attributes but POSITION; (material, triangles, index type) of
    each primitive: one per material of the look, or one in clay."""
    if look is None:
        color = [*(float(c) for c in srgb_to_linear(np.array(BASE_COLOR) / 255)), 1.0]
        builder.gltf.materials.append(pygltflib.Material(
            name="eigendance", doubleSided=True,
            pbrMetallicRoughness=pygltflib.PbrMetallicRoughness(
                baseColorFactor=color, metallicFactor=0.0, roughnessFactor=0.6)))
        attributes.NORMAL = builder.accessor(dance.rest_normals().astype("<f4"), 3,
                                             pygltflib.ARRAY_BUFFER)
        return [(0, dance.faces, "<u2" if dance.n <= 65535 else "<u4")]
    materials = write_look(look, builder)
    drawn_attributes(look, builder, attributes)
    index_type = "<u2" if look.n <= 65535 else "<u4"
    return [(materials[part.material], part.triangles, index_type) for part in look.parts]


def blender_safe(weights: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per target the range [lo, hi] its weights (T, J) are rescaled from: lo = min(0, min w),
    hi = max(0, max w) (hi = lo + 1 for a target whose weights are all 0); returns (lo, hi).

    Parameters
    ----------
    weights : (T, J).

    Returns
    -------
    (lo (J,), hi (J,)).

    Example
    -------
    >>> lo, hi = blender_safe(np.array([[-2.0, 0.5], [3.0, 0.25]]))
    >>> lo.tolist(), hi.tolist()
    ([-2.0, 0.0], [3.0, 0.5])
    """
    lo = np.minimum(0.0, weights.min(axis=0, initial=0.0))
    hi = np.maximum(0.0, weights.max(axis=0, initial=0.0))
    return lo, np.where(hi > lo, hi, lo + 1.0)


def _morph_targets(morphs, rest, builder, mesh, welded, sample_input):
    """The targets of `morphs` (`export.dance.Morphs`) on `rest` (n, 3) and their animation
    (see the module docstring), in the file's last animation when it has one (a rig's skin);
    returns the base positions (n_d, 3)."""
    lo, hi = blender_safe(morphs.weights)
    span = hi - lo
    base = rest + np.einsum("j,jnd->nd", lo, morphs.targets)
    for target, scale in zip(morphs.targets, span, strict=True):
        accessor = builder.accessor((scale * target[welded]).astype("<f4"), 3,
                                    pygltflib.ARRAY_BUFFER, bounds=True)
        for primitive in mesh.primitives:
            primitive.targets.append(pygltflib.Attributes(POSITION=accessor))
    if len(morphs.harmonics) == 0:
        return base[welded]  # a still mapping: no target, nothing to animate
    mesh.weights = [float(w) for w in -lo / span]
    mesh.extras = {"targetNames": [f"harmonic {int(nu)}" for nu in morphs.harmonics]}
    weights = np.clip((morphs.weights - lo) / span, 0.0, 1.0)
    output = builder.accessor(weights.astype("<f4").ravel(), 1)
    if not builder.gltf.animations:
        builder.gltf.animations.append(pygltflib.Animation(name="dance"))
    animation = builder.gltf.animations[-1]
    animation.channels.append(pygltflib.AnimationChannel(
        sampler=len(animation.samplers),
        target=pygltflib.AnimationChannelTarget(node=0, path="weights")))
    animation.samplers.append(pygltflib.AnimationSampler(
        input=sample_input, output=output, interpolation=pygltflib.ANIM_LINEAR))
    return base[welded]


def _skin(dance: RigDance, times, builder, attributes, welded, sample_input):
    gltf = builder.gltf
    count = len(dance.body_names)
    first_joint = len(gltf.nodes) + 1
    joints = list(range(first_joint, first_joint + count))
    gltf.nodes.append(pygltflib.Node(name="skeleton", children=joints))
    gltf.scenes[0].nodes.append(first_joint - 1)
    rest = dance.rest_frames
    for name, frame in zip(dance.body_names, rest, strict=True):
        rotation, translation = _rotation_translation(frame[None, :3, :3], frame[None, :3, 3])
        gltf.nodes.append(pygltflib.Node(name=name, rotation=rotation[0].tolist(),
                                         translation=translation[0].tolist()))
    inverse = np.linalg.inv(rest).transpose(0, 2, 1)  # column-major, as glTF stores matrices
    gltf.skins.append(pygltflib.Skin(name=dance.name, joints=joints, skeleton=first_joint - 1,
                                     inverseBindMatrices=builder.accessor(
                                         inverse.astype("<f4").reshape(-1, 16), 16)))
    gltf.nodes[0].skin = 0
    indices, weights = _influences(dance.weights[welded])
    joint_type = "u1" if count <= 256 else "<u2"
    for set_index in range(indices.shape[1] // 4):
        columns = slice(4 * set_index, 4 * set_index + 4)
        setattr(attributes, f"JOINTS_{set_index}", builder.accessor(
            indices[:, columns].astype(joint_type), 4, pygltflib.ARRAY_BUFFER))
        setattr(attributes, f"WEIGHTS_{set_index}", builder.accessor(
            weights[:, columns].astype("<f4"), 4, pygltflib.ARRAY_BUFFER))
    transforms, _ = dance.pose(times)
    world = transforms @ rest[None]  # T_b(t)·B_b: each joint's world transform
    rotations, translations = _rotation_translation(world[..., :3, :3], world[..., :3, 3])
    samplers, channels = [], []
    for body in range(count):
        for path, values, width in (("translation", translations, 3), ("rotation", rotations, 4)):
            output = builder.accessor(values[:, body].astype("<f4"), width)
            channels.append(pygltflib.AnimationChannel(
                sampler=len(samplers),
                target=pygltflib.AnimationChannelTarget(node=joints[body], path=path)))
            samplers.append(pygltflib.AnimationSampler(input=sample_input, output=output,
                                                       interpolation=pygltflib.ANIM_LINEAR))
    gltf.animations.append(pygltflib.Animation(name="dance", samplers=samplers,
                                               channels=channels))


def _sample_skin(dance: HarmonicDance, times, builder, attributes, welded, sample_input):
    """The reduced dance as a skin on its samples (module docstring)."""
    skin = dance.sample_skin(times)
    gltf = builder.gltf
    count = len(skin.joints)
    if count > 1 << 16:
        raise InputError(f"{dance.name}: a glTF skin has at most 65536 joints; this reduced "
                         f"basis has {count} samples", remedy={"samples": 1 << 16})
    first_joint = len(gltf.nodes) + 1
    joints = list(range(first_joint, first_joint + count))
    gltf.nodes.append(pygltflib.Node(name="samples", children=joints))
    gltf.scenes[0].nodes.append(first_joint - 1)
    for index, position in enumerate(skin.joints):
        gltf.nodes.append(pygltflib.Node(name=f"sample {index}",
                                         translation=[float(x) for x in position]))
    inverse = np.tile(np.eye(4), (count, 1, 1))
    inverse[:, :3, 3] = -skin.joints  # translation by −c_j, stored column-major below
    gltf.skins.append(pygltflib.Skin(name=dance.name, joints=joints, skeleton=first_joint - 1,
                                     inverseBindMatrices=builder.accessor(
                                         inverse.transpose(0, 2, 1).astype("<f4")
                                         .reshape(-1, 16), 16)))
    gltf.nodes[0].skin = 0
    weights = shares(skin.weights[welded], WEIGHT_UNITS).astype("<u2")
    for set_index in range(skin.indices.shape[1] // 4):
        columns = slice(4 * set_index, 4 * set_index + 4)
        setattr(attributes, f"JOINTS_{set_index}", builder.accessor(
            skin.indices[welded, columns].astype("<u2"), 4, pygltflib.ARRAY_BUFFER))
        setattr(attributes, f"WEIGHTS_{set_index}", builder.accessor(
            weights[:, columns], 4, pygltflib.ARRAY_BUFFER, normalized=True))
    samplers, channels = [], []
    frames = len(skin.amplitudes)
    for joint in range(count):
        output = builder.streamed(frames, 3, "<f4",
                                  lambda joint=joint: skin.translations(joint))
        channels.append(pygltflib.AnimationChannel(
            sampler=joint, target=pygltflib.AnimationChannelTarget(node=joints[joint],
                                                                  path="translation")))
        samplers.append(pygltflib.AnimationSampler(input=sample_input, output=output,
                                                   interpolation=pygltflib.ANIM_LINEAR))
    gltf.animations.append(pygltflib.Animation(name="dance", samplers=samplers,
                                               channels=channels))


def glb_size(dance: Dance, frames: int) -> dict[str, int]:
    """Bytes of the binary chunk of a harmonic dance's glb without a look, as written (`skin` of
    a reduced basis, else `morph targets`) and of the other form, for `frames` samples:
    positions, normals, faces (4-byte aligned) and sample times, plus per driven harmonic n
    displacements and T weights (morph targets) or per vertex 8 joints and 8 weights (unsigned
    shorts) and per sample an inverse bind matrix and T translations (skin). The JSON chunk is
    not counted (≈ 0.37 kB per joint of a skin; a look's attributes and images neither).

    Parameters
    ----------
    dance : a `HarmonicDance`.
    frames : samples T.

    Returns
    -------
    {"morph targets": bytes, "skin": bytes (a reduced basis only)}.
    """
    n, faces = dance.n, len(dance.faces)
    indices = faces * 3 * (2 if n <= 65535 else 4)
    base = 24 * n + indices + -indices % 4 + 4 * frames
    driven = len(dance.driven())
    sizes = {"morph targets": base + driven * (12 * n + 4 * frames)}
    if dance.basis.reduced is not None:
        count = dance.basis.reduced.count
        sizes["skin"] = base + 2 * 8 * n + 2 * 8 * n + count * (64 + 12 * frames)
    return sizes


def _rotation_translation(rotations, translations):
    """Unit quaternions (…, 4) as glTF stores them (x, y, z, w), continuous along axis 0 (no
    sign flips between samples, so LINEAR/slerp takes the short way), and translations."""
    shape = rotations.shape[:-2]
    quaternions = Rotation.from_matrix(rotations.reshape(-1, 3, 3)).as_quat().reshape(*shape, 4)
    if len(shape) == 2 and shape[0] > 1:
        flips = np.sum(quaternions[1:] * quaternions[:-1], axis=-1) < 0
        signs = np.cumprod(np.where(flips, -1.0, 1.0), axis=0)
        quaternions[1:] *= signs[..., None]
    quaternions /= np.linalg.norm(quaternions, axis=-1, keepdims=True)
    return quaternions, np.asarray(translations)


def _influences(weights: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per vertex the bodies with non-zero weight, padded to a multiple of four (index 0,
    weight 0): indices (n, L) and weights (n, L), rows summing to 1 in float32."""
    weights = np.where(weights >= WEIGHT_EPSILON, weights, 0.0)
    weights = weights / weights.sum(axis=1, keepdims=True)
    width = max(4, 4 * math.ceil(int((weights > 0).sum(axis=1).max()) / 4))
    order = np.argsort(-weights, axis=1, kind="stable")[:, :width]
    chosen = np.take_along_axis(weights, order, axis=1)
    if chosen.shape[1] < width:
        pad = width - chosen.shape[1]
        chosen = np.pad(chosen, ((0, 0), (0, pad)))
        order = np.pad(order, ((0, 0), (0, pad)))
    order = np.where(chosen > 0, order, 0)
    chosen = chosen.astype(np.float32)
    chosen /= chosen.sum(axis=1, keepdims=True, dtype=np.float64).astype(np.float32)
    return order, chosen
