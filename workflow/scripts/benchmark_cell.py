"""One benchmark cell: a tracker variant on a dataset scenario -> per-coordinate metrics.

Reads the scenario's Parquet dataset (or, when ``benchmark.runs`` overrides the Monte
Carlo size, regenerates the scenario with that many runs from its spec and the cell's
seed), runs :func:`abglib.benchmark.run_cell`, writes the CSV, then applies the VRF build
check (:func:`abglib.benchmark.check_cell`): a failure raises after the CSV is written
to a temporary name only, so the job fails and no output is left behind.
"""

import pandas as pd

from abglib.pipeline import log_to


def load(parquet, scenario, spec, runs, seed):
    from abglib import datasets

    if runs:
        return datasets.generate(scenario, {**spec, "runs": int(runs)}, seed=int(seed))
    return datasets.read(parquet)


def cell_table(dataset, variant, params) -> pd.DataFrame:
    from abglib.benchmark import run_cell

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
    from abglib.benchmark import check_cell
    from abglib.compare import write_csv

    ds = load(input.parquet, wildcards.scenario, params.scenario_spec, params.runs, params.seed)
    logger.info("%s on %s: %d runs x %d samples", wildcards.variant, ds.name, ds.runs, ds.n_samples)
    cell = cell_table(ds, wildcards.variant, params)
    check_cell(cell, float(params.threshold))
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
