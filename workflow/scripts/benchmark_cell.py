"""One benchmark cell: a tracker variant on a dataset scenario -> per-coordinate metrics.

Reads the scenario's Parquet dataset (or, when ``benchmark.runs`` overrides the Monte
Carlo size, regenerates the scenario with that many runs from its spec, with the seed
``benchmark.seed + <scenario seed>``), runs :func:`abglib.bench.benchmark.run_cell`, applies
the VRF build check (:func:`abglib.bench.benchmark.check_cell`; Bonferroni over
``benchmark.family_size`` checks, which depends on nothing but the config constants and
this cell's runs, so adding a variant reruns no other cell) and only then writes the
CSV: a failing check fails the job and leaves no output.
"""

import pandas as pd

from abglib.reporting.pipeline import log_to


def cell_table(dataset, variant, params) -> pd.DataFrame:
    from abglib.bench.benchmark import run_cell

    return run_cell(
        dataset,
        params.spec,
        variant,
        burn_in=int(params.burn_in),
        init=params.init,
        ci_level=float(params.ci_level),
        chunk_runs=int(params.chunk_runs),
    )


def main(input, output, params, wildcards, logger) -> None:
    from abglib.bench.benchmark import cell_dataset, check_cell
    from abglib.bench.metrics import fail_threshold
    from abglib.reporting.compare import write_csv

    ds = cell_dataset(
        input.parquet, wildcards.scenario, params.scenario_spec, params.runs, params.seed
    )
    logger.info("%s on %s: %d runs x %d samples", wildcards.variant, ds.name, ds.runs, ds.n_samples)
    cell = cell_table(ds, wildcards.variant, params)
    threshold = fail_threshold(ds.runs, int(params.family_size), float(params.family_alpha))
    logger.info("VRF build check: |t| <= %.3f", threshold)
    check_cell(cell, threshold)
    write_csv(cell, output.cell, params.digits)


if "snakemake" in globals():
    _logger = log_to(snakemake.log[0])  # noqa: F821
    main(
        snakemake.input,  # noqa: F821
        snakemake.output,  # noqa: F821
        snakemake.params,  # noqa: F821
        snakemake.wildcards,  # noqa: F821
        _logger,
    )
