"""League table of the benchmark matrix, all cells in one table, trade-off points, variants."""

import pandas as pd

from abglib.common.jobs import log_to
from abglib.common.tables import read_table


def variants_table(specs) -> pd.DataFrame:
    """One row per configured variant: rule, family, source, parameters as given."""
    from abglib.bench.variants import describe_variant

    return pd.DataFrame([describe_variant(spec, name) for name, spec in specs.items()])


def main(input, output, params) -> None:
    from abglib.bench.benchmark import league_table, tradeoff_table
    from abglib.bench.metrics import fail_threshold
    from abglib.common.tables import write_csv

    cells = [read_table(p) for p in input.cells]
    runs = min(int(c["runs"].iloc[0]) for c in cells)
    threshold = fail_threshold(runs, int(params.family_size), float(params.family_alpha))
    d = params.digits
    write_csv(league_table(cells, threshold, params.rank_by), output.league, d)
    write_csv(pd.concat(cells, ignore_index=True), output.cells, d)
    write_csv(tradeoff_table(cells), output.tradeoff, d)
    write_csv(variants_table(params.variants), output.variants, d)


if "snakemake" in globals():
    log_to(snakemake.log[0])  # noqa: F821
    main(snakemake.input, snakemake.output, snakemake.params)  # noqa: F821
