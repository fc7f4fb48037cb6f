"""Small dances for the export tests: a bumpy sphere by its harmonics, rigs by their modes."""

from __future__ import annotations

import numpy as np
import pytest
from export_helpers import LONG_SONG, SONG, rig

from eigendance.export.dance import HarmonicDance
from eigendance.export.rig_dance import rig_dance
from eigendance.harmonic.basis import HarmonicBasis
from eigendance.harmonic.mesh import Mesh, load_mesh
from eigendance.modal.surface import SurfaceDance
from eigendance.music.gallery import initial_gallery, strongest_item
from eigendance.music.spectrogram import Spectrogram
from helpers import bumpy_sphere, fixture_path


@pytest.fixture(scope="session")
def song():
    return Spectrogram.from_file(SONG)


@pytest.fixture(scope="session")
def basis():
    # Moved off the origin and scaled: exports are in the file's coordinates.
    mesh = bumpy_sphere(2)
    moved = Mesh.from_arrays(mesh.original_vertices * 2.5 + [3.0, -1.0, 0.5], mesh.faces)
    return HarmonicBasis.from_mesh(moved, 40, cache=False)


@pytest.fixture(scope="session")
def reduced_harmonic(song):
    """The bumpy sphere by a reduced basis (docs/design.md#reduced-basis): a skin on its
    samples in a glb."""
    mesh = bumpy_sphere(3)
    moved = Mesh.from_arrays(mesh.original_vertices * 2.5 + [3.0, -1.0, 0.5], mesh.faces)
    basis = HarmonicBasis.from_mesh(moved, 24, cache=False, construction="reduced", samples=160)
    mapping = initial_gallery(basis, song, 4)[2]
    return HarmonicDance(basis, song, mapping, audio=SONG, name="reduced")


@pytest.fixture(scope="session")
def mappings(basis, song):
    return initial_gallery(basis, song, 4)


@pytest.fixture(scope="session")
def harmonic(basis, song):
    mapping = strongest_item(basis, song)
    mapping.gain, mapping.smoothing = 1.5, 0.05  # both must reach the exports
    return HarmonicDance(basis, song, mapping, audio=SONG, name="sphere")


@pytest.fixture(scope="session")
def chain_lbs(song):
    return rig("chain", "lbs", song)


@pytest.fixture(scope="session")
def figure_modal(song):
    return rig(fixture_path("rigged", "RiggedFigure.glb"), "modal", song)


@pytest.fixture(scope="session")
def fox_lbs(song):
    return rig(fixture_path("rigged", "Fox.glb"), "lbs", song)


@pytest.fixture
def chromium(browser):
    return browser


@pytest.fixture(scope="session")
def long_song():
    return Spectrogram.from_file(LONG_SONG)


@pytest.fixture(scope="session")
def cake_basis():
    """A textured model of several pieces (the Kenney cake: 7 materials, an instanced mesh)."""
    return HarmonicBasis.from_mesh(load_mesh(fixture_path("textured", "kenney_cakeBirthday.glb")),
                                   40, laplacian="robust", cache=False)


@pytest.fixture(scope="session")
def cake(cake_basis, long_song):
    """The cake on a 21 s song: gallery item 2 (32 harmonics) with amplifications of
    alternating sign, at gain 4, so that morph weights go below 0 and above 1 — what importers
    that clamp weights to [0, 1] must survive."""
    item = initial_gallery(cake_basis, long_song, 4)[2]
    signs = np.where(np.arange(len(item.amplification)) % 2, -1.0, 1.0)
    mapping = item.with_genes(item.transfer, item.amplification * signs, item.seed, "alternating")
    mapping.gain = 4.0
    return HarmonicDance(cake_basis, long_song, mapping, audio=LONG_SONG, name="cake")


@pytest.fixture(scope="session")
def gun_lbs(long_song):
    """A rig with a textured skin and a gun attached to its hand bone, on the 21 s song."""
    return rig(fixture_path("rigged", "quaternius_Character_Gun.glb"), "lbs", long_song,
               audio=LONG_SONG)


@pytest.fixture(scope="session")
def gun_modal(long_song):
    return rig(fixture_path("rigged", "quaternius_Character_Gun.glb"), "modal", long_song,
               audio=LONG_SONG)


@pytest.fixture(scope="session")
def gun_surface(long_song):
    """The gun rig on the 21 s song with its skin rippling too (docs/design.md#surface-of-a-rig):
    gallery item 2 of the skin's harmonics with amplifications of alternating sign at gain 4,
    so that the surface's morph weights go below 0 and above 1 under the skin."""
    dance = rig(fixture_path("rigged", "quaternius_Character_Gun.glb"), "lbs", long_song,
                audio=LONG_SONG)
    harmonics = dance.rig.surface(40, cache=False)
    item = initial_gallery(harmonics.basis, long_song, 4)[2]
    signs = np.where(np.arange(len(item.amplification)) % 2, -1.0, 1.0)
    mapping = item.with_genes(item.transfer, item.amplification * signs, item.seed, "ripple")
    mapping.gain = 4.0
    return rig_dance(dance.rig, long_song, dance.rig.mapping(long_song, None), "lbs", LONG_SONG,
                     "surface-rig", surface=SurfaceDance(harmonics, long_song, mapping))
