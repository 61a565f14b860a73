"""benchmarks/suite_speed.py: what it counts and what it removes (not how fast anything is)."""

import importlib.util
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]
SCRIPT = REPO / "benchmarks" / "suite_speed.py"
_spec = importlib.util.spec_from_file_location("suite_speed", SCRIPT)
suite_speed = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(suite_speed)

#: a process that starts a grandchild burning argv[1] CPU-seconds, and exits at once: the
#: grandchild is left to whoever reaps orphans, as Snakemake's fork server is
DETACHED = """
import os, sys, time
if os.fork() == 0:
    if os.fork() == 0:
        t = time.process_time()
        while time.process_time() - t < float(sys.argv[1]):
            pass
    os._exit(0)
os.wait()
"""

#: the count, taken in a process of its own, as the script takes it: run_counted reaps any
#: child of its process (a test worker's own would be taken from it), and a subreaper stays
#: one for life
COUNT = """
import sys
sys.path.insert(0, {bench!r})
import suite_speed as s
sub = s.become_subreaper() if {reap!r} else False
code, wall, cpu = s.run_counted([sys.executable, "-c", {code!r}, {burn!r}], linger=30)
print(sub, code, cpu)
"""


def _count(reap: bool, burn: float):
    code = COUNT.format(bench=str(SCRIPT.parent), reap=reap, code=DETACHED, burn=str(burn))
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert out.returncode == 0, out.stderr
    sub, exit_code, cpu = out.stdout.split()
    assert exit_code == "0"
    return sub == "True", float(cpu)


@pytest.mark.slow  # three processes, twice
@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="a subreaper is Linux's")
def test_the_cpu_of_a_detached_grandchild_is_counted_only_by_a_subreaper():
    burn = 0.4
    sub, cpu = _count(True, burn)
    assert sub
    # the grandchild's burn, counted once, plus two short interpreters
    assert burn <= cpu < burn + 1.0
    # without: what `time pytest` counts, the reason the script exists
    sub, cpu = _count(False, burn)
    assert not sub
    assert cpu < burn


def test_caches_are_cleared_outside_virtual_environments(tmp_path):
    repo, base = tmp_path / "repo", tmp_path / "numba"
    for d in (
        "abglib/__pycache__",
        "tests/sub/__pycache__",
        ".venv/lib/__pycache__",
        "env/lib/x/__pycache__",
        ".git/__pycache__",
    ):
        (repo / d).mkdir(parents=True)
        (repo / d / "m.cpython-311.pyc").write_bytes(b"x")
    (repo / "env" / "pyvenv.cfg").write_text("home = /usr/bin\n")
    (base / "worker").mkdir(parents=True)
    assert suite_speed.clear_caches(repo, base) == 3
    assert not base.exists()
    assert not (repo / "abglib" / "__pycache__").exists()
    assert not (repo / "tests" / "sub" / "__pycache__").exists()
    for kept in (".venv/lib/__pycache__", "env/lib/x/__pycache__", ".git/__pycache__"):
        assert (repo / kept / "m.cpython-311.pyc").exists(), kept


def test_pytest_seconds_reads_the_last_summary_line():
    log = "x in 1.5s\n===== 2138 passed, 1 skipped in 176.30s (0:02:56) =====\n"
    assert suite_speed.pytest_seconds(log) == 176.30
    assert suite_speed.pytest_seconds("Interrupted: no tests ran\n") is None


@pytest.mark.parametrize(
    "args, message",
    [
        (["--runs", "0"], "--runs must be at least 1, got 0"),
        (["--target", "-5"], "--target must be a positive number of seconds, got -5.0"),
    ],
)
def test_bad_arguments_are_refused_by_name(args, message, capsys):
    with pytest.raises(SystemExit):
        suite_speed.main(args)
    assert message in capsys.readouterr().err
