# ---
# jupyter:
#   jupytext:
#     text_representation:
#       extension: .py
#       format_name: percent
#   kernelspec:
#     display_name: Python 3
#     language: python
#     name: python3
# ---

# The generic report of a source document that has no notebook of its own
# (docs/new-document.md): its verdicts, its figures, its study's tables and every published
# number against the reproduced one. A document replaces it with a `report.py` in its folder
# `abglib/replications/<doc>/`. The page's title is the document's (document.yaml), shown
# by the first cell below.

# %% tags=["parameters"]
# Defaults for interactive use; the pipeline injects the real values after this cell.
doc = "demo"
version = "dev"
figures = {}
tables = {"comparison": "results/demo/comparison.csv"}
provenance = None
made_by = {}
released = None  # file names of the tables copied beside the page (None: all)
notebook = "workflow/notebooks/document.py"
settings = {"title": "demo"}

# %%
import pandas as pd
from IPython.display import Markdown, display

from abglib.reporting.notebook import Report

R = Report(doc, figures, tables, made_by, notebook, released=released)
title = settings.get("title") or doc

pd.set_option("display.max_colwidth", None)
pd.set_option("display.max_columns", 40)
comparison = R.read("comparison", dtype={"published": str}, keep_default_na=False)
counts = comparison["verdict"].value_counts()
display(Markdown(f"# {title}: a replication"))

# %%
summary = ", ".join(f"{int(n)} {verdict}" for verdict, n in counts.items())
R.abstract(
    f"{len(comparison)} published numbers and claims of the document, judged against the "
    f"pipeline's reproduction: {summary}."
)

# %% [markdown]
# ## Figures

# %%
for key in figures:
    R.figure(key, f"Figure `{key}` of the study (`figures.py`, `figure({key!r}, tables)`).")

# %% [markdown]
# ## The study's tables

# %%
for key in tables:
    if key not in ("comparison", "robustness"):
        R.table(R.read(key), caption=f"Table `{key}` of the study.")

# %% [markdown]
# ## Every published number and claim
#
# `comparison.csv` (beside this report): the tolerance is half a unit in the last printed
# digit unless the configuration says otherwise; `depends_on` names the assumed inputs a
# row depends on and `robust` whether its verdict holds across their plausible ranges.

# %%
R.table(comparison, caption="Published against reproduced, one row per claim.")

# %% [markdown]
# ## Provenance

# %%
if provenance is not None:
    from abglib.reporting.provenance import to_markdown

    display(Markdown(to_markdown(provenance)))
