"""Simulate one dataset scenario of config.yaml and write its Parquet file and manifest."""

from abglib.pipeline import log_to


def main(scenario: str, spec, parquet: str, manifest: str) -> None:
    from abglib import datasets

    ds = datasets.generate(scenario, spec)
    datasets.write(ds, parquet, manifest)


if "snakemake" in globals():
    logger = log_to(snakemake.log[0])  # noqa: F821
    main(
        snakemake.wildcards.scenario,  # noqa: F821
        snakemake.params.spec,  # noqa: F821
        snakemake.output.parquet,  # noqa: F821
        snakemake.output.manifest,  # noqa: F821
    )
    logger.info("wrote %s", snakemake.output.parquet)  # noqa: F821
