"""Part of a song (docs/design.md#window): a clip's motion at its time t is the whole dance's at
start + t, its files start at time 0, and its song is the song's same part.

The references are independent of the clip's code path: `positions_at` of the song's times for
a mesh, `rig_coefficients` skinned by the rig for a rig; the song's part is compared with the
song decoded on its own, sample by sample (a lossless cut) or by correlation (a lossy one).
"""

from __future__ import annotations

import math

import av
import numpy as np
import pygltflib
import pytest
import soundfile
from export_helpers import SONG, check_positions
from test_gltf import load

from eigendance.cli import main
from eigendance.errors import InputError
from eigendance.export.files import export_dance
from eigendance.export.rig_dance import rig_dance
from eigendance.files import load_npz
from eigendance.harmonic.motion import positions_at
from eigendance.modal.model import ModalModel
from eigendance.modal.motion import body_transforms, rig_coefficients
from eigendance.modal.rig import Rig
from eigendance.modal.sample_rigs import load_rig
from eigendance.modal.skinning import ModalSkin, linear_blend_skinning
from eigendance.music.decode import read_audio
from eigendance.window import Window

START, LENGTH = 1.25, 1.5  # the clip: s of the 4-s test song


def run(capsys, *arguments):
    try:
        status = main([str(argument) for argument in arguments])
    except SystemExit as exit_:  # argparse
        status = exit_.code
    captured = capsys.readouterr()
    return status, captured.out, captured.err


def test_a_window_is_checked_and_clamped_to_the_song():
    assert Window.of(None, None, 4.0) == Window(0.0, 4.0)
    assert Window.of(1.0, 2.0, 4.0) == Window(1.0, 2.0)
    clamped = Window.of(3.0, 5.0, 4.0, "song.ogg")
    assert (clamped.start, clamped.duration) == (3.0, 1.0)
    assert "song.ogg ends 1 s after 3 s" in clamped.note
    assert Window.of(2.0, None, math.inf).duration == math.inf  # a rig without a song
    for start, duration, message in ((-1.0, 1.0, "start must be at least 0"),
                                     (float("nan"), 1.0, "start is not finite"),
                                     (4.0, 1.0, "cannot start at 4 s"),
                                     (9.0, None, "cannot start at 9 s"),
                                     (0.0, 0.0, "duration must be positive"),
                                     (0.0, float("inf"), "duration is not finite"),
                                     ("1", 1.0, "start must be a number")):
        with pytest.raises(InputError, match=message):
            Window.of(start, duration, 4.0)


def test_a_mesh_clip_is_the_whole_dance_from_its_start(harmonic):
    clip = harmonic.window(START, LENGTH)
    assert (clip.start, clip.duration, clip.clipped) == (START, LENGTH, True)
    times = np.array([0.0, 0.37, 1.0, LENGTH])
    expected = positions_at(harmonic.basis, harmonic.spectrogram, harmonic.mapping,
                            START + times)
    check_positions(clip.positions(times), expected, harmonic.diagonal, 1e-6)
    again = clip.window(0.5, 0.5)  # a window of a window: the song from 1.75 s
    check_positions(again.positions([0.0, 0.5]), positions_at(
        harmonic.basis, harmonic.spectrogram, harmonic.mapping, [START + 0.5, START + 1.0]),
        harmonic.diagonal, 1e-6)
    loudest = clip.loudest_times(4)
    assert len(loudest) == 4 and 0 <= loudest.min() and loudest.max() <= LENGTH


@pytest.mark.parametrize("skinning", ["modal", "lbs"])
def test_a_rig_clip_is_the_whole_dance_from_its_start(song, skinning):
    skeleton = load_rig("chain")
    rig = Rig(skeleton, np.float64)
    mapping = rig.mapping(song)
    clip = rig_dance(rig, song, mapping, skinning).window(START, LENGTH)
    times = np.array([0.0, 0.4, LENGTH])
    model = ModalModel.from_skeleton(skeleton)  # the reference, made apart from the rig
    coefficients = rig_coefficients(model, song, mapping, START + times)
    expected = ModalSkin(model, skeleton.vertices, skeleton.weights).positions(coefficients) \
        if skinning == "modal" else linear_blend_skinning(
            skeleton.vertices, skeleton.weights, body_transforms(model, coefficients))
    check_positions(clip.positions(times), expected, clip.diagonal, 1e-6)  # float32 frames
    np.testing.assert_allclose(clip.pose(times)[1], coefficients, atol=1e-12)


def test_export_of_a_clip_starts_at_zero_and_cuts_the_song(harmonic, tmp_path):
    clip = harmonic.window(START, LENGTH)
    report = export_dance(clip, tmp_path / "clip.glb", fps=10)
    gltf, read = load(tmp_path / "clip.glb")
    sampler = gltf.animations[0].samplers[0]
    times = read(sampler.input)
    expected_times = np.arange(int(LENGTH * 10) + 1) / 10.0  # i/fps, i = 0 … 15
    np.testing.assert_allclose(times, expected_times, rtol=1e-6)
    primitive = gltf.meshes[0].primitives[0]
    rest = read(primitive.attributes.POSITION)
    targets = np.stack([read(target["POSITION"]) for target in primitive.targets])
    weights = read(sampler.output).reshape(len(times), len(targets))
    played = rest[None] + np.einsum("tj,jnc->tnc", weights, targets)
    reference = positions_at(harmonic.basis, harmonic.spectrogram, harmonic.mapping,
                             START + expected_times)
    check_positions(played, reference, harmonic.diagonal, 1e-6)
    assert gltf.extras["eigendance"]["start"] == START
    assert report["files"] == [str(tmp_path / "clip.glb"), str(tmp_path / "clip.ogg")]
    song, rate = read_audio(SONG)
    cut, cut_rate = read_audio(tmp_path / "clip.ogg")
    assert cut_rate == rate and abs(len(cut) / rate - LENGTH) < 0.03
    part = song[int(round(START * rate)):][:len(cut)]
    assert np.corrcoef(cut[:len(part)], part)[0, 1] > 0.95  # Vorbis again: lossy, aligned


def test_a_lossless_song_is_cut_to_the_sample(harmonic, tmp_path):
    samples, rate = read_audio(SONG)
    wav = tmp_path / "song.wav"
    soundfile.write(wav, samples, rate, subtype="PCM_16")
    dance = type(harmonic)(harmonic.basis, harmonic.spectrogram, harmonic.mapping, wav)
    export_dance(dance.window(START, LENGTH), tmp_path / "out" / "clip.usda", fps=5)
    original, _ = soundfile.read(wav, dtype="int16")
    cut, cut_rate = soundfile.read(tmp_path / "out" / "clip.wav", dtype="int16")
    first = int(round(START * rate))
    assert cut_rate == rate and len(cut) == int(round(LENGTH * rate))
    np.testing.assert_array_equal(cut, original[first:first + len(cut)])


def test_the_command_line_clips_export_animate_and_animate_rig(tmp_path, capsys, harmonic):
    status, out, err = run(capsys, "export", "chain", SONG, "--start", START, "--duration", 9,
                           "--fps", 8, "-o", tmp_path / "chain.glb")
    assert status == 0, err
    left = 4.0 - START
    assert f"the clip lasts {left:.3g} s, not 9 s" in err  # clamped, with a note
    frames = int(left * 8) + 1
    assert f"{frames} frames" in out
    extras = pygltflib.GLTF2().load(str(tmp_path / "chain.glb")).extras["eigendance"]
    assert extras["start"] == START and extras["audio"] == "chain.ogg"
    assert abs(extras["duration"] - left) < 1e-6

    status, out, err = run(capsys, "animate-rig", "loop4", SONG, "--start", START,
                           "--duration", LENGTH, "--fps", 10, "-o", tmp_path / "loop.npz")
    assert status == 0, err
    arrays = load_npz(tmp_path / "loop.npz", ("times", "positions", "coefficients"))
    np.testing.assert_allclose(arrays["times"], np.arange(16) / 10.0, atol=1e-12)
    rig = Rig(load_rig("loop4"))
    spectrogram = harmonic.spectrogram
    expected = rig_coefficients(rig.model, spectrogram, None, START + arrays["times"])
    np.testing.assert_allclose(arrays["coefficients"], expected, atol=1e-9)
    check_positions(arrays["positions"], rig.skin.positions(expected), 1.0, 1e-5)


def test_a_clip_outside_the_song_is_one_line(tmp_path, capsys):
    status, _, err = run(capsys, "export", "chain", SONG, "--start", 7, "-o", tmp_path / "a.glb")
    assert status == 1 and "cannot start at 7 s" in err and len(err.splitlines()) == 1
    status, _, err = run(capsys, "render", "chain", SONG, "--duration", 0, "-o",
                         tmp_path / "a.mp4")
    assert status == 1 and "--duration" in err
    assert not list(tmp_path.iterdir())


def test_a_clip_never_replaces_its_own_song(harmonic, tmp_path):
    samples, rate = read_audio(SONG)
    soundfile.write(tmp_path / "song.wav", samples, rate)
    dance = type(harmonic)(harmonic.basis, harmonic.spectrogram, harmonic.mapping,
                           tmp_path / "song.wav")
    with pytest.raises(InputError, match="would replace song.wav itself"):
        export_dance(dance.window(1.0, 1.0), tmp_path / "song.glb", force=True)


def test_a_rendered_clip_has_the_clip_s_frames_and_song(tmp_path, capsys):
    status, out, err = run(capsys, "render", "chain", SONG, "--start", START, "--duration",
                           LENGTH, "--fps", 10, "--size", "64x48", "-o", tmp_path / "clip.mp4")
    assert status == 0, err
    with av.open(str(tmp_path / "clip.mp4")) as container:
        video = sum(1 for _ in container.decode(video=0))
    assert video == math.ceil(LENGTH * 10)  # frames at i/fps, i < ⌈duration·fps⌉
    with av.open(str(tmp_path / "clip.mp4")) as container:
        stream = container.streams.audio[0]
        audio = np.concatenate([frame.to_ndarray().mean(axis=0) for frame in
                                container.decode(stream)])
        rate = stream.rate
    assert abs(len(audio) / rate - LENGTH) < 0.05
    song, song_rate = read_audio(SONG)
    assert song_rate == rate
    part = song[int(round(START * rate)):][:len(audio)]
    lags = range(-2048, 2049, 16)  # AAC's priming is trimmed: the best lag is near 0
    scores = [np.dot(audio[max(0, lag):len(part) + min(0, lag)],
                     part[max(0, -lag):len(part) - max(0, lag)]) for lag in lags]
    assert abs(list(lags)[int(np.argmax(scores))]) <= 64
