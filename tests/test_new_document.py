"""A sixth source document, added with only a folder, its data and a config entry
(issue 23, item 5; docs/new-document.md): in a copy of the repository, a minimal document
(one printed table, three claims, one figure) gets its study, claims, figure and report
from the workflow's generic rules (workflow/rules/documents.smk), and nothing else runs.

The document: the steady-state position variance reduction factor (VRF) of the
Benedict-Bordner alpha-beta tracker, beta = alpha^2 / (2 - alpha), at three alphas.
The expected verdicts come from the closed form of that VRF (Kalata 1984, eq. 28;
Benedict and Bordner 1962), computed here independently of abglib.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
from itertools import pairwise
from pathlib import Path

import pytest

from ._repo_copy import copy_env, copy_repo

pytestmark = pytest.mark.pipeline

REPO = Path(__file__).resolve().parents[1]
SNAKEMAKE = Path(sys.executable).parent / "snakemake"
ALPHAS = (0.2, 0.5, 0.8)

# ---------------------------------------------------------------- the new document
DOCUMENT_YAML = """\
# what the workflow needs of this document before any job runs (docs/new-document.md)
title: "Demo: the α-β tracker's position variance reduction"
tables: [vrf]
figures: [vrf]
"""

INIT = '''\
"""A demonstration document: the Benedict-Bordner alpha-beta tracker's position VRF."""
'''

STUDY = '''\
"""The demo document's study: abglib.analysis.vrf of the Benedict-Bordner alpha-beta
tracker (beta = alpha^2 / (2 - alpha)) at the alphas of its config section."""

from functools import cached_property

import pandas as pd

from abglib import Gains
from abglib.analysis import vrf
from abglib.replications import Study


class DemoStudy(Study):
    doc = "demo"

    @cached_property
    def vrf(self) -> pd.DataFrame:
        rows = []
        for a in self.cfg["alphas"]:
            b = a * a / (2.0 - a)
            rows.append({"alpha": a, "beta": b, "x_smooth": vrf(Gains(a, b))["x_smooth"]})
        return pd.DataFrame(rows)

    def x_smooth(self, alpha: float) -> float:
        return float(self.vrf.set_index("alpha").loc[alpha, "x_smooth"])

    def tables(self):
        return {"vrf": self.vrf}
'''

CLAIMS = '''\
"""The demo document's claims: its printed VRFs and one statement."""

from abglib.replications import ClaimSet, Result

from .study import DemoStudy

CLAIMS = ClaimSet("demo")
STUDY = DemoStudy


@CLAIMS.family(r"vrf\\.a0\\.\\d+")
def _(s, key):
    alpha = float(key.split(".a", 1)[1])
    x = s.x_smooth(alpha)
    return Result(x, f"abglib.analysis.vrf at alpha = {alpha}: {x:.6f}")


@CLAIMS.claim("vrf.falls_with_alpha")
def _(s):
    x = list(s.vrf.sort_values("alpha")["x_smooth"])
    note = "x_smooth at increasing alpha: " + ", ".join(f"{v:.4f}" for v in x)
    return Result(all(a < b for a, b in zip(x, x[1:])), note)
'''

FIGURES = '''\
"""The demo document's one figure."""


def figure(name, tables):
    import matplotlib.pyplot as plt

    t = tables["vrf"]
    fig, ax = plt.subplots(figsize=(5, 3))
    ax.plot(t["alpha"], t["x_smooth"], marker="o")
    ax.set_xlabel("alpha")
    ax.set_ylabel("position VRF")
    return fig, "Position variance reduction factor of the alpha-beta tracker against alpha"
'''

# the printed table: 0.412 is the VRF at alpha = 0.5 rounded (a match), 0.19 at
# alpha = 0.2 is not (the closed form gives 0.1553: a mismatch)
PUBLISHED = """\
# The demo document's printed numbers, as printed
key,item,quantity,published,where
vrf.a0.5,"Table 1, alpha = 0.5",position variance reduction factor (dimensionless),0.412,Table 1
vrf.a0.2,"Table 1, alpha = 0.2",position variance reduction factor (dimensionless),0.19,Table 1
vrf.falls_with_alpha,Text,claim: the variance reduction falls as alpha falls,,p. 1
"""


def closed_form_vrf(alpha: float) -> float:
    """Position VRF of the alpha-beta tracker (Kalata 1984, eq. 28):
    (2 alpha^2 + 2 beta - 3 alpha beta) / (alpha (4 - 2 alpha - beta)),
    here with the Benedict-Bordner beta = alpha^2 / (2 - alpha)."""
    beta = alpha * alpha / (2.0 - alpha)
    return (2 * alpha**2 + 2 * beta - 3 * alpha * beta) / (alpha * (4 - 2 * alpha - beta))


def expected_verdict(printed: str, value: float) -> str:
    """Half a unit in the last printed digit (shared/CONTRACTS.md section 3)."""
    decimals = len(printed.split(".")[1])
    return "match" if abs(value - float(printed)) <= 0.5 * 10.0**-decimals else "mismatch"


# ---------------------------------------------------------------- the copy
# (tests._repo_copy.copy_repo: the repository's files without the release reports, with
# abglib's numba cache)


def _add_document(repo: Path, docs_entry: str = "demo") -> None:
    """What docs/new-document.md asks for: a folder, its data, a config entry."""
    folder = repo / "abglib" / "replications" / "demo"
    folder.mkdir()
    for name, text in (
        ("document.yaml", DOCUMENT_YAML),
        ("__init__.py", INIT),
        ("study.py", STUDY),
        ("claims.py", CLAIMS),
        ("figures.py", FIGURES),
    ):
        (folder / name).write_text(text, encoding="utf-8")
    data = repo / "data" / "published" / "demo"
    data.mkdir(parents=True)
    (data / "table1.csv").write_text(PUBLISHED, encoding="utf-8")
    config = repo / "config.yaml"
    text = config.read_text(encoding="utf-8")
    docs = re.search(r"^docs:\n(?:  - \w+\n)+", text, re.M)
    assert docs, "config.yaml has no docs: list"
    text = text[: docs.end()] + f"  - {docs_entry}\n" + text[docs.end() :]
    alphas = ", ".join(map(str, ALPHAS))
    text += "\n# an added document's own section (docs/new-document.md)\ndocuments:\n"
    text += f"  demo:\n    alphas: [{alphas}]\n"
    config.write_text(text, encoding="utf-8")


def _snakemake(repo: Path, *args, timeout=600):
    exe = str(SNAKEMAKE) if SNAKEMAKE.exists() else "snakemake"
    # the copy's abglib (with the new folder) first, for the parse and for every job
    env = copy_env(
        repo, PYTHONPATH=os.pathsep.join(p for p in (str(repo), os.environ.get("PYTHONPATH")) if p)
    )
    return subprocess.run(
        [exe, "-s", str(repo / "Snakefile"), "-d", str(repo), *args],
        capture_output=True,
        text=True,
        timeout=timeout,
        env=env,
    )


def test_a_sixth_document_builds_its_report_and_comparison(tmp_path):
    import pandas as pd

    import abglib

    repo = copy_repo(tmp_path / "repo")
    _add_document(repo)
    report = f"results/reports/v{abglib.__version__}/demo/index.html"
    targets = [report, "results/demo/comparison.csv"]

    built = _snakemake(repo, "-c2", *targets)
    assert built.returncode == 0, built.stdout[-3000:] + built.stderr[-3000:]
    ran = {
        line.split()[1].rstrip(":")
        for line in (built.stdout + built.stderr).splitlines()
        if line.strip().startswith(("rule ", "localrule ")) and line.strip().endswith(":")
    }
    # that document's four jobs and nothing of the five others
    assert ran == {"demo_study", "demo_claims", "demo_figures", "demo_report"}

    # the study's table against the closed form
    vrf = pd.read_csv(repo / "results/demo/vrf.csv")
    assert list(vrf["alpha"]) == list(ALPHAS)
    for a, x in zip(vrf["alpha"], vrf["x_smooth"], strict=True):
        assert x == pytest.approx(closed_form_vrf(a), rel=1e-9)

    # every printed row judged, with the verdict the closed form implies
    cmp = pd.read_csv(repo / "results/demo/comparison.csv", dtype=str, keep_default_na=False)
    assert list(cmp.columns[:3]) == ["doc", "item", "quantity"]
    assert set(cmp["doc"]) == {"demo"} and len(cmp) == 3
    rows = cmp.set_index("item")
    for item, printed, alpha in (
        ("Table 1, alpha = 0.5", "0.412", 0.5),
        ("Table 1, alpha = 0.2", "0.19", 0.2),
    ):
        row = rows.loc[item]
        assert row["published"] == printed
        assert float(row["reproduced"]) == pytest.approx(closed_form_vrf(alpha), rel=1e-9)
        assert row["verdict"] == expected_verdict(printed, closed_form_vrf(alpha))
    assert rows.loc["Table 1, alpha = 0.5", "verdict"] == "match"
    assert rows.loc["Table 1, alpha = 0.2", "verdict"] == "mismatch"
    # the statement: the closed form rises with alpha on (0, 1), so it holds
    assert all(closed_form_vrf(a) < closed_form_vrf(b) for a, b in pairwise(ALPHAS))
    assert rows.loc["Text", "reproduced"] == "True" and rows.loc["Text", "verdict"] == "match"

    # the report: the generic notebook, with the document's title and its figure
    page = (repo / report).read_text(encoding="utf-8")
    assert "<h1>Demo: the α-β tracker" in page
    assert 'src="figures/vrf.png"' in page
    png = repo / report.replace("index.html", "figures/vrf.png")
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert (repo / report.replace("index.html", "tables/comparison.csv")).is_file()
    assert (repo / report.replace("index.html", "tables/vrf.csv")).is_file()


def test_a_document_without_a_folder_is_named(tmp_path):
    """A key in docs with neither a built-in rule set nor a folder with a document.yaml
    stops the parse with a message naming it and what a document is."""
    repo = copy_repo(tmp_path / "repo")
    config = repo / "config.yaml"
    text = config.read_text(encoding="utf-8")
    config.write_text(
        text.replace("  - antenna\n", "  - antenna\n  - nosuch\n", 1), encoding="utf-8"
    )
    out = _snakemake(repo, "-n", "--quiet", "all", timeout=300)
    assert out.returncode != 0
    msg = out.stdout + out.stderr
    assert "config docs lists 'nosuch', which is no document" in msg
    assert "abglib/replications/<doc>/" in msg and "document.yaml" in msg
