import numpy as np
import pytest
import soundfile
import trimesh

import eigendance.harmonic.motion as harmonic_motion
from eigendance.cli import main
from eigendance.harmonic.basis import HarmonicBasis
from eigendance.harmonic.motion import load_animation, positions_at, write_animation
from eigendance.music.demo_music import demo_track
from eigendance.music.gallery import initial_gallery, strongest_item
from eigendance.music.mapping import Mapping
from eigendance.music.spectrogram import Spectrogram, frame_times
from helpers import bumpy_sphere


@pytest.fixture(scope="module")
def mesh():
    return bumpy_sphere(2)


@pytest.fixture(scope="module")
def basis(mesh):
    return HarmonicBasis.from_mesh(mesh, 30, cache=False)


@pytest.fixture(scope="module")
def spectrogram():
    samples, sr = demo_track(1.0)
    return Spectrogram.from_samples(samples, sr)


def test_frame_times():
    np.testing.assert_allclose(frame_times(1.0, 30), np.arange(31) / 30)
    assert len(frame_times(0.0, 30)) == 1
    assert len(frame_times(2.99, 10)) == 30


def test_zero_amplification_reproduces_the_rest_mesh(tmp_path, mesh, basis, spectrogram):
    still = Mapping(np.linspace(0, 1, 64), np.zeros(basis.k))
    times = frame_times(spectrogram.duration, 30)
    reference = positions_at(basis, spectrogram, still, times)
    np.testing.assert_allclose(reference, np.broadcast_to(mesh.original_vertices,
                                                          reference.shape), atol=1e-12)
    write_animation(tmp_path / "still.npz", basis, spectrogram, still)
    data = load_animation(tmp_path / "still.npz")
    expected = basis.to_original(basis.vertices).astype(np.float32)
    np.testing.assert_array_equal(data["positions"], np.broadcast_to(expected,
                                                                     data["positions"].shape))
    np.testing.assert_array_equal(data["faces"], mesh.faces)


def test_streamed_file_matches_reference_in_chunks(tmp_path, monkeypatch, basis, spectrogram):
    mapping = strongest_item(basis, spectrogram)
    monkeypatch.setattr(harmonic_motion, "CHUNK_BYTES", basis.n * 3 * 8 * 7)  # 7 frames per chunk
    done = []
    count = write_animation(tmp_path / "a.npz", basis, spectrogram, mapping, fps=24,
                            progress=done.append)
    data = load_animation(tmp_path / "a.npz")
    times = frame_times(spectrogram.duration, 24)
    assert count == len(times) == 25 and done[-1] == 25 and len(done) == 4
    np.testing.assert_array_equal(data["times"], times)
    assert data["positions"].dtype == np.float32
    assert data["positions"].shape == (25, basis.n, 3)
    reference = positions_at(basis, spectrogram, mapping, times)
    np.testing.assert_allclose(data["positions"], reference, rtol=0, atol=1e-5 * basis.scale)
    # The strongest item moves the mesh visibly but by a few percent at most.
    rest = basis.to_original(basis.vertices)
    motion = np.sqrt(((reference - rest) ** 2).sum(axis=2).mean(axis=1)).max()
    diagonal = np.linalg.norm(rest.max(axis=0) - rest.min(axis=0))
    assert 0.001 * diagonal < motion <= 0.05 * diagonal + 1e-12


def test_positions_at_is_linear_in_the_filter(basis, spectrogram):
    # Positions at a time halfway between two frames equal the mean of the two frames' ones.
    mapping = initial_gallery(basis, spectrogram)[1]
    a, b, half = positions_at(basis, spectrogram, mapping, [0.1, 0.11, 0.105])
    np.testing.assert_allclose(half, (a + b) / 2, atol=1e-12)


def test_mapping_with_other_k_is_resampled(basis, spectrogram):
    coarse = Mapping(np.full(64, 0.2), np.full(3, 0.01))
    fine = Mapping(np.full(64, 0.2), np.full(basis.k, 0.01))
    np.testing.assert_allclose(positions_at(basis, spectrogram, coarse, [0.5]),
                               positions_at(basis, spectrogram, fine, [0.5]))
    # Four amplifications on k = 30 harmonics, by normalised index: harmonic ν takes
    # a[⌊(ν + ½)·4/30⌋] = a[⌊(2ν + 1)/15⌋], counted by hand: ν 0–6 → a₀, 7–14 → a₁,
    # 15–21 → a₂, 22–29 → a₃ (⌊ν·4/30⌋ would give ν = 7 a₀; ⌊ν·3/29 + ½⌋ other bounds).
    # The 64 bands go to every harmonic (transfer spread over [0, 1)), so each one moves.
    assert basis.k == 30
    amplification = np.array([0.01, -0.02, 0.03, 0.05])
    transfer = (np.arange(64) + 0.5) / 64
    coarse = Mapping(transfer, amplification)
    fine = Mapping(transfer, np.repeat(amplification, [7, 8, 7, 8]))
    np.testing.assert_allclose(positions_at(basis, spectrogram, coarse, [0.5, 0.75]),
                               positions_at(basis, spectrogram, fine, [0.5, 0.75]), rtol=1e-12)


def test_cli_animate(tmp_path, mesh, capsys):
    trimesh.Trimesh(mesh.original_vertices, mesh.faces).export(tmp_path / "m.obj")
    samples, sr = demo_track(0.5)
    soundfile.write(tmp_path / "music.wav", samples, sr)
    out = tmp_path / "anim.npz"
    assert main(["animate", str(tmp_path / "m.obj"), str(tmp_path / "music.wav"), "-k", "20",
                 "--fps", "10", "-o", str(out)]) == 0
    data = load_animation(out)
    assert data["positions"].shape == (6, len(mesh.vertices), 3)
    assert main(["animate", str(tmp_path / "m.obj"), str(tmp_path / "music.wav"),
                 "-o", str(out)]) == 1
    assert "exists; pass --force" in capsys.readouterr().err
    # A basis file, a spectrogram file and an explicit still mapping: the rest mesh.
    basis = HarmonicBasis.from_mesh(mesh, 20)
    basis.save(tmp_path / "b.npz")
    Spectrogram.from_file(tmp_path / "music.wav", bands=16).save(tmp_path / "s.npz")
    Mapping(np.full(16, 0.5), np.zeros(4)).save(tmp_path / "still.json")
    assert main(["animate", str(tmp_path / "b.npz"), str(tmp_path / "s.npz"), "--mapping",
                 str(tmp_path / "still.json"), "-o", str(out), "--force"]) == 0
    positions = load_animation(out)["positions"]
    np.testing.assert_allclose(positions[3], mesh.original_vertices, atol=1e-5)
    # Audio analysed with the mapping's number of bands.
    assert main(["animate", str(tmp_path / "b.npz"), str(tmp_path / "music.wav"), "--mapping",
                 str(tmp_path / "still.json"), "-o", str(out), "--force"]) == 0
    Mapping(np.full(8, 0.5), np.zeros(4)).save(tmp_path / "eight.json")
    assert main(["animate", str(tmp_path / "b.npz"), str(tmp_path / "s.npz"), "--mapping",
                 str(tmp_path / "eight.json"), "-o", str(out), "--force"]) == 1
    assert "8 bands; the spectrogram has 16" in capsys.readouterr().err
