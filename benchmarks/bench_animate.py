"""Animation throughput: the Stanford bunny with k = 300 harmonics (docs/design.md#filter).

Prints the project's figures — frames per second of `iter_positions` (spectrogram lookup, filter,
fused product, original coordinates, float32; in memory) and of `write_animation` (the same plus
streaming ≈ 12 bytes per vertex and frame into the .npz) — beside a baseline measured in the same
run: a bare numpy float64 product of the same shapes (3C × k times k × n per chunk of C frames),
nothing else. Target: eigendance ≥ 70% of the bare product's throughput. Not run by CI. The basis
comes from the cache (computed once, ≈ 30–60 s).

    python benchmarks/bench_animate.py [--mesh PATH] [-k 300] [--seconds 20] [--fps 30]
"""

from __future__ import annotations

import argparse
import os
import tempfile
import time

import numpy as np

from eigendance.harmonic.basis import HarmonicBasis
from eigendance.harmonic.motion import chunk_frames, iter_positions, write_animation
from eigendance.music.demo_music import demo_track
from eigendance.music.gallery import strongest_item
from eigendance.music.spectrogram import Spectrogram, frame_times
from shared_data import shared_path

BUNNY = shared_path("meshes", "bunny_stanford.obj")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mesh", default=os.path.normpath(BUNNY))
    parser.add_argument("-k", type=int, default=300)
    parser.add_argument("--seconds", type=float, default=20.0)
    parser.add_argument("--fps", type=float, default=30.0)
    parser.add_argument("--rounds", type=int, default=5, help="interleaved rounds (default 5)")
    parser.add_argument("--threads", type=int, default=None,
                        help="BLAS threads for both sides (default: the library's own)")
    args = parser.parse_args()
    if args.threads:
        from threadpoolctl import threadpool_limits

        threadpool_limits(args.threads)
    start = time.perf_counter()
    basis = HarmonicBasis.from_mesh(args.mesh, args.k)
    print(f"basis: n = {basis.n}, k = {basis.k} ({time.perf_counter() - start:.1f} s, "
          "cached after the first run)")
    samples, sr = demo_track(args.seconds)
    spectrogram = Spectrogram.from_samples(samples, sr)
    mapping = strongest_item(basis, spectrogram)
    times = frame_times(spectrogram.duration, args.fps)
    per_chunk = chunk_frames(basis.n)

    def bare():
        weights = np.random.default_rng(0).standard_normal((3 * per_chunk, basis.k))
        start = time.perf_counter()
        for first in range(0, len(times), per_chunk):
            count = min(per_chunk, len(times) - first)
            weights[: 3 * count] @ basis.eigenvectors.T
        return time.perf_counter() - start

    def in_memory():
        start = time.perf_counter()
        for _ in iter_positions(basis, spectrogram, mapping, times):
            pass
        return time.perf_counter() - start

    def ours(folder):
        start = time.perf_counter()
        write_animation(os.path.join(folder, "a.npz"), basis, spectrogram, mapping, args.fps)
        return time.perf_counter() - start

    with tempfile.TemporaryDirectory() as folder:
        bare()  # warm-up
        ours_times, bare_times, memory_times = [], [], []
        for _ in range(args.rounds):  # interleaved rounds: the machine is shared
            bare_times.append(bare())
            memory_times.append(in_memory())
            ours_times.append(ours(folder))
        size = os.path.getsize(os.path.join(folder, "a.npz")) / 1e6
    frames = len(times)
    best_ours, best_bare, best_memory = min(ours_times), min(bare_times), min(memory_times)
    print(f"{frames} frames ({args.seconds:g} s at {args.fps:g} fps), chunks of {per_chunk} "
          f"frames, file {size:.0f} MB")
    print(f"eigendance iter_positions (in memory): {best_memory:.3f} s = "
          f"{frames / best_memory:.0f} frames/s "
          f"(runs: {', '.join(f'{t:.3f}' for t in memory_times)})")
    print(f"eigendance write_animation (to file): {best_ours:.3f} s = "
          f"{frames / best_ours:.0f} frames/s "
          f"(runs: {', '.join(f'{t:.3f}' for t in ours_times)})")
    print(f"baseline bare numpy float64 Wᵀ·Uᵀ, same shapes: {best_bare:.3f} s = "
          f"{frames / best_bare:.0f} frames/s (runs: {', '.join(f'{t:.3f}' for t in bare_times)})")
    print(f"ratio eigendance/baseline throughput (best/best): in memory "
          f"{best_bare / best_memory:.0%}, to file {best_bare / best_ours:.0%} (target ≥ 70%)")
    in_memory = np.median(np.array(bare_times) / np.array(memory_times))
    to_file = np.median(np.array(bare_times) / np.array(ours_times))
    print(f"ratio, median over rounds of the same round's pair: in memory {in_memory:.0%}, "
          f"to file {to_file:.0%}")


if __name__ == "__main__":
    main()
