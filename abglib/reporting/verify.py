"""Compare a build's tables with a release folder (``abglib verify``).

Every table is written with the precision it is reproducible to (a fixed number of
significant digits, fewer for a column that only holds to fewer, and a bound such as
``<1e-12`` for pure round-off), so the comparison is on the *written* numbers: two cells
agree when they differ by at most one unit in the last written digit (a rounding flip of
the same value), a bound agrees with a bound or with a smaller number, and text agrees
only when identical. For ``comparison.csv`` the verdicts are compared too.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from decimal import Decimal, InvalidOperation
from pathlib import Path

__all__ = ["DocReport", "Difference", "cell_agrees", "compare_folders", "format_report"]


@dataclass
class Difference:
    """One disagreement: where, and the two written values."""

    table: str
    row: int
    column: str
    release: str
    build: str
    deviation: float = math.nan

    def __str__(self) -> str:
        dev = "" if math.isnan(self.deviation) else f" (relative deviation {self.deviation:.3g})"
        return (
            f"{self.table}, row {self.row}, column {self.column}: release {self.release!r}, "
            f"build {self.build!r}{dev}"
        )


@dataclass
class DocReport:
    """The comparison of one document's (or the top folder's) tables."""

    doc: str
    tables: int = 0
    rows: int = 0
    verdicts: int = 0
    verdicts_same: int = 0
    largest: float = 0.0
    largest_at: str = ""
    differences: list[Difference] = field(default_factory=list)
    problems: list[str] = field(default_factory=list)

    @property
    def ok(self) -> bool:
        return not self.differences and not self.problems


def _decimal(text: str) -> Decimal | None:
    try:
        d = Decimal(text.strip())
    except (InvalidOperation, AttributeError):
        return None
    return d if d.is_finite() else None


def _significant_digits(d: Decimal) -> int:
    return len(d.normalize().as_tuple().digits) if d != 0 else 1


def _is_integer_text(text: str) -> bool:
    return text.strip().lstrip("-").isdigit()


def cell_agrees(release: str, build: str) -> tuple[bool, float]:
    """Whether two written cells agree, and their relative deviation (NaN for text, or
    when the release value is 0).

    Numbers are written with ``%g`` at their column's precision, which drops trailing
    zeros, so the precision of a cell is that of the longer of the two: they agree within
    one unit in the last significant digit of the longer one (a value on a rounding
    boundary may round either way): ``1.2`` and ``1.199999999`` agree, ``2`` and ``2.9``
    do not. Integers (counts) must be equal. ``<x`` bounds agree with each other and with
    any number below ``x``.
    """
    if release == build:
        return True, 0.0
    if release.startswith("<") or build.startswith("<"):
        bound = _decimal(release[1:] if release.startswith("<") else build[1:])
        other = _decimal(build if release.startswith("<") else release)
        if bound is not None and other is not None:
            return abs(other) < bound, math.nan
        return False, math.nan
    a, b = _decimal(release), _decimal(build)
    if a is None or b is None:
        return False, math.nan
    dev = float(abs(a - b) / abs(a)) if a != 0 else math.nan
    if _is_integer_text(release) and _is_integer_text(build):
        return False, dev
    digits = max(_significant_digits(a), _significant_digits(b))
    top = max(abs(a), abs(b))
    unit = Decimal(1).scaleb(top.adjusted() - (digits - 1))
    return abs(a - b) <= unit, dev


def _read(path: Path) -> list[list[str]]:
    import csv

    with path.open(newline="", encoding="utf-8") as fh:
        return list(csv.reader(fh))


def compare_folders(release: Path, build: Path, partial: bool = False) -> list[DocReport]:
    """Compare every CSV under ``release`` with the file at the same place under ``build``.

    One :class:`DocReport` per top-level folder (a document) and one for the files at the
    top (``scorecard.csv``). A file missing from the build, a different header or row
    count, a changed verdict or a cell outside its written precision is a difference.
    With ``partial`` only the tables the build has are compared (e.g. a build of one
    document, or of the tables without the reports).
    """
    release, build = Path(release), Path(build)
    reports: dict[str, DocReport] = {}
    for rel_path in sorted(release.rglob("*.csv")):
        rel = rel_path.relative_to(release)
        doc = rel.parts[0] if len(rel.parts) > 1 else "(index)"
        rep = reports.setdefault(doc, DocReport(doc))
        rep.tables += 1
        other = build / rel
        if not other.is_file():
            if partial:
                rep.tables -= 1
                continue
            rep.problems.append(f"{rel}: missing from the build")
            continue
        a, b = _read(rel_path), _read(other)
        if not a or not b or a[0] != b[0]:
            rep.problems.append(f"{rel}: columns differ ({a[:1]} vs {b[:1]})")
            continue
        if len(a) != len(b):
            rep.problems.append(f"{rel}: {len(a) - 1} rows in the release, {len(b) - 1} built")
            continue
        header = a[0]
        verdict_col = header.index("verdict") if "verdict" in header else None
        for i, (ra, rb) in enumerate(zip(a[1:], b[1:], strict=True), start=1):
            rep.rows += 1
            if verdict_col is not None:
                rep.verdicts += 1
                rep.verdicts_same += ra[verdict_col] == rb[verdict_col]
            for col, x, y in zip(header, ra, rb, strict=False):
                ok, dev = cell_agrees(x, y)
                if not math.isnan(dev) and dev > rep.largest:
                    rep.largest, rep.largest_at = dev, f"{rel}, row {i}, {col}"
                if not ok:
                    rep.differences.append(Difference(str(rel), i, col, x, y, dev))
    for extra in sorted(build.rglob("*.csv")):
        rel = extra.relative_to(build)
        if not (release / rel).is_file():
            doc = rel.parts[0] if len(rel.parts) > 1 else "(index)"
            reports.setdefault(doc, DocReport(doc)).problems.append(
                f"{rel}: in the build, not in the release"
            )
    return [r for r in reports.values() if r.tables or r.problems or not partial]


def format_report(reports: list[DocReport], limit: int = 5) -> str:
    """The per-document summary ``abglib verify`` prints."""
    lines = []
    for r in reports:
        status = "identical within the written precision" if r.ok else "DIFFERS"
        verdicts = f", verdicts identical {r.verdicts_same}/{r.verdicts}" if r.verdicts else ""
        largest = f", largest deviation {r.largest:.3g} at {r.largest_at}" if r.largest > 0 else ""
        lines.append(
            f"{r.doc}: {r.tables} tables, {r.rows} rows compared{verdicts}{largest}: {status}"
        )
        for p in r.problems[:limit]:
            lines.append(f"  - {p}")
        for d in r.differences[:limit]:
            lines.append(f"  - {d}")
        hidden = max(0, len(r.problems) - limit) + max(0, len(r.differences) - limit)
        if hidden:
            lines.append(f"  ... and {hidden} more")
    return "\n".join(lines)
