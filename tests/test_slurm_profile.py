"""The SLURM profile's own commands, without a cluster (profiles/slurm): its sbatch
wrapper (sbatch-submit.py) against a stand-in ``sbatch`` that records what it is given,
and its status command against a stand-in ``sacct`` printing each state.
tests/test_slurm.py runs them on a real cluster."""

import json
import os
import subprocess
from pathlib import Path

import pytest
import yaml

REPO = Path(__file__).resolve().parents[1]
PROFILE = REPO / "profiles" / "slurm"
SUBMIT = PROFILE / "sbatch-submit.py"

# a job script as Snakemake's generic cluster executor writes it (its default template)
JOBSCRIPT = """#!/bin/sh
# properties = {props}
cd /work && /venv/bin/python3 -m snakemake --snakefile /repo/Snakefile --target-jobs \
'dataset:scenario=a' --cores 1 --mode 'remote' && exit 0 || exit 1
"""
GROUP = {
    "type": "group",
    "groupid": "cells",
    "threads": 1,
    "resources": {"mem_mb": 2000, "runtime": 20, "tmpdir": "<TBD>"},
    "jobid": "d2b9",
}


def _stand_in(bindir: Path, name: str, body: str) -> None:
    path = bindir / name
    path.write_text("#!/bin/sh\n" + body, encoding="utf-8")
    path.chmod(0o755)


@pytest.fixture
def cluster(tmp_path):
    """A working directory and a PATH whose ``sbatch`` writes its arguments and the
    account and partition variables it sees to sbatch.json, then prints a job id."""
    bindir = tmp_path / "bin"
    bindir.mkdir()
    record = tmp_path / "sbatch.json"
    _stand_in(
        bindir,
        "sbatch",
        f'python3 -c \'import json, os, sys; json.dump({{"args": sys.argv[1:], '
        f'"account": os.environ.get("SBATCH_ACCOUNT"), '
        f'"partition": os.environ.get("SBATCH_PARTITION")}}, open("{record}", "w"))\' "$@"\n'
        'echo "4711;abglib"\n',
    )
    work = tmp_path / "work"
    work.mkdir()
    env = {k: v for k, v in os.environ.items() if k not in ("SBATCH_ACCOUNT", "SBATCH_PARTITION")}
    env["PATH"] = f"{bindir}{os.pathsep}{env['PATH']}"
    return work, env, record


def _submit(work, env, props=GROUP, text=None, **extra_env):
    """Run sbatch-submit.py on a job script: ``text``, or JOBSCRIPT with ``props``."""
    script = work / "snakejob.sh"
    text = JOBSCRIPT.format(props=json.dumps(props)) if text is None else text
    script.write_text(text, encoding="utf-8")
    out = subprocess.run(
        [str(SUBMIT), str(script)], cwd=work, capture_output=True, text=True,
        env={**env, **extra_env}, timeout=60,
    )  # fmt: skip
    return out, script


def test_submit_asks_sbatch_for_the_group_and_prints_its_id(cluster):
    work, env, record = cluster
    out, script = _submit(work, env)
    assert out.returncode == 0, out.stdout + out.stderr
    assert out.stdout == "4711\n"
    sent = json.loads(record.read_text())
    assert sent["args"] == [
        "--parsable",
        "--job-name=abglib-cells",
        "--cpus-per-task=1",
        "--output=.snakemake/slurm_logs/cells-%j.log",
        "--mem=2000",
        "--time=20",
        str(script),
    ]
    # nothing names an account or a partition: sbatch's defaults, or its own variables
    assert (sent["account"], sent["partition"]) == (None, None)
    assert (work / ".snakemake" / "slurm_logs").is_dir()
    # the group's run: jobs run in threads of its one Snakemake process
    text = script.read_text()
    assert text.count("--force-use-threads") == 1
    assert "/venv/bin/python3 -m snakemake --force-use-threads --snakefile" in text


def test_submit_leaves_account_and_partition_to_sbatch(cluster):
    work, env, record = cluster
    out, _ = _submit(work, env, SBATCH_ACCOUNT="ci", SBATCH_PARTITION="batch")
    assert out.returncode == 0, out.stdout + out.stderr
    sent = json.loads(record.read_text())
    assert (sent["account"], sent["partition"]) == ("ci", "batch")
    assert not any(a.startswith(("-A", "--account", "-p", "--partition")) for a in sent["args"])


def test_submit_a_job_outside_every_group_and_without_resources(cluster):
    work, env, record = cluster
    props = {"type": "single", "rule": "all", "threads": 2, "resources": {"tmpdir": "/tmp"}}
    out, script = _submit(work, env, props)
    assert out.returncode == 0, out.stdout + out.stderr
    assert json.loads(record.read_text())["args"] == [
        "--parsable",
        "--job-name=abglib-all",
        "--cpus-per-task=2",
        "--output=.snakemake/slurm_logs/all-%j.log",
        str(script),
    ]
    # submitting the same script again adds nothing twice
    out, script = _submit(work, env, text=script.read_text())
    assert out.returncode == 0, out.stdout + out.stderr
    assert script.read_text().count("--force-use-threads") == 1


@pytest.mark.parametrize(
    "old, new, message",
    [
        (" -m snakemake ", " -m other ", "no ' -m snakemake ' command"),
        ("# properties", "# nothing", "no '# properties = ' line"),
    ],
)
def test_submit_refuses_a_job_script_it_cannot_read(cluster, old, new, message):
    work, env, record = cluster
    out, _ = _submit(work, env, text=JOBSCRIPT.format(props=json.dumps(GROUP)).replace(old, new))
    assert out.returncode == 1
    assert message in out.stdout and message in out.stderr
    assert not record.exists()  # nothing was submitted


def test_submit_reports_a_failed_sbatch(cluster):
    work, env, _ = cluster
    _stand_in(Path(env["PATH"].split(os.pathsep)[0]), "sbatch",
              'echo "sbatch: error: invalid account" >&2; exit 3\n')  # fmt: skip
    out, _ = _submit(work, env)
    assert out.returncode == 1
    assert "sbatch exited with 3: sbatch: error: invalid account" in out.stdout


@pytest.mark.parametrize(
    "sacct_prints, status",
    [
        ("COMPLETED", "success"),
        ("RUNNING", "running"),
        ("PENDING", "running"),
        ("COMPLETING", "running"),
        ("", "running"),  # not in the accounting yet
        ("FAILED", "failed"),
        ("CANCELLED by 0", "failed"),
        ("TIMEOUT", "failed"),
        ("OUT_OF_MEMORY", "failed"),
        ("NODE_FAIL", "failed"),
        ("PREEMPTED", "failed"),
    ],
)
def test_status_command_maps_sacct_states(tmp_path, sacct_prints, status):
    # the profile's command as Snakemake runs it: the value with environment variables
    # expanded (Snakemake's profile reader does), then `<command> '<jobid>'` in a shell
    command = yaml.safe_load((PROFILE / "config.yaml").read_text())["cluster-generic-status-cmd"]
    command = os.path.expandvars(command)
    bindir = tmp_path / "bin"
    bindir.mkdir()
    _stand_in(
        bindir, "sacct",
        f'[ "$*" = "-j 4711 -X -n -P -o State" ] || exit 9\n'
        f'[ -z "{sacct_prints}" ] || echo "{sacct_prints}"\n',
    )  # fmt: skip
    env = {**os.environ, "PATH": f"{bindir}{os.pathsep}{os.environ['PATH']}"}
    out = subprocess.run(
        f"{command} '4711'", shell=True, capture_output=True, text=True, env=env, timeout=60
    )
    assert (out.returncode, out.stdout) == (0, f"{status}\n"), out.stderr
