"""The rig API (docs/web.md#rig-api) with Starlette's TestClient: the library's rigs, the rig
bundle's contract (GPU modal skinning and three.js linear blend skinning reproduce Python),
stiffness and pose edits, the rig gallery, uploads and errors."""

from __future__ import annotations

import json
import shutil

import numpy as np
import pytest
from starlette.testclient import TestClient
from web_helpers import write_song

from eigendance.errors import InputError
from eigendance.modal.model import ModalModel
from eigendance.modal.motion import body_poses, body_transforms, rig_coefficients
from eigendance.modal.palette import default_palette
from eigendance.modal.rig import Rig
from eigendance.modal.rig_gallery import rig_gallery
from eigendance.modal.rotations import rotation_exp
from eigendance.modal.sample_rigs import SAMPLE_RIGS, open_chain, sample_rig
from eigendance.modal.skeleton import Skeleton
from eigendance.modal.skinning import linear_blend_skinning
from eigendance.music.breeding import breed
from eigendance.music.mapping import Mapping
from eigendance.server.app import create_app
from eigendance.server.binary import unpack
from eigendance.server.library import Library
from helpers import fixture_path

ARRAYS = {  # name: (dtype, shape with n vertices, m faces, b bodies, j joints, k modes, G groups)
    "vertices": ("float32", "n,3"), "faces": ("uint32", "m,3"), "tau": ("float32", "n,G,3,4"),
    "rho": ("float32", "n,G,3,4"), "frequencies": ("float32", "k"),
    "amplitudes": ("float32", "k"), "reach": ("float32", "k"), "phases": ("float32", "k"),
    "tile_amplitudes": ("float32", "k"),
    "skin_joints": ("uint32", "n,4"), "skin_weights": ("float32", "n,4"),
    "bone_matrices": ("float32", "b,16"), "bind_matrices": ("float32", "b,16"),
    "body_centers": ("float32", "b,3"), "body_rotations": ("float32", "b,3,3"),
    "body_ends": ("float32", "b,2,3"), "body_radii": ("float32", "b"),
    "body_twists": ("float32", "k,b,6"), "joint_bodies": ("uint32", "j,2"),
    "joint_positions": ("float32", "j,3"), "joint_bend": ("float32", "j,k")}


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    folder = tmp_path_factory.mktemp("rig-files")
    skeleton = folder / "chain.json"
    skeleton.write_text(json.dumps(open_chain(4, "revolute", skin=False).to_dict()))
    rigged = folder / "RiggedSimple.glb"
    shutil.copy(fixture_path("rigged", "RiggedSimple.glb"), rigged)
    return {"song": write_song(folder / "tune.wav", 3.0), "skeleton": str(skeleton),
            "glb": str(rigged), "folder": folder}


@pytest.fixture
def client(files, tmp_path):
    library = Library(str(tmp_path / "library"), k=8, max_upload_bytes=2_000_000)
    for path in (files["song"], files["skeleton"], files["glb"]):
        library.add_path(path)
    with TestClient(create_app(library), base_url="http://localhost") as test_client:
        test_client.library = library
        yield test_client
    library.close()


def rig_id(client, name: str) -> str:
    return next(r["id"] for r in client.get("/api/library").json()["rigs"] if r["name"] == name)


def song_id(client) -> str:
    return client.get("/api/library").json()["songs"][0]["id"]


def bundle(response):
    assert response.status_code == 200, response.text
    assert response.headers["content-type"] == "application/octet-stream"
    return unpack(response.content)


def error_of(response, status):
    assert response.status_code == status, response.text
    body = response.json()
    assert set(body) == {"error"} and "\n" not in body["error"] and body["error"]
    return body["error"]


def test_the_library_lists_built_in_rigs_and_rig_files(client):
    data = client.get("/api/library").json()
    rigs = {r["name"]: r for r in data["rigs"]}
    assert set(SAMPLE_RIGS) <= set(rigs)
    for name in SAMPLE_RIGS:  # analysed when first asked for
        assert rigs[name]["origin"] == "built-in" and not rigs[name]["ready"]
    assert rigs["chain.json"]["ready"] and rigs["chain.json"]["modes"] == 3
    assert rigs["RiggedSimple.glb"] == {**rigs["RiggedSimple.glb"], "origin": "file",
                                        "bodies": 2, "joints": 1, "modes": 3}
    # a skinned glTF is listed once, as a rig
    assert not [m for m in data["meshes"] if m["name"] == "RiggedSimple.glb"]
    assert not [m for m in data["mappings"] if m["name"] == "chain.json"]
    description = client.get(f"/api/rigs/{rigs['loop16']['id']}").json()
    assert description["ready"] and description["modes"] == 13 and description["bodies"] == 16
    assert len(description["joint_list"]) == 16 and description["joint_list"][0]["type"] == \
        "revolute"
    assert all(joint["closes_loop"] for joint in description["joint_list"])  # a ring
    hand = client.get(f"/api/rigs/{rigs['hand']['id']}").json()
    assert not any(joint["closes_loop"] for joint in hand["joint_list"])  # a tree
    assert description["palette"] == default_palette(  # the ring's floor included
        Rig(sample_rig("loop16")).model).to_settings().to_json()


@pytest.mark.parametrize("name", ["loop16", "hand"])
def test_the_rig_bundle_holds_the_contract_of_web_md(client, name):
    meta, arrays = bundle(client.get(f"/api/rigs/{rig_id(client, name)}/rig.bin"))
    rig = Rig.from_skeleton(sample_rig(name))
    sizes = {"n": meta["n"], "m": meta["faces"], "b": meta["bodies"], "j": meta["joints"],
             "k": meta["modes"], "G": meta["groups"]}
    assert sizes == {"n": len(rig.skeleton.vertices), "m": len(rig.skeleton.faces),
                     "b": rig.model.n_bodies, "j": len(rig.skeleton.joints),
                     "k": rig.model.n_modes, "G": (rig.model.n_modes + 3) // 4}
    assert set(arrays) == set(ARRAYS)
    for key, (dtype, shape) in ARRAYS.items():
        assert arrays[key].dtype == np.dtype(dtype), key
        assert arrays[key].shape == tuple(sizes[s] if s in sizes else int(s)
                                          for s in shape.split(",")), key
    np.testing.assert_allclose(arrays["frequencies"], rig.model.frequencies, rtol=1e-6)
    assert meta["palette"] == rig.palette.to_settings().to_json() and meta["offset"] == 0.0
    assert meta["revision"] == 0 and meta["kind"] == "rig" and meta["edited"] is False


def test_gpu_modal_skinning_from_the_packed_texels_equals_python(client):
    """Per vertex i and group g, coordinate d moves by dot(c[4g:4g+4], tau[i, g, d]): the
    positions equal `ModalSkin.positions` within 1e-6 of the diagonal (float32)."""
    meta, arrays = bundle(client.get(f"/api/rigs/{rig_id(client, 'hand')}/rig.bin"))
    rig = Rig.from_skeleton(sample_rig("hand"), dtype=np.float64)  # the float64 reference
    times = np.linspace(0, 2, 5)
    coefficients = rig_coefficients(rig.model, None, None, times)
    padded = np.zeros((len(times), 4 * meta["groups"]))
    padded[:, :meta["modes"]] = coefficients
    groups = padded.reshape(len(times), meta["groups"], 4)
    texel_moves = np.einsum("tgj,ngdj->tnd", groups, arrays["tau"].astype(float))
    positions = arrays["vertices"][None] + texel_moves
    reference = rig.skin.positions(coefficients)
    np.testing.assert_allclose(positions, reference, atol=1e-6 * meta["diagonal"])
    turn = np.einsum("tgj,ngdj->tnd", groups, arrays["rho"].astype(float))
    flat = (coefficients @ rig.skin.rotation).reshape(len(times), -1, 3)
    np.testing.assert_allclose(turn, flat, atol=1e-6 * np.abs(flat).max())


def test_three_js_linear_blend_skinning_from_the_bundle_equals_python(client):
    """Bones: world matrix [R_b exp([θ_b]×) | c_b + R_b x_b] from the body twists; skinning
    matrix = bone · bind (column-major as three.js reads them); four influences."""
    meta, arrays = bundle(client.get(f"/api/rigs/{rig_id(client, 'loop16')}/rig.bin"))
    rig = Rig.from_skeleton(sample_rig("loop16"))
    coefficients = rig_coefficients(rig.model, None, None, [0.3, 1.1])
    twists = np.einsum("tk,kbs->tbs", coefficients, arrays["body_twists"].astype(float))
    rotations = arrays["body_rotations"].astype(float)
    posed = rotations[None] @ rotation_exp(twists[..., :3])
    centres = arrays["body_centers"] + np.einsum("bij,tbj->tbi", rotations, twists[..., 3:])
    reference_rotations, reference_centres = body_poses(rig.model, coefficients)
    np.testing.assert_allclose(posed, reference_rotations, atol=1e-5)
    np.testing.assert_allclose(centres, reference_centres, atol=1e-5)
    bones = np.zeros(posed.shape[:2] + (4, 4))
    bones[..., :3, :3], bones[..., :3, 3], bones[..., 3, 3] = posed, centres, 1
    bind = np.swapaxes(arrays["bind_matrices"].reshape(-1, 4, 4), 1, 2)
    rest_bones = np.swapaxes(arrays["bone_matrices"].reshape(-1, 4, 4), 1, 2)
    np.testing.assert_allclose(rest_bones @ bind, np.broadcast_to(np.eye(4), bind.shape),
                               atol=1e-5)
    skinning = bones @ bind  # (T, b, 4, 4)
    chosen = skinning[:, arrays["skin_joints"].astype(int)]  # (T, n, 4, 4, 4)
    blended = np.einsum("nj,tnjab->tnab", arrays["skin_weights"], chosen)
    vertices = arrays["vertices"].astype(float)
    positions = np.einsum("tnab,nb->tna", blended[..., :3, :3], vertices) + blended[..., :3, 3]
    reference = linear_blend_skinning(rig.skeleton.vertices, rig.skeleton.weights,
                                      body_transforms(rig.model, coefficients))
    np.testing.assert_allclose(positions, reference, atol=1e-5 * meta["diagonal"])
    np.testing.assert_allclose(arrays["skin_weights"].sum(axis=1), 1.0, atol=1e-6)


def test_stiffness_edits_answer_a_new_bundle(client):
    chain = rig_id(client, "chain.json")
    original = client.get(f"/api/rigs/{chain}").json()
    joint = original["joint_list"][1]
    stiffer = [4 * v for v in joint["stiffness"]]
    meta, _ = bundle(client.post(f"/api/rigs/{chain}/stiffness",
                                 json={"joints": {joint["name"]: stiffer}}))
    assert meta["revision"] == 1 and meta["joint_list"][1]["stiffness"] == stiffer
    skeleton = Skeleton.from_dict(json.loads(open(client.library.rigs[chain].source).read()))
    expected = ModalModel.from_skeleton(skeleton.with_stiffness({joint["name"]: stiffer}))
    np.testing.assert_allclose(meta["frequencies"], expected.frequencies, rtol=1e-12)
    meta, _ = bundle(client.post(f"/api/rigs/{chain}/stiffness",
                                 json={"joints": {joint["name"]: "auto"}, "scale": 4}))
    np.testing.assert_allclose(meta["frequencies"], 2 * np.array(original["frequencies"]),
                               rtol=1e-9)
    assert client.get(f"/api/rigs/{chain}").json()["revision"] == 2
    assert "no joint named 'knee'" in error_of(
        client.post(f"/api/rigs/{chain}/stiffness", json={"joints": {"knee": 1}}), 400)
    assert "list of 1 numbers" in error_of(
        client.post(f"/api/rigs/{chain}/stiffness", json={"joints": {"j0": [1, 2]}}), 400)
    for body in ({"joints": []}, {"joints": {}, "scale": "big"}, [1]):
        error_of(client.post(f"/api/rigs/{chain}/stiffness", json=body), 400)
    error_of(client.post(f"/api/rigs/{chain}/stiffness", json={"scale": -1}), 400)
    assert client.get(f"/api/rigs/{chain}").json()["revision"] == 2  # failed edits change nothing


def test_pose_edits_and_reset(client):
    chain = rig_id(client, "chain")
    before, _ = bundle(client.get(f"/api/rigs/{chain}/rig.bin"))
    meta, arrays = bundle(client.post(f"/api/rigs/{chain}/pose",
                                      json={"joint": "j0", "rotation": [0, 0, 1.2]}))
    bent = sample_rig("chain").rotate_joint("j0", [0, 0, 1.2])
    np.testing.assert_allclose(arrays["body_ends"], [[b.start, b.end] for b in bent.bodies],
                               atol=1e-6)
    np.testing.assert_allclose(arrays["vertices"], bent.vertices, atol=1e-6)
    np.testing.assert_allclose(meta["frequencies"], ModalModel.from_skeleton(bent).frequencies,
                               rtol=1e-9)
    assert meta["revision"] == 1 and meta["frequencies"] != before["frequencies"]
    assert meta["edited"] and client.get(f"/api/rigs/{chain}").json()["edited"]
    saved = client.get(f"/api/rigs/{chain}/skeleton.json").json()
    np.testing.assert_allclose(ModalModel.from_skeleton(Skeleton.from_dict(saved)).frequencies,
                               meta["frequencies"], rtol=1e-9)
    meta, _ = bundle(client.post(f"/api/rigs/{chain}/pose", json={"joint": 1,
                                                                   "rotation": [0.1, 0, 0]}))
    assert meta["revision"] == 2
    meta, arrays = bundle(client.post(f"/api/rigs/{chain}/reset"))
    assert meta["revision"] == 3 and not meta["edited"]  # a reset is not an edit
    np.testing.assert_allclose(meta["frequencies"], before["frequencies"], rtol=1e-12)
    np.testing.assert_allclose(arrays["vertices"], sample_rig("chain").vertices, atol=1e-6)
    loop = rig_id(client, "loop8")
    assert "closes a loop" in error_of(client.post(f"/api/rigs/{loop}/pose", json={
        "joint": "j2", "rotation": [0, 0, 0.3]}), 400)
    for body in ({"joint": "j0"}, {"joint": "j0", "rotation": [0, 0]},
                 {"joint": True, "rotation": [0, 0, 1]}, {"joint": "j0", "rotation": [0, "a", 1]}):
        error_of(client.post(f"/api/rigs/{chain}/pose", json=body), 400)
    assert "no joint named 'hip'" in error_of(client.post(f"/api/rigs/{chain}/pose", json={
        "joint": "hip", "rotation": [0, 0, 1]}), 400)


def test_the_rig_gallery_is_the_python_one_and_breeds(client):
    hand, song = rig_id(client, "hand"), song_id(client)
    answer = client.post("/api/rig-gallery", json={"rig": hand, "song": song, "size": 6}).json()
    rig = client.library.rigs[hand].rig
    spectrogram = client.library.songs[song].spectrogram
    expected = rig_gallery(rig.dancer(band_edges=spectrogram.band_edges), spectrogram, 6)
    assert answer["mappings"] == [m.to_json() for m in expected]
    default = Mapping.from_json(answer["default"])
    k = len(rig.palette.selected)
    shaped = default.shaped(spectrogram).values  # its swell (envelope) included
    assert np.abs(default.filter(shaped, k, offset=0.0)).max() == pytest.approx(1.0)
    parents = answer["mappings"][1:3]
    children = client.post("/api/breed", json={"parents": parents, "size": 4, "seed": 5}).json()
    direct = breed([Mapping.from_json(p) for p in parents], 4, 5)
    assert children["mappings"] == [m.to_json() for m in direct]
    assert "gallery has 2 to 16" in error_of(client.post("/api/rig-gallery", json={
        "rig": hand, "song": song, "size": 40}), 400)
    error_of(client.post("/api/rig-gallery", json={"rig": "nope", "song": song}), 404)
    error_of(client.post("/api/rig-gallery", json={"rig": hand, "song": "nope"}), 404)
    error_of(client.post("/api/rig-gallery", content=b"[1]",
                         headers={"Content-Type": "application/json"}), 400)


def test_rig_uploads(client, files):
    with open(files["skeleton"], "rb") as file:
        skeleton = file.read()
    same = client.post("/api/upload?name=again.json", content=skeleton)  # the file given to serve
    assert same.status_code == 200 and same.json()["item"]["id"] == rig_id(client, "chain.json")
    answer = client.post("/api/upload?name=my%20chain.json", content=skeleton + b"\n")
    assert answer.status_code == 201 and answer.json()["kind"] == "rig"
    item = answer.json()["item"]
    assert item["name"] == "my chain.json" and item["ready"] and item["origin"] == "upload"
    with open(fixture_path("rigged", "SimpleSkin.gltf"), "rb") as file:
        answer = client.post("/api/upload?name=skin.gltf", content=file.read())
    assert answer.status_code == 201 and answer.json()["kind"] == "rig"  # listed once, a rig
    assert answer.json()["item"]["modes"] == 3
    assert not [m for m in client.get("/api/library").json()["meshes"]
                if m["name"] == "skin.gltf"]
    bad = open_chain(2, skin=False).to_dict()
    bad["joints"][0]["type"] = "hinge"
    before = [r["id"] for r in client.get("/api/library").json()["rigs"]]
    message = error_of(client.post("/api/upload?name=bad.json",
                                   content=json.dumps(bad).encode()), 400)
    assert "bad.json: joint 'j0' has unknown type 'hinge'" in message
    assert [r["id"] for r in client.get("/api/library").json()["rigs"]] == before


@pytest.mark.parametrize("path", ["/api/rigs/nope", "/api/rigs/nope/rig.bin",
                                  "/api/rigs/nope/skeleton.json"])
def test_unknown_rigs_are_404_json(client, path):
    assert "no rig with id 'nope'" in error_of(client.get(path), 404)
    for route in ("stiffness", "pose", "reset"):
        error_of(client.post(f"/api/rigs/nope/{route}", json={}), 404)


def test_a_rig_without_vibration_modes_has_no_gallery(client):
    chain = rig_id(client, "chain.json")
    meta, arrays = bundle(client.post(f"/api/rigs/{chain}/stiffness", json={"scale": 0}))
    assert meta["modes"] == 0 and meta["palette"] is None and arrays["tau"].shape[1] == 0
    assert "no vibration mode" in error_of(client.post("/api/rig-gallery", json={
        "rig": chain, "song": song_id(client)}), 409)


def test_a_skinned_gltf_given_alone_opens_as_a_rig(files, tmp_path):
    """`eigendance serve Stag.glb song.mp3`: the library reports the rig as what opens first."""
    library = Library(str(tmp_path / "alone"), k=8)
    try:
        library.add_path(files["glb"])
        library.add_path(files["song"])
        data = library.as_json()
        assert data["first"]["kind"] == "rig"
        assert data["first"]["id"] == next(r["id"] for r in data["rigs"]
                                           if r["name"] == "RiggedSimple.glb")
        assert not data["meshes"]
    finally:
        library.close()


def test_a_skinned_gltf_whose_skin_cannot_be_analysed_dances_as_a_mesh(files, tmp_path):
    from eigendance.server import analysis

    library = Library(str(tmp_path / "broken"), k=8)
    run = library.intake.run

    def refuse(function, *args, **options):  # the rig's analysis (in a worker) refuses the skin
        if function is analysis.analyse_rig:
            raise InputError(f"{args[2]}: body 'x' has zero length")
        return run(function, *args, **options)

    library.intake.run = refuse
    try:
        item = library.add_path(files["glb"])
        assert item.name == "RiggedSimple.glb" and item in library.meshes.values()
        assert library.as_json()["first"] == {"kind": "mesh", "id": item.id}
    finally:
        library.close()
