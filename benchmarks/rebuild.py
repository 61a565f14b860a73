"""How long the pipeline takes to build: a clean build, a no-op rerun, the large sweep.

    python benchmarks/rebuild.py                 # default config: clean, no-op, large sweep
    python benchmarks/rebuild.py --small         # the tests' small config (clean, no-op)
    python benchmarks/rebuild.py --skip-large    # clean and no-op only
    python benchmarks/rebuild.py --large-only    # the large sweep only

Each case runs ``snakemake -c<cores>`` in a fresh working directory of its own (``-d``, under
``--workdir``, default a temporary directory) and is timed by the wall clock:

- ``clean``: the whole build (``snakemake -c2``) from nothing;
- ``noop``: the same command again, which must report "Nothing to be done";
- ``large``: the benchmark report of ``config/benchmark_large.yaml`` (every scenario, 10^4
  runs per cell) merged over the config, from nothing, as the README's quick start runs it.

Writes ``benchmarks/results/rebuild.csv`` (one row per case: wall time, jobs, the issue's
target) and ``benchmarks/results/rebuild_rules.csv`` (the clean build's time per rule, from
the rules' ``benchmark:`` files: where the time goes); ``--large-only`` writes
``rebuild_large.csv`` and ``rebuild_rules_large.csv`` (the large sweep's time per rule).
On a shared machine run it under the machine's lock
(``flock /work/cpu.lock python benchmarks/rebuild.py``).
"""

from __future__ import annotations

import argparse
import csv
import re
import shutil
import subprocess
import sys
import tempfile
import time
from collections import defaultdict
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
OUT = REPO / "benchmarks" / "results"
SNAKEMAKE = Path(sys.executable).parent / "snakemake"
#: issue 14's targets (seconds, 2 cores)
TARGETS = {"clean": 60.0, "noop": 3.0, "large": 180.0}


def _version() -> str:
    sys.path.insert(0, str(REPO))
    import abglib

    return abglib.__version__


def run(workdir: Path, configs: list[Path], cores: int, targets=()) -> tuple[float, str]:
    """Wall time and output of one ``snakemake`` invocation."""
    exe = str(SNAKEMAKE) if SNAKEMAKE.exists() else "snakemake"
    cmd = [exe, f"-c{cores}", "-s", str(REPO / "Snakefile"), "-d", str(workdir)]
    # as in a clone: the Snakefile's own `configfile: "config.yaml"` (a copy in the working
    # directory) and only the other configs on the command line; passing config.yaml again
    # would parse its 35 kB of YAML twice (~0.4 s of every run, the no-op's included)
    workdir.mkdir(parents=True, exist_ok=True)
    shutil.copyfile(REPO / "config.yaml", workdir / "config.yaml")
    extra = [c for c in configs if Path(c).resolve() != (REPO / "config.yaml").resolve()]
    if extra:
        cmd += ["--configfile", *map(str, extra)]
    if targets:
        cmd += ["--", *targets]
    t0 = time.perf_counter()
    out = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    if out.returncode != 0:
        raise SystemExit(f"{' '.join(cmd)} failed:\n{out.stderr[-4000:]}")
    return wall, out.stdout + out.stderr


def jobs_done(log: str) -> int:
    m = re.findall(r"(\d+) of (\d+) steps \(100%\) done", log)
    return int(m[-1][1]) if m else 0


def rule_times(workdir: Path) -> list[dict]:
    """Seconds per rule of a build, from its ``benchmarks/results/**.tsv`` files (a rule's
    files lie under ``benchmarks/results/<stage>/``; the file's stem names the job) and, for
    the benchmark cells, from their logs."""
    per: dict[str, list[float]] = defaultdict(list)
    for f in sorted((workdir / "benchmarks" / "results").rglob("*.tsv")):
        rows = list(csv.DictReader(f.open(encoding="utf-8"), delimiter="\t"))
        if not rows:
            continue
        rel = f.relative_to(workdir / "benchmarks" / "results")
        stage = rel.parts[0]
        name = (
            "benchmark_cell"
            if "cells" in rel.parts
            else f"{stage}/{re.sub(r'_?fig[1-6]$', '', f.stem)}"
        )
        per[name].append(float(rows[-1]["s"]))
    # the benchmark cells have no benchmark: file (see abglib.bench.cell.cell_job): their
    # logs end with "wrote <csv> in <seconds> s"
    for f in sorted((workdir / "logs" / "benchmark" / "cells").rglob("*.log")):
        m = re.search(r" in ([0-9.]+) s$", f.read_text(encoding="utf-8").strip())
        if m:
            per["benchmark_cell"].append(float(m.group(1)))
    out = [
        {"rule": k, "jobs": len(v), "total_s": round(sum(v), 2), "max_s": round(max(v), 2)}
        for k, v in per.items()
    ]
    return sorted(out, key=lambda r: -r["total_s"])


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--small", action="store_true", help="the tests' small config")
    ap.add_argument("--skip-large", action="store_true", help="no large sweep")
    ap.add_argument("--large-only", action="store_true", help="the large sweep only")
    ap.add_argument("--cores", type=int, default=2)
    ap.add_argument("--workdir", type=Path, default=None, help="where the builds go")
    args = ap.parse_args(argv)
    if args.large_only and (args.small or args.skip_large):
        ap.error("--large-only is the default config's large sweep: no --small/--skip-large")
    base = args.workdir or Path(tempfile.mkdtemp(prefix="abglib-rebuild-"))
    configs = [REPO / "config.yaml"]
    name = "default"
    if args.small:
        configs.append(REPO / "tests" / "data" / "config_small.yaml")
        name = "small"
    rows = []
    clean = base / f"{name}-clean"
    if not args.large_only:
        wall, log = run(clean, configs, args.cores)
        rows.append(("clean", name, wall, jobs_done(log)))
        print(f"clean build ({name}): {wall:.1f} s, {jobs_done(log)} jobs", flush=True)
        wall, log = run(clean, configs, args.cores)
        if "Nothing to be done" not in log:
            raise SystemExit(f"the second run was not a no-op:\n{log[-3000:]}")
        rows.append(("noop", name, wall, 0))
        print(f"no-op run ({name}): {wall:.2f} s", flush=True)
    if not (args.small or args.skip_large):
        large = base / "large"
        target = f"results/reports/v{_version()}/benchmark/index.html"
        wall, log = run(
            large, [*configs, REPO / "config" / "benchmark_large.yaml"], args.cores, [target]
        )
        n_cells = len(list((large / "results" / "benchmark" / "cells").rglob("*.csv")))
        rows.append(("large", f"{name}+benchmark_large", wall, jobs_done(log)))
        print(f"large sweep: {wall:.1f} s, {jobs_done(log)} jobs, {n_cells} cells", flush=True)
    OUT.mkdir(parents=True, exist_ok=True)
    suffix = "_large" if args.large_only else ("" if name == "default" else f"_{name}")
    with (OUT / f"rebuild{suffix}.csv").open("w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(["case", "config", "cores", "wall_s", "jobs", "target_s", "met"])
        for case, cfg, wall, jobs in rows:
            tgt = TARGETS[case] if name == "default" else ""
            met = "" if tgt == "" else str(wall <= tgt).lower()
            w.writerow([case, cfg, args.cores, f"{wall:.2f}", jobs, tgt, met])
    per_rule = rule_times(base / "large" if args.large_only else clean)
    with (OUT / f"rebuild_rules{suffix}.csv").open("w", newline="", encoding="utf-8") as fh:
        w = csv.DictWriter(fh, ["rule", "jobs", "total_s", "max_s"], lineterminator="\n")
        w.writeheader()
        w.writerows(per_rule)
    which = "large sweep" if args.large_only else "clean build"
    print(f"time per rule ({which}, benchmark: files):")
    for r in per_rule[:15]:
        print(
            f"  {r['rule']:<40} {r['jobs']:>4} jobs {r['total_s']:>8.1f} s (max {r['max_s']:.1f})"
        )
    print(f"wrote {OUT / f'rebuild{suffix}.csv'} and {OUT / f'rebuild_rules{suffix}.csv'}")


if __name__ == "__main__":
    main()
