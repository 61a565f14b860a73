"""The README's findings, formatted from a release's tables (never typed by hand).

``docs/readme_findings.md`` is a template: prose with placeholders
``{{<doc>/<table> | <column>=<value>[ & <column>=<value>...] | <column> | <format>}}``
(the conditions select one row; format optional, a Python format spec such as ``.3g``),
resolved against ``reports/v<version>/<doc>/tables/<table>.csv``; ``{{scorecard}}``, the
scorecard as a Markdown table; and ``{{release}}``, the release folder's name
(``v0.4.3``), so that the text says which release its numbers are from. The rendered
text goes between the ``<!-- findings:start -->`` and ``<!-- findings:end -->`` markers
of README.md (``abglib findings``); a test checks that the README holds exactly what the committed
release renders to.
"""

from __future__ import annotations

import csv
import re
from pathlib import Path

from .._checks import AbglibValueError

__all__ = ["render_findings", "update_readme"]

START, END = "<!-- findings:start -->", "<!-- findings:end -->"
_PLACEHOLDER = re.compile(r"\{\{\s*(.*?)\s*\}\}", re.S)


def _rows(path: Path) -> list[dict]:
    if not path.is_file():
        raise AbglibValueError(f"findings: no table {path}")
    with path.open(newline="", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


def _scorecard(release: Path) -> str:
    rows = _rows(release / "scorecard.csv")
    cols = ["doc", "match", "mismatch", "explained", "not_reproducible", "total"]
    extra = [c for c in ("robust", "fragile") if rows and c in rows[0]]
    head = [*cols, *extra]
    lines = [
        "| " + " | ".join(c.replace("_", " ") for c in head) + " |",
        "| --- |" + " ---: |" * (len(head) - 1),
    ]
    for r in rows:
        lines.append("| " + " | ".join([f"`{r['doc']}`", *(r[c] for c in head[1:])]) + " |")
    return "\n".join(lines)


def _resolve(expr: str, release: Path) -> str:
    if expr == "scorecard":
        return _scorecard(release)
    if expr == "release":
        return release.resolve().name
    parts = [p.strip() for p in expr.split("|")]
    if len(parts) not in (3, 4) or "=" not in parts[1]:
        raise AbglibValueError(
            f"findings: a placeholder is {{{{doc/table | column=value | column | format}}}}, "
            f"got {{{{{expr}}}}}"
        )
    table, selector, column = parts[:3]
    fmt = parts[3] if len(parts) == 4 else ""
    doc, _, name = table.partition("/")
    conditions = [tuple(x.strip() for x in c.split("=", 1)) for c in selector.split(" & ")]
    rows = [
        r
        for r in _rows(release / doc / "tables" / f"{name}.csv")
        if all(r.get(col) == val for col, val in conditions)
    ]
    if len(rows) != 1:
        where = " and ".join(f"{col} = {val!r}" for col, val in conditions)
        raise AbglibValueError(f"findings: {table} has {len(rows)} rows with {where}, need one")
    if column not in rows[0]:
        raise AbglibValueError(f"findings: {table} has no column {column!r}")
    value = rows[0][column]
    if fmt:
        try:
            return format(float(value), fmt)
        except ValueError:
            raise AbglibValueError(
                f"findings: {table} {selector!r}, {column} = {value!r} is not a number"
            ) from None
    return value


def render_findings(template: str, release) -> str:
    """The template with every placeholder replaced by its value in ``release``."""
    release = Path(release)
    if not release.is_dir():
        raise AbglibValueError(f"findings: the release folder {release} does not exist")
    return _PLACEHOLDER.sub(lambda m: _resolve(m.group(1), release), template)


def update_readme(readme, template, release, check: bool = False) -> bool:
    """Write the rendered findings between the README's markers.

    With ``check`` nothing is written. Returns whether the README already held them.
    """
    readme, template = Path(readme), Path(template)
    for what, path in (("README", readme), ("template", template)):
        if not path.is_file():
            raise AbglibValueError(f"findings: no {what} file {path}")
    text = readme.read_text(encoding="utf-8")
    if START not in text or END not in text:
        raise AbglibValueError(f"{readme} lacks the markers {START} and {END}")
    head, rest = text.split(START, 1)
    _, tail = rest.split(END, 1)
    body = render_findings(template.read_text(encoding="utf-8"), release)
    new = f"{head}{START}\n{body.strip()}\n{END}{tail}"
    same = new == text
    if not same and not check:
        readme.write_text(new, encoding="utf-8")
    return same
