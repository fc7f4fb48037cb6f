"""A glTF 2.0 document: its JSON (pygltflib), buffers, accessors, Draco primitives and images
(docs/design.md#appearance).

`GltfFile(path)` opens a .glb or a .gltf; files it names (external buffers, images) are read
only from the model's own folder: a URI with `..`, an absolute path or a non-regular file is
refused. Accessors become numpy arrays (strided views, sparse substitution, normalised
integers); primitives compressed with KHR_draco_mesh_compression are decoded by DracoPy (the
Python binding of Google's Draco decoder). A required extension we cannot decode (meshopt's
EXT_meshopt_compression, KTX2 textures …) is one InputError naming it.
"""

from __future__ import annotations

import base64
import binascii
import json
import os
import urllib.parse

import numpy as np
import pygltflib

from eigendance.errors import InputError, one_line
from eigendance.reads import open_regular

COMPONENT_TYPES = {5120: np.int8, 5121: np.uint8, 5122: np.int16, 5123: np.uint16,
                   5125: np.uint32, 5126: np.float32}
WIDTHS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT2": 4, "MAT3": 9, "MAT4": 16}
DRACO = "KHR_draco_mesh_compression"
# Extensions we read (or that change nothing we keep); any other *required* one is refused.
READ_EXTENSIONS = {DRACO, "KHR_materials_unlit", "KHR_texture_transform",
                   "KHR_mesh_quantization", "KHR_materials_emissive_strength"}
IMAGE_MAGIC = {b"\x89PNG\r\n\x1a\n": "image/png", b"\xff\xd8\xff": "image/jpeg"}
MAX_ELEMENTS = 1 << 28  # an accessor larger than this is refused before it is allocated
# An accessor without a buffer view is zeros (the base of a sparse one): its size is declared,
# not held. It may declare at most ZEROS_PER_BYTE values per byte of the file and its buffers
# (a mesh stores 12 bytes per vertex, Draco 1 or more), beyond ZEROS_FREE values.
ZEROS_PER_BYTE, ZEROS_FREE = 16, 1 << 16
# Objects of one kind (nodes, accessors, meshes …) a document may list: pygltflib takes about
# 3 ms to read each, so 10,000 nodes take 30 s (a skeleton of 100,000 joints would take 5 min).
MAX_OBJECTS = 10_000


def document_json(path: str | os.PathLike, name: str | None = None) -> dict | None:
    """The JSON document of a glTF file (.gltf, or a .glb's JSON chunk), read with json alone:
    no buffer, no image, no check of what it holds (`GltfFile` checks).

    Parameters
    ----------
    path : a .glb or .gltf file.
    name : how messages call it.

    Returns
    -------
    dict, or None for a file whose JSON cannot be read (`GltfFile` says why).

    Raises
    ------
    InputError
        For a path that is not a regular file (`open_regular`).
    """
    try:
        with open_regular(os.fspath(path), name or os.path.basename(os.fspath(path))) as file:
            head = file.read(20)
            if head[:4] == b"glTF":  # GLB: header (12 bytes), JSON chunk (8 + length)
                text = file.read(int.from_bytes(head[12:16], "little"))
            else:
                text = head + file.read()
        document = json.loads(text)
    except (ValueError, UnicodeDecodeError, OSError, RecursionError):
        return None
    return document if isinstance(document, dict) else None


class GltfFile:
    """An open glTF 2.0 file.

    Parameters
    ----------
    path : a .glb or .gltf file.
    name : how messages call it (default: the file's name).

    Attributes: document (pygltflib.GLTF2), folder (the model's folder), name.
    """

    def __init__(self, path: str | os.PathLike, name: str | None = None):
        path = os.fspath(path)
        self.name = name or os.path.basename(path)
        self.folder = os.path.dirname(os.path.abspath(path))
        self.file_bytes = os.path.getsize(path)
        self._check_objects(path)
        try:
            document = pygltflib.GLTF2().load(path)
        except Exception as error:  # pygltflib raises many kinds on a corrupt file
            raise InputError(f"{self.name}: not a readable glTF file "
                             f"({one_line(error, 150)})") from None
        if document is None or not isinstance(document.asset, pygltflib.Asset):
            raise InputError(f"{self.name}: not a readable glTF file")
        version = str(getattr(document.asset, "version", "") or "")
        if not version.startswith("2."):
            raise InputError(f"{self.name}: glTF version {version or '(none)'}; only glTF 2.0 "
                             "can be read (re-export it from Blender as glTF 2.0)")
        self.document = document
        self._buffers: dict[int, bytes] = {}
        self._check_extensions()

    def _check_objects(self, path: str) -> None:
        """InputError when the document lists more than MAX_OBJECTS of a kind (nodes,
        accessors …), read with json before pygltflib spends 3 ms on each."""
        for kind, items in (document_json(path, self.name) or {}).items():
            if isinstance(items, list) and len(items) > MAX_OBJECTS:
                raise self.message(f"the file lists {len(items)} {kind}; at most {MAX_OBJECTS} "
                                   "are read")

    def _check_extensions(self) -> None:
        required = [str(e) for e in self.document.extensionsRequired or []]
        missing = [e for e in required if e not in READ_EXTENSIONS]
        if missing:
            what = "meshopt compression" if "meshopt" in missing[0] else "this extension"
            raise InputError(f"{self.name}: requires the glTF extension {missing[0]}, which "
                             f"eigendance cannot read ({what}); re-export it without it (in "
                             "Blender: File › Export › glTF 2.0, compression off)")

    def message(self, text: str) -> InputError:
        """An InputError about this file.

        Parameters
        ----------
        text : what is wrong.

        Returns
        -------
        InputError naming the file.
        """
        return InputError(f"{self.name}: {text}")

    # --- buffers ----------------------------------------------------------------------------
    def buffer(self, index: int) -> bytes:
        """The bytes of buffer `index` (the GLB chunk, a data URI or a file beside the model).

        Parameters
        ----------
        index : the buffer.

        Returns
        -------
        bytes.
        """
        if index not in self._buffers:
            buffers = self.document.buffers
            if not isinstance(index, int) or not 0 <= index < len(buffers):
                raise self.message(f"no buffer {index}")
            uri = buffers[index].uri
            if uri is None:
                data = self.document.binary_blob()
                if data is None:
                    raise self.message(f"buffer {index} has no data (no GLB binary chunk)")
            else:
                data = self.uri_bytes(uri, f"buffer {index}")
            length = buffers[index].byteLength or 0
            if len(data) < length:
                raise self.message(f"buffer {index} holds {len(data)} bytes; the file says "
                                   f"{length}")
            self._buffers[index] = bytes(data)
        return self._buffers[index]

    def uri_bytes(self, uri: str, what: str) -> bytes:
        """The bytes a URI names: a base64 data URI, or a file inside the model's folder.

        Parameters
        ----------
        uri : the URI.
        what : what it is, for messages.

        Returns
        -------
        bytes.
        """
        if not isinstance(uri, str):
            raise self.message(f"{what}: its uri is not a string")
        if uri.startswith("data:"):
            if ";base64," not in uri:
                raise self.message(f"{what} is a data URI without base64 data")
            try:
                return base64.b64decode(uri.split(";base64,", 1)[1], validate=False)
            except (binascii.Error, ValueError):
                raise self.message(f"{what}: its data URI is not valid base64") from None
        return self._file_bytes(urllib.parse.unquote(uri), what)

    def _file_bytes(self, relative: str, what: str) -> bytes:
        parts = relative.replace("\\", "/").split("/")
        if os.path.isabs(relative) or ".." in parts or ":" in parts[0]:
            raise self.message(f"{what} names {relative!r}, outside the model's folder "
                               "(only files beside the model are read)")
        path = os.path.join(self.folder, *parts)
        if not os.path.exists(path):
            raise self.message(f"{what}: the file {relative!r} is missing (it must sit beside "
                               "the model)")
        # Links are followed only where they stay inside the folder (a linked folder leading
        # to /proc is outside), and only a regular file is opened (a FIFO would block).
        inside = os.path.realpath(self.folder) + os.sep
        if not os.path.realpath(path).startswith(inside):
            raise self.message(f"{what}: {relative!r} leads outside the model's folder")
        with open_regular(path, f"{self.name}: {what} ({relative})") as file:
            return file.read()

    def view_bytes(self, index: int) -> bytes:
        """The bytes of buffer view `index`.

        Parameters
        ----------
        index : the buffer view.

        Returns
        -------
        bytes.
        """
        views = self.document.bufferViews
        if not isinstance(index, int) or not 0 <= index < len(views):
            raise self.message(f"no buffer view {index}")
        view = views[index]
        data = self.buffer(view.buffer)
        start, length = view.byteOffset or 0, view.byteLength or 0
        if start < 0 or length < 0 or start + length > len(data):
            raise self.message(f"buffer view {index} runs past its buffer")
        return data[start:start + length]

    # --- accessors --------------------------------------------------------------------------
    def accessor(self, index: int) -> np.ndarray:
        """Accessor `index` as an (count, width) array: floats as float64, integers as int64,
        normalised integers as floats in [−1, 1] or [0, 1].

        Parameters
        ----------
        index : the accessor.

        Returns
        -------
        (count, width) array.
        """
        accessors = self.document.accessors
        if not isinstance(index, int) or not 0 <= index < len(accessors):
            raise self.message(f"no accessor {index}")
        item = accessors[index]
        dtype, width = self._layout(item, f"accessor {index}")
        count = item.count
        if item.bufferView is None:
            self._check_declared(count * width, f"accessor {index}")
            values = np.zeros((count, width), dtype=dtype)
        else:
            values = self._strided(item.bufferView, item.byteOffset or 0, dtype, width, count,
                                   f"accessor {index}")
        if item.sparse is not None and item.sparse.count:
            self._substitute(values, item, dtype, width, index)
        if item.normalized and dtype.kind in "iu":
            return np.maximum(values / float(np.iinfo(dtype).max), -1.0)
        return values.astype(np.float64 if dtype.kind == "f" else np.int64)

    def held_bytes(self) -> int:
        """Bytes the model holds: its file and its buffers.

        Returns
        -------
        int.
        """
        return self.file_bytes + sum(len(self.buffer(index))
                                     for index in range(len(self.document.buffers or [])))

    def _check_declared(self, values: int, what: str) -> None:
        """InputError when `values` declared (not held) exceed what the file's bytes can
        describe (ZEROS_PER_BYTE, ZEROS_FREE): checked before they are allocated."""
        if values > ZEROS_FREE and values > ZEROS_PER_BYTE * self.held_bytes():
            raise self.message(f"{what} declares {values} values without data, more than a "
                               f"file of {self.held_bytes()} bytes can describe")

    def _layout(self, item, what: str) -> tuple[np.dtype, int]:
        if item.componentType not in COMPONENT_TYPES or item.type not in WIDTHS:
            raise self.message(f"{what} has an unknown type ({item.componentType}, {item.type})")
        if not isinstance(item.count, int) or not 0 <= item.count <= MAX_ELEMENTS:
            raise self.message(f"{what} has an impossible count {item.count!r}")
        return np.dtype(COMPONENT_TYPES[item.componentType]).newbyteorder("<"), \
            WIDTHS[item.type]

    def _strided(self, view_index, offset, dtype, width, count, what) -> np.ndarray:
        data = self.view_bytes(view_index)
        view = self.document.bufferViews[view_index]
        element = dtype.itemsize * width
        stride = view.byteStride or element
        if stride < element or offset < 0:
            raise self.message(f"{what}: byte stride {stride} or offset {offset} is impossible")
        if count and offset + stride * (count - 1) + element > len(data):
            raise self.message(f"{what} reads {count} elements past the end of its buffer "
                               f"view ({len(data)} bytes)")
        if count == 0:
            return np.zeros((0, width), dtype=dtype)
        return np.ndarray((count, width), dtype=dtype, buffer=data, offset=offset,
                          strides=(stride, dtype.itemsize)).copy()

    def _substitute(self, values, item, dtype, width, index) -> None:
        sparse = item.sparse
        what = f"accessor {index} (sparse)"
        if not isinstance(sparse.count, int) or not 0 < sparse.count <= len(values):
            raise self.message(f"{what} has an impossible count {sparse.count!r}")
        index_type = sparse.indices.componentType
        if index_type not in (5121, 5123, 5125):
            raise self.message(f"{what} has indices of type {index_type}")
        indices = self._strided(sparse.indices.bufferView, sparse.indices.byteOffset or 0,
                                np.dtype(COMPONENT_TYPES[index_type]).newbyteorder("<"), 1,
                                sparse.count, what)[:, 0].astype(np.int64)
        if indices.max(initial=0) >= len(values):
            raise self.message(f"{what} replaces element {indices.max()} of {len(values)}")
        values[indices] = self._strided(sparse.values.bufferView,
                                        sparse.values.byteOffset or 0, dtype, width,
                                        sparse.count, what)

    # --- Draco ------------------------------------------------------------------------------
    def draco(self, extension: dict, what: str) -> tuple[dict[str, np.ndarray], np.ndarray]:
        """The attributes {name: (n, width) array} and triangles (m, 3) of a Draco primitive.

        Parameters
        ----------
        extension : the primitive's KHR_draco_mesh_compression.
        what : the primitive, for messages.

        Returns
        -------
        (attributes, triangles).
        """
        import DracoPy  # optional path: only Draco-compressed files need the decoder

        if not isinstance(extension, dict) or not isinstance(extension.get("attributes"),
                                                              dict):
            raise self.message(f"{what}: malformed {DRACO} extension")
        try:
            mesh = DracoPy.decode(self.view_bytes(extension.get("bufferView")))
        except InputError:
            raise
        except Exception as error:  # noqa: BLE001 - the decoder raises its own kinds
            raise self.message(f"{what}: the Draco data cannot be decoded "
                               f"({one_line(error, 100)})") from None
        by_id = {attribute["unique_id"]: attribute["data"] for attribute in mesh.attributes}
        attributes = {}
        for name, unique_id in extension["attributes"].items():
            if unique_id not in by_id:
                raise self.message(f"{what}: the Draco data has no attribute {unique_id} "
                                   f"({name})")
            data = np.asarray(by_id[unique_id])
            attributes[name] = data.reshape(len(data), -1)
        faces = np.asarray(mesh.faces, dtype=np.int64).reshape(-1, 3)
        return attributes, faces

    # --- images -----------------------------------------------------------------------------
    def image(self, index: int) -> tuple[str, str, bytes]:
        """(name, mime type, bytes) of image `index`; InputError if it cannot be read or is
        neither PNG nor JPEG.

        Parameters
        ----------
        index : the image.

        Returns
        -------
        (name, mime type, bytes).
        """
        images = self.document.images
        if not isinstance(index, int) or not 0 <= index < len(images):
            raise self.message(f"no image {index}")
        image = images[index]
        what = f"image {index}" + (f" ({image.name})" if image.name else "")
        if image.bufferView is not None:
            data = self.view_bytes(image.bufferView)
        elif image.uri:
            data = self.uri_bytes(image.uri, what)
        else:
            raise self.message(f"{what} has neither a buffer view nor a uri")
        mime = next((kind for magic, kind in IMAGE_MAGIC.items() if data.startswith(magic)),
                    None)
        if mime is None:
            raise self.message(f"{what} is neither a PNG nor a JPEG image")
        uri = image.uri if isinstance(image.uri, str) and not image.uri.startswith("data:") \
            else ""
        return str(image.name or uri or ""), mime, data
