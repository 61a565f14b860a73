"""Draw the tracking-antenna figures (seed 004) from the tables of rule antenna_reproduce."""

from abglib.reporting.compare import read_table
from abglib.reporting.pipeline import log_to


def main(input, output, params) -> None:
    from abglib.replications.antenna.figures import antenna_figure
    from abglib.reporting.plotting import save_figure

    tables = {k: read_table(v) for k, v in input.items()}
    for name, path in output.items():
        save_figure(antenna_figure(name, tables), path, dpi=params.dpi)


if "snakemake" in globals():
    log_to(snakemake.log[0])  # noqa: F821
    main(snakemake.input, snakemake.output, snakemake.params)  # noqa: F821
