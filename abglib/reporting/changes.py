"""What changed between two report versions: ``changes.csv`` and ``changes.html``.

Two version folders (``reports/v0.2.0`` and ``reports/v0.3.0``, or a build's
``results/reports/v<version>``) are compared document by document through their
``<doc>/tables/comparison.csv`` (``CONTRACTS.md`` §3). Each row of the older table is
paired with at most one row of the newer one (:func:`match_rows`); then

``added`` / ``removed``
    a row only in the newer / only in the older table;
``verdict``
    a paired row whose verdict changed (the note is the newer row's note, and says too
    when the value moved or the printed value was re-transcribed);
``moved``
    a paired row with the same verdict whose reproduced value moved by more than its
    tolerance (the ``tolerance`` column: half a unit in the last printed digit unless the
    config overrides it), or whose qualitative outcome changed, or that gained or lost a
    value. A qualitative row (empty ``published``) has no tolerance: any change counts.
``note``
    a paired row with the same verdict and value whose note changed, or its
    ``depends_on``, ``robust``, ``reading``, ``chance`` or printed value (the note gives
    the newer row's note, then the older one's, then the other columns that changed).
    What a reader of a note would otherwise miss: a verdict that holds at fewer of the
    plausible inputs than before, a trend found from another omega, a reading's chance.

``changes.csv`` has one row per change, columns :data:`CHANGES_COLUMNS`:

========== ==============================================================================
doc        document key
change     one of :data:`CHANGE_KINDS`
item       where the number is printed (the newer row's, for a pair)
quantity   what the number is (the newer row's, for a pair)
published  the number as printed (the newer row's, for a pair)
old_verdict, new_verdict   empty on the side that has no row
old_value, new_value       the reproduced values as written in the two tables
tolerance  the tolerance the move was judged against (empty for a qualitative row)
note       why: the newer row's note for a verdict change, the move in tolerances, the
           two notes for a ``note`` change, ...
========== ==============================================================================

Columns that only one version has (``depends_on`` and ``robust`` came with v0.3.0,
``reading`` and ``chance`` with v0.4.0) are ignored for pairing; their changes are
mentioned in the note of a row that changed for another reason, and a verdict change's
note starts with what changed it: the reading now accepted (with its chance), the reading
withdrawn, or a flip across the plausible inputs.
"""

from __future__ import annotations

import html
import math
import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from decimal import Decimal, InvalidOperation
from pathlib import Path

import pandas as pd

from .._checks import AbglibValueError
from ..verdicts import within_tolerance
from .versions import comparison_tables, previous_version

__all__ = [
    "CHANGES_COLUMNS",
    "CHANGE_KINDS",
    "Changes",
    "comparison_tables",
    "diff_folders",
    "diff_tables",
    "match_rows",
    "previous_version",
    "write_build_changes",
    "write_changes",
]

#: Columns of ``changes.csv``.
CHANGES_COLUMNS = [
    "doc",
    "change",
    "item",
    "quantity",
    "published",
    "old_verdict",
    "new_verdict",
    "old_value",
    "new_value",
    "tolerance",
    "note",
]
#: Kinds of change, in the order the page lists them.
CHANGE_KINDS = ["verdict", "moved", "note", "added", "removed"]

# the pairing passes, most specific first: (columns, name used in the note). A `key`
# column, where both tables have one, comes before all of them.
_PASSES = [
    (("item", "quantity", "published"), ""),
    (("item", "quantity"), "paired by item and quantity (the printed value changed)"),
    (("item", "published"), "paired by item and printed value (the quantity was reworded)"),
    (("quantity", "published"), "paired by quantity and printed value (the item was renamed)"),
]
_REQUIRED = ["item", "quantity", "published", "reproduced", "verdict"]


@dataclass
class Changes:
    """The changes between two version folders."""

    old: str
    new: str
    table: pd.DataFrame
    docs: list[str] = field(default_factory=list)
    #: per document: rows in the older and newer table
    rows: dict[str, tuple[int, int]] = field(default_factory=dict)
    #: per document: remarks on the table itself (columns added, a document new, ...)
    remarks: dict[str, list[str]] = field(default_factory=dict)

    def counts(self) -> pd.DataFrame:
        """One row per document, one column per kind of change, plus ``total``."""
        t = self.table
        rows = []
        for doc in self.docs:
            sub = t[t["doc"] == doc]
            row = {"doc": doc, **{k: int((sub["change"] == k).sum()) for k in CHANGE_KINDS}}
            row["total"] = len(sub)
            rows.append(row)
        return pd.DataFrame(rows, columns=["doc", *CHANGE_KINDS, "total"])


# ------------------------------------------------------------------------------ reading
def _read(path) -> pd.DataFrame:
    df = pd.read_csv(path, dtype=str, keep_default_na=False)
    missing = [c for c in _REQUIRED if c not in df.columns]
    if missing:
        raise AbglibValueError(
            f"{path}: a comparison table needs the columns {_REQUIRED}, missing {missing}"
        )
    return df


def _norm(text: str) -> str:
    return re.sub(r"\s+", " ", str(text)).strip()


# ------------------------------------------------------------------------------ pairing
def match_rows(old: pd.DataFrame, new: pd.DataFrame) -> list[tuple[int, int, str]]:
    """Pair rows of two comparison tables: ``[(old position, new position, how)]``.

    By ``key`` where both tables have that column, then by item + quantity + printed
    value, then by any two of them; a pass pairs only values that are unique among the
    rows still unpaired on both sides (text compared with whitespace collapsed). ``how``
    is empty for an exact pairing, else it says which fields differ.
    """
    left = set(range(len(old)))
    right = set(range(len(new)))
    pairs: list[tuple[int, int, str]] = []
    passes = list(_PASSES)
    if "key" in old.columns and "key" in new.columns:
        passes.insert(0, (("key",), "paired by key"))
    for cols, how in passes:
        ko = _keys(old, cols, left)
        kn = _keys(new, cols, right)
        for k, i in ko.items():
            j = kn.get(k)
            if j is not None:
                pairs.append((i, j, how))
                left.discard(i)
                right.discard(j)
    return sorted(pairs)


def _keys(df: pd.DataFrame, cols, positions) -> dict[tuple, int]:
    """Key -> position for the rows at ``positions`` whose key is unique among them and not
    empty in every field."""
    seen: dict[tuple, list[int]] = {}
    for i in sorted(positions):
        k = tuple(_norm(df.iloc[i][c]) for c in cols)
        if not any(k):
            continue
        seen.setdefault(k, []).append(i)
    return {k: v[0] for k, v in seen.items() if len(v) == 1}


# ------------------------------------------------------------------------------ values
def _number(text: str) -> float | None:
    s = str(text).strip()
    if s.startswith("<"):  # a round-off bound: zero within round-off
        s = "0"
    try:
        d = Decimal(s)
    except InvalidOperation:
        return None
    return float(d)


def _move(old: str, new: str, tol: str) -> tuple[bool, str]:
    """Whether the reproduced value moved beyond the tolerance, and how (for the note)."""
    a, b = str(old).strip(), str(new).strip()
    if a == b:
        return False, ""
    if not a:
        return True, f"now reproduced ({b})"
    if not b:
        return True, f"no longer reproduced (was {a})"
    x, y = _number(a), _number(b)
    if x is None or y is None:  # qualitative outcomes (True/False) or text
        if a.lower() == b.lower():
            return False, ""
        return True, f"outcome {a} → {b}"
    if math.isinf(x) or math.isinf(y) or math.isnan(x) or math.isnan(y):
        return (x != y), f"{a} → {b}"
    t = _number(tol) if str(tol).strip() else None
    delta = y - x
    if t is None or t <= 0:
        return delta != 0, f"moved by {delta:.3g}"
    moved = not within_tolerance(x, y, t)
    return moved, f"moved by {delta:.3g} ({abs(delta) / t:.3g} tolerances of {t:g})"


def _why(o: Mapping, n: Mapping) -> list[str]:
    """What changed a verdict, first in its note: the reading that now explains the row
    (``reading``, ``chance``: v0.4.0), the one withdrawn, or the robustness result."""
    a, b = _norm(o.get("reading", "")), _norm(n.get("reading", ""))
    why = []
    if b and b != a:
        why.append(f"explained by the reading {b} (chance {_norm(n.get('chance', ''))})")
    if a and a != b:
        why.append(f"reading {a} no longer accepted")
    if o["verdict"] == "explained" and not (a or b) and "reading" in n:
        why.append(
            "the explaining reading is no longer accepted (its look-elsewhere chance is above "
            "the budget, or the rows of its sentence contradict it)"
        )
    ro, rn = _norm(o.get("robust", "")), _norm(n.get("robust", ""))
    if rn == "false" and ro != "false":
        why.append("the verdict flips across the plausible inputs (robust=false)")
    return why


def _extra(o: Mapping, n: Mapping) -> list[str]:
    notes = []
    for col in ("depends_on", "robust", "reading", "chance"):
        a, b = _norm(o.get(col, "")), _norm(n.get(col, ""))
        if a != b and (a or b):
            notes.append(f"{col}: {a or '(empty)'} → {b or '(empty)'}")
    if _norm(o["published"]) != _norm(n["published"]):
        notes.append(f"printed value re-transcribed: {o['published']!r} → {n['published']!r}")
    return notes


# ------------------------------------------------------------------------------ diffing
def diff_tables(
    old: Mapping[str, Path], new: Mapping[str, Path], old_name="old", new_name="new"
) -> Changes:
    """The changes between two sets of comparison tables ``{doc: path}``."""
    records = []
    docs = sorted(set(old) | set(new))
    ch = Changes(old_name, new_name, pd.DataFrame(columns=CHANGES_COLUMNS), docs)
    for doc in docs:
        a = _read(old[doc]) if doc in old else pd.DataFrame(columns=_REQUIRED)
        b = _read(new[doc]) if doc in new else pd.DataFrame(columns=_REQUIRED)
        ch.rows[doc] = (len(a), len(b))
        remarks = ch.remarks.setdefault(doc, [])
        if doc not in old:
            remarks.append(f"new in {new_name}: every row is added")
        elif doc not in new:
            remarks.append(f"not in {new_name}: every row is removed")
        else:
            gained = [c for c in b.columns if c not in a.columns]
            lost = [c for c in a.columns if c not in b.columns]
            if gained:
                remarks.append(f"columns new in {new_name}: {', '.join(gained)}")
            if lost:
                remarks.append(f"columns no longer in {new_name}: {', '.join(lost)}")
        pairs = match_rows(a, b)
        loose = sum(1 for *_, how in pairs if how)
        if loose:
            remarks.append(f"{loose} rows paired although their text changed (see notes)")
        paired_old = {i for i, _, _ in pairs}
        paired_new = {j for _, j, _ in pairs}
        for i, j, how in pairs:
            o, n = a.iloc[i].to_dict(), b.iloc[j].to_dict()
            tol = n.get("tolerance", "") or o.get("tolerance", "")
            moved, how_moved = _move(o["reproduced"], n["reproduced"], tol)
            extra = _extra(o, n) + ([how] if how else [])
            if o["verdict"] != n["verdict"]:
                kind = "verdict"
                note = "; ".join(
                    _why(o, n) + [_norm(n.get("note", ""))] + ([how_moved] if moved else []) + extra
                )
            elif moved:
                kind = "moved"
                note = "; ".join([how_moved, *extra])
            elif _norm(o.get("note", "")) != _norm(n.get("note", "")) or _extra(o, n):
                # the same verdict and value; a pairing alone (reworded text) is no change
                kind = "note"
                was, now = _norm(o.get("note", "")), _norm(n.get("note", ""))
                texts = [f"now: {now or '(empty)'}", f"was: {was or '(empty)'}"]
                note = "; ".join((texts if was != now else []) + extra)
            else:
                continue
            records.append(_record(doc, kind, o, n, tol, note))
        for i in range(len(a)):
            if i not in paired_old:
                o = a.iloc[i].to_dict()
                records.append(_record(doc, "removed", o, None, o.get("tolerance", ""), ""))
        for j in range(len(b)):
            if j not in paired_new:
                n = b.iloc[j].to_dict()
                records.append(
                    _record(doc, "added", None, n, n.get("tolerance", ""), _norm(n.get("note", "")))
                )
    if records:
        ch.table = pd.DataFrame(records, columns=CHANGES_COLUMNS)
    return ch


def _record(doc, kind, o, n, tol, note) -> dict:
    ref = n if n is not None else o
    return {
        "doc": doc,
        "change": kind,
        "item": ref["item"],
        "quantity": ref["quantity"],
        "published": ref["published"],
        "old_verdict": o["verdict"] if o is not None else "",
        "new_verdict": n["verdict"] if n is not None else "",
        "old_value": o["reproduced"] if o is not None else "",
        "new_value": n["reproduced"] if n is not None else "",
        "tolerance": tol,
        "note": note.strip("; "),
    }


def diff_folders(old, new) -> Changes:
    """The changes between two version folders (see the module docstring)."""
    old, new = Path(old), Path(new)
    a, b = comparison_tables(old), comparison_tables(new)
    empty = [repr(str(f)) for f, t in ((old, a), (new, b)) if not t]
    if empty:
        # a folder without a single document's table is not a version folder (its parent,
        # say): every row of the other would be reported added or removed
        raise AbglibValueError(
            f"{' and '.join(empty)} {'holds' if len(empty) == 1 else 'hold'} no "
            "<doc>/tables/comparison.csv: give two version folders, e.g. reports/v0.3.0 "
            "or a build's results/reports/v<version>"
        )
    return diff_tables(a, b, _label(old), _label(new))


def write_build_changes(
    tables: Mapping[str, str], previous, version: str, csv_path, html_path, releases="reports"
) -> Changes | None:
    """The pipeline's ``changes`` rule: a build's comparison tables ``{doc: path}`` against
    the previous version folder (None: write the page saying there is none).

    Only the documents the build has are compared: a build of some documents does not
    report the others as removed (the page names them).
    """
    if previous is None:
        write_changes(None, csv_path, html_path, version=version, releases=releases)
        return None
    previous = Path(previous)
    old_all = comparison_tables(previous)
    old = {d: p for d, p in old_all.items() if d in tables}
    ch = diff_tables(old, {d: Path(p) for d, p in tables.items()}, previous.name, f"v{version}")
    skipped = sorted(set(old_all) - set(tables))
    if skipped:
        ch.remarks.setdefault("(build)", []).append(
            f"documents of {previous.name} not in this build, not compared: {', '.join(skipped)}"
        )
    write_changes(ch, csv_path, html_path, {d: f"{d}/index.html" for d in tables})
    return ch


def _label(folder: Path) -> str:
    """The folder's name (``v0.3.0``): pages never carry an absolute path."""
    return folder.resolve().name


# ------------------------------------------------------------------------------ writing
#: the page's own rules (change kinds, plain tables); fonts and the verdict badges come
#: from the version's shared stylesheet (assets/report.css), as on every other page
_CSS = """
body { max-width: 72em; }
nav a { margin-right: 1em; }
table { border-collapse: collapse; width: 100%; table-layout: auto; font-size: .85rem; }
td, th { border: 1px solid #ccc; padding: .2em .5em; vertical-align: top; text-align: left; }
th { background: #f0f0f0; } td.num { text-align: right; white-space: nowrap; }
td.note { overflow-wrap: anywhere; } td.item { min-width: 12em; }
.wrap { overflow-x: auto; }
.k-verdict { background: #fde2b8; } .k-moved { background: #fff4c2; }
.k-added { background: #d9f2d9; } .k-removed { background: #f6d2d2; }
.k-note { background: #dde8f6; }
tr.k-verdict, tr.k-moved, tr.k-note, tr.k-added, tr.k-removed { background: none; }
tr.k-verdict > td:first-child { border-left: .5em solid #e8a33d; }
tr.k-moved > td:first-child { border-left: .5em solid #e6c84a; }
tr.k-note > td:first-child { border-left: .5em solid #7a9cc6; }
tr.k-added > td:first-child { border-left: .5em solid #6cbf6c; }
tr.k-removed > td:first-child { border-left: .5em solid #d46a6a; }
caption, summary { text-align: left; font-weight: bold; padding: .3em 0; }
summary { cursor: pointer; margin-top: .6em; padding-left: .3em; border-radius: .2em; }
"""

_KIND_TEXT = {
    "verdict": "verdict changed",
    "moved": "value moved beyond its tolerance",
    "note": "same verdict and value, note changed",
    "added": "row added",
    "removed": "row removed",
}


def _page(ch: Changes, title: str, body: str) -> str:
    esc = html.escape
    return f"""<!DOCTYPE html>
<html lang="en">
<head><meta charset="utf-8"><meta name="viewport" content="width=device-width, initial-scale=1">
<title>{esc(title)}</title>
<link rel="stylesheet" href="assets/report.css">
<style>{_CSS}</style></head>
<body>
<nav><a href="index.html">← all reports of this version</a>
<a href="changes.csv">changes.csv</a></nav>
<h1>{esc(title)}</h1>
{body}
</body>
</html>
"""


def _verdict(v: str) -> str:
    return f'<span class="v v-{html.escape(v)}">{html.escape(v)}</span>' if v else ""


def changes_html(ch: Changes, links: Mapping[str, str] | None = None) -> str:
    """The page: the counts per document, then one section per document with its changes.

    ``links`` maps a document to its report (relative URL) for the section headings.
    """
    esc = html.escape
    links = dict(links or {})
    title = f"What changed: {ch.new} against {ch.old}"
    counts = ch.counts()
    head = "".join(f'<th class="k-{k}">{esc(_KIND_TEXT[k])}</th>' for k in CHANGE_KINDS)
    rows = []
    for rec in counts.to_dict("records"):
        n_old, n_new = ch.rows.get(rec["doc"], (0, 0))
        cells = "".join(f'<td class="num">{rec[k]}</td>' for k in CHANGE_KINDS)
        rows.append(
            f'<tr><td><a href="#{esc(rec["doc"])}">{esc(rec["doc"])}</a></td>'
            f'<td class="num">{n_old}</td><td class="num">{n_new}</td>{cells}</tr>'
        )
    intro = (
        f"<p>Every row of each document's <code>comparison.csv</code> in {esc(ch.new)} "
        f"paired with its row in {esc(ch.old)}: rows added or removed, verdicts changed, "
        "reproduced values that moved by more than their tolerance (half a unit in the last "
        "printed digit unless the report states another), and rows whose verdict and value "
        "stayed but whose note (or robustness, reading, printed value) changed. "
        "Machine-readable: "
        '<a href="changes.csv">changes.csv</a>.</p>'
    )
    summary = (
        '<div class="wrap"><table><caption>Changes per document</caption>'
        f"<tr><th>document</th><th>rows in {esc(ch.old)}</th><th>rows in {esc(ch.new)}</th>"
        f"{head}</tr>{''.join(rows)}</table></div>"
    )
    sections = [f"<p>{esc(r)}.</p>" for r in ch.remarks.get("(build)", [])]
    for doc in ch.docs:
        sub = ch.table[ch.table["doc"] == doc]
        link = f' (<a href="{esc(links[doc])}">report</a>)' if doc in links else ""
        parts = [f'<section id="{esc(doc)}"><h2>{esc(doc)}{link}</h2>']
        for r in ch.remarks.get(doc, []):
            parts.append(f"<p>{esc(r)}.</p>")
        if sub.empty:
            parts.append("<p>No change.</p>")
        for kind in CHANGE_KINDS:
            k = sub[sub["change"] == kind]
            if k.empty:
                continue
            body = "".join(
                f'<tr class="k-{kind}"><td class="item">{esc(r.item)}<br><small>'
                f"{esc(r.quantity)}</small></td><td class='num'>{esc(r.published)}</td>"
                f"<td>{_verdict(r.old_verdict)}</td><td>{_verdict(r.new_verdict)}</td>"
                f"<td class='num'>{esc(r.old_value)}</td><td class='num'>{esc(r.new_value)}</td>"
                f"<td class='note'>{esc(r.note)}</td></tr>"
                for r in k.itertuples(index=False)
            )
            # verdicts and moves open; long lists of added or removed rows open on demand
            opened = " open" if kind in ("verdict", "moved") or len(k) <= 10 else ""
            parts.append(
                f'<details{opened}><summary class="k-{kind}">{esc(_KIND_TEXT[kind])}: '
                f'{len(k)}</summary><div class="wrap"><table><tr><th>item / quantity</th>'
                f"<th>published</th><th>{esc(ch.old)}</th><th>{esc(ch.new)}</th>"
                f"<th>value {esc(ch.old)}</th><th>value {esc(ch.new)}</th><th>note</th></tr>"
                f"{body}</table></div></details>"
            )
        parts.append("</section>")
        sections.append("\n".join(parts))
    return _page(ch, title, intro + summary + "\n".join(sections))


def no_previous_html(version: str, releases: str) -> str:
    """The page written when there is no earlier version folder to compare with."""
    ch = Changes("(none)", f"v{version}", pd.DataFrame(columns=CHANGES_COLUMNS))
    body = (
        f"<p>There is no version folder below v{html.escape(version)} under "
        f"<code>{html.escape(releases)}/</code>, so there is nothing to compare with. "
        "<code>changes.csv</code> is empty.</p>"
    )
    return _page(ch, f"What changed in v{version}", body)


def write_changes(ch: Changes | None, csv_path, html_path, links=None, **no_previous) -> None:
    """Write ``changes.csv`` and ``changes.html`` atomically; ``ch=None`` writes the page
    saying there is no previous version (``no_previous``: ``version``, ``releases``)."""
    from .render import write_assets, write_text

    # the page sits at a version folder's top, beside assets/ (a build's report_assets
    # rule writes them; a folder of `abglib changes --out` gets its own copy)
    assets = Path(html_path).parent / "assets"
    if not (assets / "report.css").is_file():
        write_assets(assets)
    table = ch.table if ch is not None else pd.DataFrame(columns=CHANGES_COLUMNS)
    write_text(csv_path, table.to_csv(index=False, lineterminator="\n"))
    page = changes_html(ch, links) if ch is not None else no_previous_html(**no_previous)
    write_text(html_path, page)
