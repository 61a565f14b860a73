"""Workflow scripts run in warm worker processes instead of a new Python each.

A Snakemake ``script:`` job starts a new Python, which imports numpy, pandas, scipy,
matplotlib, numba and abglib again: about 2 s, more than most of this workflow's jobs
spend on their own work, paid some 40 times per clean build. Here a rule is a ``run:``
block that hands its script to :func:`run_script`:

- inside Snakemake's own process (a local build, whose ``run:`` jobs are threads: the
  default profile's ``force-use-threads``), the script runs in a fork of one *fork
  server*, a process that imported those modules once per build
  (:mod:`multiprocessing`'s ``forkserver``). A job starts in milliseconds, yet it still
  runs in a process of its own: its own GIL (two jobs really use two cores), its own
  matplotlib state and ``sys.stderr``, nothing left behind for the next job, and a crash
  fails only that job;
- anywhere else (a cluster job or any job that already has a process of its own), the
  script runs in the calling process, as Snakemake's ``script:`` would. A SLURM group job
  (profiles/slurm) runs its jobs in threads of one Snakemake process, and the submitting
  process of a cluster run its ``localrules`` in threads of its own: their scripts run
  there in turn, never two at once, sharing that process's imports.

Either way the script sees the same ``snakemake`` object as under ``script:``
(``snakemake.input``, ``.output``, ``.params``, ``.log``...), so the scripts themselves
are unchanged and still run under plain ``script:`` too.
"""

from __future__ import annotations

import multiprocessing
import os
import runpy
import sys
import threading
import time
import traceback
from pathlib import Path

from ..common.jobs import JobFailed, job_threads, process_usage, write_benchmark

__all__ = [
    "PRELOAD",
    "JobFailed",
    "freeze_preloaded",
    "load_figures",
    "load_kernels",
    "run_script",
    "script_object",
    "warm_up",
]

#: Modules the fork server imports once, so that no job pays for them (a module that
#: fails to import is skipped: the job that needs it will say why).
PRELOAD = [
    # first: the server's own environment (matplotlib's backend), before anything reads it
    "abglib.reporting._server_env",
    "numpy",
    "scipy.linalg",
    "scipy.signal",
    "scipy.optimize",
    "scipy.stats",
    "pandas",
    "matplotlib",
    "matplotlib.pyplot",
    "numba",
    # multiprocessing runs the main script again in every worker (a "__main__" preload
    # would not stop it: the fork server looks for a key its preparation data lacks,
    # CPython 3.11), and Snakemake's main script imports snakemake.cli: ~1 s a job unless
    # the server has it already
    "snakemake.cli",
    "snakemake.io",
    "abglib",
    "abglib.analysis",
    "abglib.bench",
    "abglib.replications",
    "jupytext",
    "nbformat",
    "IPython.core.interactiveshell",
    "abglib.common.files",
    "abglib.common.jobs",
    "abglib.common.plotting",
    "abglib.common.tables",
    "abglib.replications.compare",
    "abglib.reporting.execute",
    "abglib.reporting.notebook",
    "abglib.reporting.page",
    "abglib.reporting.pipeline",
    "abglib.reporting.render",
    # last: the compiled loops themselves and matplotlib's caches (load_kernels,
    # load_figures), with everything above in place
    "abglib.reporting._warm_caches",
]

_CONTEXT = None
_CONTEXT_LOCK = threading.Lock()
#: held while a script runs in place: the jobs of a cluster group run in threads of one
#: Snakemake process, and a script in place takes over the process's ``sys.stderr``,
#: excepthook and matplotlib state, so two must not overlap (the profile's groups are
#: one core wide, and this keeps a wider one correct)
_IN_PLACE_LOCK = threading.Lock()


def script_object(
    input, output, params, wildcards, threads, resources, log, config, rule, scriptdir
):
    """The ``snakemake`` object a script sees, as Snakemake's ``script:`` builds it
    (:func:`abglib._compat.snakemake.script_object_class`)."""
    from .._compat.snakemake import script_object_class

    return script_object_class()(
        input, output, params, wildcards, threads, resources, log, config, rule, 0, scriptdir
    )


def _context():
    """The fork-server context, started on first use (a build with nothing to do never
    starts it)."""
    global _CONTEXT
    with _CONTEXT_LOCK:
        if _CONTEXT is None:
            ctx = multiprocessing.get_context("forkserver")
            ctx.set_forkserver_preload(PRELOAD)
            _CONTEXT = ctx
    return _CONTEXT


def load_kernels() -> None:
    """Load numba's cached machine code of the loops most jobs run, by calling them once on
    tiny inputs: the tracker (batched and per-series, alpha-beta and alpha-beta-gamma,
    fixed and time-varying gains), methods M1-M5 and the benchmark metrics. Signatures
    are those the jobs use (float64, C-contiguous). A failure here is not the server's to
    report: the job that needs the loop loads it itself and says what is wrong.
    """
    try:
        import numpy as np

        from .. import methods, track
        from ..design import standard_from_alpha

        z = np.cumsum(np.ones((8, 32)), axis=-1)
        for order in (2, 3):
            g = standard_from_alpha(0.5, order=order)
            for init in ("zero", "two_point"):
                track(z, g, dt=1.0, init=init)
                track(z[0], g, dt=1.0, init=init)
            varying = type(g)(*(np.full(32, float(v)) for v in g))
            track(z[0], varying, dt=1.0)
        methods.m1(z, 0.5)
        methods.m2(z)
        methods.m3(z, np.linspace(0.1, 1.0, 3))
        methods.m4(z, 0.5, 4, np.linspace(0.1, 0.9, 3))
        methods.m5(z, np.linspace(0.1, 0.9, 3))
        methods.m5(z, np.linspace(0.1, 0.9, 3), causal=True)
        # the benchmark metrics' compiled pass (the trade-off job scores 156 cells)
        from ..bench.metrics import evaluate_cell

        coord = {"truth_pos": z, "truth_vel": np.ones_like(z), "z": z + 0.5, "sigma": 1.0}
        gains = standard_from_alpha(0.5, order=3)
        evaluate_cell({"x": coord}, 1.0, gains=gains, noise={"model": "white"}, burn_in=2)
    except Exception:  # noqa: BLE001 - see the docstring
        pass


def load_figures() -> None:
    """Fill the caches of matplotlib that every figure job's first figure fills: the
    project style's fonts and glyphs, mathtext's parser (log-axis tick labels), the log
    locators and constrained layout, by drawing one small log-log figure under
    :data:`.plotting.STYLE` on an Agg canvas. A figure job forked from the server then
    draws its first figure as fast as its later ones (0.3-0.4 s less a job). The caches
    hold what matplotlib would compute anyway: the same pixels. A failure here is the
    figure job's to report, not the server's (as :func:`load_kernels`).
    """
    try:
        import matplotlib.pyplot as plt
        from matplotlib.backends.backend_agg import FigureCanvasAgg

        from ..common.plotting import STYLE

        with plt.rc_context(STYLE):
            fig, ax = plt.subplots()
            ax.loglog([1e-2, 1.0], [1e-3, 10.0], label="α-β-γ")
            ax.set_xlabel("ωT (rad/sample)")
            ax.set_title("|X̄/X|")
            ax.legend()
            FigureCanvasAgg(fig).draw()
            plt.close(fig)
    except Exception:  # noqa: BLE001 - see the docstring
        pass


def freeze_preloaded() -> None:
    """Collect the preloads' garbage once (the warm-up figure of :func:`load_figures`
    among it), then move every object the fork server still holds (about 310,000: the
    scientific stack's modules, numba's dispatchers, matplotlib's caches) into the garbage
    collector's permanent generation (:func:`gc.freeze`), which every job forked from the
    server inherits. The collections a job triggers then traverse only what the job itself
    made, and the collector no longer writes to the server's objects (reference counts
    still do, where a job uses them): the :mod:`gc` docs' advice for a process that forks
    without exec. What a job allocates is collected as before; an object frozen here that
    later becomes cyclic garbage is never freed (the server's objects live as long as it
    does anyway)."""
    import gc

    gc.collect()
    gc.freeze()


def warm_up() -> None:
    """Start the fork server now, so that its imports (~4 s on one core) overlap what the
    build does before its first script job: the DAG's in-process jobs (the datasets,
    the benchmark cells) and Snakemake's own start. Called from the workflow's
    ``onstart`` handler, which runs only when a local build has jobs to run (never for a
    dry run or a no-op). Returns at once; a job that comes before the imports are done
    waits for them, as it would have anyway.
    """
    from multiprocessing import forkserver

    _context()
    forkserver.ensure_running()


def _execute(script, smk) -> None:
    """Run ``script`` with ``snakemake`` bound to ``smk``, as Snakemake's preamble does,
    on the job's threads (:func:`.pipeline.job_threads`: a worker's job, or a cluster
    job's cpus, not the node's)."""
    with job_threads(smk.threads):
        runpy.run_path(str(script), init_globals={"snakemake": smk}, run_name="__main__")


#: The exit code multiprocessing's forkserver ``Popen`` gives a child whose status it
#: could not read back from the fork server (``popen_forkserver.Popen.poll``).
_STATUS_LOST = 255


def _worker(script, smk, cwd, conn) -> None:
    """Body of the worker process: the script, then its outcome over ``conn``: the
    error's message (a str), or on success the process's usage (a dict,
    :func:`~abglib.common.jobs.process_usage`: a forked process starts with no CPU time
    of its own)."""
    try:
        os.chdir(cwd)
        _execute(script, smk)
    except BaseException as err:  # noqa: BLE001 - every failure must reach the parent
        # the traceback goes where the script sends its stderr (its log, see log_to)
        traceback.print_exc()
        sys.stderr.flush()
        conn.send(f"{type(err).__name__}: {err}")
        conn.close()
        os._exit(1)
    conn.send(process_usage())
    conn.close()


def run_script(script, smk, *, in_worker: bool = True, benchmark=None) -> None:
    """Run the workflow script ``script`` (a path) for one job.

    ``smk`` is the job's ``snakemake`` object (:func:`script_object`). ``in_worker``:
    run it in a fork of the warm fork server (the caller is Snakemake's own process,
    whose jobs are threads); else run it here, in the job's own process (or a cluster
    group's, one script at a time), with ``sys.stderr`` and the excepthook given back
    afterwards. Raises :class:`JobFailed` naming the script, the error and the job's log
    when the script fails.

    ``benchmark``: a path where a job that succeeded gets its benchmark record
    (:func:`~abglib.common.jobs.write_benchmark`): the job's wall time, and the CPU time
    and peak resident set of the process it ran in (the fork, or from here on in place).
    """
    script = Path(script)
    if not script.is_file():
        raise JobFailed(f"no workflow script {script}")
    log = f" (full traceback in {smk.log[0]})" if len(smk.log) else ""
    start = time.perf_counter()
    if not in_worker:
        with _IN_PLACE_LOCK:
            start = time.perf_counter()
            saved = sys.stderr, sys.excepthook
            before = process_usage()
            try:
                _execute(script, smk)
            except Exception as err:
                traceback.print_exc()
                raise JobFailed(f"{script.name} failed: {type(err).__name__}: {err}{log}") from err
            finally:
                sys.stderr, sys.excepthook = saved
            if benchmark is not None:
                usage = process_usage()
                usage["cpu_time"] -= before["cpu_time"]
                write_benchmark(benchmark, time.perf_counter() - start, usage)
        return
    ctx = _context()
    receive, send = ctx.Pipe(duplex=False)
    proc = ctx.Process(
        target=_worker, args=(str(script), smk, os.getcwd(), send), name=f"abglib-{script.stem}"
    )
    proc.start()
    send.close()
    try:
        outcome = receive.recv()
    except EOFError:  # the worker died without a word (killed, or a crash in C)
        outcome = "the worker process ended without reporting"
    proc.join()
    receive.close()
    seconds = time.perf_counter() - start
    if isinstance(outcome, dict):  # success: the worker's usage
        usage, outcome = outcome, None
        if benchmark is not None and proc.exitcode in (0, _STATUS_LOST):
            write_benchmark(benchmark, seconds, usage)
    if outcome is None and proc.exitcode == _STATUS_LOST:
        # the worker said it finished (its outputs are written); 255 is what
        # multiprocessing's forkserver Popen reports when it could not read the child's
        # exit status from the fork server, not the script's. Seen once, in the
        # lowest-versions matrix (2026-12-02: benchmark_report; the rerun passed).
        print(
            f"abglib: {script.name} reported success, but the fork server lost its exit "
            f"status (code {_STATUS_LOST}); the job counts as done",
            file=sys.stderr,
        )
        return
    if outcome is not None or proc.exitcode != 0:
        raise JobFailed(
            f"{script.name} failed: {outcome or 'no error reported'} "
            f"(worker exit code {proc.exitcode}){log}"
        )
