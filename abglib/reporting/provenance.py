"""Provenance of a report: versions, git commit, config hash, seeds (``CONTRACTS.md`` §4).

Everything here is deterministic for a given environment, checkout and config: no
timestamps, no host names, no absolute paths.

One source for each value
-------------------------
abglib's version is ``abglib.__version__``, the same value that names the version folder
(``VERSION`` in ``workflow/rules/common.smk``) and the ``abglib`` command's defaults; it is
never read from the installed distribution's metadata. That metadata is written when the
package is installed (an editable install's ``*.egg-info`` / ``dist-info``) and is not
rewritten when ``pyproject.toml`` is bumped, so it can name an older version than the code
that runs: the v0.3.1 release was built under metadata of 0.3.0 and its pages say "abglib
version 0.3.0" (``tests/test_provenance.py`` lists it as a known exception). The
dependencies' versions are those of their installed distributions, and the commit is the
checkout's, both read when a page is rendered.

A release folder states the provenance of the one build that made it: :func:`release_problems`
reads what every page of a folder states (:func:`stated`) and lists each page whose version
differs from the release's, or whose commit or dependency versions differ from the other
pages'; ``abglib release`` refuses to cut a release while there is any.
"""

from __future__ import annotations

import platform
import re
import subprocess
from collections.abc import Mapping
from html.parser import HTMLParser
from importlib import metadata
from pathlib import Path

from .._checks import AbglibValueError
from ..common.files import config_hash

__all__ = [
    "PACKAGES",
    "SAME_IN_A_RELEASE",
    "abglib_version",
    "collect",
    "find_seeds",
    "git_commit",
    "package_versions",
    "release_pages",
    "release_problems",
    "stated",
    "to_markdown",
]

#: Distributions whose versions every report states.
PACKAGES = ("abglib", "numpy", "scipy", "pandas", "matplotlib", "numba", "snakemake")


def git_commit(path=".", ignore=("reports",)) -> str | None:
    """The commit checked out at ``path``, ``+dirty`` if tracked files changed, or None.

    Changes under ``ignore`` (top-level folders of the repository) do not count: a build
    rewrites the committed reports it is building, and that must not mark the code it was
    built from as modified. None when git is missing or ``path`` is not in a repository
    (e.g. an unpacked tarball).
    """

    def git(*args):
        return subprocess.run(
            ["git", *args], cwd=Path(path), capture_output=True, text=True, check=True, timeout=30
        ).stdout

    try:
        commit = git("rev-parse", "HEAD").strip()
        top = git("rev-parse", "--show-toplevel").strip()
        excludes = [f":(exclude,top){d}" for d in ignore]
        changed = subprocess.run(
            ["git", "status", "--porcelain", "--untracked-files=no", "--", top, *excludes],
            cwd=Path(path),
            capture_output=True,
            text=True,
            check=True,
            timeout=30,
        ).stdout
    except (OSError, subprocess.SubprocessError):
        return None
    if not commit:
        return None
    return commit + ("+dirty" if changed.strip() else "")


def abglib_version() -> str:
    """The version of the abglib that runs: ``abglib.__version__``.

    The one source of the version a build states; the installed metadata may be stale (see
    the module docstring).
    """
    from .. import __version__

    return __version__


def package_versions(packages=PACKAGES) -> dict[str, str]:
    """Versions of ``packages`` (``'not installed'`` when absent), plus Python.

    ``abglib`` is :func:`abglib_version`; every other package is its installed
    distribution's version.
    """
    versions = {"python": platform.python_version()}
    for name in packages:
        if name == "abglib":
            versions[name] = abglib_version()
            continue
        try:
            versions[name] = metadata.version(name)
        except metadata.PackageNotFoundError:
            versions[name] = "not installed"
    return versions


def find_seeds(config, prefix: str = "") -> dict[str, int]:
    """Every integer in ``config`` under a key named ``seed`` or ending in ``_seed``."""
    seeds: dict[str, int] = {}
    if isinstance(config, Mapping):
        for key, value in config.items():
            name = f"{prefix}.{key}" if prefix else str(key)
            if (key == "seed" or str(key).endswith("_seed")) and isinstance(value, int):
                seeds[name] = value
            else:
                seeds.update(find_seeds(value, name))
    elif isinstance(config, list):
        for i, value in enumerate(config):
            seeds.update(find_seeds(value, f"{prefix}[{i}]"))
    return seeds


def collect(config: Mapping, repo=".") -> dict:
    """Provenance record of a report built with ``config`` from the checkout at ``repo``."""
    return {
        "abglib_version": abglib_version(),
        "git_commit": git_commit(repo) or "unknown (not a git checkout)",
        "config_sha256": config_hash(config),
        "versions": package_versions(),
        "seeds": find_seeds(config),
    }


def to_markdown(prov: Mapping) -> str:
    """A small markdown table of a :func:`collect` record, for a report's provenance cell."""
    lines = ["| item | value |", "| --- | --- |"]
    lines.append(f"| abglib version | `{prov['abglib_version']}` |")
    lines.append(f"| git commit | `{prov['git_commit']}` |")
    lines.append(f"| config sha256 | `{prov['config_sha256']}` |")
    for name, version in prov["versions"].items():
        lines.append(f"| {name} | `{version}` |")
    seeds = prov.get("seeds") or {}
    text = ", ".join(f"`{k}` = {v}" for k, v in sorted(seeds.items())) or "none used"
    lines.append(f"| random seeds | {text} |")
    return "\n".join(lines)


# ------------------------------------------------------------ what a release folder states
#: The rows of a provenance table that every page of one release states alike (the config
#: hash and the seeds are left out: the index page shortens long cells).
SAME_IN_A_RELEASE = ("abglib version", "git commit", "python", *PACKAGES)


class _TableRead(Exception):
    """Raised by :class:`_ProvenanceTable` at the end of the table: the rest of the page
    is not parsed."""


#: Where a page's provenance heading may start (the parser confirms it): parsing starts
#: there, not at the top of a page whose figures are thousands of SVG elements.
_HEADING = re.compile(r"<h2\b[^>]*\bid\s*=\s*[\"']?provenance\b", re.IGNORECASE)


class _ProvenanceTable(HTMLParser):
    """The ``item | value`` rows of the first table after ``<h2 id="provenance">``."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.state = "before"  # before -> heading -> table -> done
        self.rows: dict[str, str] = {}
        self._row: list[str] | None = None
        self._cell: list[str] | None = None

    def handle_starttag(self, tag, attrs):
        if self.state == "before" and tag == "h2" and ("id", "provenance") in attrs:
            self.state = "heading"
        elif self.state == "heading" and tag == "table":
            self.state = "table"
        elif self.state == "table" and tag == "tr":
            self._row = []
        elif self.state == "table" and tag == "td" and self._row is not None:
            self._cell = []

    def handle_endtag(self, tag):
        if self.state != "table":
            return
        if tag == "td" and self._cell is not None and self._row is not None:
            self._row.append("".join(self._cell).strip())
            self._cell = None
        elif tag == "tr" and self._row is not None:
            if len(self._row) >= 2:
                self.rows[self._row[0]] = self._row[1]
            self._row = None
        elif tag == "table":
            self.state = "done"
            raise _TableRead

    def handle_data(self, data):
        if self._cell is not None:
            self._cell.append(data)


def stated(page) -> dict[str, str]:
    """What a rendered page states as its provenance: ``{item: value}`` of its table.

    Parameters
    ----------
    page : path
        A report page or a version's ``index.html`` (:func:`to_markdown`'s rows, rendered
        by :mod:`abglib.reporting.page` under the heading ``Provenance``).

    Returns
    -------
    dict
        E.g. ``{"abglib version": "0.4.0", "git commit": "...", "numpy": "2.4.6", ...}``;
        empty when the page has no provenance table.
    """
    text = Path(page).read_text(encoding="utf-8")
    heading = _HEADING.search(text)
    parser = _ProvenanceTable()
    try:
        # from the heading on (a page without one is parsed whole: the parser decides)
        parser.feed(text[heading.start() :] if heading else text)
        parser.close()
    except _TableRead:
        pass
    return parser.rows


def release_pages(folder) -> list[Path]:
    """The pages of a version folder that state a provenance: ``index.html`` and every
    ``<report>/index.html``."""
    folder = Path(folder)
    if not folder.is_dir():
        raise AbglibValueError(f"a version folder must be a directory, got {str(folder)!r}")
    top = [folder / "index.html"] if (folder / "index.html").is_file() else []
    return top + sorted(folder.glob("*/index.html"))


def release_problems(folder, version: str) -> list[str]:
    """Why ``folder`` does not state the provenance of one build of ``version``; [] if it does.

    Every page (:func:`release_pages`) must state a provenance whose ``abglib version`` and
    ``abglib`` rows are ``version``, and every row of :data:`SAME_IN_A_RELEASE` must be
    the same on every page (one build made the folder: one commit, one set of dependency
    versions). ``CONTRACTS.md`` §4: "the provenance of a release folder
    ``reports/v<version>/`` states that same version (the build that made it)".

    Parameters
    ----------
    folder : path
        A version folder (a build's ``results/reports/v<version>`` or a release).
    version : str
        The release's version, e.g. ``"0.4.0"``.

    Returns
    -------
    list of str
        One line per problem, naming the page, the row and both values.
    """
    pages = release_pages(folder)
    if not pages:
        return [f"{folder}: no index.html, nothing states a provenance"]
    problems = []
    first: tuple[str, dict[str, str]] | None = None
    for page in pages:
        rel = page.relative_to(folder).as_posix()
        rows = stated(page)
        if not rows:
            problems.append(f"{rel}: no provenance table")
            continue
        for item in ("abglib version", "abglib"):
            if rows.get(item) != version:
                problems.append(
                    f"{rel}: states {item} {rows.get(item, '(missing)')}, the release is {version}"
                )
        if first is None:
            first = (rel, rows)
            continue
        for item in SAME_IN_A_RELEASE:
            if item.startswith("abglib"):
                continue  # judged against the release's version above
            if rows.get(item) != first[1].get(item):
                problems.append(
                    f"{rel}: states {item} {rows.get(item, '(missing)')}, "
                    f"{first[0]} states {first[1].get(item, '(missing)')} (one build makes a "
                    "release)"
                )
    return problems
