"""Provenance of the reports (abglib.reporting.provenance; CONTRACTS.md §4) and pipeline helpers."""

import subprocess
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import abglib
from abglib import AbglibValueError
from abglib.common.files import atomic_output, config_hash
from abglib.replications.steelman1978.study import wt_grid
from abglib.reporting import provenance
from abglib.reporting.cli import main
from abglib.reporting.page import markdown_html
from abglib.reporting.provenance import (
    SAME_IN_A_RELEASE,
    collect,
    find_seeds,
    git_commit,
    release_pages,
    release_problems,
    stated,
    to_markdown,
)
from abglib.reporting.render import write_index
from abglib.reporting.versions import folder_version, version_key

from .conftest import require


def test_config_hash_ignores_key_order_and_sees_values():
    a = {"x": 1, "y": {"b": [1, 2], "a": 0.5}}
    b = {"y": {"a": 0.5, "b": [1, 2]}, "x": 1}
    assert config_hash(a) == config_hash(b)
    assert config_hash(a) != config_hash({**a, "x": 2})
    assert len(config_hash(a)) == 64


def test_find_seeds_nested():
    cfg = {"seed": 1, "mc": {"noise_seed": 7, "n": 3}, "runs": [{"seed": 9}], "label": "s"}
    assert find_seeds(cfg) == {"seed": 1, "mc.noise_seed": 7, "runs[0].seed": 9}


def test_git_commit_tolerates_no_repository(tmp_path):
    assert git_commit(tmp_path) is None
    rec = collect({"seed": 3}, repo=tmp_path)
    assert rec["git_commit"].startswith("unknown")
    assert rec["seeds"] == {"seed": 3}
    for name in ("python", "numpy", "scipy", "pandas", "matplotlib", "snakemake"):
        assert name in rec["versions"]
    text = to_markdown(rec)
    assert "config sha256" in text and "`seed` = 3" in text
    assert str(tmp_path) not in text


def test_git_commit_in_a_repository(tmp_path):
    try:
        subprocess.run(["git", "init", "-q", str(tmp_path)], check=True)
        (tmp_path / "f").write_text("x")
        env = ["-c", "user.name=t", "-c", "user.email=t@t"]
        subprocess.run(["git", *env, "-C", str(tmp_path), "add", "f"], check=True)
        subprocess.run(["git", *env, "-C", str(tmp_path), "commit", "-qm", "m"], check=True)
    except (OSError, subprocess.CalledProcessError):
        require("git not available")
    commit = git_commit(tmp_path)
    assert commit is not None and len(commit) == 40
    # a rebuilt committed report does not make the code dirty; any other change does
    (tmp_path / "reports").mkdir()
    (tmp_path / "reports" / "r.html").write_text("a")
    subprocess.run(["git", *env, "-C", str(tmp_path), "add", "reports"], check=True)
    subprocess.run(["git", *env, "-C", str(tmp_path), "commit", "-qm", "r"], check=True)
    commit = git_commit(tmp_path)
    (tmp_path / "reports" / "r.html").write_text("b")
    assert git_commit(tmp_path) == commit
    assert git_commit(tmp_path / "reports") == commit
    (tmp_path / "f").write_text("y")
    assert git_commit(tmp_path) == commit + "+dirty"


def test_atomic_output_leaves_nothing_on_failure(tmp_path):
    target = tmp_path / "out.csv"
    target.write_text("old")
    with pytest.raises(RuntimeError), atomic_output(target) as tmp:
        tmp.write_text("half-written")
        raise RuntimeError("interrupted")
    assert target.read_text() == "old"
    assert [p.name for p in tmp_path.iterdir()] == ["out.csv"]
    with atomic_output(target) as tmp:
        tmp.write_text("new")
    assert target.read_text() == "new"


def test_wt_grid():
    g = wt_grid({"start": 0.0, "stop_over_pi": 1.0, "n": 5}, "linear")
    assert g[0] == 0.0 and g[-1] == pytest.approx(np.pi) and g.size == 5
    lg = wt_grid({"start": 0.01, "stop_over_pi": 1.0, "n": 3}, "log")
    assert lg[1] == pytest.approx(np.sqrt(0.01 * np.pi))
    with pytest.raises(AbglibValueError, match="start > 0"):
        wt_grid({"start": 0.0, "stop_over_pi": 1.0, "n": 3}, "log")


# ------------------------------------------------- one source of truth for a release's provenance
REPO = Path(__file__).resolve().parents[1]
REPORTS = REPO / "reports"
#: The first page format whose provenance :func:`stated` reads (``<h2 id="provenance">``);
#: v0.1.0 and v0.2.0 are frozen history in an older format, checked by nobody.
FIRST_READABLE = (0, 3, 0)
#: Release folders known to state a wrong provenance, frozen history (a release folder is
#: never rewritten, CONTRACTS.md §4), each with what it states and why. v0.3.1 was built under
#: an editable install whose metadata (a stale egg-info) still said 0.3.0, and provenance
#: then read abglib's version from that metadata instead of ``abglib.__version__`` (issue 22).
KNOWN_WRONG = {"v0.3.1": {"abglib version": "0.3.0", "abglib": "0.3.0"}}


def _version_folders():
    return sorted(
        (p for p in REPORTS.iterdir() if p.is_dir() and version_key(p.name)),
        key=lambda p: version_key(p.name),
    )


def _prov(version="9.9.9", commit="0" * 40, numpy="2.4.6"):
    rec = collect({"seed": 3}, repo=REPO)
    rec = {**rec, "abglib_version": version, "git_commit": commit}
    rec["versions"] = {**rec["versions"], "abglib": version, "numpy": numpy}
    return rec


def _index(folder, prov):
    """A version folder's index.html as the pipeline writes it (render.write_index)."""
    card = pd.DataFrame({"doc": ["doc"], "match": [1], "total": [1]})
    docs = [{"doc": "doc", "title": "Doc", "href": "doc/index.html", "headline": ""}]
    write_index(folder / "index.html", prov["abglib_version"], card, docs, prov)


def _report(folder, prov, doc="doc"):
    """A report page's provenance as a notebook shows it: its markdown heading (the page
    gives it the id) and ``to_markdown``'s table rendered by the page's markdown."""
    (folder / doc).mkdir(parents=True, exist_ok=True)
    body = '<h2 id="provenance">Provenance</h2>\n' + markdown_html(to_markdown(prov))
    (folder / doc / "index.html").write_text(f"<html><body>{body}</body></html>", "utf-8")


def test_abglib_version_is_the_code_s_not_the_installed_metadata(monkeypatch):
    """A stale install (metadata of an older version) does not change what a build states."""
    real = provenance.metadata.version

    def stale(name):
        return "0.0.1" if name == "abglib" else real(name)

    monkeypatch.setattr(provenance.metadata, "version", stale)
    rec = collect({}, repo=REPO)
    assert rec["abglib_version"] == abglib.__version__ == rec["versions"]["abglib"]
    assert rec["versions"]["numpy"] == real("numpy")  # dependencies: their installed versions


def test_stated_reads_back_the_provenance_a_page_was_rendered_with(tmp_path):
    prov = collect({"seed": 3}, repo=REPO)
    _index(tmp_path, prov)
    _report(tmp_path, prov)
    rows = {
        cells[0]: cells[1]
        for line in to_markdown(prov).splitlines()[2:]
        if (cells := [c.strip().replace("`", "") for c in line.strip("|").split("|")])
    }
    for page in (tmp_path / "index.html", tmp_path / "doc" / "index.html"):
        got = stated(page)
        assert got["abglib version"] == abglib.__version__
        assert {k: got[k] for k in SAME_IN_A_RELEASE} == {k: rows[k] for k in SAME_IN_A_RELEASE}
    assert stated(tmp_path / "doc" / "index.html") == rows  # nothing shortened there
    (tmp_path / "plain.html").write_text("<h2>Provenance</h2><table></table>")
    assert stated(tmp_path / "plain.html") == {}


@pytest.mark.parametrize(
    "heading",
    ['<h2 id="provenance">', "<H2 class='x' ID='provenance'>", "<h2 id=provenance>"],
)
def test_stated_reads_only_the_first_table_after_the_heading(tmp_path, heading):
    """Whatever the heading's spelling, only the table after it is read: not a table
    before it, not one after it, not a decoy in a figure's markup."""
    row = "<tr><td>{}</td><td>{}</td></tr>"
    page = (
        "<table>"
        + row.format("abglib version", "before")
        + "</table>"
        + '<svg><g id="provenance"></g></svg>' * 3
        + heading
        + "Provenance</h2><p>text</p><table>"
        + row.format("item", "value")
        + row.format("abglib version", "9.9.9")
        + "</table>"
        + "<table>"
        + row.format("abglib version", "after")
        + "</table>"
    )
    (tmp_path / "p.html").write_text(page, encoding="utf-8")
    assert stated(tmp_path / "p.html") == {"item": "value", "abglib version": "9.9.9"}


def test_release_problems_names_every_disagreement(tmp_path):
    good = tmp_path / "good"
    _index(good, _prov())
    _report(good, _prov(), "a")
    _report(good, _prov(), "b")
    pages = [good / "index.html", good / "a" / "index.html", good / "b" / "index.html"]
    assert release_pages(good) == pages
    assert release_problems(good, "9.9.9") == []
    assert release_problems(good, "9.9.8") == [
        f"{page}: states {item} 9.9.9, the release is 9.9.8"
        for page in ("index.html", "a/index.html", "b/index.html")
        for item in ("abglib version", "abglib")
    ]
    bad = tmp_path / "bad"
    _index(bad, _prov())
    _report(bad, _prov(commit="1" * 40), "a")  # a page left from a build of another commit
    _report(bad, _prov(numpy="2.5.0"), "b")  # ... or of another environment
    (bad / "c").mkdir()
    (bad / "c" / "index.html").write_text("<html></html>")
    assert release_problems(bad, "9.9.9") == [
        f"a/index.html: states git commit {'1' * 40}, index.html states {'0' * 40} "
        "(one build makes a release)",
        "b/index.html: states numpy 2.5.0, index.html states 2.4.6 (one build makes a release)",
        "c/index.html: no provenance table",
    ]
    (tmp_path / "empty").mkdir()
    (no_index,) = release_problems(tmp_path / "empty", "9.9.9")
    assert no_index.endswith("no index.html, nothing states a provenance")
    with pytest.raises(AbglibValueError, match="must be a directory"):
        release_pages(tmp_path / "absent")


def test_release_refuses_a_build_of_another_version(tmp_path, capsys):
    """abglib release: the build's provenance version must be the release's (both named)."""
    build = tmp_path / "results" / "reports" / "v9.9.9"
    _index(build, _prov("9.9.8"))
    _report(build, _prov("9.9.8"), "doc")
    to = tmp_path / "reports" / "v9.9.9"
    assert main(["release", str(build), "--to", str(to)]) == 2
    err = capsys.readouterr().err
    assert "index.html: states abglib version 9.9.8, the release is 9.9.9" in err
    assert "doc/index.html: states abglib 9.9.8, the release is 9.9.9" in err
    assert not to.exists()  # nothing copied
    assert main(["release", str(build), "--to", str(tmp_path / "reports" / "latest")]) == 2
    assert "must be named v<version>" in capsys.readouterr().err
    # the same build, rendered again with the release's version, is released
    _index(build, _prov("9.9.9"))
    _report(build, _prov("9.9.9"), "doc")
    assert main(["release", str(build), "--to", str(to)]) == 0
    assert stated(to / "doc" / "index.html")["abglib version"] == "9.9.9"
    with pytest.raises(AbglibValueError, match="named v<version>"):
        folder_version(tmp_path / "reports" / "latest")
    assert folder_version(to) == "9.9.9"


@pytest.mark.parametrize("folder", _version_folders(), ids=lambda p: p.name)
def test_a_release_folder_states_its_own_version(folder):
    """Every committed release from the first readable page format on states the provenance
    of one build of its own version (CONTRACTS.md §4); the known wrong ones state exactly what
    KNOWN_WRONG records, so that the exception cannot hide another fault."""
    version = folder_version(folder)
    if version_key(folder.name) < FIRST_READABLE:
        # frozen history in the older page format: no <h2 id="provenance"> to read
        assert all(stated(p) == {} for p in release_pages(folder)), folder
        return
    problems = release_problems(folder, version)
    if folder.name not in KNOWN_WRONG:
        assert problems == [], "\n".join(problems)
        return
    expected = [
        f"{page.relative_to(folder).as_posix()}: states {item} {value}, the release is {version}"
        for page in release_pages(folder)
        for item, value in KNOWN_WRONG[folder.name].items()
    ]
    assert problems == expected


def test_known_wrong_provenance_is_frozen_history():
    """Exceptions are only for releases cut before v0.4.0 (this issue's fix); every later
    release must state its own provenance. The current version's release is checked above
    once it is committed."""
    folders = {p.name for p in _version_folders()}
    assert set(KNOWN_WRONG) <= folders
    assert all(version_key(name) < (0, 4, 0) for name in KNOWN_WRONG)
