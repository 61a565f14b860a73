"""The README and the guides (``docs/*.md``, issue 23): short, their links resolve, their
example runs.

The README is for users (at most 200 lines); every topic it leaves out is a page of
``docs/`` it links. Each relative link of the README and of the guides must name a file of
the repository, and a ``#fragment`` one of that page's headings as GitHub (and MyST, with
``myst_heading_anchors``) writes it. The README's library example is a ``>>>`` session run
here as a doctest, and ``docs/extending.md``'s table of design rules lists exactly the
registered rules. The README's findings block is checked by ``tests/test_readme_findings.py``.
"""

from __future__ import annotations

import doctest
import re
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]
README = REPO / "README.md"
DOCS = REPO / "docs"
#: Markdown files of docs/ that are not pages (the findings template of abglib findings)
NOT_PAGES = {"readme_findings.md"}

FENCE = re.compile(r"^(```|~~~).*?^\1[ \t]*$", re.S | re.M)
INLINE_CODE = re.compile(r"`+[^`\n]*`+")
LINK = re.compile(r"\]\(([^)\s]+)\)")
HEADING = re.compile(r"^#{1,6}[ \t]+(.+?)[ \t]*#*[ \t]*$", re.M)


def pages() -> list[Path]:
    """The README and every guide of docs/ (findings notes included)."""
    found = [p for p in sorted(DOCS.rglob("*.md")) if p.name not in NOT_PAGES]
    return [README, *(p for p in found if "_build" not in p.parts)]


def prose(text: str) -> str:
    """``text`` without fenced code blocks and inline code (links there are not links)."""
    return INLINE_CODE.sub("", FENCE.sub("", text))


def slug(heading: str) -> str:
    """GitHub's anchor of a heading: lower case, punctuation dropped, spaces to hyphens."""
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # a link keeps its text
    text = text.replace("`", "").replace("*", "")
    return re.sub(r"[^\w\- ]", "", text.strip().lower()).replace(" ", "-")


def anchors(path: Path) -> set[str]:
    return {slug(h) for h in HEADING.findall(FENCE.sub("", path.read_text(encoding="utf-8")))}


def broken_links(path: Path, root: Path = REPO) -> list[str]:
    """The relative links and images of one Markdown page that point at nothing."""
    broken = []
    for target in LINK.findall(prose(path.read_text(encoding="utf-8"))):
        if re.match(r"[a-z]+:", target):
            continue  # https:, mailto: ... (none is followed offline)
        file, _, fragment = target.partition("#")
        dest = (path.parent / file).resolve() if file else path
        where = f"{path.relative_to(root)}: {target}"
        if not dest.exists():
            broken.append(f"{where} (no such file)")
        elif fragment and dest.suffix == ".md" and fragment not in anchors(dest):
            broken.append(f"{where} (no heading #{fragment})")
    return broken


def test_slug_and_link_check_catch_what_they_should(tmp_path):
    assert slug("What changed between two versions: `abglib changes`") == (
        "what-changed-between-two-versions-abglib-changes"
    )
    assert slug("How long things take (v0.4.0, 2026-12-01)") == (
        "how-long-things-take-v040-2026-12-01"
    )
    assert slug("The comparison table, `comparison.csv`") == "the-comparison-table-comparisoncsv"
    page = tmp_path / "a.md"
    (tmp_path / "b.md").write_text("# B\n\n## A heading\n```\n# not a heading\n```\n")
    page.write_text(
        "[ok](b.md#a-heading) [gone](c.md) [bad](b.md#not-a-heading) `[code](x.md)`\n"
        "```\n[fenced](y.md)\n```\n[web](https://example.org) ![img](b.md)\n"
    )
    assert broken_links(page, root=tmp_path) == [
        "a.md: c.md (no such file)",
        "a.md: b.md#not-a-heading (no heading #not-a-heading)",
    ]


def linked_pages(path: Path) -> set[Path]:
    """The Markdown files one page links (relative links only)."""
    found = set()
    for target in LINK.findall(prose(path.read_text(encoding="utf-8"))):
        file = target.partition("#")[0]
        if file.endswith(".md") and not re.match(r"[a-z]+:", file):
            found.add((path.parent / file).resolve())
    return found


def test_readme_is_short_and_every_topic_page_is_reached_from_it():
    text = README.read_text(encoding="utf-8")
    lines = text.count("\n")
    assert lines <= 200, f"README.md has {lines} lines: at most 200 (move a topic to docs/)"
    direct = {p.name for p in linked_pages(README)}
    for topic in ("installation", "reading-reports", "extending", "releases", "performance"):
        assert f"{topic}.md" in direct, f"the README does not link docs/{topic}.md"
    reached, todo = set(), [README.resolve()]
    while todo:  # every page of docs/ is one or more links away from the README
        page = todo.pop()
        if page not in reached and page.is_file():
            reached.add(page)
            todo.extend(linked_pages(page))
    topics = {p.resolve() for p in DOCS.glob("*.md") if p.name not in NOT_PAGES}
    topics.discard((DOCS / "overview.md").resolve())  # the README itself, as a page of the site
    missed = sorted(p.name for p in topics - reached)
    assert not missed, f"docs pages no link from the README leads to: {missed}"


@pytest.mark.parametrize("page", pages(), ids=lambda p: str(p.relative_to(REPO)))
def test_every_relative_link_resolves(page):
    assert broken_links(page) == []


def test_quick_start_has_the_setup_and_test_commands():
    """``.ci/run`` runs "the README's test command": the Quick start shows it as a block."""
    text = README.read_text(encoding="utf-8")
    quick = text.split("## Quick start", 1)[1].split("\n## ", 1)[0]
    blocks = re.findall(r"```bash\n(.*?)```", quick, re.S)
    commands = [line.split("#")[0].strip() for b in blocks for line in b.splitlines()]
    assert 'python3 -m venv .venv && . .venv/bin/activate && pip install -e ".[dev]"' in commands
    assert "snakemake -c2" in commands and "pytest" in commands


def test_readme_library_example_runs():
    text = README.read_text(encoding="utf-8")
    sessions = [b for b in re.findall(r"```python\n(.*?)```", text, re.S) if ">>>" in b]
    assert sessions, "the README has no library example (a >>> session)"
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
    for i, block in enumerate(sessions):
        test = doctest.DocTestParser().get_doctest(block, {}, f"README[{i}]", str(README), 0)
        runner.run(test)
    result = runner.summarize(verbose=False)
    assert result.failed == 0 and result.attempted >= 5, result


def test_extending_lists_every_registered_design_rule():
    from abglib.bench.variants import RULES

    text = (DOCS / "extending.md").read_text(encoding="utf-8")
    table = re.findall(r"^\| `(\w+)` \|", text, re.M)
    assert sorted(table) == sorted(RULES), (
        f"docs/extending.md's rule table: missing {sorted(set(RULES) - set(table))}, "
        f"unknown {sorted(set(table) - set(RULES))}"
    )
    for name, rule in RULES.items():
        row = re.search(rf"^\| `{name}` \|(.*)\|(.*)\|$", text, re.M)
        params = set(re.findall(r"`(\w+)", row.group(1)))
        assert params == set(rule.allowed), (name, params, rule.allowed)
