"""Models made of pieces (issue 23): do touching pieces move as one?

For every shared multi-part model and every item of its initial gallery on a real song, the
drift of touching pieces (`harmonic.contacts.part_drift`: the RMS change of offset between a
vertex and the closest point of another piece within 1% of the diagonal, over the dance,
relative to the dance's RMS motion; must be ≤ 0.3) and how many of the k harmonics drive real
shape (`music.gallery.drivable_harmonics`). Baseline, in the same run: the operator without the
coupling of pieces (CONTACT_STIFFNESS = 0), i.e. one harmonic of eigenvalue 0 per piece.

With --solve: the solve of the *uncoupled* operator (one component per piece) instead —
`solve(..., "bands")`, which solves each component on its own and identical ones once
(`harmonic.components`), beside, in the same run, the band solver on the whole operator as it
ran before (falling back to eigsh when its bands do not close) and the naive eigsh. Besides the
models above: COPIES translated copies of a shared mesh, a large model of identical pieces.

Run: EIGENDANCE_SHARED_DATA=/work/shared/data .venv/bin/python benchmarks/bench_parts.py
     [--k 150] [--song kevin_macleod_vibe_ace.ogg] [--frames 400] [--solve]
"""

from __future__ import annotations

import argparse
import os
import time
import warnings

import numpy as np

from shared_data import shared_path

MODELS = [("textured", "kenney_cakeBirthday.glb"), ("textured", "robot.obj"),
          ("textured", "MorphStressTest.gltf"), ("textured", "craft_speederD.gltf"),
          ("rigged", "quaternius_Character_Gun.glb"),
          ("rigged", "quaternius_Astronaut_FinnTheFrog.glb"),
          ("rigged", "quaternius_men_Casual.glb"), ("rigged", "quaternius_Horse.glb")]


def measure(mesh, k, song, frames, stiffness, solver):
    from eigendance.harmonic import laplacian
    from eigendance.harmonic.basis import HarmonicBasis
    from eigendance.harmonic.contacts import part_drift
    from eigendance.harmonic.motion import positions_at
    from eigendance.music.gallery import drivable_harmonics, initial_gallery

    laplacian.CONTACT_STIFFNESS = stiffness
    kind = "robust" if mesh.non_manifold_edge_count() else "cotan"
    start = time.perf_counter()
    basis = HarmonicBasis.from_mesh(mesh, min(k, mesh.n - 2), laplacian=kind, solver=solver,
                                    cache=False)
    seconds = time.perf_counter() - start
    items = initial_gallery(basis, song, 8)
    times = np.linspace(0, song.duration, frames)
    rest = basis.to_original(basis.vertices)
    drift = [part_drift(rest, basis.faces, positions_at(basis, song, item, times) - rest)
             for item in items]
    zero = int(np.sum(basis.eigenvalues < 1e-9 * basis.eigenvalues.max()))
    return drift, len(drivable_harmonics(basis)), basis.k, zero, seconds


COPIES = (8, ("meshes", "fertility.off"))


def uncoupled(mesh):
    """(L, M) of `mesh` without the coupling of pieces."""
    from eigendance.harmonic import laplacian

    laplacian.CONTACT_STIFFNESS = 0.0
    kind = "robust" if mesh.non_manifold_edge_count() else "cotan"
    return laplacian.laplacian(mesh.vertices, mesh.faces, kind)


def timed(function, *arguments):
    """(result, seconds, label) of function(*arguments); the label names an eigsh fallback."""
    from eigendance.errors import InternalError
    from eigendance.harmonic.eigensolver import solve_eigsh

    start = time.perf_counter()
    try:
        return function(*arguments), time.perf_counter() - start, ""
    except InternalError:
        return solve_eigsh(*arguments), time.perf_counter() - start, " (bands failed: eigsh)"


def solve_times(k):
    """Seconds of the three solves of each uncoupled model, and their largest difference."""
    from eigendance.harmonic.components import groups
    from eigendance.harmonic.eigensolver import solve, solve_bands, solve_eigsh
    from eigendance.harmonic.mesh import Mesh, load_mesh

    count, (folder, name) = COPIES
    single = load_mesh(shared_path(folder, name))
    offsets = np.repeat(np.arange(count), single.n)[:, None] * [3.0, 0, 0]
    copies = Mesh.from_arrays(np.tile(single.vertices, (count, 1)) + offsets,
                              np.concatenate([single.faces + i * single.n for i in range(count)]),
                              name=f"{count} copies of {name}")
    models = [load_mesh(shared_path(*model)) for model in MODELS] + [copies]
    for mesh in models:
        stiffness, mass = uncoupled(mesh)
        kept = min(k, mesh.n - 2)
        found = groups(stiffness, mass)
        print(f"{mesh.name}: {mesh.n} vertices, {sum(len(g.members) for g in found)} pieces in "
              f"{len(found)} groups of copies; load {os.getloadavg()[0]:.1f}", flush=True)
        (values, _), after, _ = timed(solve, stiffness, mass, kept)
        (before_values, _), before, fell = timed(solve_bands, stiffness, mass, kept)
        (naive_values, _), naive, _ = timed(solve_eigsh, stiffness, mass, kept)
        worst = max(np.abs(values - before_values).max(), np.abs(values - naive_values).max())
        print(f"  by component {after:6.2f} s | whole, bands {before:6.2f} s{fell} | "
              f"whole, eigsh {naive:6.2f} s | largest |Δλ| {worst:.1e}", flush=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--k", type=int, default=150)
    parser.add_argument("--song", default="kevin_macleod_vibe_ace.ogg")
    parser.add_argument("--frames", type=int, default=400)
    parser.add_argument("--solve", action="store_true", help="time the uncoupled solves only")
    args = parser.parse_args()
    warnings.simplefilter("ignore")
    if args.solve:
        print(f"load: {os.getloadavg()[0]:.1f}; k = {args.k}, operators without the coupling")
        solve_times(args.k)
        return
    from eigendance.harmonic.contacts import components
    from eigendance.harmonic.laplacian import CONTACT_STIFFNESS as coupled
    from eigendance.harmonic.mesh import load_mesh
    from eigendance.music.spectrogram import Spectrogram

    song = Spectrogram.from_file(shared_path("audio", args.song))
    print(f"load: {os.getloadavg()[0]:.1f}; song {args.song} ({song.duration:.0f} s), "
          f"k = {args.k}, gallery of 8, {args.frames} frames")
    worst = 0.0
    for folder, name in MODELS:
        mesh = load_mesh(shared_path(folder, name))
        parts, _ = components(mesh.n, mesh.faces)
        print(f"{name}: {mesh.n} vertices, {parts} pieces", flush=True)
        for label, stiffness, solver in (("before (uncoupled)", 0.0, "bands"),
                                         ("after (coupled)", coupled, "bands")):
            drift, drivable, k, zero, seconds = measure(mesh, args.k, song, args.frames,
                                                        stiffness, solver)
            shown = " ".join("—" if np.isnan(d) else f"{d:.2f}" for d in drift)
            print(f"  {label:19s} drift per item {shown} | eigenvalue 0: {zero}, drivable "
                  f"{drivable} of {k} | solve {seconds:.1f} s ({solver})", flush=True)
            if stiffness:
                worst = max([worst, *(d for d in drift if not np.isnan(d))])
    print(f"largest drift with the coupling: {worst:.2f} (bound 0.3)")


if __name__ == "__main__":
    main()
