"""Harmonic basis: band-by-band solver against the naive one-shot eigsh, in the same run.

Cases of issue 2: Stanford bunny (34,834 vertices) k = 1070 and armadillo (43,243) k = 2376,
the thesis's Table 7.1 cases. Prints time and peak memory of each solver and the ratio.
Run: .venv/bin/python benchmarks/bench_basis.py [--quick] [--skip-eigsh] [--only bunny]
(the naive eigsh at k = 2376 takes tens of minutes and several GB).
"""

from __future__ import annotations

import argparse
import multiprocessing
import os
import resource
import time
from queue import Empty

from shared_data import shared_path

SHARED = shared_path("meshes")
CASES = [("bunny_stanford.obj", 1070), ("armadillo.obj", 2376)]
QUICK = [("bunny_stanford.obj", 300)]


def measure(path, k, solver, queue):
    """Run in a fresh process so peak memory (ru_maxrss) belongs to this solve alone."""
    from eigendance.harmonic.eigensolver import solve
    from eigendance.harmonic.laplacian import laplacian
    from eigendance.harmonic.mesh import load_mesh

    mesh = load_mesh(path)
    stiffness, mass = laplacian(mesh.vertices, mesh.faces)
    start = time.perf_counter()
    values, _ = solve(stiffness, mass, k, solver)
    seconds = time.perf_counter() - start
    # children: the band workers' peak is reported separately by the kernel
    peak = max(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss,
               resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss) / 2**20
    queue.put((seconds, peak, values[-1], len(mesh.vertices)))


def run(path, k, solver):
    context = multiprocessing.get_context("fork")
    queue = context.Queue()
    process = context.Process(target=measure, args=(path, k, solver, queue))
    process.start()
    while True:  # a solve that dies (a missing file, the OOM killer) must not hang the run
        try:
            result = queue.get(timeout=1)
            break
        except Empty:
            if not process.is_alive():
                raise SystemExit(f"the {solver} solve of {path} failed "
                                 f"(exit status {process.exitcode})") from None
    process.join()
    return result


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--quick", action="store_true", help="bunny k=300 only")
    parser.add_argument("--skip-eigsh", action="store_true", help="bands only (no ratio)")
    parser.add_argument("--only", metavar="NAME", help="one case: bunny or armadillo")
    args = parser.parse_args()
    cases = QUICK if args.quick else CASES
    if args.only:
        cases = [case for case in cases if case[0].startswith(args.only)]
    print(f"{'mesh':<20}{'n':>7}{'k':>6}{'solver':>8}{'time s':>9}{'peak GB':>9}{'λ_k-1':>10}")
    for name, k in cases:
        path = os.path.join(SHARED, name)
        times = {}
        for solver in ("bands",) if args.skip_eigsh else ("bands", "eigsh"):
            seconds, peak, largest, n = run(path, k, solver)
            times[solver] = seconds
            print(f"{name:<20}{n:>7}{k:>6}{solver:>8}{seconds:>9.1f}{peak:>9.2f}{largest:>10.2f}",
                  flush=True)
        if "eigsh" in times:
            print(f"{name}: bands is {times['eigsh'] / times['bands']:.1f}x faster than eigsh")


if __name__ == "__main__":
    main()
