"""The reports in a real browser: headless Chromium, offline (tests/_browser.py).

Two parts. The driver's own tests load small pages written here, each with known defects,
and check that every defect is caught and that a clean page passes (and that a request to
a live local server is blocked before it leaves the browser). Then every page of the
report folders (default: the committed release ``reports/v<version>``; another list with
``ABGLIB_BROWSER_REPORTS=dir1:dir2``) is loaded with the network blocked and fails on any
failed request, request to a non-file URL, console error, raw TeX in the visible text,
NaN in a table cell, broken image or horizontal overflow. ``pages.csv`` (page heights and
problems) goes to ``<root>/<folder name>/``, the root ``results/screenshots`` of the
repository; with ``ABGLIB_SCREENSHOTS`` set, a full-page screenshot of every page goes
there too, the root being its value (``1``, ``true`` or ``yes``: the default root). A
screenshot is for a person to look at and checks nothing; it cost 2-2.7 s a page, two
thirds of the browser's time, so a plain ``pytest`` takes none (issue 24). The last test
prints where.

Without Chromium (Debian package ``chromium``) every test here that needs it skips, saying
so, on a developer's machine, and fails under CI (``CI=true``: ``.ci/run`` installs Chromium,
so a missing one there is a broken install, not a reason to check nothing). So does a report
folder that is not there.
"""

from __future__ import annotations

import csv
import http.server
import os
import threading
from pathlib import Path

import pytest

import abglib

from ._browser import (
    Browser,
    PageCheck,
    check_folder,
    check_page,
    check_pages,
    find_chromium,
    report_pages,
)
from .conftest import require

REPO = Path(__file__).resolve().parents[1]
CHROMIUM = find_chromium()
# one worker runs the module: the summary test reads the pages its page tests checked
# (CHECKED), and the browser starts once
pytestmark = [pytest.mark.browser, pytest.mark.xdist_group("browser")]


@pytest.fixture(scope="module")
def chromium() -> str:
    """The Chromium binary; without one: skip, or fail under CI (conftest.require)."""
    if CHROMIUM is None:
        require(
            "no Chromium found (Debian: apt-get install chromium, or set ABGLIB_CHROMIUM): "
            "the reports are not checked in a browser"
        )
    return CHROMIUM


needs_chromium = pytest.mark.usefixtures("chromium")


@pytest.fixture(scope="module")
def browser(chromium):
    with Browser(chromium) as b:
        yield b


# ---------------------------------------------------------------------- without Chromium
def test_report_pages_lists_index_reports_and_changes(tmp_path):
    for rel in ("index.html", "b/index.html", "a/index.html", "changes.html", "a/figures/x.png"):
        (tmp_path / rel).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / rel).write_text("x")
    names = [p.relative_to(tmp_path).as_posix() for p in report_pages(tmp_path)]
    assert names == ["index.html", "a/index.html", "b/index.html", "changes.html"]


def test_find_chromium_honours_the_environment(monkeypatch, tmp_path):
    fake = tmp_path / "my-chrome"
    fake.write_text("")
    monkeypatch.setenv("ABGLIB_CHROMIUM", str(fake))
    assert find_chromium() == str(fake)
    monkeypatch.setenv("ABGLIB_CHROMIUM", str(tmp_path / "absent"))
    assert find_chromium() is None


def test_problems_are_listed_one_per_defect():
    c = PageCheck("file:///x.html", width=1280)
    assert c.problems == []
    c.network_requests.append("https://cdn.example/x.js")
    c.nan_cells, c.nan_examples = 2, ["NaN", "NaN"]
    c.overflow = 300
    assert c.problems == [
        "network request (blocked): https://cdn.example/x.js",
        "NaN in 2 table cells, e.g. ['NaN', 'NaN']",
        "horizontal overflow: the page is 1580 px wide in a 1280 px viewport",
    ]


# ---------------------------------------------------------------------- the driver
GOOD = """<!DOCTYPE html><html><head><meta charset="utf-8"><title>ok</title></head>
<body><h1>A clean page</h1><p>Price $5, ratio 1/2, a NaNometre is not a number.</p>
<table><tr><td>1.5</td><td></td></tr></table>
<img src="pixel.png" alt="one pixel">
<pre style="display:none">$$\\frac{1}{2}$$ hidden code is not visible text</pre>
</body></html>"""

# a 1x1 PNG
PIXEL = bytes.fromhex(
    "89504e470d0a1a0a0000000d4948445200000001000000010806000000"
    "1f15c4890000000d4944415478da63f8ffff3f0005fe02fea7d6a3c4"
    "0000000049454e44ae426082"
)


def _bad(port: int) -> str:
    return f"""<!DOCTYPE html><html><head><meta charset="utf-8">
<script src="http://127.0.0.1:{port}/cdn/mathjax.js"></script>
<link rel="stylesheet" href="missing.css"></head>
<body><p>Raw: $$\\frac{{a}}{{b}}$$ and \\(x\\), e^{{jωT}}</p>
<pre>code may write f"x_{{o}}" and x**{{2}}</pre>
<table><tr><td>NaN</td><td>1.0</td></tr><tr><td>2</td><td>nan NaN PC_{{3,1}}</td></tr></table>
<img src="figures/absent.png" alt="gone">
<div style="width:3000px">wide</div>
<script>console.error("boom"); throw new Error("uncaught here");</script>
</body></html>"""


@pytest.fixture
def server():
    """A live HTTP server on localhost, to prove that nothing reaches it."""
    hits = []

    class Handler(http.server.BaseHTTPRequestHandler):
        def do_GET(self):  # noqa: N802 (http.server's name)
            hits.append(self.path)
            self.send_response(200)
            self.end_headers()
            self.wfile.write(b"window.loaded = 1;")

        def log_message(self, *args):
            pass

    srv = http.server.ThreadingHTTPServer(("127.0.0.1", 0), Handler)
    t = threading.Thread(target=srv.serve_forever, daemon=True)
    t.start()
    yield srv.server_address[1], hits
    srv.shutdown()


@needs_chromium
def test_a_clean_page_passes_and_is_screenshot(browser, tmp_path):
    (tmp_path / "ok.html").write_text(GOOD, encoding="utf-8")
    (tmp_path / "pixel.png").write_bytes(PIXEL)
    shot = tmp_path / "shots" / "ok.png"
    c = check_page(browser, tmp_path / "ok.html", screenshot=shot)
    assert c.problems == []
    assert c.width == 1280 and c.height == 900  # a short page fills the viewport
    assert shot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


@needs_chromium
def test_every_defect_is_caught_and_nothing_leaves_the_browser(browser, tmp_path, server):
    port, hits = server
    (tmp_path / "bad.html").write_text(_bad(port), encoding="utf-8")
    c = check_page(browser, tmp_path / "bad.html")
    assert c.network_requests == [f"http://127.0.0.1:{port}/cdn/mathjax.js"]
    assert hits == []  # blocked inside the browser: the live server saw no request
    assert any("missing.css" in f and "ERR_FILE_NOT_FOUND" in f for f in c.failed_requests)
    assert any("absent.png" in f for f in c.failed_requests)
    assert c.broken_images == ["figures/absent.png"]
    assert any("boom" in e for e in c.console_errors)
    assert any("uncaught here" in e for e in c.console_errors)
    # each raw pattern once; "_{" only in code and a table cell, which are not prose
    assert [r.split(" ")[0] for r in c.raw_tex] == ["$$", "\\frac", "\\(", "$\\", "^{"]
    assert c.nan_cells == 2 and c.nan_examples == ["NaN", "nan NaN PC_{3,1}"]
    assert c.overflow > 1500
    assert len(c.problems) >= 8


def test_a_reply_to_a_command_posted_meanwhile_is_not_taken_for_the_awaited_one():
    """While :meth:`Browser.send` waits, an event handler may post a command (a page's
    intercepted request answered while another tab opens); that command's reply can come
    first. It once took it for its own (check_pages: KeyError 'targetId')."""
    b = object.__new__(Browser)  # the protocol alone, no Chromium
    b._id, b.timeout, b.events, written = 0, 5.0, [], []
    b._write = written.append
    incoming = iter(
        [
            {"method": "Fetch.requestPaused", "params": {"requestId": "r1"}},
            {"id": 2, "result": {}},  # the posted Fetch.continueRequest
            {"id": 1, "result": {"targetId": "T"}},
        ]
    )
    b._read = lambda deadline: next(incoming)
    b.on_event = lambda ev: b.post("Fetch.continueRequest", ev["params"])
    assert b.send("Target.createTarget") == {"targetId": "T"}
    assert [m["id"] for m in written] == [1, 2]


@needs_chromium
def test_pages_checked_together_are_checked_as_each_alone(browser, tmp_path, server):
    """check_pages keeps several pages open at once: each keeps its own defects and
    height, as checked alone."""
    port, hits = server
    (tmp_path / "pixel.png").write_bytes(PIXEL)
    pages = []
    for i in range(4):
        page = tmp_path / f"p{i}.html"
        body = GOOD if i % 2 else _bad(port)
        page.write_text(body.replace("</body>", "<p>x</p>" * (40 * i) + "</body>"), "utf-8")
        pages.append(page)
    alone = [check_page(browser, p) for p in pages]
    together = check_pages(browser, pages, batch=3)  # two batches
    # (the order of a page's events, two failed requests say, is the browser's, run to run)
    assert [(c.url, c.height, sorted(c.problems)) for c in together] == [
        (c.url, c.height, sorted(c.problems)) for c in alone
    ]
    assert [bool(c.problems) for c in together] == [True, False] * 2
    assert len({c.height for c in together}) == 4  # each page's own height
    assert hits == []


@needs_chromium
def test_check_folder_writes_screenshots_and_heights(browser, tmp_path):
    site = tmp_path / "v9.9.9"
    (site / "doc").mkdir(parents=True)
    (site / "index.html").write_text('<a href="doc/index.html">doc</a>', encoding="utf-8")
    tall = "<body>" + "<p>line</p>" * 300 + "</body>"
    (site / "doc" / "index.html").write_text(tall, encoding="utf-8")
    checks = check_folder(site, tmp_path / "shots", browser=browser)
    assert [c.problems for c in checks] == [[], []]
    rows = list(csv.DictReader(open(tmp_path / "shots" / "pages.csv", encoding="utf-8")))
    assert [r["page"] for r in rows] == ["index.html", "doc/index.html"]
    assert int(rows[1]["height_px"]) > 5000 > int(rows[0]["height_px"])
    assert (tmp_path / "shots" / "doc_index.png").stat().st_size > 1000


# ---------------------------------------------------------------------- the reports
def _folders() -> list[Path]:
    env = os.environ.get("ABGLIB_BROWSER_REPORTS")
    if env:
        return [Path(p) for p in env.split(os.pathsep) if p]
    return [REPO / "reports" / f"v{abglib.__version__}"]


def _pages():
    out = []
    for folder in _folders():
        pages = report_pages(folder) if folder.is_dir() else []
        if not pages:
            # the test itself skips (fails under CI): an absent folder checks nothing
            out.append(pytest.param(folder, None, id=f"{folder.name}-absent"))
        for p in pages:
            out.append(pytest.param(folder, p, id=f"{folder.name}/{p.relative_to(folder)}"))
    return out


def _screenshots_asked() -> bool:
    """``ABGLIB_SCREENSHOTS`` set to a folder or ``1``/``true``/``yes`` (not ``0``/``false``
    /``no``)."""
    return os.environ.get("ABGLIB_SCREENSHOTS", "").strip().lower() not in ("", "0", "false", "no")


def _shots(folder: Path) -> Path:
    """Where ``folder``'s ``pages.csv`` (and screenshots, :func:`_screenshot_of`) go:
    ``<root>/<folder name>``, the root ``$ABGLIB_SCREENSHOTS`` (``results/screenshots`` of
    the repository when unset or ``1``, ``true``, ``yes``), numbered when several folders
    are checked (a build and a release are both ``v<version>``)."""
    asked = os.environ.get("ABGLIB_SCREENSHOTS", "")
    default = not _screenshots_asked() or asked.strip().lower() in ("1", "true", "yes")
    root = REPO / "results" / "screenshots" if default else Path(asked)
    folders = _folders()
    if len(folders) == 1:
        return root / folder.name
    return root / f"{folders.index(folder) + 1}-{folder.name}"


def _screenshot_of(folder: Path, page: Path) -> Path | None:
    """The screenshot of ``page`` in :func:`_shots`, when ``ABGLIB_SCREENSHOTS`` asks for
    screenshots; else None."""
    if not _screenshots_asked():
        return None
    rel = page.relative_to(folder).as_posix()
    return _shots(folder) / (rel.replace("/", "_").removesuffix(".html") + ".png")


CHECKED: dict[Path, list[tuple[Path, PageCheck]]] = {}


@needs_chromium
@pytest.mark.parametrize("folder, page", _pages())
def test_report_page_in_the_browser(browser, folder, page):
    if page is None:
        require(f"no report folder with index.html at {folder}")
    shot = _screenshot_of(folder, page)
    c = check_page(browser, page, screenshot=shot)
    CHECKED.setdefault(folder, []).append((page, c))
    seen = f"screenshot {shot}" if shot else "ABGLIB_SCREENSHOTS=<folder> saves a screenshot"
    assert not c.problems, f"{page} ({seen}):\n  " + "\n  ".join(c.problems)


@needs_chromium
def test_page_heights_and_screenshots_are_recorded(capsys):
    """Runs after the pages: writes pages.csv per folder and prints the heights (and, with
    ``ABGLIB_SCREENSHOTS`` set, checks that every page has its screenshot)."""
    from ._browser import write_summary

    if not CHECKED:
        require("no report page was checked")
    lines = []
    for folder, checks in CHECKED.items():
        out = _shots(folder) / "pages.csv"
        write_summary([c for _, c in checks], folder, out)
        shots = _screenshots_asked()
        what = "screenshots and pages.csv" if shots else "pages.csv"
        lines.append(f"browser check of {folder}: {what} in {out.parent}")
        for page, c in checks:
            shot = _screenshot_of(folder, page)  # one file, or tiles <stem>-<n>.png
            tiles = [shot, *shot.parent.glob(f"{shot.stem}-*.png")] if shot else []
            assert bool(c.screenshot) == shots and (not shots or any(map(Path.is_file, tiles)))
            lines.append(
                f"  {page.relative_to(folder).as_posix():28s} {c.height:7d} px tall"
                f"  {len(c.problems)} problems"
            )
    with capsys.disabled():
        print("\n" + "\n".join(lines))
    assert all(out.is_file() for out in (_shots(f) / "pages.csv" for f in CHECKED))
