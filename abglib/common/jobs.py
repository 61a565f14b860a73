"""How a pipeline job runs: on the threads Snakemake gave it, logging to its own file,
timed on its own.

Shared by the benchmark's cells (:mod:`abglib.bench.cell`, run inside Snakemake's
process), the reports' worker processes (:mod:`abglib.reporting.workers`) and every
workflow script (:func:`log_to`, first thing).
"""

from __future__ import annotations

import contextlib
import logging
import os
import sys
from pathlib import Path

from .._checks import AbglibValueError

__all__ = [
    "BENCHMARK_COLUMNS",
    "JobFailed",
    "job_log",
    "job_threads",
    "log_to",
    "process_usage",
    "write_benchmark",
]


def log_to(path) -> logging.Logger:
    """Send stderr and a logger named ``abglib.pipeline`` to the rule's log file.

    Call first thing in a workflow script (``log_to(snakemake.log[0])``). An uncaught
    exception is written to the log with its traceback, and its message to the console.
    """
    fh = open(path, "w", encoding="utf-8")  # noqa: SIM115 - lives as long as the script
    console = sys.stderr
    sys.stderr = fh

    def excepthook(kind, value, tb):
        # the traceback goes to the log; the message also to the console, so that a
        # failed job says what to do where the user is looking
        sys.__excepthook__(kind, value, tb)
        fh.flush()
        print(f"{kind.__name__}: {value}\n(full traceback in {path})", file=console)

    sys.excepthook = excepthook
    logger = logging.getLogger("abglib.pipeline")
    logger.handlers[:] = [logging.StreamHandler(fh)]
    logger.setLevel(logging.INFO)
    logging.captureWarnings(True)
    return logger


class JobFailed(RuntimeError):
    """A job run inside Snakemake's own process, or in its worker, failed; the message
    names its log."""


@contextlib.contextmanager
def job_threads(n):
    """Run the enclosed code on at most ``n`` threads of numba's parallel loops: a job
    uses the cores Snakemake gave it (the rule's ``threads:``), no more.

    Without it a 1-thread job's batched tracking ran on all of numba's threads (2 here),
    and two such jobs side by side (two cores) competed for three or four: a job next to
    one that does slowed by up to 40 %. The count is the calling thread's own (numba's
    ``set_num_threads``), so it holds for a thread of Snakemake's process (the cells) as
    for a worker process, and it is put back on exit. Parallel and serial tracking give
    the same bits (:func:`abglib.track`).
    """
    import numba

    n = int(n)
    if n < 1:
        raise AbglibValueError(f"a job needs at least 1 thread, got {n}")
    old = numba.get_num_threads()
    numba.set_num_threads(min(n, numba.config.NUMBA_NUM_THREADS))
    try:
        yield
    finally:
        numba.set_num_threads(old)


@contextlib.contextmanager
def job_log(path, name: str = "job"):
    """The log of a job that runs inside Snakemake's process (a ``run:`` block).

    Yields a logger writing to ``path`` (truncated) and nowhere else, so that jobs running
    side by side in threads keep separate logs and the process's ``sys.stderr`` is left
    alone (unlike :func:`log_to`, which is for a script's own process). An exception is
    written to the log with its traceback and raised again as :class:`JobFailed` with its
    message and the log's path.
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    logger = logging.getLogger(f"abglib.job.{path.resolve()}")
    logger.propagate = False
    logger.setLevel(logging.INFO)
    handler = logging.FileHandler(path, mode="w", encoding="utf-8")
    logger.handlers[:] = [handler]
    try:
        yield logger
    except Exception as exc:
        logger.error("%s failed", name, exc_info=True)
        raise JobFailed(
            f"{name}: {type(exc).__name__}: {exc}\n(full traceback in {path})"
        ) from None
    finally:
        handler.close()
        logger.handlers.clear()
        logging.Logger.manager.loggerDict.pop(logger.name, None)


#: The columns of a job's benchmark record (``benchmarks/results/<job>.tsv``): the job's
#: wall time in seconds and as ``h:m:s``, the peak resident set of its process (MiB) and
#: the CPU time it used (user + system, s), named as in Snakemake's ``benchmark:`` files.
BENCHMARK_COLUMNS = ("s", "h:m:s", "max_rss", "cpu_time")


def process_usage() -> dict[str, float]:
    """The calling process's ``cpu_time`` so far (user + system seconds, its own and its
    waited-for children's) and ``max_rss``, its peak resident set so far (MiB), from
    :func:`resource.getrusage`; NaN each where the platform has no ``resource`` module.
    """
    try:
        import resource
    except ImportError:  # not POSIX
        return {"cpu_time": float("nan"), "max_rss": float("nan")}
    own = resource.getrusage(resource.RUSAGE_SELF)
    kids = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = own.ru_utime + own.ru_stime + kids.ru_utime + kids.ru_stime
    # ru_maxrss: kibibytes on Linux, bytes on macOS
    rss = own.ru_maxrss / (2**20 if sys.platform == "darwin" else 2**10)
    return {"cpu_time": cpu, "max_rss": rss}


def write_benchmark(path, seconds: float, usage: dict[str, float]) -> Path:
    """Write a job's benchmark record (:data:`BENCHMARK_COLUMNS`) to ``path``: a header
    line and one row, tab-separated, the file whole or not at all.

    Snakemake's own ``benchmark:`` directive is not used for the workflow's script jobs:
    it samples the process that runs the job and all of that process's children, twice a
    second (psutil's ``memory_full_info`` of each, reading ``/proc/<pid>/smaps_rollup``).
    A local build runs its jobs as threads of Snakemake's process, so every record summed
    Snakemake, the fork server and every job running at the time: a small build's
    Al-Wagih claims job, which used 9.5 CPU-s alone, was recorded at 23.9 CPU-s and
    1,326 MB, and the sampling itself cost the build about 1.7 CPU-s of its 31
    (2026-12-03, issue 24). Each job here times its own process (:func:`process_usage`).

    Parameters
    ----------
    path : path-like
        The record's file; its folder is made.
    seconds : float
        The job's wall time (s), at least 0.
    usage : dict
        ``cpu_time`` (s) and ``max_rss`` (MiB) of the job's process
        (:func:`process_usage`, or the difference of two for ``cpu_time``).
    """
    seconds = float(seconds)
    if not seconds >= 0.0:
        raise AbglibValueError(f"a job's wall time must be at least 0 s, got {seconds!r}")
    whole = int(seconds)
    hms = f"{whole // 3600}:{whole // 60 % 60:02d}:{whole % 60:02d}"
    row = (f"{seconds:.4f}", hms, f"{usage['max_rss']:.2f}", f"{usage['cpu_time']:.2f}")
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    part = path.with_name(f".{path.name}.{os.getpid()}.part")
    part.write_text("\t".join(BENCHMARK_COLUMNS) + "\n" + "\t".join(row) + "\n", "utf-8")
    part.replace(path)
    return path
