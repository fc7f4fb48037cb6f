"""The server's library: meshes (with their basis jobs), songs (with spectrograms), mappings and
rigs (with their modes and edits), within a memory budget (docs/design.md#server).

The library is the front of single-purpose parts, as trimesh's caching.py splits caching:

- `server.items`: the items and the basis jobs;
- `server.intake`: files into items, one item per distinct content (`server.contents`);
- `server.shelf`: the items by kind, charged within the memory budget (`server.memory`: what
  an item holds, least recently used first out), lookups and removal;
- `server.solver`: the queue of bases computed one at a time;
- `server.rigs`: rig analysis and edits;
- `server.workers.run`: the worker processes that read and analyse files
  (`server.analysis`), off the server's interpreter lock (`run`).

A skinned glTF is listed once, as a rig (as a mesh if its skin cannot be analysed). `first` is
the first model given to the server (a mesh or a rig): what the page opens first.
"""

from __future__ import annotations

import os
import threading

from eigendance.errors import InputError, InternalError
from eigendance.inputs.defaults import DEFAULT_K
from eigendance.inputs.model import built_in
from eigendance.modal.sample_rigs import SAMPLE_RIGS
from eigendance.server import rigs, workers
from eigendance.server.binary import appearance_bundle, basis_bundle
from eigendance.server.intake import UNPACKED_FACTOR, Intake
from eigendance.server.items import Job, MeshItem, RigItem, new_id
from eigendance.server.memory import DEFAULT_BUDGET, Budget
from eigendance.server.shelf import Shelf
from eigendance.server.solver import BasisSolver


class Library:
    """The items a server offers (see the module docstring).

    Parameters
    ----------
    folder : where uploads are stored (the server's temporary folder).
    k : harmonics per mesh basis.
    max_upload_bytes : the largest upload.
    memory_budget : bytes the items may keep in memory (`server.memory`).
    spectrogram_options : options of `Spectrogram.from_file`.
    construction : how mesh bases are solved: "auto" (docs/design.md#reduced-basis), "exact" or
        "reduced".
    samples : the samples a reduced basis asks for (None: `reduced.sample_count`).

    Attributes: shelf, intake, solver (the parts); folder, k, max_upload_bytes;
    meshes, songs, mappings, rigs ({id: item}) and budget, as the shelf holds them.
    """

    def __init__(self, folder: str, k: int = DEFAULT_K, max_upload_bytes: int = 64 << 20,
                 memory_budget: int = DEFAULT_BUDGET, spectrogram_options: dict | None = None,
                 construction: str = "auto", samples: int | None = None):
        os.makedirs(folder, exist_ok=True)
        self.folder, self.k, self.max_upload_bytes = folder, k, max_upload_bytes
        self.shelf = Shelf(folder, Budget(memory_budget))
        self.solver = BasisSolver(self.shelf.recharge, self.shelf.public, self.shelf.discard)
        self.shelf.removed = self.solver.forget
        self.intake = Intake(self.shelf, self.solver, k, spectrogram_options, construction,
                             UNPACKED_FACTOR * max_upload_bytes, self.run, samples)
        self.meshes, self.songs = self.shelf.meshes, self.shelf.songs
        self.mappings, self.rigs, self.budget = self.shelf.mappings, self.shelf.rigs, \
            self.shelf.budget
        for rig_name in SAMPLE_RIGS:
            item = RigItem(new_id(), rig_name, "built-in", rig_name)
            self.rigs[item.id] = item
        self.first: dict | None = None  # {"kind": "mesh" | "rig", "id"} of the first model file
        # The API of the parts: the intake adds items, the shelf finds, removes and describes them.
        self.add_upload, self.add_mapping = self.intake.add_upload, self.intake.add_mapping
        self.get, self.remove, self.public = self.shelf.get, self.shelf.remove, self.shelf.public

    def add_path(self, path: str, name: str | None = None, k: int | None = None):
        """Register a file given to the server (`Intake.add_path`); the first model becomes
        `first`.

        Parameters
        ----------
        path : the file, or a built-in rig's name (as the commands take it: its item).
        name : how the page calls it (default: the file's name).
        k : harmonics of a mesh's basis (default the library's).

        Returns
        -------
        The item: new, or the one already there with the same content.
        """
        item = self._built_in(path) or self.intake.add_path(path, name, k)
        if self.first is None and isinstance(item, MeshItem | RigItem):
            self.first = {"kind": "mesh" if isinstance(item, MeshItem) else "rig", "id": item.id}
        return item

    def _built_in(self, source: str) -> RigItem | None:
        """The built-in rig `source` names (as the commands take it), or None."""
        if not built_in(source):
            return None
        return next((item for item in self.rigs.values()
                     if item.origin == "built-in" and item.source == source), None)

    def as_json(self) -> dict:
        """The library as `GET /api/library` answers it.

        Returns
        -------
        `Shelf.as_json` and "first": the first model's {"kind", "id"} while it is there, else
        None.
        """
        answer = self.shelf.as_json()
        present = self.first is not None and self.shelf.find(self.first["id"]) is not None
        answer["first"] = self.first if present else None
        return answer

    # --- the solve queue's state, as the routes and the terminal see it ----------------------
    @property
    def jobs(self) -> dict[str, Job]:
        """Basis jobs by id (`server.solver`)."""
        return self.solver.jobs

    @property
    def stopping(self) -> threading.Event:
        """Set once the server stops."""
        return self.solver.stopping

    @property
    def solving(self) -> MeshItem | None:
        """The mesh item whose basis is being computed, or None."""
        return self.solver.solving

    @property
    def progress_listeners(self) -> list:
        """Callables(job) told of every job's progress (the terminal's bars)."""
        return self.solver.progress_listeners

    def half_bundle(self, item: MeshItem) -> bytes:
        """The basis bundle with float16 harmonics, made once (and charged).

        Parameters
        ----------
        item : a mesh item whose basis is ready.

        Returns
        -------
        bytes.
        """
        if item.half_bundle is None:
            item.half_bundle = basis_bundle(item.basis, item.name, True)
            self.shelf.recharge(item)
        return item.half_bundle

    def look_bundle(self, item: MeshItem | RigItem) -> bytes:
        """The appearance bundle of a mesh or (analysed) rig item, made once and charged.

        Parameters
        ----------
        item : a mesh item, or a rig item analysed (`ready_rig`).

        Returns
        -------
        bytes (`binary.appearance_bundle`); InputError 404 for a model without materials or
        colours (drawn in clay).
        """
        appearance = item.appearance
        if appearance is None:
            raise InputError(f"{item.name} has no materials or colours of its own (it is drawn "
                             "in clay)", status=404)
        if item.look_bundle is None:
            item.look_bundle = appearance_bundle(appearance, item.name)
            self.shelf.recharge(item)
        return item.look_bundle

    # --- rigs ----------------------------------------------------------------------------------
    def ready_rig(self, item: RigItem) -> RigItem:
        """The rig item analysed (`rigs.ready`), charged what it holds.

        Parameters
        ----------
        item : a rig item of this library.

        Returns
        -------
        The item; InputError (409) when it could not be analysed.
        """
        rigs.ready(item, self.shelf.public, self.run)
        self.shelf.recharge(item)  # after the item's lock: _drop takes the library's lock first
        return item

    def edit_rig(self, item: RigItem, change) -> bytes:
        """Apply an edit to the rig item's current rig (`rigs.edit`).

        Parameters
        ----------
        item : a rig item of this library.
        change : skeleton → edited skeleton (`Skeleton.with_stiffness`,
            `Skeleton.rotate_joint`), analysed anew in a worker process.

        Returns
        -------
        bytes: the new rig bundle; a failed edit leaves the rig as it was.
        """
        self.ready_rig(item)
        with self.shelf.reserving(f"{item.id}/edit", rigs.planned_bytes(item.rig.skeleton),
                                  f"{item.name}: an edit"):
            bundle = rigs.edit(item, change, self.run)
        self.shelf.budget.release(f"{item.id}/edit")
        self.shelf.recharge(item)
        return bundle

    def reset_rig(self, item: RigItem) -> bytes:
        """Back to the rig as loaded (pose and stiffness).

        Parameters
        ----------
        item : a rig item of this library.

        Returns
        -------
        bytes: its rig bundle.
        """
        return self.edit_rig(item, lambda skeleton: item.original)

    def run(self, function, *args, seconds: float | None = None):
        """function(*args) in a worker process (`workers.run`), unless the library is
        stopping; killed past its deadline.

        Parameters
        ----------
        function : a function of `server.analysis`.
        *args : its arguments.
        seconds : its deadline (None: none), counted once its process runs; the message
            past it names args[1], the file's name for every analysis of a file (path, name, …).

        Returns
        -------
        Its result; InternalError once the library is stopping; InputError (422) past the
        deadline.
        """
        if self.stopping.is_set():
            raise InternalError("the server is stopping")
        if seconds is None:
            return workers.run(function, *args)
        timers, expired = [], threading.Event()

        def started(process):
            def expire():
                expired.set()
                workers.kill(process)

            timers.append(threading.Timer(seconds, expire))
            timers[-1].daemon = True
            timers[-1].start()

        try:
            return workers.run(function, *args, started=started)
        except InternalError:
            if expired.is_set():
                raise InputError(f"{args[1] if len(args) > 1 else function.__name__}: the "
                                 f"analysis took more than its {seconds:.0f} s (the deadline "
                                 "for a file of this size) and was stopped", status=422) from None
            raise
        finally:
            for timer in timers:
                timer.cancel()

    # --- the end --------------------------------------------------------------------------------
    def wait(self, timeout: float | None = None) -> bool:
        """Block until every basis job has finished (tests, CLI).

        Parameters
        ----------
        timeout : seconds at most (None: no limit).

        Returns
        -------
        bool: True when every job finished in time.
        """
        return self.solver.wait(timeout)

    def stop(self) -> None:
        """End the work in progress at once: the solve (its workers are killed), the queued
        ones and the analyses (their worker processes are killed). Safe to call from any thread,
        more than once."""
        self.solver.stop()
        workers.stop()

    def close(self, timeout: float = 2.0) -> None:
        """`stop`, then give the solve thread `timeout` seconds to end.

        Parameters
        ----------
        timeout : seconds.
        """
        self.stop()
        self.solver.close(timeout)
