"""abglib verify and abglib release (abglib.reporting.verify, abglib.reporting.cli)."""

from __future__ import annotations

import math

import pytest

from abglib.reporting.cli import main
from abglib.reporting.verify import cell_agrees, compare_folders

COMP = "doc,item,reproduced,verdict,note\nd,a,0.1235,match,\nd,b,12.5,mismatch,off by 2\n"


@pytest.mark.parametrize(
    "release, build, agrees",
    [
        ("0.1235", "0.1235", True),
        ("0.1235", "0.1234", True),  # one unit in the last written digit: a rounding flip
        ("0.1235", "0.1233", False),
        ("1.20", "1.2", True),  # the same value
        ("1.2", "1.199999999", True),  # %g drops trailing zeros: a flip at the 10th digit
        ("2", "2.9", False),  # "2" is 2.000000000 at 10 digits, not 2 +- 1
        ("0", "0.5", False),
        ("0.5", "0.59", False),
        ("1e-05", "1.9e-05", False),
        ("12", "13", False),  # integers (counts) must be equal
        ("<1e-12", "<1e-12", True),
        ("<1e-12", "3e-13", True),  # a bound holds a smaller number
        ("<1e-12", "2e-12", False),
        ("match", "mismatch", False),
        ("", "", True),
        ("", "0", False),
    ],
)
def test_cell_agreement_is_within_the_written_precision(release, build, agrees):
    assert cell_agrees(release, build)[0] is agrees


def test_relative_deviation_of_numbers():
    ok, dev = cell_agrees("2.000000001", "2.000000002")
    assert ok and dev == pytest.approx(5e-10)
    assert math.isnan(cell_agrees("0", "1e-9")[1])  # no relative deviation from 0
    assert math.isnan(cell_agrees("a", "b")[1])


def _folder(root, comp=COMP, extra=None):
    (root / "doc").mkdir(parents=True)
    (root / "index.html").write_text("<html></html>")
    (root / "scorecard.csv").write_text("doc,match,total\ndoc,1,2\n")
    (root / "doc" / "comparison.csv").write_text(comp)
    if extra:
        (root / "doc" / "extra.csv").write_text(extra)
    return root


def test_identical_folders_pass(tmp_path, capsys):
    rel, build = _folder(tmp_path / "rel"), _folder(tmp_path / "build")
    reports = {r.doc: r for r in compare_folders(rel, build)}
    assert reports["doc"].ok and reports["doc"].verdicts_same == reports["doc"].verdicts == 2
    assert main(["verify", str(build), "--release", str(rel)]) == 0
    out = capsys.readouterr().out
    assert "doc: 1 tables, 2 rows compared, verdicts identical 2/2" in out


def test_a_changed_verdict_and_a_moved_number_fail(tmp_path, capsys):
    rel = _folder(tmp_path / "rel")
    changed = COMP.replace("12.5,mismatch", "12.9,match")
    build = _folder(tmp_path / "build", comp=changed)
    rep = {r.doc: r for r in compare_folders(rel, build)}["doc"]
    assert rep.verdicts_same == 1
    assert {d.column for d in rep.differences} == {"reproduced", "verdict"}
    assert rep.largest == pytest.approx(0.4 / 12.5)
    assert "doc/comparison.csv, row 2" in rep.largest_at
    assert main(["verify", str(build), "--release", str(rel)]) == 1
    assert "row 2, column verdict: release 'mismatch', build 'match'" in capsys.readouterr().out


def test_missing_and_extra_tables_fail(tmp_path):
    rel = _folder(tmp_path / "rel", extra="a\n1\n")
    build = _folder(tmp_path / "build")
    (build / "doc" / "new.csv").write_text("a\n1\n")
    rep = {r.doc: r for r in compare_folders(rel, build)}["doc"]
    assert any("extra.csv: missing from the build" in p for p in rep.problems)
    assert any("new.csv: in the build, not in the release" in p for p in rep.problems)


def test_verify_without_a_build_says_what_to_run(tmp_path, capsys):
    rel = _folder(tmp_path / "rel")
    assert main(["verify", str(tmp_path / "nothing"), "--release", str(rel)]) == 2
    assert "run `snakemake -c2` first" in capsys.readouterr().err


def test_release_copies_and_refuses_to_overwrite(tmp_path, capsys):
    build = _folder(tmp_path / "build")
    # the build states the release's version (abglib release checks it: test_provenance.py)
    rows = "<tr><td>abglib version</td><td>9.9.9</td></tr><tr><td>abglib</td><td>9.9.9</td></tr>"
    (build / "index.html").write_text(f'<h2 id="provenance">Provenance</h2><table>{rows}</table>')
    to = tmp_path / "reports" / "v9.9.9"
    assert main(["release", str(build), "--to", str(to)]) == 0
    assert (to / "doc" / "comparison.csv").read_text() == COMP
    (build / "doc" / "comparison.csv").write_text(COMP.replace("0.1235", "0.2"))
    assert main(["release", str(build), "--to", str(to)]) == 2
    assert "add --force" in capsys.readouterr().err
    assert (to / "doc" / "comparison.csv").read_text() == COMP  # untouched
    assert main(["release", str(build), "--to", str(to), "--force"]) == 0
    assert "0.2" in (to / "doc" / "comparison.csv").read_text()


def test_partial_compares_only_the_builds_tables(tmp_path, capsys):
    rel = _folder(tmp_path / "rel", extra="a\n1\n")
    build = tmp_path / "build"
    (build / "doc").mkdir(parents=True)
    (build / "doc" / "comparison.csv").write_text(COMP)  # no index.html, no extra.csv
    assert main(["verify", str(build), "--release", str(rel)]) == 2
    assert main(["verify", str(build), "--release", str(rel), "--partial"]) == 0
    assert "doc: 1 tables, 2 rows compared" in capsys.readouterr().out
    (build / "doc" / "comparison.csv").write_text(COMP.replace("mismatch", "match"))
    assert main(["verify", str(build), "--release", str(rel), "--partial"]) == 1


def test_partial_verify_of_a_folder_without_tables_fails(tmp_path, capsys):
    rel = _folder(tmp_path / "rel")
    (tmp_path / "empty").mkdir()
    assert main(["verify", str(tmp_path / "empty"), "--release", str(rel), "--partial"]) == 1
    assert "no table of" in capsys.readouterr().err


def test_the_report_counts_what_it_leaves_out(tmp_path):
    from abglib.reporting.verify import Difference, DocReport, format_report

    rep = DocReport("doc", differences=[Difference("t", i, "c", "1", "2") for i in range(7)])
    assert "... and 2 more" in format_report([rep], limit=5)


@pytest.mark.parametrize(
    "argv, named",
    [
        (["verify", "--limit", "-3"], "argument --limit: must be an integer >= 0, got -3"),
        (["verify", "--limit", "two"], "argument --limit: must be an integer >= 0, got 'two'"),
        (["precision", "--runs", "1"], "argument --runs: must be an integer >= 2, got 1"),
        (["precision", "--cores", "0"], "argument --cores: must be an integer >= 1, got 0"),
    ],
)
def test_an_out_of_range_count_is_refused_before_anything_runs(argv, named, capsys):
    """A negative ``--limit`` printed "... and 6 more" under identical documents; ``--runs
    1`` reached the derivation and ended in a traceback. argparse refuses both, by name."""
    with pytest.raises(SystemExit) as exc:
        main(argv)
    assert exc.value.code == 2
    err = capsys.readouterr().err
    assert named in err and "Traceback" not in err


def test_help_names_every_command_in_plain_text(capsys):
    with pytest.raises(SystemExit) as exc:
        main(["--help"])
    assert exc.value.code == 0
    out = capsys.readouterr().out
    for command in ("verify", "release", "changes", "precision", "findings"):
        assert command in out
    assert "``" not in out  # no reStructuredText markup


def test_version_is_the_package_version(capsys):
    """``abglib --version``: the version a build writes its reports under (reports/v<it>)."""
    import abglib

    with pytest.raises(SystemExit) as exc:
        main(["--version"])
    assert exc.value.code == 0
    assert capsys.readouterr().out.strip() == f"abglib {abglib.__version__}"
