"""Basis cache hits: what checking an entry's content against L and M costs (issue 12).

A hit reads the entry (checksum verified) and, since issue 12, also builds L and M and tests
the stored pairs (residuals, uᵀMu = 1, Uᵀ M U w = w: `construction.eigenpairs_fit`). Baseline,
in the same run: the hit without that test (read + coefficients), and the solve the cache
saves.
Run: .venv/bin/python benchmarks/bench_cache.py [--k 300] [--mesh bunny_stanford.obj]
"""

from __future__ import annotations

import argparse
import os
import tempfile
import time

from shared_data import shared_path


def best_of(count, call):
    times = []
    for _ in range(count):
        start = time.perf_counter()
        call()
        times.append(time.perf_counter() - start)
    return min(times)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--mesh", default="bunny_stanford.obj")
    parser.add_argument("--k", type=int, default=300)
    args = parser.parse_args()
    os.environ["EIGENDANCE_CACHE_DIR"] = tempfile.mkdtemp(prefix="bench-cache-")

    from eigendance.harmonic.basis import HarmonicBasis
    from eigendance.harmonic.construction import basis_cache, basis_key, eigenpairs_fit
    from eigendance.harmonic.laplacian import laplacian
    from eigendance.harmonic.mesh import load_mesh

    mesh = load_mesh(shared_path("meshes", args.mesh))
    start = time.perf_counter()
    HarmonicBasis.from_mesh(mesh, args.k)  # solves and stores the entry
    solve = time.perf_counter() - start
    key = basis_key(mesh, args.k, "cotan")

    def unchecked_hit():
        arrays = basis_cache().load(key)
        HarmonicBasis.from_arrays(mesh, arrays["eigenvalues"], arrays["eigenvectors"],
                                  arrays["mass"])

    def checked_hit():
        HarmonicBasis.from_mesh(mesh, args.k)

    def check_alone():
        stiffness, mass = laplacian(mesh.vertices, mesh.faces)
        assert eigenpairs_fit(stiffness, mass, args.k, basis_cache().load(key))

    baseline, ours, check = (best_of(3, call) for call in (unchecked_hit, checked_hit,
                                                          check_alone))
    print(f"{args.mesh}: n = {mesh.n}, k = {args.k}")
    print(f"  solve (what a hit saves):        {solve:8.3f} s")
    print(f"  hit without content check (base):{baseline:8.3f} s")
    print(f"  hit with content check (ours):   {ours:8.3f} s  ({ours / baseline:.2f}× the base, "
          f"{ours / solve:.1%} of the solve)")
    print(f"  the check alone (L, M, residuals):{check:8.3f} s")


if __name__ == "__main__":
    main()
