"""Exports keep the model's look (docs/design.md#exports, #appearance): the glb its materials,
UVs and embedded textures, one primitive per material; USD binds UsdPreviewSurface materials
with the textures beside it (usd-core's compliance checker passes); the OBJ beside a .pc2 its
MTL and images, its vertices the point cache's, in order; a rig's export every mesh and
material of its source. The files are read back with pygltflib, usd-core and by hand — tools
independent of the writer."""

from __future__ import annotations

import os
import warnings

import numpy as np
import pygltflib
import pytest
from export_helpers import LONG_SONG
from pxr import Usd, UsdGeom, UsdShade, UsdUtils

from eigendance.export.dance import HarmonicDance
from eigendance.export.files import export_dance
from eigendance.export.pointcache import read_pc2
from eigendance.harmonic.basis import HarmonicBasis
from eigendance.harmonic.mesh import load_mesh
from eigendance.music.gallery import strongest_item
from helpers import fixture_path


@pytest.fixture(scope="module")
def textured(long_song):
    """MorphStressTest: 2 materials, 3 PNG textures (base colour, occlusion on UV set 1)."""
    basis = HarmonicBasis.from_mesh(load_mesh(fixture_path("textured", "MorphStressTest.gltf")),
                                    16, cache=False)
    return HarmonicDance(basis, long_song, strongest_item(basis, long_song, 4), LONG_SONG,
                         name="morph")


def glb_document(path) -> pygltflib.GLTF2:
    return pygltflib.GLTF2().load(str(path))


def test_the_glb_keeps_materials_uvs_and_embedded_textures(textured, tmp_path):
    export_dance(textured, tmp_path / "morph.glb", fps=2)
    document = glb_document(tmp_path / "morph.glb")
    look = textured.appearance
    assert [m.name for m in document.materials] == [m.name for m in look.materials]
    primitives = document.meshes[0].primitives
    assert len(primitives) == len(look.parts) == 2  # one per material
    assert sorted(p.material for p in primitives) == [0, 1]
    assert primitives[0].attributes.TEXCOORD_0 is not None
    assert primitives[0].attributes.TEXCOORD_1 is not None
    blob = document.binary_blob()
    found = []
    for image in document.images:
        assert image.uri is None  # embedded
        view = document.bufferViews[image.bufferView]
        found.append(blob[view.byteOffset:view.byteOffset + view.byteLength])
    assert found == [image.data for image in look.images]
    base = document.materials[1].pbrMetallicRoughness.baseColorTexture
    assert base is not None and document.textures[base.index].source is not None
    occlusion = document.materials[0].occlusionTexture
    assert occlusion is not None and occlusion.texCoord == 1


def test_a_rig_export_keeps_every_material_and_the_prop(gun_lbs, tmp_path):
    export_dance(gun_lbs, tmp_path / "gun.glb", fps=2)
    document = glb_document(tmp_path / "gun.glb")
    source = glb_document(fixture_path("rigged", "quaternius_Character_Gun.glb"))
    assert sorted(m.name for m in document.materials) == sorted(m.name for m in
                                                                source.materials)
    drawn = sum(document.accessors[p.indices].count for p in document.meshes[0].primitives)
    assert drawn == 3 * len(gun_lbs.appearance.triangles)  # every triangle of every mesh


def test_usd_binds_preview_surfaces_with_the_textures(textured, tmp_path):
    path = tmp_path / "morph.usda"
    report = export_dance(textured, path, fps=2)
    textures = [f for f in report["files"] if "_texture" in f]
    assert len(textures) == 3 and all(os.path.getsize(f) > 0 for f in textures)
    stage = Usd.Stage.Open(str(path))
    mesh = UsdGeom.Mesh(stage.GetPrimAtPath("/Dance/Mesh"))
    subsets = UsdGeom.Subset.GetAllGeomSubsets(mesh)
    assert len(subsets) == 2
    files = set()
    for subset in subsets:
        material, _ = UsdShade.MaterialBindingAPI(subset.GetPrim()).ComputeBoundMaterial()
        assert material, subset.GetPath()
        for prim in Usd.PrimRange(material.GetPrim()):
            shader = UsdShade.Shader(prim)
            if shader and shader.GetIdAttr().Get() == "UsdUVTexture":
                files.add(shader.GetInput("file").Get().path)
    assert files == {os.path.basename(f) for f in textures}
    st = UsdGeom.PrimvarsAPI(mesh).GetPrimvar("st")
    assert st.GetInterpolation() == UsdGeom.Tokens.faceVarying
    assert len(st.GetIndices()) == 3 * len(mesh.GetFaceVertexCountsAttr().Get())
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", "Use of UsdUtils.ComplianceChecker is deprecated")
        checker = UsdUtils.ComplianceChecker()
    checker.CheckCompliance(str(path))
    assert not checker.GetErrors() and not checker.GetFailedChecks(), \
        (checker.GetErrors(), checker.GetFailedChecks())


def test_the_obj_beside_a_point_cache_keeps_its_mtl_and_images(textured, tmp_path):
    report = export_dance(textured, tmp_path / "morph.pc2", fps=2)
    names = {os.path.basename(f) for f in report["files"]}
    assert {"morph.pc2", "morph.obj", "morph.mtl", "morph_texture0.png"} <= names
    text = (tmp_path / "morph.obj").read_text()
    vertices = np.array([line.split()[1:] for line in text.splitlines()
                         if line.startswith("v ")], dtype=float)
    positions, _, _ = read_pc2(tmp_path / "morph.pc2")
    np.testing.assert_allclose(vertices, positions[0], atol=1e-6 * textured.diagonal)
    assert "mtllib morph.mtl" in text and text.count("usemtl ") == 2
    assert sum(line.startswith("vt ") for line in text.splitlines()) == \
        textured.appearance.n
    mtl = (tmp_path / "morph.mtl").read_text()
    assert mtl.count("newmtl ") == 2 and "map_Kd morph_texture" in mtl
