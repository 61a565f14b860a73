"""Write ``changes.csv`` and ``changes.html`` of a build: its comparison tables against the
previous version folder under ``reports/`` (or a page saying there is none)."""

from abglib.common.jobs import log_to


def main(input, output, params) -> None:
    from abglib.reporting.changes import write_build_changes

    tables = dict(zip(params.docs, input.comparisons, strict=True))
    ch = write_build_changes(tables, params.previous, params.version, output.csv, output.html)
    print(
        f"changes against {params.previous}: {len(ch.table)} rows"
        if ch is not None
        else "no previous version folder: page says so"
    )


if "snakemake" in globals():
    log_to(snakemake.log[0])  # noqa: F821
    main(snakemake.input, snakemake.output, snakemake.params)  # noqa: F821
