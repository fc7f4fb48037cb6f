"""The initial gallery (docs/design.md#gallery): every item dances, visibly and differently, on
several meshes × songs, checked against displacements computed directly (not through the Gram
matrices the gallery uses)."""

import json
import os
import shutil
import subprocess

import numpy as np
import pytest

from eigendance.cli import main
from eigendance.errors import EigendanceError
from eigendance.harmonic.basis import HarmonicBasis
from eigendance.music.breeding import Mulberry32, breed, cross
from eigendance.music.dancer import gallery_correlations, gallery_motion
from eigendance.music.demo_music import demo_track
from eigendance.music.envelope import Pulse
from eigendance.music.filter import harmonic_indices
from eigendance.music.gallery import (
    FOLD_SHARE,
    MAX_GALLERY,
    MIN_GALLERY,
    MOTION_BOUNDS,
    MOTION_HIGHEST,
    MOTION_LOWEST,
    drivable_harmonics,
    initial_gallery,
    motion_content,
    strongest_item,
)
from eigendance.music.mapping import Mapping
from eigendance.music.spectrogram import Spectrogram
from helpers import bumpy_sphere, fixture_path, folded_over, required, sphere

CAT = os.path.join(os.path.dirname(__file__), "..", "..", "src", "eigendance", "data",
                   "cat_lowres.obj")
LOW, HIGH = MOTION_BOUNDS
JS = os.path.join(os.path.dirname(__file__), "..", "js", "breed_reference.mjs")


@pytest.fixture(scope="module")
def meshes():
    """Bases of meshes made by code, fixture meshes and the built-in cat (small k: fast)."""
    return {"icosphere": HarmonicBasis.from_mesh(sphere(3), 40, cache=False),
            "bumpy sphere": HarmonicBasis.from_mesh(bumpy_sphere(2), 40, cache=False),
            "knight": HarmonicBasis.from_mesh(fixture_path("meshes", "decimated-knight.off"),
                                              60, cache=False),
            "teapot": HarmonicBasis.from_mesh(fixture_path("meshes", "teapot.obj"), 40,
                                              cache=False),
            "beetle": HarmonicBasis.from_mesh(fixture_path("meshes", "beetle.obj"), 40,
                                              laplacian="robust", cache=False),
            "cat": HarmonicBasis.from_mesh(CAT, 60, cache=False)}


@pytest.fixture(scope="module")
def songs():
    demo = Spectrogram.from_samples(*demo_track(6.0))
    vibe, rate = fixture_path("audio", "kevin_macleod_vibe_ace_20s-24s.ogg"), None
    trumpet = Spectrogram.from_file(fixture_path("audio", "sorohanro_solo_trumpet_06.ogg"))
    vibe = Spectrogram.from_file(vibe)
    samples, rate = demo_track(4.0)
    quiet = Spectrogram.from_samples(samples * 10 ** (-45 / 20), rate)  # 45 dB down
    return {"demo": demo, "vibe ace": vibe, "trumpet": trumpet, "quiet demo": quiet}


def direct_motion(basis, song, mapping):
    """RMS displacement / diagonal of every frame, from the positions themselves (T,)."""
    phi = mapping.play(song, song.times, basis.k)  # envelope and pulse included
    moved = basis.displacements(phi)
    return np.sqrt((moved ** 2).sum(axis=2).mean(axis=1)) / basis.diagonal


def direct_correlations(basis, song, gallery):
    """Correlations of the displacement fields over the song, from the positions themselves."""
    fields = np.array([basis.displacements(item.play(song, song.times, basis.k)).ravel()
                       for item in gallery])
    norms = np.linalg.norm(fields, axis=1)
    return fields @ fields.T / np.outer(norms, norms)


def zero_eigenvalue_harmonics(basis):
    return np.flatnonzero(basis.eigenvalues < 1e-9 * basis.eigenvalues[-1])


@pytest.mark.parametrize("name", ["icosphere", "bumpy sphere", "knight"])
def test_motion_and_correlations_equal_the_positions_themselves(meshes, songs, name):
    basis, song = meshes[name], songs["vibe ace"]
    gallery = initial_gallery(basis, song, 8)
    motion = gallery_motion(basis, song, gallery)
    for item, measured in zip(gallery, motion, strict=True):
        rms = direct_motion(basis, song, item)
        assert measured.motion == pytest.approx(np.percentile(rms, 95), rel=1e-9)
        assert measured.peak == pytest.approx(rms.max(), rel=1e-9)
    np.testing.assert_allclose(gallery_correlations(basis, song, gallery),
                               direct_correlations(basis, song, gallery), atol=1e-9)


@pytest.mark.parametrize("size", [2, 3, 8, 16])
def test_every_item_dances_visibly_and_differently_on_every_mesh_and_song(meshes, songs, size):
    for mesh_name, basis in meshes.items():
        for song_name, song in songs.items():
            where = f"{mesh_name}, {song_name}, S = {size}"
            gallery = initial_gallery(basis, song, size)
            motion = gallery_motion(basis, song, gallery)
            for number, measured in enumerate(motion):
                assert measured.motion <= HIGH, f"{where}: item {number} m = " \
                    f"{measured.motion:.4f}"
                if measured.motion < LOW:  # only where more would fold its surface over
                    assert folded_weight(basis, song, gallery[number], 1.05) > FOLD_SHARE, \
                        f"{where}: item {number} m = {measured.motion:.4f}, nothing folds"
                    assert measured.motion >= LOW / 5, f"{where}: item {number} is still"
                assert measured.peak <= 0.15 + 1e-9, f"{where}: item {number} explodes"
            correlations = np.abs(gallery_correlations(basis, song, gallery))
            np.fill_diagonal(correlations, 0)
            assert correlations.max() <= 0.9, f"{where}: items correlate " \
                f"{correlations.max():.3f}"
            zero = zero_eigenvalue_harmonics(basis)
            for item in gallery:  # eigenvalue-0 harmonics (translations) are never driven
                assert not np.isin(harmonic_indices(item.transfer, basis.k), zero).any(), where
                assert (item.amplification[zero] == 0).all(), where


def test_items_drive_the_spectrum_from_low_to_high(meshes, songs):
    for name in ("bumpy sphere", "knight", "teapot", "beetle", "cat"):
        basis = meshes[name]
        drivable = drivable_harmonics(basis)
        for size in (4, 8, 16):
            motion = gallery_motion(basis, songs["demo"], initial_gallery(basis, songs["demo"],
                                                                         size))
            lowest = [item.lowest for item in motion]
            highest = [item.highest for item in motion]
            assert lowest[0] == highest[0] == drivable[0], name
            assert lowest[-1] == highest[-1] == drivable[-1], name
            assert (np.diff(lowest) > 0).all() and (np.diff(highest) > 0).all(), \
                f"{name}, S = {size}: ranges {list(zip(lowest, highest, strict=True))}"
            targets = [item.motion for item in motion]  # calibrated exactly on the song
            np.testing.assert_allclose(targets[0], MOTION_LOWEST, rtol=1e-9)
            if targets[-1] < MOTION_HIGHEST * (1 - 1e-9):  # only where it would fold over
                item = initial_gallery(basis, songs["demo"], size)[-1]
                assert folded_weight(basis, songs["demo"], item, 0.99) <= FOLD_SHARE, name
                assert folded_weight(basis, songs["demo"], item, 1.05) > FOLD_SHARE, name
            else:
                np.testing.assert_allclose(targets[-1], MOTION_HIGHEST, rtol=1e-9)


def folded_weight(basis, song, item, factor):
    """The share of the surface's area folded over (a face's normal against its rest normal) in
    the 16 frames that move the item most, its motion scaled by `factor`, from positions
    computed directly rather than from the calibration's roots."""
    times = np.arange(0.0, song.duration, 0.01)
    phi = item.play(song, times, basis.k)
    rest = basis.vertices
    moved = basis.filter_positions(1 + factor * (phi - 1))
    loudest = np.argsort(np.sqrt(((moved - rest) ** 2).sum(-1).mean(-1)))[-16:]
    over, area = folded_over(rest, basis.faces, moved[loudest])
    over = over.any(axis=0)  # a face folded in any of them
    return float(area[over].sum() / area.sum())


def test_initial_items_span_what_breeding_needs(meshes, songs):
    """Per band, the transfers reach from the lowest to the highest drivable harmonic; per
    drivable harmonic, the amplifications hold both signs; any initial transfer crossed with any
    initial amplification moves the model as much as the transfer's own item."""
    basis, song = meshes["knight"], songs["trumpet"]
    drivable = drivable_harmonics(basis)
    for size in (2, 5, 8):
        gallery = initial_gallery(basis, song, size)
        targets = np.array([harmonic_indices(item.transfer, basis.k) for item in gallery])
        assert (targets.min(axis=0) == drivable[0]).all()
        assert (targets.max(axis=0) == drivable[-1]).all()
        amplification = np.array([item.amplification for item in gallery])
        assert (amplification[:, drivable].max(axis=0) > 0).all()
        assert (amplification[:, drivable].min(axis=0) < 0).all()
        others = np.setdiff1d(np.arange(basis.k), drivable)
        assert (amplification[:, others] == 0).all()
        own = [measured.motion for measured in gallery_motion(basis, song, gallery)]
        for i, item in enumerate(gallery):
            crossed = [item.with_genes(item.transfer, other.amplification, None, "crossed")
                       for other in gallery]
            np.testing.assert_allclose([m.motion for m in gallery_motion(basis, song, crossed)],
                                       own[i], rtol=1e-9)


def test_children_of_the_initial_gallery_move(meshes, songs):
    basis, song = meshes["cat"], songs["demo"]
    gallery = initial_gallery(basis, song, 8)
    children = breed([gallery[1], gallery[4], gallery[6]], 8, seed=3)
    assert all(item.motion > 0.002 for item in gallery_motion(basis, song, children))


def test_a_quiet_song_moves_as_visibly_as_a_loud_one_and_silence_stays_still(meshes, songs):
    basis = meshes["bumpy sphere"]
    samples, rate = demo_track(4.0)
    loud = Spectrogram.from_samples(samples, rate)
    for song in (loud, songs["quiet demo"]):
        motion = [m.motion for m in gallery_motion(basis, song, initial_gallery(basis, song))]
        np.testing.assert_allclose(motion[0], MOTION_LOWEST, rtol=1e-9)
    silence = Spectrogram.from_samples(np.zeros(rate), rate)
    gallery = initial_gallery(basis, silence, 6)  # calibrated at full-scale input instead
    assert all(np.isfinite(item.amplification).all() for item in gallery)
    assert all(m.motion == 0 for m in gallery_motion(basis, silence, gallery))
    full = Spectrogram.from_samples(np.zeros(rate), rate)
    full.values[:] = 1.0
    np.testing.assert_allclose(gallery_motion(basis, full, gallery[:1])[0].motion,
                               MOTION_LOWEST, rtol=1e-9)


def test_every_size_of_the_rule_works_and_others_are_refused(meshes, songs):
    basis, song = meshes["bumpy sphere"], songs["demo"]
    for size in range(MIN_GALLERY, MAX_GALLERY + 1):  # odd sizes included
        gallery = initial_gallery(basis, song, size)
        assert len(gallery) == size
        assert len({tuple(item.transfer) for item in gallery}) == size
    for size in (MIN_GALLERY - 1, MAX_GALLERY + 1, 8.0, True, "8"):
        with pytest.raises(EigendanceError, match=f"{MIN_GALLERY} to {MAX_GALLERY} items"):
            initial_gallery(basis, song, size)


def test_a_model_with_few_moving_harmonics_combines_them(meshes, songs):
    """An icosphere moves only through a few triples of harmonics: items combine them."""
    basis, song = meshes["icosphere"], songs["demo"]
    content = motion_content(basis)
    drivable = drivable_harmonics(basis, content)
    assert drivable.tolist() == [1, 2, 3, 30, 31, 32]  # x, y, z and the next symmetric triple
    assert content[np.setdiff1d(np.arange(1, basis.k), drivable)].max() < 1e-9 * content.max()
    assert content[drivable].min() > 1e-5 * content.max()
    small = HarmonicBasis.from_mesh(sphere(2), 12, cache=False)  # only x, y and z move it
    assert len(initial_gallery(small, song, 13)) == 13
    with pytest.raises(EigendanceError, match="only 3 harmonics that move it") as raised:
        initial_gallery(small, song, 14)
    assert raised.value.remedy == {"k": 48}


def test_strongest_item_moves_most(meshes, songs):
    basis, song = meshes["knight"], songs["demo"]
    gallery = initial_gallery(basis, song)
    motion = [m.motion for m in gallery_motion(basis, song, gallery)]
    assert strongest_item(basis, song).to_json() == gallery[int(np.argmax(motion))].to_json()


def test_cli_gallery_writes_the_items_and_shows_their_table(tmp_path, meshes, songs, capsys):
    basis = meshes["knight"]
    samples, rate = demo_track(2.0)
    Spectrogram.from_samples(samples, rate).save(tmp_path / "s.npz")
    basis.save(tmp_path / "b.npz")
    out = tmp_path / "gallery"
    assert main(["gallery", str(tmp_path / "b.npz"), str(tmp_path / "s.npz"), "-n", "5",
                 "-o", str(out), "--verbose"]) == 0
    assert sorted(os.listdir(out)) == [f"{i}.json" for i in range(5)]
    shown = capsys.readouterr().out.splitlines()
    header = next(i for i, line in enumerate(shown) if line.split()[:3] == ["item", "m", "peak"])
    rows = [line.split() for line in shown[header + 1:header + 6]]
    assert [row[0] for row in rows] == ["1", "2", "3", "4", "5"]
    assert float(rows[0][1].rstrip("%")) == pytest.approx(100 * MOTION_LOWEST, abs=0.01)
    assert any("largest correlation" in line for line in shown)
    first = Mapping.load(out / "0.json")
    assert first.bands == 64 and len(first.amplification) == basis.k and first.seed is None
    children = tmp_path / "children"
    arguments = ["gallery", str(tmp_path / "b.npz"), str(tmp_path / "s.npz"), "--breed",
                 str(out / "3.json"), str(out / "4.json"), "-n", "4", "--seed", "9",
                 "-o", str(children)]
    assert main(arguments) == 0
    child = Mapping.load(children / "2.json")
    expected = breed([Mapping.load(out / "3.json"), Mapping.load(out / "4.json")], 4, 9)[2]
    np.testing.assert_array_equal(child.transfer, expected.transfer)
    assert child.seed == 9
    assert main(arguments) == 1  # refuses to overwrite
    assert "exists; pass --force" in capsys.readouterr().err
    assert main([*arguments, "--force", "--verbose"]) == 0
    assert "item" in capsys.readouterr().out
    assert main(["gallery", str(tmp_path / "b.npz"), str(tmp_path / "s.npz"), "-n", "3",
                 "-o", str(tmp_path / "odd")]) == 0
    for size in ("17", "1", "x"):
        with pytest.raises(SystemExit) as refused:
            main(["gallery", str(tmp_path / "b.npz"), str(tmp_path / "s.npz"), "-n", size,
                  "-o", str(tmp_path / "big")])
        assert refused.value.code == 1
        assert "argument -n/--size: a gallery has 2 to 16 items" in capsys.readouterr().err


# Breeding (docs/design.md#breeding)


def test_mulberry32_matches_the_javascript_reference():
    # mulberry32(1) in JavaScript: 0.6270739405881613, 0.002735721180215478, …
    random = Mulberry32(1)
    assert random.uniform() == 0.6270739405881613
    assert random.next_uint32() == 11749833
    assert Mulberry32(2 ** 32 + 1).next_uint32() == Mulberry32(1).next_uint32()


def distinct_parents(rng, count=2, bands=64, k=40):
    return [Mapping(rng.uniform(0, 1, bands), rng.normal(0, 3, k), name=f"p{i}")
            for i in range(count)]


def test_same_seed_same_children_other_seed_other_children(rng):
    parents = distinct_parents(rng, 3)
    first = breed(parents, 6, seed=11)
    again = breed(parents, 6, seed=11)
    other = breed(parents, 6, seed=12)
    for a, b in zip(first, again, strict=True):
        np.testing.assert_array_equal(a.transfer, b.transfer)
        np.testing.assert_array_equal(a.amplification, b.amplification)
        assert a.seed == 11
    assert any(not np.array_equal(a.transfer, b.transfer) for a, b in zip(first, other,
                                                                          strict=True))


def segments_of(child, first, second):
    """The r of each entry (child = r·first + (1 − r)·second), and runs of equal r."""
    r = (child - second) / (first - second)
    breaks = np.flatnonzero(np.abs(np.diff(r)) > 1e-9) + 1
    return r, np.split(r, breaks)


def test_children_are_segmentwise_convex_combinations(rng):
    parents = distinct_parents(rng, 2)
    children = breed(parents, 40, seed=3)
    crossed = 0
    for child in children:
        for name in ("transfer", "amplification"):
            a, b = getattr(parents[0], name), getattr(parents[1], name)
            c = getattr(child, name)
            if np.array_equal(c, a) or np.array_equal(c, b):
                continue  # copied from one parent
            crossed += 1
            low, high = np.minimum(a, b), np.maximum(a, b)
            assert (c >= low - 1e-12).all() and (c <= high + 1e-12).all()
            # Either orientation of the pair: r is constant on each segment and in [0, 1].
            runs = min((segments_of(c, a, b)[1], segments_of(c, b, a)[1]), key=len)
            assert all(0 - 1e-9 <= run[0] <= 1 + 1e-9 for run in runs)
            assert len(runs) < len(c) / 2  # segments, not per-entry mixing
    assert crossed > 10


def test_crossing_segment_lengths_average_a_quarter(rng):
    random = Mulberry32(5)
    lengths = []
    a, b = np.zeros(4000), np.ones(4000)
    for _ in range(5):
        child = cross(a, b, random, mean_segment=100)
        runs = np.split(child, np.flatnonzero(np.diff(child) != 0) + 1)
        lengths += [len(run) for run in runs[:-1]]  # the last is truncated
    assert np.mean(lengths) == pytest.approx(100, rel=0.25)
    assert cross([1.0, 2.0], [3.0, 4.0], Mulberry32(0)).shape == (2,)


def test_breed_resamples_amplifications_and_checks_bands(rng):
    a = Mapping(rng.uniform(0, 1, 8), rng.normal(size=10))
    b = Mapping(rng.uniform(0, 1, 8), rng.normal(size=20))
    children = breed([a, b], 4, seed=1)
    assert all(len(child.amplification) == 10 for child in children)
    only = breed([a], 3, seed=1)
    assert all(np.array_equal(child.transfer, a.transfer) for child in only)
    with pytest.raises(EigendanceError, match="parents must agree"):
        breed([a, Mapping(np.zeros(4), np.zeros(3))], 2)
    with pytest.raises(EigendanceError, match="at least one parent"):
        breed([], 2)


def test_javascript_port_breeds_identical_children(rng):
    required("Node", shutil.which("node") is not None, "make system")
    parents = distinct_parents(rng, 3, bands=16, k=24)
    children = breed(parents, 8, seed=987654321)
    payload = {"parents": [{"transfer": list(p.transfer), "amplification":
                            list(p.amplification)} for p in parents],
               "size": 8, "seed": 987654321}
    result = subprocess.run(["node", JS], input=json.dumps(payload), capture_output=True,
                            text=True, check=True, timeout=60)
    ported = json.loads(result.stdout)
    for python, javascript in zip(children, ported, strict=True):
        assert list(python.transfer) == javascript["transfer"]
        assert list(python.amplification) == javascript["amplification"]


def test_children_keep_the_settings_of_their_first_drawn_parent(rng):
    loud = Mapping(rng.uniform(0, 1, 8), rng.normal(size=10), gain=2.0, offset=1.0,
                   shading="flat", name="loud")
    calm = Mapping(rng.uniform(0, 1, 8), rng.normal(size=10), smoothing=0.3, name="calm")
    children = breed([loud, calm], 12, seed=5)
    settings = {(c.gain, c.smoothing, c.offset, c.shading) for c in children}
    assert settings == {(2.0, 0.0, 1.0, "flat"), (1.0, 0.3, 0.0, "smooth")}


def test_an_inactive_parents_pulse_range_never_reaches_a_child(rng):
    """Issue 30: a parent without a pulse (amount 0, range 0–1) crossed its range into children
    whose pulse is active, which then kicked about 135 of 150 harmonics. The active parent's
    range [0.1, 0.3] holds the harmonics ν whose centre (ν + ½)/150 lies in it: ν = 15…44, 30."""
    kicks = Pulse(3.0, 0.2, 0.1, 0.3, "onsets")
    active = Mapping(rng.uniform(0, 1, 8), rng.normal(size=150), pulse=kicks, name="active")
    still = Mapping(rng.uniform(0, 1, 8), rng.normal(size=150), name="still")
    assert still.pulse.amount == 0 and (still.pulse.low, still.pulse.high) == (0, 1)
    crossed = 0
    for seed in range(1, 21):
        for child in breed([active, still], 8, seed) + breed([still, active], 8, seed):
            pulse = child.pulse
            assert 0 <= pulse.amount <= 3.0
            if pulse.amount > 0:
                assert (pulse.low, pulse.high, pulse.decay, pulse.source) == \
                    (0.1, 0.3, 0.2, "onsets"), (seed, pulse)
                assert pulse.routed(150).sum() == 30
                crossed += pulse.amount < 3.0
        assert all(c.pulse.amount == 0 for c in breed([still, still], 8, seed))
    assert crossed  # some amounts were crossed with the still parent's 0, and kept the range


def test_active_parents_cross_their_pulse_ranges_within_their_hull(rng):
    first = Mapping(rng.uniform(0, 1, 8), rng.normal(size=20), pulse=Pulse(2.0, 0.1, 0.1, 0.3))
    second = Mapping(rng.uniform(0, 1, 8), rng.normal(size=20), pulse=Pulse(1.0, 0.3, 0.5, 0.9))
    ranges = set()
    for seed in range(1, 21):
        for child in breed([first, second], 8, seed):
            assert 1.0 <= child.pulse.amount <= 2.0 and 0.1 <= child.pulse.decay <= 0.3
            assert 0.1 <= child.pulse.low <= child.pulse.high <= 0.9
            ranges.add((child.pulse.low, child.pulse.high))
    assert {(0.1, 0.3), (0.5, 0.9)} < ranges  # copied from either, and crossed


def test_the_kernel_of_a_model_of_coupled_pieces_is_never_driven():
    """The textured speeder (4 pieces coupled by contacts: one component, so exactly one
    eigenvalue 0, computed as 3·10⁻¹² λ_max beside the contacts' stiff springs) dances from
    harmonic 1: harmonic 0 (a translation of the whole model) was its tile #1."""
    from eigendance.harmonic.basis import HarmonicProblem

    basis = HarmonicProblem(fixture_path("textured", "craft_speederD.gltf"),
                            cache=False).basis(40)
    assert basis.eigenvalues[0] < 1e-9 * basis.eigenvalues[-1] < basis.eigenvalues[1]
    assert drivable_harmonics(basis)[0] == 1
