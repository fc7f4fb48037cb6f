"""Bad input on the command line (docs/design.md#errors): each reproducer of issue 12, and
every flag given absurd values, ends in one line on stderr and exit status 1 — no traceback, no
NaN, no output file — or, where the input is merely unusual, in a correct result.

Every input is made here, by the test; commands run in-process through `eigendance.cli.main`.
"""

import argparse
import json
import math
import os
import re
import socket
import subprocess
import sys
import time

import numpy as np
import pygltflib
import pytest
import soundfile
import trimesh

import eigendance.limits
from eigendance.cli import build_parser, main
from eigendance.harmonic.basis import HarmonicBasis
from eigendance.harmonic.mesh import Mesh
from eigendance.music.spectrogram import Spectrogram
from helpers import fixture_path, start

KNIGHT = fixture_path("meshes", "decimated-knight.off")
SR = 8000


def tone(seconds=1.0, sample_rate=SR):
    return 0.5 * np.sin(2 * np.pi * 440 * np.arange(int(seconds * sample_rate)) / sample_rate)


def mapping(**changes):
    document = {"format": "eigendance.mapping", "version": 2, "bands": 64,
                "transfer": [0.5] * 64, "amplification": [1.0] * 8, "seed": None}
    document.update(changes)
    return json.dumps(document)


def skeleton(body=None, joint=None):
    document = {"format": "eigendance.skeleton", "version": 1,
                "bodies": [{"name": "upper", "start": [0, 0, 0], "end": [0, 0, 1],
                            "radius": 0.1},
                           {"name": "lower", "start": [0, 0, 1], "end": [0, 1, 1],
                            "radius": 0.1}],
                "joints": [{"name": "knee", "type": "revolute", "bodies": ["upper", "lower"],
                            "stiffness": 10.0}]}
    document["bodies"][0].update(body or {})
    document["joints"][0].update(joint or {})
    return json.dumps(document)


def obj(vertices, faces, header=b""):
    lines = [f"v {x!r} {y!r} {z!r}" for x, y, z in np.asarray(vertices, float).tolist()]
    lines += [f"f {a} {b} {c}" for a, b, c in faces]
    return header + "\n".join(lines).encode() + b"\n"


TETRA = ([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], [(1, 3, 2), (1, 2, 4), (1, 4, 3), (2, 3, 4)])


@pytest.fixture(scope="module")
def made(tmp_path_factory):
    """name → path of every input the corpus uses, all written here."""
    folder = tmp_path_factory.mktemp("inputs")
    paths = {}

    def put(name, content):
        path = folder / name
        path.write_bytes(content if isinstance(content, bytes) else content.encode())
        paths[name] = str(path)

    def put_audio(name, samples, sample_rate=SR, **options):
        soundfile.write(folder / name, samples, sample_rate, **options)
        paths[name] = str(folder / name)

    put_audio("ok.wav", tone())
    put_audio("1hz.wav", np.zeros(10), 1)
    put_audio("empty.wav", np.zeros(0))
    for name, value in (("nan.wav", np.nan), ("inf.wav", np.inf)):
        samples = tone().astype(np.float32)
        samples[100] = value
        put_audio(name, samples, subtype="FLOAT")
    put_audio("song.mp3", tone(2.0, 44100), 44100, format="MP3")
    data = (folder / "song.mp3").read_bytes()
    put("damaged.mp3", data[:2000] + np.random.default_rng(0).bytes(5000) + data[7000:])

    sphere = trimesh.creation.icosphere(2)
    basis = HarmonicBasis.from_mesh(Mesh.from_arrays(sphere.vertices, sphere.faces), 8,
                                    cache=False)
    basis.save(folder / "basis.npz")
    paths["basis.npz"] = str(folder / "basis.npz")
    arrays = dict(np.load(folder / "basis.npz"))
    spoiled = {"basis-nan": {"eigenvectors": arrays["eigenvectors"] * np.nan},
               "basis-faces": {"faces": arrays["faces"] + 10**6},
               "basis-types": {"eigenvalues": arrays["eigenvalues"].astype(str)},
               "basis-scale": {"scale": np.array([1.0, 2.0])},
               "basis-complex": {"vertices": arrays["vertices"].astype(complex)},
               "basis-huge": {"coefficients": arrays["coefficients"] * 1e300}}
    for name, change in spoiled.items():
        np.savez(folder / f"{name}.npz", **{**arrays, **change})
        paths[f"{name}.npz"] = str(folder / f"{name}.npz")

    Spectrogram.from_samples(tone(), SR).save(folder / "spectrogram.npz")
    paths["spectrogram.npz"] = str(folder / "spectrogram.npz")
    arrays = dict(np.load(folder / "spectrogram.npz"))
    values = arrays["values"].copy()
    values[3, 3] = np.nan
    for name, change in {"spectrogram-nan": {"values": values},
                         "spectrogram-rate": {"rate": np.float64(0)},
                         "spectrogram-long": {"duration": np.float64(1e300)},
                         "spectrogram-loud": {"values": arrays["values"] * 1e30}}.items():
        np.savez(folder / f"{name}.npz", **{**arrays, **change})
        paths[f"{name}.npz"] = str(folder / f"{name}.npz")

    put("bigint.json", mapping().replace('"seed": null', '"seed": ' + "9" * 5000))
    put("int4000.json", mapping().replace('"seed": null', '"seed": ' + "9" * 4000))
    put("nested.json", "[" * 100000 + "]" * 100000)
    put("amplified.json", mapping(amplification=[1e200] * 8))
    put("radius.json", skeleton(body={"radius": 1e-300}))
    put("density.json", skeleton(body={"density": 1e-300}))
    put("unhashable.json", skeleton(joint={"bodies": [["upper"], ["lower"]]}))
    put("nameless.json", skeleton(body={"name": 5}))
    put("bigradius.json", skeleton().replace('"radius": 0.1', '"radius": ' + "9" * 400, 1))

    vertices, faces = TETRA
    put("huge.obj", obj(np.array(vertices) * 1e300, faces))
    put("index0.obj", obj(vertices, [(0, 1, 2), *faces]))
    put("latin1.obj", obj(vertices, faces, header="# modèle café\n".encode("latin-1")))
    put("binary.obj", np.random.default_rng(1).bytes(2000))
    sphere.export(folder / "sphere.stl")
    data = (folder / "sphere.stl").read_bytes()
    put("truncated.stl", data[: len(data) // 2 + 7])
    put("point.obj", obj([[1, 1, 1]] * 4, faces))
    with open(fixture_path("rigged", "RiggedSimple.glb"), "rb") as file:
        data = file.read()
    put("cut.glb", data[: len(data) // 2])
    put("zero-ibm.glb", zero_inverse_bind_matrices(fixture_path("rigged", "RiggedSimple.glb")))
    put("version7.glb", data[:4] + (7).to_bytes(4, "little") + data[8:])  # pygltflib warns
    return paths


def zero_inverse_bind_matrices(path) -> bytes:
    """The bytes of a .glb whose first skin's inverse bind matrices are all zeros."""
    document = pygltflib.GLTF2().load(path)
    accessor = document.accessors[document.skins[0].inverseBindMatrices]
    view = document.bufferViews[accessor.bufferView]
    blob = bytearray(document.binary_blob())
    start = view.byteOffset + (accessor.byteOffset or 0)
    blob[start:start + 64 * accessor.count] = bytes(64 * accessor.count)
    document.set_binary_blob(bytes(blob))
    return b"".join(document.save_to_bytes())


def run(argv, capfd) -> tuple[int, str, str]:
    """(exit status, stdout, stderr) of one command, stderr read at the file descriptor (so
    the lines a C library prints are seen too)."""
    try:
        status = main([str(arg) for arg in argv])
    except SystemExit as exit_:  # argparse
        status = exit_.code
    out, err = capfd.readouterr()
    return status, out, err


def assert_refused(status, err, folder, fragment=""):
    lines = err.strip().splitlines()
    assert status == 1, err
    assert len(lines) == 1 and lines[0].startswith("eigendance: error: "), err
    assert "Traceback" not in err and fragment in lines[0], lines[0]
    left = os.listdir(folder) if os.path.isdir(folder) else []
    assert left == [], f"output left behind: {left}"


# (id, command with {name} for an input and {out} for the output folder, what the line says)
REFUSED = [
    ("output is a folder", "basis " + KNIGHT + " -k 5 -o {out}", "is a folder"),
    ("picture of unknown type", "spectrum {ok.wav} --png {out}/s.xyz -o {out}/s.npz",
     "cannot draw a picture of type 'xyz'"),
    ("5000-digit integer", "animate {basis.npz} {spectrogram.npz} --mapping {bigint.json} "
     "-o {out}/a.npz", "an integer of 5000 digits"),
    ("4000-digit integer", "gallery {basis.npz} {spectrogram.npz} --breed {int4000.json} "
     "-o {out}", "an integer of 4000 digits"),
    ("100k nested arrays", "gallery {basis.npz} {spectrogram.npz} --breed {nested.json} "
     "-o {out}", "nested too deeply"),
    ("nested rig mapping", "animate-rig chain --mapping {nested.json} -o {out}/a.npz",
     "nested too deeply"),
    ("basis with NaN", "animate {basis-nan.npz} {spectrogram.npz} -o {out}/a.npz",
     "eigenvectors holds NaN"),
    ("basis faces past the vertices", "animate {basis-faces.npz} {spectrogram.npz} "
     "-o {out}/a.npz", "faces must be triangles of vertex indices 0 … 161"),
    ("basis of strings", "gallery {basis-types.npz} {spectrogram.npz} -o {out}",
     "eigenvalues must hold real numbers"),
    ("basis scale a vector", "animate {basis-scale.npz} {spectrogram.npz} -o {out}/a.npz",
     "scale has shape (2,)"),
    ("basis complex", "animate {basis-complex.npz} {spectrogram.npz} -o {out}/a.npz",
     "vertices must hold real numbers"),
    ("basis inconsistent", "animate {basis-huge.npz} {spectrogram.npz} -o {out}/a.npz",
     "coefficients do not follow"),
    ("spectrogram with NaN", "animate {basis.npz} {spectrogram-nan.npz} -o {out}/a.npz",
     "values holds NaN"),
    ("spectrogram rate 0", "animate-rig chain {spectrogram-rate.npz} -o {out}/a.npz",
     "rate must be positive"),
    ("spectrogram of 1e300 s", "animate {basis.npz} {spectrogram-long.npz} -o {out}/a.npz",
     "do not fit a duration"),
    ("spectrogram too loud", "animate {basis.npz} {spectrogram-loud.npz} -o {out}/a.npz",
     "values must lie in [0, 1]"),
    ("radius 1e-300", "modes {radius.json} -o {out}/m.npz", "radius / length = 1e-300"),
    ("density 1e-300", "animate-rig {density.json} -o {out}/a.npz",
     "mass or moment of inertia outside"),
    ("unhashable body name", "modes {unhashable.json} -o {out}/m.npz",
     "names unknown body [\"upper\"]"),
    ("body name a number", "modes {nameless.json} -o {out}/m.npz", "needs a \"name\" string"),
    ("400-digit radius", "modes {bigradius.json} -o {out}/m.npz", "an integer of 400 digits"),
    ("truncated glTF", "animate-rig {cut.glb} -o {out}/a.npz", "cut.glb: "),
    ("1 Hz audio", "spectrum {1hz.wav} -o {out}/s.npz", "1hz.wav: a sample rate of 1 Hz"),
    ("0-sample audio", "spectrum {empty.wav} -o {out}/s.npz", "empty.wav: holds no audio"),
    ("0-sample audio for a rig", "animate-rig chain {empty.wav} -o {out}/a.npz",
     "holds no audio"),
    ("NaN samples", "animate-rig chain {nan.wav} -o {out}/a.npz", "NaN or infinite samples"),
    ("inf samples", "animate {basis.npz} {inf.wav} -o {out}/a.npz", "NaN or infinite samples"),
    ("damaged MP3, libmpg123 silent", "spectrum {damaged.mp3} -o {out}/s.npz",
     "damaged.mp3: corrupt audio data"),
    ("coordinates 1e300", "basis {huge.obj} -k 2 -o {out}/b.npz", "coordinates reach 1e+300"),
    ("OBJ face index 0", "basis {index0.obj} -k 2 -o {out}/b.npz",
     "line 5: a face uses vertex index 0"),
    ("truncated STL", "basis {truncated.stl} -k 2 -o {out}/b.npz", "truncated binary STL"),
    ("binary OBJ", "basis {binary.obj} -k 2 -o {out}/b.npz", "binary.obj:"),
    ("a point", "basis {point.obj} -k 2 -o {out}/b.npz", "point.obj:"),
    ("amplification 1e200", "animate {basis.npz} {spectrogram.npz} --mapping "
     "{amplified.json} -o {out}/a.npz", "not written: positions holds NaN or infinite"),
    ("amplification 1e200 on a rig", "animate-rig chain {spectrogram.npz} --mapping "
     "{amplified.json} -o {out}/a.npz", "not written"),
    ("modes 0-999999999", "animate-rig chain --modes 0-999999999 -o {out}/a.npz",
     "modes 0-999999999: the rig has"),
    ("a day at 1000 fps", "animate-rig chain --duration 86400 --fps 1000 -o {out}/a.npz",
     "86400001 frames"),
    ("gallery of 10^8", "gallery {basis.npz} {spectrogram.npz} -n 100000000 -o {out}",
     "a gallery has"),
    ("k beyond the mesh", "basis " + KNIGHT + " -k 20000 -o {out}/b.npz",
     "need a mesh of more than 20000 vertices"),
    # issue 21: no non-finite value reaches a file, no crash on what a reader accepts
    ("amplification 1e200 in a glb", "export {basis.npz} {ok.wav} --mapping {amplified.json} "
     "-o {out}/a.glb", "amplified.json: the motion it asks for leaves the range"),
    ("amplification 1e200 in a point cache", "export {basis.npz} {ok.wav} --mapping "
     "{amplified.json} -o {out}/a.pc2", "amplified.json: the motion it asks for leaves"),
    ("amplification 1e200 in a rig export", "export chain {ok.wav} --mapping {amplified.json} "
     "-o {out}/a.glb", "amplified.json: the motion it asks for turns or moves a body"),
    ("render at 1e-9 fps", "render {basis.npz} {ok.wav} --fps 1e-9 -o {out}/v.mp4",
     "frames per second must be from 0.01 to 240"),
    ("all-zero inverse bind matrices", "modes {zero-ibm.glb} -o {out}/m.npz",
     "zero-ibm.glb: skin 0: inverseBindMatrices[0] is not an invertible matrix"),
    ("all-zero inverse bind matrices, export", "export {zero-ibm.glb} {ok.wav} --rig "
     "-o {out}/a.glb", "is not an invertible matrix"),
    # all or nothing: the second output cannot be written (a file stands where its folder
    # would be), so the first one, written already, is removed too
    ("spectrum and an unwritable picture", "spectrum {ok.wav} --png {ok.wav}/s.png "
     "-o {out}/s.npz", "cannot write"),
    ("rig animation and an unwritable mapping", "animate-rig chain --duration 1 "
     "--save-mapping {ok.wav}/m.json -o {out}/a.npz", "cannot write"),
]


@pytest.mark.parametrize("command, fragment", [case[1:] for case in REFUSED],
                         ids=[case[0] for case in REFUSED])
def test_bad_input_is_refused_in_one_line(made, tmp_path, capfd, command, fragment):
    out = tmp_path / "out"
    names = {**made, "out": str(out)}
    argv = [re.sub(r"\{([^}]+)\}", lambda found: names[found[1]], part)
            for part in command.split()]
    if argv[0] in ("animate", "animate-rig", "modes", "spectrum", "basis", "gallery"):
        out.mkdir()
    status, _, err = run(argv, capfd)
    assert_refused(status, err, out, fragment)


def busy_port():
    holder = socket.socket()
    holder.bind(("127.0.0.1", 0))
    holder.listen()
    return holder


@pytest.mark.parametrize("command", ["serve", "demo"])
def test_a_port_in_use_is_one_line_before_any_work(tmp_path, capfd, command):
    with busy_port() as holder:
        status, _, err = run([command, "--port", holder.getsockname()[1]], capfd)
    assert_refused(status, err, tmp_path / "none", "Address already in use; try --port 0")


def test_a_solve_larger_than_memory_is_refused_with_a_k_that_fits(tmp_path, capfd,
                                                                    monkeypatch):
    monkeypatch.setattr(eigendance.limits, "available_memory", lambda: 2 << 20)  # 2 MiB
    status, _, err = run(["basis", KNIGHT, "-k", "400", "-o", tmp_path / "b.npz"], capfd)
    assert_refused(status, err, tmp_path / "none", "need about 4.8 MB of memory")
    assert "try -k 139" in err  # 0.8 · 2 MiB / (24 bytes · 502 vertices)


def test_a_rig_animation_larger_than_memory_is_refused(tmp_path, capfd, monkeypatch):
    monkeypatch.setattr(eigendance.limits, "available_memory", lambda: 1 << 30)  # 1 GiB
    status, _, err = run(["animate-rig", "chain", "--duration", "1000", "--fps", "1000", "-o",
                          tmp_path / "a.npz"], capfd)
    assert_refused(status, err, tmp_path, "1000001 frames of")
    assert "of memory; 859.0 MB can be used" in err


def test_an_animation_larger_than_the_disk_is_refused(tmp_path):
    with pytest.raises(eigendance.limits.InputError, match="of disk"):
        eigendance.limits.check_disk(tmp_path / "a.npz", 1e18, "a.npz: many frames")


# --- every flag, absurd values --------------------------------------------------------------

ABSURD = ["nan", "inf", "-inf", "1e999", "-1e999", "abc", "", "9" * 5000, "0x10"]


def numeric_flags():
    """(command, flag, values) for every option whose type checks numbers."""
    parser = build_parser()
    commands = next(action for action in parser._actions
                    if isinstance(action, argparse._SubParsersAction))
    for name, command in commands.choices.items():
        for action in command._actions:
            if not action.option_strings or action.type is None:
                continue
            values = list(ABSURD)
            low, high = getattr(action.type, "bounds", (-math.inf, math.inf))
            if math.isfinite(high):
                values.append(repr(high * 10 + 1))
            if math.isfinite(low):
                values.append(repr(low - 1))
            yield name, action.option_strings, values


@pytest.mark.parametrize("command, flags, values", list(numeric_flags()),
                         ids=[f"{c} {f[-1]}" for c, f, _ in numeric_flags()])
def test_every_numeric_flag_refuses_absurd_values_in_one_line(tmp_path, capfd, command, flags,
                                                               values):
    for value in values:
        status, _, err = run([command, "x", "y", "-o", tmp_path / "o.npz", flags[-1], value],
                             capfd)
        assert_refused(status, err, tmp_path, f"argument {'/'.join(flags)}: ")
        assert f"see eigendance {command} --help" in err


# --- unusual but valid: a correct result -----------------------------------------------------

def test_a_latin1_comment_does_not_stop_an_obj(made, tmp_path, capfd):
    status, _, err = run(["basis", made["latin1.obj"], "-k", "2", "-o", tmp_path / "b.npz"],
                         capfd)
    assert status == 0, err
    assert HarmonicBasis.load(tmp_path / "b.npz").n == 4


@pytest.mark.parametrize("scale", [1e-20, 1e14])
def test_tiny_and_huge_meshes_have_the_harmonics_of_the_same_shape(tmp_path, capfd, scale):
    """Eigenvalues are those of the normalised mesh: the same at any scale within range."""
    sphere = trimesh.creation.icosphere(2)
    bases = []
    for factor in (1.0, scale):
        path = tmp_path / f"sphere-{factor:g}.obj"
        path.write_bytes(obj(sphere.vertices * factor + 3 * factor, sphere.faces + 1))
        status, _, err = run(["basis", path, "-k", "9", "--force", "-o",
                              tmp_path / "b.npz"], capfd)
        assert status == 0, err
        bases.append(HarmonicBasis.load(tmp_path / "b.npz"))
    np.testing.assert_allclose(bases[1].eigenvalues, bases[0].eigenvalues, rtol=1e-9,
                               atol=1e-9)
    np.testing.assert_allclose(bases[1].to_original(bases[1].vertices) / scale,
                               bases[0].to_original(bases[0].vertices), rtol=1e-12, atol=1e-9)


def test_a_library_warning_does_not_reach_the_terminal(made, tmp_path, capfd):
    status, out, err = run(["modes", made["version7.glb"], "-o", tmp_path / "m.npz"], capfd)
    assert status == 0 and err == "" and "vibration modes" in out


def test_an_mp3_gives_the_spectrogram_of_its_wav_and_nothing_on_stderr(made, tmp_path, capfd):
    status, _, err = run(["spectrum", made["song.mp3"], "-o", tmp_path / "s.npz"], capfd)
    assert status == 0 and err == ""
    values = Spectrogram.load(tmp_path / "s.npz").values
    assert values.shape == (201, 64) and np.all(np.isfinite(values))


# --- issue 21: inputs are sacred, names from files, the memory advice ----------------------

def test_force_never_overwrites_an_input(tmp_path, capfd):
    """`export dance.obj … -o dance.pc2 --force` would write the rest mesh over dance.obj."""
    model = tmp_path / "dance.obj"
    model.write_bytes(obj(*TETRA))
    before = model.read_bytes()
    song = tmp_path / "song.wav"
    soundfile.write(song, tone(), SR)
    for argv in (["export", model, song, "-k", 2, "-o", tmp_path / "dance.pc2", "--force"],
                 ["spectrum", song, "-o", song, "--force"],
                 ["basis", model, "-k", 2, "-o", model, "--force"]):
        status, _, err = run(argv, capfd)
        assert_refused(status, err, tmp_path / "none", "an input is never overwritten")
    assert model.read_bytes() == before
    assert sorted(os.listdir(tmp_path)) == ["dance.obj", "song.wav"]


CONTROL = re.compile(r"[\x00-\x08\x0b-\x1f\x7f-\x9f]")


def test_names_from_files_are_printed_without_control_characters(tmp_path, capfd):
    evil = "up\x1b]0;PWNED\x07\x1b[2J\x9b"
    path = tmp_path / "evil\x1b[31m.json"
    path.write_text(skeleton(body={"name": evil}, joint={"bodies": [evil, "lower"]}))
    status, out, err = run(["modes", path, "-o", tmp_path / "m.npz"], capfd)
    assert status == 0, err
    assert "up]0;PWNED[2J" in out  # the name is there, its control characters are not
    assert not CONTROL.search(out + err), repr(out + err)
    status, out, err = run(["modes", path, "--joints", tmp_path / "none.json",
                            "-o", tmp_path / "n.npz"], capfd)
    assert status == 1 and not CONTROL.search(out + err.rstrip("\n")), repr(err)


@pytest.mark.parametrize("argv, advice", [
    (["modes", "chain"], "fewer bodies and joints"),
    (["animate-rig", "chain"], "fewer bodies and joints"),
    (["basis", KNIGHT, "-k", "5"], "smaller -k or mesh")])
def test_out_of_memory_advice_fits_the_input(tmp_path, capfd, monkeypatch, argv, advice):
    def exhausted(*_, **__):
        raise MemoryError

    monkeypatch.setattr("eigendance.cli.rigs.rig_from", exhausted)
    monkeypatch.setattr("eigendance.cli.harmonics.read_model", exhausted)
    status, _, err = run([*argv, "-o", tmp_path / "o.npz"], capfd)
    assert_refused(status, err, tmp_path, advice)
    if argv[0] != "basis":
        assert "-k" not in err


def test_demo_with_a_cache_folder_that_is_a_file_makes_its_music_for_the_run(tmp_path, capfd,
                                                                             monkeypatch):
    from eigendance.server.serve import demo_paths

    cache = tmp_path / "cache"
    cache.write_text("not a folder")
    monkeypatch.setenv("EIGENDANCE_CACHE_DIR", str(cache))
    mesh, song = demo_paths()
    _, err = capfd.readouterr()
    assert os.path.isfile(mesh) and soundfile.info(song).duration > 10
    assert err.startswith("eigendance: warning: ") and err.count("\n") == 1, err
    assert "cannot write (Not a directory)" in err and cache.read_text() == "not a folder"


DEMO_RUN = ("import sys, time; from eigendance.server.serve import demo_paths; "
            "print(demo_paths()[1], flush=True); time.sleep(float(sys.argv[1]))")


def test_the_demo_music_folder_of_a_killed_run_is_swept_by_the_next_run(tmp_path):
    """A cache that cannot be written: each run makes the demo's music in a folder of its own,
    which a run killed outright (SIGKILL) cannot remove; the next run removes it (its lock is no
    longer held), not the folder of a run still going, nor a folder that is not ours."""
    cache, temporary = tmp_path / "cache", tmp_path / "tmp"
    cache.write_text("not a folder")
    temporary.mkdir()
    env = dict(os.environ, EIGENDANCE_CACHE_DIR=str(cache), TMPDIR=str(temporary))

    def run_for(seconds):
        process = start([sys.executable, "-c", DEMO_RUN, str(seconds)], env=env,
                        stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
        folder = os.path.dirname(process.stdout.readline().strip())
        assert os.path.basename(folder).startswith("eigendance-demo-"), folder
        return process, folder

    killed, killed_folder = run_for(600)
    killed.kill()
    killed.wait(10)
    running, running_folder = run_for(600)
    foreign = temporary / "eigendance-demo-notours"  # no lock file: not ours to judge
    foreign.mkdir()
    hour_ago = time.time() - 3600  # past the minute a new run has to take its lock
    for folder in (killed_folder, running_folder, foreign):
        os.utime(folder, (hour_ago, hour_ago))
    try:
        assert os.path.isdir(killed_folder)  # SIGKILL: nothing removed it
        ended, ended_folder = run_for(0)
        assert ended.wait(60) == 0
        assert not os.path.exists(killed_folder)
        assert os.path.isdir(running_folder) and foreign.is_dir()
        assert not os.path.exists(ended_folder)  # its own, removed at its end
    finally:
        running.kill()
        running.wait(10)
