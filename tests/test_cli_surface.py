"""--surface on the rig commands (docs/design.md#surface-of-a-rig): `animate-rig`, `export --rig`
and `render` ripple a rig's skin in its harmonics while its bones sway."""

import numpy as np
import pygltflib

from eigendance.cli import main
from eigendance.export.rig_dance import rig_dance
from eigendance.modal.rig import Rig
from eigendance.modal.sample_rigs import load_rig
from eigendance.modal.surface import SurfaceDance
from eigendance.music.gallery import initial_gallery
from eigendance.music.mapping import Mapping
from eigendance.music.spectrogram import Spectrogram
from helpers import fixture_path

FOX = fixture_path("rigged", "Fox.glb")
SONG = fixture_path("audio", "kevin_macleod_vibe_ace_20s-24s.ogg")  # 4 s


def test_animate_rig_with_a_surface_plays_what_the_export_plays(tmp_path, capsys):
    """The animation file of `animate-rig --surface M --skinning lbs` holds, frame by frame,
    the positions of the same rig and mapping built through the Python API."""
    song = Spectrogram.from_file(SONG)
    rig = Rig(load_rig(FOX))
    mapping = initial_gallery(rig.surface(20).basis, song, 4)[1]
    path = tmp_path / "ripple.json"
    mapping.save(path)
    output = tmp_path / "fox.npz"
    assert main(["animate-rig", FOX, SONG, "--surface", str(path), "--surface-k", "20",
                 "--surface-gain", "2", "--skinning", "lbs", "--fps", "10", "--save-mapping",
                 str(tmp_path / "whole.json"), "-o", str(output)]) == 0
    printed = capsys.readouterr().out
    assert "surface: " in printed and "of the skin's motion" in printed
    mapping.gain = 2.0
    dance = rig_dance(rig, song, rig.mapping(song, None), "lbs",
                      surface=SurfaceDance(rig.surface(20), song, mapping))
    with np.load(output) as data:
        times, positions = data["times"], data["positions"]
    frames = [0, len(times) // 2, len(times) - 1]
    expected = dance.blend_positions(times[frames])
    diagonal = np.linalg.norm(np.ptp(rig.skeleton.vertices, axis=0))
    assert np.abs(positions[frames] - expected).max() <= 1e-5 * diagonal
    bones = rig.positions(rig.coefficients(song, rig.mapping(song, None), times[frames]), "lbs")
    assert np.abs(positions[frames] - bones).max() > 1e-3 * diagonal  # the skin ripples
    # The saved mapping holds both halves: played again without --surface, the same dance.
    again = tmp_path / "again.npz"
    assert main(["animate-rig", FOX, SONG, "--mapping", str(tmp_path / "whole.json"),
                 "--surface-k", "20", "--skinning", "lbs", "--fps", "10", "-o",
                 str(again)]) == 0
    with np.load(again) as data:
        np.testing.assert_allclose(data["positions"], positions, atol=1e-6 * diagonal)


def test_export_of_a_rig_with_a_surface_has_morph_targets_under_its_skin(tmp_path):
    output = tmp_path / "fox.glb"
    assert main(["export", "--rig", FOX, SONG, "--surface", "auto", "--surface-k", "20",
                 "--fps", "5", "-o", str(output)]) == 0
    gltf = pygltflib.GLTF2().load(str(output))
    assert gltf.skins and gltf.meshes[0].primitives[0].targets
    paths = {channel.target.path for channel in gltf.animations[0].channels}
    assert paths == {"translation", "rotation", "weights"}


def test_surface_errors_are_one_line(tmp_path, capsys):
    output = tmp_path / "out.npz"
    assert main(["animate-rig", FOX, "--surface", "auto", "-o", str(output)]) == 1
    error = capsys.readouterr().err.strip().splitlines()[-1]
    assert error.startswith("eigendance: error:") and "needs a song" in error
    wrong = tmp_path / "eight.json"
    Mapping(np.zeros(8), np.ones(4)).save(wrong)
    assert main(["export", fixture_path("meshes", "teapot.obj"), SONG, "--surface",
                 str(wrong), "-o", str(tmp_path / "t.glb")]) == 1
    assert "--surface ripples a rig's skin" in capsys.readouterr().err
    assert not output.exists()
