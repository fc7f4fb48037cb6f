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
from eigendance.music.demo_music import demo_track
from eigendance.music.gallery import (
    MAX_GALLERY,
    MIN_GALLERY,
    TARGET_MOTION,
    direct_transfer,
    full_scale_motion,
    gallery_epsilons,
    gallery_intervals,
    initial_gallery,
    reversed_transfer,
    strongest_item,
)
from eigendance.music.mapping import Mapping
from eigendance.music.spectrogram import Spectrogram, band_edges
from helpers import bumpy_sphere

EDGES = band_edges(64, 44100)
JS = os.path.join(os.path.dirname(__file__), "..", "js", "breed_reference.mjs")


@pytest.fixture(scope="module")
def basis():
    return HarmonicBasis.from_mesh(bumpy_sphere(2), 40, cache=False)


def test_mulberry32_matches_the_javascript_reference():
    # mulberry32(1) in JavaScript: 0.6270739405881613, 0.002735721180215478, …
    random = Mulberry32(1)
    assert random.uniform() == 0.6270739405881613
    assert random.next_uint32() == 11749833
    assert Mulberry32(2 ** 32 + 1).next_uint32() == Mulberry32(1).next_uint32()


def test_epsilons_and_intervals():
    np.testing.assert_allclose(gallery_epsilons(8), [0, 1, 0.25, 0.5])
    np.testing.assert_allclose(gallery_epsilons(2), [0])
    np.testing.assert_allclose(gallery_intervals(8),
                               [[0, 1 / 16], [1 / 16, 1 / 4], [1 / 4, 9 / 16], [9 / 16, 1]])


def test_initial_gallery_structure_and_calibration(basis):
    size = 8
    gallery = initial_gallery(basis, EDGES, size)
    assert len(gallery) == size
    xi = np.arange(64.0)
    for i, eps in enumerate(gallery_epsilons(size)):
        np.testing.assert_allclose(gallery[i].transfer,
                                   direct_transfer(basis.frequencies, EDGES, eps * xi))
        np.testing.assert_allclose(gallery[4 + i].transfer,
                                   reversed_transfer(basis.frequencies, EDGES, eps * xi))
    assert len(set(gallery[0].transfer)) == 1  # ε = 0: a constant map
    np.testing.assert_allclose(gallery[1].transfer, direct_transfer(basis.frequencies, EDGES))
    amplitude = max(np.abs(item.amplification).max() for item in gallery)
    first = np.array([item.amplification for item in gallery[:4]])
    second = np.array([item.amplification for item in gallery[4:]])
    np.testing.assert_array_equal(second, -first)
    assert (first >= 0).all()
    # Every harmonic lies in exactly one interval; intervals are finer at low frequencies.
    np.testing.assert_array_equal((first > 0).sum(axis=0), 1)
    widths = (first > 0).sum(axis=1)
    assert (np.diff(widths) > 0).all()
    motion = full_scale_motion(basis, gallery)
    assert motion.max() / basis.diagonal == pytest.approx(TARGET_MOTION, rel=1e-9)
    assert strongest_item(basis, EDGES, size).name == gallery[int(motion.argmax())].name
    scaled = initial_gallery(basis, EDGES, size, amplitude=2 * amplitude)
    np.testing.assert_allclose(scaled[0].amplification, 2 * gallery[0].amplification)


def test_each_item_calibration_gives_every_moving_item_five_percent(basis):
    gallery = initial_gallery(basis, EDGES, 8, calibration="each")
    motion = full_scale_motion(basis, gallery) / basis.diagonal
    moving = motion > 0
    assert moving.sum() >= 2
    np.testing.assert_allclose(motion[moving], TARGET_MOTION, rtol=1e-6)
    with pytest.raises(EigendanceError, match="unknown calibration"):
        initial_gallery(basis, EDGES, 8, calibration="median")


def test_every_gallery_size_of_the_rule_works_and_others_are_refused(basis):
    for size in range(MIN_GALLERY, MAX_GALLERY + 1):  # odd sizes included
        gallery = initial_gallery(basis, EDGES, size)
        assert len(gallery) == size
        assert len({tuple(item.amplification) for item in gallery}) == size
    for size in (MIN_GALLERY - 1, MAX_GALLERY + 1, 8.0, True):
        with pytest.raises(EigendanceError, match=f"{MIN_GALLERY} to {MAX_GALLERY} items"):
            initial_gallery(basis, EDGES, size)


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


@pytest.mark.skipif(shutil.which("node") is None, reason="node is not installed")
def test_javascript_port_breeds_identical_children(rng):
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


def test_cli_gallery_and_breed(tmp_path, basis, capsys):
    samples, sr = demo_track(1.0)
    Spectrogram.from_samples(samples, sr).save(tmp_path / "s.npz")
    basis.save(tmp_path / "b.npz")
    out = tmp_path / "gallery"
    assert main(["gallery", str(tmp_path / "b.npz"), str(tmp_path / "s.npz"), "-n", "6",
                 "-o", str(out)]) == 0
    assert sorted(os.listdir(out)) == [f"{i}.json" for i in range(6)]
    first = Mapping.load(out / "0.json")
    assert first.bands == 64 and len(first.amplification) == basis.k and first.seed is None
    children = tmp_path / "children"
    arguments = ["gallery", str(tmp_path / "b.npz"), str(tmp_path / "s.npz"), "--breed",
                 str(out / "3.json"), str(out / "5.json"), "-n", "4", "--seed", "9",
                 "-o", str(children)]
    assert main(arguments) == 0
    child = Mapping.load(children / "2.json")
    expected = breed([Mapping.load(out / "3.json"), Mapping.load(out / "5.json")], 4, 9)[2]
    np.testing.assert_array_equal(child.transfer, expected.transfer)
    assert child.seed == 9
    assert main(arguments) == 1  # refuses to overwrite
    assert "exists; pass --force" in capsys.readouterr().err
    assert main([*arguments, "--force"]) == 0
    assert main(["gallery", str(tmp_path / "b.npz"), str(tmp_path / "s.npz"), "-n", "3",
                 "-o", str(tmp_path / "odd")]) == 0
    assert main(["gallery", str(tmp_path / "b.npz"), str(tmp_path / "s.npz"), "-n", "17",
                 "-o", str(tmp_path / "big")]) == 1
    assert "2 to 16 items" in capsys.readouterr().err


def test_children_keep_the_settings_of_their_first_drawn_parent(rng):
    loud = Mapping(rng.uniform(0, 1, 8), rng.normal(size=10), gain=2.0, offset=1.0,
                   shading="flat", name="loud")
    calm = Mapping(rng.uniform(0, 1, 8), rng.normal(size=10), smoothing=0.3, name="calm")
    children = breed([loud, calm], 12, seed=5)
    settings = {(c.gain, c.smoothing, c.offset, c.shading) for c in children}
    assert settings == {(2.0, 0.0, 1.0, "flat"), (1.0, 0.3, 0.0, "smooth")}
