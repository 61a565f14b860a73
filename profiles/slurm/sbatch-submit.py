#!/usr/bin/env python3
"""Submit one Snakemake job, or one group of jobs, to SLURM with ``sbatch``.

Snakemake's generic cluster executor (profiles/slurm, ``cluster-generic-submit-cmd``)
calls this with the path of the job script it wrote; this prints the SLURM job id, which
Snakemake then polls with ``sacct-status.sh``. What it asks SLURM for comes from the job
script's ``# properties = {...}`` line (Snakemake's default job script; the format
``snakemake.utils.read_job_properties`` reads, parsed here with the standard library so
that the script runs under any ``python3`` on the login node):

- ``--job-name=abglib-<group>`` (or ``abglib-<rule>`` for a job outside every group);
- ``--cpus-per-task`` = the job's ``threads`` (a group: its width, the profile's ``cores``);
- ``--mem`` = its ``resources.mem_mb`` and ``--time`` = its ``resources.runtime``
  (minutes), where the job has them;
- ``--output=.snakemake/slurm_logs/<name>-<jobid>.log`` in the working directory.

The account and the partition are left to sbatch, which reads ``SBATCH_ACCOUNT`` and
``SBATCH_PARTITION`` itself; unset, SLURM charges the user's default account and uses the
cluster's default partition.

One change to the job script: ``--force-use-threads`` is added to its Snakemake command,
so that the group's ``run:`` jobs run in threads of that one Snakemake process, as in a
local build (the workflow's default profile says ``force-use-threads``, but Snakemake reads
profiles only in its main process). Without it each ``run:`` job of a group would start a
Snakemake of its own (about 2 s a job). If the job script has no ``python -m snakemake``
command this stops with an error naming the script: Snakemake has changed how it writes
them, and the profile needs updating (docs/cluster.md).

Exit status: 0 with the job id on stdout; otherwise non-zero with the reason on stdout
(which Snakemake shows in its error) and stderr.
"""

import json
import re
import subprocess
import sys
from pathlib import Path

#: Snakemake's job scripts carry the job's properties on one line (its default template)
PROPERTIES = re.compile(r"^# properties = (.*)$", flags=re.M)
#: the Snakemake command of a job script (snakemake-interface-executor-plugins'
#: RealExecutor.format_job_exec: ``<python> -m snakemake --snakefile ...``)
SNAKEMAKE = re.compile(r" -m snakemake (?!--force-use-threads)")
#: SLURM's logs of the jobs, in the working directory
LOGS = Path(".snakemake") / "slurm_logs"


def fail(message: str) -> None:
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
    threaded, count = SNAKEMAKE.subn(" -m snakemake --force-use-threads ", text, count=1)
    if count != 1 and "--force-use-threads" not in text:
        fail(
            f"no ' -m snakemake ' command in the job script {jobscript}: Snakemake writes its "
            "job scripts differently now; profiles/slurm/sbatch-submit.py needs updating"
        )
    jobscript.write_text(threaded)
    LOGS.mkdir(parents=True, exist_ok=True)
    out = subprocess.run(sbatch_command(props, str(jobscript)), capture_output=True, text=True)
    if out.returncode != 0:
        fail(f"sbatch exited with {out.returncode}: {out.stderr.strip() or out.stdout.strip()}")
    # --parsable prints "<jobid>" or "<jobid>;<cluster>"
    print(out.stdout.strip().split(";")[0])


if __name__ == "__main__":
    main(sys.argv[1:])
