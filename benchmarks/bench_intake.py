"""A mesh added to the server: the bytes that cross process boundaries and the server
process's peak memory (issue 29: the parsed mesh crosses a process boundary once).

Counts, per call of a worker process (`server.workers.run`): the bytes of its arguments as
pickled (what the fork server is handed) and of its result as received (`server.transfer`);
and the server process's peak resident memory (ru_maxrss) before and after the add and its
solve. One mesh per run (a fresh process: ru_maxrss only grows).
Run: .venv/bin/python benchmarks/bench_intake.py [--mesh meshes/armadillo.obj] [--k 16]
"""

from __future__ import annotations

import argparse
import os
import pickle
import resource
import tempfile
import time

from shared_data import shared_path


def pickled_bytes(value) -> int:
    """Bytes of `value` pickled with protocol 5, out-of-band buffers included."""
    buffers: list = []
    head = pickle.dumps(value, protocol=5, buffer_callback=buffers.append)
    return len(head) + sum(buffer.raw().nbytes for buffer in buffers)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--mesh", default="meshes/armadillo.obj")
    parser.add_argument("--k", type=int, default=16)
    args = parser.parse_args()
    os.environ["EIGENDANCE_CACHE_DIR"] = tempfile.mkdtemp(prefix="bench-cache-")

    from eigendance.server import transfer, workers
    from eigendance.server.library import Library

    calls: list[list] = []
    run, receive = workers.run, transfer.receive

    def counted(function, *arguments, **options):
        calls.append([function.__name__, pickled_bytes(arguments), 0])
        return run(function, *arguments, **options)

    def received(connection):
        value = receive(connection)
        if calls:
            calls[-1][2] += pickled_bytes(value)
        return value

    workers.run, transfer.receive = counted, received
    path = shared_path(*args.mesh.split("/"))
    before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    library = Library(tempfile.mkdtemp(prefix="bench-library-"), k=args.k)
    try:
        start = time.perf_counter()
        item = library.add_path(path)
        assert library.wait(3600) and item.job.state == "done", item.job.message
        seconds = time.perf_counter() - start
    finally:
        library.close()
    after = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    print(f"{args.mesh}: {item.vertices} vertices, k = {item.k} ({item.construction}), "
          f"{seconds:.1f} s")
    for name, sent, back in calls:
        print(f"  {name:<14} arguments {sent / 1e6:8.2f} MB   result {back / 1e6:8.2f} MB")
    print(f"  crossing in all: {sum(sent + back for _, sent, back in calls) / 1e6:.2f} MB")
    print(f"  server peak RSS: {before / 1024:.0f} MB before, {after / 1024:.0f} MB after")


if __name__ == "__main__":
    main()
