"""The layers: the tracker core installs and runs with numpy, scipy and numba only, and
every module of ``abglib`` imports only its own layer or the ones below it.

``pip install abglib`` must not bring pandas, matplotlib, the replications or the report
machinery (issue 12). Two routes: an import blocker in a subprocess (fast, every run) and
a real ``pip install .`` into a fresh virtual environment (marked ``install``). The order
of the layers is the one line of ``docs/architecture.md`` that declares it; the whole
import graph (every module, every import statement at any depth) is checked against it
(issue 23).
"""

from __future__ import annotations

import ast
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


# --------------------------------------------------------------------------- the import graph
#: the package's layers and their folders; every other module of ``abglib`` is the core
LAYER_PACKAGES = ("common", "bench", "replications", "reporting")
#: how docs/architecture.md declares the order (the one statement this test reads)
ORDER_LINE = re.compile(r"^Layers, lowest first: `([a-z_ <]+)`", re.M)


def declared_order() -> tuple[str, ...]:
    """The layers, lowest first, as ``docs/architecture.md`` declares them."""
    found = ORDER_LINE.findall((REPO / "docs" / "architecture.md").read_text(encoding="utf-8"))
    assert len(found) == 1, "docs/architecture.md must declare the order once"
    return tuple(part.strip() for part in found[0].split("<"))


def module_name(path: Path, root: Path) -> str:
    """``abglib/bench/peers.py`` -> ``abglib.bench.peers``; a package is its ``__init__``."""
    parts = list(path.relative_to(root.parent).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def import_edges(root: Path) -> dict[str, list[tuple[int, str]]]:
    """Every module of the package at ``root`` and what it imports from the package:
    ``{module: [(line, imported module), ...]}``.

    Every ``import`` and ``from ... import`` statement counts, at any depth (inside
    functions, ``if TYPE_CHECKING:``, ``try:``); a relative import is resolved against the
    module's package, and ``from X import name`` imports ``X.name`` when that is a
    module of the package (``from .. import design``), else ``X``. A name that is no
    module of the package (a stale import after a move) is reported as its own target so
    that the check below fails on it."""
    pkg = root.name
    files = sorted(root.rglob("*.py"))
    modules = {module_name(p, root): p for p in files}
    edges: dict[str, list[tuple[int, str]]] = {}
    for mod, path in modules.items():
        here = mod if path.name == "__init__.py" else mod.rpartition(".")[0]
        out = edges.setdefault(mod, [])
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"), str(path))):
            if isinstance(node, ast.Import):
                targets = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom):
                if node.level:
                    base = here.split(".")[: len(here.split(".")) - (node.level - 1)]
                    src = ".".join(base + ([node.module] if node.module else []))
                else:
                    src = node.module or ""
                targets = [
                    f"{src}.{a.name}" if f"{src}.{a.name}" in modules else src for a in node.names
                ]
            else:
                continue
            for t in targets:
                if t == pkg or t.startswith(pkg + "."):
                    out.append((node.lineno, t))
    return edges


def layer_of(module: str) -> str:
    parts = module.split(".")
    return parts[1] if len(parts) > 1 and parts[1] in LAYER_PACKAGES else "core"


def violations(root: Path, order: tuple[str, ...], edges=None) -> list[str]:
    """Each import of ``root``'s package that goes to a layer above the importer's, or to
    a module the package does not have, as ``'module:line -> target (why)'``; ``edges``:
    ``import_edges(root)`` where the caller has it already."""
    rank = {name: i for i, name in enumerate(order)}
    edges = import_edges(root) if edges is None else edges
    bad = []
    for mod, imports in edges.items():
        for line, target in imports:
            known = target in edges or any(m.startswith(target + ".") for m in edges)
            if not known:
                bad.append(f"{mod}:{line} -> {target} (no such module)")
            elif rank[layer_of(target)] > rank[layer_of(mod)]:
                bad.append(f"{mod}:{line} -> {target} ({layer_of(mod)} imports {layer_of(target)})")
    return bad


def test_the_declared_order_names_every_layer():
    order = declared_order()
    assert order == ("core", "common", "bench", "replications", "reporting", "workflow")
    assert set(order) == {"core", *LAYER_PACKAGES, "workflow"}
    for name in LAYER_PACKAGES:  # each layer is a package of its own
        assert (REPO / "abglib" / name / "__init__.py").is_file(), name


def test_every_module_imports_only_its_own_layer_or_lower():
    """The whole import graph of ``abglib`` against the order of docs/architecture.md."""
    root = REPO / "abglib"
    edges = import_edges(root)
    # every .py file under abglib/ is checked, none twice, none missed
    assert set(edges) == {module_name(p, root) for p in root.rglob("*.py")}
    assert len(edges) == len(list(root.rglob("*.py"))) > 100
    assert sum(map(len, edges.values())) > 500  # it does see the graph
    # the layers this test is about do import each other, downwards
    seen = {(layer_of(m), layer_of(t)) for m, imports in edges.items() for _, t in imports}
    assert {("bench", "common"), ("replications", "bench"), ("reporting", "bench")} <= seen
    bad = violations(root, declared_order()[:-1], edges)
    assert not bad, "imports against the layers of docs/architecture.md:\n" + "\n".join(bad)


def test_the_check_catches_an_upward_import(tmp_path):
    """A synthetic package: upward imports at module level, inside a function, relative
    and absolute, and a stale one, are each found with their line; downward ones are not."""
    files = {
        "__init__.py": "from .gains import Gains\n",
        "gains.py": "import numpy as np\n\n\ndef f():\n    from .reporting.cli import main\n",
        "design.py": "from . import gains\nfrom . import bench\n",
        "common/__init__.py": "",
        "common/tables.py": "from ..gains import Gains\n",
        "bench/__init__.py": "",
        "bench/cell.py": (
            "from ..common.tables import x\n"
            "try:\n    from abglib.replications import compare\nexcept ImportError:\n    pass\n"
        ),
        "replications/__init__.py": "from ..bench import cell\nfrom .gone import y\n",
        "reporting/__init__.py": "",
        "reporting/cli.py": "import abglib.replications\nfrom ..common import tables\n",
    }
    root = tmp_path / "abglib"
    for rel, text in files.items():
        (root / rel).parent.mkdir(parents=True, exist_ok=True)
        (root / rel).write_text(text)
    order = ("core", "common", "bench", "replications", "reporting")
    assert sorted(violations(root, order)) == [
        "abglib.bench.cell:3 -> abglib.replications (bench imports replications)",
        "abglib.design:2 -> abglib.bench (core imports bench)",
        "abglib.gains:5 -> abglib.reporting.cli (core imports reporting)",
        "abglib.replications:2 -> abglib.replications.gone (no such module)",
    ]
    # the same package under a stricter order (replications below bench) fails elsewhere
    swapped = ("core", "common", "replications", "bench", "reporting")
    assert "abglib.replications:1 -> abglib.bench.cell (replications imports bench)" in (
        violations(root, swapped)
    )


def test_the_core_imports_no_extra_even_inside_functions():
    """No core module imports pandas, matplotlib, ... at any depth (the subprocess test
    above sees only what a run imports); ``abglib._compat`` imports its library lazily,
    only when a layer above calls it."""
    root = REPO / "abglib"
    bad = []
    for p in root.rglob("*.py"):
        mod = module_name(p, root)
        if layer_of(mod) != "core" or mod.startswith("abglib._compat"):
            continue
        for node in ast.walk(ast.parse(p.read_text(encoding="utf-8"))):
            names = (
                [a.name for a in node.names]
                if isinstance(node, ast.Import)
                else [node.module or ""]
                if isinstance(node, ast.ImportFrom) and not node.level
                else []
            )
            bad += [f"{mod}:{node.lineno} {n}" for n in names if n.split(".")[0] in BLOCKED]
    assert not bad, bad


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
