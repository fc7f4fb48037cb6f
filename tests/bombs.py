"""Inputs that ask for more than they hold: rigs of many bodies, glTF files whose declared sizes
exceed their bytes (issue 21, docs/design.md#errors). Used by the bad-input suite, the server's
tests and benchmarks/bench_limits.py.
"""

from __future__ import annotations

import base64
import json
import os

import numpy as np
import pygltflib


def chain_skeleton(path, bodies: int, joint_type: str = "spherical") -> str:
    """A skeleton JSON: `bodies` rods end to end along y, joined by `joint_type` joints.

    Parameters
    ----------
    path : where to write it.
    bodies : how many bodies.
    joint_type : the joints' type.

    Returns
    -------
    str, the path.
    """
    document = {
        "format": "eigendance.skeleton", "version": 1,
        "bodies": [{"name": f"b{i}", "start": [0, 0.1 * i, 0], "end": [0, 0.1 * (i + 1), 0],
                    "radius": 0.01} for i in range(bodies)],
        "joints": [{"name": f"j{i}", "type": joint_type, "bodies": [f"b{i}", f"b{i + 1}"],
                    "stiffness": "auto"} for i in range(bodies - 1)]}
    with open(path, "w", encoding="utf-8") as file:
        json.dump(document, file)
    return os.fspath(path)


def chain_gltf(path, joints: int) -> str:
    """A skinned .glb: a square tube of `joints` segments, each ring bound to one joint of a
    chain of `joints` nodes (children listed after their parents).

    Parameters
    ----------
    path : where to write it.
    joints : how many joints.

    Returns
    -------
    str, the path.
    """
    rings = joints + 1
    angle = np.arange(4) * np.pi / 2
    ring = np.stack([0.02 * np.cos(angle), np.zeros(4), 0.02 * np.sin(angle)], axis=1)
    positions = (ring[None] + np.arange(rings)[:, None, None] * [0, 0.1, 0]).reshape(-1, 3)
    bound = np.repeat(np.minimum(np.arange(rings), joints - 1), 4)
    joint_ids = np.zeros((4 * rings, 4), np.uint16)
    joint_ids[:, 0] = bound
    weights = np.zeros((4 * rings, 4), np.float32)
    weights[:, 0] = 1
    first = (np.arange(rings - 1)[:, None] * 4 + np.arange(4)).reshape(-1)
    second = (np.arange(rings - 1)[:, None] * 4 + (np.arange(4) + 1) % 4).reshape(-1)
    triangles = np.concatenate([np.stack([first, second, first + 4], 1),
                                np.stack([second, second + 4, first + 4], 1)]).astype(np.uint32)
    inverse_binds = np.tile(np.eye(4, dtype=np.float32), (joints, 1, 1))
    inverse_binds[:, 3, 1] = -0.1 * np.arange(joints)  # column-major translation
    arrays = [positions.astype(np.float32), triangles, joint_ids, weights, inverse_binds]
    blob, views = b"", []
    for array in arrays:
        views.append(pygltflib.BufferView(buffer=0, byteOffset=len(blob),
                                          byteLength=array.nbytes))
        blob += array.tobytes()
    accessor = pygltflib.Accessor
    accessors = [
        accessor(bufferView=0, componentType=5126, count=4 * rings, type="VEC3",
                 min=positions.min(0).tolist(), max=positions.max(0).tolist()),
        accessor(bufferView=1, componentType=5125, count=triangles.size, type="SCALAR"),
        accessor(bufferView=2, componentType=5123, count=4 * rings, type="VEC4"),
        accessor(bufferView=3, componentType=5126, count=4 * rings, type="VEC4"),
        accessor(bufferView=4, componentType=5126, count=joints, type="MAT4")]
    nodes = [pygltflib.Node(mesh=0, skin=0)] + [
        pygltflib.Node(name=f"bone{i}", translation=[0, 0.1 if i else 0, 0],
                       children=[i + 2] if i < joints - 1 else []) for i in range(joints)]
    primitive = pygltflib.Primitive(attributes=pygltflib.Attributes(
        POSITION=0, JOINTS_0=2, WEIGHTS_0=3), indices=1)
    document = pygltflib.GLTF2(
        asset=pygltflib.Asset(version="2.0"), scene=0, scenes=[pygltflib.Scene(nodes=[0, 1])],
        nodes=nodes, meshes=[pygltflib.Mesh(primitives=[primitive])],
        skins=[pygltflib.Skin(joints=list(range(1, joints + 1)), inverseBindMatrices=4)],
        accessors=accessors, bufferViews=views, buffers=[pygltflib.Buffer(byteLength=len(blob))])
    document.set_binary_blob(blob)
    document.save_binary(os.fspath(path))
    return os.fspath(path)


def accessor_bomb(path, count: int = 10**8, buffer_length: int | None = None) -> str:
    """A .gltf of a few hundred bytes whose POSITION accessor has no buffer view (zeros, as
    the glTF specification allows) and declares `count` elements; `buffer_length` (when
    given) is the byteLength its one buffer declares.

    Parameters
    ----------
    path : where to write it.
    count : the declared count.
    buffer_length : the buffer's declared byteLength (default: its real 12).

    Returns
    -------
    str, the path.
    """
    data = np.array([0, 1, 2], np.uint32).tobytes()
    uri = "data:application/octet-stream;base64," + base64.b64encode(data).decode()
    primitive = pygltflib.Primitive(attributes=pygltflib.Attributes(POSITION=0), indices=1)
    document = pygltflib.GLTF2(
        asset=pygltflib.Asset(version="2.0"), scene=0, scenes=[pygltflib.Scene(nodes=[0])],
        nodes=[pygltflib.Node(mesh=0)], meshes=[pygltflib.Mesh(primitives=[primitive])],
        accessors=[pygltflib.Accessor(componentType=5126, count=count, type="VEC3"),
                   pygltflib.Accessor(bufferView=0, componentType=5125, count=3,
                                      type="SCALAR")],
        bufferViews=[pygltflib.BufferView(buffer=0, byteLength=12)],
        buffers=[pygltflib.Buffer(uri=uri, byteLength=buffer_length or 12)])
    document.save_json(os.fspath(path))
    return os.fspath(path)
