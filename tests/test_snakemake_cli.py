"""tests/_snakemake_cli.py: a forked Snakemake says and exits what a fresh one does."""

import os
import re
import subprocess
import sys
import time
from pathlib import Path

import pytest

from . import _snakemake_cli as cli

SNAKEMAKE = Path(sys.executable).parent / "snakemake"
EXE = str(SNAKEMAKE) if SNAKEMAKE.exists() else "snakemake"

TINY = """
rule all:
    input: "out/b.txt"

rule make:
    output: "out/{name}.txt"
    params: label=lambda wildcards: wildcards.name.upper()
    shell: "echo {params.label} > {output}"
"""


#: A job's time stamp, "[Thu Dec  3 15:41:50 2026]"
STAMP = re.compile(r"^\[\w{3} \w{3} [ \d]\d \d\d:\d\d:\d\d \d{4}\]$")


def _lines(text: str) -> list[str]:
    """The output without what differs from run to run (the date, the workflow's id, the
    jobs' time stamps)."""
    return [
        x
        for x in text.splitlines()
        if not (x.strip().startswith(("Date:", "Workflow ID:")) or STAMP.match(x.strip()))
    ]


@pytest.mark.parametrize(
    "args, env, fresh, forked",
    [
        (["-n"], None, False, True),
        (["--dry-run", "all"], None, False, True),
        (["--lint"], None, False, True),
        (["--list-rules"], None, False, True),
        (["-c2"], None, False, False),  # a build: a real process
        (["-n"], None, True, False),
        (["-n"], {"NUMBA_CACHE_DIR": "/elsewhere"}, False, True),
        (["-n"], {"PYTHONPATH": "/elsewhere"}, False, False),
        (["-n"], {"PYTHONPROFILEIMPORTTIME": "1"}, False, False),
    ],
)
def test_what_is_forked(args, env, fresh, forked):
    full = None if env is None else {**os.environ, **env}
    assert cli.forkable([EXE, *args], full, fresh) is forked
    assert not cli.forkable(["python", "-n"])


@pytest.mark.slow  # Snakemake, forked and fresh
def test_a_forked_run_says_and_exits_what_a_fresh_one_does(tmp_path):
    (tmp_path / "Snakefile").write_text(TINY, encoding="utf-8")
    bad = tmp_path / "bad"
    bad.mkdir()
    (bad / "Snakefile").write_text("rule broken:\n    output 'x'\n", encoding="utf-8")
    for args, cwd, code in (
        (["-n"], tmp_path, 0),
        (["--list-rules"], tmp_path, 0),
        (["-n", "no/such/target"], tmp_path, 1),
        (["-n"], bad, 1),
    ):
        forked = cli.run([EXE, *args], cwd=cwd, timeout=120)
        fresh = cli.run([EXE, *args], cwd=cwd, timeout=120, fresh=True)
        assert (forked.returncode, fresh.returncode) == (code, code), (args, forked, fresh)
        assert _lines(forked.stdout) == _lines(fresh.stdout), args
        assert _lines(forked.stderr) == _lines(fresh.stderr), args
    assert "make" in forked.stdout + cli.run([EXE, "-n"], cwd=tmp_path).stdout
    assert not (tmp_path / "out").exists()  # dry runs


@pytest.mark.slow  # Snakemake, forked
def test_a_forked_run_sees_the_environment_it_is_given(tmp_path):
    (tmp_path / "Snakefile").write_text(
        'import os\nprint("cache:", os.environ.get("NUMBA_CACHE_DIR"))\n'
        'rule all:\n    shell: "true"\n',
        encoding="utf-8",
    )
    env = {**os.environ, "NUMBA_CACHE_DIR": str(tmp_path / "numba")}
    out = cli.run([EXE, "-n"], cwd=tmp_path, env=env, timeout=120)
    assert out.returncode == 0, out.stderr
    assert f"cache: {tmp_path / 'numba'}" in out.stdout
    assert os.environ.get("NUMBA_CACHE_DIR") != str(tmp_path / "numba")  # this process's


@pytest.mark.slow  # Snakemake, forked
def test_a_forked_run_past_its_timeout_is_killed_and_the_server_goes_on(tmp_path):
    (tmp_path / "Snakefile").write_text(
        'import time\ntime.sleep(60)\nrule all:\n    shell: "true"\n', encoding="utf-8"
    )
    t = time.monotonic()
    with pytest.raises(subprocess.TimeoutExpired):
        cli.run([EXE, "-n"], cwd=tmp_path, timeout=3)
    assert time.monotonic() - t < 30
    (tmp_path / "Snakefile").write_text(TINY, encoding="utf-8")
    assert cli.run([EXE, "-n"], cwd=tmp_path, timeout=120).returncode == 0
