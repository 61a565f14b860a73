"""How long the test suite takes, cold, and the CPU time of every process it starts.

    python benchmarks/suite_speed.py                  # 3 runs of `pytest`, caches cold
    python benchmarks/suite_speed.py --runs 1 --warm  # numba's cache and bytecode kept
    python benchmarks/suite_speed.py --warm --target 30 -- -m "not slow"  # the dev loop

Issue 24's measure of the README's test command. Each run, unless ``--warm``:

- removes numba's caches: the tests' base folder (``tests/_numba_warm.NUMBA_BASE``) and the
  compiled loops a build left in the repository (``__pycache__/*.nbi``, ``*.nbc``);
- removes the repository's ``__pycache__`` folders (the tests' rewritten asserts, abglib's
  bytecode), leaving alone every virtual environment inside it (a folder holding
  ``pyvenv.cfg``, as the README's ``.venv``);

then runs ``pytest -p no:cacheprovider <args>`` from the repository's root (the pytest
beside this interpreter) and records:

- ``wall_s``: the wall clock, from start to pytest's exit;
- ``pytest_s``: pytest's own count ("in 123.45s");
- ``cpu_s``: user + system CPU time of *every* process the run started. Snakemake's fork
  server detaches from its parent (its parent becomes init, and its time is counted by no
  one, ``time pytest`` included: 228 CPU-s where the run took 356, 2026-12-03). This script
  makes itself the *subreaper* of the run (Linux ``prctl(PR_SET_CHILD_SUBREAPER)``), so
  that detached descendants become its children, and reaps them: their time then adds to
  its own children's (``getrusage(RUSAGE_CHILDREN)``). Elsewhere ``cpu_s`` counts only the
  processes pytest waited for, and the CSV says so (``cpu_complete``);
- ``probe_s``: the machine's speed at numba's own work, the CPU time of a fresh interpreter
  importing numba and compiling one fixed loop (uncached). Runs on the "same" idle 2-core
  machine kind differ by a third (`docs/testing.md`); the probe tells which machine a run
  had, where a pure-Python loop did not.

Writes ``benchmarks/results/suite_speed.csv`` (one row per run) and prints every run; the
pytest output of run ``k`` goes to ``benchmarks/results/suite_speed.<k>.log``. Run it alone
on the machine: the suite is bound by CPU on two cores, so anything beside it is measured
too.
"""

from __future__ import annotations

import argparse
import csv
import ctypes
import os
import re
import shutil
import subprocess
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
OUT = REPO / "benchmarks" / "results"
PYTEST = Path(sys.executable).parent / "pytest"
#: issue 24's targets on two cores (s): the whole suite cold, and the development loop
TARGET_S, LOOP_TARGET_S = 120.0, 30.0
COLUMNS = ["run", "cold", "wall_s", "pytest_s", "cpu_s", "cpu_complete", "probe_s", "outcome"]
#: ``prctl`` option (linux/prctl.h)
PR_SET_CHILD_SUBREAPER = 36
#: the fixed loop of the machine probe
PROBE = """
import numba, numpy as np
@numba.njit(cache=False)
def f(x, a, b):
    out = np.empty_like(x)
    p = v = 0.0
    for k in range(x.size):
        e = x[k] - p
        s = p + a * e
        v = v + b * e
        p = s + v
        out[k] = s
    return out
f(np.ones(8), 0.5, 0.1)
"""


def become_subreaper() -> bool:
    """Make this process the subreaper of its descendants (Linux); False where it cannot."""
    if not sys.platform.startswith("linux"):
        return False
    try:
        libc = ctypes.CDLL(None, use_errno=True)
        return libc.prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0) == 0
    except (OSError, AttributeError):
        return False


def children_cpu() -> float:
    """User + system CPU seconds of this process's reaped children (and theirs)."""
    import resource

    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def run_counted(cmd, *, cwd=None, stdout=None, linger: float = 60.0) -> tuple[int, float, float]:
    """Run ``cmd`` and wait for it and for every descendant it leaves behind.

    Returns ``(returncode, wall seconds to the command's exit, CPU seconds)``. The CPU
    time is that of every process the command started, detached ones included, when this
    process is the subreaper (:func:`become_subreaper`): it reaps them as they exit.
    Descendants still alive ``linger`` seconds after the command exited are left running
    and uncounted.
    """
    cpu0, t0 = children_cpu(), time.perf_counter()
    proc = subprocess.Popen(cmd, cwd=cwd, stdout=stdout, stderr=subprocess.STDOUT)
    code, wall, deadline = None, None, None
    while True:
        try:
            pid, status = os.waitpid(-1, os.WNOHANG)
        except ChildProcessError:  # no child left at all
            break
        if pid == proc.pid:
            code = os.waitstatus_to_exitcode(status)
            proc.returncode = code  # Popen must not wait for it again
            wall = time.perf_counter() - t0
            deadline = time.monotonic() + linger
        elif pid == 0:  # children left, none finished
            if deadline is not None and time.monotonic() > deadline:
                break
            time.sleep(0.05)
    return code, wall, children_cpu() - cpu0


def clear_caches(repo: Path, numba_base: Path) -> int:
    """Remove numba's cache folder ``numba_base`` and every ``__pycache__`` of ``repo``
    outside virtual environments and hidden folders; returns how many were removed."""
    removed = 0
    if numba_base.exists():
        shutil.rmtree(numba_base)
        removed += 1
    for root, dirs, _ in os.walk(repo):
        here = Path(root)
        if (here / "pyvenv.cfg").exists():
            dirs[:] = []
            continue
        dirs[:] = [d for d in dirs if not d.startswith(".")]
        if "__pycache__" in dirs:
            shutil.rmtree(here / "__pycache__")
            dirs.remove("__pycache__")
            removed += 1
    return removed


def probe() -> float:
    """CPU seconds of a fresh interpreter importing numba and compiling :data:`PROBE`."""
    return run_counted([sys.executable, "-c", PROBE], stdout=subprocess.DEVNULL)[2]


def pytest_seconds(log: str) -> float | None:
    """pytest's own duration from the last line of its output ("... in 123.45s ...")."""
    found = re.findall(r" in ([0-9.]+)s", log)
    return float(found[-1]) if found else None


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--runs", type=int, default=3, help="how many runs (default 3)")
    ap.add_argument("--warm", action="store_true", help="keep numba's cache and bytecode")
    ap.add_argument(
        "--target",
        type=float,
        default=TARGET_S,
        help=f"the target (s) to count runs against (default {TARGET_S:.0f}: the whole "
        f"suite; the development loop's is {LOOP_TARGET_S:.0f})",
    )
    ap.add_argument("pytest_args", nargs="*", help="after --: arguments for pytest")
    args = ap.parse_args(argv)
    if args.runs < 1:
        ap.error(f"--runs must be at least 1, got {args.runs}")
    if not args.target > 0:
        ap.error(f"--target must be a positive number of seconds, got {args.target}")
    if not PYTEST.exists():
        ap.error(f"no pytest beside {sys.executable}: pip install -e '.[dev]'")
    sys.path.insert(0, str(REPO))
    from tests._numba_warm import NUMBA_BASE

    complete = become_subreaper()
    if not complete:
        print("suite_speed: not Linux: cpu_s counts only the processes pytest waited for")
    OUT.mkdir(parents=True, exist_ok=True)
    rows = []
    for k in range(1, args.runs + 1):
        if not args.warm:
            clear_caches(REPO, NUMBA_BASE)
        probe_s = probe()
        log = OUT / f"suite_speed.{k}.log"
        cmd = [str(PYTEST), "-p", "no:cacheprovider", *args.pytest_args]
        with open(log, "w", encoding="utf-8") as fh:
            code, wall, cpu = run_counted(cmd, cwd=REPO, stdout=fh)
        text = log.read_text(encoding="utf-8", errors="replace")
        last = (text.strip().splitlines() or ["(no output)"])[-1].strip("= ")
        row = {
            "run": k,
            "cold": not args.warm,
            "wall_s": round(wall, 2),
            "pytest_s": pytest_seconds(text),
            "cpu_s": round(cpu, 1),
            "cpu_complete": complete,
            "probe_s": round(probe_s, 2),
            "outcome": f"exit {code}: {last}",
        }
        rows.append(row)
        print(
            f"run {k}: pytest {row['pytest_s']} s, wall {row['wall_s']} s, "
            f"{row['cpu_s']} CPU-s, probe {row['probe_s']} CPU-s; {row['outcome']}",
            flush=True,
        )
    with open(OUT / "suite_speed.csv", "w", newline="", encoding="utf-8") as fh:
        w = csv.DictWriter(fh, fieldnames=COLUMNS)
        w.writeheader()
        w.writerows(rows)
    within = sum(1 for r in rows if r["pytest_s"] is not None and r["pytest_s"] <= args.target)
    print(f"{within} of {len(rows)} runs within {args.target:g} s by pytest's count")
    return 0 if all(r["outcome"].startswith("exit 0") for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
