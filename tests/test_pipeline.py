"""The real pipeline end to end on a small config (tests/data/config_small.yaml).

Runs ``snakemake -s <repo>/Snakefile -d <tmp> --configfile config_small.yaml -c2`` twice in
two clean working directories: the outputs exist, the comparison table has the contract's
columns, the scorecard adds up, the two runs give byte-identical CSV tables, and a second
invocation in the same directory schedules nothing.
"""

import os
import re
import subprocess
import sys
from pathlib import Path

import pandas as pd
import pytest

import abglib
from abglib._perturb import ENV as PERTURB
from abglib.replications.compare import COMPARISON_COLUMNS, SCORECARD_COLUMNS, VERDICTS
from abglib.reporting import precision

from .conftest import require

pytestmark = pytest.mark.pipeline

REPO = Path(__file__).resolve().parents[1]
SMALL = REPO / "tests" / "data" / "config_small.yaml"
SNAKEMAKE = Path(sys.executable).parent / "snakemake"
# a build writes its reports here; reports/v<version> (the release) only `abglib release` writes
REPORTS = Path("results") / "reports" / f"v{abglib.__version__}"
OLD_REPORT = "<html>an older version's report</html>"


def _snakemake(workdir: Path, *args: str, env=None) -> subprocess.CompletedProcess:
    exe = str(SNAKEMAKE) if SNAKEMAKE.exists() else "snakemake"
    cmd = [
        exe,
        "-s",
        str(REPO / "Snakefile"),
        "-d",
        str(workdir),
        "--configfile",
        str(SMALL),
        *args,
    ]
    return subprocess.run(cmd, capture_output=True, text=True, timeout=600, env=env)


# what the second build makes: every document's tables and the benchmark matrix's, without
# figures and reports (they show nothing the tables do not hold)
TABLE_TARGETS = list(precision.TABLE_TARGETS)


@pytest.fixture(scope="module")
def two_runs(tmp_path_factory):
    """Run 1: the whole small build. Run 2: its tables again, with perturbed arithmetic
    (``ABGLIB_PERTURB``, abglib._perturb): every float input of the numerical core moved by
    up to 7 ulps, what another CPU, BLAS kernel or dependency set moves one operation by."""
    dirs = []
    envs = {"run1": None, "run2": dict(os.environ, **{PERTURB: "1"})}
    targets = {"run1": [], "run2": TABLE_TARGETS}
    # run 2 logs the scheduler's rounds (--verbose: "Ready jobs: N" once a round)
    flags = {"run1": [], "run2": ["--verbose"]}
    for name in ("run1", "run2"):
        d = tmp_path_factory.mktemp(name)
        # an older version's report, which building this version must not touch
        old = d / "reports" / "v0.0.0" / "steelman1978" / "index.html"
        old.parent.mkdir(parents=True)
        old.write_text(OLD_REPORT, encoding="utf-8")
        out = _snakemake(
            d,
            "-c2",
            *flags[name],
            *(["--", *targets[name]] if targets[name] else []),
            env=envs[name],
        )
        assert out.returncode == 0, out.stdout[-3000:] + out.stderr[-3000:]
        (d / "snakemake.out").write_text(out.stdout + out.stderr, encoding="utf-8")
        dirs.append(d)
    return dirs


def test_outputs_exist(two_runs):
    d = two_runs[0]
    for rel in [
        "results/scorecard.csv",
        "results/steelman1978/comparison.csv",
        REPORTS / "index.html",
        REPORTS / "scorecard.csv",
        REPORTS / "steelman1978" / "index.html",
        REPORTS / "steelman1978" / "tables" / "comparison.csv",
        *(REPORTS / "steelman1978" / "figures" / f"fig{i}.png" for i in range(1, 7)),
    ]:
        assert (d / rel).is_file(), rel
    assert (d / "logs").is_dir()


def test_older_version_untouched_and_no_release_written(two_runs):
    old = two_runs[0] / "reports" / "v0.0.0"
    assert sorted(p.name for p in old.rglob("*") if p.is_file()) == ["index.html"]
    # a build never writes a release folder: only `abglib release` does
    assert sorted(p.name for p in (two_runs[0] / "reports").iterdir()) == ["v0.0.0"]
    assert (old / "steelman1978" / "index.html").read_text(encoding="utf-8") == OLD_REPORT


def test_comparison_contract_and_scorecard(two_runs):
    d = two_runs[0]
    comp = pd.read_csv(d / "results/steelman1978/comparison.csv", dtype=str, keep_default_na=False)
    assert list(comp.columns) == COMPARISON_COLUMNS
    assert set(comp["verdict"]) <= set(VERDICTS)
    assert (comp.loc[comp["verdict"] != "match", "note"].str.len() > 0).all()
    card = pd.read_csv(d / "results/scorecard.csv")
    assert list(card.columns) == SCORECARD_COLUMNS
    row = card.set_index("doc").loc["steelman1978"]
    assert sum(int(row[v]) for v in VERDICTS) == int(row["total"]) == len(comp)


def test_report_is_self_contained_and_relocatable(two_runs):
    """Every file a page links exists in the version folder (CONTRACTS.md §4), images are
    linked rather than embedded, and nothing is loaded from the network."""
    page = two_runs[0] / REPORTS / "steelman1978" / "index.html"
    html = page.read_text(encoding="utf-8")
    links = set(re.findall(r'(?:src|href)="([^"#]+)"', html))
    assert any(link.startswith("figures/") for link in links)
    assert {"../assets/report.css", "../assets/report.js", "../index.html"} <= links
    missing = [link for link in links if not (page.parent / link).is_file()]
    assert missing == []
    assert "data:image/png;base64," not in html and "http" not in html
    assert str(two_runs[0]) not in html and str(REPO) not in html
    assert "config sha256" in html


def test_abglib_verify_finds_the_two_builds_identical(two_runs):
    """Run 2 (perturbed arithmetic) against run 1: every table within its written precision
    (derived by ``abglib precision``), every verdict identical (`abglib verify --partial`:
    run 2 has no reports)."""
    a, b = two_runs
    exe = Path(sys.executable).parent / "abglib"
    cmd = [str(exe) if exe.exists() else "abglib", "verify", str(b / "results"), "--partial"]
    out = subprocess.run(
        [*cmd, "--release", str(a / "results")], capture_output=True, text=True, timeout=300
    )
    assert out.returncode == 0, out.stdout[-3000:] + out.stderr[-2000:]
    assert "verdicts identical" in out.stdout
    for doc in ("steelman1978", "huang", "alwagih", "faa_bendix", "antenna", "benchmark"):
        assert f"\n{doc}: " in out.stdout, doc


def test_scheduler_runs_a_round_when_a_job_ends(two_runs):
    # Snakemake's rate limit would add a chain of rounds, one a second, per ended job (a
    # round per job end and a timer's round per round: 179 rounds for 24 jobs of run 2);
    # the workflow switches it off for a local build (common.smk, without_rate_limit)
    log = (two_runs[1] / "snakemake.out").read_text(encoding="utf-8")
    rounds = len(re.findall(r"^Ready jobs", log, flags=re.M))
    jobs = len(re.findall(r"^Finished jobid", log, flags=re.M))
    assert jobs > 5, log[-2000:]
    # at least a round for every other job end: fewer means the log no longer says
    # "Ready jobs" once a round and this test would pass on anything
    assert max(1, jobs // 2) <= rounds <= 2 * jobs + 2, (rounds, jobs)


def test_second_run_schedules_nothing(two_runs):
    out = _snakemake(two_runs[0], "-n")
    assert out.returncode == 0
    assert "Nothing to be done" in out.stdout + out.stderr


def test_huang_outputs(two_runs):
    d = two_runs[0]
    for rel in [
        "results/huang/comparison.csv",
        REPORTS / "huang" / "index.html",
        REPORTS / "huang" / "tables" / "comparison.csv",
        *(REPORTS / "huang" / "figures" / f"fig{i}.png" for i in range(2, 8)),
    ]:
        assert (d / rel).is_file(), rel
    comp = pd.read_csv(d / "results/huang/comparison.csv", dtype=str, keep_default_na=False)
    published = sum(
        len(pd.read_csv(p, comment="#")) for p in (REPO / "data/published/huang").glob("*.csv")
    )
    assert len(comp) == published
    assert (comp.loc[comp["verdict"] != "match", "note"].str.len() > 0).all()


def test_datasets_and_alwagih_outputs(two_runs):
    a, b = two_runs
    names = [f"alwagih_{k}{i}" for k in "wc" for i in range(1, 6)]
    for name in names:
        for suffix in (".parquet", ".manifest.json"):
            rel = Path("results/datasets") / f"{name}{suffix}"
            assert (a / rel).is_file(), rel
            # datasets are rebuilt byte for byte
            assert (a / rel).read_bytes() == (b / rel).read_bytes(), rel
    comp = pd.read_csv(a / "results/alwagih/comparison.csv", dtype=str, keep_default_na=False)
    assert list(comp.columns) == COMPARISON_COLUMNS
    assert set(comp["verdict"]) <= set(VERDICTS)
    # every printed number of Tables 1-6 and every claim has a row
    published = sum(
        len(pd.read_csv(p, comment="#")) for p in (REPO / "data/published/alwagih").glob("*.csv")
    )
    assert len(comp) == published
    assert (comp.loc[comp["depends_on"] != "", "robust"] != "").all()
    assert (a / REPORTS / "alwagih" / "index.html").is_file()


def test_every_comparison_says_what_it_hinges_on(two_runs):
    """CONTRACTS.md §3 (v0.3.0): a row that hinges on an input names it in depends_on, and
    every row with depends_on says whether its verdict is robust."""
    for doc in ("steelman1978", "alwagih", "huang", "faa_bendix", "antenna"):
        comp = pd.read_csv(
            two_runs[0] / "results" / doc / "comparison.csv", dtype=str, keep_default_na=False
        )
        assert list(comp.columns) == COMPARISON_COLUMNS, doc
        assert not comp.loc[comp["note"].str.contains("hinges on"), "depends_on"].eq("").any(), doc
        robust = comp.loc[comp["depends_on"] != "", "robust"]
        assert set(robust) <= {"true", "false"}, doc
        flipped = comp[comp["robust"] == "false"]
        assert (flipped["verdict"] == "not_reproducible").all(), doc


def test_built_reports_in_a_browser(two_runs, tmp_path):
    """The small build's pages (not only the committed release) pass the offline browser
    checks of tests/test_browser.py: no request, no console error, no raw TeX, no NaN,
    no broken image, no horizontal overflow."""
    from ._browser import check_folder, find_chromium

    if find_chromium() is None:
        require("no Chromium on PATH (apt-get install chromium; .ci/run installs it)")
    checks = check_folder(two_runs[0] / REPORTS, tmp_path)
    assert len(checks) >= 3
    bad = {c.url: c.problems for c in checks if c.problems}
    assert not bad, bad
