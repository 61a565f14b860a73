"""Heatmap of the benchmark matrix and the noise-versus-lag trade-off per design family."""

from abglib.common.jobs import log_to
from abglib.common.tables import read_table


def main(input, output, params) -> None:
    from abglib.bench.figures import benchmark_heatmap, tradeoff_figure
    from abglib.common.plotting import save_figure

    league = read_table(input.league)
    save_figure(benchmark_heatmap(league, params.rank_by), output.heatmap, dpi=params.dpi)
    points = read_table(input.tradeoff)
    curves = read_table(input.curves)
    fig = tradeoff_figure(curves, points, params.tradeoff_scenarios)
    save_figure(fig, output.tradeoff, dpi=params.dpi)


if "snakemake" in globals():
    log_to(snakemake.log[0])  # noqa: F821
    main(snakemake.input, snakemake.output, snakemake.params)  # noqa: F821
