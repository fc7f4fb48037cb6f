"""The whole body dances (docs/design.md#surface-of-a-rig): a rig's skin ripples in its
harmonics, applied in the bind pose before skinning, while its bones sway in their modes."""

import numpy as np
import pytest

from eigendance.errors import EigendanceError
from eigendance.harmonic.contacts import part_drift
from eigendance.modal.rig import Rig
from eigendance.modal.sample_rigs import load_rig
from eigendance.modal.surface import SurfaceDance, surface_share
from eigendance.music.gallery import initial_gallery
from eigendance.music.spectrogram import Spectrogram
from helpers import fixture_path

LONG_SONG = fixture_path("audio", "kevin_macleod_vibe_ace_0s-21s.ogg")
K = 40


@pytest.fixture(scope="module")
def song():
    return Spectrogram.from_file(LONG_SONG)


@pytest.fixture(scope="module")
def gun():
    """A real rig of several pieces: a textured character with a gun on its hand bone."""
    return Rig(load_rig(fixture_path("rigged", "quaternius_Character_Gun.glb")), np.float64)


def surface_dance(rig, song, item=1, gain=1.0):
    mapping = initial_gallery(rig.surface(K, cache=False).basis, song, 4)[item]
    mapping.gain = gain
    return SurfaceDance(rig.surface(K, cache=False), song, mapping)


def test_the_ripple_is_the_harmonic_half_of_the_same_skin(gun, song):
    """d = X_φ − X of the skin's basis (`HarmonicBasis.filter_positions`, the harmonic half's
    own path), in the rig's units, for every skin vertex."""
    dance = surface_dance(gun, song)
    times = np.array([3.0, 11.0])
    basis = dance.harmonics.basis
    expected = basis.to_original(basis.filter_positions(dance.phi(times))) - \
        basis.to_original(basis.vertices)
    found = dance.displacements(times)
    kept = dance.harmonics.vertex_map
    assert (kept >= 0).all()
    np.testing.assert_allclose(found, expected[:, kept], atol=1e-12 * basis.scale)
    assert np.abs(found).max() > 1e-3 * basis.scale  # it ripples


def test_a_vertex_on_one_bone_carries_its_ripple_turned_by_that_bone(gun, song):
    """Linear blend skinning of x + d for a vertex with all its weight on body b is
    T_b (x + d): the skinned ripple is R_b d, R_b the body's rotation."""
    times = np.array([2.0, 9.5, 17.0])
    c = gun.coefficients(song, None, times)
    d = surface_dance(gun, song).displacements(times)
    weights = np.asarray(gun.skeleton.weights.todense() if hasattr(gun.skeleton.weights, "todense")
                         else gun.skeleton.weights)
    single = np.flatnonzero(weights.max(axis=1) > 1 - 1e-12)
    body = weights[single].argmax(axis=1)
    rotations = gun.body_transforms(c)[:, body, :3, :3]  # (T, s, 3, 3)
    ripple = gun.positions(c, "lbs", surface=d) - gun.positions(c, "lbs")
    np.testing.assert_allclose(ripple[:, single],
                               np.einsum("tsij,tsj->tsi", rotations, d[:, single]), atol=1e-9)
    assert len(single) > 100


def test_modal_skinning_of_the_ripple_agrees_with_linear_blend_to_first_order(gun, song):
    times = np.linspace(1, 20, 7)
    d = surface_dance(gun, song).displacements(times)

    def gap(scale):
        c = scale * gun.coefficients(song, None, times)
        return np.abs(gun.positions(c, "modal", surface=d) -
                      gun.positions(c, "lbs", surface=d)).max()

    assert 3.2 < gap(0.2) / gap(0.1) < 4.8  # halving the bones' amplitude quarters the gap


def test_touching_pieces_stay_together_with_the_surface_on(gun, song):
    """The tearing statistic of issue 23 (`contacts.part_drift`) over the whole body's motion
    on a 21 s song stays ≤ 0.3."""
    times = np.linspace(0, 20.9, 40)
    c = gun.coefficients(song, None, times)
    rest = gun.skeleton.vertices
    for item in range(4):
        d = surface_dance(gun, song, item).displacements(times)
        whole = gun.positions(c, "lbs", surface=d)
        assert part_drift(rest, gun.skeleton.faces, whole - rest) <= 0.3
        assert part_drift(rest, gun.skeleton.faces, d) <= 0.3  # the ripple alone


def test_the_gain_sets_the_surfaces_share_of_the_motion(gun, song):
    times = np.linspace(0, 20.9, 30)
    c = gun.coefficients(song, None, times)
    bones = gun.positions(c, "lbs")
    shares = [surface_share(bones, gun.positions(
        c, "lbs", surface=surface_dance(gun, song, 1, gain).displacements(times)),
        gun.skeleton.vertices) for gain in (0.0, 0.5, 1.0, 4.0)]
    assert shares[0] == 0.0
    assert 0 < shares[1] < shares[2] < shares[3] < 1


def test_a_surface_mapping_of_other_bands_is_refused(gun, song):
    from eigendance.music.mapping import Mapping
    with pytest.raises(EigendanceError, match="bands"):
        SurfaceDance(gun.surface(K, cache=False), song, Mapping(np.zeros(8), np.ones(K)))


def test_a_rig_dance_carries_and_breeds_its_surface_genes(tmp_path):
    """A rig's mapping holds its skin's mapping (`surface`, in the file too); breeding two such
    dances crosses their surface genes as it crosses any mapping's (the same draws as breeding
    the two surface mappings alone), and a parent without them passes none."""
    from eigendance.music.breeding import SURFACE_STREAM, breed
    from eigendance.music.mapping import Mapping

    ripple_a = Mapping(np.linspace(0, 0.5, 8), np.ones(6), name="a")
    ripple_b = Mapping(np.linspace(0.5, 1, 8), -np.ones(6), name="b")
    first = Mapping(np.linspace(0, 1, 8), np.ones(3), name="one", surface=ripple_a)
    second = Mapping(np.linspace(1, 0, 8), np.ones(3), name="two", surface=ripple_b, gain=2.0)
    first.save(tmp_path / "one.json")
    assert Mapping.load(tmp_path / "one.json").surface.transfer.tolist() == \
        ripple_a.transfer.tolist()
    children = breed([first, second], 4, seed=5)
    for index, child in enumerate(children):  # parents i, j in the order the child drew them
        pair = [ripple_a, ripple_b] if child.gain == 1.0 else [ripple_b, ripple_a]
        alone = breed(pair, 1, 5 + SURFACE_STREAM + index)[0]
        assert child.surface.transfer.tolist() == alone.transfer.tolist()
        assert child.surface.amplification.tolist() == alone.amplification.tolist()
    plain = Mapping(np.linspace(1, 0, 8), np.ones(3), name="plain")
    assert all(child.surface is None or child.surface == ripple_a
               for child in breed([first, plain], 6, seed=2))
    with pytest.raises(EigendanceError, match="surface of its own"):
        Mapping(np.zeros(8), np.ones(3), surface=first)


def test_the_videos_frames_carry_the_ripple_with_the_moved_skins_normals(gun, song):
    """What `render` draws (`RigDance.frames`, modal skinning): the positions of
    `Rig.positions(c, "modal", surface=d)` and unit normals of the moved skin."""
    from eigendance.export.rig_dance import rig_dance
    from eigendance.geometry import vertex_normals

    ripple = surface_dance(gun, song, 2)
    dance = rig_dance(gun, song, None, "modal", surface=ripple).window(5.0, 2.0)
    times = np.array([0.0, 0.5, 1.5])
    (first, positions, normals), = list(dance.frames(times))
    c = dance.pose(times)[1]
    expected = gun.positions(c, "modal", surface=ripple.displacements(5.0 + times))
    np.testing.assert_allclose(positions, expected, atol=1e-5 * ripple.harmonics.basis.scale)
    # the normals of positions equal within 1e-5 of the scale: a vertex among small faces turns
    # its normal by ~1e-5 for that (1 of 7,152 components at 1.04e-5 after the contacts' cap)
    np.testing.assert_allclose(normals[1], vertex_normals(positions[1], gun.skeleton.faces,
                                                          [0.0, 0, 1]), atol=1e-4)
    assert first == 0
