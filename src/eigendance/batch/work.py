"""What a batch's workers run, on any engine (docs/design.md#batch).

Four tasks: `prepare_model` (a mesh's basis through the content cache, or a rig's modal analysis
and modal skin), `prepare_song` (the spectrogram and the rhythm, through the content cache),
`prepare_gallery` (the initial gallery of a model on a song) and `make_outputs` (one job: the
dance of a model, a song and a mapping, written in each format). Each is called through `task`,
which gives the worker one thread for numbers and one for drawing (a batch runs one task per
core), points the content cache where the driver says, and turns every failure into one line, so
a task never raises: it returns (report, value). The report holds the task's seconds, the
worker's memory and, for a job, the files written with their sizes and SHA-256.
"""

from __future__ import annotations

import os
import resource
import time
from dataclasses import replace

import numpy as np
from threadpoolctl import threadpool_limits

from eigendance.batch.plan import FORMATS
from eigendance.batch.record import file_entry
from eigendance.errors import EigendanceError, InputError, one_line
from eigendance.export.dance import HarmonicDance
from eigendance.export.files import export_dance
from eigendance.export.renderer import Look
from eigendance.export.rig_dance import rig_dance
from eigendance.export.video import render_video
from eigendance.harmonic.cache import DiskCache
from eigendance.harmonic.motion import write_animation
from eigendance.inputs.model import read_model
from eigendance.inputs.song import read_song
from eigendance.modal.motion import save_animation
from eigendance.modal.rig import Rig
from eigendance.modal.rig_gallery import rig_gallery
from eigendance.modal.surface import SurfaceDance
from eigendance.music.gallery import initial_gallery, strongest_item
from eigendance.music.mapping import Mapping
from eigendance.music.spectrogram import Spectrogram, frame_times
from eigendance.window import Window

SPECTROGRAM_VERSION = 2  # part of a cached spectrogram's key (2: with the rhythm)


def setup_worker() -> None:
    """In a worker, before any task: one BLAS/OpenMP thread and one llvmpipe thread (the engine
    runs one task per core)."""
    for name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS",
                 "LP_NUM_THREADS"):
        os.environ[name] = "1"
    threadpool_limits(1)


def task(function, *arguments, cache: str | None = None):
    """Run `function(*arguments)` as a batch task: never raises.

    Parameters
    ----------
    function : one of the tasks of this module.
    *arguments : its arguments.
    cache : the content cache's folder (None: this process's default).

    Returns
    -------
    (report, value): report {"error": one line or None, "kind": "input" | "internal" | None,
    "seconds", "memory", "pid"} updated with what the function reports; value the function's
    result
    (None after an error).
    """
    if cache is not None:
        os.environ["EIGENDANCE_CACHE_DIR"] = cache
    began = time.perf_counter()
    report = {"error": None, "kind": None}
    value = None
    try:
        value = function(*arguments)
        if isinstance(value, dict) and "report" in value:
            report.update(value.pop("report"))
    except InputError as error:
        report.update(error=str(error), kind="input")
    except MemoryError:
        report.update(error="out of memory", kind="input")
    except EigendanceError as error:
        report.update(error=f"internal error, a bug to report: {error}", kind="internal")
    except Exception as error:  # noqa: BLE001 - every failure of a task is one line
        report.update(error=f"internal error, a bug to report: {type(error).__name__}: "
                            f"{one_line(error)}", kind="internal")
    report["seconds"] = time.perf_counter() - began
    report["memory"] = memory()
    report["pid"] = os.getpid()
    return report, value


def memory() -> dict:
    """This process's memory now: resident (RSS), proportional (PSS: shared pages divided among
    the processes sharing them) and the peak resident, in MB.

    Returns
    -------
    {"rss_mb", "pss_mb", "peak_rss_mb"} (PSS None where /proc has no smaps_rollup).
    """
    values = {"rss_mb": None, "pss_mb": None}
    try:
        with open("/proc/self/smaps_rollup", encoding="ascii") as file:
            for line in file:
                name, _, rest = line.partition(":")
                if name in ("Rss", "Pss"):
                    values[f"{name.lower()}_mb"] = int(rest.split()[0]) / 1024
    except OSError:
        pass
    values["peak_rss_mb"] = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    return values


def prepare_model(path: str, kind: str, k: int, construction: str = "auto",
                  samples: int | None = None):
    """A model's basis (a mesh, through the content cache) or rig (modal analysis and skin).

    Parameters
    ----------
    path : the model file, or a built-in rig's name.
    kind : "mesh" or "rig".
    k : harmonics of a mesh.
    construction, samples : a mesh's basis, "auto" (the rule), "exact" or "reduced", and a
        reduced one's samples (None: the default count).

    Returns
    -------
    HarmonicBasis or Rig (float64, as the exports use it).
    """
    if kind == "mesh":
        model = read_model(path, kind=kind, construction=construction, samples=samples)
        return model.problem.basis(k)
    rig = Rig(read_model(path, kind=kind).skeleton, np.float64)
    if rig.model.n_modes == 0:
        raise InputError(f"{rig.skeleton.name}: the rig has no vibration mode (no elastic "
                         "joint); nothing to move")
    rig.skin  # noqa: B018 - the modal skin, made once here and shared
    return rig


def prepare_song(path: str, digest: str, bands: int, rhythm_of: Spectrogram | None = None
                 ) -> Spectrogram:
    """A song's spectrogram of `bands` bands with its rhythm, through the content cache (folder
    `spectrograms`, keyed by the song's SHA-256 and the analysis).

    The rhythm (onsets, beats, tempo: docs/design.md#rhythm) does not depend on the bands: a
    song asked at a second band count takes it from `rhythm_of`, its spectrogram at the first,
    so the rhythm is analysed once per song.

    Parameters
    ----------
    path : the audio file.
    digest : its SHA-256 (`files.file_digest`).
    bands : bands.
    rhythm_of : the same song's spectrogram at another band count, or None (analyse it here).

    Returns
    -------
    Spectrogram, its `rhythm` set.
    """
    cache = DiskCache("spectrograms")
    entry = cache.path(f"eigendance.spectrogram audio={digest} bands={bands} "
                       f"version={SPECTROGRAM_VERSION}")
    if os.path.isfile(entry):
        try:
            spectrogram = Spectrogram.load(entry)
            if spectrogram.rhythm is not None:
                return spectrogram
        except InputError:
            pass  # damaged: made again
    if rhythm_of is not None and rhythm_of.rhythm is not None:
        spectrogram = replace(read_song(path, bands, rhythm=False),
                              rhythm=rhythm_of.rhythm)
    else:
        spectrogram = read_song(path, bands)
    try:
        spectrogram.save(entry)
    except InputError:
        pass  # an unwritable cache only costs the speed-up
    return spectrogram


def prepare_gallery(model, spectrogram: Spectrogram, size: int) -> list[Mapping]:
    """The initial gallery of `size` items of a model (basis or rig) on a song.

    Parameters
    ----------
    model : HarmonicBasis or Rig (`prepare_model`).
    spectrogram : the song's.
    size : items.

    Returns
    -------
    list of Mapping.
    """
    if isinstance(model, Rig):
        return rig_gallery(model.dancer(band_edges=spectrogram.band_edges), spectrogram, size)
    return initial_gallery(model, spectrogram, size)


def make_outputs(job: dict, model, spectrogram: Spectrogram, mapping, index=None) -> dict:
    """One job: the dance of a model on a song with a mapping, written in each format asked.

    Parameters
    ----------
    job : {"stem", "out", "formats", "song", "fps", "size", "start", "duration"} (the
        driver's description of the job).
    model : HarmonicBasis or Rig.
    spectrogram : the song's (as many bands as the mapping).
    mapping : a Mapping, or a gallery (list of Mapping) whose item `index` plays.
    index : the gallery's item, or None.

    Returns
    -------
    {"report": {"outputs": {format: {file name: `record.file_entry`}}, "times": {format: wall
    s}, "cpu": {format: CPU s, the encoder's included}, "note": the window's note or None}}.
    """
    if index is not None:
        mapping = mapping[index]
    dance = _dance(job, model, spectrogram, mapping)
    outputs, times, cpu = {}, {}, {}
    for format in job["formats"]:
        began, used = time.perf_counter(), cpu_seconds()
        path = os.path.join(job["out"], job["stem"] + FORMATS[format])
        files = _write(format, path, job, dance, model, spectrogram, mapping)
        outputs[format] = {os.path.basename(file): file_entry(file) for file in files}
        times[format], cpu[format] = time.perf_counter() - began, cpu_seconds() - used
    return {"report": {"outputs": outputs, "times": times, "cpu": cpu, "note": dance.note}}


def cpu_seconds() -> float:
    """CPU time of this process and of the children it waited for (the video encoder), s.

    Returns
    -------
    float.
    """
    mine, children = (resource.getrusage(who) for who in (resource.RUSAGE_SELF,
                                                            resource.RUSAGE_CHILDREN))
    return mine.ru_utime + mine.ru_stime + children.ru_utime + children.ru_stime


def _dance(job: dict, model, spectrogram, mapping):
    """The windowed dance of a job (`export.dance`)."""
    if isinstance(model, Rig):
        mapping = model.mapping(spectrogram, mapping)
        dance = rig_dance(model, spectrogram, mapping, "modal", job["song"], job["stem"],
                          surface=job_surface(job, model, spectrogram, mapping))
    else:
        dance = HarmonicDance(model, spectrogram, mapping, job["song"], job["stem"])
    return dance.window(job["start"], job["duration"])


def job_surface(job: dict, rig: Rig, spectrogram, mapping=None) -> SurfaceDance | None:
    """The rig's rippling skin a job asks for (the plan's `surface`, else the surface genes of
    its mapping), or None.

    Parameters
    ----------
    job : the job's description ("surface": a Mapping, "auto" or None).
    rig : the rig.
    spectrogram : the song (the surface mapping must have its bands).
    mapping : the job's mapping (its `surface` genes), or None.

    Returns
    -------
    SurfaceDance or None.
    """
    surface = job.get("surface") or (None if mapping is None else mapping.surface)
    if surface is None:
        return None
    harmonics = rig.surface()
    if surface == "auto":
        surface = strongest_item(harmonics.basis, spectrogram)
    return SurfaceDance(harmonics, spectrogram, surface)


def _write(format: str, path: str, job: dict, dance, model, spectrogram, mapping) -> list[str]:
    """Write one format of a job; the files written (the main one first)."""
    if format == "mp4":
        look = Look(mapping.shading, mapping.deformed_normal_weight)
        render_video(path, [dance], [look], job["song"], job["fps"], job["size"], force=True,
                     workers=1)
        return [path]
    if format == "npz":
        _write_animation(path, dance, model, spectrogram, mapping, job["fps"])
        return [path]
    files = export_dance(dance, path, format, job["fps"], force=True)["files"]
    song = os.path.splitext(path)[0] + os.path.splitext(job["song"])[1].lower()
    if os.path.isfile(song) and song not in files:  # an earlier format's copy, kept
        files.append(song)
    return files


def _write_animation(path: str, dance, model, spectrogram, mapping, fps: float) -> None:
    """The animation file of a dance's window (`harmonic.motion`, `Rig.animation`)."""
    window = Window(dance.start, dance.duration)
    if isinstance(model, Rig):
        mapping = model.mapping(spectrogram, mapping)
        times = frame_times(window.duration, fps)
        coefficients = model.coefficients(spectrogram, mapping, window.start + times)
        ripple = None if dance.surface is None else \
            (lambda first, stop: dance.ripple(times[first:stop]))
        save_animation(path, model.animation(times, coefficients, model.palette_of(mapping),
                                             surface=ripple))
    else:
        write_animation(path, model, spectrogram, mapping, fps, window=window)
