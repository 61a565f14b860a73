"""Draw the FAA Bendix report's figures (seed 003) from the tables of faa_bendix.py."""

import pandas as pd

from abglib.reporting.pipeline import log_to


def main(input, output, params) -> None:
    from abglib.replications.faa_bendix import program as bendix
    from abglib.replications.faa_bendix.figures import response_grid, stability_triangle
    from abglib.reporting.plotting import save_figure

    resp = pd.read_csv(input.responses)
    for kind in bendix.INPUTS:
        title = (
            f"{kind.upper()} RESPONSE OF THE BENDIX ALPHA-BETA FILTER, T = 1-8 s "
            "(y grid every SFY, the captions' scale factor)"
        )
        fig = response_grid(resp, kind, bendix.SFY[kind], title)
        save_figure(fig, getattr(output, kind), dpi=params.dpi)
    fig = stability_triangle(
        pd.read_csv(input.damping_lags), "The eight Bendix gain sets (memo) in the α-β plane"
    )
    save_figure(fig, output.triangle, dpi=params.dpi)


if "snakemake" in globals():
    log_to(snakemake.log[0])  # noqa: F821
    main(snakemake.input, snakemake.output, snakemake.params)  # noqa: F821
