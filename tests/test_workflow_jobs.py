"""The jobs a build schedules, against what the configuration asks for (issue 23, item 4).

The rules are generated (workflow/rules/documents.smk declares each document's rules in a
loop; scripts.smk defines every script rule from its declaration), so a future edit could
drop or duplicate a job without any rule file looking wrong. Here a dry run of a clean
build (``snakemake -n --forceall``) on the default and the tests' small config lists its
jobs, and they must be exactly the jobs derived independently from the config file: per
document of ``docs`` its study, claims, figures and report; per Steelman figure its
response table and plot; per dataset scenario one dataset; per variant and benchmark
scenario one cell; and the benchmark's, the index's and the scorecard's jobs once.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
from collections import Counter
from pathlib import Path

import pytest
import yaml

# Snakemake dry runs of both configs (about 5 CPU-s): not in the fast loop. One worker runs
# the module, so that each config's dry run is made once (a module fixture is made once
# per worker that needs it).
pytestmark = [pytest.mark.slow, pytest.mark.xdist_group("workflow_jobs")]

REPO = Path(__file__).resolve().parents[1]
SNAKEMAKE = Path(sys.executable).parent / "snakemake"
CONFIGS = {
    "default": REPO / "config.yaml",
    "small": REPO / "tests" / "data" / "config_small.yaml",
}
# rule names that are not <doc>_<part> (kept as they were: the SLURM profile and the
# tests name them)
REPORT_RULE = {"steelman1978": "steelman_report"}
# documents whose figures are drawn per figure (steelman_frequency_response and
# steelman_figure, wildcard fig) instead of by one <doc>_figures job
PER_FIGURE = {"steelman1978"}
#: What the workflow's parse must not import: the scientific stack beyond numpy and the
#: root finders of scipy.optimize (which a variant's design rule may need, to solve for
#: its gains: Huang's ENBW rule of the default config).
HEAVY = ("pandas", "matplotlib", "numba", "scipy.integrate", "scipy.signal", "scipy.stats")
BENCHMARK_JOBS = (
    "benchmark_league",
    "benchmark_tradeoff",
    "benchmark_figures",
    "benchmark_peers",
    "benchmark_speed",
    "benchmark_report",
)


def parse_jobs(stdout: str) -> list[dict]:
    """Every job of a dry run's listing: ``{"rule", "output": [...], "wildcards": {...}}``."""
    jobs, job = [], None
    for line in stdout.splitlines():
        head = re.fullmatch(r"(?:local)?rule (\S+):", line)
        if head:
            job = {"rule": head.group(1), "output": [], "wildcards": {}}
            jobs.append(job)
        elif job is not None and line.startswith("    "):
            key, _, value = line.strip().partition(": ")
            if key == "output":
                job["output"] = value.split(", ")
            elif key == "wildcards":
                job["wildcards"] = dict(w.split("=", 1) for w in value.split(", "))
        else:
            job = None
    return jobs


def expected_jobs(config: dict) -> Counter:
    """(rule, wildcards) of every job a clean build of ``config`` runs, from the config."""
    jobs = Counter()

    def add(rule, **wildcards):
        jobs[rule, tuple(sorted(wildcards.items()))] += 1

    for doc in config["docs"]:
        add(f"{doc}_study")
        add(f"{doc}_claims")
        add(REPORT_RULE.get(doc, f"{doc}_report"))
        if doc in PER_FIGURE:
            for fig in config[doc]["figures"]:
                add("steelman_frequency_response", fig=fig)
                add("steelman_figure", fig=fig)
        else:
            add(f"{doc}_figures")
    for scenario in config.get("datasets", {}).get("scenarios", {}):
        add("dataset", scenario=scenario)
    bench = config.get("benchmark")
    if bench:
        for variant in bench["variants"]:
            for scenario in bench["scenarios"]:
                add("benchmark_cell", variant=variant, scenario=scenario)
        for rule in BENCHMARK_JOBS:
            add(rule)
    for rule in ("scorecard", "report_assets", "report_index", "changes", "all"):
        add(rule)
    return jobs


#: What Python's ``-X importtime`` writes for each module: ``import time: self | cumulative
#: | name`` (the name indented by its depth).
IMPORT_TIME = re.compile(r"import time:\s+\d+ \|\s+\d+ \|\s*(\S+)\s*$")


@pytest.fixture(scope="module", params=sorted(CONFIGS))
def dry_run(request, tmp_path_factory):
    """(config, jobs, imported) of a clean build's dry run in an empty working directory:
    ``imported`` names every module that run imported (``PYTHONPROFILEIMPORTTIME``)."""
    name = request.param
    work = tmp_path_factory.mktemp(f"jobs-{name}")
    exe = str(SNAKEMAKE) if SNAKEMAKE.exists() else "snakemake"
    cmd = [exe, "-s", str(REPO / "Snakefile"), "-d", str(work), "--configfile", str(CONFIGS[name])]
    env = {**os.environ, "PYTHONPROFILEIMPORTTIME": "1"}
    out = subprocess.run(
        [*cmd, "-n", "--forceall"], capture_output=True, text=True, cwd=REPO, timeout=300, env=env
    )
    assert out.returncode == 0, out.stdout[-3000:] + out.stderr[-3000:]
    config = yaml.safe_load(CONFIGS[name].read_text(encoding="utf-8"))
    imported = {m.group(1) for m in map(IMPORT_TIME.match, out.stderr.splitlines()) if m}
    assert "snakemake" in imported, "no import was recorded: " + out.stderr[-1000:]
    return config, parse_jobs(out.stdout), imported


def test_a_new_working_directorys_parse_imports_no_numerics(dry_run):
    """Snakemake's parse of the workflow in a new working directory, the benchmark
    matrix's checks included (common.smk's ``_check_matrix``, which runs whenever the
    matrix or its code changed), imports none of the scientific stack beyond numpy
    (:data:`HEAVY`): the jobs import it in their workers. Counting the matrix's VRF checks
    through abglib.bench.benchmark once imported scipy and pandas here (the small
    config's dry run 2.3 → 1.3 CPU-s)."""
    _, _, imported = dry_run
    heavy = sorted(m for m in imported if m.startswith(HEAVY))
    assert not heavy, f"the parse imported {heavy[:8]}"


def test_the_dry_run_schedules_exactly_the_configured_jobs(dry_run):
    config, jobs, _ = dry_run
    listed = Counter((j["rule"], tuple(sorted(j["wildcards"].items()))) for j in jobs)
    expected = expected_jobs(config)
    assert listed == expected, (
        f"missing: {sorted((expected - listed).elements())[:10]}; "
        f"unexpected: {sorted((listed - expected).elements())[:10]}"
    )


def test_a_plain_build_writes_nothing_under_the_committed_releases(dry_run):
    """A plain build's every output lies outside the committed releases (``reports/``,
    written only by ``abglib release``); its reports go to ``results/reports/v<version>``."""
    _, jobs, _ = dry_run
    written = [f for j in jobs for f in j["output"]]
    assert written, "the dry run listed no outputs"
    assert not [f for f in written if f.startswith("reports/")], written[:5]
    assert any(f.startswith("results/reports/v") for f in written)


def test_each_job_writes_its_own_outputs_where_the_contracts_say(dry_run):
    import abglib

    config, jobs, _ = dry_run
    reports = f"results/reports/v{abglib.__version__}"
    outputs = [f for j in jobs for f in j["output"]]
    assert len(outputs) == len(set(outputs)), "an output is written by two jobs"
    by_rule: dict[str, list] = {}
    for j in jobs:
        by_rule.setdefault(j["rule"], []).append(j)
    for doc in config["docs"]:
        (study,) = by_rule[f"{doc}_study"]
        (claims,) = by_rule[f"{doc}_claims"]
        (report,) = by_rule[REPORT_RULE.get(doc, f"{doc}_report")]
        tables = {Path(f).stem for f in study["output"]}
        assert tables and all(f.startswith(f"results/{doc}/") for f in study["output"])
        assert sorted(claims["output"]) == [
            f"results/{doc}/comparison.csv",
            f"results/{doc}/robustness.csv",
        ]
        assert f"{reports}/{doc}/index.html" in report["output"]
        # the report copies only tables its document computed, and figures its figure
        # jobs drew
        copied = {Path(f).stem for f in report["output"] if "/tables/" in f}
        assert "comparison" in copied and copied <= tables | {"comparison", "robustness"}
        figure_jobs = by_rule["steelman_figure"] if doc in PER_FIGURE else by_rule[f"{doc}_figures"]
        drawn = {Path(f).stem for j in figure_jobs for f in j["output"]}
        shown = {Path(f).stem for f in report["output"] if "/figures/" in f}
        assert shown and shown <= drawn
    for j in by_rule.get("steelman_frequency_response", []):
        assert j["output"] == [f"results/steelman1978/freqresp/{j['wildcards']['fig']}.csv"]
    for j in by_rule.get("dataset", []):
        s = j["wildcards"]["scenario"]
        assert j["output"] == [
            f"results/datasets/{s}.parquet",
            f"results/datasets/{s}.manifest.json",
        ]
    for j in by_rule.get("benchmark_cell", []):
        w = j["wildcards"]
        assert j["output"] == [f"results/benchmark/cells/{w['variant']}/{w['scenario']}.csv"]
    (index,) = by_rule["report_index"]
    assert f"{reports}/index.html" in index["output"]


def test_every_documents_rules_exist_whatever_the_config_builds():
    """The five documents' rules are defined even when a config builds fewer of them (the
    SLURM profile and the tests name them)."""
    exe = str(SNAKEMAKE) if SNAKEMAKE.exists() else "snakemake"
    out = subprocess.run(
        [exe, "--list-rules"], capture_output=True, text=True, cwd=REPO, timeout=300
    )
    assert out.returncode == 0, out.stderr[-3000:]
    rules = set(out.stdout.split())
    from abglib.replications import DOCS

    for doc in DOCS:
        assert {f"{doc}_study", f"{doc}_claims", REPORT_RULE.get(doc, f"{doc}_report")} <= rules
    assert {"steelman_frequency_response", "steelman_figure", "tables", "datasets"} <= rules
    assert {f"{doc}_figures" for doc in DOCS if doc not in PER_FIGURE} <= rules
