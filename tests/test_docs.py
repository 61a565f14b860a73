"""The API reference site (``docs/``, issue 23): built offline with warnings as errors, its
gallery run, every page loaded in headless Chromium with the network blocked.

The build test runs ``sphinx-build -W --keep-going -b html docs <tmp>`` (the command of
``docs/README.md``) once per module. It checks that every example of ``docs/examples``
ran and drew its figure, that every public name of the documented modules has its page,
that the current release's reports are inside the site and linked from its front page, and
that no local link, anchor or image of any page is broken. The browser test loads every
page of the site (the copied reports included) offline and fails on any network request,
failed request, console error, raw TeX, broken image or horizontal overflow
(``tests/_browser.py``).

Without Sphinx (the ``docs`` extra) or Chromium the tests skip, saying why; under CI
(``CI=true``, as ``.ci/run`` runs) they fail instead. The References test needs neither.
"""

from __future__ import annotations

import importlib
import inspect
import re
import subprocess
import sys
import time
import types
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import unquote, urlsplit

import pytest

import abglib

from .conftest import require, require_module

REPO = Path(__file__).resolve().parents[1]
DOCS = REPO / "docs"
REPORTS = Path("reports") / f"v{abglib.__version__}"

#: the tracker core: each public function names its source document and equation
CORE = [
    "abglib",
    "abglib.design",
    "abglib.analysis",
    "abglib.conventions",
    "abglib.simulate",
    "abglib.methods",
]
#: a source document by its seed number or its key (/work/shared/seeds/README.md)
SOURCE = re.compile(
    r"seed 00[0-4]|steelman1978|alwagih|huang|faa_bendix|antenna|Steelman|Al-Wagih|Huang"
    r"|Bendix|Sinsky|Elwell"
)
#: where in it: an equation, table, figure, section or algorithm, as printed (seed 003 numbers
#: none: its test program, graphs and the memo's table)
WHERE = re.compile(
    r"\beqs?\.? ?\(?\d|\bequations? \d|\bTables? \d|\bFig(?:ure)?s?\.? ?\d|\bsections? \d"
    r"|\bAlgorithms? \d|\bapp(?:endix)?\.? [A-Z]|\bch(?:apter)?\.? \d|\bunnumbered"
    r"|\bgraphs \d|memo's table|test program's|design example, step \d"
)
#: public functions that come from no document: their References say "None: <why>"
NO_SOURCE = {"abglib.simulate.rng_from"}


def _public_callables(modname):
    mod = importlib.import_module(modname)
    names = getattr(mod, "__all__", None)
    if names is None:  # abglib.analysis re-exports its submodules' __all__
        names = [n for n in dir(mod) if not n.startswith("_")]
        names = [n for n in names if getattr(getattr(mod, n), "__module__", "").startswith(modname)]
    for name in names:
        obj = getattr(mod, name)
        if inspect.isfunction(obj) or inspect.isclass(obj) or hasattr(obj, "ufunc"):
            yield name, obj


def _references(doc: str) -> str:
    """The text of a numpydoc References section ('' when there is none)."""
    m = re.search(
        r"\n\s*References\n\s*-{10}\n(.*?)(?:\n\s*\n\s*\w[^\n]*\n\s*-{3,}\n|\Z)", doc, re.S
    )
    return m.group(1) if m else ""


@pytest.mark.parametrize("modname", CORE)
def test_core_functions_have_references_naming_document_and_equation(modname):
    missing, vague = [], []
    for name, obj in _public_callables(modname):
        if inspect.isclass(obj) and issubclass(obj, Exception):
            continue  # an exception cites nothing
        refs = _references(inspect.getdoc(obj) or "")
        if not refs:
            missing.append(name)
        elif f"{modname}.{name}" in NO_SOURCE:
            assert refs.startswith("None: "), f"{modname}.{name}: {refs!r}"
        elif not (SOURCE.search(refs) and WHERE.search(refs)):
            vague.append(f"{name}: {refs.strip()[:120]!r}")
    assert not missing, f"{modname}: no References section in {missing}"
    assert not vague, f"{modname}: References name no source and place: {vague}"


def test_references_regexes_tell_a_citation_from_none():
    doc = "Summary.\n\nReferences\n----------\nSteelman 1978 (seed 000), eqs 31-32.\n"
    refs = _references(doc)
    assert SOURCE.search(refs) and WHERE.search(refs)
    assert _references("Summary.\n\nNotes\n-----\nseed 000, eq 3\n") == ""
    assert not WHERE.search("Steelman (seed 000), the whole report")


# --------------------------------------------------------------------- the built site


@pytest.fixture(scope="module")
def site(tmp_path_factory):
    """The site built offline with warnings as errors into a temporary folder."""
    require_module("sphinx")
    for name in ("numpydoc", "sphinx_gallery", "latex2mathml"):
        require_module(name)
    out = tmp_path_factory.mktemp("docs") / "html"
    doctrees = out.parent / "doctrees"
    cmd = [
        sys.executable,
        "-m",
        "sphinx",
        "-W",
        "--keep-going",
        "-b",
        "html",
        "-d",
        str(doctrees),
        str(DOCS),
        str(out),
    ]
    t0 = time.monotonic()
    proc = subprocess.run(cmd, cwd=REPO, capture_output=True, text=True, timeout=600)
    elapsed = time.monotonic() - t0
    assert proc.returncode == 0, (
        f"sphinx-build -W failed ({proc.returncode}):\n{proc.stderr[-6000:]}"
    )
    print(f"docs built in {elapsed:.0f} s")
    return out


@pytest.mark.docs
def test_gallery_runs_every_example_and_draws_its_figure(site):
    examples = sorted(p.stem for p in (DOCS / "examples").glob("plot_*.py"))
    assert len(examples) >= 6, examples
    for stem in examples:
        page = site / "auto_examples" / f"{stem}.html"
        assert page.is_file(), f"no gallery page for {stem}"
        figs = list((site / "_images").glob(f"sphx_glr_{stem}_00*.png"))
        assert figs, f"{stem} drew no figure"
        assert "Traceback" not in page.read_text(encoding="utf-8"), stem


@pytest.mark.docs
def test_every_public_name_has_its_api_page(site):
    modules = [
        line.strip()
        for line in (DOCS / "api.rst").read_text().splitlines()
        if line.startswith("   abglib")
    ]
    assert {
        "abglib",
        "abglib.analysis",
        "abglib.verdicts",
        "abglib.replications.compare",
        "abglib.reporting.verify",
        "abglib.bench.variants",
    } <= set(modules)
    sys.path.insert(0, str(DOCS))
    try:
        from conf import api_home
    finally:
        sys.path.remove(str(DOCS))
    for modname in modules:
        assert (site / "generated" / f"{modname}.html").is_file(), modname
        mod = importlib.import_module(modname)
        names = getattr(mod, "__all__", None) or [
            n for n in dir(mod) if not n.startswith("_") and callable(getattr(mod, n))
        ]
        for name in names:
            obj = getattr(mod, name)
            if not callable(obj):
                continue
            home = api_home(modname, name)
            assert (site / "generated" / f"{home}.{name}.html").is_file(), (
                f"{modname}.{name}: no page generated/{home}.{name}.html"
            )
        # constants: a page of their own (autosummary, a #: comment in the module itself) or
        # an entry on the module's page (re-exported from a submodule: conf.py documents it)
        page = (site / "generated" / f"{modname}.html").read_text(encoding="utf-8")
        for name in getattr(mod, "__all__", None) or [n for n in dir(mod) if n[0] != "_"]:
            obj = getattr(mod, name)
            if name.startswith("_") or callable(obj) or isinstance(obj, types.ModuleType):
                continue
            own = site / "generated" / f"{modname}.{name}.html"
            assert own.is_file() or f'id="{modname}.{name}"' in page, (
                f"{modname}.{name}: a public constant documented nowhere"
            )


@pytest.mark.docs
def test_site_holds_the_current_release_reports(site):
    index = site / REPORTS / "index.html"
    assert index.is_file(), f"{REPORTS} not copied into the site"
    for page in (REPO / REPORTS).rglob("*.html"):
        assert (site / page.relative_to(REPO)).is_file(), page
    assert f'href="{REPORTS.as_posix()}/index.html"' in (site / "index.html").read_text()


class _Refs(HTMLParser):
    """The ids a page defines and the links and images it uses."""

    def __init__(self):
        super().__init__()
        self.ids: set[str] = set()
        self.refs: list[tuple[str, str]] = []

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        for key in ("id", "name"):
            if a.get(key):
                self.ids.add(a[key])
        for key in ("href", "src"):
            if a.get(key) is not None and not (tag == "a" and key == "src"):
                self.refs.append((tag, a[key]))


def _parse(path: Path) -> _Refs:
    p = _Refs()
    p.feed(path.read_text(encoding="utf-8", errors="replace"))
    return p


def broken_links(root: Path) -> list[str]:
    """Every local link, anchor, stylesheet, script or image of the HTML pages under
    ``root`` that points at nothing."""
    pages = {p.resolve(): _parse(p) for p in root.rglob("*.html")}
    broken = []
    for page, parsed in pages.items():
        for tag, ref in parsed.refs:
            url = urlsplit(ref)
            if url.scheme in ("http", "https", "mailto", "data", "javascript"):
                continue  # an external link: not followed offline (the browser test
                # fails any request the page itself would make)
            where = f"{page.relative_to(root.resolve())}: <{tag}> {ref}"
            if url.scheme or url.netloc:
                broken.append(f"{where} (not a local URL)")
                continue
            target = (page.parent / unquote(url.path)).resolve() if url.path else page
            if target.is_dir():
                target = target / "index.html"
            if not target.is_file():
                broken.append(f"{where} (no such file)")
            elif url.fragment and target.suffix == ".html":
                ids = pages[target].ids if target in pages else _parse(target).ids
                if unquote(url.fragment) not in ids:
                    broken.append(f"{where} (no anchor #{url.fragment})")
    return broken


def test_broken_links_finds_missing_files_and_anchors(tmp_path):
    (tmp_path / "sub").mkdir()
    (tmp_path / "a.html").write_text(
        '<a href="sub/b.html#here">ok</a><a href="#top" id="top">ok</a>'
        '<a href="sub/b.html#gone">x</a><img src="missing.png"><a href="https://x.org">ext</a>'
        '<link rel="stylesheet" href="//cdn.example/x.css">'
    )
    (tmp_path / "sub" / "b.html").write_text('<h1 id="here">b</h1><a href="../a.html">up</a>')
    found = broken_links(tmp_path)
    assert found == [
        "a.html: <a> sub/b.html#gone (no anchor #gone)",
        "a.html: <img> missing.png (no such file)",
        "a.html: <link> //cdn.example/x.css (not a local URL)",
    ]


@pytest.mark.docs
def test_no_broken_local_link_anchor_or_image(site):
    assert broken_links(site) == []


@pytest.mark.docs
@pytest.mark.browser
def test_every_page_loads_offline_in_chromium(site):
    from ._browser import Browser, check_pages, find_chromium

    chromium = find_chromium()
    if chromium is None:
        require(
            "no Chromium found (Debian: apt-get install chromium, or set ABGLIB_CHROMIUM): "
            "the docs site is not checked in a browser"
        )
    pages = sorted(site.rglob("*.html"))
    assert len(pages) > 50
    problems = {}
    with Browser(chromium) as browser:
        checks = check_pages(browser, pages, timeout=30)
    for page, check in zip(pages, checks, strict=True):
        # "NaN in a table cell" is a report's missing number; the API tables hold
        # docstring summaries, which may name NaN (e.g. "... NaN where either is empty")
        check.nan_cells = 0
        found = check.problems
        if found:
            problems[page.relative_to(site).as_posix()] = found
    assert not problems, f"{len(problems)} of {len(pages)} pages fail: {problems}"
