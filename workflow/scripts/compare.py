"""Build ``results/<doc>/comparison.csv`` (CONTRACTS.md §3) from the transcribed published
numbers, the reproduced values and the alternatives (see :mod:`abglib.reporting.compare`)."""

import pandas as pd

from abglib.reporting.pipeline import log_to


def _read(path) -> pd.DataFrame:
    return pd.read_csv(path, dtype=str, keep_default_na=False)


def main(input, output, params) -> None:
    from abglib.reporting.compare import build_comparison, read_published, write_csv

    alternatives = _read(input.alternatives)
    alternatives["value"] = pd.to_numeric(alternatives["value"])
    table = build_comparison(
        params.doc,
        read_published(input.published),
        _read(input.reproduced),
        alternatives,
        params.overrides,
    )
    write_csv(table, output.comparison, params.digits)


if "snakemake" in globals():
    log_to(snakemake.log[0])  # noqa: F821
    main(snakemake.input, snakemake.output, snakemake.params)  # noqa: F821
