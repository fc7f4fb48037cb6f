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
from eigendance.music.dancer import edge_strain
from eigendance.music.gallery import initial_gallery
from eigendance.music.spectrogram import Spectrogram
from helpers import fixture_path

# An edge at most this many times its rest length in any frame of the song. The cap allows a
# linearised change of 3 rest lengths (a length of at most 4×), measured on the 16 frames that
# move an item most; 4.5 leaves room for the frames it did not look at (the speeder reaches 4.1).
# Main reached 16× (the cake) and 14× (the speeder).
LONGEST = 4.5
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
