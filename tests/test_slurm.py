"""The pipeline on a real SLURM cluster through the shipped profile (profiles/slurm).

Runs the README's cluster command,

    snakemake --profile profiles/slurm

from the repository's root with the small config, in a scratch working directory and for
a subset of targets, and the same targets locally with ``snakemake -c2``. Checks that every
Snakemake job of the cluster run was submitted with sbatch and accounted by SLURM as
COMPLETED under the profile's account and partition (one accounted SLURM job per Snakemake
job, nothing else submitted under the run's job name), and that the two runs wrote
byte-identical tables and datasets.

The subset keeps the test's cost near a minute and a half on a 2-core node: every SLURM job
pays about 10 s of Snakemake start-up twice (the plugin's job step, then the job under
srun), so the 48 jobs of the whole small build would take over 5 minutes on two cores.
It is one document's comparison (FAA Bendix, its tables and verdicts) and the benchmark
league table, which needs the matrix's 4 cells, which need their 2 datasets: 8 jobs on
three levels of dependencies.

Marker ``slurm``, deselected by default; ``.ci/run`` starts a one-node cluster
(tools/slurm-cluster.sh) and runs ``pytest -m slurm``. Without a cluster it is skipped
(it fails instead when ABGLIB_REQUIRE_SLURM=1, as .ci/run sets).
Account and partition come from SBATCH_ACCOUNT and SBATCH_PARTITION, as in the README;
unset, they are the loopback cluster's ``ci`` and ``debug``.
"""

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

pytestmark = pytest.mark.slurm

REPO = Path(__file__).resolve().parents[1]
SMALL = REPO / "tests" / "data" / "config_small.yaml"
BIN = Path(sys.executable).parent
TARGETS = ["results/faa_bendix/comparison.csv", "results/benchmark/league.csv"]
# the cluster run must end well inside CI's budget for this test (4 min)
TIMEOUT_S = 420


def _exe(name: str) -> str:
    return str(BIN / name) if (BIN / name).exists() else name


def _no_cluster(reason: str) -> None:
    """Skip; with ABGLIB_REQUIRE_SLURM=1 (.ci/run, which has started a cluster) fail."""
    if os.environ.get("ABGLIB_REQUIRE_SLURM") == "1":
        pytest.fail(f"ABGLIB_REQUIRE_SLURM=1 but {reason}")
    pytest.skip(reason)


def _cluster_or_skip() -> None:
    """Skip unless sinfo shows a partition up and sacct answers (the plugin polls sacct)."""
    try:
        import snakemake_executor_plugin_slurm  # noqa: F401
    except ImportError:
        _no_cluster("snakemake-executor-plugin-slurm is not installed: pip install -e '.[slurm]'")
    answers = {}
    for cmd in (["sinfo", "-h", "-o", "%a"], ["sacct", "-n", "-X", "-S", "now"]):
        if shutil.which(cmd[0]) is None:
            _no_cluster(f"no SLURM client ({cmd[0]} not found): sudo tools/slurm-cluster.sh start")
        out = subprocess.run(cmd, capture_output=True, text=True, timeout=60)
        if out.returncode != 0:
            _no_cluster(
                f"no SLURM cluster answers ({' '.join(cmd)}: {out.stderr.strip()[:200]}); "
                "start one with `sudo tools/slurm-cluster.sh start`"
            )
        answers[cmd[0]] = out.stdout.split()
    if "up" not in answers["sinfo"]:
        _no_cluster("the SLURM cluster has no partition up")


def _snakemake(workdir: Path, *args: str, env=None) -> subprocess.CompletedProcess:
    cmd = [
        "timeout", "-k", "30", str(TIMEOUT_S),
        _exe("snakemake"), *args,
        "--configfile", str(SMALL), "-d", str(workdir), *TARGETS,
    ]  # fmt: skip
    out = subprocess.run(cmd, cwd=REPO, capture_output=True, text=True, env=env)
    # snakemake waits for running jobs on SIGTERM; timeout's SIGKILL ends it (rc 124/137)
    assert out.returncode not in (124, 137), f"timed out after {TIMEOUT_S} s:\n" + (
        out.stdout[-3000:] + out.stderr[-3000:]
    )
    assert out.returncode == 0, out.stdout[-3000:] + out.stderr[-3000:]
    return out


def _sacct(*args: str) -> list[list[str]]:
    out = subprocess.run(
        ["sacct", "-n", "-X", "-P", *args], capture_output=True, text=True, timeout=60, check=True
    )
    return [line.split("|") for line in out.stdout.splitlines() if line]


def test_pipeline_on_slurm_equals_local_run(tmp_path):
    _cluster_or_skip()
    account = os.environ.get("SBATCH_ACCOUNT", "ci")
    partition = os.environ.get("SBATCH_PARTITION", "debug")
    env = dict(os.environ, SBATCH_ACCOUNT=account, SBATCH_PARTITION=partition)

    local, cluster = tmp_path / "local", tmp_path / "slurm"
    _snakemake(local, "-c2")
    # the README's command
    run = _snakemake(cluster, "--profile", "profiles/slurm", env=env)
    log = run.stdout + run.stderr

    # every job of the run was submitted to SLURM; none ran on the submitting machine
    jobs = re.findall(r"^(local)?rule (\w+):$", log, flags=re.M)
    total = int(re.search(r"^total\s+(\d+)$", log, flags=re.M).group(1))
    local_jobs = [name for is_local, name in jobs if is_local]
    assert local_jobs == [], f"jobs that did not go through sbatch: {local_jobs}"
    submitted = re.findall(r"has been submitted with SLURM jobid (\d+)", log)
    assert total >= 8 and len(jobs) == total, (total, jobs)
    assert len(submitted) == len(set(submitted)) == total, (total, submitted)

    # ... and SLURM accounted each of them, finished, with the profile's account and
    # partition; the plugin names every job of a run after the run, and nothing else was
    # submitted under that name
    rows = _sacct("-j", ",".join(submitted), "-o", "JobID,JobName,State,Account,Partition")
    assert sorted(r[0] for r in rows) == sorted(submitted)
    assert {r[2] for r in rows} == {"COMPLETED"}, rows
    assert {(r[3], r[4]) for r in rows} == {(account, partition)}, rows
    (run_name,) = {r[1] for r in rows}
    named = _sacct("--name", run_name, "-S", "now-1days", "-o", "JobID")
    assert sorted(r[0] for r in named) == sorted(submitted)

    # the same tables and datasets as the local run, byte for byte
    files = sorted(
        p.relative_to(local)
        for p in (local / "results").rglob("*")
        if p.is_file() and p.suffix in (".csv", ".parquet", ".json")
    )
    assert Path("results/faa_bendix/comparison.csv") in files
    assert len([f for f in files if f.parts[2:3] == ("cells",)]) >= 4, files
    different = [
        str(f)
        for f in files
        if not (cluster / f).is_file() or (cluster / f).read_bytes() != (local / f).read_bytes()
    ]
    assert different == []
