"""The server's library: meshes (with their basis jobs), songs (with spectrograms), mappings
and rigs (with their modes and edits).

Items get short random ids; files a person uploads are stored as ``upload-<random><suffix>``
inside the library folder, so names from the network never become paths. Bases are computed by
one worker thread through `HarmonicBasis.from_mesh` (and its disk cache); each job records its
progress for the page (server-sent events).

Rigs: the built-in rigs are listed from the start and analysed when first asked for; a skeleton
JSON, or a glTF file with a skin (which is also a mesh), is analysed when added. Each rig item
keeps its original skeleton and the current one (stiffness and rest-pose edits); every edit
analyses the rig again (`Rig.from_skeleton`) and bumps its revision.
"""

from __future__ import annotations

import copy
import json
import os
import secrets
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field

from eigendance.errors import EigendanceError, InputError, one_line
from eigendance.files import check_readable, kind_of, suffix_of
from eigendance.harmonic.basis import HarmonicBasis, basis_cache, basis_key
from eigendance.harmonic.mesh import load_mesh
from eigendance.modal.gltf_skin import has_skin
from eigendance.modal.rig import Rig
from eigendance.modal.sample_rigs import SAMPLE_RIGS, load_rig, sample_rig
from eigendance.modal.skeleton import Skeleton, is_skeleton_json
from eigendance.music.mapping import Mapping
from eigendance.music.spectrogram import Spectrogram
from eigendance.server.binary import basis_bundle, rig_bundle, spectrogram_bundle


def new_id() -> str:
    return secrets.token_hex(6)


def named(error: EigendanceError, path: str, name: str) -> EigendanceError:
    """The error with the stored file's path and name replaced by the name the person gave it
    (an upload is stored as upload-<random><suffix>: no message should show that)."""
    text = str(error).replace(path, name).replace(os.path.basename(path), name)
    renamed = copy.copy(error)
    renamed.args = (text,)
    return renamed


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

    def as_json(self) -> dict:
        return {"id": self.id, "name": self.name, "k": self.k, "vertices": self.vertices,
                "ready": self.basis is not None,
                "job": self.job.as_json() if self.job else None, "rig": self.rig}


@dataclass
class SongItem:
    id: str
    name: str
    path: str
    spectrogram: object = None
    bundle: bytes | None = None

    def as_json(self) -> dict:
        duration = float(getattr(self.spectrogram, "duration", 0) or 0)
        return {"id": self.id, "name": self.name, "duration": duration}


@dataclass
class MappingItem:
    id: str
    name: str
    data: dict

    def as_json(self) -> dict:
        return {"id": self.id, "name": self.name}


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
    lock: threading.Lock = field(default_factory=threading.Lock)

    def as_json(self) -> dict:
        info = {"id": self.id, "name": self.name, "origin": self.origin,
                "ready": self.rig is not None, "revision": self.revision,
                "error": self.error or None}
        if self.rig is not None:
            info.update(bodies=self.rig.skeleton.n_bodies, joints=len(self.rig.skeleton.joints),
                        vertices=len(self.rig.skeleton.vertices), modes=self.rig.model.n_modes)
        return info


class Library:
    def __init__(self, folder: str, k: int = 150, max_upload_bytes: int = 64 << 20,
                 spectrogram_options: dict | None = None):
        self.folder = folder
        os.makedirs(folder, exist_ok=True)
        self.k = k
        self.max_upload_bytes = max_upload_bytes
        self.spectrogram_options = spectrogram_options or {}
        self.meshes: dict[str, MeshItem] = {}
        self.songs: dict[str, SongItem] = {}
        self.mappings: dict[str, MappingItem] = {}
        self.jobs: dict[str, Job] = {}
        self.rigs: dict[str, RigItem] = {}
        self.lock = threading.Lock()
        self.worker = ThreadPoolExecutor(max_workers=1, thread_name_prefix="basis")
        self.progress_listeners = []  # callables(job) for the terminal
        for rig_name in SAMPLE_RIGS:
            item = RigItem(new_id(), rig_name, "built-in", rig_name)
            self.rigs[item.id] = item

    # --- adding items -----------------------------------------------------------------------
    def add_path(self, path: str, name: str | None = None, k: int | None = None):
        """Register a file by its kind (suffix). Meshes start a basis job; songs are decoded."""
        name = name or os.path.basename(path)
        kind = kind_of(name)
        check_readable(path)
        if kind == "mesh":
            item = self.add_mesh(path, name, k)
            self.add_skinned_rig(item, path, "file")
            return item
        if kind == "audio":
            return self.add_song(path, name)
        if is_skeleton_json(path):
            return self.add_rig(path, name, "file")
        return self.add_mapping_file(path, name)

    def add_upload(self, data: bytes, name: str, kind: str):
        """Store an uploaded file under a name of our own and register it as `kind`."""
        stored = os.path.join(self.folder, f"upload-{secrets.token_hex(6)}{suffix_of(name)}")
        os.makedirs(self.folder, exist_ok=True)  # a /tmp cleaner may have removed it meanwhile
        with open(stored, "wb") as file:
            file.write(data)
        try:
            if kind == "mesh":
                item = self.add_mesh(stored, name)
                self.add_skinned_rig(item, stored, "upload")
                return item
            if kind == "audio":
                return self.add_song(stored, name)
            if is_skeleton_json(stored):
                return self.add_rig(stored, name, "upload")
            return self.add_mapping_file(stored, name)
        except EigendanceError as error:
            os.unlink(stored)
            raise named(error, stored, name) from None
        except BaseException:
            os.unlink(stored)
            raise

    def add_mesh(self, path: str, name: str, k: int | None = None) -> MeshItem:
        mesh = load_mesh(path)  # raises EigendanceError on anything unreadable
        if mesh.non_manifold_edge_count():
            laplacian = "robust"
        else:
            laplacian = "cotan"
        k = max(2, min(k or self.k, len(mesh.vertices) - 2))
        item = MeshItem(new_id(), name, path, k, len(mesh.vertices))
        job = Job(new_id(), "basis", k, name)
        item.job = job
        with self.lock:
            self.meshes[item.id] = item
            self.jobs[job.id] = job
        self.worker.submit(self._solve, item, mesh, laplacian)
        return item

    def _solve(self, item: MeshItem, mesh, laplacian: str) -> None:
        job = item.job
        job.cached = os.path.isfile(basis_cache().path(basis_key(mesh, item.k, laplacian)))
        job.update(state="running")
        for listener in self.progress_listeners:
            listener(job)

        def progress(done):
            job.update(done=int(min(done, job.total)))
            for listener in self.progress_listeners:
                listener(job)

        try:
            basis = HarmonicBasis.from_mesh(mesh, item.k, laplacian=laplacian, progress=progress)
            item.bundle = basis_bundle(basis, item.name)
            item.basis = basis
            job.update(state="done", done=job.total)
        except EigendanceError as error:
            job.update(state="error", message=str(named(error, item.path, item.name)))
        except Exception as error:  # noqa: BLE001 - reported to the page, never crashes the server
            job.update(state="error", message=f"{item.name}: the basis failed (internal error: "
                                              f"{type(error).__name__}: {one_line(error, 200)})")
        for listener in self.progress_listeners:
            listener(job)

    def add_song(self, path: str, name: str) -> SongItem:
        try:
            spectrogram = Spectrogram.from_file(path, **self.spectrogram_options)
        except EigendanceError:
            raise
        except Exception as error:  # noqa: BLE001 - decoders raise many types
            raise InputError(f"{name}: cannot decode the audio ({one_line(error)})") from None
        item = SongItem(new_id(), name, path, spectrogram)
        item.bundle = spectrogram_bundle(spectrogram, name)
        with self.lock:
            self.songs[item.id] = item
        return item

    def add_mapping_file(self, path: str, name: str) -> MappingItem:
        try:
            with open(path, encoding="utf-8") as file:
                data = json.load(file)
        except (OSError, ValueError) as error:
            raise InputError(f"{name}: not a JSON mapping ({one_line(error)})") from None
        return self.add_mapping(data, name)

    def add_mapping(self, data, name: str) -> MappingItem:
        mapping = Mapping.from_json(data, name)  # EigendanceError naming the bad field
        item = MappingItem(new_id(), name, mapping.to_json())
        with self.lock:
            self.mappings[item.id] = item
        return item

    # --- rigs -------------------------------------------------------------------------------
    def add_rig(self, path: str, name: str, origin: str) -> RigItem:
        """A rig file (skeleton JSON or glTF skin), analysed now; InputError if it is bad."""
        item = RigItem(new_id(), name, origin, path)
        self._analyse(item, load_rig(path, name))
        with self.lock:
            self.rigs[item.id] = item
        return item

    def add_skinned_rig(self, mesh: MeshItem, path: str, origin: str) -> RigItem | None:
        """The rig of a mesh file that has a skin (glTF), or None. A skin that cannot be
        analysed is kept as an item with its error, so the page can say why."""
        if not has_skin(path):
            return None
        item = RigItem(new_id(), mesh.name, origin, path)
        try:
            self._analyse(item, load_rig(path, mesh.name))
        except EigendanceError as error:
            item.error = str(error)
        with self.lock:
            self.rigs[item.id] = item
        mesh.rig = item.id
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
                    item.error = str(error)
            if item.error:
                raise InputError(item.error, status=409)
        return item

    def edit_rig(self, item: RigItem, edit) -> bytes:
        """Apply `edit` (skeleton → skeleton) to the current skeleton, analyse the result and
        return its bundle; a failed edit leaves the rig as it was."""
        self.ready_rig(item)
        with item.lock:
            self._analyse(item, edit(item.rig.skeleton), original=item.original)
            return item.bundle

    def reset_rig(self, item: RigItem) -> bytes:
        """Back to the rig as loaded (pose and stiffness)."""
        return self.edit_rig(item, lambda _: item.original)

    def _analyse(self, item: RigItem, skeleton: Skeleton, original: Skeleton | None = None):
        rig = Rig.from_skeleton(skeleton)
        bundle = rig_bundle(rig, item.name, item.revision + (item.rig is not None))
        item.original = original or skeleton
        item.revision += item.rig is not None
        item.rig, item.bundle = rig, bundle

    # --- lookups ----------------------------------------------------------------------------
    def as_json(self) -> dict:
        with self.lock:
            return {"meshes": [m.as_json() for m in self.meshes.values()],
                    "songs": [s.as_json() for s in self.songs.values()],
                    "mappings": [m.as_json() for m in self.mappings.values()],
                    "rigs": [r.as_json() for r in self.rigs.values()]}

    def wait(self, timeout: float | None = None) -> bool:
        """Block until every basis job has finished (tests, CLI)."""
        deadline = None if timeout is None else time.time() + timeout
        for job in list(self.jobs.values()):
            with job.changed:
                while job.state in ("queued", "running"):
                    left = None if deadline is None else deadline - time.time()
                    if left is not None and left <= 0:
                        return False
                    job.changed.wait(left)
        return True

    def close(self) -> None:
        self.worker.shutdown(wait=False, cancel_futures=True)
