"""Draw the Huang et al. report's figures (seed 002, Figs 2-7) from the study's tables."""

from abglib.common.jobs import log_to
from abglib.common.tables import read_table


def main(input, output, params) -> None:
    from abglib.common.plotting import save_figure
    from abglib.replications.compare import read_published
    from abglib.replications.huang.figures import huang_figures

    names = ("bandwidth_curves", "tables12", "thermal", "track", "track_metrics")
    tables = {n: read_table(input[n]) for n in names}
    figures = huang_figures(tables, read_published(input.published), params.cfg)
    for name, fig in figures.items():
        save_figure(fig, output[name], dpi=params.dpi)


if "snakemake" in globals():
    log_to(snakemake.log[0])  # noqa: F821
    main(snakemake.input, snakemake.output, snakemake.params)  # noqa: F821
