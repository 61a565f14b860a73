"""Draw the FAA Bendix report's figures (seed 003) from the tables of its reproduce rule."""

from abglib.common.jobs import log_to
from abglib.common.tables import read_table


def main(input, output, params) -> None:
    from abglib.common.plotting import save_figure
    from abglib.replications.faa_bendix.figures import draw_all

    figs = draw_all(
        read_table(input.responses),
        read_table(input.damping_lags),
        read_table(input.captions),
    )
    for name, fig in figs.items():
        save_figure(fig, getattr(output, name), dpi=params.dpi)


if "snakemake" in globals():
    log_to(snakemake.log[0])  # noqa: F821
    main(snakemake.input, snakemake.output, snakemake.params)  # noqa: F821
