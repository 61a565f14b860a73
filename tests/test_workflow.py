"""The workflow itself: Snakemake's linter finds nothing, parsing it stays light, and an edit
reruns only what it changes (a user's own tracker in the benchmark matrix:
tests/test_benchmark_pipeline.py)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from ._repo_copy import copy_env, copy_repo

REPO = Path(__file__).resolve().parents[1]
SNAKEMAKE = Path(sys.executable).parent / "snakemake"


def _run(*args):
    exe = str(SNAKEMAKE) if SNAKEMAKE.exists() else "snakemake"
    return subprocess.run([exe, *args], capture_output=True, text=True, cwd=REPO, timeout=300)


@pytest.mark.slow
def test_snakemake_lint_is_clean():
    out = _run("--lint")
    assert out.returncode == 0, out.stdout[-3000:] + out.stderr[-3000:]
    assert "Congratulations" in out.stdout + out.stderr


def test_parsing_the_workflow_imports_no_numerics_beyond_numpy():
    """Every abglib module the rule files import while Snakemake parses them stays light
    (no scipy, pandas, matplotlib or numba), so that a build with nothing to do is quick:
    the science is imported by the jobs, in their worker processes."""
    import re

    modules = set()
    for smk in sorted((REPO / "workflow" / "rules").glob("*.smk")):
        for line in smk.read_text(encoding="utf-8").splitlines():
            m = re.match(r"(?:from (abglib[\w.]*) import|import (abglib[\w.]*))", line)
            if m:
                modules.add(m.group(1) or m.group(2))
    assert "abglib.reporting.workers" in modules and "abglib.bench.variants" in modules
    code = (
        f"import sys; sys.path.insert(0, {str(REPO)!r})\n"
        + "".join(f"import {m}\n" for m in sorted(modules))
        + "heavy = sorted({m.split('.')[0] for m in sys.modules} & "
        "{'scipy', 'pandas', 'matplotlib', 'numba'})\n"
        "assert not heavy, heavy\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr[-2000:]


# ------------------------------------------------------------------ what an edit reruns
# A copy of the repository is built (a few targets of the small config: one document's
# study, claims and report, one dataset, one benchmark cell), then edited; `snakemake -n`
# must schedule exactly what the edit touches (issue 14). The copy builds its own: a copy
# of the session's small build would not do, since its jobs' inputs (the published tables)
# are the repository's own files, and the copy's are other paths.
SMALL = REPO / "tests" / "data" / "config_small.yaml"
COPIED = ("Snakefile", "config.yaml", "abglib", "workflow", "data", "profiles", "benchmarks")


def _copy_repo(dest: Path) -> Path:
    """What a build needs of the repository (:data:`COPIED`), with abglib's numba cache
    (:func:`tests._repo_copy.copy_repo`)."""
    return copy_repo(dest, COPIED)


def _in_copy(repo: Path, work: Path, *args):
    exe = str(SNAKEMAKE) if SNAKEMAKE.exists() else "snakemake"
    cmd = [exe, "-s", str(repo / "Snakefile"), "-d", str(work), "--configfile", str(SMALL)]
    env = copy_env(repo)
    return subprocess.run([*cmd, *args], capture_output=True, text=True, timeout=600, env=env)


def _scheduled_rules(stdout: str) -> set[str]:
    return {
        line.split()[1].rstrip(":")
        for line in stdout.splitlines()
        if line.strip().startswith(("rule ", "localrule ")) and line.strip().endswith(":")
    }


def _edit(path: Path, old: str, new: str) -> None:
    text = path.read_text(encoding="utf-8")
    assert old in text, f"{old!r} not in {path}"
    path.write_text(text.replace(old, new, 1), encoding="utf-8")


@pytest.mark.pipeline
def test_an_edit_reruns_only_the_jobs_whose_code_it_changes(tmp_path):
    import abglib

    repo, work = _copy_repo(tmp_path / "repo"), tmp_path / "work"
    targets = [
        f"results/reports/v{abglib.__version__}/steelman1978/index.html",
        "results/benchmark/cells/std_ab_a0.3/alwagih_w1.csv",
    ]
    built = _in_copy(repo, work, "-c2", *targets)
    assert built.returncode == 0, built.stdout[-3000:] + built.stderr[-3000:]
    assert (work / "results/steelman1978/comparison.csv").is_file()

    def dry():
        out = _in_copy(repo, work, "-n", *targets)
        assert out.returncode == 0, out.stdout[-3000:] + out.stderr[-3000:]
        return _scheduled_rules(out.stdout)

    assert dry() == set()
    # a docstring and a comment of abglib/analysis: nothing reruns, no benchmark cell
    variance = repo / "abglib" / "analysis" / "_variance.py"
    _edit(variance, '"""Variance reduction factors', '"""Variance-reduction factors')
    _edit(variance, "\nimport ", "\n# an edited comment\nimport ")
    assert dry() == set()
    # one claim's note: that document's claims job and its report, nothing else
    claims = repo / "abglib" / "replications" / "steelman1978" / "claims.py"
    _edit(claims, "as stated in the text", "as the text states it")
    assert dry() == {"steelman1978_claims", "steelman_report"}
    # a real change to abglib/analysis reruns what imports it, the cell included
    _edit(variance, "\nimport ", "\n_EDITED = 1\nimport ")
    rerun = dry()
    assert {"benchmark_cell", "steelman1978_study", "steelman1978_claims"} <= rerun
