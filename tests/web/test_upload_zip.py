"""A model in several files, uploaded as one .zip (docs/design.md#server, server.archive): read
like a single .glb; refused in one line when it would write outside its folder, unpack too
much, or hold what a model does not use; nothing left behind either way."""

from __future__ import annotations

import io
import os
import stat
import struct
import zipfile

import pytest
from PIL import Image
from starlette.testclient import TestClient
from web_helpers import zipped

from eigendance.server.app import create_app
from eigendance.server.library import UNPACKED_FACTOR, Library
from helpers import fixture_path

LIMIT = 2_000_000  # the upload limit of these tests: a zip may unpack to 4× it


@pytest.fixture
def client(tmp_path):
    library = Library(str(tmp_path / "library"), k=8, max_upload_bytes=LIMIT)
    with TestClient(create_app(library), base_url="http://localhost") as test_client:
        test_client.library = library
        yield test_client
    library.close()


def read(*parts) -> bytes:
    with open(fixture_path(*parts), "rb") as file:
        return file.read()


def upload(client, name: str, data: bytes):
    return client.post(f"/api/upload?name={name}", content=data)


def leftovers(client) -> list[str]:
    return sorted(os.listdir(client.library.folder))


def png(color) -> bytes:
    buffer = io.BytesIO()
    Image.new("RGB", (4, 4), color).save(buffer, format="PNG")
    return buffer.getvalue()


def test_a_gltf_with_its_bin_is_read_like_a_glb(client):
    data = zipped({"ship/craft_speederD.gltf": read("textured", "craft_speederD.gltf"),
                   "ship/craft_speederD_data.bin": read("textured", "craft_speederD_data.bin"),
                   "license.txt": b"CC0", "__MACOSX/ship/._craft_speederD.gltf": b"junk",
                   "ship/.DS_Store": b"junk"})
    answer = upload(client, "ship.zip", data)
    assert answer.status_code == 201, answer.text
    item = answer.json()["item"]
    assert answer.json()["kind"] == "mesh" and item["name"] == "craft_speederD.gltf"
    assert item["look"] == {"materials": 4, "images": 0, "drawn": 532}
    assert client.library.wait(60)
    assert client.get(f"/api/meshes/{item['id']}/basis.bin").status_code == 200
    again = upload(client, "same.zip", data)  # the same bytes: the item already there
    assert again.status_code == 200 and again.json()["item"]["id"] == item["id"]
    assert len([name for name in leftovers(client) if name.startswith("upload-")]) == 1
    assert client.delete(f"/api/meshes/{item['id']}").status_code == 200
    assert leftovers(client) == []  # the folder goes with the item


def test_an_obj_with_its_mtl_and_texture(client):
    obj = (b"mtllib quad.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 0.4\n"
           b"vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\nusemtl painted\n"
           b"f 1/1 2/2 5/5\nf 2/2 3/3 5/5\nf 3/3 4/4 5/5\nf 4/4 1/1 5/5\nf 1/1 4/4 3/3 2/2\n")
    texture = png((200, 30, 40))
    data = zipped({"quad.obj": obj, "quad.mtl": b"newmtl painted\nKd 1 1 1\nmap_Kd tex/red.png\n",
                   "tex/red.png": texture})
    answer = upload(client, "quad.zip", data)
    assert answer.status_code == 201, answer.text
    item = answer.json()["item"]
    assert item["look"]["images"] == 1
    from eigendance.server.binary import unpack

    meta, arrays = unpack(client.get(f"/api/meshes/{item['id']}/appearance.bin").content)
    assert bytes(arrays["image0"]) == texture
    assert meta["materials"][0]["shading"]["defines"]["BASE_MAP"] == 1


def test_a_skinned_gltf_in_a_zip_is_listed_once_as_a_rig(client):
    answer = upload(client, "skin.zip", zipped({"SimpleSkin.gltf": read("rigged",
                                                                        "SimpleSkin.gltf")}))
    assert answer.status_code == 201, answer.text
    assert answer.json()["kind"] == "rig"
    library = client.get("/api/library").json()
    assert [r["name"] for r in library["rigs"]].count("SimpleSkin.gltf") == 1
    assert "SimpleSkin.gltf" not in [m["name"] for m in library["meshes"]]


def link() -> zipfile.ZipInfo:
    info = zipfile.ZipInfo("model/link.png")
    info.external_attr = (stat.S_IFLNK | 0o777) << 16
    return info


def named(name: str) -> zipfile.ZipInfo:
    info = zipfile.ZipInfo("x")
    info.filename = name  # as a hostile zip names it (ZipInfo would clean some names)
    return info


@pytest.mark.parametrize("members, status, words", [
    ({named("../evil.gltf"): b"{}"}, 400, "outside its folder"),
    ({named("/etc/evil.gltf"): b"{}"}, 400, "outside its folder"),
    ({named("C:/evil.gltf"): b"{}"}, 400, "outside its folder"),
    ({named("a/../../evil.glb"): b"x"}, 400, "outside its folder"),
    ({"a.glb": b"x", link(): b"/etc/passwd"}, 400, "is a link"),
    ({**{f"{i}.png": b"x" for i in range(257)}, "a.glb": b"x"}, 413, "at most 256"),
    ({"a.glb": b"x", "big.bin": bytes(UNPACKED_FACTOR * LIMIT + 1)}, 413, "unpacks to"),
    ({"a.gltf": b"{}", "run.exe": b"MZ"}, 415, "run.exe"),
    ({"a.glb": b"x", "b.gltf": b"{}"}, 400, "2 models"),
    ({"only.png": png((1, 2, 3))}, 400, "no model"),
])
def test_refused_zips_say_why_in_one_line_and_leave_nothing(client, members, status, words):
    answer = upload(client, "bad.zip", zipped(members))
    assert answer.status_code == status, answer.text
    message = answer.json()["error"]
    assert "\n" not in message and "bad.zip" in message and words in message
    assert client.library.folder not in message
    assert leftovers(client) == []


def test_a_member_that_unpacks_to_more_than_its_header_says_is_refused(client):
    data = bytearray(zipped({"a.glb": b"x", "data.bin": bytes(10_000)}))
    central = data.rfind(b"PK\x01\x02")  # data.bin's central record: its size says 10 bytes
    data[central + 24:central + 28] = struct.pack("<I", 10)
    answer = upload(client, "liar.zip", bytes(data))
    assert answer.status_code in (400, 413), answer.text
    assert "liar.zip" in answer.json()["error"]
    assert leftovers(client) == []


def test_an_encrypted_member_is_refused(client):
    data = bytearray(zipped({"secret.glb": b"glTF"}, zipfile.ZIP_STORED))
    for signature, at in ((b"PK\x03\x04", 6), (b"PK\x01\x02", 8)):  # the flag: encrypted
        start = data.find(signature)
        data[start + at] |= 0x1
    answer = upload(client, "bad.zip", bytes(data))
    assert answer.status_code == 400 and "encrypted" in answer.json()["error"]
    assert leftovers(client) == []


def test_not_a_zip(client):
    answer = upload(client, "broken.zip", b"PK\x03\x04" + bytes(100))
    assert answer.status_code == 400 and "not a zip" in answer.json()["error"]
    assert upload(client, "text.zip", b"hello").status_code == 415  # not even its signature
    assert leftovers(client) == []


def test_a_lone_gltf_says_to_add_its_files_together(client):
    answer = upload(client, "craft_speederD.gltf", read("textured", "craft_speederD.gltf"))
    assert answer.status_code == 400
    message = answer.json()["error"]
    assert "craft_speederD_data.bin" in message and ".zip" in message
    assert leftovers(client) == []


def test_an_fbx_says_how_to_convert_it(client):
    answer = upload(client, "Stag.fbx", b"Kaydara FBX Binary  \x00\x1a\x00" + bytes(64))
    assert answer.status_code in (400, 415)
    message = answer.json()["error"]
    assert "\n" not in message and "Stag.fbx" in message and "glTF" in message
    assert "Blender" in message


def test_serve_reads_a_zip_given_to_it(tmp_path):
    path = tmp_path / "robot.zip"
    path.write_bytes(zipped({"robot.obj": read("textured", "robot.obj"),
                             "robot.mtl": read("textured", "robot.mtl")}))
    library = Library(str(tmp_path / "library"), k=8)
    try:
        item = library.add_path(str(path))
        assert item.name == "robot.obj" and library.first == {"kind": "mesh", "id": item.id}
        assert len(item.appearance.materials) == 3
        assert item.path.startswith(library.folder + os.sep)
    finally:
        library.close()
