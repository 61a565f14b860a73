"""Adding a tracker variant is one config entry: Snakemake schedules exactly its new cells
(plus the aggregations that read them), and the league table includes it after a run."""

import subprocess
import sys
from pathlib import Path

import pandas as pd
import pytest
import yaml

from .conftest import SMALL_BUILD, copy_build

pytestmark = pytest.mark.pipeline

REPO = Path(__file__).resolve().parents[1]
SMALL = REPO / "tests" / "data" / "config_small.yaml"
SNAKEMAKE = Path(sys.executable).parent / "snakemake"
LEAGUE = "results/benchmark/league.csv"


def _snakemake(workdir: Path, *args: str) -> subprocess.CompletedProcess:
    exe = str(SNAKEMAKE) if SNAKEMAKE.exists() else "snakemake"
    cmd = [exe, "-s", str(REPO / "Snakefile"), "-d", str(workdir), "--configfile", *args]
    return subprocess.run(cmd, capture_output=True, text=True, timeout=600)


def _scheduled(stdout: str) -> dict:
    """rule -> outputs of the jobs a dry run lists."""
    jobs, rule = {}, None
    for line in stdout.splitlines():
        s = line.strip()
        if s.startswith(("rule ", "localrule ")) and s.endswith(":"):
            rule = s.split()[1].rstrip(":")
            jobs.setdefault(rule, [])
        elif s.startswith("output:") and rule:
            jobs[rule] += [o.strip() for o in s[len("output:") :].split(",")]
    return jobs


@pytest.mark.xdist_group(SMALL_BUILD)
def test_new_variant_schedules_only_its_cells(tmp_path, small_build):
    # the session's small build (its league included), copied: the dry run below schedules
    # only the new cells and the league, so nothing of the copy reruns (the original's
    # no-op rerun: tests/test_pipeline.py::test_second_run_schedules_nothing)
    copy_build(small_build, tmp_path / "build")
    tmp_path = tmp_path / "build"
    assert (tmp_path / LEAGUE).is_file()
    small = yaml.safe_load(SMALL.read_text(encoding="utf-8"))
    scenarios = small["benchmark"]["scenarios"]
    extra = tmp_path / "extra.yaml"
    extra.write_text(
        "benchmark:\n  variants:\n    extra_bb: {rule: benedict_bordner, alpha: 0.4}\n",
        encoding="utf-8",
    )
    dry = _snakemake(tmp_path, str(SMALL), str(extra), "-n", LEAGUE)
    assert dry.returncode == 0, dry.stdout[-3000:] + dry.stderr[-3000:]
    jobs = _scheduled(dry.stdout)
    assert set(jobs) == {"benchmark_cell", "benchmark_league"}, jobs
    assert sorted(jobs["benchmark_cell"]) == sorted(
        f"results/benchmark/cells/extra_bb/{s}.csv" for s in scenarios
    )
    run = _snakemake(tmp_path, str(SMALL), str(extra), "-c2", LEAGUE)
    assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-3000:]
    league = pd.read_csv(tmp_path / LEAGUE)
    assert set(league["variant"]) == {"std_ab_a0.3", "kalata_ab_L1", "extra_bb"}
    assert (league.groupby("scenario")["rank"].max() == 3).all()
    # a bad entry fails at parse time, naming the variant and the allowed parameters
    extra.write_text(
        "benchmark:\n  variants:\n    typo: {rule: benedict_bordner, alpah: 0.4}\n",
        encoding="utf-8",
    )
    bad = _snakemake(tmp_path, str(SMALL), str(extra), "-n", LEAGUE)
    assert bad.returncode != 0
    assert "variant 'typo'" in bad.stderr + bad.stdout
    assert "allowed: alpha" in bad.stderr + bad.stdout


def test_regenerated_cell_datasets_are_shared_read_only_and_every_variant_runs_on_them():
    from abglib.bench import benchmark as bm

    cfg = yaml.safe_load((REPO / "config.yaml").read_text())
    large = yaml.safe_load((REPO / "config" / "benchmark_large.yaml").read_text())
    spec = cfg["datasets"]["scenarios"]["alwagih_w1"]
    a = bm.cell_dataset(None, "alwagih_w1", spec, runs=20, seed=3)
    assert bm.cell_dataset(None, "alwagih_w1", spec, runs=20, seed=3) is a
    assert bm.cell_dataset(None, "alwagih_w1", spec, runs=21, seed=3) is not a
    assert not a.z[a.coords[0]].flags.writeable
    variants = {**cfg["benchmark"]["variants"], **large["benchmark"]["variants"]}
    for name, v in variants.items():
        bm.run_cell(a, v, name)  # a write into the shared dataset would raise here
