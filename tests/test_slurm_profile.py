"""The SLURM profile's own commands, without a cluster (profiles/slurm): its sbatch
wrapper (sbatch-submit.py) against a stand-in ``sbatch`` that records what it is given,
and its status command against stand-ins for ``sacct`` and ``squeue`` that record what
they are asked and print each state. tests/test_slurm.py runs them on a real cluster."""

import json
import os
import subprocess
import sys
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
        "--no-requeue",
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
    # Snakemake passes --force-use-threads itself to a job outside every group
    text = JOBSCRIPT.format(props=json.dumps(props)).replace(
        " --cores 1", " --cores 1 --force-use-threads"
    )
    out, script = _submit(work, env, text=text)
    assert out.returncode == 0, out.stdout + out.stderr
    assert json.loads(record.read_text())["args"] == [
        "--parsable",
        "--no-requeue",
        "--job-name=abglib-all",
        "--cpus-per-task=2",
        "--output=.snakemake/slurm_logs/all-%j.log",
        str(script),
    ]
    assert script.read_text() == text  # the flag is there once already


@pytest.mark.parametrize(
    "old, new, message",
    [
        (" -m snakemake ", " -m other ", "no '-m snakemake' command"),
        ("# properties", "# nothing", "no '# properties = ' line"),
    ],
)
def test_submit_refuses_a_job_script_it_cannot_read(cluster, old, new, message):
    work, env, record = cluster
    out, _ = _submit(work, env, text=JOBSCRIPT.format(props=json.dumps(GROUP)).replace(old, new))
    assert out.returncode == 1
    assert message in out.stdout and message in out.stderr
    assert not record.exists()  # nothing was submitted


@pytest.mark.parametrize(
    "body, message",
    [
        ('echo "sbatch: error: invalid account" >&2; exit 3\n',
         "sbatch exited with 3: sbatch: error: invalid account"),
        ('echo "queued"\n', "sbatch printed no job id: 'queued'"),
    ],
)  # fmt: skip
def test_submit_reports_a_failed_sbatch(cluster, body, message):
    # Snakemake shows the submit command's stdout when it fails, and would poll a job id
    # that is not one for ever
    work, env, _ = cluster
    _stand_in(Path(env["PATH"].split(os.pathsep)[0]), "sbatch", body)
    out, _ = _submit(work, env)
    assert out.returncode == 1
    assert message in out.stdout


def _profile_value(key: str) -> str:
    """A value of the profile as Snakemake's profile reader gives it to the executor (with
    environment variables expanded)."""
    return os.path.expandvars(yaml.safe_load((PROFILE / "config.yaml").read_text())[key])


def test_submit_command_runs_the_script_from_any_directory(cluster, tmp_path):
    # the submit command is formatted like a job's (snakemake.utils.format, the Snakefile's
    # globals: sys and workflow); a clone in a path with spaces still works
    from types import SimpleNamespace

    from snakemake.utils import format as smk_format

    work, env, record = cluster
    clone = tmp_path / "a clone" / "abglib"
    (clone / "profiles" / "slurm").mkdir(parents=True)
    # a copy without the executable bit: the command runs it with Snakemake's Python
    (clone / "profiles" / "slurm" / "sbatch-submit.py").write_bytes(SUBMIT.read_bytes())
    command = smk_format(
        _profile_value("cluster-generic-submit-cmd"),
        sys=sys,
        workflow=SimpleNamespace(basedir=str(clone)),
    )
    script = work / "snakejob.sh"
    script.write_text(JOBSCRIPT.format(props=json.dumps(GROUP)), encoding="utf-8")
    out = subprocess.run(
        f'{command} "{script}"', shell=True, cwd=work, capture_output=True, text=True,
        env=env, timeout=60,
    )  # fmt: skip
    assert (out.returncode, out.stdout) == (0, "4711\n"), out.stderr
    assert json.loads(record.read_text())["args"][-1] == str(script)


def test_status_command_stays_one_short_name():
    # Snakemake's profile reader checks whether each value names a file beside the profile
    # (profiles.py: (profile_dir / value).exists()); a value over 255 bytes without a slash
    # makes that raise "File name too long" and the profile fail to load
    command = _profile_value("cluster-generic-status-cmd")
    assert "/" not in command and len(command.encode()) < 255, len(command.encode())
    assert not (PROFILE / command).exists()


@pytest.mark.parametrize(
    "sacct_prints, squeue_prints, status",
    [
        ("COMPLETED", None, "success"),
        ("RUNNING", None, "running"),
        ("PENDING", None, "running"),
        ("COMPLETING", None, "running"),
        ("REQUEUED", None, "running"),
        ("SUSPENDED", None, "running"),
        ("FAILED", None, "failed"),
        ("CANCELLED by 0", None, "failed"),
        ("TIMEOUT", None, "failed"),
        ("OUT_OF_MEMORY", None, "failed"),
        ("NODE_FAIL", None, "failed"),
        ("PREEMPTED", None, "failed"),
        # a job id the cluster used twice: the newest job's state (sacct lists it last)
        ("FAILED\nCOMPLETED", None, "success"),
        # not in the accounting yet (or no accounting): squeue's state
        ("", "PENDING", "running"),
        ("", "RUNNING", "running"),
        ("", "COMPLETED", "success"),
        ("", "FAILED", "failed"),
        # a job neither knows
        ("", "", "failed"),
    ],
)
def test_status_command_maps_slurm_states(tmp_path, sacct_prints, squeue_prints, status):
    # the profile's command as Snakemake runs it: `<command> '<jobid>'` in a shell, with
    # stand-ins for sacct and squeue that write what they were asked
    command = _profile_value("cluster-generic-status-cmd")
    bindir = tmp_path / "bin"
    bindir.mkdir()
    for name, prints in (("sacct", sacct_prints), ("squeue", squeue_prints)):
        _stand_in(
            bindir, name,
            f'echo "$*" >> "{tmp_path}/{name}.args"\n[ -z "{prints or ""}" ] || echo "{prints}"\n',
        )  # fmt: skip
    env = {**os.environ, "PATH": f"{bindir}{os.pathsep}{os.environ['PATH']}"}
    out = subprocess.run(
        f"{command} '4711'", shell=True, capture_output=True, text=True, env=env, timeout=60
    )
    assert (out.returncode, out.stdout) == (0, f"{status}\n"), out.stderr
    assert (tmp_path / "sacct.args").read_text() == "-XnPo State -j 4711\n"
    # squeue only when sacct has nothing
    if squeue_prints is None:
        assert not (tmp_path / "squeue.args").exists()
    else:
        assert (tmp_path / "squeue.args").read_text() == "-ho %T -j 4711\n"
