"""A model's look over HTTP (docs/web.md#appearance-bundle): the appearance bundle of a textured
mesh and of a textured rig, checked against the glTF files' own JSON and bytes (read here with
json and base64, not the project's reader)."""

from __future__ import annotations

import base64
import json
import struct

import numpy as np
import pytest
from starlette.testclient import TestClient

from eigendance.server.app import create_app
from eigendance.server.binary import unpack
from eigendance.server.library import Library
from helpers import fixture_path

MORPH = fixture_path("textured", "MorphStressTest.gltf")
FOX = fixture_path("rigged", "Fox.glb")
ROBOT = fixture_path("textured", "robot.obj")
CAT = fixture_path("..", "..", "src", "eigendance", "data", "cat_lowres.obj")


@pytest.fixture(scope="module")
def client(tmp_path_factory):
    library = Library(str(tmp_path_factory.mktemp("look") / "library"), k=8)
    for path in (MORPH, FOX, ROBOT, CAT):
        library.add_path(path)
    assert library.wait(120)
    with TestClient(create_app(library), base_url="http://localhost") as test_client:
        test_client.library = library
        yield test_client
    library.close()


def item(client, kind: str, name: str) -> dict:
    return next(x for x in client.get("/api/library").json()[kind] if x["name"] == name)


def look_of(client, kind: str, name: str):
    response = client.get(f"/api/{kind}/{item(client, kind, name)['id']}/appearance.bin")
    assert response.status_code == 200, response.text
    assert response.headers["content-type"] == "application/octet-stream"
    return unpack(response.content)


def gltf_json_and_buffer(path: str) -> tuple[dict, bytes]:
    """The JSON and the first buffer of a .glb, or of a .gltf with an embedded buffer."""
    with open(path, "rb") as file:
        data = file.read()
    if data[:4] == b"glTF":
        length = struct.unpack("<I", data[12:16])[0]
        document = json.loads(data[20:20 + length])
        start = 20 + length
        return document, data[start + 8:start + 8 + struct.unpack("<I", data[start:start + 4])[0]]
    document = json.loads(data)
    uri = document["buffers"][0]["uri"]
    return document, base64.b64decode(uri.split(",", 1)[1])


def image_bytes(document: dict, buffer: bytes, image: int) -> bytes:
    entry = document["images"][image]
    if "uri" in entry:
        return base64.b64decode(entry["uri"].split(",", 1)[1])
    view = document["bufferViews"][entry["bufferView"]]
    start = view.get("byteOffset", 0)
    return buffer[start:start + view["byteLength"]]


def triangle_count(document: dict) -> int:
    """Triangles the scene draws: each node's mesh's primitives' indices (or positions) / 3."""
    meshes = [sum(document["accessors"][p.get("indices", p["attributes"]["POSITION"])]["count"]
                  // 3 for p in mesh["primitives"]) for mesh in document["meshes"]]
    return sum(meshes[node["mesh"]] for node in document["nodes"] if "mesh" in node)


def test_the_library_says_which_models_have_a_look(client):
    assert item(client, "meshes", "MorphStressTest.gltf")["look"] == {
        "materials": 2, "images": 3, "drawn": 1528}
    assert item(client, "meshes", "robot.obj")["look"]["materials"] == 3
    assert item(client, "meshes", "cat_lowres.obj")["look"] is None
    assert item(client, "rigs", "Fox.glb")["look"]["images"] == 1


def test_a_model_without_a_look_answers_404_in_one_line(client):
    response = client.get(f"/api/meshes/{item(client, 'meshes', 'cat_lowres.obj')['id']}"
                          "/appearance.bin")
    assert response.status_code == 404
    assert "cat_lowres.obj" in response.json()["error"] and "clay" in response.json()["error"]
    assert client.get("/api/meshes/nothing/appearance.bin").status_code == 404


def test_a_textured_mesh_comes_with_its_materials_images_and_uv_sets(client):
    meta, arrays = look_of(client, "meshes", "MorphStressTest.gltf")
    document, buffer = gltf_json_and_buffer(MORPH)
    basis_meta, _ = unpack(client.get(
        f"/api/meshes/{item(client, 'meshes', 'MorphStressTest.gltf')['id']}/basis.bin").content)
    drawn = meta["drawn"]
    assert arrays["welded"].shape == (drawn,) and arrays["welded"].max() < basis_meta["n"]
    assert set(np.unique(arrays["welded"])) == set(range(basis_meta["n"]))  # every vertex drawn
    parts = [arrays[f"triangles{p}"] for p in range(len(meta["parts"]))]
    assert sum(len(t) for t in parts) == triangle_count(document)
    assert all(t.dtype == np.uint32 and t.max() < drawn for t in parts)
    assert np.allclose(np.linalg.norm(arrays["normals"], axis=1), 1, atol=1e-4)
    assert arrays["uv0"].shape == arrays["uv1"].shape == (drawn, 2)
    for material in document["materials"]:
        ours = next(m for m in meta["materials"] if m["name"] == material["name"])
        pbr = material["pbrMetallicRoughness"]
        assert ours["roughness"] == pytest.approx(pbr["roughnessFactor"])
        assert ours["doubleSided"] is material["doubleSided"]
        shading = ours["shading"]
        texture = document["textures"][pbr["baseColorTexture"]["index"]]
        ours_image = shading["textures"]["baseMap"]["image"]
        assert bytes(arrays[f"image{ours_image}"]) == image_bytes(document, buffer,
                                                                 texture["source"])
        assert shading["textures"]["baseMap"]["srgb"] is True
        if "occlusionTexture" in material:  # read from the second UV set, as the file says
            assert material["occlusionTexture"]["texCoord"] == 1
            assert shading["defines"]["OCCLUSION_MAP_UV"] == "vUv1"
            assert shading["defines"]["UV1"] == 1
            assert shading["textures"]["occlusionMap"]["srgb"] is False


def test_a_textured_rig_comes_with_its_skins_look(client):
    rig = item(client, "rigs", "Fox.glb")
    meta, arrays = look_of(client, "rigs", "Fox.glb")
    rig_meta, _ = unpack(client.get(f"/api/rigs/{rig['id']}/rig.bin").content)
    document, buffer = gltf_json_and_buffer(FOX)
    assert arrays["welded"].max() < rig_meta["n"]
    assert bytes(arrays["image0"]) == image_bytes(document, buffer, 0)
    assert meta["materials"][0]["shading"]["defines"]["BASE_MAP"] == 1
    assert sum(len(arrays[f"triangles{p}"]) for p in range(len(meta["parts"]))) == \
        triangle_count(document)


def test_an_obj_keeps_its_mtl_colours(client):
    meta, arrays = look_of(client, "meshes", "robot.obj")
    with open(ROBOT.replace(".obj", ".mtl")) as file:
        kd = [[float(x) for x in line.split()[1:4]] for line in file if line.startswith("Kd")]
    linear = np.array([m["shading"]["uniforms"]["baseColorFactor"][:3]
                       for m in meta["materials"]])
    # the bundle's factors are linear; an MTL's Kd is sRGB (kept as bytes by trimesh)
    srgb = np.where(linear <= 0.0031308, linear * 12.92, 1.055 * linear ** (1 / 2.4) - 0.055)
    np.testing.assert_allclose(sorted(srgb.tolist()), sorted(kd), atol=1 / 255)
