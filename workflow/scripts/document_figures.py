"""Draw a document's figures from its study's tables: the generic ``<doc>_figures`` rule
(workflow/rules/documents.smk) of a document without a figures rule of its own.

The document's ``abglib/replications/<doc>/figures.py`` defines ``figure(name, tables)``:
``name`` is a figure stem of its ``document.yaml``, ``tables`` maps every study table's
stem to its DataFrame; it returns a matplotlib Figure, or ``(figure, alt text)``
(docs/new-document.md).
"""

from abglib.common.jobs import log_to
from abglib.common.tables import read_table


def main(input, output, params) -> None:
    import importlib

    from abglib import AbglibValueError
    from abglib.common.plotting import save_figure

    module = importlib.import_module(f"abglib.replications.{params.doc}.figures")
    draw = getattr(module, "figure", None)
    if not callable(draw):
        raise AbglibValueError(
            f"{module.__file__} must define figure(name, tables), the figures of "
            f"{params.doc}'s document.yaml"
        )
    tables = {name: read_table(path) for name, path in input.items()}
    for name, path in output.items():
        out = draw(name, tables)
        fig, alt = out if isinstance(out, tuple) else (out, None)
        save_figure(fig, path, alt, dpi=params.dpi)


if "snakemake" in globals():
    log_to(snakemake.log[0])  # noqa: F821
    main(snakemake.input, snakemake.output, snakemake.params)  # noqa: F821
