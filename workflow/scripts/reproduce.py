"""One part of a source document's replication, one table per named output:
``part='study'`` writes the study's tables (abglib.replications.study_tables),
``part='claims'`` writes ``comparison.csv`` (CONTRACTS.md §3) and ``robustness.csv``
(abglib.replications.judge_claims)."""

from abglib.common.jobs import log_to


def main(input, output, params) -> None:
    from abglib import AbglibValueError
    from abglib.common.tables import write_csv
    from abglib.replications import judge_claims, study_tables

    published = list(input.published)
    if params.part == "study":
        tables = study_tables(params.doc, params.cfg, published)
    else:
        tables = judge_claims(params.doc, params.cfg, published, params.overrides)
    names = list(output.keys())
    if set(names) != set(tables):
        raise AbglibValueError(
            f"{params.doc} {params.part}: the rule's outputs {sorted(names)} must be the "
            f"tables {sorted(tables)}"
        )
    for name in names:
        write_csv(tables[name], output[name], params.digits)


if "snakemake" in globals():
    log_to(snakemake.log[0])  # noqa: F821
    main(snakemake.input, snakemake.output, snakemake.params)  # noqa: F821
