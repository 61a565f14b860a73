"""The workflow itself: Snakemake's linter finds nothing, a dry run parses."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
SNAKEMAKE = Path(sys.executable).parent / "snakemake"


def _run(*args):
    exe = str(SNAKEMAKE) if SNAKEMAKE.exists() else "snakemake"
    return subprocess.run([exe, *args], capture_output=True, text=True, cwd=REPO, timeout=300)


def test_snakemake_lint_is_clean():
    out = _run("--lint")
    assert out.returncode == 0, out.stdout[-3000:] + out.stderr[-3000:]
    assert "Congratulations" in out.stdout + out.stderr


def test_dry_run_writes_nothing_under_reports():
    """A plain build's every output lies outside the committed release reports/."""
    listing = _run("-n", "--forceall")
    assert listing.returncode == 0, listing.stderr[-3000:]
    outputs = [
        line.split(":", 1)[1].strip()
        for line in listing.stdout.splitlines()
        if line.strip().startswith("output:")
    ]
    assert outputs, "the dry run listed no outputs"
    written = [f for line in outputs for f in line.split(", ")]
    assert not [f for f in written if f.startswith("reports/")], written[:5]
    assert any(f.startswith("results/reports/v") for f in written)
