"""Every image a model names is judged by the size its header declares before a pixel of it is
decoded, on every path (issue 34 case 5): OBJ/MTL and PLY (through trimesh's resolver), glTF,
and Blender's formats. The images here are a few hundred bytes declaring 13,300 × 13,300
pixels (1.5-1.7 GB and 8-20 s decoded): decoding one fails the test."""

from __future__ import annotations

import io
import struct
import warnings
import zlib
from types import SimpleNamespace

import numpy as np
import pytest
import trimesh
from PIL import Image, ImageFile

from eigendance.assets import other_formats
from eigendance.assets.materials import MAX_IMAGE_SIDE, check_image_header
from eigendance.assets.reader import read_model
from eigendance.errors import InputError, ModelWarning

SIDE = 13_300


def png_header(width: int, height: int) -> bytes:
    """A PNG declaring width × height RGB pixels (PNG spec: signature, IHDR, IDAT, IEND), its
    pixel data a few zero rows: enough for a reader of the header, never decoded here."""
    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + \
            struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2,
                                                              0, 0, 0)) + \
        chunk(b"IDAT", zlib.compress(bytes(4 * (3 * width + 1)))) + chunk(b"IEND", b"")


@pytest.fixture
def no_large_decoding(monkeypatch):
    """Decoding an image over the limit fails the test (Pillow decodes in ImageFile.load; the
    readers may swallow an exception raised there, so each decoding is noted and checked
    after)."""
    load, decoded = ImageFile.ImageFile.load, []

    def noted(self):
        if self.size[0] * self.size[1] > 1 << 20:
            decoded.append(self.size)
            raise MemoryError("a large image was decoded")
        return load(self)

    monkeypatch.setattr(ImageFile.ImageFile, "load", noted)
    yield
    assert not decoded, f"decoded images of {decoded}"


def write_box(folder, suffix: str) -> str:
    box = trimesh.creation.box()
    uv = np.random.default_rng(0).random((len(box.vertices), 2))
    if suffix == ".obj":
        (folder / "box.mtl").write_text("newmtl skin\nKd 1 1 1\nmap_Kd huge.png\n")
        lines = ["mtllib box.mtl", "usemtl skin"]
        lines += [f"v {x} {y} {z}" for x, y, z in box.vertices]
        lines += [f"vt {u} {v}" for u, v in uv]
        lines += [f"f {a}/{a} {b}/{b} {c}/{c}" for a, b, c in box.faces + 1]
        text = "\n".join(lines) + "\n"
    else:
        box.visual = trimesh.visual.TextureVisuals(uv=uv)
        text = box.export(file_type="ply", encoding="ascii").decode()
        text = text.replace("format ascii 1.0\n",
                            "format ascii 1.0\ncomment TextureFile huge.png\n")
    (folder / f"box{suffix}").write_text(text)
    (folder / "huge.png").write_bytes(png_header(SIDE, SIDE))
    return str(folder / f"box{suffix}")


@pytest.mark.parametrize("suffix", [".obj", ".ply"])
def test_a_texture_declaring_too_many_pixels_is_dropped_before_decoding(
        tmp_path, no_large_decoding, suffix):
    path = write_box(tmp_path, suffix)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        model = read_model(path)
    assert len(model.triangles) == 12
    for image in model.images:  # trimesh's stand-in for a missing texture at most
        with Image.open(io.BytesIO(image.data)) as opened:
            assert max(opened.size) < SIDE
    said = [str(w.message) for w in caught if issubclass(w.category, ModelWarning)]
    assert len(said) == 1 and f"{SIDE} × {SIDE} pixels" in said[0] and "huge.png" in said[0]


@pytest.mark.parametrize(("side", "words"), [(SIDE, f"{SIDE} × {SIDE}"),
                                             (20_000, "more than"),  # past Pillow's own limit
                                             (MAX_IMAGE_SIDE + 2, "pixels")])
def test_the_header_check_refuses_before_decoding(no_large_decoding, side, words):
    with pytest.raises(InputError, match=words):
        check_image_header(png_header(side, 2 if side == MAX_IMAGE_SIDE + 2 else side))
    check_image_header(png_header(64, 64))  # within the limits: nothing said
    check_image_header(b"not an image")  # said where it is decoded


def test_blenders_images_are_judged_from_their_bytes(tmp_path):
    """What `_blender_export` drops before the glTF exporter decodes: packed or on disk."""
    (tmp_path / "huge.png").write_bytes(png_header(SIDE, SIDE))
    (tmp_path / "small.png").write_bytes(png_header(8, 8))
    packed = SimpleNamespace(name="packed", filepath="",
                             packed_file=SimpleNamespace(data=png_header(20_000, 4)))
    huge = SimpleNamespace(name="huge", filepath="//huge.png", packed_file=None)
    small = SimpleNamespace(name="small", filepath="//small.png", packed_file=None)
    gone = SimpleNamespace(name="gone", filepath="//gone.png", packed_file=None)
    found = other_formats.large_images(
        [packed, huge, small, gone], lambda path: str(tmp_path / path.removeprefix("//")))
    assert [image.name for image, _ in found] == ["packed", "huge"]
    assert "20000 × 4" in found[0][1] and found[1][1].startswith("huge: ")
