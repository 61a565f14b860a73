"""Write ``reports/v<version>/index.html`` with the scorecard and its CSV beside it."""

from pathlib import Path

import pandas as pd

from abglib.common.jobs import log_to


def main(input, output, params, config) -> None:
    from abglib.reporting import provenance
    from abglib.reporting.page import read_headline
    from abglib.reporting.render import write_index, write_text

    card = pd.read_csv(input.scorecard)
    pages = {Path(p).parent.name: p for p in [*input.reports, *input.others]}
    docs = [
        {"doc": d, "title": params.titles.get(d, d), "href": f"{d}/index.html"} for d in params.docs
    ]
    extras = [dict(e) for e in params.extras]
    for entry in [*docs, *extras]:
        entry["headline"] = read_headline(pages[entry["doc"]]) if entry["doc"] in pages else ""
    prov = provenance.collect(config, repo=params.repo)
    write_index(output.html, params.version, card, docs, prov, extras=extras)
    write_text(output.scorecard, open(input.scorecard, encoding="utf-8").read())


if "snakemake" in globals():
    log_to(snakemake.log[0])  # noqa: F821
    main(snakemake.input, snakemake.output, snakemake.params, snakemake.config)  # noqa: F821
