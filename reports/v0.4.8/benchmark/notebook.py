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

# %% [markdown]
# # Benchmark matrix: every tracker variant on every dataset scenario
#
# Each *variant* is one entry of `config.yaml` (`benchmark: variants:`) naming a gain-design
# rule of `abglib.bench.variants` and its parameters; each *scenario* is a simulated radar dataset
# (`datasets: scenarios:`, Parquet + manifest, built by the `dataset` rule). The pipeline runs
# every variant on every scenario over the scenario's Monte Carlo runs (one Snakemake job per
# cell) and scores it against the truth. This notebook only reads what those jobs computed.
#
# This is not a replication of a source document: there is no published table to compare
# with, so no `comparison.csv`. Its checks are internal: the measured variance reduction of
# every fixed-gain variant on white noise must agree with the exact (Lyapunov) VRF of
# `abglib.analysis.vrf`, or the build fails.

# %% tags=["parameters"]
# Defaults for interactive use; the pipeline injects the real values after this cell.
doc = "benchmark"
version = "dev"
figures = {f: f"results/benchmark/figures/{f}.png" for f in ("heatmap", "tradeoff")}
tables = {
    t: f"results/benchmark/{t}.csv"
    for t in ("league", "cells", "tradeoff", "tradeoff_curves", "variants", "peers", "engine_speed")
}
provenance = None
made_by = {}
released = None  # file names of the tables copied beside the page (None: all)
notebook = "workflow/notebooks/benchmark.py"
settings = {"rank_by": "rmse_x_pred"}  # config.yaml benchmark.rank_by

# %%
import pandas as pd
from IPython.display import Markdown, display

from abglib.bench import findings
from abglib.common.tables import read_table
from abglib.reporting.notebook import Report

R = Report(doc, figures, tables, made_by, notebook, released=released)

pd.set_option("display.max_colwidth", 120)
pd.set_option("display.precision", 4)
pd.set_option("display.max_columns", 40)
pd.set_option("display.max_rows", 400)
league = R.read("league")
cells = R.read("cells")
variants = R.read("variants")
peers = R.read("peers", reader=read_table)
speed = R.read("engine_speed")
n_var, n_sc = league["variant"].nunique(), league["scenario"].nunique()
runs = sorted(league["runs"].unique().tolist())
display(
    Markdown(
        f"**Matrix:** {n_var} variants × {n_sc} scenarios = {len(league)} cells; Monte Carlo "
        f"runs per cell: {', '.join(map(str, runs))}."
    )
)

# %% [markdown]
# ## 1. Findings
#
# Formatted from the league, trade-off and peers tables by `abglib.bench.findings`.

# %%
metric = settings["rank_by"]  # the league is ranked by it (config.yaml)
# alwagih_M5 has seen the sample it predicts (section 4): not a realisable predictor
lead = findings.leaders(league, metric, exclude=["alwagih_M5"])
ext = findings.tradeoff_extremes(R.read("tradeoff"))
disagree = findings.peer_disagreements(peers)
wins = lead["family"].value_counts()
lines = [
    f"**Who leads.** Ranked by `{metric}` (the non-causal `alwagih_M5` left out), "
    f"{len(wins)} design families share the {len(lead)} scenarios: "
    + "; ".join(f"{fam} leads {n}" for fam, n in wins.items())
    + ". Per scenario, the leader and its margin over the best variant of another family:"
]
for r in lead.itertuples():
    lines.append(
        f"- *{r.scenario}* ({r.noise_colour} noise): `{r.leader}` ({r.family}), {r.value:.3g}, "
        f"{100 * r.margin:.1f} % ahead of `{r.runner_up}` ({r.runner_up_family}, "
        f"{r.runner_up_value:.3g})."
    )
md_lines = "\n".join(lines)
trade = [
    "**Noise against lag** (smoothed position, the variants of the trade-off table). The "
    "least noisy variant pays in lag and the least lagging in noise:"
]
for r in ext.itertuples():
    if r.lag_free:
        trade.append(
            f"- *{r.scenario}*: no lag for any variant (lag below 10⁻⁶ of the noise), so the "
            f"least noisy `{r.quiet}` is also the best ({r.quiet_noise:.3g} RMS)."
        )
        continue
    trade.append(
        f"- *{r.scenario}*: `{r.quiet}` has the least noise ({r.quiet_noise:.3g}) but lags "
        f"{r.quiet_lag:.3g}; `{r.fast}` lags least ({r.fast_lag:.2g}) with {r.fast_noise:.3g} "
        f"of noise; the best total RMSE, {r.best_rmse:.3g}, is `{r.best_rmse_variant}`'s."
    )
peer_lines = ["**What the peers disagree on.**"]
for r in disagree.itertuples():
    if r.disagreements == 0:
        peer_lines.append(f"- {r.peer} agrees with abglib in all {r.comparisons} comparisons.")
    else:
        other_rule = (
            f", and {r.not_comparable} compare a different rule ({r.not_comparable_functions})"
            if r.not_comparable
            else ""
        )
        peer_lines.append(
            f"- {r.peer} disagrees in {r.disagreements} of {r.comparisons} comparisons: the "
            f"independent routes side with abglib in {r.settled_for_abglib}{other_rule} "
            "(section 8)."
        )
display(Markdown(md_lines + "\n\n" + "\n".join(trade) + "\n\n" + "\n".join(peer_lines)))
R.abstract(
    f"Every configured tracker variant on every simulated scenario. Ranked by `{metric}` "
    "(the non-causal `alwagih_M5` left out), "
    + "; ".join(
        f"{r.family} leads on {r.scenario} by {100 * r.margin:.1f} %" for r in lead.itertuples()
    )
    + f". FilterPy disagrees with abglib in {int(disagree['disagreements'].sum())} comparisons,"
    f" {int(disagree['settled_for_abglib'].sum())} of them settled for abglib by independent routes"
    + (
        f"; {int(disagree['not_comparable'].sum())} compare a different rule."
        if int(disagree["not_comparable"].sum())
        else "."
    )
)

# %% [markdown]
# ## 2. How a cell is scored
#
# Per coordinate, after a burn-in of the first samples (the two-point start-up), over all
# runs: the RMSE and maximum absolute error of the smoothed and predicted position
# (`x_smooth`, `x_pred`) and velocity (`v_smooth`, `v_pred`), and the steady-state lag (mean
# error). The `all` rows use the Euclidean error over the coordinates.
#
# **Noise and lag.** The recursion (seed 000, eqs 1–6) is linear in the measurements for every
# initialisation, so `track(z) − truth = track(noise) + (track(truth) − truth)`: a *noise part*,
# computed by tracking the noise itself, and a deterministic *lag part*. Their RMS values are
# the two axes of the trade-off figure.
#
# **Measured VRF.** The mean square of the noise part after the variant's own transient has
# decayed (pole radiusⁿ < 10⁻⁸), divided by σ², against the exact VRF (`abglib.analysis.vrf`
# for white noise; for AR(1) noise the Lyapunov equation of the tracker augmented with the
# noise's shaping filter, `abglib.bench.metrics.coloured_vrf`). Samples within a run are correlated,
# so the confidence interval comes from the spread of the per-run estimates across runs
# (Student t, runs − 1 degrees of freedom), never from the pooled samples. The build check
# uses a simultaneous interval: Bonferroni over every check of the matrix at a family-wise
# error of `benchmark.family_alpha`, so a correct build fails by chance with at most that
# probability; a single 95 % interval per check would fail a correct matrix of hundreds of
# checks almost surely. Cells whose scenarios are too short for the variant to settle, with
# time-varying gains (growing memory) or unstable gains say so (`vrf_check`).

# %% [markdown]
# ## 3. Variants

# %%
display(variants)

# %% [markdown]
# ## 4. League table, per scenario
#
# Ranked by the metric named in `benchmark.rank_by` of `config.yaml` (default
# `rmse_x_pred`: the RMSE of the one-step predicted position, Euclidean over the coordinates,
# after the burn-in; it is the one output every variant has, the seed 001 methods included);
# diverged variants last.
#
# **Reading the seed 001 rows (`alwagih_M1` … `alwagih_M5_causal`).** These are adaptive
# methods, not fixed gains: they have no VRF check, and their error has no exact noise/lag
# split, so those columns are empty. `alwagih_M5` picks, at each step, the bank member whose
# prediction is closest to the *current* measurement, so its "prediction" has already seen the
# sample it predicts; it is not a realisable predictor and its rank is an upper bound.
# `alwagih_M5_causal` makes the same choice from past measurements only, and is the fair
# comparison (see the Al-Wagih report). `vrf_check`: `pass` if every measured VRF of the cell is
# within the simultaneous interval (white noise: the build enforces it), `outside` otherwise
# (reported for coloured noise, where it is not enforced); `vrf_worst_t` is the largest
# standardised deviation.

# %%
cols = [
    "rank",
    "variant",
    "family",
    "rmse_x_smooth",
    "rmse_x_pred",
    "rmse_v_smooth",
    "max_x_smooth",
    "noise_rms_x_smooth",
    "lag_rms_x_smooth",
    "diverged",
    "vrf_check",
    "vrf_worst_t",
]
for sc, d in league.groupby("scenario", sort=False):
    colour = d["noise_colour"].iloc[0]
    display(Markdown(f"### {sc} ({colour} noise)"))
    display(d[cols].reset_index(drop=True))

# %% [markdown]
# ## 5. Heatmap across the matrix

# %%
R.figure(
    "heatmap",
    f"`{metric}` (the league's ranking metric) of every variant divided by the best variant of "
    "each scenario (1 = best); grey `div` cells diverged.",
)

# %% [markdown]
# ## 6. Noise versus lag, per design family
#
# The RMS of the noise part and of the lag part of the smoothed-position error. Each design
# family is swept over its design parameter (`benchmark.tradeoff_families`, table
# `tradeoff_curves.csv`): along a curve lighter smoothing trades lag for noise; a family
# whose curve lies lower-left dominates on that scenario. The configured variants of the
# league table are markers, one shape per variant in its family's colour, named in the legend.
#
# At the heavy-smoothing end (small α, small tracking index, long QD memory) the noise part
# rises again: the two-point start-up takes its velocity from two noisy samples (variance
# 2σ²/T²), and a tracker with a pole radius near 1 carries that start-up error through much
# of the scoring window. It is part of what such a tracker delivers on a track of this
# length, so it is not removed; the measured VRF, in contrast, is taken only after each
# variant's own transient has decayed.

# %%
R.figure(
    "tradeoff",
    "Noise RMS against lag RMS of the smoothed position, each design family swept over its "
    "parameter; crosses: the configured variants.",
)

# %% [markdown]
# ## 7. Measured against exact variance reduction
#
# Every fixed-gain cell with a VRF window: measured VRF of each output, its 95 % interval and
# the exact value. White-noise cells are enforced by the build; AR(1) cells are shown against
# the coloured-noise theory.

# %%
rows = []
per = cells[cells["coord"] != "all"]
for o in ("x_smooth", "x_pred", "v_smooth", "v_pred"):
    sel = per[per[f"vrf_{o}_theory"].notna()]
    for r in sel.itertuples():
        rows.append(
            {
                "variant": r.variant,
                "scenario": r.scenario,
                "coord": r.coord,
                "noise": r.noise_colour,
                "output": o,
                "exact": getattr(r, f"vrf_{o}_theory"),
                "measured": getattr(r, f"vrf_{o}_measured"),
                "lo95": getattr(r, f"vrf_{o}_lo"),
                "hi95": getattr(r, f"vrf_{o}_hi"),
                "t": getattr(r, f"vrf_{o}_t"),
            }
        )
vrf_table = pd.DataFrame(rows)
if len(vrf_table):
    inside = (
        (vrf_table["lo95"] <= vrf_table["exact"]) & (vrf_table["exact"] <= vrf_table["hi95"])
    ).mean()
    display(
        Markdown(
            f"{len(vrf_table)} checks; the exact VRF lies inside the 95 % interval in "
            f"{100 * inside:.1f} % of them (about 95 % expected); largest |t| = "
            f"{vrf_table['t'].abs().max():.2f}."
        )
    )
    display(vrf_table.sort_values("t", key=abs, ascending=False).head(15).reset_index(drop=True))

# %% [markdown]
# ## 8. Peers: FilterPy, scipy.signal, python-control
#
# The same gains through each peer (FilterPy's `k = γ/2`, converted by
# `abglib.conventions.to_filterpy`). A disagreement is settled by independent routes that
# share no code with either side (direct summation of the impulse response, a seeded Monte
# Carlo, python-control's `dlyap`, a simulated track); `supports` names the side they
# confirm and `alternative` evaluates what the peer's formula would have to be to agree
# (`alternative_rel_diff` against abglib).

# %%
agree = peers["agree"].astype(bool)
display(
    Markdown(
        f"**{int(agree.sum())} agreements, {int((~agree).sum())} disagreements** "
        f"(relative tolerance {peers['rel_diff'][agree].max():.1g} reached by the agreements)."
    )
)
display(
    peers.loc[
        ~agree,
        [
            "function",
            "gains",
            "abglib",
            "peer_value",
            "rel_diff",
            "independent_value",
            "supports",
            "alternative_rel_diff",
            "explanation",
        ],
    ].reset_index(drop=True)
)

# %% [markdown]
# All rows, agreements included:

# %%
display(peers[["peer", "function", "gains", "quantity", "rel_diff", "agree", "supports"]])

# %% [markdown]
# ### Speed (wall clock, not reproducible)
#
# `benchmarks/engine_speed.py --quick` run by the pipeline on this machine: samples per second
# and the ratio to FilterPy. These numbers change from run to run and machine to machine;
# they are kept out of every deterministic table.

# %%
if len(speed):
    display(speed[["case", "filter", "implementation", "samples_per_s", "ratio_vs_filterpy"]])
else:
    display(Markdown("Timing disabled (`benchmark.speed.run: false`)."))

# %% [markdown]
# ## Provenance

# %%
if provenance:
    from abglib.reporting.provenance import to_markdown

    display(Markdown(to_markdown(provenance)))
