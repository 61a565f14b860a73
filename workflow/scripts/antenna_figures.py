"""Draw the tracking-antenna figures (seed 004) from the tables of rule antenna_reproduce."""

from abglib.common.jobs import log_to
from abglib.common.tables import read_table


def main(input, output, params) -> None:
    from abglib.common.plotting import save_figure
    from abglib.replications.antenna.figures import antenna_figure

    tables = {k: read_table(v) for k, v in input.items()}
    for name, path in output.items():
        save_figure(antenna_figure(name, tables), path, dpi=params.dpi)


if "snakemake" in globals():
    log_to(snakemake.log[0])  # noqa: F821
    main(snakemake.input, snakemake.output, snakemake.params)  # noqa: F821
