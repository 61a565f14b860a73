"""The FAA Bendix report's prose, its notebook executed on the committed v0.4.5 tables: it says
what its tables say. v0.4.5 wrote that every caption gain "is the memo's *truncated*, not
rounded", a reading its comparison.csv rejects for the 1 s beta, and wrote |closed form −
Lyapunov| read back from the CSV as "0.00e+00", which is not an exact zero."""

from __future__ import annotations

import re

import numpy as np
import pandas as pd
import pytest

from abglib.reporting.execute import execute_notebook
from abglib.reporting.render import inject_parameters

from .conftest import ROOT

jupytext = pytest.importorskip("jupytext")

RELEASE = ROOT / "reports" / "v0.4.5" / "faa_bendix"
TABLES = ("comparison", "gains", "memo_table", "rounding", "row7", "damping_lags",
          "responses", "captions", "robustness")  # fmt: skip
FIGURES = ("impulse", "ramp", "triangle")


@pytest.fixture(scope="module")
def prose() -> str:
    """Every markdown output of the notebook (the abstract included), one paragraph a line."""
    nb = jupytext.read(ROOT / "workflow" / "notebooks" / "faa_bendix.py")
    tables = {t: str(RELEASE / "tables" / f"{t}.csv") for t in TABLES}
    figures = {f: str(RELEASE / "figures" / f"{f}.png") for f in FIGURES}
    inject_parameters(nb, {"tables": tables, "figures": figures})
    execute_notebook(nb, cwd=ROOT)
    return "\n".join(
        " ".join(o["data"]["text/markdown"].split())
        for c in nb.cells
        if c.cell_type == "code"
        for o in c.outputs
        if "text/markdown" in o.get("data", {})
    )


def test_caption_prose_says_what_the_table_says(prose):
    comp = pd.read_csv(RELEASE / "tables" / "comparison.csv", dtype=str, keep_default_na=False)
    gains = comp[comp["item"].str.contains("captions") & comp["item"].str.contains("ALPHA=|BETA=")]
    bad = gains[gains["verdict"] != "match"]
    # the table rejects truncation for the one gain beyond the tie, printed on two captions
    assert len(bad) == 2 and set(bad["verdict"]) == {"mismatch"}
    assert {re.sub(r"^\w+ response captions, ", "", i) for i in bad["item"]} == {
        "T = 1 s, BETA= 0.06"
    }
    chance, budget = re.search(r"at chance (\S+) > budget (\S+)$", bad["note"].iloc[0]).groups()
    assert "*truncated*, not rounded" not in prose
    assert "the captions' gains are the memo's truncated" not in prose.lower()
    assert "one gain printed twice, on the impulse and the ramp captions" in prose
    assert "The captions are consistent with truncation throughout" in prose
    assert f"chance {chance} of reproducing an unrelated number" in prose
    assert f"above its budget {budget}, so its 2 rows stay mismatches" in prose
    assert f"chance {chance} > budget {budget}" in prose  # the abstract and section 1
    # counted by hand from captions.csv: the memo's three decimals (the ramp captions print
    # the same gains as the impulse ones)
    c = pd.read_csv(RELEASE / "tables" / "captions.csv")
    ramp = c[c["input"] == "ramp"]
    thousandths = np.round(np.concatenate([ramp["alpha_memo"], ramp["beta_memo"]]) * 1000)
    values = thousandths.astype(int)
    ties = int(np.sum(values % 10 == 5))
    exact = int(np.sum(values % 10 == 0))
    assert (len(values), exact, ties) == (16, 7, 7)
    assert f"each of the memo's {len(values)} gains is printed as its truncation" in prose
    assert f"— {exact} exact at two decimals" in prose
    assert f"{ties} ending in a half unit, printed low" in prose
    assert "rounding differ beyond the tie, .066 → 0.06 (rounded 0.07)" in prose


def test_closed_form_against_lyapunov_is_a_bound(prose):
    # both columns written to 10 significant digits (values in 0.1-1): equal as written,
    # so the exact difference (round-off) is below one unit in the 10th decimal
    assert "0.00e+00" not in prose
    assert "Largest |closed form − Lyapunov|: < 1e-10 (position), < 1e-10 (velocity)" in prose
