"""The driver of a batch: what is left to make, the tasks in order, the record and the report
(docs/design.md#batch).

`run_plan` refuses a plan whose outputs would collide or replace an input (`outputs`), hashes
the inputs (`content`), finds the outputs the record already holds complete,
refuses to overwrite files it did not write (unless forced), then runs the rest on an engine:
each model prepared once (its basis or rig), each song once per band count (its spectrogram),
each (model, song) gallery once, then the jobs, each as soon as its inputs are ready — songs in
the plan's order, so that a song's prepared inputs are released once its jobs are done. A
prepared input that fails fails its jobs with its one line, said once; a job that fails is said
once; the others go on. Every complete output is recorded at once; Ctrl-C stops the engine,
removes the temporary files and still writes the report and the record.
"""

from __future__ import annotations

import heapq
import os
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field

from eigendance.batch.content import (
    file_digest,
    item_identity,
    item_key,
    model_digest,
    output_key,
)
from eigendance.batch.engines import Task
from eigendance.batch.outputs import check_outputs, written_names
from eigendance.batch.plan import FORMATS, Job, Plan
from eigendance.batch.record import Record, write_report
from eigendance.errors import InputError
from eigendance.writes import sweep_temporary_files

DEFAULT_BANDS = 64  # the gallery's spectrogram


class Input(tuple):
    """The name of a prepared input among a task's arguments: ("model", path), ("song", path,
    bands) or ("gallery", model path, song path, size); the engine's handle replaces it."""


@dataclass
class Pending:
    """A job and what it has left to make.

    Parameters
    ----------
    index : its place in the plan's jobs.
    job : the job.
    keys : {format still to make: its output key}.
    complete : the formats the record holds complete.
    """

    index: int
    job: Job
    keys: dict[str, str]
    complete: list[str]


@dataclass
class Outcome:
    """What a run did.

    Parameters
    ----------
    lines : one report line per job.
    kinds : the kinds of the failures ("input", "internal", "crash").
    seconds : the run's wall time.
    report : the report's path.
    interrupted : Ctrl-C stopped it.
    prepared : {"model" | "song" | "gallery": worker seconds preparing them}.
    """

    lines: list[dict] = field(default_factory=list)
    kinds: set = field(default_factory=set)
    seconds: float = 0.0
    report: str = ""
    interrupted: bool = False
    prepared: dict = field(default_factory=dict)

    def count(self, status: str) -> tuple[int, int]:
        """How many jobs and outputs ended so.

        Parameters
        ----------
        status : "done", "skipped", "failed" or "interrupted" (the skipped outputs of jobs that
            made others count as skipped).

        Returns
        -------
        (jobs, outputs).
        """
        jobs = sum(line["status"] == status for line in self.lines)
        if status == "skipped":
            return jobs, sum(len(line["skipped"]) for line in self.lines)
        if status == "done":
            return jobs, sum(len(line["outputs"]) for line in self.lines)
        return jobs, sum(len(line["planned"]) for line in self.lines
                         if line["status"] == status)


def digests(plan: Plan) -> dict[str, str]:
    """The content digest of every model, song and item of a plan, read in parallel.

    Parameters
    ----------
    plan : the plan.

    Returns
    -------
    {path (or an item's `item_key`): digest}.
    """
    with ThreadPoolExecutor(4) as pool:  # hashlib and reads release the GIL
        models = pool.map(model_digest, plan.models)
        songs = pool.map(file_digest, [song.path for song in plan.songs])
        items = pool.map(item_identity, plan.items)
        return {**dict(zip([model.path for model in plan.models], models, strict=True)),
                **dict(zip([song.path for song in plan.songs], songs, strict=True)),
                **dict(zip([item_key(item) for item in plan.items], items, strict=True))}


def pending_jobs(plan: Plan, record: Record, found: dict[str, str]) -> list[Pending]:
    """Every job with what it has left to make (nothing: up to date).

    Parameters
    ----------
    plan : the plan.
    record : the output folder's record.
    found : `digests(plan)`.

    Returns
    -------
    list of Pending, in the plan's order.
    """
    result = []
    for index, job in enumerate(plan.jobs()):
        keys, complete = {}, []
        for format in plan.outputs:
            key = output_key(plan, job, format, found)
            if record.complete(job.stem + FORMATS[format], key):
                complete.append(format)
            else:
                keys[format] = key
        result.append(Pending(index, job, keys, complete))
    return result


def check_foreign(plan: Plan, pending: list[Pending], record: Record, force: bool) -> None:
    """InputError, before any work, for a file in the way of an output that no batch wrote
    there (unless `force`).

    Parameters
    ----------
    plan, pending, record : the run.
    force : overwrite such files.
    """
    if force:
        return
    for each in pending:
        for name in {name for format in each.keys for name in written_names(each.job, format)}:
            if os.path.exists(os.path.join(plan.out, name)) and not record.ours(name):
                raise InputError(f"{os.path.join(plan.out, name)} exists and was not written "
                                 "by a batch", remedy={"force": True})


def run_plan(plan: Plan, engine_factory, observer, force: bool = False,
             dry_run: bool = False) -> Outcome:
    """Run a plan (module docstring).

    Parameters
    ----------
    plan : a checked plan (`plan.read_plan`).
    engine_factory : () → engine (`engines.LocalEngine`, `engines.RayEngine`), made only when
        there is work.
    observer : told what happens: start(total, skipped, engine description or None),
        job(line), failure(message), planned(pending) for a dry run.
    force : overwrite files in the way that no batch wrote.
    dry_run : only say what would be made.

    Returns
    -------
    Outcome (its report written to out/batch-report.jsonl, unless a dry run); after Ctrl-C,
    what was done, `interrupted` set.
    """
    began = time.perf_counter()
    outcome = Outcome()
    check_outputs(plan)  # no two outputs of one name, none over an input, --force or not
    found = digests(plan)
    with Record(plan.out) as record:
        pending = pending_jobs(plan, record, found)
        if dry_run:
            observer.planned(pending)
            return outcome
        check_foreign(plan, pending, record, force)
        sweep_temporary_files(plan.out, fresh=0.0)  # a killed run's debris
        todo = [each for each in pending if each.keys]
        # Claimed before any is made: an output a worker finished just before Ctrl-C, not yet
        # recorded, is the batch's own file for the next run (made again, without --force).
        record.claim({each.job.stem + FORMATS[format]: written_names(each.job, format)
                      for each in todo for format in each.keys})
        for each in pending:
            if not each.keys:
                outcome.lines.append(_line(each, "skipped"))
        engine = engine_factory() if todo else None
        observer.start(len(pending), len(pending) - len(todo),
                       engine.describe() if engine else None)
        interrupted = True
        try:
            if engine is not None:
                Scheduler(plan, engine, record, observer, outcome).run(todo, found)
            interrupted = False
        except KeyboardInterrupt:
            outcome.interrupted = True
        finally:
            if engine is not None:
                engine.close(interrupted)
            sweep_temporary_files(plan.out, fresh=0.0)  # our workers are gone: none is ours
            done = {line["job"] for line in outcome.lines}
            outcome.lines += [_line(each, "interrupted") for each in todo
                              if each.job.stem not in done]
            outcome.lines.sort(key=lambda line: line["index"])
            outcome.seconds = time.perf_counter() - began
            outcome.report = write_report(plan.out, outcome.lines)
    return outcome


def _line(each: Pending, status: str, **more) -> dict:
    """A report line of a job."""
    job = each.job
    planned = [job.stem + FORMATS[format] for format in each.keys]
    return {"index": each.index, "job": job.stem, "model": job.model.path,
            "song": job.song.path, "item": job.item.name, "status": status,
            "outputs": planned if status == "done" else [], "planned": planned,
            "skipped": [job.stem + FORMATS[f] for f in each.complete], **more}


class Scheduler:
    """Runs the pending jobs and what they need on an engine (module docstring).

    Parameters
    ----------
    plan, engine, record, observer, outcome : the run.
    """

    def __init__(self, plan: Plan, engine, record: Record, observer, outcome: Outcome):
        self.plan, self.engine, self.record = plan, engine, record
        self.observer, self.outcome = observer, outcome
        self.ready: list = []  # heap of (priority, sequence, task)
        self.values: dict = {}  # prepared input → handle
        self.waiting: dict = {}  # prepared input → tasks waiting for it
        self.users: dict = {}  # prepared input → jobs that will use it
        self.failed: dict = {}  # prepared input → its error
        self.known: set = set()  # prepared inputs asked for
        self.songs: dict = {}  # song path → its first prepared input (the rhythm's)
        self.sequence = 0

    def run(self, todo: list[Pending], found: dict[str, str]) -> None:
        """Run every pending job (and its inputs) to its end.

        Parameters
        ----------
        todo : the jobs with something to make.
        found : `digests` of the plan.
        """
        for each in todo:
            self.add_job(each, found)
        while self.ready or self.engine.running:
            while self.ready and len(self.engine.running) < self.engine.slots:
                self.engine.submit(heapq.heappop(self.ready)[2])
            for task, report, handle in self.engine.finished(timeout=None):
                if task.extra["what"] == "job":
                    self.finish_job(task, report)
                else:
                    self.prepared(task, report, handle)

    # --- the graph: inputs prepared once, jobs when their inputs are ready --------------------
    def add_job(self, each: Pending, found: dict[str, str]) -> None:
        """Schedule a job after its inputs (asked for once: its model, its song at the
        mapping's bands, its gallery).

        Parameters
        ----------
        each : the job.
        found : `digests` of the plan.
        """
        job, plan = each.job, self.plan
        bands = job.item.mapping.bands if job.item.mapping is not None else DEFAULT_BANDS
        model = Input(("model", job.model.path))
        song = Input(("song", job.song.path, bands))
        self.prepare(model, "prepare_model", (job.model.path, job.model.kind, plan.k,
                                               plan.construction, plan.samples), each.index, [])
        first = self.songs.setdefault(job.song.path, song)  # its rhythm, for other bands
        self.prepare(song, "prepare_song", (job.song.path, found[job.song.path], bands) +
                     ((first,) if first != song else ()), each.index,
                     [first] if first != song else [])
        inputs = [model, song]
        if job.item.gallery is not None:
            gallery = Input(("gallery", job.model.path, job.song.path, job.item.gallery))
            self.prepare(gallery, "prepare_gallery", (model, song, job.item.gallery),
                         each.index, [model, song])
            inputs.append(gallery)
        spec = {"stem": job.stem, "out": plan.out, "formats": list(each.keys),
                "song": job.song.path, "fps": plan.fps, "size": plan.size,
                "start": plan.start, "duration": plan.duration,
                "surface": plan.surface if job.model.kind == "rig" else None}
        mapping = inputs[2] if job.item.gallery is not None else job.item.mapping
        task = Task(job.stem, "make_outputs", (spec, model, song, mapping, job.item.index),
                    extra={"what": "job", "pending": each, "inputs": inputs})
        for name in inputs:
            self.users[name] = self.users.get(name, 0) + 1
        self.schedule(task, (each.index, 1), inputs)

    def prepare(self, name: Input, function: str, arguments: tuple, index: int,
                inputs: list) -> None:
        """Schedule a prepared input, unless it was asked for already.

        Parameters
        ----------
        name : the input.
        function : the task's function (`batch.work`).
        arguments : its arguments.
        index : the first job needing it (its priority).
        inputs : the inputs it needs itself.
        """
        if name in self.known:
            return
        self.known.add(name)
        what = {"model": "preparing", "song": "analysing", "gallery": "gallery of"}[name[0]]
        label = f"{what} {os.path.basename(name[1])}" + \
            (f" on {os.path.basename(name[2])}" if name[0] == "gallery" else "")
        task = Task(label, function, arguments, keep=True, extra={"what": name, "inputs": inputs})
        for needed in inputs:
            self.users[needed] = self.users.get(needed, 0) + 1
        self.schedule(task, (index, 0), inputs)

    def schedule(self, task: Task, priority: tuple, inputs: list) -> None:
        """Make a task ready when its inputs are (at once if they are; failed if one failed).

        Parameters
        ----------
        task : the task.
        priority : (first job's index, 0 for an input or 1 for a job): lowest first.
        inputs : the inputs it needs.
        """
        self.sequence += 1
        task.extra["priority"] = (priority, self.sequence)
        missing = [name for name in inputs if name not in self.values]
        failed = [name for name in missing if name in self.failed]
        if failed:
            self.fail(task, self.failed[failed[0]])
        elif not missing:
            self.push(task)
        else:
            task.extra["missing"] = set(missing)
            for name in missing:
                self.waiting.setdefault(name, []).append(task)

    def push(self, task: Task) -> None:
        """A task whose inputs are ready: their handles in its arguments, in the ready queue.

        Parameters
        ----------
        task : the task.
        """
        task.arguments = tuple(self.values[value] if isinstance(value, Input) else value
                               for value in task.arguments)
        heapq.heappush(self.ready, (task.extra["priority"], self.sequence, task))

    def prepared(self, task: Task, report: dict, handle, quiet: bool = False) -> None:
        """A prepared input is ready, or failed: its waiting tasks go on, or fail.

        Parameters
        ----------
        task : the input's task.
        report : its report.
        handle : its value's handle (None after a failure).
        quiet : its failure comes from its own input's, said already.
        """
        name = task.extra["what"]
        if not quiet:
            self.outcome.prepared[name[0]] = self.outcome.prepared.get(name[0], 0.0) + \
                (report["seconds"] or 0.0)
        if report["error"]:
            self.failed[name] = report
            if not quiet:
                self.outcome.kinds.add(report["kind"])
                count = self.users.get(name, 0)
                self.observer.failure(f"{report['error']} ({count} job{'s' * (count != 1)} "
                                      "not made)")
        else:
            self.values[name] = handle
        self.done_with(task.extra["inputs"])
        for waiting in self.waiting.pop(name, []):
            if report["error"]:
                self.fail(waiting, report)
            else:
                waiting.extra["missing"].discard(name)
                if not waiting.extra["missing"]:
                    self.push(waiting)

    def fail(self, task: Task, report: dict) -> None:
        """A task whose input failed: a job fails with that error (said once, by `prepared`); a
        prepared input fails in turn. A task waiting for two failed inputs fails once.

        Parameters
        ----------
        task : the task.
        report : the failed input's report.
        """
        if task.extra.get("failed"):
            return
        task.extra["failed"] = True
        if task.extra["what"] == "job":
            self.finish_job(task, {**report, "seconds": None, "memory": None}, quiet=True)
        else:
            self.prepared(task, report, None, quiet=True)

    def finish_job(self, task: Task, report: dict, quiet: bool = False) -> None:
        """A job ended: its outputs recorded, its line reported, the inputs nobody needs any
        more released.

        Parameters
        ----------
        task : the job's task.
        report : its report.
        quiet : a failure said already (its input's).
        """
        each: Pending = task.extra["pending"]
        if report["error"] is None:
            for format, files in report["outputs"].items():
                self.record.add(each.job.stem + FORMATS[format], each.keys[format], files)
            line = _line(each, "done", seconds=report["seconds"], times=report["times"],
                         cpu=report["cpu"],
                         attempts=task.attempts, memory=report["memory"], note=report["note"],
                         pid=report["pid"])
        else:
            if not quiet:
                self.outcome.kinds.add(report["kind"])
            line = _line(each, "failed", error=report["error"], kind=report["kind"],
                         attempts=task.attempts, seconds=report["seconds"],
                         memory=report["memory"])
        self.outcome.lines.append(line)
        self.observer.job(line, quiet)
        self.done_with(task.extra["inputs"])

    def done_with(self, inputs: list) -> None:
        """A task that needed these inputs has ended: those no task needs any more are
        released.

        Parameters
        ----------
        inputs : the prepared inputs the task needed.
        """
        for name in inputs:
            self.users[name] -= 1
            if self.users[name] == 0 and name in self.values:
                self.engine.release(self.values.pop(name))
