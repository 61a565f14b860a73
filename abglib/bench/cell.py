"""One benchmark cell as a pipeline job (rule ``benchmark_cell``, a ``run:`` block).

The rule calls :func:`cell_job` inside Snakemake's own process, so the 100-odd cells of a
build share one Python start-up, one set of imports and one numba load; each cell is still
its own job in the DAG (adding a variant schedules only its cells). It reads only its
dataset and writes only its CSV (atomically), so it runs the same way in a job of its own
on a cluster.
"""

from __future__ import annotations

import time
from collections.abc import Mapping

__all__ = ["cell_job"]


def cell_job(
    parquet,
    out_csv,
    log,
    *,
    variant: str,
    spec: Mapping,
    scenario: str,
    scenario_spec: Mapping,
    settings: Mapping,
    seed: int,
    digits: int,
    threads: int = 1,
) -> None:
    """Run one cell and write its CSV, or fail leaving no output.

    Reads the scenario's Parquet dataset (or, when ``settings['runs']`` overrides the
    Monte Carlo size, regenerates the scenario with that many runs and ``seed``), runs
    :func:`abglib.bench.benchmark.run_cell`, applies the VRF build check
    (:func:`abglib.bench.benchmark.check_cell`; Bonferroni over ``family_size`` checks,
    which depends only on the config and this cell's runs) and only then writes the CSV.

    ``settings`` holds ``runs, burn_in, init, ci_level, chunk_runs, family_size,
    family_alpha`` (``config['benchmark']``). ``threads``: the job's cores (the rule's
    ``threads:``), which its tracking keeps to (:func:`abglib.common.jobs.job_threads`).
    """
    from ..common.jobs import job_log, job_threads
    from ..common.tables import write_csv
    from .benchmark import cell_dataset, check_cell, run_cell
    from .metrics import fail_threshold

    started = time.perf_counter()
    with job_threads(threads), job_log(log, f"benchmark cell {variant}/{scenario}") as logger:
        ds = cell_dataset(parquet, scenario, scenario_spec, settings.get("runs"), seed)
        logger.info("%s on %s: %d runs x %d samples", variant, ds.name, ds.runs, ds.n_samples)
        cell = run_cell(
            ds,
            spec,
            variant,
            burn_in=int(settings["burn_in"]),
            init=settings["init"],
            ci_level=float(settings["ci_level"]),
            chunk_runs=int(settings["chunk_runs"]),
        )
        threshold = fail_threshold(
            ds.runs, int(settings["family_size"]), float(settings["family_alpha"])
        )
        logger.info("VRF build check: |t| <= %.3f", threshold)
        check_cell(cell, threshold)
        write_csv(cell, out_csv, digits)
        # the cell's own time (the rule has no benchmark: file, whose per-second sampling of
        # Snakemake's whole process tree cost more than a small cell; benchmarks/rebuild.py
        # reads this line)
        logger.info("wrote %s in %.3f s", out_csv, time.perf_counter() - started)
