"""Draw seed 001's Figures 5-8 (and the causal-M5 comparison) from the study's tables."""

from abglib.common.jobs import log_to
from abglib.common.tables import read_table


def main(input, output, params) -> None:
    from abglib.common.plotting import save_figure
    from abglib.replications.alwagih.figures import (
        alwagih_causal,
        alwagih_rmse_bars,
        alwagih_tracks,
    )
    from abglib.replications.alwagih.printed import PAPER_METHODS as PAPER

    tracks = read_table(input.tracks)
    summary = read_table(input.mc_rmse)
    for noise, out, num in (("white", output.fig5, 5), ("coloured", output.fig6, 6)):
        d = tracks[tracks["noise"] == noise]
        e = int(d["experiment"].iloc[0])
        fig = alwagih_tracks(
            d,
            PAPER,
            f"Figure {num} (reconstruction): actual, measured and predicted track, "
            f"{noise} noise, experiment {e}",
        )
        save_figure(fig, out, dpi=params.dpi)
    for noise, table, out, num in (
        ("white", input.table1, output.fig7, 7),
        ("coloured", input.table2, output.fig8, 8),
    ):
        fig = alwagih_rmse_bars(
            summary[summary["noise"] == noise],
            read_table(table),
            PAPER,
            f"Figure {num} (reconstruction): RMSE of the 5 methods, {noise} noise",
        )
        save_figure(fig, out, dpi=params.dpi)
    fig = alwagih_causal(
        read_table(input.causal),
        "Beyond seed 001: M5 vs its causal variant, the best of M1-M4 and Kalman α-β designs",
    )
    save_figure(fig, output.causal, dpi=params.dpi)


if "snakemake" in globals():
    log_to(snakemake.log[0])  # noqa: F821
    main(snakemake.input, snakemake.output, snakemake.params)  # noqa: F821
