"""Build ``results/scorecard.csv``: verdict counts per document (CONTRACTS.md §3)."""

import pandas as pd

from abglib.common.jobs import log_to


def main(input, output, params) -> None:
    from abglib.common.tables import write_csv
    from abglib.replications.compare import scorecard

    tables = [pd.read_csv(p, dtype=str, keep_default_na=False) for p in input.comparisons]
    write_csv(scorecard(tables), output.scorecard, params.digits)


if "snakemake" in globals():
    log_to(snakemake.log[0])  # noqa: F821
    main(snakemake.input, snakemake.output, snakemake.params)  # noqa: F821
