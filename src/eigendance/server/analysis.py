"""The analysis of the library's files, as run in the server's worker processes
(`server.workers.run`, docs/design.md#server).

Each function takes and returns picklable values only: what a file holds, read once by the
inputs layer (`inputs.model`: a skeleton, a mapping's document), or what the page is sent (a
rig's analysis, a basis, with their bundles). A mesh's parse never comes back: the reading
worker saves its `HarmonicProblem` into the library's folder (`HarmonicProblem.save`) and
answers what the server plans the item with (`ReadMesh`: counts, k, construction, cache key and
the look); the solve's worker loads it from there (`solve_basis`). The mesh so crosses a
process boundary once, and only the solved basis comes back. Reading a mesh or a rig's glTF, a rig's
modal analysis, a basis's solve and their bundles are mostly pure
Python or hold the interpreter's lock in C; in a worker process they never make the event loop
wait. A song is decoded (`read_song`) in a worker process too, after its length is read from
its header (`song_seconds`, nothing decoded) so that the library charges the spectrogram's
bytes (`song_bytes`) before it is made: a native decoder that crashes takes only its worker
down, and a one-hour take no longer holds the server's interpreter lock. librosa's numba
kernels are compiled once, by the fork server (`music.compiled`), not by every worker.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import soundfile

from eigendance.errors import InputError
from eigendance.files import suffix_of
from eigendance.harmonic.basis import HarmonicBasis, HarmonicProblem
from eigendance.inputs.model import GLTF_SUFFIXES, classify, read_model
from eigendance.inputs.song import read_song as read_audio
from eigendance.modal.rig import Rig
from eigendance.modal.sample_rigs import sample_rig
from eigendance.modal.skeleton import Skeleton
from eigendance.music.analyser import BANDS, RATE
from eigendance.music.decode import SOUNDFILE_MAGIC, SOUNDFILE_SUFFIXES
from eigendance.music.spectrogram import Spectrogram
from eigendance.server.binary import basis_bundle, rig_bundle, spectrogram_bundle


@dataclass
class ReadMesh:
    """A mesh read in a worker process (`read_file`), as the server plans its item; the parse
    itself is in the file `parsed` (`HarmonicProblem.save`), for the solve's worker.

    Parameters
    ----------
    name : the mesh's name.
    vertices : its vertex count after clean-up.
    k : the harmonics of its basis (the asked k, within 2 and the vertex count − 2).
    construction : "exact" or "reduced", decided for k (`HarmonicProblem.construction_for`).
    key : the disk cache's key of the basis (`HarmonicProblem.key`).
    appearance : its look (`assets.Appearance`), or None.
    parsed : the saved problem.
    """

    name: str
    vertices: int
    k: int
    construction: str
    key: str
    appearance: object
    parsed: str


def read_file(path: str, name: str, parsed: str, k: int, construction: str = "auto",
              as_mesh: bool = False, samples: int | None = None) -> tuple[str, object]:
    """A library file classified by its content and read once (`inputs.model`): a mapping's
    document, a rig's skeleton, or a mesh, whose `HarmonicProblem` is saved to `parsed` (its
    construction for k decided) and summarised (`ReadMesh`). A glTF whose skin cannot be read
    is read as a mesh.

    Parameters
    ----------
    path : the file.
    name : how the page calls it (its suffix is the file's).
    parsed : where a mesh's problem is saved (a new file of the library's folder).
    k : the harmonics asked for a mesh's basis.
    construction : "auto", "exact" or "reduced": the mesh's basis.
    as_mesh : read a skinned glTF as a mesh (its skin could not be analysed).
    samples : the samples a reduced basis asks for (None: `reduced.sample_count`).

    Returns
    -------
    ("mapping", document), ("rig", Skeleton) or ("mesh", ReadMesh).

    Raises
    ------
    InputError
        As `inputs.model.classify` and `inputs.model.read_model`.
    """
    kind, document = ("mesh", None) if as_mesh else classify(path, name)
    if kind == "mapping":
        return kind, document
    if kind == "rig":
        try:
            return kind, read_model(path, name, "rig", document).skeleton
        except InputError:
            if suffix_of(name) not in GLTF_SUFFIXES:
                raise
    problem = read_model(path, name, "mesh", construction=construction, samples=samples).problem
    mesh = problem.mesh
    k = max(2, min(k, mesh.n - 2))
    chosen = problem.construction_for(k)
    problem.save(parsed)
    return "mesh", ReadMesh(mesh.name, mesh.n, k, chosen, problem.key(k), mesh.appearance,
                            parsed)


def read_rig(source: str, name: str, built_in: bool = False) -> Skeleton:
    """A rig's skeleton with its skin: a file (skeleton JSON or skinned glTF) or a built-in rig.

    Parameters
    ----------
    source : the file, or the built-in rig's name.
    name : how the page calls it.
    built_in : whether `source` names a built-in rig (`sample_rig`).

    Returns
    -------
    Skeleton.

    Raises
    ------
    InputError
        When it is not a rig that can be analysed.
    """
    return sample_rig(source) if built_in else read_model(source, name, "rig").skeleton


def analyse_rig(skeleton: Skeleton, dtype, name: str, revision: int,
                edited: bool) -> tuple[Rig, bytes]:
    """A skeleton's modal analysis (`Rig`, its modal skin made) and its bundle for the page.

    Parameters
    ----------
    skeleton : bodies, joints and skin.
    dtype : the modal skin's precision (numpy dtype).
    name, revision, edited : the bundle's (`binary.rig_bundle`).

    Returns
    -------
    (rig, bundle bytes).
    """
    rig = Rig(skeleton, np.dtype(dtype))
    return rig, rig_bundle(rig, name, revision, edited)


def read_song(path: str, name: str, options: dict) -> tuple[Spectrogram, bytes]:
    """A song decoded into its spectrogram (`inputs.song.read_song`), and its bundle for the
    page.

    Parameters
    ----------
    path : the audio file.
    name : its name.
    options : those of `Spectrogram.from_file`.

    Returns
    -------
    (spectrogram, bundle bytes).

    Raises
    ------
    InputError
        When the audio cannot be decoded.
    """
    spectrogram = read_audio(path, name=name, **options)
    return spectrogram, spectrogram_bundle(spectrogram, name)


def song_seconds(path: str, name: str) -> float:
    """A song's length from its header, or from its packets' times where the header does not
    say (a page's WebM take): nothing is decoded.

    Parameters
    ----------
    path : the audio file.
    name : its name.

    Returns
    -------
    float, seconds (0 when nothing tells: the decoding then says what is wrong).
    """
    if suffix_of(path) in SOUNDFILE_SUFFIXES:
        try:
            with open(path, "rb") as head:
                magic = head.read(4)
            if magic in SOUNDFILE_MAGIC:  # as `music.decode` reads it
                info = soundfile.info(path)
                if info.frames > 0 and info.samplerate > 0:
                    return info.frames / info.samplerate
        except Exception:  # noqa: BLE001 - libsndfile refuses it: FFmpeg's turn
            pass
    import av  # heavy (FFmpeg's libraries): imported only for what libsndfile cannot read

    try:
        with av.open(path) as container:
            if container.duration:
                return container.duration / av.time_base
            streams = container.streams.audio
            if not streams:
                return 0.0
            end = 0.0
            for packet in container.demux(streams[0]):
                if packet.pts is not None and packet.time_base:
                    end = max(end, float((packet.pts + (packet.duration or 0)) *
                                         packet.time_base))
            return end
    except Exception:  # noqa: BLE001 - the decoding says what is wrong, in one line
        return 0.0


def song_bytes(seconds: float, options: dict) -> int:
    """The bytes a song item keeps for a song of `seconds`: its spectrogram, the page's bundle
    and its rhythm (8.4 bytes a value measured on 2 s and 30 s songs; 9 charged).

    Parameters
    ----------
    seconds : the song's length.
    options : those of `Spectrogram.from_file` (rate, bands).

    Returns
    -------
    int.
    """
    frames = int(seconds * options.get("rate", RATE)) + 1
    return frames * options.get("bands", BANDS) * 9 + (64 << 10)


def solve_basis(parsed: str, k: int, progress=None) -> tuple[HarmonicBasis, bytes]:
    """A mesh's basis (`HarmonicProblem.basis`, with its disk cache) and its bundle, from the
    problem the reading worker saved (`read_file`).

    Parameters
    ----------
    parsed : the saved problem (its construction for k the one the item was planned with).
    k : harmonics.
    progress : None, or a callable given the harmonics done.

    Returns
    -------
    (basis, bundle bytes): the basis without its mesh's look (the server's item has it).
    """
    problem = HarmonicProblem.load(parsed)
    basis = problem.basis(k, progress)
    return basis, basis_bundle(basis, problem.mesh.name)
