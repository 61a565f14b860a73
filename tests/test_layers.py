"""The layers: the tracker core installs and runs with numpy, scipy and numba only.

``pip install abglib`` must not bring pandas, matplotlib, the replications or the report
machinery (issue 12). Two routes: an import blocker in a subprocess (fast, every run) and
a real ``pip install .`` into a fresh virtual environment (marked ``install``).
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
import tomllib
import venv
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]

# what a user of the core does: track, design, analyse, convert, simulate, M1-M5
CORE_USE = """
import numpy as np
import abglib
from abglib import analysis, conventions, design, methods, simulate
g = design.standard_from_alpha(0.3, order=3)
out = abglib.track(np.cumsum(np.ones(50)), g, dt=0.1)
assert out.x_pred.shape == (50,)
h = abglib.track(np.r_[1.0, np.zeros(3000)], g).x_smooth  # impulse response: VRF = sum h^2
assert abs(np.sum(h**2) - analysis.vrf(g)["x_smooth"]) < 1e-9
assert analysis.is_stable(g)
conventions.to_filterpy(g)
methods.m1(np.cumsum(np.ones((2, 30)), axis=-1), 0.4, 1.0)
simulate.white_noise(10, 1.0, np.random.default_rng(0))
print("core ok")
"""

BLOCKED = ("pandas", "matplotlib", "pyarrow", "snakemake", "jupytext", "nbclient", "yaml")

BLOCKER = f"""
import sys
class _Block:
    def find_spec(self, name, path=None, target=None):
        if name.split(".")[0] in {BLOCKED!r}:
            raise ImportError(f"the tracker core must not import {{name}}")
        return None
sys.meta_path.insert(0, _Block())
"""


def test_core_dependencies_are_numpy_scipy_numba():
    meta = tomllib.loads((REPO / "pyproject.toml").read_text())["project"]
    names = {d.split(">")[0].split("=")[0].split("[")[0].strip() for d in meta["dependencies"]}
    assert names == {"numpy", "scipy", "numba"}
    extras = meta["optional-dependencies"]
    for layer in ("bench", "replications", "reporting"):
        assert any(d.startswith("pandas") for d in extras[layer]), layer


def test_core_runs_without_pandas_or_matplotlib():
    env = dict(os.environ, PYTHONPATH=str(REPO))
    out = subprocess.run(
        [sys.executable, "-c", BLOCKER + CORE_USE],
        capture_output=True,
        text=True,
        env=env,
        cwd=REPO,
        timeout=300,
    )
    assert out.returncode == 0, out.stderr[-2000:]
    assert "core ok" in out.stdout


def test_layers_import_only_downwards():
    """The core never imports a layer above it (bench, replications, reporting)."""
    layers = ("bench", "replications", "reporting")
    names = "|".join(layers)
    upward = re.compile(
        rf"^\s*(from\s+(abglib\.|\.+)({names})\b|import\s+abglib\.({names})\b"
        rf"|from\s+(abglib|\.+)\s+import\s+.*\b({names})\b)",
        re.M,
    )
    core = [
        p
        for p in (REPO / "abglib").rglob("*.py")
        if p.relative_to(REPO / "abglib").parts[0] not in layers
    ]
    assert len(core) > 10
    offenders = [str(p) for p in core if upward.search(p.read_text(encoding="utf-8"))]
    assert not offenders, f"core modules import an upper layer: {offenders}"
    # the pattern does catch an upward import
    assert upward.search("    from ..reporting.compare import x")
    assert upward.search("from .. import design, replications")


@pytest.mark.install
def test_pip_install_into_a_fresh_venv_brings_no_pandas(tmp_path):
    env_dir = tmp_path / "venv"
    venv.create(env_dir, with_pip=True)
    py = env_dir / "bin" / "python"
    pip = subprocess.run(
        [str(py), "-m", "pip", "install", "--quiet", "--disable-pip-version-check", str(REPO)],
        capture_output=True,
        text=True,
        timeout=900,
    )
    assert pip.returncode == 0, pip.stderr[-3000:]
    listed = subprocess.run(
        [str(py), "-m", "pip", "list", "--format=freeze"], capture_output=True, text=True
    ).stdout.lower()
    for name in ("pandas", "matplotlib", "snakemake", "pyarrow"):
        assert f"\n{name}==" not in "\n" + listed, f"pip install . brought {name}"
    # run from an empty folder so that the installed package, not the checkout, is imported
    run = subprocess.run(
        [str(py), "-c", CORE_USE], capture_output=True, text=True, cwd=tmp_path, timeout=300
    )
    assert run.returncode == 0, run.stderr[-2000:]
    assert "core ok" in run.stdout
