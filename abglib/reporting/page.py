"""An executed report notebook as one HTML page that reads like a paper, and the index page.

No code is shown (the notebook's source is linked instead); markdown is rendered with
mistune and every equation (``$…$``, ``$$…$$``) is converted to MathML at render time
with latex2mathml, so the page needs no script to show it and makes no network request.
The page links one stylesheet and one script shared by every page of the version
(``assets/report.css``, ``assets/report.js``, copied from ``abglib/reporting/assets``).

Page structure (relied on by the browser test and the index):

- ``header.report-head``: ``nav.pager`` (index, previous, next), ``h1``, ``div.abstract``,
  ``div.verdicts`` (counts and ``div.vbar``), ``nav.files`` (CSV, figures, notebook), ``nav.toc``;
- ``main``: the sections; each ``h2`` has an ``id`` (``sec-<n>`` for a numbered section);
- ``<meta name="description">``: the abstract as plain text (the index page's headline).
"""

from __future__ import annotations

import html
import re
from collections.abc import Mapping, Sequence
from pathlib import Path

from .tables import VERDICTS

__all__ = [
    "ASSETS",
    "build_page",
    "index_page",
    "markdown_html",
    "math_html",
    "read_headline",
    "verdict_bar",
]

#: the shared stylesheet and script, copied once per version folder
ASSETS = Path(__file__).with_name("assets")

_DISPLAY = re.compile(r"\$\$(.+?)\$\$", re.S)
_INLINE = re.compile(r"(?<![\\$\w])\$(?=\S)([^$\n]+?)(?<=\S)\$(?![\w$])")


def math_html(latex: str, display: bool = False) -> str:
    """LaTeX as MathML (``<math>``), block or inline.

    Raises
    ------
    ValueError
        If latex2mathml cannot parse ``latex``, or its MathML still shows a backslash (a
        command it took for text, e.g. a line-ending ``\\ ``); the message quotes ``latex``.
    """
    from latex2mathml.converter import convert

    try:
        out = convert(latex.strip(), display="block" if display else "inline")
    except Exception as exc:  # latex2mathml raises its own exception types
        raise ValueError(f"cannot convert the equation {latex!r} to MathML: {exc}") from exc
    if "\\" in out:
        raise ValueError(f"the equation {latex!r} shows a backslash as MathML (an unknown command)")
    return out.replace(' xmlns="http://www.w3.org/1998/Math/MathML"', "")


def _markdown():
    import mistune

    return mistune.create_markdown(escape=False, plugins=["table", "strikethrough"])


def markdown_html(text: str, inline: bool = False) -> str:
    """Markdown with ``$…$`` and ``$$…$$`` equations as MathML.

    ``inline=True`` drops the enclosing paragraph (for captions).
    """
    maths: list[str] = []

    def keep(m, display):
        maths.append(math_html(m.group(1), display))
        return f"\x00{len(maths) - 1}\x00"

    text = _DISPLAY.sub(lambda m: keep(m, True), text)
    text = _INLINE.sub(lambda m: keep(m, False), text)
    out = _markdown()(text).strip()
    if inline and out.startswith("<p>") and out.endswith("</p>") and out.count("<p>") == 1:
        out = out[3:-4]
    return re.sub("\x00(\\d+)\x00", lambda m: maths[int(m.group(1))], out)


# "section 7" is this report's section 7; "§7" is left alone (the source's own sections)
_SECTION_REF = re.compile(r"\b([Ss]ections?) (\d+)((?:, | and )(\d+))?")


def link_sections(fragment: str, known: set[str]) -> str:
    """Turn "section 7" (and "sections 7, 8" / "sections 7 and 8") in text, not inside
    links, code or tags, into links to ``#sec-7`` when the page has that section. "§7" is
    not linked: the reports use it for the source document's own sections."""
    parts = re.split(r"(<[^>]+>)", fragment)
    depth = 0
    for i, part in enumerate(parts):
        if part.startswith("<"):
            tag = re.match(r"</?\s*(\w+)", part)
            if tag and tag.group(1).lower() in ("a", "code", "pre", "math", "summary"):
                depth += -1 if part.startswith("</") else 1
            continue
        if depth > 0:
            continue

        def sub(m):
            word, first, tail, second = m.groups()

            def link(n, text):
                return f'<a href="#sec-{n}">{text}</a>' if f"sec-{n}" in known else text

            out = link(first, f"{word} {first}")
            if tail:
                out += tail[: -len(second)] + link(second, second)
            return out

        parts[i] = _SECTION_REF.sub(sub, part)
    return "".join(parts)


def _slug(text: str) -> str:
    return re.sub(r"[^a-z0-9]+", "-", text.lower()).strip("-") or "section"


def _plain(fragment: str) -> str:
    return " ".join(html.unescape(re.sub(r"<[^>]+>", "", fragment)).split())


def verdict_bar(
    counts: Mapping[str, int], robust: int | None = None, fragile: int | None = None
) -> str:
    """The verdict counts as coloured badges and a proportional bar (``div.verdicts``)."""
    total = sum(int(counts.get(v, 0)) for v in VERDICTS)
    badges = " ".join(
        f'<span class="v v-{v}">{int(counts.get(v, 0))} {v.replace("_", " ")}</span>'
        for v in VERDICTS
    )
    segs = "".join(
        f'<span class="v-{v}" style="flex:{int(counts.get(v, 0))}" '
        f'title="{int(counts.get(v, 0))} {v}"></span>'
        for v in VERDICTS
        if int(counts.get(v, 0))
    )
    rob = ""
    if robust is not None and fragile is not None:
        rob = (
            f' · <span class="v r-true">{robust} robust</span>'
            f' <span class="v r-false">{fragile} fragile</span>'
        )
    return (
        f'<div class="verdicts"><p>{total} published numbers and claims: {badges}{rob}</p>'
        f'<div class="vbar" role="img" aria-label="{html.escape(_plain(badges))}">'
        f"{segs}</div></div>"
    )


def _heading_ids(fragment: str, outline: list, seen: set[str]) -> str:
    def sub(m):
        level, attrs, inner = m.group(1), m.group(2), m.group(3)
        text = _plain(inner)
        num = re.match(r"(\d+)\.\s", text)
        ident = f"sec-{num.group(1)}" if num and level == "2" else _slug(text)
        base, k = ident, 2
        while ident in seen:
            ident, k = f"{base}-{k}", k + 1
        seen.add(ident)
        outline.append((int(level), ident, text))
        return f'<h{level}{attrs} id="{ident}">{inner}</h{level}>'

    return re.sub(r"<h([2-3])([^>]*)>(.*?)</h\1>", sub, fragment, flags=re.S)


def _cell_fragments(nb) -> tuple[str, str, list[str]]:
    """(title, abstract, body fragments) of an executed notebook; code is not shown."""
    title, abstract, frags = "", "", []
    for cell in nb.cells:
        if cell.cell_type == "markdown":
            frag = markdown_html(cell.source)
            if not title:
                m = re.search(r"<h1[^>]*>(.*?)</h1>", frag, re.S)
                if m:
                    title = m.group(1)
                    frag = frag.replace(m.group(0), "", 1)
            frags.append(frag)
            continue
        if cell.cell_type != "code":
            continue
        for out in cell.get("outputs", []):
            kind = out.get("output_type")
            if kind == "error":
                raise RuntimeError(f"the notebook failed: {out.get('ename')}: {out.get('evalue')}")
            if kind == "stream":
                frags.append(f'<pre class="output">{html.escape(out.get("text", ""))}</pre>')
                continue
            data = out.get("data", {})
            if out.get("metadata", {}).get("abstract"):
                abstract = markdown_html(data["text/markdown"])
            elif "text/html" in data:
                frags.append(data["text/html"])
            elif "text/markdown" in data:
                frag = markdown_html(data["text/markdown"])
                # a title the notebook computes (the generic report of a document,
                # workflow/notebooks/document.py) is the first heading it displays
                m = None if title else re.search(r"<h1[^>]*>(.*?)</h1>", frag, re.S)
                if m:
                    title = m.group(1)
                    frag = frag.replace(m.group(0), "", 1)
                frags.append(frag)
            elif "image/png" in data:
                frags.append(f'<img src="data:image/png;base64,{data["image/png"]}" alt="">')
            elif "text/plain" in data:
                frags.append(f'<pre class="output">{html.escape(data["text/plain"])}</pre>')
    return title, abstract, frags


def _pager(nav: Mapping, up: str) -> str:
    items = [f'<a href="{up}index.html">↑ all reports</a>']
    for rel, label in (("prev", "← "), ("next", "→ ")):
        d = nav.get(rel)
        if d:
            href = html.escape(f"{up}{d['doc']}/index.html")
            items.append(f'<a rel="{rel}" href="{href}">{label}{html.escape(d["title"])}</a>')
    return '<nav class="pager">' + " ".join(items) + "</nav>"


def build_page(
    nb,
    *,
    doc: str,
    version: str,
    counts: Mapping[str, int] | None = None,
    robust: tuple[int, int] | None = None,
    nav: Mapping | None = None,
    files: Mapping[str, Sequence[str]] | None = None,
    notebook: str = "",
) -> str:
    """The HTML page of an executed report notebook.

    Parameters
    ----------
    nb : NotebookNode
        The executed notebook.
    doc, version : str
        Document key and package version.
    counts : mapping, optional
        Verdict counts of the document's ``comparison.csv``.
    robust : (int, int), optional
        Robust and fragile row counts.
    nav : mapping, optional
        ``{"prev": {"doc", "title"}, "next": {...}}``: the neighbouring reports.
    files : mapping, optional
        ``{"tables": [...], "figures": [...]}``: file names beside the page.
    notebook : str
        The notebook's path in the repository (copied beside the page as ``notebook.py``).
    """
    title, abstract, frags = _cell_fragments(nb)
    outline: list = []
    seen: set[str] = set()
    body = _heading_ids("\n".join(frags), outline, seen)
    body = link_sections(body, seen)
    abstract = link_sections(abstract, seen)
    toc = "".join(
        f'<li class="toc{level}"><a href="#{ident}">{html.escape(text)}</a></li>'
        for level, ident, text in outline
        if level == 2
    )
    verdicts = ""
    if counts:
        verdicts = verdict_bar(counts, *(robust or (None, None)))
    files = files or {}
    links = []
    for kind in ("tables", "figures"):
        names = files.get(kind, [])
        if names:
            items = ", ".join(
                f'<a href="{kind}/{html.escape(n)}">{html.escape(n)}</a>' for n in names
            )
            links.append(f"<li>{kind}: {items}</li>")
    if notebook:
        links.append(
            f'<li>the notebook that wrote this page: <a href="notebook.py"><code>'
            f"{html.escape(notebook)}</code></a> (code hidden here)</li>"
        )
    pager = _pager(nav or {}, "../")
    plain_title = _plain(title) or doc
    description = html.escape(_plain(abstract))
    return f"""<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<meta name="description" content="{description}">
<title>{html.escape(plain_title)} — abglib v{html.escape(version)}</title>
<link rel="stylesheet" href="../assets/report.css">
<script src="../assets/report.js" defer></script>
</head>
<body class="report" data-doc="{html.escape(doc)}">
<header class="report-head">
{pager}
<p class="kicker">abglib {html.escape(version)} · report <code>{html.escape(doc)}</code></p>
<h1>{title}</h1>
<div class="abstract">{abstract}</div>
{verdicts}
<details class="files" open><summary>Data and source</summary>
<nav class="files"><ul>{"".join(links)}</ul></nav></details>
<nav class="toc" aria-label="Contents"><h2 class="toc-title">Contents</h2><ol>{toc}</ol></nav>
</header>
<main>
{body}
</main>
<footer>{pager}</footer>
</body>
</html>
"""


def read_headline(path) -> str:
    """The ``<meta name="description">`` of a report page (its abstract as plain text)."""
    text = Path(path).read_text(encoding="utf-8")
    m = re.search(r'<meta name="description" content="([^"]*)">', text)
    return html.unescape(m.group(1)) if m else ""


def index_page(
    version: str,
    entries: Sequence[Mapping],
    scorecard_table: str,
    provenance_table: str,
    changes: str = "changes.html",
) -> str:
    """The version's index page.

    ``entries``: per report ``{"doc", "title", "href", "headline", "counts", "robust",
    "fragile"}`` (``counts`` empty for a report with no published numbers).
    """
    esc = html.escape
    cards = []
    for e in entries:
        bar = verdict_bar(e["counts"], e.get("robust"), e.get("fragile")) if e.get("counts") else ""
        cards.append(
            f'<section class="card" id="doc-{esc(e["doc"])}"><h3><a href="{esc(e["href"])}">'
            f"{esc(e['title'])}</a> <code>{esc(e['doc'])}</code></h3>"
            f'<p class="headline">{esc(e.get("headline", ""))}</p>{bar}</section>'
        )
    return f"""<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>abglib replication reports, version {esc(version)}</title>
<link rel="stylesheet" href="assets/report.css">
<script src="assets/report.js" defer></script>
</head>
<body class="index">
<header class="report-head">
<h1>abglib replication reports, version {esc(version)}</h1>
<p>Each report regenerates the figures and tables of one source document and compares every
published number with the value abglib reproduces (<code>comparison.csv</code> in each
report's <code>tables/</code> folder). Verdicts:
<span class="v v-match">match</span> within half a unit of the last printed digit (unless the
report states another tolerance);
<span class="v v-explained">explained</span> a different quantity or reading, demonstrated in
the report, reproduces the printed number;
<span class="v v-mismatch">mismatch</span> neither;
<span class="v v-not_reproducible">not reproducible</span> no value can be computed, or the
verdict flips within the plausible range of an input the document never gives
(<span class="v r-false">fragile</span>; a row that keeps its verdict there is
<span class="v r-true">robust</span>).</p>
<nav class="pager"><a href="{esc(changes)}">What changed since the previous version</a>
· <a href="scorecard.csv">scorecard.csv</a></nav>
</header>
<main>
<h2 id="reports">Reports</h2>
{chr(10).join(cards)}
<h2 id="scorecard">Scorecard</h2>
{scorecard_table}
<h2 id="provenance">Provenance</h2>
{provenance_table}
</main>
</body>
</html>
"""
