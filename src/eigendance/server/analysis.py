"""The analysis of the library's files, as run in the server's worker processes
(`server.workers.run`, docs/design.md#server).

Each function takes and returns picklable values only: what a file holds (a cleaned mesh, a
skeleton) or what the page is sent (a rig's analysis, a basis, with their bundles). Reading a
mesh or a rig's glTF, a rig's modal analysis, a basis's solve and their bundles are mostly pure
Python or hold the interpreter's lock in C; in a worker process they never make the event loop
wait. A song is decoded (`read_song`) in a worker process too, after its length is read from
its header (`song_seconds`, nothing decoded) so that the library charges the spectrogram's
bytes (`song_bytes`) before it is made: a native decoder that crashes takes only its worker
down, and a one-hour take no longer holds the server's interpreter lock. librosa's numba
kernels are compiled once, by the fork server (`music.compiled`), not by every worker.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import soundfile

from eigendance.errors import EigendanceError, InputError, one_line
from eigendance.files import read_json, suffix_of
from eigendance.harmonic.basis import HarmonicBasis
from eigendance.harmonic.laplacian import laplacian_for
from eigendance.harmonic.mesh import Mesh, load_mesh
from eigendance.modal.gltf_skin import has_skin
from eigendance.modal.rig import Rig
from eigendance.modal.sample_rigs import load_rig, sample_rig
from eigendance.modal.skeleton import Skeleton
from eigendance.music.analyser import BANDS, RATE
from eigendance.music.decode import SOUNDFILE_MAGIC, SOUNDFILE_SUFFIXES
from eigendance.music.spectrogram import Spectrogram
from eigendance.server.binary import basis_bundle, rig_bundle, spectrogram_bundle


def classify(path: str, name: str, kind: str) -> tuple[str, object]:
    """A file's kind by its content: a skeleton JSON is a rig, any other JSON a mapping (its
    document returned); a skinned glTF is a rig (its skin the mesh the modes move).

    Parameters
    ----------
    path : the file.
    name : its name (its suffix).
    kind : its kind by suffix (`files.kind_of`).

    Returns
    -------
    (kind, document): the mapping's parsed JSON, else None.
    """
    if kind == "mapping":
        document = read_json(path, name)
        if isinstance(document, dict) and document.get("format") == "eigendance.skeleton":
            return "rig", None
        return "mapping", document
    if kind == "mesh" and suffix_of(name) in (".glb", ".gltf") and has_skin(path):
        return "rig", None
    return kind, None


def read_mesh(path: str, name: str) -> tuple[Mesh, str]:
    """A mesh file read and cleaned (`load_mesh`), and the Laplacian its basis takes.

    Parameters
    ----------
    path : the mesh file.
    name : how the page calls it.

    Returns
    -------
    (mesh, laplacian): the `Mesh` named `name` and `laplacian.laplacian_for` it.
    EigendanceError when the file cannot be read.
    """
    mesh = dataclasses.replace(load_mesh(path), name=name)
    return mesh, laplacian_for(mesh)


def read_rig(source: str, name: str, built_in: bool = False) -> Skeleton:
    """A rig's skeleton with its skin: a file (skeleton JSON or skinned glTF) or a built-in rig.

    Parameters
    ----------
    source : the file, or the built-in rig's name.
    name : how the page calls it.
    built_in : whether `source` names a built-in rig (`sample_rig`).

    Returns
    -------
    Skeleton; InputError when it is not a rig that can be analysed.
    """
    return sample_rig(source) if built_in else load_rig(source, name)


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
    """A song decoded into its spectrogram, and its bundle for the page.

    Parameters
    ----------
    path : the audio file.
    name : its name.
    options : those of `Spectrogram.from_file`.

    Returns
    -------
    (spectrogram, bundle bytes); InputError when the audio cannot be decoded.
    """
    try:
        spectrogram = Spectrogram.from_file(path, **options)
    except EigendanceError:
        raise
    except Exception as error:  # noqa: BLE001 - decoders raise many types
        raise InputError(f"{name}: cannot decode the audio ({one_line(error)})") from None
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


def solve_basis(mesh: Mesh, k: int, laplacian: str, construction: str,
                progress=None) -> tuple[HarmonicBasis, bytes]:
    """A mesh's basis (`HarmonicBasis.from_mesh`, with its disk cache) and its bundle.

    Parameters
    ----------
    mesh : the cleaned mesh (its name names the bundle).
    k : harmonics.
    laplacian : "cotan" or "robust".
    construction : "exact" or "reduced".
    progress : None, or a callable given the harmonics done.

    Returns
    -------
    (basis, bundle bytes).
    """
    basis = HarmonicBasis.from_mesh(mesh, k, laplacian=laplacian, construction=construction,
                                    progress=progress)
    return basis, basis_bundle(basis, mesh.name)
