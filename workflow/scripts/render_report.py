"""Execute a document's report notebook into ``reports/v<version>/<doc>/index.html``.

The notebook gets the pipeline's parameters (relative paths of what upstream rules
computed, and the provenance record); the figures and tables it shows are copied beside
the HTML (CONTRACTS.md §4).
"""

import os
import shutil
from pathlib import Path

from abglib.common.files import atomic_output
from abglib.common.jobs import log_to


def copy_atomic(src, dst) -> None:
    """Copy ``src`` to ``dst`` through a temporary file (no half-written copy on failure)."""
    with atomic_output(dst) as tmp:
        shutil.copyfile(src, tmp)


def main(input, output, params, config, logger) -> None:
    from abglib.reporting import provenance
    from abglib.reporting.render import render_notebook, report_context

    parameters, page = report_context(
        params.doc,
        params.version,
        input,
        output,
        repo=params.repo,
        nav=params.page["nav"],
        made_by=params.page["made_by"],
        provenance=provenance.collect(config, repo=params.repo),
        settings=getattr(params, "settings", None),
    )
    render_notebook(
        input.notebook,
        output.html,
        parameters,
        cwd=os.getcwd(),
        name=params.doc,
        timeout=params.timeout,
        log=logger.info,
        page=page,
    )
    copy_atomic(input.notebook, output.notebook)
    # a table the report shows but does not list as an output (wall-clock timings) stays
    # out of the report's tables folder, so the release's tables hold results only
    dests = {Path(p).name: p for p in [*output.figures, *output.tables]}
    for src in [*input.figures, *input.tables]:
        if Path(src).name in dests:
            copy_atomic(src, dests.pop(Path(src).name))
    if dests:
        raise ValueError(f"report outputs without an input to copy: {sorted(dests)}")


if "snakemake" in globals():
    _logger = log_to(snakemake.log[0])  # noqa: F821
    main(snakemake.input, snakemake.output, snakemake.params, snakemake.config, _logger)  # noqa: F821
