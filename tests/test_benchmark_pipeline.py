"""Adding a tracker variant is one config entry, of a built-in rule or of a user's own
tracker in a file of their own: Snakemake schedules exactly its new cells (plus the
aggregations that read them), and the league table includes it after a run."""

import subprocess
import sys
from pathlib import Path
from types import SimpleNamespace

import pandas as pd
import pytest
import yaml

from .conftest import SMALL_BUILD, copy_build

pytestmark = pytest.mark.pipeline

REPO = Path(__file__).resolve().parents[1]
SMALL = REPO / "tests" / "data" / "config_small.yaml"
SNAKEMAKE = Path(sys.executable).parent / "snakemake"
LEAGUE = "results/benchmark/league.csv"
TRADEOFF = "results/benchmark/tradeoff.csv"


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


#: A user's own trackers, in a file of their own outside the repository
#: (abglib.bench.variants, "A user's own tracker").
USER_TRACKERS = '''
import numpy as np
from abglib import Gains


def my_gains(dt, n_samples, alpha):
    """A fixed-gain alpha-beta tracker of the user's own design."""
    return Gains(alpha, alpha**2 / (2.0 - alpha))


def my_tracker(dt, n_samples, window):
    """A moving average of the last ``window`` measurements (no velocity estimate)."""

    def run(z):
        c = np.cumsum(np.pad(z, ((0, 0), (window, 0))), axis=1)
        x = (c[:, window:] - c[:, :-window]) / window
        return {"x_smooth": x, "x_pred": np.concatenate([z[:, :1], x[:, :-1]], axis=1)}

    return run
'''
#: The variants the tests add: one config entry of a built-in rule, two of the user's file.
NEW_VARIANTS = ("extra_bb", "mine_ab", "mine_ma")


@pytest.fixture(scope="module")
def extended(tmp_path_factory, small_build):
    """The session's small build, copied and extended by three variants (one config entry
    of a built-in rule, and the user's two trackers of :data:`USER_TRACKERS`): the dry run
    of its league before, and the league and trade-off built after. One build serves both
    stories below (each one of its own cost a build and a dry run, ~10 CPU-s)."""
    root = tmp_path_factory.mktemp("extended")
    work = copy_build(small_build, root / "build")
    assert (work / LEAGUE).is_file()
    code = root / "elsewhere" / "my_trackers.py"
    code.parent.mkdir()
    code.write_text(USER_TRACKERS, encoding="utf-8")
    extra = root / "extra.yaml"
    extra.write_text(
        "benchmark:\n  variants:\n"
        "    extra_bb: {rule: benedict_bordner, alpha: 0.4}\n"
        f"    mine_ab: {{callable: '{code}:my_gains', alpha: 0.4}}\n"
        f"    mine_ma: {{callable: '{code}:my_tracker', window: 4, family: moving average}}\n",
        encoding="utf-8",
    )
    # nothing of the copy reruns: only the new cells and what reads them (the original's
    # no-op rerun: tests/test_pipeline.py::test_second_run_schedules_nothing)
    dry = _snakemake(work, str(SMALL), str(extra), "-n", LEAGUE)
    assert dry.returncode == 0, dry.stdout[-3000:] + dry.stderr[-3000:]
    run = _snakemake(work, str(SMALL), str(extra), "-c2", LEAGUE, TRADEOFF)
    assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-3000:]
    return SimpleNamespace(work=work, code=code, extra=extra, dry=dry.stdout)


@pytest.mark.xdist_group(SMALL_BUILD)
def test_new_variant_schedules_only_its_cells(extended):
    jobs = _scheduled(extended.dry)
    assert set(jobs) == {"benchmark_cell", "benchmark_league"}, jobs
    small = yaml.safe_load(SMALL.read_text(encoding="utf-8"))
    scenarios = small["benchmark"]["scenarios"]
    assert sorted(jobs["benchmark_cell"]) == sorted(
        f"results/benchmark/cells/{v}/{s}.csv" for v in NEW_VARIANTS for s in scenarios
    )
    league = pd.read_csv(extended.work / LEAGUE)
    assert set(league["variant"]) == {"std_ab_a0.3", "kalata_ab_L1", *NEW_VARIANTS}
    assert (league.groupby("scenario")["rank"].max() == 5).all()
    bb = league[league["variant"] == "extra_bb"].iloc[0]
    assert bb["rule"] == "benedict_bordner" and bb["alpha"] == 0.4


@pytest.mark.xdist_group(SMALL_BUILD)
def test_a_users_own_tracker_runs_in_the_matrix(extended):
    work, code = extended.work, extended.code
    table = pd.read_csv(work / LEAGUE)
    mine = table[table["variant"] == "mine_ab"].iloc[0]
    assert mine["family"] == "user: my_gains" and mine["alpha"] == 0.4
    # fixed gains are VRF-checked (60 samples are too few here); the user's tracker is not
    assert mine["vrf_check"] in ("pass", "n/a (too few samples)")
    assert set(table[table["variant"] == "mine_ma"]["vrf_check"]) == {"n/a (not fixed-gain)"}
    ma = table[table["variant"] == "mine_ma"]
    assert (ma["family"] == "moving average").all() and ma["rmse_x_smooth"].notna().all()
    variants = pd.read_csv(work / "results/benchmark/variants.csv")
    assert variants.set_index("variant").loc["mine_ab", "source"] == f"{code}:my_gains"
    assert (work / TRADEOFF).is_file()
    # editing the user's file reruns its cells (and only them); a docstring does not
    try:
        code.write_text(USER_TRACKERS.replace("A moving average", "A running mean"), "utf-8")
        dry = _snakemake(work, str(SMALL), str(extended.extra), "-n", LEAGUE)
        assert _scheduled(dry.stdout) == {}, dry.stdout[-2000:]
        code.write_text(USER_TRACKERS.replace("2.0 - alpha", "2 - alpha"), encoding="utf-8")
        dry = _snakemake(work, str(SMALL), str(extended.extra), "-n", LEAGUE)
        jobs = _scheduled(dry.stdout)
        assert set(jobs) == {"benchmark_cell", "benchmark_league"}, dry.stdout[-2000:]
        assert len(jobs["benchmark_cell"]) == 4, jobs
        assert all("/mine_" in c for c in jobs["benchmark_cell"]), jobs
    finally:  # the module's build stays as built for the test above
        code.write_text(USER_TRACKERS, encoding="utf-8")


@pytest.mark.xdist_group(SMALL_BUILD)
def test_every_bad_variant_is_named_at_parse_time(extended):
    """A misspelt parameter of a built-in rule, a gain out of range and a user's function
    that is not there: the dry run stops at parse time with one error naming the three
    variants, what is wrong with each and the allowed parameters, and the good variants say
    nothing."""
    bad = extended.work.parent / "bad.yaml"
    bad.write_text(
        "benchmark:\n  variants:\n"
        "    typo: {rule: benedict_bordner, alpah: 0.4}\n"
        "    fine: {rule: benedict_bordner, alpha: 0.4}\n"
        "    wild: {rule: benedict_bordner, alpha: 2.5}\n"
        f"    gone: {{callable: '{extended.code}:my_gainz', alpha: 0.4}}\n",
        encoding="utf-8",
    )
    out = _snakemake(extended.work, str(SMALL), str(bad), "-n", LEAGUE)
    assert out.returncode != 0, out.stdout[-2000:]
    said = out.stdout + out.stderr
    assert "variant 'typo'" in said and "allowed: alpha" in said, said[-2000:]
    assert "variant 'gone'" in said and "has no function 'my_gainz'" in said, said[-2000:]
    # a gain out of range fails alike on every scenario: the reason is said once
    assert "variant 'wild' is infeasible on every scenario (" in said, said[-2000:]
    assert said.count("alpha must satisfy 0 < alpha <= 1, got 2.5") == 1, said[-2000:]
    assert "variant 'fine'" not in said


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
