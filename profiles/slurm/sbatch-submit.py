#!/usr/bin/env python3
"""Submit one Snakemake job, or one group of jobs, to SLURM with ``sbatch``.

Snakemake's generic cluster executor (profiles/slurm, ``cluster-generic-submit-cmd``)
runs this with its own Python and the path of the job script it wrote; this prints the
SLURM job id, whose state the profile's status command then asks ``sacct`` for. What it
asks SLURM for comes from the job script's ``# properties = {...}`` line (Snakemake's
default job script; the format ``snakemake.utils.read_job_properties`` reads, parsed here
with the standard library: a submission starts no Snakemake import):

- ``--job-name=abglib-<group>`` (or ``abglib-<rule>`` for a job outside every group);
- ``--cpus-per-task`` = the job's ``threads`` (a group: its width, the profile's ``cores``);
- ``--mem`` = its ``resources.mem_mb`` and ``--time`` = its ``resources.runtime``
  (minutes), where the job has them;
- ``--output=.snakemake/slurm_logs/<name>-<jobid>.log`` in the working directory;
- ``--no-requeue``: a job that fails (a node failure, a preemption) stays failed, as
  Snakemake records it, instead of SLURM running it again behind Snakemake's back while
  Snakemake goes on without its outputs (rerun the build to retry).

The account and the partition are left to sbatch, which reads ``SBATCH_ACCOUNT`` and
``SBATCH_PARTITION`` itself; unset, SLURM charges the user's default account and uses the
cluster's default partition.

One change to the job script: ``--force-use-threads`` is added to its Snakemake command,
so that the group's ``run:`` jobs run in threads of that one Snakemake process, as in a
local build (the workflow's default profile says ``force-use-threads``, but Snakemake reads
profiles only in its main process, and passes the flag itself only for a job outside every
group). Without it each ``run:`` job of a group would start a Snakemake of its own (about
2 s a job). If the job script has no ``python -m snakemake`` command this stops with an
error naming the script: Snakemake has changed how it writes them, and the profile needs
updating (docs/cluster.md).

Exit status: 0 with the job id on stdout; otherwise non-zero with the reason on stdout
(which Snakemake shows in its error) and stderr, also when sbatch printed no job id.
"""

import json
import re
import subprocess
import sys
from pathlib import Path
from typing import NoReturn

#: Snakemake's job scripts carry the job's properties on one line (its default template)
PROPERTIES = re.compile(r"^# properties = (.*)$", flags=re.M)
#: the Snakemake command of a job script (snakemake-interface-executor-plugins'
#: RealExecutor.format_job_exec: ``<python> -m snakemake --snakefile ...``)
SNAKEMAKE = " -m snakemake "
THREADS = "--force-use-threads"
#: SLURM's logs of the jobs, in the working directory
LOGS = Path(".snakemake") / "slurm_logs"


def fail(message: str) -> NoReturn:
    """Say why on stdout (which Snakemake shows) and stderr, and exit with 1."""
    print(f"sbatch-submit.py: {message}")
    print(f"sbatch-submit.py: {message}", file=sys.stderr)
    sys.exit(1)


def sbatch_command(props: dict, jobscript: str) -> list[str]:
    """The sbatch command for a job with Snakemake's job properties ``props``."""
    name = props.get("groupid") if props.get("type") == "group" else props.get("rule")
    if not name:
        fail(f"no rule or group in the properties of {jobscript}")
    resources = props.get("resources") or {}
    cmd = [
        "sbatch",
        "--parsable",
        "--no-requeue",
        f"--job-name=abglib-{name}",
        f"--cpus-per-task={int(props.get('threads') or 1)}",
        f"--output={LOGS}/{name}-%j.log",
    ]
    if isinstance(resources.get("mem_mb"), (int, float)):
        cmd.append(f"--mem={int(resources['mem_mb'])}")
    if isinstance(resources.get("runtime"), (int, float)):
        cmd.append(f"--time={int(resources['runtime'])}")
    return [*cmd, jobscript]


def main(argv: list[str]) -> None:
    if len(argv) != 1:
        fail(f"expected one argument, the job script; got {len(argv)}: {argv}")
    jobscript = Path(argv[0])
    try:
        text = jobscript.read_text()
    except OSError as err:
        fail(f"cannot read the job script: {err}")
    found = PROPERTIES.search(text)
    if found is None:
        fail(f"no '# properties = ' line in the job script {jobscript}")
    props = json.loads(found.group(1))
    if SNAKEMAKE not in text:
        fail(
            f"no '{SNAKEMAKE.strip()}' command in the job script {jobscript}: Snakemake writes "
            "its job scripts differently now; profiles/slurm/sbatch-submit.py needs updating"
        )
    if THREADS not in text:
        jobscript.write_text(text.replace(SNAKEMAKE, f"{SNAKEMAKE}{THREADS} ", 1))
    LOGS.mkdir(parents=True, exist_ok=True)
    out = subprocess.run(sbatch_command(props, str(jobscript)), capture_output=True, text=True)
    if out.returncode != 0:
        fail(f"sbatch exited with {out.returncode}: {out.stderr.strip() or out.stdout.strip()}")
    # --parsable prints "<jobid>" or "<jobid>;<cluster>"
    jobid = out.stdout.strip().split(";")[0]
    if not jobid.isdigit():
        fail(f"sbatch printed no job id: {out.stdout.strip()!r}")
    print(jobid)


if __name__ == "__main__":
    main(sys.argv[1:])
