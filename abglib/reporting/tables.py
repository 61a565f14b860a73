"""Tables of the reports as HTML: one verdict colour scheme, blank empty cells, no index
column, long runs of identical verdicts and notes collapsed into one ``<details>`` group.

The markup is the contract with ``assets/report.css`` and ``assets/report.js`` (sorting,
filtering) and with the browser test:

- ``figure.abg-table`` wraps a table and its ``figcaption``; ``div.scroll`` lets a wide
  table scroll inside the page (and print whole); ``div.scroll.long`` also limits the
  height of a table of more than ``LONG_ROWS`` rows on screen (not in print);
- ``table.data`` is a data table; each body row carries ``data-verdict``,
  ``data-section`` (the part of ``item`` before its first comma) and ``data-robust`` when
  the table has those columns, which the filters use;
- a verdict cell holds ``span.v.v-<verdict>`` (``match``, ``mismatch``, ``explained``,
  ``not_reproducible``); a robustness cell ``span.v.r-true`` / ``span.v.r-false``;
- ``tr.group`` is a collapsed run of rows: one cell holding ``details`` whose ``summary``
  names the count, the verdict and the note (or the reason the notes start with, up to their
  first ";"), and whose body is a ``table.data.inner`` with every row of the run.
"""

from __future__ import annotations

import html
import math
from collections.abc import Mapping, Sequence

import pandas as pd

__all__ = ["VERDICTS", "cell_strings", "group_runs", "note_reason", "section_of", "table_html"]

#: verdicts in the order they are listed everywhere (counts, bars, filters)
VERDICTS = ("match", "mismatch", "explained", "not_reproducible")
#: a run of at least this many consecutive rows with one verdict and one note is collapsed
GROUP_MIN = 6
#: a table with more rows (after grouping) scrolls inside a box of limited height on screen
LONG_ROWS = 30


def _blank(value) -> bool:
    if value is None or value is pd.NA or value is pd.NaT:
        return True
    if isinstance(value, float) and math.isnan(value):
        return True
    return isinstance(value, str) and value.strip().lower() in ("", "nan", "<na>", "none")


def cell_strings(df: pd.DataFrame) -> list[list[str]]:
    """Every cell of ``df`` as text, column by column formatted as pandas displays it
    (``display.precision``), with empty, ``NaN`` and ``<NA>`` cells blank (pandas'
    formatter, through :func:`abglib._compat.pandas.format_column`)."""
    from .._compat.pandas import format_column

    digits = pd.get_option("display.precision")
    cols = []
    for j in range(df.shape[1]):
        values = df.iloc[:, j]
        raw = values.to_numpy(dtype=object)
        if pd.api.types.is_bool_dtype(values) or values.dtype == object:
            text = ["" if _blank(v) else str(v) for v in raw]
        else:
            formatted = format_column(values, digits, na_rep="")
            text = ["" if _blank(v) else s.strip() for v, s in zip(raw, formatted, strict=True)]
        cols.append(text)
    return [list(r) for r in zip(*cols, strict=True)] if cols else [[] for _ in range(len(df))]


def section_of(item: str) -> str:
    """The document section of a ``comparison.csv`` item: the text before its first comma
    (``"Table 1, alpha=0.3, exact overshoot"`` -> ``"Table 1"``)."""
    return str(item).split(",")[0].strip()


def group_runs(keys: Sequence, minimum: int = GROUP_MIN) -> list[tuple[int, int]]:
    """``(start, stop)`` of every run of at least ``minimum`` consecutive equal keys; a key
    of ``None`` never groups."""
    runs, start = [], 0
    for i in range(1, len(keys) + 1):
        if i == len(keys) or keys[i] != keys[start] or keys[start] is None:
            if keys[start] is not None and i - start >= minimum:
                runs.append((start, i))
            start = i
    return runs


def note_reason(note: str) -> str:
    """The reason a note starts with: its text up to the first ``;`` (notes of one kind
    share it and go on with row-specific numbers)."""
    return note.split(";")[0].strip()


def _flat(df: pd.DataFrame) -> pd.DataFrame:
    """No index column: a default index is dropped, a meaningful one becomes a column."""
    if isinstance(df.columns, pd.MultiIndex):
        df = df.copy()
        df.columns = [" / ".join(str(c) for c in col if str(c)) for col in df.columns]
    # an unnamed integer index is a row counter (also after filtering): not shown
    plain = (
        df.index.nlevels == 1 and df.index.name is None and pd.api.types.is_integer_dtype(df.index)
    )
    if plain:
        return df.reset_index(drop=True)
    out = df.copy()
    out.index.names = [n if n is not None else "" for n in out.index.names]
    return out.reset_index()


def _cell(col: str, text: str, numeric: bool) -> str:
    esc = html.escape(text)
    if text in VERDICTS:
        return f'<td class="verdict"><span class="v v-{esc}">{esc}</span></td>'
    if col == "robust" and text in ("true", "false", "True", "False"):
        flag = text.lower()
        return f'<td class="robust"><span class="v r-{flag}">{esc}</span></td>'
    if numeric:
        return f'<td class="num">{esc}</td>'
    cls = ' class="note"' if col in ("note", "notes") or len(text) > 60 else ""
    return f"<td{cls}>{esc}</td>"


def _head(columns: Sequence[str]) -> str:
    return "<thead><tr>" + "".join(f"<th>{html.escape(c)}</th>" for c in columns) + "</tr></thead>"


def table_html(
    df: pd.DataFrame,
    *,
    caption: str | None = None,
    number: int | None = None,
    source: str | None = None,
    group_min: int = GROUP_MIN,
    attrs: Mapping[str, str] | None = None,
    group_by: Sequence[str] = (),
) -> str:
    """``df`` as a ``figure.abg-table``: caption, optional provenance line, scrolling table.

    Parameters
    ----------
    df : DataFrame
        Any table; its index is dropped when it is the default one and shown as a column
        otherwise.
    caption : str, optional
        Caption text (HTML allowed: it is inserted as is).
    number : int, optional
        Table number; the caption then starts with "Table <number>.".
    source : str, optional
        A provenance line (HTML) placed after the caption, e.g. the CSV and the rule.
    group_min : int
        Runs of at least this many consecutive rows with the same ``verdict`` and ``note``
        are collapsed into one ``tr.group``; 0 disables grouping.
    attrs : mapping, optional
        Extra attributes of the ``figure`` element (e.g. ``{"id": "tab-3"}``).
    group_by : sequence of str
        Group the rows with the same values in these columns instead (for tables without
        verdicts, e.g. one group per equation): rows of one key are brought together, keys
        in order of first appearance, and a key with at least ``group_min`` rows is one group.
    """
    flat = _flat(df)
    columns = [str(c) for c in flat.columns]
    numeric = [
        pd.api.types.is_numeric_dtype(flat.iloc[:, j])
        and not pd.api.types.is_bool_dtype(flat.iloc[:, j])
        for j in range(flat.shape[1])
    ]
    text = cell_strings(flat)
    idx = {c: i for i, c in enumerate(columns)}
    keys: list = [None] * len(text)
    shared = tuple(group_by) if group_by else ("verdict", "note")
    missing = [c for c in shared if c not in idx]
    if group_by and missing:
        raise KeyError(f"group_by columns {missing} are not columns of the table {columns}")
    if not missing and group_min:
        keys = [tuple(r[idx[c]] for c in shared) for r in text]
        if group_by:  # rows of one key together, keys in order of first appearance
            first = {k: i for i, k in reversed(list(enumerate(keys)))}
            order = sorted(range(len(keys)), key=lambda i: first[keys[i]])
            text, keys = [text[i] for i in order], [keys[i] for i in order]
        if not group_by:  # rows share a verdict and the reason their notes start with
            keys = [(v, note_reason(n)) if n else None for v, n in keys]

    def data_attrs(rows: Sequence[Sequence[str]]) -> str:
        out = []
        for name, col in (("verdict", "verdict"), ("robust", "robust")):
            if col in idx:
                vals = sorted({r[idx[col]] for r in rows})
                out.append(f' data-{name}="{html.escape(" ".join(vals))}"')
        if "item" in idx:
            secs = sorted({section_of(r[idx["item"]]) for r in rows})
            out.append(f' data-section="{html.escape("|".join(secs))}"')
        return "".join(out)

    def row(r: Sequence[str], skip: frozenset = frozenset()) -> str:
        cells = "".join(_cell(c, r[j], numeric[j]) for j, c in enumerate(columns) if c not in skip)
        return f"<tr{'' if skip else data_attrs([r])}>{cells}</tr>"

    body, i = [], 0
    runs = dict(group_runs(keys, group_min)) if group_min else {}
    while i < len(text):
        if i in runs:
            stop = runs[i]
            drop = set(shared)
            if not group_by and len({r[idx["note"]] for r in text[i:stop]}) > 1:
                drop.discard("note")  # the notes differ after their shared reason: kept
            inner_cols = [c for c in columns if c not in drop]
            inner = "".join(row(r, frozenset(drop)) for r in text[i:stop])
            if group_by:
                what = ", ".join(
                    f"{c} = {html.escape(v)}" for c, v in zip(shared, keys[i], strict=True)
                )
                summary = f"{stop - i} rows with {what}"
            else:
                verdict, note = keys[i]
                same = "the note" if "note" in drop else "notes starting"
                summary = (
                    f'{stop - i} rows, all <span class="v v-{html.escape(verdict)}">'
                    f"{html.escape(verdict)}</span> with {same}: {html.escape(note)}"
                )
            body.append(
                f'<tr class="group"{data_attrs(text[i:stop])}><td colspan="{len(columns)}">'
                f"<details><summary>{summary}</summary>"
                f'<table class="data inner">{_head(inner_cols)}<tbody>{inner}</tbody></table>'
                "</details></td></tr>"
            )
            i = stop
        else:
            body.append(row(text[i]))
            i += 1
    filters = [c for c in ("verdict", "item", "robust") if c in idx] if "verdict" in idx else []
    label = f"<b>Table {number}.</b> " if number is not None else ""
    cap = ""
    if caption or number is not None or source:
        extra = f' <span class="made-by">{source}</span>' if source else ""
        cap = f"<figcaption>{label}{caption or ''}{extra}</figcaption>"
    attr = "".join(f' {k}="{html.escape(str(v))}"' for k, v in (attrs or {}).items())
    filt = f' data-filters="{" ".join(filters)}"' if filters else ""
    scroll = "scroll long" if len(body) > LONG_ROWS else "scroll"
    return (
        f'<figure class="abg-table"{attr}>{cap}<div class="{scroll}">'
        f'<table class="data"{filt}>{_head(columns)}<tbody>{"".join(body)}</tbody></table>'
        "</div></figure>"
    )
