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
# # Steelman 1978, *Frequency Response of α-β-γ Trackers*: a replication
#
# J. E. Steelman, US Army White Sands Missile Range, Technical Report STEWS-ID-78-3,
# September 1978 (seed 000). This report regenerates the report's Figures 1–6, Tables 1–5 and
# its design example with `abglib`, and checks every numbered equation that makes a numeric
# claim against an exact route. Everything shown here was computed by the pipeline's rules
# (`snakemake -c2`); this notebook only reads and displays it.

# %% tags=["parameters"]
# Defaults for interactive use; the pipeline injects the real values after this cell.
doc = "steelman1978"
version = "dev"
figures = {f"fig{i}": f"results/steelman1978/figures/fig{i}.png" for i in range(1, 7)}
tables = {
    t: f"results/steelman1978/{t}.csv"
    for t in ("comparison", "gains", "design_example", "tables345", "equations", "stability")
}
provenance = None

# %%
import pandas as pd
from IPython.display import Image, Markdown, display

from abglib.reporting.compare import non_matches, scorecard

pd.set_option("display.max_colwidth", None)
pd.set_option("display.precision", 6)
comparison = pd.read_csv(tables["comparison"], dtype={"published": str}, keep_default_na=False)
equations = pd.read_csv(tables["equations"])
stability = pd.read_csv(tables["stability"])
gains = pd.read_csv(tables["gains"])
design_example = pd.read_csv(tables["design_example"])
t345 = pd.read_csv(tables["tables345"])


def verdicts(prefix):
    """Rows of comparison.csv whose item starts with ``prefix``."""
    return comparison[comparison["item"].str.startswith(prefix)][
        ["item", "published", "reproduced", "abs_err", "tolerance", "verdict", "note"]
    ]


# %% [markdown]
# ## Reading guide
#
# **What this report establishes.** The α-β-γ recursion of eqs 1–6, its transfer functions
# (eqs 36–39) and hence every frequency-response figure are reproduced exactly: the
# transfer functions agree with the DFT of the impulse response of the simulated tracker to
# rounding error (section 5). The gains of Tables 1 and 2 and the exact overshoots of Table 4
# are the standard (critically damped) and QD designs as the text defines them (the QD
# column was computed from the unrounded m = 16.563, not the printed 16.6). Table 5's exact
# peak frequency holds at α = .1; at α = .3 the printed 0.13325 misses the exact 0.1332450
# by 3.5e-8 more than half a unit of its last digit — agreement to five significant digits,
# but we do not rescue it by guessing how the author rounded, so it stays a mismatch.
#
# **What holds.** Simpson's variance and transient measures (eqs 11–20) are exact for the
# smoothed outputs; eqs 22–24 put all three poles at z = θ (critically damped); eqs 50 and
# 51 are exact; the stability conditions 45–48 are necessary and sufficient and eq 49 is
# sufficient (section 6).
#
# **What does not, and why.** Morrison's variance factors as quoted in eqs 25–26 and 31 are
# those of the one-step *prediction* `x_pred`, not of the smoothed output the text defines
# (section 5). The design example's numbers follow from a
# graph reading, ωT = .135, which is 0.7 % above the exact −3 dB frequency; the later steps
# are right arithmetic on the printed inputs (section 3). The approximations 53–55 are only
# approximations: Tables 3–5 show by how much. The "exact" −6 dB frequencies of Table 3, two
# of the eq 55 overshoots of Table 4 and both α = .488 entries of Table 5 are not reproduced
# by any reading we tried (section 4); the printed "exact" −6 dB values sit 2 % low in ωT
# (at −5.85 to −5.94 dB), consistent with readings off the lost Fig. 2. The phase of X_p/X is not monotone as the text says:
# it first rises a little (a phase lead of the predictor at low ωT) before it falls
# (Fig. 3; the claim's row below gives the size).
#
# The scorecard of this document:

# %%
display(scorecard([comparison]).set_index("doc"))
display(Markdown("Rows that are not a match:"))
display(non_matches(comparison))

# %% [markdown]
# ## 1. Figures 1–6
#
# The responses are those of eqs 36–39 with z = e^{jωT} (`abglib.analysis.frequency_response`),
# for the gains the figure captions and Tables 1–2 name. The scanned figures are lost (only
# captions remain), so these plots are regenerated from the text's description; the Bode plots
# show magnitude in dB against log ωT, the dashed line marks −3 dB (1/√2 on Fig. 1).
# Fig. 4's caption is damaged in the scan ("X̄/X, 7VT, and 200T²Ā/X"); we read the middle
# term as T·V̄/X and plot it too.

# %%
for name in sorted(figures):
    display(Markdown(f"**{name}**"))
    display(Image(filename=figures[name]))

# %% [markdown]
# ## 2. Tables 1 and 2: the gains of Figures 5 and 6
#
# Standard α-β-γ: eqs 22–24 with θ = (1 − α)^{1/3}; standard α-β: α = 1 − θ², β = (1 − θ)²;
# QD: eqs 28–30. "The m required to produce α = .3 is 16.6": the exact root of eq 28 is
# m = 16.5633, and the printed QD β and γ of Table 1 are those of that m (with m = 16.6
# exactly, β = 0.0361 and γ = 0.00218). Table 2's QD column is m = 21 (α = 0.24582, printed
# .246); its standard columns are computed at α = .246.

# %%
display(gains)
display(verdicts("Table 1").pipe(lambda d: pd.concat([d, verdicts("text after Table 1")])))
display(verdicts("Table 2"))

# %% [markdown]
# ## 3. The design example
#
# Standard α-β-γ tracker with α = .1 that must pass 5 Hz (p. 8). The paper reads the −3 dB
# frequency off Fig. 2 (ωT = .135) and continues by arithmetic. Below, the same steps twice:
# from our exact −3 dB frequency, and with the printed inputs. The printed T = .0043 s,
# ωT = 1.62 at 60 Hz, ω = 1452/s and f = 231 Hz are the printed arithmetic; the attenuation
# at 60 Hz (about 23 dB) and the offset d = .04 of the first undesired maximum hold on either
# route. The sample rate "235 times per second" follows from neither route.

# %%
display(design_example.set_index("route").T)
display(verdicts("p. 8 design example"))

# %% [markdown]
# ## 4. Tables 3–5: analytical expressions
#
# Table 3 compares eq 53 (with −.3 in the exponent, i.e. the −6 dB point) with the exact
# −6 dB frequency; Table 4 the overshoot of eq 55 (eqs 56–59) with the exact one; Table 5 the
# ωT_max of eq 54 with the exact one (`abglib.analysis.peak`, `omega_at_gain`). The column
# `wT_half_exact` is the frequency where |X̄/X| = 0.5 (−6.02 dB), a reading tried for the
# "exact" row of Table 3.

# %%
display(t345)
display(verdicts("Table 3"))
display(verdicts("Table 4"))
display(verdicts("Table 5"))

# %% [markdown]
# ## 5. Equations: table of agreement
#
# Every printed closed form is evaluated as printed and compared with an exact route:
# the discrete Lyapunov equation for variances (`abglib.analysis.vrf`), direct summation
# for the transient measures, the characteristic polynomial for eqs 22–24 and 41, the DFT
# of the simulated impulse response (`abglib.track`) for eqs 36–39, and the exact
# frequency-domain features for eqs 50–59. `holds` applies to forms the paper presents as
# exact (relative agreement within the configured tolerance); approximations show their
# worst relative error. `matches` names the exact quantity a printed form equals. Eq 21
# (Simpson's optimality condition) and eqs 28–30 (the QD definition, ref. 5) are
# definitions, not checkable claims.

# %%
summary = (
    equations.groupby(["equation", "quantity", "claimed"], sort=False)
    .agg(
        cases=("case", "count"),
        worst_rel_diff=("rel_diff", "max"),
        holds=("holds", lambda s: "" if s.isna().all() else bool(s.astype(bool).all())),
        matches=("matches", lambda s: ", ".join(sorted({x for x in s.dropna() if x}))),
    )
    .reset_index()
)
display(summary)

# %% [markdown]
# Per gain set (all rows):

# %%
display(equations)

# %% [markdown]
# ## 6. Stability criteria
#
# Random gain sets (the seed is in the provenance table) drawn from the configured box;
# the printed criteria (`abglib.analysis.stable_jury_steelman`, `stable_sufficient_eq49`)
# against the poles (`abglib.analysis.is_stable`), and the implications the text states
# after eq 48.

# %%
display(stability)
display(verdicts("eqs"))

# %% [markdown]
# ## 7. Every published number and claim
#
# `comparison.csv` (beside this report): tolerance is half a unit in the last printed digit
# unless the note says otherwise.

# %%
display(comparison)

# %% [markdown]
# ## Provenance

# %%
if provenance is not None:
    from abglib.reporting.provenance import to_markdown

    display(Markdown(to_markdown(provenance)))

# %% [markdown]
# ## References
#
# 1. J. E. Steelman, *Frequency Response of α-β-γ Trackers*, Technical Report
#    STEWS-ID-78-3, US Army White Sands Missile Range, 1978 (seed 000).
# 2. H. R. Simpson, "Performance Measures and Optimization Condition for a Third Order
#    Sampled Data Tracker", IEEE Trans. Automatic Control, April 1963 (Steelman's ref. 1).
# 3. N. Morrison, *Introduction to Sequential Smoothing and Prediction*, McGraw-Hill, 1969
#    (Steelman's refs. 3–4).
