"""Draw one frequency-response figure of seed 000 (Figs. 1-6) from its response table."""

from abglib.common.jobs import log_to
from abglib.common.tables import read_table


def main(input, output, params) -> None:
    from abglib.common.plotting import save_figure
    from abglib.replications.steelman1978.figures import draw

    fig = draw(read_table(input.data), params.axes, params.caption)
    save_figure(fig, output.png, dpi=params.dpi)


if "snakemake" in globals():
    log_to(snakemake.log[0])  # noqa: F821
    main(snakemake.input, snakemake.output, snakemake.params)  # noqa: F821
