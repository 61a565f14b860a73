"""What a report notebook calls to show its figures and tables (runs inside the kernel).

``R = Report(doc, figures, tables, made_by)`` after the parameters cell, then

- ``R.read(key, **kw)`` reads ``tables[key]`` (CSV) and remembers where it came from;
- ``R.figure(key, caption)`` shows ``figures/<key>.png`` (linked, not embedded) as a
  numbered figure with its alt text and the rule that made it;
- ``R.table(df, caption)`` shows a numbered table (:func:`abglib.reporting.tables.table_html`);
  every other ``display(df)`` goes through the same formatter (installed by ``Report``);
- ``R.abstract(text)`` gives the report's short summary (markdown), which the page puts
  under its title and the index page beside its link;
- :func:`and_list` writes a list into a sentence ("a, b and c").

Figures and tables are referenced relative to the report's own folder, where the report
rule copies them (``figures/<key>.png``, ``tables/<key>.csv``).
"""

from __future__ import annotations

import html
from collections.abc import Mapping
from pathlib import Path

import pandas as pd

from ..common.pngmeta import png_description
from .tables import GROUP_MIN, table_html

__all__ = ["Report", "and_list"]


def and_list(words) -> str:
    """``'a, b and c'``: the words of a sentence's list (``''`` for none).

    >>> and_list(["eq 25", "eq 26", "eq 31"]), and_list(["X"]), and_list([])
    ('eq 25, eq 26 and eq 31', 'X', '')
    """
    words = [str(w) for w in words]
    return " and ".join(filter(None, [", ".join(words[:-1]), words[-1]])) if words else ""


def _plain(markdown: str) -> str:
    """Caption text without markdown markup, for an alt attribute."""
    for ch in ("*", "`", "$"):
        markdown = markdown.replace(ch, "")
    return " ".join(markdown.split())


def _caption(markdown: str) -> str:
    from .page import markdown_html

    return markdown_html(markdown, inline=True) if markdown else ""


class Report:
    """Numbered figures and tables of one report, with where each came from.

    Parameters
    ----------
    doc : str
        Document key (the report's folder name).
    figures, tables : mapping
        ``{key: path}`` of the figures (PNG) and tables (CSV) the pipeline passed in.
    made_by : mapping, optional
        ``{file name: (rule, script)}``: the rule that wrote each figure or table and its
        script, shown under each caption.
    notebook : str
        The notebook's path in the repository (shown for tables computed in the notebook).
    install : bool
        Install :meth:`table` as the HTML formatter of every DataFrame displayed.
    released : iterable of str, optional
        File names of the tables copied beside the page (the report rule's ``tables``
        outputs); a table the page shows but does not copy (wall-clock timings) is named
        by its path in the build instead of linked. Default: every table is copied.
    """

    def __init__(
        self,
        doc: str,
        figures: Mapping[str, str],
        tables: Mapping[str, str],
        made_by: Mapping | None = None,
        notebook: str | None = None,
        install: bool = True,
        released=None,
    ):
        self.doc = doc
        self.released = None if released is None else set(released)
        self.figures = dict(figures)
        self.tables = dict(tables)
        self.made_by = {k: tuple(v) for k, v in (made_by or {}).items()}
        self.notebook = notebook or f"workflow/notebooks/{doc}.py"
        self.n_figures = 0
        self.n_tables = 0
        if install:
            self._install()

    # -- provenance -------------------------------------------------------------------
    def _rule(self, filename: str) -> str:
        rule = self.made_by.get(filename)
        if not rule:
            return ""
        name, script = rule
        where = f" (<code>{html.escape(script)}</code>)" if script else ""
        return f"made by rule <code>{html.escape(name)}</code>{where}"

    def _table_source(self, key: str | None) -> str:
        if key is None or key not in self.tables:
            return (
                "Computed for this page by the report's notebook "
                f'(<a href="notebook.py"><code>{html.escape(self.notebook)}</code></a>).'
            )
        name = Path(self.tables[key]).name
        rule = self._rule(name)
        if self.released is not None and name not in self.released:
            where = html.escape(Path(self.tables[key]).as_posix())
            link = f"<code>{where}</code> of the build (not a release table)"
        else:
            link = f'<a href="tables/{html.escape(name)}">tables/{html.escape(name)}</a>'
        return f"From {link}{', ' + rule if rule else ''}."

    # -- reading ------------------------------------------------------------------------
    def read(self, key: str, reader=None, **kwargs) -> pd.DataFrame:
        """Read ``tables[key]`` with ``reader`` (default
        :func:`~abglib.common.tables.read_table`: a round-off bound such as ``<1e-11``
        read as 0.0 in a column of numbers) and tag it with its source
        (``df.attrs["source"]``, kept by pandas through most operations)."""
        if key not in self.tables:
            raise KeyError(
                f"table {key!r} is not an input of this report; have {sorted(self.tables)}"
            )
        from ..common.tables import read_table

        df = (reader or read_table)(self.tables[key], **kwargs)
        df.attrs["source"] = key
        return df

    # -- showing ------------------------------------------------------------------------
    def table_markup(
        self,
        df: pd.DataFrame,
        caption: str | None = None,
        source: str | None = None,
        group_by: tuple = (),
        group_min: int = GROUP_MIN,
    ) -> str:
        """The HTML of a numbered table (the next number)."""
        self.n_tables += 1
        key = source if source is not None else df.attrs.get("source")
        return table_html(
            df,
            caption=_caption(caption or df.attrs.get("caption") or ""),
            number=self.n_tables,
            source=self._table_source(key),
            attrs={"id": f"tab-{self.n_tables}"},
            group_by=group_by,
            group_min=group_min,
        )

    def table(
        self,
        df: pd.DataFrame,
        caption: str | None = None,
        source: str | None = None,
        group_by: tuple = (),
        group_min: int = GROUP_MIN,
    ) -> None:
        """Display ``df`` as a numbered table with ``caption`` and its source; ``group_by``
        collapses runs of rows sharing those columns' values (see ``table_html``)."""
        from IPython.display import HTML, display

        display(HTML(self.table_markup(df, caption, source, group_by, group_min)))

    def figure(self, key: str, caption: str = "", alt: str | None = None) -> None:
        """Display ``figures/<key>.png`` as a numbered figure.

        The alt text is, in order: ``alt``; the PNG's ``Description`` text chunk (written
        by the figure's script); the caption.
        """
        from IPython.display import HTML, display

        if key not in self.figures:
            raise KeyError(
                f"figure {key!r} is not an input of this report; have {sorted(self.figures)}"
            )
        path = Path(self.figures[key])
        self.n_figures += 1
        n = self.n_figures
        if alt is None:
            alt = png_description(path) or _plain(caption) or f"Figure {n}"
        name = html.escape(path.name)
        rule = self._rule(path.name)
        made = f' <span class="made-by">{rule[0].upper() + rule[1:]}.</span>' if rule else ""
        display(
            HTML(
                f'<figure class="abg-figure" id="fig-{n}">'
                f'<a href="figures/{name}"><img src="figures/{name}" alt="{html.escape(alt)}">'
                "</a>"
                f"<figcaption><b>Figure {n}.</b> {_caption(caption)}{made}</figcaption></figure>"
            )
        )

    def abstract(self, text: str) -> None:
        """The report's short summary (markdown); the page lifts it under the title."""
        from IPython.display import display

        display({"text/markdown": text, "text/plain": text}, raw=True, metadata={"abstract": True})

    def _install(self) -> None:
        try:
            from IPython import get_ipython
        except ImportError:  # pragma: no cover - IPython comes with ipykernel
            return
        ip = get_ipython()
        if ip is None:
            return
        ip.display_formatter.formatters["text/html"].for_type(pd.DataFrame, self.table_markup)
