"""Children of any breeding stay bounded (issue 30 item 2, docs/design.md#breeding): over the
whole song, every child's bounding box stays within BOX_LIMIT = 1.3× the rest shape's, on the
shared meshes for seeds 1–20, through the library and through `eigendance gallery --breed` then
`animate`. The boxes are measured here with numpy on positions at 12 or 30 frames a second, not
on the frames the calibration looks at.
"""

from __future__ import annotations

import numpy as np
import pytest
import trimesh

from eigendance.cli.main import main
from eigendance.harmonic.basis import HarmonicBasis
from eigendance.music.breeding import BOX_LIMIT, bounded_children, breed
from eigendance.music.dancer import gallery_motion
from eigendance.music.gallery import initial_gallery
from eigendance.music.mapping import Mapping
from eigendance.music.spectrogram import Spectrogram
from helpers import fixture_path

K = 40
CALM = (5, 6, 7)  # the gallery's calmest tiles: breeding three of them exploded (issue 30)


def growth(rest: np.ndarray, frames: np.ndarray) -> float:
    """The largest bounding-box diagonal of the frames (F, n, 3) over the rest shape's."""
    rest_size = np.linalg.norm(rest.max(axis=0) - rest.min(axis=0))
    return float((np.linalg.norm(frames.max(axis=1) - frames.min(axis=1), axis=1)
                  / rest_size).max())


def song_growth(basis: HarmonicBasis, song, mapping: Mapping, fps: float = 12.0) -> float:
    times = np.arange(0.0, song.duration, 1.0 / fps)
    return growth(basis.vertices, basis.filter_positions(mapping.play(song, times, basis.k)))


@pytest.fixture(scope="module")
def song():
    return Spectrogram.from_file(fixture_path("audio", "sorohanro_solo_trumpet_06.ogg"))


@pytest.mark.parametrize("name", ["teapot.obj", "decimated-knight.off", "beetle.obj"])
def test_children_of_seeds_1_to_20_stay_within_the_box(name, song):
    basis = HarmonicBasis.from_mesh(fixture_path("meshes", name), K,
                                    laplacian="robust" if name == "beetle.obj" else "cotan")
    gallery = initial_gallery(basis, song, 8)
    parents = [gallery[i] for i in CALM]
    bred_worst, worst = 1.0, 1.0
    for seed in range(1, 21):
        children = breed(parents, 8, seed)
        bounded = bounded_children(basis, song, children)
        bred_worst = max(bred_worst, *(song_growth(basis, song, c) for c in children))
        worst = max(worst, *(song_growth(basis, song, c) for c in bounded))
        assert [c.transfer.tolist() for c in bounded] == [c.transfer.tolist() for c in children]
        # Bounding only calms the children that need it: they still move visibly.
        for before, after in zip(gallery_motion(basis, song, children),
                                 gallery_motion(basis, song, bounded), strict=True):
            assert after.motion >= min(before.motion, 0.01) - 1e-12, (seed, before, after)
    print(f"{name}: children as bred grow to {bred_worst:.2f}×, bounded {worst:.2f}×")
    assert worst <= BOX_LIMIT


def test_the_command_line_breeds_bounded_children_that_animate_within_the_box(tmp_path, song):
    mesh = fixture_path("meshes", "teapot.obj")
    audio = fixture_path("audio", "sorohanro_solo_trumpet_06.ogg")
    first = tmp_path / "first"
    assert main(["gallery", mesh, audio, "-k", str(K), "-o", str(first)]) == 0
    rest = trimesh.load(mesh, force="mesh").vertices  # the file's rest shape, read by trimesh
    for seed in (7,):
        children = tmp_path / f"children-{seed}"
        assert main(["gallery", mesh, audio, "-k", str(K), "--breed",
                     *(str(first / f"{i}.json") for i in CALM), "--seed", str(seed),
                     "-o", str(children)]) == 0
        for index in range(8):
            out = tmp_path / f"dance-{seed}-{index}.npz"
            assert main(["animate", mesh, audio, "-k", str(K), "--mapping",
                         str(children / f"{index}.json"), "--fps", "30", "-o", str(out)]) == 0
            with np.load(out) as animation:
                assert growth(rest, animation["positions"]) <= BOX_LIMIT
