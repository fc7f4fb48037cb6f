"""Files into the library: meshes, songs, mappings and rigs (docs/design.md#server).

A file given to `serve` (`add_path`) or uploaded (`add_upload`) becomes an item by its kind: a
mesh (its basis queued), a song (decoded into its spectrogram), a mapping, or a rig (a skeleton
JSON is a rig, any other JSON a mapping; a skinned glTF is a rig, or a mesh when its skin cannot
be analysed). One item per distinct content (`server.contents`): the same bytes again answer the
item already there — unless that item is a mesh whose solve failed (its worker killed, out of
memory): then the same bytes make a new item, whose solve starts again, and the failed one is
removed. Uploads are stored inside the library folder as ``upload-<content digest><suffix>``, so
names from the network never become paths. A .zip is a model in several files
(`server.archive`): unpacked once into the folder ``upload-<digest>/`` and read from there.
Each file is classified by its content and read once through the inputs layer
(`server.analysis.read_file` in one of the server's worker processes: `run`, songs included),
each within a deadline proportional to its size (`analysed`); a mesh's parse stays out of the
server (`analysis.ReadMesh`: its `HarmonicProblem` saved in the library's folder for its
solve's worker, removed once the solve ends), and a song's spectrogram is charged to the memory
budget from its length before it is decoded.
"""

from __future__ import annotations

import hashlib
import json
import os
import shutil

from eigendance.errors import EigendanceError, InputError
from eigendance.files import check_readable, file_digest, kind_of, suffix_of
from eigendance.harmonic.construction import is_cached
from eigendance.inputs.mapping import mapping_from
from eigendance.inputs.model import GLTF_SUFFIXES
from eigendance.modal.skeleton import Skeleton
from eigendance.server import analysis, rigs
from eigendance.server.archive import is_archive, unpack
from eigendance.server.items import Job, MappingItem, MeshItem, RigItem, SongItem, new_id
from eigendance.server.shelf import Shelf
from eigendance.server.solver import BasisSolver

UPLOAD_PREFIX = "upload-"
# An analysis of a file (reading a mesh, a rig or a song) is stopped past ANALYSIS_SECONDS plus
# a second per ANALYSIS_BYTES_PER_SECOND of the file (a 64 MB upload: 316 s), so that stuck
# analyses do not hold the upload slots forever (docs/design.md#server).
ANALYSIS_SECONDS, ANALYSIS_BYTES_PER_SECOND = 60.0, 256 << 10
# A model's zip may unpack to this many times the upload limit (docs/design.md#server).
UNPACKED_FACTOR = 4


class Intake:
    """Turns files into items on the shelf (see the module docstring).

    Parameters
    ----------
    shelf : where the items go, charged within its memory budget.
    solver : the queue that computes mesh bases.
    k : harmonics per mesh basis.
    spectrogram_options : options of `Spectrogram.from_file`.
    construction : "auto", "exact" or "reduced": how each mesh's basis is solved.
    samples : the samples a reduced basis asks for (None: `reduced.sample_count`).
    unpacked_limit : the most bytes a model's zip may unpack to.
    run : how to call `server.analysis` (`Library.run`: in a worker process; default
        `rigs.direct`: here).
    """

    def __init__(self, shelf: Shelf, solver: BasisSolver, k: int,
                 spectrogram_options: dict | None = None, construction: str = "auto",
                 unpacked_limit: int = 256 << 20, run: rigs.Run = rigs.direct,
                 samples: int | None = None):
        self.shelf, self.solver, self.k, self.run = shelf, solver, k, run
        self.construction, self.samples = construction, samples
        self.spectrogram_options = spectrogram_options or {}
        self.unpacked_limit = unpacked_limit

    def add_path(self, path: str, name: str | None = None, k: int | None = None):
        """Register a file by its kind (suffix): meshes start a basis job, songs are decoded.

        Parameters
        ----------
        path : the file (given to `serve`, or an upload already stored).
        name : how the page calls it (default: the file's name).
        k : harmonics of a mesh's basis (default the library's).

        Returns
        -------
        The item: new, or the one already there with the same content.
        """
        name = name or os.path.basename(path)
        check_readable(path)
        if is_archive(name):
            return self._add_archive(path, name, file_digest(path), "file", k)[0]
        return self._add_file(path, name, kind_of(name), file_digest(path), "file", k)[0]

    def add_upload(self, stored: str, name: str, kind: str, digest: str):
        """Register an uploaded file under a name of our own; an upload that fails leaves no
        file behind.

        Parameters
        ----------
        stored : where it was received, inside the library folder.
        name : the name it was uploaded under.
        kind : "mesh", "audio" or "mapping" (by suffix; a skeleton JSON becomes a rig).
        digest : the SHA-256 of its bytes.

        Returns
        -------
        (item, new): new is False when the same content was there (that item is answered).
        """
        if is_archive(name):
            try:
                return self._add_archive(stored, name, digest, "upload")
            finally:
                os.unlink(stored)
        final = os.path.join(self.shelf.folder, f"{UPLOAD_PREFIX}{digest[:24]}{suffix_of(name)}")
        try:
            os.replace(stored, final)
            item, new = self._add_file(final, name, kind, digest, "upload")
        except BaseException as error:
            self.shelf.discard(stored, final)
            if isinstance(error, EigendanceError):
                message = self.shelf.public(str(error), {final: name})
                if "is missing" in message:  # a .gltf's buffer or image, not uploaded with it
                    message += "; add the model together with the files it names (drop them " \
                               "together, or as one .zip)"
                error.args = (message,)
            raise
        if not new:
            self.shelf.discard(final)  # unless it is the file of the item already there
        return item, new

    def _add_archive(self, path: str, name: str, digest: str, origin: str,
                     k: int | None = None):
        """A model's zip (`server.archive`): unpacked once into the library's folder
        `upload-<digest>/` and its model file added (named by that file); the item and whether
        it is new. A zip that fails leaves no folder behind."""
        shelf = self.shelf
        folder = os.path.join(shelf.folder, f"{UPLOAD_PREFIX}{digest[:24]}")
        if folder not in shelf.unpacked:
            part = f"{folder}.{new_id()}"
            try:
                model = os.path.relpath(unpack(path, part, self.unpacked_limit, name), part)
            except BaseException as error:
                shutil.rmtree(part, ignore_errors=True)
                if isinstance(error, EigendanceError):
                    error.args = (shelf.public(str(error), {path: name}),)
                raise
            with shelf.lock:  # the same zip unpacked meanwhile: keep the first
                if folder in shelf.unpacked:
                    shutil.rmtree(part, ignore_errors=True)
                else:
                    os.rename(part, folder)
                    shelf.unpacked[folder] = model
        model = os.path.join(folder, shelf.unpacked[folder])
        try:
            return self._add_file(model, os.path.basename(model), kind_of(model), digest,
                                  origin, k)
        except BaseException as error:
            shelf.discard(model)
            if isinstance(error, EigendanceError):
                error.args = (shelf.public(str(error), {model: os.path.basename(model)}),)
            raise

    def _add_file(self, path: str, name: str, kind: str, digest: str, origin: str,
                  k: int | None = None):
        """The item of a file (new, or the one with the same content) and whether it is new:
        classified and read once in a worker process (`analysis.read_file`), a song decoded
        here."""
        suffix = suffix_of(name)
        key = (kind, suffix, digest, k or self.k) if kind == "mesh" else (kind, suffix, digest)
        failed: list[MeshItem] = []  # the same content's mesh whose solve failed: retried

        def usable(item_id):
            item = self.shelf.touched(item_id)
            if isinstance(item, MeshItem) and item.job is not None and \
                    item.job.state == "error":
                failed.append(item)
                return None
            return item

        existing = self.shelf.contents.claim(key, usable)
        if existing is not None:
            return existing, False
        try:
            made = self._read_new(path, name, kind, origin, k, key)
        finally:
            self.shelf.contents.release(key)
        for old in failed:  # replaced by the new item (which keeps the stored file)
            try:
                self.shelf.remove("mesh", old.id)
            except InputError:  # removed meanwhile
                pass
        return made

    def _read_new(self, path: str, name: str, kind: str, origin: str, k: int | None,
                  key: tuple):
        """The new item of a file and True (a mapping: the item with its content and whether
        it is new): read once in a worker process within the file's deadline (`analysed`)."""
        if kind == "audio":
            return self.add_song(path, name, key), True
        parsed = os.path.join(self.shelf.folder, f"parsed-{new_id()}.npz")  # a mesh's problem
        try:
            kind, value = self.analysed(analysis.read_file, path, name, parsed, k or self.k,
                                        self.construction, False, self.samples)
            if kind == "mapping":
                return self.add_mapping(value, name, origin)
            if kind == "mesh":
                return self.add_mesh(value, path, key), True
            try:
                return self.add_rig(value, path, origin, key), True
            except InputError:
                if suffix_of(name) not in GLTF_SUFFIXES:
                    raise
            # a skin that cannot be analysed: the glTF dances as a mesh
            _, mesh = self.analysed(analysis.read_file, path, name, parsed, k or self.k,
                                    self.construction, True, self.samples)
            return self.add_mesh(mesh, path, key), True
        except BaseException:
            self.shelf.discard(parsed)  # no solve queued: nobody else removes it
            raise

    def add_mesh(self, mesh: analysis.ReadMesh, path: str,
                 content: tuple | None = None) -> MeshItem:
        """A mesh item, charged its planned basis, and its basis job queued.

        Parameters
        ----------
        mesh : the mesh as read (`analysis.read_file`): its name, vertex count, k and
            construction are the item's; its saved problem goes to the solve's worker.
        path : the mesh file.
        content : its content key.

        Returns
        -------
        MeshItem.

        Raises
        ------
        InputError
            When its basis cannot fit the library's memory.
        """
        item = MeshItem(new_id(), mesh.name, path, mesh.k, mesh.vertices, content=content,
                        construction=mesh.construction, appearance=mesh.appearance)
        item.job = Job(new_id(), "basis", mesh.k, mesh.name, cached=is_cached(mesh.key))
        self.shelf.admit(item, self.shelf.meshes, f"{mesh.name}: a basis of {mesh.k} "
                                                  f"harmonics of {mesh.vertices} vertices")
        self.solver.put(item, mesh)
        return item
    def add_song(self, path: str, name: str, content: tuple | None = None) -> SongItem:
        """A song item: the audio decoded into its spectrogram and bundle.

        Parameters
        ----------
        path : the audio file.
        name : its name.
        content : its content key.

        Returns
        -------
        SongItem; InputError when the audio cannot be decoded or cannot fit.
        """
        seconds = self.analysed(analysis.song_seconds, path, name)
        item_id = new_id()
        with self.shelf.reserving(item_id, analysis.song_bytes(seconds, self.spectrogram_options),
                                  f"{name}: the spectrogram of {seconds:.0f} s"):
            spectrogram, bundle = self.analysed(analysis.read_song, path, name,
                                                self.spectrogram_options)
            item = SongItem(item_id, name, path, spectrogram, content=content)
            item.bundle = bundle
            self.shelf.admit(item, self.shelf.songs, f"{name}: its spectrogram")
        return item

    def analysed(self, function, path: str, name: str, *rest):
        """function(path, name, *rest) of `server.analysis` through `run`, within the deadline
        of the file's size (ANALYSIS_SECONDS, ANALYSIS_BYTES_PER_SECOND).

        Parameters
        ----------
        function : a function of `server.analysis` taking a file and its name first.
        path, name : the file and its name.
        *rest : its other arguments.

        Returns
        -------
        Its result; InputError (422) past the deadline.
        """
        try:
            size = os.path.getsize(path)
        except OSError:
            size = 0
        return self.run(function, path, name, *rest,
                        seconds=ANALYSIS_SECONDS + size / ANALYSIS_BYTES_PER_SECOND)

    def add_mapping(self, data, name: str, origin: str = "upload") -> tuple[MappingItem, bool]:
        """A mapping item from a parsed mapping document.

        Parameters
        ----------
        data : the document (checked by `inputs.mapping.mapping_from`).
        name : its name.
        origin : "file" (given to `serve`: the page opens it at start) or "upload".

        Returns
        -------
        (item, new): new is False when the same mapping (the same fields) was there.
        """
        fields = mapping_from(data, name).to_json()
        text = json.dumps(fields, sort_keys=True).encode()
        key = ("mapping", hashlib.sha256(text).hexdigest())
        with self.shelf.lock:
            existing = self.shelf.touched(self.shelf.contents.find(key) or "")
            if existing is not None:
                return existing, False
            item = MappingItem(new_id(), name, fields, content=key, origin=origin)
            self.shelf.admit(item, self.shelf.mappings, f"{name}: the mapping")
            return item, True

    def add_rig(self, skeleton: Skeleton, path: str, origin: str,
                content: tuple | None = None) -> RigItem:
        """A rig item (skeleton JSON or glTF skin), analysed now.

        Parameters
        ----------
        skeleton : its skeleton with its skin (`analysis.read_file`); its name is the item's.
        path : the file.
        origin : "file" or "upload".
        content : its content key.

        Returns
        -------
        RigItem.

        Raises
        ------
        InputError
            When it is not a rig that can be analysed, or cannot fit (its planned memory is
            charged before the analysis: `rigs.planned_bytes`).
        """
        name = skeleton.name
        item = RigItem(new_id(), name, origin, path, content=content)
        with self.shelf.reserving(item.id, rigs.planned_bytes(skeleton),
                                  f"{name}: the analysis of {skeleton.n_bodies} bodies"):
            rigs.analyse(item, skeleton, self.run)
            self.shelf.admit(item, self.shelf.rigs, f"{name}: the rig")
        return item
