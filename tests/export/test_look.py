"""The video's look is the player's (docs/design.md#exports): the same frame drawn by the page
(`?render&bare&view=player`, headless Chromium, SwiftShader) and by the offline renderer
(moderngl, llvmpipe) differs by rasterisation only — in clay (a bumpy sphere) and in a model's
own materials and textures (MorphStressTest: two materials, three textures, two UV sets). Both
compile the same GLSL (eigendance.shaders); the cameras, studio colours and the material rule
are checked here."""

from __future__ import annotations

import io
import os
import subprocess
import sys

import numpy as np
import pytest
from export_helpers import SONG
from scipy.ndimage import binary_dilation

from eigendance.export.dance import HarmonicDance
from eigendance.export.renderer import Look, Renderer
from eigendance.export.video import render_frames, view_cameras
from eigendance.harmonic.basis import HarmonicBasis
from eigendance.music.mapping import Mapping
from eigendance.music.spectrogram import Spectrogram
from helpers import bumpy_sphere, fixture_path, start

K = 24
STUDIO_TOLERANCE = 2  # 8-bit levels: two rasterisers' rounding of the backdrop's gradient


def model_file(kind: str, folder) -> str:
    """The model of each case: a bumpy sphere written as OBJ (clay), or the textured fixture."""
    if kind == "textured":
        return fixture_path("textured", "MorphStressTest.gltf")
    mesh = bumpy_sphere(3)
    mesh_path = folder / "bumpy.obj"
    with open(mesh_path, "w") as file:
        file.write(("v %.9g %.9g %.9g\n" * mesh.n) % tuple(mesh.original_vertices.ravel()))
        file.write(("f %d %d %d\n" * len(mesh.faces)) % tuple((mesh.faces + 1).ravel()))
    return str(mesh_path)


@pytest.fixture(scope="module", params=["clay", "textured"])
def served(request, tmp_path_factory):
    """`eigendance serve MESH SONG MAPPING -k 24` on a free port, with its files."""
    folder = tmp_path_factory.mktemp("look")
    mesh_path = model_file(request.param, folder)
    rng = np.random.default_rng(11)
    reach = 1.0 if request.param == "clay" else 0.15  # the pieces of the textured one stay whole
    mapping = Mapping(rng.uniform(0, 1, 64), rng.uniform(-reach, reach, K), name="look.json")
    mapping.save(folder / "look.json")
    env = dict(os.environ, EIGENDANCE_CACHE_DIR=str(folder / "cache"))
    sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "web"))
    from web_helpers import free_port  # noqa: E402 - the web tests' helper

    port = free_port()
    process = start([sys.executable, "-m", "eigendance.cli", "serve", str(mesh_path),
                                SONG, str(folder / "look.json"), "-k", str(K), "--port",
                                str(port)], env=env, stdout=subprocess.PIPE,
                    stderr=subprocess.DEVNULL, text=True)
    line = process.stdout.readline()
    assert "serving on" in line, line
    yield {"url": line.split()[-1], "mesh": str(mesh_path), "mapping": mapping,
           "kind": request.param}
    process.terminate()
    process.wait(10)


@pytest.mark.web
def test_the_offline_frame_looks_like_the_players(served, chromium):
    import json
    import urllib.request

    from PIL import Image

    with urllib.request.urlopen(served["url"] + "api/library") as answer:
        library = json.load(answer)
    mapping_id = library["mappings"][0]["id"]
    page = chromium.new_page(viewport={"width": 800, "height": 560})
    try:
        page.goto(served["url"] + f"?render&bare&view=player&path=cpu&mapping={mapping_id}")
        page.wait_for_function("window.eigendance && window.eigendance.ready", timeout=120_000)
        page.evaluate("window.eigendance.ready")
        page.wait_for_function("window.eigendance.info().k > 0", timeout=120_000)
        page.evaluate("window.eigendance.renderAt(2.0)")
        page_look = page.evaluate("window.eigendance.look()")
        area = page.evaluate("(() => { const r = document.getElementById('player-area')"
                             ".getBoundingClientRect(); return [r.left, r.top, r.width,"
                             " r.height]; })()")
        left, top, width, height = (int(round(v)) for v in area)
        shot = page.screenshot(clip={"x": left, "y": top, "width": width, "height": height})
    finally:
        page.close()
    theirs = np.asarray(Image.open(io.BytesIO(shot)).convert("RGB"), dtype=float)
    basis = HarmonicBasis.from_mesh(served["mesh"], K)
    dance = HarmonicDance(basis, Spectrogram.from_file(SONG), served["mapping"])
    frame = next(render_frames([dance], [Look()], [2.0], width, height))
    ours = np.frombuffer(frame, np.uint8).reshape(height, width, 4)[::-1, :, :3].astype(float)
    # The empty studio (backdrop and shadow) under the same camera: the mesh is what differs.
    if served["kind"] == "textured":
        assert page_look is not None and dance.appearance is not None
        assert page_look["images"] == len(dance.appearance.images) == 3
    renderer = Renderer(width, height, dance.faces, dance.rest_normals(), dance.rest,
                        dance.scale, dance.appearance)
    try:
        renderer.begin([(0, 0, width, height)])
        renderer.draw(None, view_cameras([dance], [(0, 0, width, height)])[0], Look())
        studio = renderer.image().astype(float)
    finally:
        renderer.release()
    mesh_theirs = np.any(np.abs(theirs - studio) > STUDIO_TOLERANCE, axis=2)
    mesh_ours = np.any(np.abs(ours - studio) > STUDIO_TOLERANCE, axis=2)
    overlap = (mesh_theirs & mesh_ours).sum() / (mesh_theirs | mesh_ours).sum()
    assert 0.05 < mesh_ours.mean() < 0.8  # framed: the mesh fills part of the view
    # Same camera, same deformation: the silhouettes overlap, and each lies within a pixel of
    # the other (the edges are where two rasterisers differ: a thin model has more of them).
    assert overlap > (0.97 if served["kind"] == "clay" else 0.95), overlap
    for one, other in ((mesh_ours, mesh_theirs), (mesh_theirs, mesh_ours)):
        near = one[binary_dilation(other, iterations=2)].sum() / one.sum()
        print(f"{served['kind']}: {near:.4f} of one silhouette within 2 pixels of the other")
        assert near > 0.995
    both = mesh_theirs & mesh_ours
    difference = np.abs(theirs - ours)
    print(f"{served['kind']}: silhouette overlap {overlap:.4f}, studio difference at most "
          f"{difference[~mesh_theirs & ~mesh_ours].max():.0f} (mean "
          f"{difference[~mesh_theirs & ~mesh_ours].mean():.3f}), mean colour difference "
          f"{difference[both].mean():.2f} (median {np.median(difference[both].max(axis=1)):.1f}, "
          f"90th percentile {np.percentile(difference[both].max(axis=1), 90):.1f}), "
          f"mean colours {theirs[both].mean(axis=0).round(1)} / "
          f"{ours[both].mean(axis=0).round(1)}")
    # same studio: backdrop gradient and contact shadow
    assert difference[~mesh_theirs & ~mesh_ours].max() <= STUDIO_TOLERANCE
    assert difference[~mesh_theirs & ~mesh_ours].mean() < 0.5
    # Same shading and colours. A textured model's edges and thin texture lines (mip levels:
    # SwiftShader and llvmpipe pick them differently; the page antialiases) differ more than a
    # smooth clay: measured mean 0.32 (clay), 9.6 (textured), median 0 and 1.
    assert difference[both].mean() < (4.0 if served["kind"] == "clay" else 14.0)
    assert np.median(difference[both].max(axis=1)) <= 3
    # and the same colour on average: no tint, no brighter or darker light rig
    assert np.abs(theirs[both].mean(axis=0) - ours[both].mean(axis=0)).max() < 2.0
