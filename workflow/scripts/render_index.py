"""Write ``reports/v<version>/index.html`` with the scorecard and its CSV beside it."""

import pandas as pd

from abglib.reporting.pipeline import log_to


def main(input, output, params, config) -> None:
    from abglib.reporting import provenance
    from abglib.reporting.render import write_index, write_text

    card = pd.read_csv(input.scorecard)
    docs = [
        {"doc": d, "title": params.titles.get(d, d), "href": f"{d}/index.html"} for d in params.docs
    ]
    prov = provenance.collect(config, repo=params.repo)
    write_index(output.html, params.version, card, docs, prov, extras=params.extras)
    write_text(output.scorecard, open(input.scorecard, encoding="utf-8").read())


if "snakemake" in globals():
    log_to(snakemake.log[0])  # noqa: F821
    main(snakemake.input, snakemake.output, snakemake.params, snakemake.config)  # noqa: F821
