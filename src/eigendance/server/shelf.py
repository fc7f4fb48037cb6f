"""The library's shelf: its items by kind, charged within the memory budget
(docs/design.md#server).

Every item is charged the bytes it keeps (`server.memory`: a mesh its planned basis and bundles
before it is solved); lookups by id make an item the most recently used, and when the total
exceeds the budget the least recently used items are dropped, never one in use (`busy`). An
item too large for the budget on its own is refused (413). A dropped item's stored file is
deleted once no item uses it; a built-in rig is never dropped, only its analysis forgotten.
Messages name stored files by the names they were uploaded under (`public`).
"""

from __future__ import annotations

import contextlib
import os
import re
import shutil
import threading

from eigendance.errors import InputError
from eigendance.server import rigs
from eigendance.server.contents import Contents
from eigendance.server.items import MappingItem, MeshItem, RigItem, SongItem
from eigendance.server.memory import Budget, refusal

# Names of our own in the library folder: stored uploads and uploads being received.
STORED_NAME = re.compile(r"(upload-[0-9a-f]{6,}|\.incoming-\w+)(\.\w+)?")
KINDS = ("mesh", "song", "mapping", "rig")


class Shelf:
    """Items by kind within a memory budget (see the module docstring).

    Parameters
    ----------
    folder : the library folder (stored uploads).
    budget : the memory budget.

    Attributes: meshes, songs, mappings, rigs ({id: item}); contents (`server.contents`);
    lock (held while the shelf changes); removed: called with a mesh item dropped (its solve
    stops).
    """

    def __init__(self, folder: str, budget: Budget):
        self.folder = folder
        self.meshes: dict[str, MeshItem] = {}
        self.songs: dict[str, SongItem] = {}
        self.mappings: dict[str, MappingItem] = {}
        self.rigs: dict[str, RigItem] = {}
        self.budget = budget
        self.lock = threading.RLock()
        self.contents = Contents(self.lock)
        self.unpacked: dict[str, str] = {}  # a zip's folder → its model file, relative
        self.removed = lambda item: None
        self.reserved: set[str] = set()  # keys charged for work in progress (`reserving`)

    @contextlib.contextmanager
    def reserving(self, key: str, size: int, what: str):
        """Charge `size` bytes under `key` before the work that allocates them (dropping the
        least recently used items to make room); release them if the work fails. Work that
        succeeds charges what it keeps under the same key (`admit`, `recharge`).

        Parameters
        ----------
        key : the budget's key (an item's id, or one of its own for an edit).
        size : the planned bytes.
        what : the work in words, for the message when it cannot fit (InputError 413 or 409).

        Yields
        ------
        None, while the work runs (its key is busy: never dropped meanwhile).
        """
        with self.lock:
            dropped = self.budget.charge(key, size, busy=self._busy)
            if dropped is None:
                raise refusal(size, self.budget.limit, what)
            self.reserved.add(key)
            for other in dropped:
                self._drop(other)
        try:
            yield
        except BaseException:
            self.budget.release(key)
            raise
        finally:
            self.reserved.discard(key)

    def admit(self, item, store: dict, what: str) -> None:
        """Charge `item` its bytes (dropping the least recently used items to make room) and
        list it.

        Parameters
        ----------
        item : a new item.
        store : where it is listed (`meshes`, `songs`, `mappings`, `rigs`).
        what : the item in words, for the message when it cannot fit (InputError 413 or 409).
        """
        size = item.held()
        with self.lock:
            dropped = self.budget.charge(item.id, size, busy=self._busy)
            if dropped is None:
                raise refusal(size, self.budget.limit, what)
            for other in dropped:
                self._drop(other)
            store[item.id] = item
            self.contents.add(item.content, item.id)

    def recharge(self, item) -> None:
        """Charge `item` what it holds now (a solved basis, a new bundle), dropping others.

        Parameters
        ----------
        item : an item of the shelf (nothing happens if it is gone).
        """
        with self.lock:
            if self.find(item.id) is not item:
                return
            dropped = self.budget.charge(item.id, item.held(), busy=self._busy)
            for other in dropped or ():
                self._drop(other)

    def _busy(self, item_id: str) -> bool:
        """In use, not to be dropped: a mesh whose basis is queued or being solved, a rig being
        analysed or edited."""
        if item_id in self.reserved:
            return True
        item = self.find(item_id)
        return item is not None and item.busy

    def get(self, kind: str, item_id: str):
        """The item of `kind` with `item_id`; a lookup makes it the most recently used.

        Parameters
        ----------
        kind : "mesh", "song", "mapping" or "rig".
        item_id : its id.

        Returns
        -------
        The item, or None.
        """
        item = self._store(kind).get(item_id)
        if item is not None:
            self.budget.touch(item.id)
        return item

    def remove(self, kind: str, item_id: str) -> list[str]:
        """Remove an item (a mesh with the rig of its skin), stopping its solve.

        Parameters
        ----------
        kind : "mesh", "song", "mapping" or "rig".
        item_id : its id.

        Returns
        -------
        list of the ids removed; InputError 404 for an unknown id, 409 for a built-in rig.
        """
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
        item = self.find(item_id)
        if isinstance(item, RigItem) and item.origin == "built-in":
            rigs.forget(item)
            return
        for kind in KINDS:
            self._store(kind).pop(item_id, None)
        if item is None:
            return
        self.contents.forget(item.content, item_id)
        if isinstance(item, MeshItem):
            item.removed = True
            self.removed(item)
        elif isinstance(item, RigItem):
            for mesh in self.meshes.values():
                if mesh.rig == item.id:
                    mesh.rig = None
        self.discard(getattr(item, "path", ""))

    def discard(self, *paths: str) -> None:
        """Delete files of the library folder that no item uses (a zip's whole folder once no
        item uses its model).

        Parameters
        ----------
        *paths : files (others than the library folder's are left alone).
        """
        with self.lock:
            for path in paths:
                folder = self._unpacked_folder(path)
                if folder and not self._in_use(os.path.join(folder, self.unpacked[folder])):
                    shutil.rmtree(folder, ignore_errors=True)
                    del self.unpacked[folder]
                elif path and os.path.dirname(path) == self.folder and not self._in_use(path):
                    try:
                        os.unlink(path)
                    except OSError:
                        pass

    def _unpacked_folder(self, path: str) -> str | None:
        """The zip folder of the library holding `path`, or None."""
        for folder in self.unpacked:
            if path.startswith(folder + os.sep):
                return folder
        return None

    def _store(self, kind: str) -> dict:
        return {"mesh": self.meshes, "song": self.songs, "mapping": self.mappings,
                "rig": self.rigs}[kind]

    def find(self, item_id: str):
        """The item with this id, of any kind.

        Parameters
        ----------
        item_id : its id.

        Returns
        -------
        The item, or None.
        """
        for kind in KINDS:
            if item_id in self._store(kind):
                return self._store(kind)[item_id]
        return None

    def touched(self, item_id: str):
        """The item with this id (any kind), made the most recently used.

        Parameters
        ----------
        item_id : its id.

        Returns
        -------
        The item, or None when it is gone.
        """
        item = self.find(item_id)
        if item is not None:
            self.budget.touch(item.id)
        return item

    def _in_use(self, path: str) -> bool:
        return any(getattr(item, "path", "") == path for store in
                   (self.meshes, self.songs, self.rigs) for item in store.values())

    # --- what the page sees ---------------------------------------------------------------------
    def public(self, text: str, names: dict[str, str] | None = None) -> str:
        """A message for the page: every stored file called by the name it was uploaded
        under, and no path inside the library folder.

        Parameters
        ----------
        text : the message.
        names : more {path: name} to replace.

        Returns
        -------
        str.
        """
        names = dict(names or {})
        for store in (self.meshes, self.songs, self.rigs):
            for item in list(store.values()):
                if item.path and item.path.startswith(self.folder + os.sep):
                    names[item.path] = item.name
        for path, name in names.items():
            text = text.replace(path, name).replace(os.path.basename(path), name)
        text = text.replace(self.folder + os.sep, "").replace(self.folder, "the library")
        return STORED_NAME.sub("an uploaded file", text)

    def as_json(self) -> dict:
        """The library as `GET /api/library` answers it.

        Returns
        -------
        {"meshes", "songs", "mappings", "rigs": [item.as_json()], "memory": {"used",
        "budget"} (bytes)}.
        """
        with self.lock:
            return {"meshes": [m.as_json() for m in self.meshes.values()],
                    "songs": [s.as_json() for s in self.songs.values()],
                    "mappings": [m.as_json() for m in self.mappings.values()],
                    "rigs": [r.as_json() for r in self.rigs.values()],
                    "memory": {"used": self.budget.used, "budget": self.budget.limit}}

