"""Check report pages in headless Chromium, offline, through the DevTools protocol.

Standard library only: Chromium is started with ``--remote-debugging-pipe``, which reads
commands on its file descriptor 3 and writes replies and events on 4, each a JSON message
ended by a NUL byte (no websocket, no Selenium or Playwright). Every request a page makes
passes through ``Fetch`` interception: ``file:`` and ``data:`` URLs go on, anything else is
recorded and failed, so the page is checked as a reader without network sees it.

:func:`check_pages` loads pages, several at once in tabs of their own, and returns a
:class:`PageCheck` each (:func:`check_page`: one page): failed requests,
network requests, console errors and uncaught exceptions, raw TeX in the visible text,
``NaN`` in table cells, broken images, horizontal overflow, the page height, and, when
asked for, a full-page screenshot. :func:`find_chromium` finds the browser (Debian package
``chromium``); ``ABGLIB_CHROMIUM`` names another binary.
"""

from __future__ import annotations

import base64
import fcntl
import json
import os
import select
import shutil
import subprocess
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

__all__ = [
    "Browser",
    "BrowserError",
    "PageCheck",
    "check_folder",
    "check_page",
    "check_pages",
    "find_chromium",
    "report_pages",
    "write_summary",
]

#: Viewport of every check (CSS pixels): a laptop screen.
VIEWPORT = (1280, 900)
#: Screenshots of taller pages are cut into tiles of this height (Chromium's limit is
#: 16384 px per side for one capture).
MAX_SCREENSHOT_HEIGHT = 16000

_FLAGS = [
    "--headless=new",
    "--remote-debugging-pipe",
    "--no-first-run",
    "--no-default-browser-check",
    "--disable-gpu",
    "--disable-dev-shm-usage",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--disable-extensions",
    "--disable-default-apps",
    "--metrics-recording-only",
    "--mute-audio",
    "--hide-scrollbars",
    "--font-render-hinting=none",
    # a second fence behind the Fetch interception: no proxy, no name resolves
    "--proxy-server=http://127.0.0.1:9",
    "--host-resolver-rules=MAP * ~NOTFOUND",
    f"--window-size={VIEWPORT[0]},{VIEWPORT[1]}",
]


class BrowserError(RuntimeError):
    """Chromium could not be started, or did not answer."""


def find_chromium() -> str | None:
    """Path of a Chromium binary (``$ABGLIB_CHROMIUM``, else ``chromium``,
    ``chromium-browser``, ``google-chrome`` on ``PATH``), or None."""
    env = os.environ.get("ABGLIB_CHROMIUM")
    if env:
        return env if Path(env).is_file() else shutil.which(env)
    for name in ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable"):
        path = shutil.which(name)
        if path:
            return path
    return None


class Browser:
    """One headless Chromium driven over ``--remote-debugging-pipe``.

    Use as a context manager; :meth:`send` sends a command (to the browser, or to a page's
    session) and returns its result, collecting the events that arrive meanwhile in
    :attr:`events`.
    """

    def __init__(self, binary: str | None = None, timeout: float = 60.0):
        self.binary = binary or find_chromium()
        if not self.binary:
            raise BrowserError("no Chromium found (apt-get install chromium, or $ABGLIB_CHROMIUM)")
        self.timeout = timeout
        self.events: list[dict] = []
        self._id = 0
        self._buf = b""
        self._profile = tempfile.TemporaryDirectory(prefix="abglib-chromium-")
        self._log = open(Path(self._profile.name) / "stderr.log", "wb")  # noqa: SIM115
        # fds 3 (Chromium reads) and 4 (Chromium writes) in the child
        to_child_r, self._to_child = os.pipe()
        self._from_child, from_child_w = os.pipe()
        args = [self.binary, *_FLAGS, f"--user-data-dir={self._profile.name}"]
        if hasattr(os, "geteuid") and os.geteuid() == 0:
            args.append("--no-sandbox")  # Chromium refuses to run as root with its sandbox
        args.append("about:blank")

        # move the child's ends above 4 first, so that placing them on 3 and 4 cannot
        # overwrite one with the other
        high = [fcntl.fcntl(fd, fcntl.F_DUPFD, 10) for fd in (to_child_r, from_child_w)]
        for fd in (to_child_r, from_child_w):
            os.close(fd)

        def _fds():
            os.dup2(high[0], 3)
            os.dup2(high[1], 4)

        self.proc = subprocess.Popen(
            args,
            stdin=subprocess.DEVNULL,
            stdout=subprocess.DEVNULL,
            # a file, not a pipe: a pipe nobody reads would fill and stall Chromium
            stderr=self._log,
            pass_fds=(3, 4),
            preexec_fn=_fds,
        )
        for fd in high:
            os.close(fd)
        try:
            self.version = self.send("Browser.getVersion")["product"]
        except BrowserError:
            self.close()
            raise

    # -- protocol --------------------------------------------------------------------
    def _write(self, msg: dict) -> None:
        data = json.dumps(msg).encode() + b"\0"
        try:
            while data:
                n = os.write(self._to_child, data)
                data = data[n:]
        except OSError as exc:
            raise BrowserError(f"Chromium closed its pipe: {exc}; {self._stderr()}") from None

    def _read(self, deadline: float) -> dict | None:
        while b"\0" not in self._buf:
            left = deadline - time.monotonic()
            if left <= 0:
                return None
            ready, _, _ = select.select([self._from_child], [], [], min(left, 0.5))
            if not ready:
                if self.proc.poll() is not None:
                    raise BrowserError(
                        f"Chromium exited ({self.proc.returncode}); {self._stderr()}"
                    )
                continue
            chunk = os.read(self._from_child, 1 << 20)
            if not chunk:
                raise BrowserError(f"Chromium closed its pipe; {self._stderr()}")
            self._buf += chunk
        msg, _, self._buf = self._buf.partition(b"\0")
        return json.loads(msg)

    def _stderr(self) -> str:
        """The end of Chromium's stderr."""
        try:
            return Path(self._log.name).read_text(errors="replace")[-2000:]
        except OSError:
            return ""

    def send(
        self,
        method: str,
        params: dict | None = None,
        session: str | None = None,
        timeout: float | None = None,
    ) -> dict:
        """Send one command and wait for its reply; events meanwhile go to
        :meth:`on_event` (which may :meth:`post` commands of its own)."""
        self._id += 1
        own = self._id  # a command posted meanwhile takes the next ids
        msg = {"id": own, "method": method, "params": params or {}}
        if session:
            msg["sessionId"] = session
        self._write(msg)
        deadline = time.monotonic() + (timeout or self.timeout)
        while True:
            reply = self._read(deadline)
            if reply is None:
                raise BrowserError(f"no reply to {method} within {timeout or self.timeout} s")
            if "id" in reply and reply["id"] != own:
                continue  # the reply to a posted command
            if reply.get("id") == own:
                if "error" in reply:
                    raise BrowserError(f"{method}: {reply['error'].get('message')}")
                return reply.get("result", {})
            self.on_event(reply)

    def post(self, method: str, params: dict | None = None, session: str | None = None) -> None:
        """Send one command without waiting for its reply (which :meth:`send` will skip):
        to answer an intercepted request from inside an event handler."""
        self._id += 1
        msg = {"id": self._id, "method": method, "params": params or {}}
        if session:
            msg["sessionId"] = session
        self._write(msg)

    def on_event(self, event: dict) -> None:
        """Called for every event; the default keeps it in :attr:`events`. A page check
        replaces it to answer intercepted requests as they come."""
        self.events.append(event)

    def pump(self, seconds: float, until=None) -> None:
        """Handle events for ``seconds``, or until ``until()`` is true after one."""
        deadline = time.monotonic() + seconds
        if until is not None and until():
            return
        while (event := self._read(deadline)) is not None:
            self.on_event(event)
            if until is not None and until():
                return

    def close(self) -> None:
        if self.proc.poll() is None:
            try:
                self._write({"id": self._id + 1, "method": "Browser.close", "params": {}})
                self.proc.wait(timeout=10)
            except (BrowserError, subprocess.TimeoutExpired):
                self.proc.kill()
                self.proc.wait()
        for fd in (self._to_child, self._from_child):
            try:
                os.close(fd)
            except OSError:
                pass
        self._log.close()
        self._profile.cleanup()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


# ---------------------------------------------------------------------------- checks
@dataclass
class PageCheck:
    """What one page did in the browser."""

    url: str
    height: int = 0
    width: int = 0
    failed_requests: list[str] = field(default_factory=list)
    network_requests: list[str] = field(default_factory=list)
    console_errors: list[str] = field(default_factory=list)
    raw_tex: list[str] = field(default_factory=list)
    nan_cells: int = 0
    nan_examples: list[str] = field(default_factory=list)
    broken_images: list[str] = field(default_factory=list)
    overflow: int = 0
    screenshot: str = ""

    @property
    def problems(self) -> list[str]:
        """Every defect, one line each (empty when the page passes)."""
        out = [f"request failed: {u}" for u in self.failed_requests]
        out += [f"network request (blocked): {u}" for u in self.network_requests]
        out += [f"console error: {m}" for m in self.console_errors]
        out += [f"raw TeX in the visible text: {s}" for s in self.raw_tex]
        if self.nan_cells:
            out.append(f"NaN in {self.nan_cells} table cells, e.g. {self.nan_examples}")
        out += [f"broken image: {s}" for s in self.broken_images]
        if self.overflow:
            out.append(
                f"horizontal overflow: the page is {self.width + self.overflow} px wide in a "
                f"{self.width} px viewport"
            )
        return out


#: Raw TeX a reader must never see anywhere in the visible text: display math, a fraction,
#: math delimiters.
RAW_TEX = ("$$", "\\frac", "\\(", "\\[")
#: Raw TeX that is wrong in visible prose (outside code, where Python has the same
#: characters, and outside table cells, which show CSV text as written): a dollar before a
#: command (``$\\alpha``), and super- or subscripts in braces written outside any math
#: (``e^{jωT}``, ``∫_{−∞}``).
RAW_TEX_PROSE = ("$\\", "^{", "_{")

_INSPECT = r"""
(() => {
  const text = document.body ? document.body.innerText : "";
  // visible prose: text nodes that are rendered and not inside code, typeset math or a
  // table cell (cells show CSV text as written, e.g. the transcribed quantity "PC_{3,1}")
  const skip = "code, pre, kbd, samp, script, style, textarea, mjx-container, .MathJax, .katex, "
             + "td, th";
  const walker = document.createTreeWalker(document.body || document.documentElement,
                                           NodeFilter.SHOW_TEXT);
  const parts = [];
  for (let n = walker.nextNode(); n; n = walker.nextNode()) {
    const el = n.parentElement;
    if (!el || el.closest(skip)) continue;
    if (el.checkVisibility && !el.checkVisibility({visibilityProperty: true})) continue;
    parts.push(n.nodeValue);
  }
  const prose = parts.join(" ");
  const raw = [];
  const find = (pats, t) => {
    for (const pat of pats) {
      const i = t.indexOf(pat);
      if (i < 0) continue;
      const n = t.split(pat).length - 1;
      raw.push(pat + " (" + n + "×) … " + JSON.stringify(t.slice(Math.max(0, i - 40), i + 60)));
    }
  };
  find(%s, text);
  find(%s, prose);
  const cells = [...document.querySelectorAll("td, th")]
    .filter(c => /(^|[^A-Za-z])NaN([^A-Za-z]|$)/.test(c.textContent));
  const broken = [...document.images]
    .filter(im => !im.complete || im.naturalWidth === 0)
    .map(im => (im.getAttribute("src") || "").slice(0, 120));
  const de = document.documentElement, body = document.body || de;
  return {raw, nan: cells.length, nanEx: cells.slice(0, 3).map(c => c.textContent.slice(0, 60)),
          broken, scrollWidth: Math.max(de.scrollWidth, body.scrollWidth),
          width: de.clientWidth, height: Math.max(de.scrollHeight, body.scrollHeight)};
})()
"""

# wait for MathJax (if the page has it) to finish typesetting, at most a few seconds
_SETTLE = r"""
new Promise(resolve => {
  const done = () => resolve(true);
  setTimeout(done, 8000);
  const mj = window.MathJax;
  if (mj && mj.startup && mj.startup.promise) mj.startup.promise.then(done, done);
  else if (mj && mj.Hub && mj.Hub.Queue) mj.Hub.Queue(done);
  else done();
})
"""


#: How long a page's events are still collected after it loaded and settled (s): a late
#: console error or uncaught exception of its scripts.
GRACE = 0.3
#: How many pages :func:`check_pages` has open at once, each in a tab of its own.
BATCH = 8


class _Page:
    """One page's check under way: its tab (target and session) and what it did."""

    def __init__(self, browser: Browser, path, screenshot):
        self.browser, self.screenshot = browser, screenshot
        self.url = Path(path).resolve().as_uri()
        self.res = PageCheck(self.url)
        self.loaded = False
        self.requests: dict[str, str] = {}
        # a window of its own: a background tab draws no frames (no screenshot) and has
        # its timers throttled
        new = {"url": "about:blank", "newWindow": True}
        self.target = browser.send("Target.createTarget", new)["targetId"]
        self.session = browser.send(
            "Target.attachToTarget", {"targetId": self.target, "flatten": True}
        )["sessionId"]

    def on_event(self, ev) -> None:
        """Answer an intercepted request (file, data, blob and about URLs go on, anything
        else is recorded and failed) and record what the page did."""
        res, browser, session = self.res, self.browser, self.session
        method, p = ev.get("method"), ev.get("params", {})
        if method == "Fetch.requestPaused":
            req_url = p["request"]["url"]
            if req_url.startswith(("file:", "data:", "blob:", "about:")):
                browser.post("Fetch.continueRequest", {"requestId": p["requestId"]}, session)
            else:
                res.network_requests.append(req_url)
                browser.post(
                    "Fetch.failRequest",
                    {"requestId": p["requestId"], "errorReason": "BlockedByClient"},
                    session,
                )
        elif method == "Network.requestWillBeSent":
            self.requests[p["requestId"]] = p["request"]["url"]
        elif method == "Network.loadingFailed":
            u = self.requests.get(p["requestId"], "?")
            if u not in res.network_requests:  # the blocked ones are reported as such
                res.failed_requests.append(f"{u} ({p.get('errorText', '')})")
        elif method == "Network.responseReceived":
            status = p["response"].get("status", 200)
            if status >= 400:
                res.failed_requests.append(f"{p['response']['url']} (HTTP {status})")
        elif method == "Runtime.consoleAPICalled" and p.get("type") in ("error", "assert"):
            args = [str(a.get("value", a.get("description", ""))) for a in p.get("args", [])]
            res.console_errors.append(" ".join(args)[:300])
        elif method == "Runtime.exceptionThrown":
            d = p.get("exceptionDetails", {})
            text = d.get("exception", {}).get("description") or d.get("text", "")
            res.console_errors.append(f"uncaught: {text[:300]}")
        elif method == "Log.entryAdded" and p["entry"].get("level") == "error":
            e = p["entry"]
            u = e.get("url", "")
            if not any(u and u in x for x in res.network_requests):
                res.console_errors.append(f"{e.get('text', '')[:300]} {u}".strip())
        elif method == "Page.loadEventFired":
            self.loaded = True

    def open(self) -> None:
        """Intercept the tab's requests, listen to it, and navigate to the page."""
        for m, params in (
            ("Fetch.enable", {"patterns": [{"urlPattern": "*"}]}),
            ("Network.enable", {}),
            ("Page.enable", {}),
            ("Runtime.enable", {}),
            ("Log.enable", {}),
            (
                "Emulation.setDeviceMetricsOverride",
                {
                    "width": VIEWPORT[0],
                    "height": VIEWPORT[1],
                    "deviceScaleFactor": 1,
                    "mobile": False,
                },
            ),
        ):
            self.browser.send(m, params, self.session)
        nav = self.browser.send("Page.navigate", {"url": self.url}, self.session)
        if nav.get("errorText"):
            self.res.failed_requests.append(f"{self.url} ({nav['errorText']})")

    def inspect(self) -> None:
        """What the loaded page shows (:data:`_INSPECT`), and its screenshot if asked."""
        res = self.res
        pats = (json.dumps(list(RAW_TEX)), json.dumps(list(RAW_TEX_PROSE)))
        info = _evaluate(self.browser, self.session, _INSPECT % pats)
        res.raw_tex = info["raw"]
        res.nan_cells, res.nan_examples = info["nan"], info["nanEx"]
        res.broken_images = info["broken"]
        res.width, res.height = info["width"], info["height"]
        res.overflow = max(0, info["scrollWidth"] - info["width"])
        if self.screenshot is not None:
            shots = _screenshot(self.browser, self.session, self.screenshot, res.height)
            res.screenshot = " ".join(str(p) for p in shots)

    def close(self) -> None:
        try:
            self.browser.send("Target.closeTarget", {"targetId": self.target})
        except BrowserError:
            pass


def check_pages(browser: Browser, pages, timeout: float = 60.0, batch: int = BATCH):
    """Load the HTML files ``pages`` offline and check each (see :class:`PageCheck`);
    returns their checks in order.

    ``pages`` holds paths, or ``(path, screenshot)`` pairs where ``screenshot`` is a path
    for a full-page PNG (tiles ``<stem>-<n>.png`` for a page taller than
    :data:`MAX_SCREENSHOT_HEIGHT`; :attr:`PageCheck.screenshot` lists them) or None.
    ``batch`` pages at a time each load in a tab of their own, and each is inspected only
    after it loaded (``timeout`` s at most), settled (:data:`_SETTLE`) and had
    :data:`GRACE` s more for late errors: the tabs wait those out together (one page after
    the other, the docs site's 212 pages took 130 s, mostly waiting)."""
    items = [(p, None) if isinstance(p, (str, os.PathLike)) else tuple(p) for p in pages]
    out: list[PageCheck] = []
    old_handler = browser.on_event
    for i in range(0, len(items), batch):
        group: list[_Page] = []
        sessions: dict[str, _Page] = {}

        def route(ev, sessions=sessions):
            page = sessions.get(ev.get("sessionId"))
            if page is not None:  # other tabs' and the browser's own events: not ours
                page.on_event(ev)

        browser.on_event = route
        try:
            for path, shot in items[i : i + batch]:
                page = _Page(browser, path, shot)
                group.append(page)
                sessions[page.session] = page
                page.open()
            browser.pump(timeout, until=lambda g=group: all(p.loaded for p in g))
            for page in group:
                if not page.loaded:
                    page.res.console_errors.append(
                        f"the page did not finish loading within {timeout} s"
                    )
                _evaluate(browser, page.session, _SETTLE)
            browser.pump(GRACE)
            for page in group:
                page.inspect()
                out.append(page.res)
        finally:
            browser.on_event = old_handler
            for page in group:
                page.close()
    return out


def check_page(browser: Browser, path, screenshot=None, timeout: float = 60.0) -> PageCheck:
    """Load the HTML file ``path`` offline and check it (:func:`check_pages` of one page)."""
    return check_pages(browser, [(path, screenshot)], timeout)[0]


def _evaluate(browser: Browser, session: str, expr: str) -> dict:
    out = browser.send(
        "Runtime.evaluate",
        {"expression": expr, "returnByValue": True, "awaitPromise": True},
        session,
        timeout=30,
    )
    if "exceptionDetails" in out:
        raise BrowserError(f"page script failed: {out['exceptionDetails'].get('text')}")
    return out["result"].get("value")


def _screenshot(browser: Browser, session: str, path, height: int) -> list[Path]:
    """Full-page PNG at ``path``; a page taller than :data:`MAX_SCREENSHOT_HEIGHT` is cut
    into tiles ``<stem>-1.png``, ``<stem>-2.png``, ... from the top (one capture holds at
    most 16384 px a side). Returns the files written."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    height = max(1, int(height))
    tiles = range(0, height, MAX_SCREENSHOT_HEIGHT)
    written = []
    for n, top in enumerate(tiles, start=1):
        h = min(MAX_SCREENSHOT_HEIGHT, height - top)
        clip = {"x": 0, "y": top, "width": VIEWPORT[0], "height": h, "scale": 1}
        shot = browser.send(
            "Page.captureScreenshot",
            {"format": "png", "captureBeyondViewport": True, "clip": clip},
            session,
            timeout=120,
        )
        out = path if len(tiles) == 1 else path.with_name(f"{path.stem}-{n}{path.suffix}")
        out.write_bytes(base64.b64decode(shot["data"]))
        written.append(out)
    return written


def report_pages(folder) -> list[Path]:
    """The pages of a report version folder a reader opens: ``index.html``, every
    ``<sub>/index.html`` and ``changes.html`` when present."""
    folder = Path(folder)
    pages = [folder / "index.html"]
    pages += sorted(p for p in folder.glob("*/index.html"))
    if (folder / "changes.html").is_file():
        pages.append(folder / "changes.html")
    return [p for p in pages if p.is_file()]


def check_folder(folder, shots=None, browser: Browser | None = None) -> list[PageCheck]:
    """Check every page of a report version folder (:func:`report_pages`); with ``shots``
    a folder, save a full-page screenshot of each there (``<page path with _>.png``) and
    write ``pages.csv`` (page, height, problems) beside them."""
    folder = Path(folder)
    own = browser is None
    browser = browser or Browser()
    try:
        pages = []
        for page in report_pages(folder):
            rel = page.relative_to(folder).as_posix()
            shot = (
                Path(shots) / (rel.replace("/", "_").removesuffix(".html") + ".png")
                if shots
                else None
            )
            pages.append((page, shot))
        checks = check_pages(browser, pages)
    finally:
        if own:
            browser.close()
    if shots:
        write_summary(checks, folder, Path(shots) / "pages.csv")
    return checks


def write_summary(checks: list[PageCheck], folder, path) -> None:
    """``pages.csv``: one row per page: its path in ``folder``, height and width in CSS px,
    the number of problems, the screenshot and the first problem."""
    import csv

    root = Path(folder).resolve().as_uri() + "/"
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(["page", "height_px", "width_px", "problems", "screenshot", "first_problem"])
        for c in checks:
            p = c.problems
            w.writerow(
                [
                    c.url.removeprefix(root),
                    c.height,
                    c.width,
                    len(p),
                    c.screenshot,
                    p[0][:200] if p else "",
                ]
            )
