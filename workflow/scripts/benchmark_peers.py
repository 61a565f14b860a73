"""abglib against FilterPy, scipy.signal and python-control on the same gains."""

from abglib.common.jobs import log_to


def main(output, params) -> None:
    from abglib.bench.peers import agreement_table
    from abglib.common.tables import write_csv

    write_csv(agreement_table(float(params.rtol), int(params.seed)), output.peers, params.digits)


if "snakemake" in globals():
    log_to(snakemake.log[0])  # noqa: F821
    main(snakemake.output, snakemake.params)  # noqa: F821
