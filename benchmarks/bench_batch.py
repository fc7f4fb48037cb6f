"""Batch throughput against workers: one plan of 24 jobs on 1 and 2 local worker processes and
on a Ray cluster started on this machine (`ray start --head` plus a worker node), issue 20.

The plan: the bunny (34,834 vertices, k = 300: an 84 MB basis the workers share) and a rigged
character (CesiumMan.glb), three shared songs, the initial gallery's 4 items, each job a video
(mp4, 480x270, 30 fps) and a glb of a clip of `--seconds` s. Drawing the frames (one llvmpipe
thread per worker) dominates a job; the bases and spectrograms come from a warm content cache,
the galleries are made in every run (a serial part: a pair's gallery precedes its jobs). Every
configuration starts from an empty output folder and is timed from the command's start to its
end (worker start-up, preparing, jobs). Also printed: each worker's memory (resident, and
proportional: shared pages divided among the processes mapping them) and the CPU time of a
1280x720 frame, the figure the cluster estimate of docs/batch.md scales.

Baseline, in the same run: 1 local worker. Report `uptime`'s load beside the figures (a shared
2-core host: other work there slows the 2-worker run most).
Run: .venv/bin/python benchmarks/bench_batch.py [--seconds 4] [--repeat 2] [--wait-load 1.5]
[--skip-ray] (EIGENDANCE_SHARED_DATA=/path/to/shared/data when the checkout is not beside it).
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time

from shared_data import shared_path

BIN = os.path.dirname(sys.executable)
SONGS = ("kevin_macleod_vibe_ace.ogg", "tad_florist_lofi.mp3", "emegeme_country.mp3")


def load() -> str:
    with open("/proc/loadavg") as file:
        return " ".join(file.read().split()[:3])


def write_plan(folder: str, out: str, seconds: float, size: str, models, gallery: int) -> str:
    path = os.path.join(folder, f"{out}.toml")
    songs = ", ".join(f'"{shared_path("audio", name)}"' for name in SONGS)
    with open(path, "w") as file:
        file.write(f"models = [{', '.join(repr(m).replace(chr(39), chr(34)) for m in models)}]\n"
                   f"songs = [{songs}]\noutputs = [\"mp4\", \"glb\"]\ngallery = {gallery}\n"
                   f"out = \"{out}\"\nsize = \"{size}\"\nfps = 30\nk = 300\nstart = 20.0\n"
                   f"duration = {seconds}\n")
    return path


def run(plan: str, *flags: str) -> dict:
    """Run `eigendance batch`, timed; its report's lines."""
    before = load()
    began = time.perf_counter()
    done = subprocess.run([os.path.join(BIN, "eigendance"), "batch", plan, *flags],
                          capture_output=True, text=True)
    wall = time.perf_counter() - began
    if done.returncode != 0:
        sys.exit(f"batch failed: {done.stderr[-2000:]}")
    out = os.path.join(os.path.dirname(plan), os.path.splitext(os.path.basename(plan))[0])
    with open(os.path.join(out, "batch-report.jsonl")) as file:
        lines = [json.loads(line) for line in file]
    summary = [line for line in done.stdout.splitlines() if line.startswith("time: ")]
    return {"wall": wall, "lines": lines, "load": f"{before} → {load()}", "summary": summary}


def memory(lines) -> str:
    """Each worker's memory at its last job, MB: resident (RSS), proportional (PSS), peak."""
    workers = {}
    for line in lines:
        if line.get("memory"):
            workers[line["pid"]] = line["memory"]
    return "; ".join(f"RSS {m['rss_mb']:.0f}, PSS {m['pss_mb']:.0f}, peak {m['peak_rss_mb']:.0f}"
                     for m in workers.values())


def free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


def ray_cluster(nodes: int, cpus: int, folder: str):
    """`ray start --head` plus nodes − 1 worker nodes on this machine (each `--block`, in a
    session of its own, so that stopping it stops only what it started); the address."""
    port = free_port()
    ray = os.path.join(BIN, "ray")
    common = ["--block", "--num-cpus", str(cpus), "--disable-usage-stats"]
    head = subprocess.Popen([ray, "start", "--head", "--port", str(port), "--include-dashboard",
                             "true", "--dashboard-port", str(free_port()),
                             "--temp-dir", os.path.join(folder, "ray"), *common],
                            start_new_session=True, stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL)
    processes = [head]
    address = f"127.0.0.1:{port}"
    time.sleep(8)
    for _ in range(nodes - 1):
        processes.append(subprocess.Popen([ray, "start", "--address", address, *common],
                                          start_new_session=True, stdout=subprocess.DEVNULL,
                                          stderr=subprocess.DEVNULL))
    time.sleep(8)
    return address, processes


def stop(processes) -> None:
    for process in reversed(processes):
        try:
            os.killpg(process.pid, signal.SIGTERM)  # `ray start --block` stops its node
        except ProcessLookupError:
            pass
        process.wait(60)


def quiet_host(limit: float | None) -> None:
    """Wait (at most 5 min) until the 1-minute load is at most `limit` (None: do not wait)."""
    deadline = time.time() + 300
    while limit is not None and float(load().split()[0]) > limit and time.time() < deadline:
        time.sleep(10)


def configurations(args, folder: str, models) -> list:
    """Each configuration's fastest run of `--repeat`, interleaved: [(name, workers, result)]."""
    local = [("local, 1 worker", ["-j", "1"]), ("local, 2 workers", ["-j", "2"])]
    best: dict = {}
    for repeat in range(args.repeat):
        for name, flags in local:
            quiet_host(args.wait_load)
            plan = write_plan(folder, f"local{flags[-1]}-{repeat}", args.seconds, args.size,
                              models, 4)
            result = run(plan, *flags)
            print(f"{name}: {result['wall']:.1f} s, load {result['load']}", flush=True)
            if name not in best or result["wall"] < best[name][2]["wall"]:
                best[name] = (name, int(flags[-1]), result)
    if not args.skip_ray:
        name = "Ray: head + 1 worker node, 1 CPU each"
        address, processes = ray_cluster(2, 1, folder)
        try:
            for repeat in range(args.repeat):
                quiet_host(args.wait_load)
                result = run(write_plan(folder, f"ray-{repeat}", args.seconds, args.size,
                                        models, 4), "--ray", address)
                print(f"{name}: {result['wall']:.1f} s, load {result['load']}", flush=True)
                if name not in best or result["wall"] < best[name][2]["wall"]:
                    best[name] = (name, 2, result)
        finally:
            stop(processes)
    return list(best.values())


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--seconds", type=float, default=4.0, help="each clip's length")
    parser.add_argument("--size", default="480x270")
    parser.add_argument("--repeat", type=int, default=1,
                        help="runs of each configuration, interleaved; the fastest is kept")
    parser.add_argument("--wait-load", type=float, default=None, metavar="LOAD",
                        help="before each run, wait (up to 5 min) for a 1-minute load ≤ LOAD")
    parser.add_argument("--skip-ray", action="store_true")
    args = parser.parse_args()
    folder = tempfile.mkdtemp(prefix="bench-batch-")
    os.environ["EIGENDANCE_CACHE_DIR"] = os.path.join(folder, "cache")
    # A cluster on this machine's loopback, for this benchmark only: without Ray's token
    # authentication (Ray 2.60 turns it on where a token exists; a real cluster keeps it).
    os.environ["RAY_AUTH_MODE"] = "disabled"
    models = [shared_path("meshes", "bunny_stanford.obj"), shared_path("rigged", "CesiumMan.glb")]
    try:
        print(f"warming the content cache (bases, spectrograms); load {load()}")
        warm = write_plan(folder, "warm", 0.5, "32x32", models, 2)
        run(warm, "-j", "2")
        report(configurations(args, folder, models))
        quiet_host(args.wait_load)
        single = write_plan(folder, "hd", args.seconds, "1280x720", models[:1], 2)
        hd = run(single, "-j", "1")
        frames = round(args.seconds * 30)
        per_frame = [line["cpu"]["mp4"] / frames for line in hd["lines"]]
        sizes = [os.path.getsize(os.path.join(folder, "hd", name)) for line in hd["lines"]
                 for name in line["outputs"] if name.endswith(".mp4")]
        print(f"\n1280x720, bunny, 1 worker: {min(per_frame) * 1000:.0f} ms per frame (CPU of one "
              f"core, drawing + encoding); mp4 {sum(sizes) / len(sizes) / args.seconds / 1e6:.2f}"
              f" MB per second of video; load {hd['load']}")
        song_cost()
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def song_cost() -> None:
    """CPU seconds of a song's analysis (spectrogram and rhythm) per minute of audio, in this
    process (one thread), for the cluster estimate of docs/batch.md."""
    from threadpoolctl import threadpool_limits

    from eigendance.music.spectrogram import Spectrogram

    with threadpool_limits(1):
        Spectrogram.from_file(shared_path("audio", SONGS[0]))  # imports, librosa's JIT
        used, minutes = time.process_time(), 0.0
        for name in SONGS:
            minutes += Spectrogram.from_file(shared_path("audio", name)).duration / 60
        used = time.process_time() - used
    print(f"a song's analysis: {used / minutes:.2f} s of CPU per minute of audio "
          f"({minutes:.1f} min of audio); load {load()}")


def report(rows) -> None:
    """The table: throughput against the 1-worker baseline, the cores the jobs obtained (their
    CPU seconds over the wall time: under other load, what the host gave), the load."""
    base = len(rows[0][2]["lines"]) / rows[0][2]["wall"]
    print(f"\n{'engine':<40}{'jobs':>5}{'wall s':>9}{'jobs/min':>10}{'× 1 worker':>12}"
          f"{'cores':>7}  load")
    for name, _, result in rows:
        jobs = [line for line in result["lines"] if line["status"] == "done"]
        rate = len(jobs) / result["wall"]
        cores = sum(sum(line["cpu"].values()) for line in jobs) / result["wall"]
        print(f"{name:<40}{len(jobs):>5}{result['wall']:>9.1f}{rate * 60:>10.2f}"
              f"{rate / base:>12.2f}{cores:>7.2f}  {result['load']}")
    for name, _, result in rows:
        jobs = [line for line in result["lines"] if line["status"] == "done"]
        busy = sum(line["seconds"] for line in jobs)
        cpu = sum(sum(line["cpu"].values()) for line in jobs)
        print(f"{name}: jobs took {busy:.1f} s of worker time ({busy / len(jobs):.2f} s each, "
              f"{cpu / len(jobs):.2f} s of CPU); {result['summary'][0]}; "
              f"worker memory, MB: {memory(result['lines'])}")


if __name__ == "__main__":
    main()
