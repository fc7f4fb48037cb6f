"""Coarse models made of pieces dance without tearing (docs/design.md#gallery).

The low-poly textured cake (552 welded vertices, 7 pieces) and speeder (163) at the page's
k = 150: their top harmonics are a vertex or two zig-zagging. Before the gallery's strain cap
(`music.gallery.PEAK_STRAIN`), tiles #7 and #8 (harmonics 65–148) stretched edges to 16 and 14
times their rest length over the song: the cake's top tore into spikes and facets.
"""

import numpy as np
import pytest

from eigendance.geometry import bounding_box_diagonal, face_edges
from eigendance.harmonic.basis import HarmonicBasis
from eigendance.harmonic.contacts import closest_on_others, components
from eigendance.harmonic.mesh import load_mesh
from eigendance.harmonic.motion import positions_at
from eigendance.inputs.defaults import DEFAULT_K
from eigendance.music.dancer import edge_strain, first_positive_root, fold_scale
from eigendance.music.gallery import initial_gallery
from eigendance.music.spectrogram import Spectrogram
from helpers import fixture_path, folded_over

# An edge at most this many times its rest length in any frame of the song. The cap allows a
# linearised change of 3 rest lengths (a length of at most 4×), measured on the 16 frames that
# move an item most; 4.5 leaves room for the frames it did not look at (the speeder reaches 4.1).
# Main reached 16× (the cake) and 14× (the speeder).
LONGEST = 4.5
# At most this share of the surface's area turned past edge-on (folded over) in any frame of the
# song, in every tile. The cap lets 0.1% fold in the 16 frames that move an item most; frames it
# did not look at reach 0.3% (the cake's item 5). Main folded 0.8% (the cake's item 7), 1.7%
# (the speeder's item 6) and 4.8% (the teapot's item 6): tiles that crumpled into facets.
FOLDED = 0.005
# Pieces that touch at rest (closer than 1% of the diagonal, `part_drift`'s reach) keep their
# offset to within this fraction of the diagonal: less than the gap that counts as touching.
DRIFT = 0.005


@pytest.fixture(scope="module")
def song():
    return Spectrogram.from_file(fixture_path("audio", "kevin_macleod_vibe_ace_0s-21s.ogg"))


@pytest.mark.parametrize("name", ["kenney_cakeBirthday.glb", "craft_speederD.gltf"])
def test_no_tile_tears_or_flies_apart_over_the_whole_song(song, name):
    mesh = load_mesh(fixture_path("textured", name))
    basis = HarmonicBasis.from_mesh(mesh, min(DEFAULT_K, mesh.n - 2), cache=False,
                                    laplacian="robust" if mesh.non_manifold_edge_count()
                                    else "cotan")
    rest = basis.to_original(basis.vertices)
    diagonal = bounding_box_diagonal(rest)
    edges = face_edges(basis.faces)
    length = np.linalg.norm(rest[edges[:, 0]] - rest[edges[:, 1]], axis=1)
    edges, length = edges[length > 1e-3 * diagonal], length[length > 1e-3 * diagonal]
    _, labels = components(len(rest), basis.faces)
    used = np.unique(basis.faces)
    touching = closest_on_others(rest, basis.faces, labels, used,
                                 np.full(len(used), 0.01 * diagonal))
    times = np.arange(0.0, song.duration, 1 / 30)  # the whole song at 30 frames per second
    for number, item in enumerate(initial_gallery(basis, song, 8), start=1):
        moved = positions_at(basis, song, item, times)
        stretched = np.linalg.norm(moved[:, edges[:, 0]] - moved[:, edges[:, 1]], axis=-1)
        longest = (stretched / length).max()
        assert longest <= LONGEST, f"{name} tile #{number}: an edge reaches {longest:.1f}×"
        if len(touching):
            offset = moved[:, touching.vertices] - touching.gather(moved)
            drift = np.linalg.norm(offset - (rest[touching.vertices] - touching.gather(rest)),
                                   axis=-1).max() / diagonal
            assert drift <= DRIFT, f"{name} tile #{number}: touching pieces part by {drift:.4f}"


class Triangle:
    """A dancer of one right triangle whose vertex 1 moves 0.5 along x per unit of φ − 1."""

    vertices = np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0]])
    faces = np.array([[0, 1, 2]])
    diagonal = float(np.sqrt(2))

    def displacements(self, phi):
        moved = np.zeros((len(phi), 3, 3))
        moved[:, 1, 0] = 0.5 * (np.asarray(phi)[:, 0] - 1)
        return moved


def test_edge_strain_is_the_largest_change_of_an_edge_over_its_length():
    # Edge 0–1 (length 1) changes by 0.5 (φ − 1), edge 1–2 (√2) by 0.5 (φ − 1): the first rules.
    assert edge_strain(Triangle(), [[2.0], [3.0], [1.0]]) == pytest.approx([0.5, 1.0, 0.0])
    faceless = type("Faceless", (), {"vertices": Triangle.vertices})()
    assert edge_strain(faceless, [[2.0]]).tolist() == [0.0]  # a rig's modes: not measured


def folded_share(rest, faces, moved):
    """The largest share of the surface's area turned past edge-on in any frame (F, n, 3)."""
    over, area = folded_over(rest, faces, moved)
    return float((over * area).sum(axis=1).max() / area.sum())


@pytest.mark.parametrize("name", ["textured/kenney_cakeBirthday.glb",
                                  "textured/craft_speederD.gltf", "meshes/teapot.obj"])
def test_no_tile_crumples_into_folded_facets(song, name):
    """Issue 30 item 9: a tile's top harmonics folded faces over (a crumpled, faceted look), on
    the coarse textured models and on the smooth teapot alike; measured here by the faces'
    own normals over the whole song at 30 frames per second, not by the cap's arithmetic."""
    mesh = load_mesh(fixture_path(*name.split("/")))
    basis = HarmonicBasis.from_mesh(mesh, min(DEFAULT_K, mesh.n - 2), cache=False,
                                    laplacian="robust" if mesh.non_manifold_edge_count()
                                    else "cotan")
    rest = basis.to_original(basis.vertices)
    times = np.arange(0.0, song.duration, 1 / 30)
    for number, item in enumerate(initial_gallery(basis, song, 8), start=1):
        folded = folded_share(rest, basis.faces, positions_at(basis, song, item, times))
        assert folded <= FOLDED, f"{name} tile #{number}: {100 * folded:.2f}% of the area folds"


def test_the_first_positive_root_of_each_quadratic():
    # 1 − 2t (linear): 0.5; (1 − t)² (a double root): 1; 1 + t² and 1 + t: none;
    # 2 − 3t + t² = (1 − t)(2 − t): 1; 1 − t − 2t² = (1 − 2t)(1 + t): 0.5.
    roots = first_positive_root(np.array([1.0, 1, 1, 1, 2, 1]), np.array([-2.0, -2, 0, 1, -3, -1]),
                                np.array([0.0, 1, 1, 0, 1, -2]))
    assert roots == pytest.approx([0.5, 1.0, np.inf, np.inf, 1.0, 0.5])


class Folding:
    """Two right triangles in z = 0: A (legs 1, area ½) and B (legs √3, area 3/2). Per unit of
    φ − 1, A's third vertex moves (0, −2, 0): A is flat at φ − 1 = ½ (its leg 1 − 2t), then
    inverted; B's third vertex moves (0, −√3/2, 0): flat at 2. A rigid turn about x moves B's
    third vertex along z: never a fold."""

    r = np.sqrt(3.0)
    vertices = np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0], [5, 0, 0], [5 + r, 0, 0], [5, r, 0]])
    faces = np.array([[0, 1, 2], [3, 4, 5]])
    diagonal = 1.0

    def __init__(self, turn=False):
        self.turn = turn

    def displacements(self, phi):
        t = np.asarray(phi, dtype=np.float64)[:, 0] - 1
        moved = np.zeros((len(t), 6, 3))
        moved[:, 2, 1] = -2 * t
        if self.turn:
            moved[:, 5, 2] = self.r * t
        else:
            moved[:, 5, 1] = -self.r / 2 * t
        return moved


def test_fold_scale_is_the_area_quantile_of_each_face_folding():
    # A holds ¼ of the area: from ¼ on it may fold, so B's fold (2) bounds; below ¼, A's (½).
    assert fold_scale(Folding(), [[2.0]], 0.2) == pytest.approx(0.5)
    assert fold_scale(Folding(), [[2.0]], 0.3) == pytest.approx(2.0)
    assert fold_scale(Folding(), [[2.0]], 0.9) == pytest.approx(2.0)  # not B's ¾ as well
    # Measured at φ − 1 = 2 (not 1): the scale is of that motion, so the folds come at half.
    assert fold_scale(Folding(), [[3.0]], 0.2) == pytest.approx(0.25)
    # Of several frames, each face at its earliest fold; a still frame never folds.
    assert fold_scale(Folding(), [[1.0], [3.0], [2.0]], 0.2) == pytest.approx(0.25)
    assert fold_scale(Folding(turn=True), [[2.0]], 0.9) == np.inf  # B turns: A bounds at ½
    assert fold_scale(Folding(turn=True), [[2.0]], 0.2) == pytest.approx(0.5)
    faceless = type("Faceless", (), {"vertices": Folding.vertices})()
    assert fold_scale(faceless, [[2.0]], 0.0) == np.inf  # a rig's modes: not measured
