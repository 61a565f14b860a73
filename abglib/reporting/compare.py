"""Published-versus-reproduced tables: ``comparison.csv`` and the scorecard.

Implements ``shared/CONTRACTS.md`` section 3. The published numbers of a source document
are transcribed once, as the *printed strings*, into ``data/published/<doc>/*.csv`` with
columns ``key, item, quantity, published, where`` (see :data:`PUBLISHED_COLUMNS`); a
pipeline rule computes the reproduced value of every key with :mod:`abglib`; this module
joins the two and gives each row a verdict:

``match``
    ``|reproduced - published| <= tolerance``.
``explained``
    not a match, but an *alternative* quantity or interpretation, computed by abglib and
    shown in the report, reproduces the printed number within tolerance (the note names
    the alternative and the report section that demonstrates it).
``mismatch``
    neither; the note says what is known.
``not_reproducible``
    no reproduced value (damaged print, a number read off a lost figure, ...); the note
    says why.

A qualitative claim has an empty ``published`` field and a boolean ``reproduced`` value
(the outcome of a check): ``match`` when the check holds, ``mismatch`` otherwise.

The tolerance is half a unit in the last printed digit (:func:`tolerance_from_printed`)
unless an override (with a reason) is given, e.g. for a value read off a graph.

Numbers are written with a fixed number of significant digits (:func:`format_number`) so
that a rebuild gives identical bytes.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from pathlib import Path

import numpy as np
import pandas as pd

from .._checks import AbglibValueError

# the judging half lives in abglib.verdicts (one home for judging); re-exported here so
# that every existing import keeps working
from ..verdicts import (  # noqa: F401
    SIGNIFICANT_DIGITS,
    Alternative,
    format_number,
    judge,
    parse_printed,
    tolerance_from_printed,
    verdict,
    within_tolerance,
)
from ..verdicts._judge import HAND_WRITTEN, _assess, _text, judge_sentences

__all__ = [
    "ALTERNATIVE_COLUMNS",
    "COMPARISON_COLUMNS",
    "PUBLISHED_COLUMNS",
    "REPRODUCED_COLUMNS",
    "SCORECARD_COLUMNS",
    "VERDICTS",
    "Alternative",
    "build_comparison",
    "ROUNDOFF",
    "format_cell",
    "format_number",
    "roundoff",
    "with_precision",
    "read_table",
    "csv_text",
    "format_table",
    "judge",
    "parse_printed",
    "read_published",
    "scorecard",
    "tolerance_from_printed",
    "verdict",
    "write_csv",
]

#: Columns of ``results/<doc>/comparison.csv``, in contract order.
COMPARISON_COLUMNS = [
    "doc",
    "item",
    "quantity",
    "published",
    "reproduced",
    "abs_err",
    "rel_err",
    "tolerance",
    "verdict",
    "note",
    "depends_on",
    "robust",
    "reading",
    "chance",
]
#: Verdicts, in scorecard column order.
VERDICTS = ["match", "mismatch", "explained", "not_reproducible"]
#: Columns of ``results/scorecard.csv``.
SCORECARD_COLUMNS = ["doc", *VERDICTS, "total", "robust", "fragile"]
#: Required columns of a transcription file ``data/published/<doc>/*.csv``.
PUBLISHED_COLUMNS = ["key", "item", "quantity", "published", "where"]
#: Optional column of a transcription file: rows sharing a value were transcribed from one
#: printed sentence or table cell group and are judged together
#: (:func:`abglib.verdicts.judge_sentences`).
SENTENCE_COLUMN = "sentence"
#: Columns of the reproduced-values table written by a document's reproducing rule.
REPRODUCED_COLUMNS = ["key", "reproduced", "note"]
#: Columns of the alternatives table written by a document's reproducing rule.
ALTERNATIVE_COLUMNS = ["key", "alternative", "value", "section"]


# --------------------------------------------------------------------------- numbers
#: Below this relative size a difference between two exact routes is floating-point
#: round-off: it moves with the BLAS kernel and the summation order, so it is written as
#: this bound (notes: :func:`roundoff`; tables: precision ``"<1e-12"``), never as digits.
ROUNDOFF = 1e-12


def roundoff(x, digits: int = 3, bound: float = ROUNDOFF) -> str:
    """A difference for a note: ``'< 1e-12'`` when it is round-off, else ``digits``
    significant digits (e.g. a misprint's relative error ``'0.134'``)."""
    xf = float(x)
    if math.isfinite(xf) and abs(xf) < bound:
        return f"< {bound:g}"
    return format_number(xf, digits)


def format_cell(x, spec) -> str:
    """Format one number under a column's declared precision.

    ``spec`` is an int (significant digits) or a string ``"<B"`` with ``B`` a number
    (e.g. ``"<1e-12"``): a round-off column, whose values below ``B`` in magnitude are
    written as the bound ``<B`` (their digits are noise), others with 10 significant
    digits; ``"<B:n"`` writes the others with ``n`` digits.
    """
    if isinstance(spec, str):
        body = spec[1:] if spec.startswith("<") else ""
        bound, _, n = body.partition(":")
        try:
            limit = float(bound)
        except ValueError:
            raise AbglibValueError(
                f"a precision must be digits (int) or '<bound' such as '<1e-12', got {spec!r}"
            ) from None
        if x is not None and not isinstance(x, (str, bool, np.bool_)):
            xf = float(x)
            if not math.isnan(xf) and abs(xf) < limit:
                return f"<{bound}"
        return format_number(x, int(n) if n else SIGNIFICANT_DIGITS)
    return format_number(x, int(spec))


def with_precision(df: pd.DataFrame, **columns) -> pd.DataFrame:
    """``df`` (a shallow copy) declaring the precision of some of its columns, e.g.
    ``with_precision(t, rel_diff="<1e-12", pole_radius=4)`` (:func:`format_cell`);
    :func:`write_csv` writes them so."""
    out = df.copy(deep=False)
    out.attrs = {**df.attrs, "precision": {**df.attrs.get("precision", {}), **columns}}
    return out


def read_table(path, **kwargs) -> pd.DataFrame:
    """Read a table written by :func:`write_csv` for display or further computing: a
    column of numbers whose round-off cells are written as a bound (``<1e-12``) is read as
    numbers, each bound as 0.0 (zero within round-off), so that the notebooks and figure
    scripts can format and plot it; a column asked for as ``str`` (``dtype=str`` or
    ``dtype={col: str}``) stays as written."""
    df = pd.read_csv(path, **kwargs)
    asked = kwargs.get("dtype")
    if asked is str:  # the caller asked for the text as written
        return df
    as_text = {c for c, t in asked.items() if t is str} if isinstance(asked, dict) else set()
    for col in df.columns:
        if col in as_text:
            continue
        if not (df[col].dtype == object or pd.api.types.is_string_dtype(df[col])):
            continue
        text = df[col].dropna().astype(str)
        bounds = text.str.startswith("<")
        if not bounds.any():
            continue
        rest = pd.to_numeric(text[~bounds], errors="coerce")
        bound_values = pd.to_numeric(text[bounds].str[1:], errors="coerce")
        if rest.isna().any() or bound_values.isna().any():
            continue
        df[col] = pd.to_numeric(df[col].where(~df[col].astype(str).str.startswith("<"), "0"))
    return df


def _declared_precision(df: pd.DataFrame, precision) -> dict:
    """``precision`` (default ``df.attrs["precision"]``), checked against the columns."""
    precision = dict(df.attrs.get("precision", {}) if precision is None else precision)
    unknown = sorted(set(precision) - set(df.columns))
    if unknown:
        raise AbglibValueError(f"precision declared for columns the table lacks: {unknown}")
    return precision


def _is_formatted(dtype) -> bool:
    """Whether a column of ``dtype`` is written through :func:`format_cell` (floats and
    objects; other columns as pandas writes them)."""
    return pd.api.types.is_float_dtype(dtype) or (isinstance(dtype, np.dtype) and dtype.kind == "O")


def _formatted(values, spec) -> list[str]:
    return [v if isinstance(v, str) else format_cell(v, spec) for v in values]


def format_table(
    df: pd.DataFrame, digits: int = SIGNIFICANT_DIGITS, precision=None
) -> pd.DataFrame:
    """Copy of ``df`` with every float column formatted at its precision.

    ``precision`` (default ``df.attrs["precision"]``) maps a column to its declared
    precision (:func:`format_cell`): the digits it is reproducible to. Other columns get
    ``digits`` significant digits.
    """
    precision = _declared_precision(df, precision)
    out = df.copy()
    for col in out.columns:
        if _is_formatted(out[col].dtype):
            out[col] = _formatted(out[col], precision.get(col, digits))
    return out


def _column_text(col: pd.Series, spec) -> list[str] | None:
    """A column as ``to_csv`` writes it after :func:`format_table`, or None for a dtype
    this route does not cover (nullable integers, categories, dates...)."""
    dtype = col.dtype
    if _is_formatted(dtype):
        return _formatted(col.tolist(), spec)
    if isinstance(dtype, np.dtype) and dtype.kind == "b":
        return ["True" if v else "False" for v in col.tolist()]
    if isinstance(dtype, np.dtype) and dtype.kind in "iu":
        return [str(v) for v in col.tolist()]
    if pd.api.types.is_string_dtype(dtype):
        return ["" if v is None or v is pd.NA or v != v else str(v) for v in col.tolist()]
    return None


def csv_text(df: pd.DataFrame, digits: int = SIGNIFICANT_DIGITS, precision=None) -> str:
    """The CSV text :func:`write_csv` writes: ``format_table(df).to_csv(index=False)``.

    Written row by row with :mod:`csv` (the writer ``to_csv`` itself uses, same quoting)
    from the formatted columns, which for a small table is ~20x cheaper than building the
    formatted frame; a table with a column of another dtype or with multi-level columns
    takes pandas' route. Both give the same bytes (``tests/test_compare.py``).
    """
    import csv
    import io

    precision = _declared_precision(df, precision)
    columns = None
    if not isinstance(df.columns, pd.MultiIndex) and df.shape[1] > 0:
        columns = [
            _column_text(df.iloc[:, i], precision.get(c, digits)) for i, c in enumerate(df.columns)
        ]
        if any(text is None for text in columns):
            columns = None
    if columns is None:
        return format_table(df, digits, precision).to_csv(index=False, lineterminator="\n")
    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow([str(c) for c in df.columns])
    writer.writerows(zip(*columns, strict=True))
    return buf.getvalue()


def write_csv(df: pd.DataFrame, path, digits: int = SIGNIFICANT_DIGITS, precision=None) -> None:
    """Write ``df`` as CSV at each column's declared precision, atomically.

    Numbers get ``digits`` significant digits unless ``precision`` (default
    ``df.attrs["precision"]``, set where the table is made) declares fewer for a column,
    or a bound for a round-off column (:func:`format_cell`), so that a rebuild on any
    machine writes identical bytes. The table goes to a temporary file beside ``path``
    that replaces it only once complete: an interrupted run leaves no half-written table.
    """
    from .pipeline import atomic_output
    from .precision import precision_for

    digits, precision = precision_for(df, path, digits, precision)
    text = csv_text(df, digits, precision)
    with atomic_output(path) as tmp:
        tmp.write_text(text, encoding="utf-8", newline="")


# --------------------------------------------------------------------------- inputs
def read_published(paths: Iterable) -> pd.DataFrame:
    """Read and check transcription files; ``published`` stays the printed string.

    Raises
    ------
    AbglibValueError
        Naming the file and column when a required column is missing, a key is
        duplicated, or a published value is not a number as printed.
    """
    frames = []
    for p in sorted(Path(p) for p in paths):
        df = pd.read_csv(p, dtype=str, keep_default_na=False, comment="#")
        missing = [c for c in PUBLISHED_COLUMNS if c not in df.columns]
        if missing:
            raise AbglibValueError(
                f"{p.name}: published table must have columns {PUBLISHED_COLUMNS}, "
                f"missing {missing}"
            )
        for key, text in zip(df["key"], df["published"], strict=True):
            if text.strip():
                try:
                    parse_printed(text)
                except AbglibValueError as exc:
                    raise AbglibValueError(f"{p.name}, key {key!r}: {exc}") from None
        if SENTENCE_COLUMN not in df.columns:
            df[SENTENCE_COLUMN] = ""
        frames.append(df[[*PUBLISHED_COLUMNS, SENTENCE_COLUMN]])
    if not frames:
        raise AbglibValueError("no published tables given")
    out = pd.concat(frames, ignore_index=True)
    dup = out["key"][out["key"].duplicated()].tolist()
    if dup:
        raise AbglibValueError(f"published keys must be unique, got duplicates {dup}")
    return out


def build_comparison(
    doc: str,
    published: pd.DataFrame,
    reproduced: pd.DataFrame,
    alternatives: pd.DataFrame | None = None,
    overrides: Mapping[str, Mapping] | None = None,
) -> pd.DataFrame:
    """Join published and reproduced values into the contract's comparison table.

    Parameters
    ----------
    doc : str
        Document key (``shared/seeds/README.md``).
    published : DataFrame
        From :func:`read_published` (columns :data:`PUBLISHED_COLUMNS`, strings).
    reproduced : DataFrame
        Columns :data:`REPRODUCED_COLUMNS`: one row per key; ``reproduced`` empty/NaN when
        not reproducible; ``note`` explains any non-match (required for
        ``not_reproducible`` rows).
    alternatives : DataFrame, optional
        Columns :data:`ALTERNATIVE_COLUMNS` (several rows per key allowed).
    overrides : mapping, optional
        ``{key: {"tolerance": float, "reason": str}}``, e.g. for values read off a graph.

    Returns
    -------
    DataFrame with columns :data:`COMPARISON_COLUMNS`, in the order of ``published``.

    Raises
    ------
    AbglibValueError
        A published key without a reproduced row (or the reverse), an override for an
        unknown key or without a reason, or a not-reproducible row without a note.
    """
    overrides = dict(overrides or {})
    rep = _index_unique(reproduced, "reproduced")
    pub_keys = list(published["key"])
    missing = [k for k in pub_keys if k not in rep.index]
    extra = [k for k in rep.index if k not in set(pub_keys)]
    if missing or extra:
        raise AbglibValueError(
            f"{doc}: reproduced keys must equal published keys; "
            f"not reproduced: {missing}, not published: {extra}"
        )
    unknown = sorted(set(overrides) - set(pub_keys))
    if unknown:
        raise AbglibValueError(f"{doc}: tolerance override for unknown keys {unknown}")
    alts: dict[str, list[Alternative]] = {}
    if alternatives is not None and len(alternatives):
        bad = sorted(set(alternatives["key"]) - set(pub_keys))
        if bad:
            raise AbglibValueError(f"{doc}: alternatives for unknown keys {bad}")
        for row in alternatives.itertuples(index=False):
            family = getattr(row, "family", "") or HAND_WRITTEN
            alts.setdefault(row.key, []).append(
                Alternative(row.key, row.alternative, row.value, row.section, family)
            )

    judged = []
    for row in published.itertuples(index=False):
        r = rep.loc[row.key]
        j = _assess(doc, row, r["reproduced"], r.get("note", ""), alts.get(row.key, ()), overrides)
        vague = j.row.pop("robust", "")
        words = j.row.pop("vague", ())
        for col in ("depends_on", "robust"):
            j.row[col] = _text(r.get(col, ""))
        j.row["depends_on"] = ";".join(x for x in (j.row["depends_on"], *words) if x)
        if vague and not j.row["robust"]:
            j.row["robust"] = vague
        judged.append(j)
    sentences = published[SENTENCE_COLUMN] if SENTENCE_COLUMN in published else [""] * len(judged)
    rows = judge_sentences(judged, list(sentences))
    return pd.DataFrame(rows, columns=COMPARISON_COLUMNS)


def _index_unique(df: pd.DataFrame, name: str) -> pd.DataFrame:
    dup = df["key"][df["key"].duplicated()].tolist()
    if dup:
        raise AbglibValueError(f"{name} keys must be unique, got duplicates {dup}")
    return df.set_index("key")


def scorecard(comparisons: Iterable[pd.DataFrame]) -> pd.DataFrame:
    """One row per document: the count of each verdict and the total, and how many rows
    that depend on assumed inputs keep their verdict across the plausible ranges
    (``robust``) or flip (``fragile``) (contract section 3)."""
    rows = []
    for comp in comparisons:
        docs = comp["doc"].unique()
        if len(docs) != 1:
            raise AbglibValueError(f"a comparison table must hold one document, got {list(docs)}")
        counts = comp["verdict"].value_counts()
        unknown = sorted(set(counts.index) - set(VERDICTS))
        if unknown:
            raise AbglibValueError(f"verdict must be one of {VERDICTS}, got {unknown}")
        row = {"doc": docs[0], **{v: int(counts.get(v, 0)) for v in VERDICTS}}
        row["total"] = int(len(comp))
        robust = comp["robust"].astype(str).str.lower() if "robust" in comp else pd.Series([])
        row["robust"] = int((robust == "true").sum())
        row["fragile"] = int((robust == "false").sum())
        rows.append(row)
    return pd.DataFrame(rows, columns=SCORECARD_COLUMNS).sort_values("doc", ignore_index=True)


def non_matches(comparison: pd.DataFrame) -> pd.DataFrame:
    """The rows of one ``comparison.csv`` whose verdict is not ``match``, with the columns a
    reader needs to judge them (``item, published, reproduced, verdict, note``, and from
    v0.4.0 the explaining ``reading`` and its ``chance`` beside the verdict)."""
    cols = ["item", "published", "reproduced", "verdict", "note"]
    missing = sorted(set(cols) - set(comparison.columns))
    if missing:
        raise AbglibValueError(f"comparison table lacks columns {missing}")
    if {"reading", "chance"} <= set(comparison.columns):
        cols = [*cols[:4], "reading", "chance", "note"]
    return comparison.loc[comparison["verdict"] != "match", cols]
