"""What the server's library holds: one item per mesh, song, mapping and rig, and the basis jobs
(docs/design.md#server).

Every item has a short random id, a name (the one it was given or uploaded under), `as_json`
(what the page is told about it), `held` (the bytes it keeps, charged to the memory budget,
`server.memory`) and `busy` (in use: never dropped for memory). `content` is the key of its
content (`server.contents`), so that the same bytes added again answer the same item.
"""

from __future__ import annotations

import secrets
import threading
import time
from dataclasses import dataclass, field

from eigendance.harmonic.reduced import sample_count
from eigendance.modal.rig import Rig
from eigendance.modal.skeleton import Skeleton
from eigendance.server.memory import footprint

# Bytes per vertex and harmonic a mesh item keeps: the basis (float64), its bundle (float32)
# and the float16 bundle the page may ask for.
BYTES_PER_ENTRY = 8 + 4 + 2
BYTES_PER_VERTEX = 256  # vertices, mass, faces (≈ 2 per vertex) in the basis and the bundles
# A reduced basis (docs/design.md#reduced-basis) keeps per vertex its interpolation (indices,
# weights, P as a matrix, the bundle's float16 and uint16 copies) instead of k entries.
REDUCED_BYTES_PER_VERTEX = 320


def new_id() -> str:
    """A new item or job id.

    Returns
    -------
    str: 12 random hexadecimal digits.
    """
    return secrets.token_hex(6)


@dataclass
class Job:
    """A basis being computed, as the page follows it (`GET /api/jobs/{id}`, its events).

    Parameters
    ----------
    id : the job's id.
    kind : "basis".
    total : harmonics to compute.
    name : the mesh's name.
    done : harmonics computed so far.
    state : "queued", "running", "done" or "error".
    message : why it failed (state "error").
    cached : the basis is in the on-disk cache (no solve).
    started : when it was made, seconds since the epoch.
    changed : notified at every `update`.
    """

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
        """Set fields and wake whoever waits on `changed`.

        Parameters
        ----------
        **values : {field name: new value}.
        """
        with self.changed:
            for name, value in values.items():
                setattr(self, name, value)
            self.changed.notify_all()

    @property
    def busy(self) -> bool:
        """Queued or running."""
        return self.state in ("queued", "running")

    def as_json(self) -> dict:
        """What the page is told.

        Returns
        -------
        {"id", "kind", "state", "done", "total", "message", "cached"} (cached: the basis is
        read from the disk cache, not solved).
        """
        return {"id": self.id, "kind": self.kind, "state": self.state, "done": self.done,
                "total": self.total, "message": self.message, "cached": self.cached}


@dataclass
class MeshItem:
    """A mesh and its basis (computed by `server.solver`).

    Parameters
    ----------
    id, name, path : its id, its name, its file.
    k : harmonics of its basis.
    vertices : its vertex count.
    job : the basis job.
    basis : the `HarmonicBasis`, once computed.
    bundle, half_bundle : the basis bundle with float32 and float16 harmonics (`server.binary`).
    rig : the id of the rig item of the same file (a glTF with a skin), or None.
    content : its content key.
    removed : taken out of the library (its solve stops).
    construction : "exact" or "reduced" (docs/design.md#reduced-basis).
    appearance : its look (`assets.Appearance`: materials, drawn vertices), None for clay.
    look_bundle : its appearance bundle, made when first asked for (`server.binary`).
    """

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
    content: tuple | None = None  # the key of its content (server.contents)
    removed: bool = False
    construction: str = "exact"
    appearance: object = None
    look_bundle: bytes | None = None

    def as_json(self) -> dict:
        """What the page is told.

        Returns
        -------
        {"id", "name", "k", "vertices", "ready", "construction", "job", "rig", "look"
        (`look_summary`)}.
        """
        return {"id": self.id, "name": self.name, "k": self.k, "vertices": self.vertices,
                "ready": self.basis is not None, "construction": self.construction,
                "job": self.job.as_json() if self.job else None, "rig": self.rig,
                "look": look_summary(self.appearance)}

    def held(self) -> int:
        """Bytes kept: the basis and bundles once solved, the planned ones until then, and the
        look.

        Returns
        -------
        int, bytes.
        """
        look = footprint(self.appearance, self.look_bundle)
        if self.basis is None and self.construction == "reduced":
            return self.vertices * (REDUCED_BYTES_PER_VERTEX + BYTES_PER_VERTEX) + \
                sample_count(self.vertices, self.k) * self.k * BYTES_PER_ENTRY + look
        if self.basis is None:
            return self.vertices * (self.k * BYTES_PER_ENTRY + BYTES_PER_VERTEX) + look
        return footprint(self.basis, self.bundle, self.half_bundle, self.appearance,
                         self.look_bundle)

    @property
    def busy(self) -> bool:
        """Its basis is queued or being computed."""
        return self.job is not None and self.job.busy


@dataclass
class SongItem:
    """A song and its spectrogram.

    Parameters
    ----------
    id, name, path : its id, its name, its audio file.
    spectrogram : its `Spectrogram`.
    bundle : the spectrogram bundle (`server.binary`).
    content : its content key.
    """

    id: str
    name: str
    path: str
    spectrogram: object = None
    bundle: bytes | None = None
    content: tuple | None = None
    busy = False

    def as_json(self) -> dict:
        """What the page is told.

        Returns
        -------
        {"id", "name", "duration" (s)}.
        """
        duration = float(getattr(self.spectrogram, "duration", 0) or 0)
        return {"id": self.id, "name": self.name, "duration": duration}

    def held(self) -> int:
        """Bytes kept: the spectrogram and its bundle.

        Returns
        -------
        int, bytes.
        """
        return footprint(self.spectrogram, self.bundle)


@dataclass
class MappingItem:
    """A saved mapping.

    Parameters
    ----------
    id, name : its id and name.
    data : its document (`Mapping.to_json`).
    content : its content key (the SHA-256 of its fields).
    origin : "file" (given to `serve`: the page opens it at start) or "upload".
    """

    id: str
    name: str
    data: dict
    content: tuple | None = None
    origin: str = "upload"
    busy = False

    def as_json(self) -> dict:
        """What the page is told.

        Returns
        -------
        {"id", "name", "origin"}.
        """
        return {"id": self.id, "name": self.name, "origin": self.origin}

    def held(self) -> int:
        """Bytes kept: its document.

        Returns
        -------
        int, bytes.
        """
        return footprint(self.data)


@dataclass
class RigItem:
    """A rig and its edits (`server.rigs`).

    Parameters
    ----------
    id, name : its id and name.
    origin : "built-in", "file" or "upload".
    source : a built-in rig's name, else the file's path.
    original : the skeleton as loaded, once analysed.
    rig : the current `Rig` (edits included), once analysed.
    bundle : the rig bundle of the current rig (`server.binary.rig_bundle`).
    revision : how many edits made the current rig.
    edited : whether its pose or stiffness differs from the rig as loaded (a reset is not an
        edit).
    error : why a file could not be analysed ("" when it was).
    content : its content key.
    lock : held while it is analysed or edited.
    look_bundle : the appearance bundle of its skin, made when first asked for.
    """

    id: str
    name: str
    origin: str
    source: str
    original: Skeleton | None = None
    rig: Rig | None = None
    bundle: bytes | None = None
    revision: int = 0
    edited: bool = False
    error: str = ""
    content: tuple | None = None
    lock: threading.Lock = field(default_factory=threading.Lock)
    look_bundle: bytes | None = None

    @property
    def appearance(self):
        """The skin's look (`assets.Appearance`), or None (clay, or not analysed yet)."""
        return getattr(self.original, "appearance", None)

    @property
    def path(self) -> str:
        """Its file ("" for a built-in rig)."""
        return "" if self.origin == "built-in" else self.source

    def as_json(self) -> dict:
        """What the page is told.

        Returns
        -------
        {"id", "name", "origin", "ready", "revision", "edited", "error"}, and once analysed
        "bodies", "joints", "vertices", "modes", "look" (`look_summary`).
        """
        info = {"id": self.id, "name": self.name, "origin": self.origin,
                "ready": self.rig is not None, "revision": self.revision,
                "edited": self.edited, "error": self.error or None}
        if self.rig is not None:
            info.update(bodies=self.rig.skeleton.n_bodies, joints=len(self.rig.skeleton.joints),
                        vertices=len(self.rig.skeleton.vertices), modes=self.rig.model.n_modes,
                        look=look_summary(self.appearance))
        return info

    def held(self) -> int:
        """Bytes kept: the skeletons, the rig (modes, modal skin) and its bundle.

        Returns
        -------
        int, bytes.
        """
        return footprint(self.original, self.rig, self.bundle, self.look_bundle)

    @property
    def busy(self) -> bool:
        """Being analysed or edited."""
        return self.lock.locked()


def look_summary(appearance) -> dict | None:
    """What the page knows of a model's look before asking for it.

    Parameters
    ----------
    appearance : an `assets.Appearance`, or None.

    Returns
    -------
    None (clay), or {"materials", "images", "drawn"} counts.
    """
    if appearance is None:
        return None
    return {"materials": len(appearance.materials), "images": len(appearance.images),
            "drawn": int(appearance.n)}
