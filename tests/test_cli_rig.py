"""`eigendance modes` and `eigendance animate-rig`."""

import json

import numpy as np
import pytest
import soundfile

from eigendance.cli import main
from eigendance.modal.model import ModalModel
from eigendance.modal.motion import parse_modes, rig_coefficients
from eigendance.modal.rig import Rig
from eigendance.modal.sample_rigs import load_rig
from eigendance.music.mapping import Mapping
from eigendance.music.mode_settings import ModeSettings
from eigendance.music.spectrogram import Spectrogram
from helpers import fixture_path


def test_modes_writes_the_modal_file_and_prints_a_table(tmp_path, capsys):
    output = tmp_path / "fox.npz"
    assert main(["modes", fixture_path("rigged", "Fox.glb"), "-o", str(output),
                 "--show", "4"]) == 0
    printed = capsys.readouterr().out
    # 24 joints, of which _rootJoint and b_Root_00 move no vertex and connect nothing that
    # does (docs/design.md#skeleton): 22 bodies, 21 spherical joints
    assert "frequency Hz" in printed and "6 rigid + 63 vibration modes" in printed
    model = ModalModel.load(output)
    assert model.n_modes == 63 and model.rigid_modes == 6 and model.n_bodies == 22
    assert main(["modes", "loop16", "-o", str(output)]) == 1  # exists, no --force
    assert "--force" in capsys.readouterr().err
    assert main(["modes", "loop16", "-o", str(output), "--force"]) == 0
    assert ModalModel.load(output).nullspace_dim == 19


def test_modes_reports_a_bad_rig_on_one_line(tmp_path, capsys):
    rig = tmp_path / "rig.json"
    rig.write_text(json.dumps({"format": "eigendance.skeleton", "version": 1,
                               "bodies": [{"name": "a", "start": [0, 0, 0], "end": [0, 0, 0],
                                           "radius": 1}]}))
    assert main(["modes", str(rig), "-o", str(tmp_path / "m.npz")]) == 1
    error = capsys.readouterr().err.strip()
    assert error.count("\n") == 0 and "body 'a' has zero length" in error


def test_animate_rig_without_audio(tmp_path):
    output = tmp_path / "anim.npz"
    assert main(["animate-rig", "loop8", "--modes", "0,2-3", "--fps", "10", "--duration",
                 "1", "-o", str(output)]) == 0
    with np.load(output) as data:
        assert data["positions"].shape == (11, len(data["rest_vertices"]), 3)
        assert data["positions"].dtype == np.float32
        assert data["faces"].shape[1] == 3 and data["times"].shape == (11,)
        assert data["body_transforms"].shape == (11, 8, 4, 4)
        assert data["modes"].tolist() == [0, 2, 3]
        coefficients = data["coefficients"]
        assert np.all(coefficients[:, [1, 4]] == 0) and np.any(coefficients[:, 0] != 0)
        motion = np.abs(data["positions"] - data["rest_vertices"]).max()
        assert 0.01 < motion < 0.5  # visible, not exploding (the loop is about 3 wide)


def test_animate_rig_with_audio_drive(tmp_path, capsys):
    rate = 8000
    time = np.arange(rate) / rate
    quiet_then_loud = np.where(time < 0.5, 0.0, 0.5 * np.sin(2 * np.pi * 60 * time))
    audio = tmp_path / "tone.wav"
    soundfile.write(audio, quiet_then_loud, rate)
    output = tmp_path / "anim.npz"
    assert main(["animate-rig", fixture_path("rigged", "RiggedSimple.glb"), str(audio),
                 "--fps", "20", "--bands", "4", "--skinning", "lbs", "-o", str(output)]) == 0
    with np.load(output) as data:
        coefficients = data["coefficients"]
        assert len(coefficients) == 21
        assert np.abs(coefficients[:9]).max() < 1e-9  # silence stands still
        assert np.abs(coefficients[12:]).max() > 0
    bad = tmp_path / "bad.wav"
    bad.write_text("not audio")
    assert main(["animate-rig", "chain", str(bad), "-o", str(tmp_path / "x.npz")]) == 1
    assert "bad.wav: not a readable audio file" in capsys.readouterr().err


def test_mode_selection():
    assert parse_modes("0,2-4", 6).tolist() == [0, 2, 3, 4]
    assert parse_modes(None, 3) is None  # the palette's default selection
    with pytest.raises(Exception, match="mode 9 does not exist"):
        parse_modes("9", 5)



def test_animate_rig_plays_the_mapping_as_the_python_api_does(tmp_path):
    """`animate-rig --mapping` and `rig_coefficients` give the same motion; so does the mapping
    it saves (every setting explicit), and the positions are the modal skin of it."""
    audio = fixture_path("audio", "kevin_macleod_vibe_ace_20s-24s.ogg")
    palette = ModeSettings(np.array([0, 3, 5]), None, np.array([0.0, 1.0, 2.0]), 1.5)
    mapping = Mapping(np.linspace(0, 1, 32), [0.4, -0.2], gain=0.8, smoothing=0.1, offset=0.5,
                      modes=palette)
    mapping.save(tmp_path / "m.json")
    output, saved = tmp_path / "anim.npz", tmp_path / "saved.json"
    assert main(["animate-rig", "hand", audio, "--mapping", str(tmp_path / "m.json"),
                 "--fps", "24", "--save-mapping", str(saved), "-o", str(output)]) == 0
    rig = Rig.from_skeleton(load_rig("hand"))
    spectrogram = Spectrogram.from_file(audio, bands=32)
    with np.load(output) as data:
        times, coefficients = data["times"], data["coefficients"]
        expected = rig_coefficients(rig.model, spectrogram, mapping, times)
        np.testing.assert_allclose(coefficients, expected, rtol=1e-12, atol=0)
        again = rig_coefficients(rig.model, spectrogram, Mapping.load(saved), times)
        np.testing.assert_allclose(again, expected, rtol=1e-12, atol=0)
        assert data["modes"].tolist() == [0, 3, 5] and float(data["time_scale"]) == 1.5
        positions = rig.skin.positions(coefficients)
        scale = np.abs(data["rest_vertices"]).max()
        np.testing.assert_allclose(data["positions"], positions, atol=1e-5 * scale)


def test_animate_rig_flags_override_the_palette_and_joints_file(tmp_path, capsys):
    joints = tmp_path / "joints.json"
    joints.write_text(json.dumps({"j0": 50.0, "j1": "auto"}))
    output = tmp_path / "a.npz"
    assert main(["animate-rig", "chain", "--joints", str(joints), "--modes", "1-2",
                 "--amplitude", "0.05", "--time-scale", "0.5", "--duration", "1",
                 "-o", str(output)]) == 0
    skeleton = load_rig("chain").with_stiffness({"j0": 50.0})
    model = ModalModel.from_skeleton(skeleton)
    with np.load(output) as data:
        np.testing.assert_allclose(data["frequencies"], model.frequencies, rtol=1e-12)
        assert data["modes"].tolist() == [1, 2] and float(data["time_scale"]) == 0.5
        np.testing.assert_allclose(data["amplitudes"], 0.05)  # under the floor's cap
    joints.write_text(json.dumps({"elbow": 1.0}))
    assert main(["animate-rig", "chain", "--joints", str(joints), "-o", str(output),
                 "--force"]) == 1
    assert "no joint named 'elbow'" in capsys.readouterr().err


def test_modes_prints_the_default_palette(tmp_path, capsys):
    assert main(["modes", "loop16", "-o", str(tmp_path / "m.npz")]) == 0
    printed = capsys.readouterr().out
    assert "default palette: modes 0, 1, 2, 3" in printed and "time scale" in printed


@pytest.mark.parametrize("tempo", ["free", "beat"])
def test_animate_rig_tempo_flag_sets_the_palette_tempo(tmp_path, tempo):
    """`--tempo free|beat` plays what a mapping whose palette says that tempo plays (the
    Blender add-on's *On the beat* switch); the two differ on a song with beats."""
    audio = fixture_path("audio", "beatnet_808kick120bpm.mp3")  # a real kick track: beats
    output = tmp_path / f"{tempo}.npz"
    assert main(["animate-rig", "hand", audio, "--tempo", tempo, "--fps", "24", "--duration",
                 "6", "-o", str(output)]) == 0
    rig = Rig.from_skeleton(load_rig("hand"))
    spectrogram = Spectrogram.from_file(audio)
    assert spectrogram.rhythm.has_beats
    as_file = rig.mapping(spectrogram, None)
    as_file = Mapping.from_json({**as_file.to_json(),
                                 "modes": {**as_file.modes.to_json(), "tempo": tempo}})
    with np.load(output) as data:
        times, coefficients = data["times"], data["coefficients"]
    np.testing.assert_allclose(coefficients, rig_coefficients(rig.model, spectrogram, as_file,
                                                              times), rtol=1e-12, atol=1e-12)
    other = "beat" if tempo == "free" else "free"
    as_other = Mapping.from_json({**as_file.to_json(),
                                  "modes": {**as_file.modes.to_json(), "tempo": other}})
    assert not np.allclose(coefficients, rig_coefficients(rig.model, spectrogram, as_other,
                                                          times))
