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

The tolerance is half a unit in the last printed digit
(:func:`abglib.verdicts.tolerance_from_printed`) unless an override (with a reason) is
given, e.g. for a value read off a graph. Judging is the verdict engine's
(:mod:`abglib.verdicts`); the claim model (``abglib.replications._claims``) builds each
document's table from its claims; writing a table at its columns' precision is
:func:`abglib.common.tables.write_csv`.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from pathlib import Path

import pandas as pd

from .._checks import AbglibValueError
from ..verdicts import Alternative, parse_printed
from ..verdicts._judge import HAND_WRITTEN, _assess, _text, judge_sentences

__all__ = [
    "ALTERNATIVE_COLUMNS",
    "COMPARISON_COLUMNS",
    "PUBLISHED_COLUMNS",
    "REPRODUCED_COLUMNS",
    "SCORECARD_COLUMNS",
    "SENTENCE_COLUMN",
    "VERDICTS",
    "build_comparison",
    "non_matches",
    "read_published",
    "scorecard",
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
