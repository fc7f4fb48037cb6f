"""Worker threads for the app's heavy work (parsing, decoding, galleries, breeding, rig analysis,
bundles), so that the event loop only routes and streams (docs/design.md#server).

`asyncio.to_thread` would do, but its threads are waited for when the process ends: a Ctrl-C
during a 30-second decoding would take 30 seconds. These are daemon threads: the process ends
at once, and the work in progress with it (its answer was going nowhere).
"""

from __future__ import annotations

import asyncio
import os
import queue
import threading
from concurrent.futures import Future

THREADS = max(4, os.cpu_count() or 1)


class Workers:
    """`threads` daemon threads, started on first use, running submitted calls in turn.

    Parameters
    ----------
    threads : how many threads.
    """

    def __init__(self, threads: int = THREADS):
        self.threads, self.started = threads, 0
        self.calls: queue.SimpleQueue = queue.SimpleQueue()
        self.lock = threading.Lock()

    def submit(self, function, *args) -> Future:
        """Run function(*args) in a worker thread.

        Parameters
        ----------
        function : what to call.
        *args : its arguments.

        Returns
        -------
        concurrent.futures.Future of its result (or exception).
        """
        future: Future = Future()
        self.calls.put((future, function, args))
        with self.lock:
            if self.started < self.threads:
                self.started += 1
                threading.Thread(target=self._work, name=f"worker-{self.started}",
                                 daemon=True).start()
        return future

    def _work(self) -> None:
        while True:
            future, function, args = self.calls.get()
            if not future.set_running_or_notify_cancel():
                continue
            try:
                result = function(*args)
            except BaseException as error:  # noqa: BLE001 - handed to the awaiting request
                future.set_exception(error)
            else:
                future.set_result(result)


WORKERS = Workers()


async def in_worker(function, *args):
    """function(*args) in a worker thread, awaited: the event loop stays free meanwhile.

    Parameters
    ----------
    function : what to call.
    *args : its arguments.

    Returns
    -------
    Its result (its exception is raised here).
    """
    return await asyncio.wrap_future(WORKERS.submit(function, *args))
