"""Limits of what one input may ask for (docs/design.md#errors, #server): the time and peak
memory of a rig's analysis by its size, which sets MAX_BODIES and MAX_JOINTS; the peak memory of
the allocation bombs (a glTF declaring 10⁸ vertices) refused before they allocate (each case in
a fresh process, its address space capped at 6 GiB). With --part server, against a running
`eigendance serve`: the worst wait of a cheap request while heavy uploads are analysed and the
mesh's basis solved (beside the same requests with nothing uploaded, measured in the same run),
and what 1,100 connections that never finish their headers do to the page's requests. Not run by
CI.

    python benchmarks/bench_limits.py [--part rigs|bombs|server|all] [--timeout 300]
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import socket
import subprocess
import sys
import tempfile
import threading
import time
import urllib.request

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


def waits(port: int, upload_paths: list[str]) -> list[float]:
    """Seconds each GET /api/config took while `upload_paths` were uploaded one after another
    and the meshes' bases solved."""
    import http.client

    times, done = [], threading.Event()

    def tick():
        connection = http.client.HTTPConnection("127.0.0.1", port, timeout=300)
        while not done.is_set():
            start = time.perf_counter()
            connection.request("GET", "/api/config")
            connection.getresponse().read()
            times.append(time.perf_counter() - start)
            time.sleep(0.01)

    ticker = threading.Thread(target=tick)
    ticker.start()
    for path in upload_paths:
        connection = http.client.HTTPConnection("127.0.0.1", port, timeout=900)
        with open(path, "rb") as file:
            connection.request("POST", f"/api/upload?name={os.path.basename(path)}", file.read(),
                               {"Content-Type": "application/octet-stream"})
        response = connection.getresponse()
        print(f"    {os.path.basename(path)}: {response.status}", flush=True)
        response.read()
    if not upload_paths:
        time.sleep(5)
    deadline = time.monotonic() + 900
    while time.monotonic() < deadline and not all(  # and while the meshes' bases are solved
            mesh["ready"] for mesh in json.load(urllib.request.urlopen(
                f"http://127.0.0.1:{port}/api/library", timeout=300))["meshes"]):
        time.sleep(0.2)
    done.set()
    ticker.join()
    return sorted(times)


def server(timeout: float) -> None:
    sys.path.insert(0, TESTS)
    import bombs as makers
    from shared_data import shared_path

    with tempfile.TemporaryDirectory() as folder:
        heavy = [makers.chain_gltf(os.path.join(folder, "chain250.glb"), 250),
                 makers.chain_skeleton(os.path.join(folder, "snake150.json"), 150),
                 shared_path("meshes", "armadillo.obj")]
        port = 18790
        process = subprocess.Popen(
            [sys.executable, "-m", "eigendance.cli", "serve", "--port", str(port), "-k", "60",
             "--max-upload-mb", "200"], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
            text=True, preexec_fn=lambda: resource.setrlimit(resource.RLIMIT_NOFILE,
                                                              (1024, 1024)),
            env=dict(os.environ, EIGENDANCE_CACHE_DIR=folder))
        try:
            process.stdout.readline()
            for label, paths in (("nothing uploaded (baseline)", []), ("heavy uploads", heavy)):
                print(f"  GET /api/config every 10 ms, {label}:", flush=True)
                times = waits(port, paths)
                print(f"    {len(times)} requests: median {1e3 * times[len(times) // 2]:.0f} ms,"
                      f" p99 {1e3 * times[int(0.99 * len(times))]:.0f} ms, worst "
                      f"{1e3 * times[-1]:.0f} ms", flush=True)
            flood = []
            for _ in range(1100):
                client = socket.create_connection(("127.0.0.1", port), timeout=5)
                client.sendall(b"GET / HTTP/1.1\r\nHost: 127.0.0.1:%d\r\n" % port)
                flood.append(client)
            start = time.perf_counter()
            with urllib.request.urlopen(f"http://127.0.0.1:{port}/api/config", timeout=30) as r:
                status = r.status
            print(f"  1,100 idle connections open: GET /api/config {status} in "
                  f"{time.perf_counter() - start:.2f} s", flush=True)
            time.sleep(12)
            closed = 0
            for client in flood:
                client.setblocking(False)
                try:
                    closed += client.recv(4096) is not None
                except BlockingIOError:
                    pass
                except OSError:
                    closed += 1
                client.close()
            print(f"  closed by the server within 12 s: {closed} of {len(flood)}")
        finally:
            process.terminate()
            _, err = process.communicate(timeout=30)
            print(f"  server stderr: {len(err)} bytes", flush=True)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--part", choices=["rigs", "bombs", "server", "all"], default="all")
    parser.add_argument("--timeout", type=float, default=300)
    options = parser.parse_args()
    print(f"load: {os.getloadavg()[0]:.1f} (1 min), {os.cpu_count()} cores")
    if options.part in ("bombs", "all"):
        bombs(options.timeout)
    if options.part in ("server", "all"):
        server(options.timeout)
    if options.part in ("rigs", "all"):
        rigs(options.timeout)


if __name__ == "__main__":
    main()
