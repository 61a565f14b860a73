"""Tables a rebuild writes byte for byte: each column at the digits it is reproducible to.

The one home of writing and reading the project's CSV tables, shared by every layer above
the core (the benchmark, the replications, the reports): a column's declared precision
(:func:`with_precision`, digits or a round-off bound such as ``"<1e-12"``, the
:func:`format_cell` grammar), merged with the precision derived for that table by
``abglib precision`` (:func:`precision_for`, reading the generated
``abglib.common._precision_table``; the derivation is ``abglib.reporting.precision``),
the formatted text (:func:`csv_text`), the atomic write (:func:`write_csv`) and the read
back for display (:func:`read_table`). Numbers use the verdict engine's deterministic
:func:`abglib.verdicts.format_number` (``shared/CONTRACTS.md`` section 3: "numbers are
written with the significant digits they are reproducible to").
"""

from __future__ import annotations

import math
import os
from collections.abc import Mapping
from pathlib import Path

import numpy as np
import pandas as pd

from .._checks import AbglibValueError
from ..verdicts import SIGNIFICANT_DIGITS, format_number

__all__ = [
    "RAW_DIGITS",
    "RAW_ENV",
    "ROUNDOFF",
    "csv_text",
    "format_cell",
    "format_table",
    "merge_specs",
    "precision_for",
    "raw_tables",
    "read_table",
    "roundoff",
    "stricter",
    "table_key",
    "with_precision",
    "write_csv",
]

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
    from .files import atomic_output

    digits, precision = precision_for(df, path, digits, precision)
    text = csv_text(df, digits, precision)
    with atomic_output(path) as tmp:
        tmp.write_text(text, encoding="utf-8", newline="")


# --------------------------------------------------------------------------- precision
#: environment variable: ``1`` writes every float at :data:`RAW_DIGITS` digits, no bounds
RAW_ENV = "ABGLIB_RAW_TABLES"
#: digits of a raw table: enough to round-trip any float64
RAW_DIGITS = 17


def raw_tables() -> bool:
    """Whether ``ABGLIB_RAW_TABLES`` asks for raw tables (``1``) or not (unset, ``0``)."""
    text = os.environ.get(RAW_ENV, "").strip()
    if text not in ("", "0", "1"):
        raise AbglibValueError(f"{RAW_ENV} must be 0 or 1 (or unset), got {text!r}")
    return text == "1"


def table_key(path) -> str:
    """The key of a table in the precision table: ``<folder>/<stem>`` of its file
    (``results/alwagih/table1.csv`` -> ``alwagih/table1``); one benchmark cell's table
    (``results/benchmark/cells/<variant>/<scenario>.csv``) has the key of the matrix it
    is a row of, ``benchmark/cells``, so that a new variant's cells get its precision."""
    p = Path(path)
    if len(p.parts) >= 4 and p.parts[-3] == "cells":
        return f"{p.parts[-4]}/cells"
    return f"{p.parent.name}/{p.stem}"


def _parse(spec) -> tuple[float | None, int | None]:
    """``(bound, digits)`` of a spec: ``6`` -> (None, 6), ``"<1e-12"`` -> (1e-12, None),
    ``"<1e-10:5"`` -> (1e-10, 5)."""
    if isinstance(spec, bool) or not isinstance(spec, (int, str)):
        raise AbglibValueError(f"a precision is digits (int) or '<bound[:digits]', got {spec!r}")
    if isinstance(spec, int):
        if spec < 1:
            raise AbglibValueError(f"a precision's digits must be >= 1, got {spec}")
        return None, spec
    if not spec.startswith("<"):
        raise AbglibValueError(f"a precision string must start with '<', got {spec!r}")
    bound, _, n = spec[1:].partition(":")
    try:
        return float(bound), (int(n) if n else None)
    except ValueError:
        raise AbglibValueError(f"a precision must be '<bound[:digits]', got {spec!r}") from None


def _spec(bound: float | None, digits: int | None):
    if bound is None:
        return digits
    text = f"{bound:g}"
    return f"<{text}:{digits}" if digits is not None else f"<{text}"


def stricter(a, b):
    """The stricter of two precision specs: the larger bound and the fewer digits."""
    if a is None:
        return b
    if b is None:
        return a
    (ba, na), (bb, nb) = _parse(a), _parse(b)
    bounds = [x for x in (ba, bb) if x is not None]
    digits = [x for x in (na, nb) if x is not None]
    return _spec(max(bounds) if bounds else None, min(digits) if digits else None)


def merge_specs(*tables: Mapping[str, Mapping[str, object]]) -> dict[str, dict[str, object]]:
    """Merge ``{table: {column: spec}}`` mappings, the stricter spec winning."""
    out: dict[str, dict[str, object]] = {}
    for table in tables:
        for key, cols in table.items():
            dest = out.setdefault(key, {})
            for col, spec in cols.items():
                dest[col] = stricter(dest.get(col), spec)
    return out


def _derived() -> Mapping[str, Mapping[str, object]]:
    from ._precision_table import PRECISION

    return PRECISION


def precision_for(df, path, digits: int, precision=None) -> tuple[int, dict]:
    """The ``(digits, precision)`` :func:`write_csv` writes
    ``df`` at ``path`` with: the code's declared precision (``precision``, else
    ``df.attrs["precision"]``) merged with the derived one of this table (stricter wins,
    derived digits never more than ``digits``). In a raw build (``ABGLIB_RAW_TABLES=1``):
    :data:`RAW_DIGITS` digits and no declared precision."""
    if raw_tables():
        return RAW_DIGITS, {}
    declared = dict(df.attrs.get("precision", {}) if precision is None else precision)
    derived = _derived().get(table_key(path), {})
    merged = dict(declared)
    for col, spec in derived.items():
        if col in df.columns:
            merged[col] = stricter(merged.get(col), _capped(spec, digits))
    return digits, merged


def _capped(spec, digits: int):
    bound, n = _parse(spec)
    if bound is None:
        return spec if n < digits else None
    return _spec(bound, None if n is None else min(n, digits))
