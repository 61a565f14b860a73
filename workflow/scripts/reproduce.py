"""Reproduce one source document (abglib.replications.reproduce): write its study's tables,
``comparison.csv`` (CONTRACTS.md §3) and ``robustness.csv``, one per named output."""

from abglib.reporting.pipeline import log_to


def main(input, output, params) -> None:
    from abglib import AbglibValueError
    from abglib.replications import reproduce
    from abglib.reporting.compare import write_csv

    tables = reproduce(params.doc, params.cfg, list(input.published), params.overrides)
    names = list(output.keys())
    if set(names) != set(tables):
        raise AbglibValueError(
            f"{params.doc}: the rule's outputs {sorted(names)} must be the study's tables "
            f"{sorted(tables)}"
        )
    for name in names:
        write_csv(tables[name], output[name], params.digits)


if "snakemake" in globals():
    log_to(snakemake.log[0])  # noqa: F821
    main(snakemake.input, snakemake.output, snakemake.params)  # noqa: F821
