"""Draw the FAA Bendix report's figures (seed 003) from the tables of its reproduce rule."""

import pandas as pd

from abglib.reporting.pipeline import log_to


def main(input, output, params) -> None:
    from abglib.replications.faa_bendix.figures import draw_all
    from abglib.reporting.plotting import save_figure

    figs = draw_all(
        pd.read_csv(input.responses),
        pd.read_csv(input.damping_lags),
        pd.read_csv(input.captions),
    )
    for name, fig in figs.items():
        save_figure(fig, getattr(output, name), dpi=params.dpi)


if "snakemake" in globals():
    log_to(snakemake.log[0])  # noqa: F821
    main(snakemake.input, snakemake.output, snakemake.params)  # noqa: F821
