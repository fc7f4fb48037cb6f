"""The `batch` command: a plan of many songs × many models, on local processes or Ray
(docs/design.md#batch)."""

from __future__ import annotations

import argparse
import os
import sys

from tqdm import tqdm

from eigendance.batch.engines import LocalEngine, RayEngine
from eigendance.batch.plan import EXAMPLE, read_plan
from eigendance.batch.run import run_plan
from eigendance.cli.options import number, progress_bar, say_note
from eigendance.cli.presets import add_preset_options, preset_items
from eigendance.errors import InputError, InternalError
from eigendance.harmonic.cache import cache_folder

# What --help says after the example plan.
AFTER = """
A second run makes only what is missing, changed or altered (out/batch-record.jsonl); each
job's status, times and outputs: out/batch-report.jsonl. Exit status 0; 1 when a job failed on
its input; 2 on an internal failure; 130 after Ctrl-C (what was finished stays finished).
"""


def add_batch(parser):
    """The options of `eigendance batch` (its --help ends with an example plan).

    Parameters
    ----------
    parser : the command's parser.
    """
    parser.formatter_class = argparse.RawDescriptionHelpFormatter
    parser.epilog = "An example plan:\n\n" + EXAMPLE + AFTER
    parser.add_argument("plan", help="the plan (TOML): models, songs, outputs, gallery or "
                                     "mappings, out (see below)")
    parser.add_argument("-j", "--jobs", type=number(1, 4096, integer=True), default=None,
                        help="tasks at once: local worker processes, or a local Ray's CPUs "
                             "(default: the CPUs this process may use)")
    parser.add_argument("--ray", nargs="?", const="local", metavar="ADDRESS",
                        help="run on Ray (pip install 'eigendance[ray]'): alone, a local Ray "
                             "started for the batch; 'auto' or ADDRESS (host:port, "
                             "ray://host:10001) joins a running cluster")
    parser.add_argument("-v", "--verbose", action="store_true", help="a line per job")
    parser.add_argument("-n", "--dry-run", action="store_true",
                        help="list the jobs and what each would make; make nothing")
    parser.add_argument("--force", action="store_true",
                        help="overwrite files in the way of outputs that no batch wrote")
    add_preset_options(parser)


class Console:
    """What a batch says on the terminal: one progress bar over the jobs (stderr), a line per
    failure, a line per job with --verbose.

    Parameters
    ----------
    verbose : a line per job.
    """

    def __init__(self, verbose: bool):
        self.verbose, self.bar, self.update, self.done = verbose, None, None, 0

    def start(self, total: int, skipped: int, engine: str | None) -> None:
        """The run starts: the engine's line (with Ray, its dashboard) and the bar.

        Parameters
        ----------
        total : jobs in the plan.
        skipped : those up to date.
        engine : the engine in words (None: nothing to do).
        """
        if engine is None:
            return
        print(f"eigendance: {total - skipped} of {total} jobs to make on {engine}",
              file=sys.stderr)
        self.bar, self.update = progress_bar(total, "jobs", unit="job", initial=skipped)
        self.done = skipped

    def job(self, line: dict, quiet: bool) -> None:
        """A job ended: its failure said (once), with --verbose its outputs.

        Parameters
        ----------
        line : its report line.
        quiet : its failure was said already (its input's).
        """
        self.done += 1
        if line["status"] == "failed" and not quiet:
            self.say(f"eigendance: error: {line['job']}: {line['error']}")
        elif self.verbose and line["status"] == "done":
            retried = f", attempt {line['attempts']}" if (line["attempts"] or 1) > 1 else ""
            self.say(f"{line['job']}: {', '.join(line['outputs'])} ({line['seconds']:.1f} s"
                     f"{retried})")
        if self.update is not None:
            self.update(self.done)

    def failure(self, message: str) -> None:
        """A prepared input failed: said once for all its jobs.

        Parameters
        ----------
        message : the error's line.
        """
        self.say(f"eigendance: error: {message}")

    def planned(self, pending) -> None:
        """A dry run: each job and what it would make.

        Parameters
        ----------
        pending : `batch.run.Pending` of every job.
        """
        for each in pending:
            what = ", ".join(each.keys) if each.keys else "up to date"
            print(f"{each.job.stem}: {what}")
        left = sum(bool(each.keys) for each in pending)
        print(f"{left} of {len(pending)} jobs to make")

    def say(self, text: str) -> None:
        """A line on stderr, above the bar.

        Parameters
        ----------
        text : the line.
        """
        tqdm.write(text, file=sys.stderr)

    def close(self) -> None:
        """Remove the bar."""
        if self.bar is not None:
            self.bar.close()


PREPARED = {"model": "models", "song": "songs", "gallery": "galleries"}  # the summary's words


def summary(outcome) -> list[str]:
    """The table printed at the end: jobs and outputs done, up to date, failed (interrupted),
    the time, the throughput and the workers' memory.

    Parameters
    ----------
    outcome : `batch.run.Outcome`.

    Returns
    -------
    list of lines.
    """
    lines = [f"{'':<12}{'jobs':>7}{'outputs':>9}"]
    for status, label in (("done", "done"), ("skipped", "up to date"), ("failed", "failed"),
                          ("interrupted", "interrupted")):
        jobs, outputs = outcome.count(status)
        if status != "interrupted" or jobs:
            lines.append(f"{label:<12}{jobs:>7}{outputs:>9}")
    done = [line for line in outcome.lines if line["status"] == "done"]
    work = sum(line["seconds"] for line in done)
    rate = f", {len(done) / outcome.seconds * 60:.1f} jobs/min" if done else ""
    preparing = ", ".join(f"{PREPARED[what]} {format_seconds(seconds)}" for what, seconds in
                          sorted(outcome.prepared.items()))
    lines.append(f"time: {format_seconds(outcome.seconds)}{rate}; jobs took "
                 f"{format_seconds(work)} of worker time"
                 + (f", preparing {preparing}" if preparing else ""))
    memory = [line["memory"] for line in done if line.get("memory")]
    if memory:
        peak = max(entry["peak_rss_mb"] for entry in memory)
        pss = [entry["pss_mb"] for entry in memory if entry["pss_mb"] is not None]
        shared = f", {max(pss):.0f} MB proportional (shared pages divided)" if pss else ""
        lines.append(f"worker memory: at most {peak:.0f} MB resident{shared}")
    lines.append(f"report: {outcome.report}")
    return lines


def format_seconds(seconds: float) -> str:
    """A duration as the summary writes it.

    Parameters
    ----------
    seconds : s.

    Returns
    -------
    str.

    Example
    -------
    >>> format_seconds(3725), format_seconds(185), format_seconds(12.34)
    ('1 h 02 min', '3 min 05 s', '12.3 s')
    """
    if seconds >= 3600:
        return f"{int(seconds // 3600)} h {int(seconds % 3600 // 60):02d} min"
    if seconds >= 60:
        return f"{int(seconds // 60)} min {int(seconds % 60):02d} s"
    return f"{seconds:.1f} s"


def engine_factory(args, plan):
    """The engine `--ray` and `-j` ask for, made only when there is work.

    Parameters
    ----------
    args : the parsed command line.
    plan : the plan (its cache folder).

    Returns
    -------
    callable() → LocalEngine or RayEngine.
    """
    cache = plan.cache or cache_folder()
    if args.ray:
        return lambda: RayEngine(args.ray, args.jobs, cache)
    workers = args.jobs or (len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity")
                            else os.cpu_count() or 1)
    return lambda: LocalEngine(workers, cache)


def run_batch(args) -> None:
    """`eigendance batch`: run a plan; a summary at the end; exit status 1 when a job failed on
    its input, 2 when one failed by a fault of ours, 130 when interrupted.

    Parameters
    ----------
    args : the parsed command line.
    """
    plan = read_plan(args.plan)
    presets = preset_items(args)
    if presets:
        plan.items = presets
        plan.settle_basis()
    for note in plan.notes:  # a mapping made on another basis: as the command line says it
        say_note(plan.path, note)
    console = Console(args.verbose)
    try:
        outcome = run_plan(plan, engine_factory(args, plan), console, args.force, args.dry_run)
    finally:
        console.close()
    if args.dry_run:
        return
    print("\n".join(summary(outcome)))
    if outcome.interrupted:
        raise KeyboardInterrupt
    failed = outcome.count("failed")[0]
    if failed:
        message = f"{failed} of {len(outcome.lines)} jobs failed (see {outcome.report})"
        raise (InputError if outcome.kinds <= {"input"} else InternalError)(message)
