"""The server's library: meshes (with their basis jobs), songs (with spectrograms), mappings
and rigs (with their modes and edits), within a memory budget.

Items get short random ids. Files a person uploads are stored inside the library folder as
``upload-<content digest><suffix>``, so names from the network never become paths, and
messages call them by the name they were uploaded under (`Library.public`). One item per
distinct content: adding the same bytes again (a file or an upload of the same suffix; a
mapping with the same fields) answers the item already there.

Memory (`server.memory`): every item is charged the bytes it keeps (a mesh is charged its
planned basis and bundles before it is solved); the least recently used items are removed when
the total exceeds the budget, never the basis being solved. An item too large for the budget
on its own is refused (413). Items can be removed on request (`remove`); the built-in rigs are
never removed: dropping one only forgets its analysis (and its edits).

Bases are computed one at a time by one daemon thread through `HarmonicBasis.from_mesh` (and its
disk cache); each job records its progress for the page (server-sent events). `stop` ends the
solve in progress at once (its band worker processes are killed) and `close` stops the thread.

Rigs: the built-in rigs are listed from the start and analysed when first asked for; a skeleton
JSON, or a glTF file with a skin (listed once, as a rig; as a mesh if its skin cannot be
analysed), is analysed when added. `first` is
the first model given to the server (a mesh or a rig): what the page opens first. Each rig item
keeps its original skeleton and the current one (stiffness and rest-pose edits); every edit
analyses the rig again (`Rig.from_skeleton`) and bumps its revision.
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
import multiprocessing
import os
import queue
import re
import secrets
import threading
import time
from dataclasses import dataclass, field

from eigendance.errors import EigendanceError, InputError, one_line
from eigendance.files import check_readable, kind_of, read_json, suffix_of
from eigendance.harmonic.basis import HarmonicBasis, basis_cache, basis_key, choose_construction
from eigendance.harmonic.mesh import load_mesh
from eigendance.harmonic.reduced import reduced_key, sample_count
from eigendance.limits import size_text
from eigendance.modal.gltf_skin import has_skin
from eigendance.modal.rig import Rig
from eigendance.modal.sample_rigs import SAMPLE_RIGS, load_rig, sample_rig
from eigendance.modal.skeleton import Skeleton
from eigendance.music.mapping import Mapping
from eigendance.music.spectrogram import Spectrogram
from eigendance.server.binary import basis_bundle, rig_bundle, spectrogram_bundle
from eigendance.server.memory import DEFAULT_BUDGET, Budget, footprint

UPLOAD_PREFIX = "upload-"
# Names of our own in the library folder: stored uploads and uploads being received.
STORED_NAME = re.compile(r"(upload-[0-9a-f]{6,}|\.incoming-\w+)(\.\w+)?")
# Bytes per vertex and harmonic a mesh item keeps: the basis (float64), its bundle (float32)
# and the float16 bundle the page may ask for.
BYTES_PER_ENTRY = 8 + 4 + 2
BYTES_PER_VERTEX = 256  # vertices, mass, faces (≈ 2 per vertex) in the basis and the bundles
# A reduced basis (docs/design.md#reduced-basis) keeps per vertex its interpolation (indices,
# weights, P as a matrix, the bundle's float16 and uint16 copies) instead of k entries.
REDUCED_BYTES_PER_VERTEX = 320
# What a mapping sent to the server may hold: the bands of a spectrogram (`eigendance spectrum
# --bands`) and the harmonics of a basis (-k) at most, so that breeding answers a bounded size.
MAX_BANDS, MAX_HARMONICS = 1024, 20000


def new_id() -> str:
    return secrets.token_hex(6)


def file_digest(path: str) -> str:
    """SHA-256 of a file's bytes (hex)."""
    digest = hashlib.sha256()
    with open(path, "rb") as file:
        while chunk := file.read(1 << 20):
            digest.update(chunk)
    return digest.hexdigest()


def check_mapping_size(data, name: str) -> None:
    """InputError unless a mapping document's lists fit MAX_BANDS and MAX_HARMONICS (checked
    before `Mapping.from_json` looks at every value)."""
    if not isinstance(data, dict):
        return  # Mapping.from_json says what is wrong
    modes = data.get("modes") if isinstance(data.get("modes"), dict) else {}
    for field_name, values, most in (
            ("transfer", data.get("transfer"), MAX_BANDS),
            ("amplification", data.get("amplification"), MAX_HARMONICS),
            *((f"modes.{key}", modes.get(key), MAX_HARMONICS)
              for key in ("selected", "amplitudes", "phases"))):
        if isinstance(values, list) and len(values) > most:
            raise InputError(f"{name}: {field_name} has {len(values)} values; at most "
                             f"{most}")


class Stopped(Exception):
    """Raised in a solve's progress callback to end it: the mesh was removed or the server is
    stopping."""


@dataclass
class Job:
    id: str
    kind: str
    total: int
    name: str = ""
    done: int = 0
    state: str = "queued"  # queued | running | done | error
    message: str = ""
    cached: bool = False  # the basis is in the on-disk cache (no solve)
    started: float = field(default_factory=time.time)
    changed: threading.Condition = field(default_factory=threading.Condition)

    def update(self, **values) -> None:
        with self.changed:
            for name, value in values.items():
                setattr(self, name, value)
            self.changed.notify_all()

    @property
    def busy(self) -> bool:
        return self.state in ("queued", "running")

    def as_json(self) -> dict:
        return {"id": self.id, "kind": self.kind, "state": self.state, "done": self.done,
                "total": self.total, "message": self.message}


@dataclass
class MeshItem:
    id: str
    name: str
    path: str
    k: int
    vertices: int = 0
    job: Job | None = None
    basis: object = None
    bundle: bytes | None = None
    half_bundle: bytes | None = None
    rig: str | None = None  # id of the rig item of the same file (a glTF with a skin)
    content: tuple | None = None  # the key of its content in Library.contents
    removed: bool = False
    construction: str = "exact"  # "exact" or "reduced" (docs/design.md#reduced-basis)

    def as_json(self) -> dict:
        return {"id": self.id, "name": self.name, "k": self.k, "vertices": self.vertices,
                "ready": self.basis is not None, "construction": self.construction,
                "job": self.job.as_json() if self.job else None, "rig": self.rig}

    def held(self) -> int:
        """Bytes kept: the basis and bundles once solved, the planned ones until then."""
        if self.basis is None:
            if self.construction == "reduced":
                return self.vertices * (REDUCED_BYTES_PER_VERTEX + BYTES_PER_VERTEX) + \
                    sample_count(self.vertices, self.k) * self.k * BYTES_PER_ENTRY
            return self.vertices * (self.k * BYTES_PER_ENTRY + BYTES_PER_VERTEX)
        return footprint(self.basis, self.bundle, self.half_bundle)


@dataclass
class SongItem:
    id: str
    name: str
    path: str
    spectrogram: object = None
    bundle: bytes | None = None
    content: tuple | None = None

    def as_json(self) -> dict:
        duration = float(getattr(self.spectrogram, "duration", 0) or 0)
        return {"id": self.id, "name": self.name, "duration": duration}

    def held(self) -> int:
        return footprint(self.spectrogram, self.bundle)


@dataclass
class MappingItem:
    id: str
    name: str
    data: dict
    content: tuple | None = None

    def as_json(self) -> dict:
        return {"id": self.id, "name": self.name}

    def held(self) -> int:
        return footprint(self.data)


@dataclass
class RigItem:
    """A rig: `source` is a built-in rig's name (origin "built-in") or a file's path (origin
    "file" or "upload"). `original` and `rig` are set once analysed; `error` says why a file
    could not be."""

    id: str
    name: str
    origin: str
    source: str
    original: Skeleton | None = None
    rig: Rig | None = None
    bundle: bytes | None = None
    revision: int = 0
    error: str = ""
    content: tuple | None = None
    lock: threading.Lock = field(default_factory=threading.Lock)

    @property
    def path(self) -> str:
        return "" if self.origin == "built-in" else self.source

    def as_json(self) -> dict:
        info = {"id": self.id, "name": self.name, "origin": self.origin,
                "ready": self.rig is not None, "revision": self.revision,
                "error": self.error or None}
        if self.rig is not None:
            info.update(bodies=self.rig.skeleton.n_bodies, joints=len(self.rig.skeleton.joints),
                        vertices=len(self.rig.skeleton.vertices), modes=self.rig.model.n_modes)
        return info

    def held(self) -> int:
        return footprint(self.original, self.rig, self.bundle)


class Library:
    """The items a server offers (see the module docstring).

    Parameters
    ----------
    folder : where uploads are stored (the server's temporary folder).
    k : harmonics per mesh basis.
    max_upload_bytes : the largest upload.
    memory_budget : bytes the items may keep in memory (`server.memory`).
    spectrogram_options : options of `Spectrogram.from_file`.
    """

    def __init__(self, folder: str, k: int = 150, max_upload_bytes: int = 64 << 20,
                 memory_budget: int = DEFAULT_BUDGET, spectrogram_options: dict | None = None,
                 construction: str = "auto"):
        self.folder = folder
        os.makedirs(folder, exist_ok=True)
        self.k = k
        self.construction = construction  # of every basis: "auto", "exact" or "reduced"
        self.max_upload_bytes = max_upload_bytes
        self.spectrogram_options = spectrogram_options or {}
        self.meshes: dict[str, MeshItem] = {}
        self.songs: dict[str, SongItem] = {}
        self.mappings: dict[str, MappingItem] = {}
        self.jobs: dict[str, Job] = {}
        self.rigs: dict[str, RigItem] = {}
        self.first: dict | None = None  # {"kind": "mesh" | "rig", "id"} of the first model file
        self.contents: dict[tuple, str] = {}  # content key → item id
        self.arriving: dict[tuple, threading.Event] = {}  # content keys being added now
        self.budget = Budget(memory_budget)
        self.lock = threading.RLock()
        self.progress_listeners = []  # callables(job) for the terminal
        self.stopping = threading.Event()
        self.solving: MeshItem | None = None
        self.solve_children: set = set()  # processes that existed before the current solve
        self.queue: queue.Queue = queue.Queue()
        self.worker = threading.Thread(target=self._solve_queue, name="basis", daemon=True)
        self.worker.start()
        for rig_name in SAMPLE_RIGS:
            item = RigItem(new_id(), rig_name, "built-in", rig_name)
            self.rigs[item.id] = item

    # --- adding items -----------------------------------------------------------------------
    def add_path(self, path: str, name: str | None = None, k: int | None = None):
        """Register a file by its kind (suffix). Meshes start a basis job; songs are decoded."""
        name = name or os.path.basename(path)
        kind = kind_of(name)
        check_readable(path)
        item = self._add_file(path, name, kind, file_digest(path), "file", k)[0]
        if self.first is None and isinstance(item, MeshItem | RigItem):
            self.first = {"kind": "mesh" if isinstance(item, MeshItem) else "rig", "id": item.id}
        return item

    def add_upload(self, stored: str, name: str, kind: str, digest: str):
        """Register an uploaded file, written to `stored` inside the library folder, under a
        name of our own; the item and whether it is new (False: the same content was there).
        An upload that fails leaves no file behind."""
        final = os.path.join(self.folder, f"{UPLOAD_PREFIX}{digest[:24]}{suffix_of(name)}")
        try:
            os.replace(stored, final)
            item, new = self._add_file(final, name, kind, digest, "upload")
        except BaseException as error:
            self._discard(stored, final)
            if isinstance(error, EigendanceError):
                error.args = (self.public(str(error), {final: name}),)
            raise
        if not new:
            self._discard(final)  # unless it is the file of the item already there
        return item, new

    def _add_file(self, path: str, name: str, kind: str, digest: str, origin: str,
                  k: int | None = None):
        """The item of a file (new, or the one with the same content) and whether it is new."""
        suffix = suffix_of(name)
        document = None
        if kind == "mapping":  # a skeleton JSON is a rig, any other JSON a mapping
            document = read_json(path, name)
            if isinstance(document, dict) and document.get("format") == "eigendance.skeleton":
                kind = "rig"
        elif kind == "mesh" and suffix in (".glb", ".gltf") and has_skin(path):
            kind = "rig"  # a skinned glTF is a rig (its skin the mesh the modes move)
        key = (kind, suffix, digest, k or self.k) if kind == "mesh" else (kind, suffix, digest)
        if kind == "mapping":
            return self.add_mapping(document, name)
        existing = self._claim(key)
        if existing is not None:
            return existing, False
        try:
            if kind == "mesh":
                item = self.add_mesh(path, name, k, key)
            elif kind == "audio":
                item = self.add_song(path, name, key)
            elif suffix in (".glb", ".gltf"):  # a skin that cannot be analysed: a mesh
                try:
                    item = self.add_rig(path, name, origin, key)
                except InputError:
                    item = self.add_mesh(path, name, k, key)
            else:
                item = self.add_rig(path, name, origin, key)
        finally:
            self._release(key)
        return item, True

    def _claim(self, key: tuple):
        """The item with content `key`, or None after reserving `key` for the caller (who must
        `_release` it). Waits while another thread adds the same content."""
        while True:
            with self.lock:
                item_id = self.contents.get(key)
                if item_id is not None:
                    item = self._find(item_id)
                    if item is not None:
                        self.budget.touch(item.id)
                        return item
                waiting = self.arriving.get(key)
                if waiting is None:
                    self.arriving[key] = threading.Event()
                    return None
            waiting.wait()

    def _release(self, key: tuple) -> None:
        with self.lock:
            self.arriving.pop(key).set()

    def add_mesh(self, path: str, name: str, k: int | None = None,
                 content: tuple | None = None) -> MeshItem:
        """A mesh item, charged its planned basis, and its basis job queued."""
        mesh = dataclasses.replace(load_mesh(path), name=name)  # EigendanceError if unreadable
        laplacian = "robust" if mesh.non_manifold_edge_count() else "cotan"
        k = max(2, min(k or self.k, len(mesh.vertices) - 2))
        construction = choose_construction(mesh.n, k) if self.construction == "auto" \
            else self.construction
        item = MeshItem(new_id(), name, path, k, len(mesh.vertices), content=content,
                        construction=construction)
        item.job = Job(new_id(), "basis", k, name)
        self._admit(item, self.meshes, f"{name}: a basis of {k} harmonics of "
                                      f"{len(mesh.vertices)} vertices")
        with self.lock:
            self.jobs[item.job.id] = item.job
        self.queue.put((item, mesh, laplacian))
        return item

    def add_song(self, path: str, name: str, content: tuple | None = None) -> SongItem:
        try:
            spectrogram = Spectrogram.from_file(path, **self.spectrogram_options)
        except EigendanceError:
            raise
        except Exception as error:  # noqa: BLE001 - decoders raise many types
            raise InputError(f"{name}: cannot decode the audio ({one_line(error)})") from None
        item = SongItem(new_id(), name, path, spectrogram, content=content)
        item.bundle = spectrogram_bundle(spectrogram, name)
        self._admit(item, self.songs, f"{name}: its spectrogram")
        return item

    def add_mapping(self, data, name: str) -> tuple[MappingItem, bool]:
        """A mapping item from a parsed mapping document, and whether it is new (False: the
        same mapping was there, and is answered)."""
        check_mapping_size(data, name)
        mapping = Mapping.from_json(data, name)  # EigendanceError naming the bad field
        fields = mapping.to_json()
        text = json.dumps(fields, sort_keys=True).encode()
        key = ("mapping", hashlib.sha256(text).hexdigest())
        with self.lock:
            existing = self._find(self.contents.get(key, ""))
            if existing is not None:
                self.budget.touch(existing.id)
                return existing, False
            item = MappingItem(new_id(), name, fields, content=key)
            self._admit(item, self.mappings, f"{name}: the mapping")
            return item, True

    def _admit(self, item, store: dict, what: str) -> None:
        """Charge `item` its bytes (dropping the least recently used items to make room) and
        list it; InputError when it cannot fit."""
        size = item.held()
        with self.lock:
            dropped = self.budget.charge(item.id, size, busy=self._busy)
            if dropped is None:
                self._refuse(size, what)
            for other in dropped:
                self._drop(other)
            store[item.id] = item
            if item.content is not None:
                self.contents[item.content] = item.id

    def _refuse(self, size: int, what: str):
        limit = self.budget.limit
        if size > limit:
            raise InputError(f"{what} would take {size_text(size)} of memory, more than the "
                             f"library's budget of {size_text(limit)}", status=413)
        raise InputError(f"{what} would take {size_text(size)} of memory; the library's budget "
                         f"of {size_text(limit)} is held by bases being computed (wait for them "
                         "or remove some)", status=409)

    def _recharge(self, item) -> None:
        """Charge `item` what it holds now (a solved basis, a new bundle), dropping others."""
        with self.lock:
            if self._find(item.id) is not item:
                return
            dropped = self.budget.charge(item.id, item.held(), busy=self._busy)
            for other in dropped or ():
                self._drop(other)

    # --- bases --------------------------------------------------------------------------------
    def _solve_queue(self) -> None:
        while True:
            item, mesh, laplacian = self.queue.get()
            if item is None:
                return
            self._solve(item, mesh, laplacian)

    def _solve(self, item: MeshItem, mesh, laplacian: str) -> None:
        job = item.job
        if item.removed or self.stopping.is_set():
            job.update(state="error", message=f"{item.name}: removed from the library")
            return
        key = basis_key(mesh, item.k, laplacian)
        if item.construction == "reduced":
            key = reduced_key(key, sample_count(mesh.n, item.k))
        job.cached = os.path.isfile(basis_cache().path(key))
        self.solving, self.solve_children = item, set(multiprocessing.active_children())
        job.update(state="running")
        self._tell(job)

        def progress(done):
            if item.removed or self.stopping.is_set():
                raise Stopped
            job.update(done=int(min(done, job.total)))
            self._tell(job)

        try:
            basis = HarmonicBasis.from_mesh(mesh, item.k, laplacian=laplacian, progress=progress,
                                            construction=item.construction)
            if item.removed or self.stopping.is_set():
                raise Stopped
            item.bundle = basis_bundle(basis, item.name)
            item.basis = basis
            job.update(state="done", done=job.total)
            self._recharge(item)
        except Exception as error:  # noqa: BLE001 - reported to the page, never crashes the server
            job.update(state="error", message=self._solve_failure(item, error))
        finally:
            self.solving = None
        self._tell(job)

    def _solve_failure(self, item: MeshItem, error: Exception) -> str:
        if item.removed or self.stopping.is_set():
            return f"{item.name}: removed from the library" if item.removed else \
                f"{item.name}: the server stopped before the basis was done"
        if isinstance(error, EigendanceError):
            return self.public(str(error))
        return self.public(f"{item.name}: the basis failed (internal error: "
                           f"{type(error).__name__}: {one_line(error, 200)})")

    def _tell(self, job: Job) -> None:
        for listener in self.progress_listeners:
            listener(job)

    def _stop_solve(self) -> None:
        """Kill the band worker processes of the solve in progress (the processes started
        since it began): the solve fails at once instead of finishing its bands."""
        if self.solving is None:
            return
        for process in set(multiprocessing.active_children()) - self.solve_children:
            process.kill()

    # --- rigs -------------------------------------------------------------------------------
    def add_rig(self, path: str, name: str, origin: str, content: tuple | None = None) -> RigItem:
        """A rig file (skeleton JSON or glTF skin), analysed now; InputError if it is bad."""
        item = RigItem(new_id(), name, origin, path, content=content)
        self._analyse(item, load_rig(path, name))
        self._admit(item, self.rigs, f"{name}: the rig")
        return item

    def ready_rig(self, item: RigItem) -> RigItem:
        """The item analysed (a built-in rig is analysed on first use); InputError (409) if
        it could not be."""
        with item.lock:
            if item.rig is None and not item.error:
                try:
                    self._analyse(item, sample_rig(item.source) if item.origin == "built-in"
                                  else load_rig(item.source, item.name))
                except EigendanceError as error:
                    item.error = self.public(str(error))
            if item.error:
                raise InputError(item.error, status=409)
        self._recharge(item)  # after the item's lock: _drop takes the library's lock first
        return item

    def edit_rig(self, item: RigItem, edit) -> bytes:
        """Apply `edit` (skeleton → skeleton) to the current skeleton, analyse the result and
        return its bundle; a failed edit leaves the rig as it was."""
        self.ready_rig(item)
        with item.lock:
            self._analyse(item, edit(item.rig.skeleton), original=item.original)
            bundle = item.bundle
        self._recharge(item)
        return bundle

    def reset_rig(self, item: RigItem) -> bytes:
        """Back to the rig as loaded (pose and stiffness)."""
        return self.edit_rig(item, lambda _: item.original)

    def _analyse(self, item: RigItem, skeleton: Skeleton, original: Skeleton | None = None):
        rig = Rig.from_skeleton(skeleton)
        bundle = rig_bundle(rig, item.name, item.revision + (item.rig is not None))
        item.original = original or skeleton
        item.revision += item.rig is not None
        item.rig, item.bundle = rig, bundle

    # --- lookups, removal ---------------------------------------------------------------------
    def get(self, kind: str, item_id: str):
        """The item of `kind` ("mesh", "song", "mapping", "rig") with `item_id`, or None; a
        lookup makes it the most recently used."""
        store = {"mesh": self.meshes, "song": self.songs, "mapping": self.mappings,
                 "rig": self.rigs}[kind]
        item = store.get(item_id)
        if item is not None:
            self.budget.touch(item.id)
        return item

    def half_bundle(self, item: MeshItem) -> bytes:
        """The basis bundle with float16 harmonics, made once (and charged)."""
        if item.half_bundle is None:
            item.half_bundle = basis_bundle(item.basis, item.name, True)
            self._recharge(item)
        return item.half_bundle

    def remove(self, kind: str, item_id: str) -> list[str]:
        """Remove an item (a mesh with the rig of its skin), stopping its solve; the ids
        removed. InputError 404 for an unknown id, 409 for a built-in rig."""
        with self.lock:
            item = self.get(kind, item_id)
            if item is None:
                raise InputError(f"no {kind} with id '{item_id}'", status=404)
            if kind == "rig" and item.origin == "built-in":
                raise InputError(f"{item.name} is a built-in rig; it cannot be removed",
                                 status=409)
            removed = [item.id]
            if kind == "mesh" and item.rig in self.rigs:
                removed.append(item.rig)
            for each in removed:
                self.budget.release(each)
                self._drop(each)
        return removed

    def _drop(self, item_id: str) -> None:
        """Take an item out of the library (a built-in rig: forget its analysis) and delete its
        stored file once no item uses it. Called with the lock held."""
        item = self._find(item_id)
        if isinstance(item, RigItem) and item.origin == "built-in":
            item.original = item.rig = item.bundle = None
            item.revision, item.error = 0, ""
            return
        for store in (self.meshes, self.songs, self.mappings, self.rigs):
            store.pop(item_id, None)
        if item is None:
            return
        if item.content is not None and self.contents.get(item.content) == item_id:
            del self.contents[item.content]
        if isinstance(item, MeshItem):
            item.removed = True
            if self.solving is item:
                self._stop_solve()
            self.jobs.pop(item.job.id, None)
            if item.job.state == "queued":
                item.job.update(state="error", message=f"{item.name}: removed from the library")
        elif isinstance(item, RigItem):
            for mesh in self.meshes.values():
                if mesh.rig == item.id:
                    mesh.rig = None
        self._discard(getattr(item, "path", ""))

    def _discard(self, *paths: str) -> None:
        """Delete files of the library folder that no item uses."""
        with self.lock:
            for path in paths:
                if path and os.path.dirname(path) == self.folder and not self._in_use(path):
                    try:
                        os.unlink(path)
                    except OSError:
                        pass

    def _find(self, item_id: str):
        for store in (self.meshes, self.songs, self.mappings, self.rigs):
            if item_id in store:
                return store[item_id]
        return None

    def _in_use(self, path: str) -> bool:
        return any(getattr(item, "path", "") == path for store in
                   (self.meshes, self.songs, self.rigs) for item in store.values())

    def _busy(self, item_id: str) -> bool:
        """In use, not to be dropped: a mesh whose basis is queued or being solved, a rig being
        analysed or edited."""
        item = self._find(item_id)
        return isinstance(item, MeshItem) and item.job.busy or \
            isinstance(item, RigItem) and item.lock.locked()

    def public(self, text: str, names: dict[str, str] | None = None) -> str:
        """`text` (a message for the page) with every stored file called by the name it was
        uploaded under, and no path inside the library folder."""
        names = dict(names or {})
        for store in (self.meshes, self.songs, self.rigs):
            for item in list(store.values()):
                if item.path and os.path.dirname(item.path) == self.folder:
                    names[item.path] = item.name
        for path, name in names.items():
            text = text.replace(path, name).replace(os.path.basename(path), name)
        text = text.replace(self.folder + os.sep, "").replace(self.folder, "the library")
        return STORED_NAME.sub("an uploaded file", text)

    def as_json(self) -> dict:
        with self.lock:
            return {"meshes": [m.as_json() for m in self.meshes.values()],
                    "songs": [s.as_json() for s in self.songs.values()],
                    "mappings": [m.as_json() for m in self.mappings.values()],
                    "rigs": [r.as_json() for r in self.rigs.values()],
                    "first": self.first if self._find((self.first or {}).get("id", ""))
                    else None,
                    "memory": {"used": self.budget.used, "budget": self.budget.limit}}

    def wait(self, timeout: float | None = None) -> bool:
        """Block until every basis job has finished (tests, CLI)."""
        deadline = None if timeout is None else time.time() + timeout
        for job in list(self.jobs.values()):
            with job.changed:
                while job.busy:
                    left = None if deadline is None else deadline - time.time()
                    if left is not None and left <= 0:
                        return False
                    job.changed.wait(left)
        return True

    # --- the end --------------------------------------------------------------------------------
    def stop(self) -> None:
        """End the work in progress at once: the solve (its workers are killed) and the queued
        ones. Safe to call from any thread, more than once."""
        self.stopping.set()
        self._stop_solve()

    def close(self, timeout: float = 2.0) -> None:
        """`stop`, then give the solve thread `timeout` seconds to end (it is a daemon thread:
        a solve step that cannot be interrupted does not keep the process alive)."""
        self.stop()
        self.queue.put((None, None, None))
        self.worker.join(timeout)
