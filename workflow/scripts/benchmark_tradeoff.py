"""Noise-versus-lag curves: each design family of the config swept over its parameter."""

from abglib.common.jobs import log_to


def main(input, output, params) -> None:
    from abglib.bench import datasets
    from abglib.bench.benchmark import tradeoff_sweep
    from abglib.common.tables import write_csv

    data = [datasets.read(p) for p in input.parquets]
    curves = tradeoff_sweep(
        data, params.families or {}, burn_in=int(params.burn_in), init=params.init
    )
    write_csv(curves, output.curves, params.digits)


if "snakemake" in globals():
    log_to(snakemake.log[0])  # noqa: F821
    main(snakemake.input, snakemake.output, snakemake.params)  # noqa: F821
