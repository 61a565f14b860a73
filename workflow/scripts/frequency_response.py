"""Frequency responses of one figure of seed 000 (Figs. 1-6), as a long table
(abglib.replications.steelman1978.figures.response_table)."""

from abglib.common.jobs import log_to


def main(output, params) -> None:
    from abglib.common.tables import write_csv
    from abglib.replications.steelman1978.figures import response_table

    write_csv(response_table(params.figure, params.grids), output.data, params.digits)


if "snakemake" in globals():
    log_to(snakemake.log[0])  # noqa: F821
    main(snakemake.output, snakemake.params)  # noqa: F821
