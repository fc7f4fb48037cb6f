"""The reduced basis against the exact one (issue 19, docs/design.md#reduced-basis).

accuracy: on subdivided scans (≥ 150k vertices, detail noise, benchmarks/big_meshes.py) where
  both solvers run, k = 300: the median relative eigenvalue error and, for each item of the
  initial gallery (8 items, calibrated on the exact basis) on a real song, the RMS displacement
  error of the reduced dance relative to the item's RMS motion, beside the sample count. With
  --sensitivity, the same errors between the exact bases of two draws of the detail noise (the
  same shape, detail moved by a tenth of an edge): how much the exact dance itself moves.
speed: a 1.15 M-vertex mesh (fertility ×256 with detail) at k = 300: wall-clock and peak memory
  of the reduced basis beside the exact solver's at the largest size it reaches here (armadillo
  ×16, 692k vertices), and the Laplacian's assembly (libigl) beside robust-laplacian's.
bad: big meshes that are not clean — the ogre ×16 (≈ 1 M vertices, 44 parts, degenerate faces,
  non-manifold vertices) and the beetle ×256 (non-manifold edges, 2 parts): a result or one
  clear error, as on the exact path, and the memory planned beside the peak.
exports: the same mesh and a 3-minute song (two shared songs end to end) at 30 fps: the glb as
  a skin on the samples (written, with its time and peak memory) beside the same dance as morph
  targets (the driven harmonics, and all k as issue 19 counts them) and as a point cache; and
  the page's basis bundle of that mesh (its coarse basis, weights and indices beside the mesh).

Every solve runs in a fresh process (peak memory is its own; the band workers' is reported by
the kernel for the children). Run: .venv/bin/python benchmarks/bench_reduced.py [accuracy]
[speed] [bad] [exports] [--meshes armadillo-173k ...] [--sensitivity] [--samples 7200 6300]
[--skip-exact-speed]
"""

from __future__ import annotations

import argparse
import multiprocessing
import os
import resource
import subprocess
import tempfile
import time
from queue import Empty

import numpy as np

from big_meshes import detailed
from shared_data import shared_path

ACCURACY_MESHES = ("armadillo-173k", "camelhead-182k", "ogre-248k")
SONG = shared_path("audio", "kevin_macleod_vibe_ace.ogg")
K = 300
FRAMES = 240  # evenly spaced frames of the song where the dances are compared
LOW = 100  # items whose main harmonics lie below this must be within 3%, all within 10%


def load() -> str:
    return open("/proc/loadavg").read().split()[0]


def solve(name: str, seed: int, construction: str, k: int, output: str | None,
          laplacian: str, samples: int | None, queue):
    """In a fresh process: the basis of a benchmark mesh; puts (seconds, peak GB, details), or
    the error's one line."""
    from eigendance.errors import EigendanceError
    from eigendance.harmonic.basis import HarmonicBasis
    from eigendance.harmonic.mesh import Mesh

    vertices, faces = detailed(name, seed)
    start = time.perf_counter()
    mesh = Mesh.from_arrays(vertices, faces, name=name)
    cleaned = time.perf_counter() - start
    start = time.perf_counter()
    try:
        basis = HarmonicBasis.from_mesh(mesh, k, laplacian=laplacian, cache=False,
                                        construction=construction, samples=samples)
    except EigendanceError as error:
        queue.put(str(error))
        return
    seconds = time.perf_counter() - start
    peak = max(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss,
               resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss) / 2**20
    if output:
        basis.save(output)
    queue.put((seconds, peak, {"n": basis.n, "clean-up s": cleaned,
                               "samples": basis.reduced.count if basis.reduced else 0,
                               "zeros": int(np.sum(np.abs(basis.eigenvalues) < 1e-8))}))


def in_process(name, seed, construction, k, output, laplacian="cotan", samples=None):
    arguments = (name, seed, construction, k, output, laplacian, samples)
    context = multiprocessing.get_context("fork")
    queue = context.Queue()
    process = context.Process(target=solve, args=(*arguments, queue))
    process.start()
    while True:  # a solve that dies (the OOM killer) must not hang the run
        try:
            result = queue.get(timeout=1)
            break
        except Empty:
            if not process.is_alive():
                raise SystemExit(f"the solve {arguments[:3]} failed "
                                 f"(exit {process.exitcode})") from None
    process.join()
    if isinstance(result, str):
        raise SystemExit(f"error: {result}")
    return result


def item_errors(reference, other, song, items):
    """Per item: (main harmonic range, RMS(d_other − d_reference) / RMS(d_reference))."""
    from eigendance.music.dancer import gallery_motion

    times = np.linspace(0, song.duration, FRAMES)
    rows = []
    for item, motion in zip(items, gallery_motion(reference, song, items), strict=True):
        phi = item.play(song, times, reference.k)  # envelope, pulse: as every dance plays
        error = total = 0.0
        for chunk in range(0, FRAMES, 50):  # bounded memory: 50 frames of n × 3 at a time
            moved = reference.displacements(phi[chunk:chunk + 50])
            error += float(((other.displacements(phi[chunk:chunk + 50]) - moved) ** 2).sum())
            total += float((moved ** 2).sum())
        rows.append(((motion.lowest, motion.highest), np.sqrt(error / total)))
    return rows


def accuracy(meshes, sensitivity: bool, counts) -> None:
    """The errors of the reduced basis of each mesh, at each sample count of `counts` (None:
    the default count) against one exact solve."""
    from eigendance.harmonic.basis import HarmonicBasis
    from eigendance.music.gallery import initial_gallery
    from eigendance.music.spectrogram import Spectrogram

    song = Spectrogram.from_file(SONG)
    print(f"song: {os.path.basename(SONG)}, {song.duration:.0f} s; k = {K}; errors over "
          f"{FRAMES} frames; load {load()}")
    for name in meshes:
        with tempfile.TemporaryDirectory() as folder:
            paths = {kind: os.path.join(folder, f"{kind}.npz") for kind in ("exact", "noise")}
            timing = in_process(name, 0, "exact", K, paths["exact"])
            exact = HarmonicBasis.load(paths["exact"])
            items = initial_gallery(exact, song, 8)
            noise = [(None, np.nan)] * len(items)
            if sensitivity:
                in_process(name, 1, "exact", K, paths["noise"])
                noise = item_errors(exact, HarmonicBasis.load(paths["noise"]), song, items)
            for count in counts:
                path = os.path.join(folder, f"reduced-{count}.npz")
                reduced_timing = in_process(name, 0, "reduced", K, path, samples=count)
                reduced = HarmonicBasis.load(path)
                relative = np.abs(reduced.eigenvalues[1:] - exact.eigenvalues[1:]) / \
                    np.maximum(exact.eigenvalues[1:], 1e-12)
                errors = item_errors(exact, reduced, song, items)
                print(f"\n{name}: n = {exact.n}, samples m = {reduced_timing[2]['samples']}; "
                      f"exact {timing[0]:.1f} s {timing[1]:.2f} GB, reduced "
                      f"{reduced_timing[0]:.1f} s {reduced_timing[1]:.2f} GB (load {load()})")
                print_errors(relative, errors, noise)


def print_errors(relative, errors, noise) -> None:
    """The eigenvalue errors' summary and each gallery item's dance error beside its bound."""
    print(f"  eigenvalues: median relative error {np.median(relative):.2%}, largest "
          f"{relative.max():.2%}; every λ̃ ≥ λ: {bool(np.all(relative >= -1e-9))}")
    print(f"  {'item':>4} {'main harmonics':>15} {'error':>8} {'bound':>6} "
          f"{'exact vs exact, other noise':>28}")
    for number, ((span, error), (_, other)) in enumerate(zip(errors, noise, strict=True), 1):
        bound = 0.03 if span[1] < LOW else 0.10
        mark = "ok" if error <= bound else "OVER"
        print(f"  {number:>4} {f'{span[0]}–{span[1]}':>15} {error:>8.2%} {bound:>5.0%} "
              f"{mark:>4} {other:>22.2%}")


def laplacian_profile(name: str) -> None:
    from eigendance.harmonic.laplacian import laplacian
    from eigendance.harmonic.mesh import Mesh

    mesh = Mesh.from_arrays(*detailed(name))
    for kind in ("cotan", "robust"):
        start = time.perf_counter()
        laplacian(mesh.vertices, mesh.faces, kind)
        library = "libigl" if kind == "cotan" else "robust-laplacian"
        print(f"  Laplacian and mass, {kind:>6} ({library}): "
              f"{time.perf_counter() - start:.1f} s (load {load()})")


def speed(skip_exact: bool) -> None:
    print(f"uptime: {subprocess.run(['uptime'], capture_output=True, text=True).stdout.strip()}")
    seconds, peak, info = in_process("fertility-1.15M", 0, "reduced", K, None)
    print(f"reduced, fertility ×256 with detail, n = {info['n']}, k = {K}, m = {info['samples']}: "
          f"{seconds:.1f} s, peak {peak:.2f} GB (clean-up of the arrays before it: "
          f"{info['clean-up s']:.1f} s; load {load()})")
    if not skip_exact:
        seconds, peak, info = in_process("armadillo-692k", 0, "exact", K, None)
        print(f"exact, armadillo ×16 with detail, n = {info['n']}, k = {K}: {seconds:.1f} s, "
              f"peak {peak:.2f} GB (load {load()})")
        seconds, peak, info = in_process("armadillo-692k", 0, "reduced", K, None)
        print(f"reduced, the same mesh: {seconds:.1f} s, peak {peak:.2f} GB (load {load()})")
    laplacian_profile("fertility-1.15M")


def bad_input() -> None:
    from eigendance.harmonic.mesh import Mesh
    from eigendance.harmonic.reduced import sample_count, solve_bytes

    print(f"\nbad input (load {load()})")
    for name, laplacian in (("ogre-995k", "cotan"), ("beetle-294k", "cotan"),
                            ("beetle-294k", "robust")):
        vertices, faces = detailed(name)
        mesh = Mesh.from_arrays(vertices, faces)
        planned = solve_bytes(mesh.n, len(mesh.faces), K, sample_count(mesh.n, K), laplacian)
        try:
            seconds, peak, info = in_process(name, 0, "reduced", K, None, laplacian)
            outcome = f"{seconds:.1f} s, peak {peak:.2f} GB (planned {planned / 2**30:.2f} GB), " \
                      f"{info['samples']} samples, {info['zeros']} eigenvalues 0 (one per part)"
        except SystemExit as error:
            outcome = str(error)
        print(f"  {name} ({mesh.report}), {laplacian}: {outcome}")


def three_minutes():
    """A 3-minute song: two shared songs end to end (none of them is that long)."""
    from eigendance.music.decode import read_audio
    from eigendance.music.spectrogram import Spectrogram

    first, rate = read_audio(shared_path("audio", "karissa_hobbs_lets_go_fishin.ogg"))
    second, other = read_audio(shared_path("audio", "emegeme_country.mp3"))
    if other != rate:
        second = np.interp(np.arange(int(len(second) * rate / other)) * other / rate,
                           np.arange(len(second)), second)
    return Spectrogram.from_samples(np.concatenate([first, second])[:180 * rate], rate)


def write_skin(path: str, queue) -> None:
    """In a fresh process: the 1.15 M-vertex dance's glb (time, peak memory, sizes)."""
    from eigendance.export.dance import HarmonicDance
    from eigendance.export.files import export_dance
    from eigendance.export.gltf import glb_size
    from eigendance.export.pointcache import pc2_size
    from eigendance.harmonic.basis import HarmonicBasis
    from eigendance.harmonic.mesh import Mesh
    from eigendance.music.dancer import gallery_motion
    from eigendance.music.gallery import initial_gallery
    from eigendance.music.spectrogram import frame_times
    from eigendance.server.binary import basis_bundle

    basis = HarmonicBasis.from_mesh(Mesh.from_arrays(*detailed("fertility-1.15M")), K,
                                    construction="reduced")  # cached after the first run
    song = three_minutes()
    items = initial_gallery(basis, song, 8)
    motions = gallery_motion(basis, song, items)
    widest = max(range(len(items)), key=lambda i: motions[i].highest - motions[i].lowest)
    dance = HarmonicDance(basis, song, items[widest], name="fertility")
    frames = len(frame_times(song.duration, 30.0))
    start = time.perf_counter()
    report = export_dance(dance, path, fps=30.0, force=True)
    seconds = time.perf_counter() - start
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 2**20
    sizes = glb_size(dance, frames)
    bundle = len(basis_bundle(basis))  # what the page is sent (docs/web.md#basis-bundle)
    interpolation = basis.reduced.interpolation
    sent = 4 * basis.reduced.count * 4 * -(-K // 4) + 2 * interpolation.weights.size + \
        2 * interpolation.indices.size  # coarse float32 texels, float16 weights, uint16 indices
    base = sizes["morph targets"] - len(dance.driven()) * (12 * dance.n + 4 * frames)
    queue.put({"n": dance.n, "m": basis.reduced.count, "frames": frames, "bytes": report["bytes"],
               "seconds": seconds, "peak": peak, "driven": len(dance.driven()), **sizes,
               "bundle": bundle, "sent": sent, "all k": base + K * (12 * dance.n + 4 * frames),
               "pc2": pc2_size(dance.n, frames)})


def exports() -> None:
    context = multiprocessing.get_context("fork")
    queue = context.Queue()
    with tempfile.TemporaryDirectory() as folder:
        process = context.Process(target=write_skin, args=(os.path.join(folder, "d.glb"), queue))
        process.start()
        while True:  # a writer that dies must not hang the run
            try:
                result = queue.get(timeout=1)
                break
            except Empty:
                if not process.is_alive():
                    raise SystemExit(f"the export failed (exit {process.exitcode})") from None
        process.join()
    mb = 1e6
    print(f"\nexports: fertility ×256, n = {result['n']}, m = {result['m']} samples, a 3-minute "
          f"song at 30 fps ({result['frames']} frames), the gallery item driving the most "
          f"harmonics ({result['driven']}); load {load()}")
    written = result["bytes"]
    print(f"  glb, skin on the samples (written): {written / mb:.1f} MB in "
          f"{result['seconds']:.0f} s, peak {result['peak']:.2f} GB (planned binary chunk "
          f"{result['skin'] / mb:.1f} MB; the rest is the JSON and the headers)")
    print(f"  the same dance as morph targets: the {result['driven']} driven harmonics "
          f"{result['morph targets'] / mb:.0f} MB ({written / result['morph targets']:.2f}"
          f"×); all k = {K} harmonics {result['all k'] / mb:.0f} MB "
          f"({written / result['all k']:.3f}×, ≤ 1/8 = 0.125 asked)")
    print(f"  as a point cache: {result['pc2'] / mb:.0f} MB (written only with --force)")
    print(f"  the page's basis bundle: {result['bundle'] / mb:.1f} MB, of which "
          f"{result['sent'] / mb:.1f} MB of coarse basis, weights and indices (≤ 64 MB asked); "
          f"the exact harmonics would be {4 * result['n'] * 4 * -(-K // 4) / mb:.0f} MB")


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parts = ["accuracy", "speed", "bad", "exports"]
    parser.add_argument("parts", nargs="*", metavar="PART",
                        help=f"any of {', '.join(parts)} (default: all of them)")
    parser.add_argument("--meshes", nargs="+", default=list(ACCURACY_MESHES))
    parser.add_argument("--sensitivity", action="store_true",
                        help="also the exact basis of another noise draw (one more exact solve)")
    parser.add_argument("--samples", nargs="+", type=int, default=[None],
                        help="accuracy: the sample counts m to compare (default: the default m)")
    parser.add_argument("--skip-exact-speed", action="store_true",
                        help="skip the exact solve at 692k vertices (minutes, ~5 GB)")
    args = parser.parse_args()
    if unknown := set(args.parts) - set(parts):  # (not argparse's choices: Python 3.12 checks
        parser.error(f"unknown parts: {', '.join(sorted(unknown))}")  # the empty list too)
    args.parts = args.parts or parts
    if "accuracy" in args.parts:
        accuracy(args.meshes, args.sensitivity, args.samples)
    if "speed" in args.parts:
        speed(args.skip_exact_speed)
    if "bad" in args.parts:
        bad_input()
    if "exports" in args.parts:
        exports()


if __name__ == "__main__":
    main()
