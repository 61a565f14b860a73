"""How a pipeline job runs: on the threads Snakemake gave it, logging to its own file.

Shared by the benchmark's cells (:mod:`abglib.bench.cell`, run inside Snakemake's
process), the reports' worker processes (:mod:`abglib.reporting.workers`) and every
workflow script (:func:`log_to`, first thing).
"""

from __future__ import annotations

import contextlib
import logging
import sys
from pathlib import Path

from .._checks import AbglibValueError

__all__ = ["JobFailed", "job_log", "job_threads", "log_to"]


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
