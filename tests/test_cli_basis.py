import subprocess
import sys

import numpy as np
import pytest
import trimesh

from eigendance.cli import main
from eigendance.harmonic.basis import HarmonicBasis
from helpers import fixture_path


def test_basis_command_writes_the_basis_file(tmp_path, capsys):
    out = tmp_path / "knight.npz"
    assert main(["basis", fixture_path("meshes", "decimated-knight.off"), "-k", "20",
                 "-o", str(out)]) == 0
    line = capsys.readouterr().out.strip()
    assert "n = 502 vertices" in line and "k = 20 harmonics" in line
    assert "largest eigenvalue" in line
    with np.load(out) as data:
        assert set(data.files) == {"vertices", "faces", "center", "scale", "mass", "eigenvalues",
                                   "eigenvectors", "coefficients", "residual", "laplacian"}
        assert data["eigenvectors"].shape == (502, 20) and str(data["laplacian"]) == "cotan"


def test_refuses_to_overwrite(tmp_path, capsys):
    out = tmp_path / "exists.npz"
    out.write_bytes(b"mine")
    assert main(["basis", fixture_path("meshes", "decimated-knight.off"), "-k", "5",
                 "-o", str(out)]) == 1
    assert "--force" in capsys.readouterr().err and out.read_bytes() == b"mine"


def test_solvers_agree_through_the_cli(tmp_path):
    paths = {}
    for solver in ("bands", "eigsh"):
        paths[solver] = tmp_path / f"{solver}.npz"
        assert main(["basis", fixture_path("meshes", "decimated-knight.off"), "-k", "30",
                     "--solver", solver, "--no-cache", "-o", str(paths[solver])]) == 0
    bands, eigsh = (HarmonicBasis.load(paths[s]).eigenvalues for s in ("bands", "eigsh"))
    assert np.allclose(bands, eigsh, rtol=1e-8, atol=1e-10)


def test_bad_input_exits_1_with_one_line_and_no_traceback(tmp_path):
    bad = tmp_path / "nan.obj"
    bad.write_text("v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n")
    result = subprocess.run([sys.executable, "-m", "eigendance.cli", "basis", str(bad), "-k", "2",
                             "-o", str(tmp_path / "o.npz")], capture_output=True, text=True)
    assert result.returncode == 1
    assert result.stderr.startswith("eigendance: error: nan.obj:")
    assert "Traceback" not in result.stderr and len(result.stderr.strip().splitlines()) == 1
    assert not (tmp_path / "o.npz").exists()


REAL_MESHES = ["decimated-knight.off", "beetle.obj", "teapot.obj", "fertility.off"]
BROKEN = {
    "empty.obj": "",
    "points.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\n",
    "index.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n",
    "inf.off": "OFF\n3 1 0\n0 0 0\n1 0 0\n0 inf 0\n3 0 1 2\n",
    "flat.obj": "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n",
    "words.stl": "this is not an stl file",
    "mesh.xyz": "1 2 3",
}


def run_basis(path, out, *options):
    return main(["basis", str(path), "-k", "12", "--force", "-o", str(out), *options])


def test_real_meshes_give_a_basis_messy_ones_after_a_hint(tmp_path, capsys):
    """Messy real meshes (holes, components, non-manifold edges) all end with a finite basis."""
    paths = [fixture_path("meshes", name) for name in REAL_MESHES]
    trimesh.creation.annulus(0.5, 1.0, 0.2).export(tmp_path / "annulus.ply")
    paths.append(tmp_path / "annulus.ply")
    out = tmp_path / "out.npz"
    for path in paths:
        status = run_basis(path, out)
        if status != 0:
            error = capsys.readouterr().err.strip().splitlines()[-1]
            assert "non-manifold edges" in error and "--laplacian robust" in error, error
            status = run_basis(path, out, "--laplacian", "robust")
        assert status == 0, path
        basis = HarmonicBasis.load(out)
        assert np.all(np.isfinite(basis.eigenvectors)) and np.all(np.isfinite(basis.residual))


@pytest.mark.parametrize("name", sorted(BROKEN))
def test_broken_files_give_one_line_error(tmp_path, capsys, name):
    (tmp_path / name).write_text(BROKEN[name])
    assert run_basis(tmp_path / name, tmp_path / "out.npz") == 1
    captured = capsys.readouterr()
    assert captured.err.startswith(f"eigendance: error: {name}")
    assert len(captured.err.strip().splitlines()) == 1 and "Traceback" not in captured.err
    assert not (tmp_path / "out.npz").exists()


@pytest.mark.parametrize("argv", [["--help"], ["basis", "--help"]])
def test_help(argv, capsys):
    with pytest.raises(SystemExit) as exit_info:
        main(argv)
    assert exit_info.value.code == 0 and "usage" in capsys.readouterr().out


def test_reduced_and_exact_are_chosen_and_said(tmp_path, capsys, monkeypatch):
    """`basis --reduced/--exact/--samples` and the rule (docs/design.md#reduced-basis): the line
    says which construction was used, the file holds it, and a reduced basis's eigenvalues lie
    above the exact solver's (Rayleigh–Ritz) — the exact ones being independent of the reduction."""
    knight = fixture_path("meshes", "decimated-knight.off")
    paths = {name: tmp_path / f"{name}.npz" for name in ("exact", "reduced", "auto", "large")}
    assert main(["basis", knight, "-k", "12", "--exact", "--no-cache",
                 "-o", str(paths["exact"])]) == 0
    assert "(exact)" in capsys.readouterr().out
    assert main(["basis", knight, "-k", "12", "--reduced", "--samples", "150", "--no-cache",
                 "-o", str(paths["reduced"])]) == 0
    reduced = HarmonicBasis.load(paths["reduced"])
    assert reduced.reduced is not None and 140 <= reduced.reduced.count <= 160
    assert f"(reduced, 150 samples asked, {reduced.reduced.count} placed)" in \
        capsys.readouterr().out
    exact = HarmonicBasis.load(paths["exact"])
    assert exact.reduced is None
    assert np.all(reduced.eigenvalues[1:] >= exact.eigenvalues[1:] * (1 - 1e-9))
    assert main(["basis", knight, "-k", "12", "-o", str(paths["auto"])]) == 0
    assert "(exact)" in capsys.readouterr().out  # 502 vertices: the exact solve fits
    # as if the mesh were huge
    monkeypatch.setattr("eigendance.harmonic.construction.EXACT_VALUES", 100)
    assert main(["basis", knight, "-k", "12", "--samples", "150", "--no-cache",
                 "-o", str(paths["large"])]) == 0
    assert "(reduced, " in capsys.readouterr().out
    with pytest.raises(SystemExit) as exit_info:
        main(["basis", knight, "--reduced", "--exact", "-o", str(tmp_path / "both.npz")])
    assert exit_info.value.code == 1 and "not allowed with" in capsys.readouterr().err
    assert main(["basis", knight, "--exact", "--samples", "150",
                 "-o", str(tmp_path / "both.npz")]) == 1
    assert "--samples" in capsys.readouterr().err and not (tmp_path / "both.npz").exists()
