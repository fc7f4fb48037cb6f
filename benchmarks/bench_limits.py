"""Limits of what one input may ask for (docs/design.md#errors, #server): the time and peak
memory of a rig's analysis by its size, which sets MAX_BODIES and MAX_JOINTS; the peak memory of
the allocation bombs (a glTF declaring 10⁸ vertices, a skeleton of 500 bodies) refused before
they allocate. Each case runs in a fresh process (its own peak RSS). Not run by CI.

    python benchmarks/bench_limits.py [--part rigs|bombs|all] [--timeout 300]
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
TESTS = os.path.join(os.path.dirname(HERE), "tests")

ONE_RIG = """
import json, resource, sys, time
sys.path.insert(0, {tests!r})
import bombs
from eigendance.errors import InputError
from eigendance.modal.rig import Rig
from eigendance.modal.sample_rigs import load_rig
from eigendance.server.binary import rig_bundle
path = {path!r}
getattr(bombs, {maker!r})(path, {size})
start = time.perf_counter()
try:
    rig = Rig(load_rig(path, "rig"))
    bundle = rig_bundle(rig, "rig")
    result = {{"modes": int(rig.model.n_modes), "vertices": len(rig.skeleton.vertices),
               "bundle_mb": len(bundle) / 1e6}}
except InputError as error:
    result = {{"refused": str(error)}}
result["seconds"] = time.perf_counter() - start
result["peak_mb"] = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1e3
print(json.dumps(result))
"""

ONE_BOMB = """
import json, resource, sys, time
sys.path.insert(0, {tests!r})
import bombs
from eigendance.errors import InputError
from eigendance.harmonic.mesh import load_mesh
start = time.perf_counter()
path = bombs.accessor_bomb({path!r}, {size})
try:
    mesh = load_mesh(path)
    result = {{"vertices": len(mesh.vertices)}}
except InputError as error:
    result = {{"refused": str(error)}}
except MemoryError:
    result = {{"refused": "MemoryError"}}
result["seconds"] = time.perf_counter() - start
result["peak_mb"] = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1e3
print(json.dumps(result))
"""


CAP = 6 << 30  # address space of one case: a bomb must not take the shared machine down


def _capped() -> None:
    resource.setrlimit(resource.RLIMIT_AS, (CAP, CAP))


def run_case(code: str, timeout: float) -> dict:
    """Run `code` in a fresh Python (address space capped at CAP); its JSON line, or what
    stopped it."""
    try:
        done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                              timeout=timeout, preexec_fn=_capped)
    except subprocess.TimeoutExpired:
        return {"stopped": f"over {timeout:.0f} s"}
    if done.returncode:
        return {"failed": done.stderr.strip().splitlines()[-1:]}
    return json.loads(done.stdout.strip().splitlines()[-1])


def rigs(timeout: float) -> None:
    print("rig analysis and bundle, by size (one process each):")
    with tempfile.TemporaryDirectory() as folder:
        for maker, sizes, suffix in (("chain_skeleton", (50, 100, 200, 300, 400), ".json"),
                                     ("chain_gltf", (100, 250, 500, 1000), ".glb")):
            for size in sizes:
                path = os.path.join(folder, f"{maker}-{size}{suffix}")
                result = run_case(ONE_RIG.format(tests=TESTS, path=path, maker=maker,
                                                 size=size), timeout)
                print(f"  {maker:15s} {size:5d}: {json.dumps(result)}", flush=True)


def bombs(timeout: float) -> None:
    print("a .gltf declaring N zero vertices (no buffer view), read as a mesh:")
    with tempfile.TemporaryDirectory() as folder:
        for size in (10**6, 10**7, 10**8):
            result = run_case(ONE_BOMB.format(tests=TESTS, path=os.path.join(folder, "b.gltf"),
                                              size=size), timeout)
            print(f"  N = {size:.0e}: {json.dumps(result)}", flush=True)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--part", choices=["rigs", "bombs", "all"], default="all")
    parser.add_argument("--timeout", type=float, default=300)
    options = parser.parse_args()
    print(f"load: {os.getloadavg()[0]:.1f} (1 min), {os.cpu_count()} cores")
    if options.part in ("bombs", "all"):
        bombs(options.timeout)
    if options.part in ("rigs", "all"):
        rigs(options.timeout)


if __name__ == "__main__":
    main()
