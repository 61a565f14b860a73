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
# # The FAA Bendix α-β tracking filter test: a replication
#
# W. Elwell, FAA Technical Center letter report *Bendix Alpha-Beta Tracking Filter Test*, with
# A. I. Sinsky's memo *Expected Smoothing of Alpha-Beta Filter in TCAS Simulation* (seed 003).
# The letter report describes a program that graphs the impulse and ramp responses of the
# Bendix α-β filter for eight gain sets (update periods 1–8 s); only the 48 graph captions
# survive. The memo tabulates the expected standard-deviation reduction of the same gain sets.
# This report re-runs the program, rebuilds the memo's table three ways, and places the gain
# sets in the α-β plane. Everything shown was computed by the pipeline's rules
# (`snakemake -c2`); this notebook only reads and displays it.

# %% tags=["parameters"]
# Defaults for interactive use; the pipeline injects the real values after this cell.
doc = "faa_bendix"
version = "dev"
figures = {f: f"results/faa_bendix/figures/{f}.png" for f in ("impulse", "ramp", "triangle")}
tables = {
    t: f"results/faa_bendix/{t}.csv"
    for t in (
        "comparison",
        "gains",
        "memo_table",
        "rounding",
        "row7",
        "damping_lags",
        "responses",
    )
}
provenance = None

# %%
import pandas as pd
from IPython.display import Image, Markdown, display

from abglib.reporting.compare import non_matches, scorecard

pd.set_option("display.max_colwidth", None)
pd.set_option("display.precision", 5)
pd.set_option("display.max_columns", 40)
comparison = pd.read_csv(tables["comparison"], dtype={"published": str}, keep_default_na=False)
gains = pd.read_csv(tables["gains"])
memo = pd.read_csv(tables["memo_table"])
rounding = pd.read_csv(tables["rounding"])
row7 = pd.read_csv(tables["row7"])
damping = pd.read_csv(tables["damping_lags"])


def verdicts(prefix):
    """Rows of comparison.csv whose item starts with ``prefix``."""
    return comparison[comparison["item"].str.startswith(prefix)][
        ["item", "published", "reproduced", "abs_err", "tolerance", "verdict", "note"]
    ]


# %% [markdown]
# ## Reading guide
#
# **What this report establishes.** The letter report's three difference equations are the
# canonical α-β recursion (seed 000, eqs 1–6 with γ = 0, x_p(k+1) = x̄(k) + T·v̄(k)); a literal
# transcription of them and `abglib.track` agree exactly on all 96 runs. The program states
# no initial values; we start from zero (FORTRAN's zero-initialised variables), i.e.
# `abglib.track(..., init="zero")`. Section 1 shows the six graphs of every gain set as small
# multiples with the captions' y scale factors (SFY), run with the captions' two-digit gains
# (the runs that were plotted) and the memo's three-digit gains; the difference is invisible
# except at T = 1 s, where β = .06 instead of .066 moves the ramp graphs by up to a third of
# an SFY division.
#
# **The memo's columns.** Headed σ_ẋ/σ_x and σ_ẍ/σ_x, they are in fact the *smoothed
# position* ratio σ_x̄/σ_x = √k_x (dimensionless) and the *smoothed velocity* ratio
# σ_v̄/σ_x = √k_v in 1/s with T in seconds (the memo's own example: ".125 × 1° = .125°/sec");
# the dots mean "smoothed", not derivatives of the position error. k_x, k_v are the
# Benedict–Bordner VRFs (section 2).
#
# **What holds.** 15 of the 16 printed ratios and the worked example (0.69°, .125°/s) are
# the closed form for the printed gains to half a unit in the third decimal; the closed form
# equals the Lyapunov solution to rounding error and agrees with a seeded Monte Carlo of 10⁷
# samples per row. The 7 s row, which looks out of trend (0.861/0.158 between 0.820/0.142 and
# 0.872/0.149), is *right for its printed gains*: the kink is in β = .855 itself (the captions
# confirm β = 0.85 was run), not a slip in the ratios (section 3).
#
# **What does not, and why.** The 1 s position ratio is printed .491, the printed gains give
# 0.4916 (1.3 tolerances off). Gains that still print as .250/.066 (α = 0.2495,
# β = 0.0659) reproduce both printed ratios of the row together: the memo was computed from
# unrounded gains (section 2b). "Optimum" cannot be checked: the criterion is in a Bendix
# technical note we do not have. Beyond the source (section 4): all eight gain sets are
# stable and markedly *underdamped* — β is 1.8–2.8 times the Benedict–Bordner β — with zero
# steady-state lag to a ramp and a lag of T²/β (predicted) or (1 − α)T²/β (smoothed) per unit
# acceleration.
#
# The scorecard of this document:

# %%
display(scorecard([comparison]).set_index("doc"))
display(Markdown("Rows that are not a match:"))
display(non_matches(comparison))

# %% [markdown]
# ## 1. The test program: impulse and ramp responses
#
# Input as the letter report writes it: impulse = one sample of 1/T at the first sampling
# (`abglib.simulate.bendix_impulse`); ramp = 0 at the first sampling, raised by T each
# sampling for 10 periods (reaching 10T), then held at zero (`bendix_ramp`); 40 samples.
# Graph order as in the report: smoothed position X(K), smoothed velocity XD(KB), predicted
# position XP(K) (the prediction for sample k made before sample k arrived). The y grid is
# drawn every SFY, the captions' scale factor (0.10 for every impulse graph; 10.00 for the
# ramp graphs, 1.00 at T = 1 s), so that a reader can hold the panels against the originals.
# Solid with dots: the captions' two-digit gains; dashed: the memo's three-digit gains.

# %%
for name in ("impulse", "ramp"):
    display(Markdown(f"**{name} responses**"))
    display(Image(filename=figures[name]))

# %% [markdown]
# ### The gain tables and what their difference does
#
# The captions' gains are the memo's truncated (not rounded) to two digits: .066 → .06,
# .175 → .17, .465 → .46, .565 → .56, .685 → .68, .855 → .85, .665 → .66. `maxdiff_*` is the
# largest difference between the two runs over the 40 samples, `*_sfy` the same in SFY
# divisions.

# %%
display(gains.set_index("period_s").T)

# %% [markdown]
# ## 2. The memo's table
#
# Closed form (Benedict & Bordner; the γ → 0 limit of seed 000, eqs 11–12):
#
# $$k_x = \frac{2\alpha^2 + 2\beta - 3\alpha\beta}{\alpha(4 - 2\alpha - \beta)},\qquad
#   k_v = \frac{2\beta^2}{\alpha(4 - 2\alpha - \beta)\,T^2},$$
#
# printed columns = √k_x and √k_v. Twins: the discrete Lyapunov solution
# (`abglib.analysis.vrf`) and a Monte Carlo — unit white noise on a stationary target through
# `abglib.track`, 500 runs × 20 000 samples per row after a 200-sample burn-in (the seed is in
# the provenance table; each row uses seed + row index). The 95 % CI comes from the spread
# of the per-run variances; `*_mc_z` is the standard score of the Monte Carlo variance
# against the exact one. `velocity_per_sample` = √k_v·T, the per-sample reading of the
# second column, which the printed numbers do not follow (except trivially at T = 1 s).

# %%
cols = ["period_s", "alpha", "beta", "position_published", "position_closed",
        "position_lyapunov", "position_mc", "position_mc_lo", "position_mc_hi", "position_mc_z",
        "velocity_published", "velocity_closed", "velocity_lyapunov", "velocity_mc",
        "velocity_mc_lo", "velocity_mc_hi", "velocity_mc_z", "velocity_per_sample",
        "position_closed_captions", "velocity_closed_captions"]
display(memo[cols])
display(Markdown(
    f"Largest |closed form − Lyapunov|: "
    f"{(memo['position_closed'] - memo['position_lyapunov']).abs().max():.2e} (position), "
    f"{(memo['velocity_closed'] - memo['velocity_lyapunov']).abs().max():.2e} (velocity). "
    f"Monte Carlo samples per row: {int(memo['mc_samples'].iloc[0]):,}."
))
display(verdicts("Memo table"))

# %% [markdown]
# ### What the memo's columns are
#
# The worked example ("for update rate of three seconds, the standard deviation in smoothed
# angle is 0.69 × 1° = .69°. The standard deviation in angle rate is 0.125 × 1° =
# .125°/sec") names the first column the smoothed position and the second a rate per second.
# All eight velocity entries agree with √k_v in 1/s; the per-sample √k_v·T (0.23 … 1.19)
# agrees with none for T ≥ 2 s.

# %%
display(verdicts("Memo example"))
display(verdicts("Memo text"))

# %% [markdown]
# ### 2b. Rounding of the gains
#
# The memo prints the gains to three decimals. For every row, the range of each ratio over
# all gain pairs that print as the memo's (α ± .0005, β ± .0005; Lyapunov, 101 × 101 grid),
# and the pair inside that box that best reproduces *both* printed ratios together (worst
# error in tolerances). Every printed ratio lies inside its range; for the 1 s row, where
# the printed gains give 0.4916 against the printed .491, α = 0.2495, β = 0.0659 gives
# 0.4914 and 0.1006 — both printed ratios within half a unit. The memo's ratios were
# evidently computed from gains with more digits than it prints.

# %%
display(rounding)

# %% [markdown]
# ## 3. The 7 s row
#
# Out of trend on its face: 0.861/0.158 between 0.820/0.142 (6 s) and 0.872/0.149 (8 s).
# Three hypotheses: (a) the ratios are right for the printed gains α = .645, β = .855;
# (b) the gains are on trend and the ratios a slip — α and β interpolated by a cubic in T
# through the other seven periods give β ≈ 0.806, whose ratios would be 0.849/0.147;
# (c) the velocity column was computed for another T (6 s: 0.184; 8 s: 0.138). Only (a)
# reproduces both printed numbers. The kink is in β = .855 (β/β_BB = 2.78 against 2.46 and
# 2.75 on either side, damping ratio ζ = 0.414 below both neighbours), and the plot
# captions (BETA = 0.85 at T = 7 s) show it is the β that was actually run.

# %%
display(row7)

# %% [markdown]
# ## 4. Beyond the source: stability, damping and lags
#
# The poles are the roots of z² − (2 − α − β)z + (1 − α) (seed 000, eq 41). Stability
# triangle: 0 < α < 2, 0 < β < 4 − 2α. Critically damped: β = 2 − α − 2√(1 − α) (seed 001,
# eq 20); Benedict–Bordner: β = α²/(2 − α); between the critical-damping curve and its upper
# twin β = 2 − α + 2√(1 − α) the poles are complex (underdamped). ζ is the damping ratio of
# the continuous system with poles s = ln(z)/T.
#
# Lags (final-value theorem, `abglib.analysis.steady_state_lag`): to a ramp (constant
# velocity) the α-β tracker is type 2 and both smoothed and predicted positions have zero
# steady-state lag; to a constant acceleration A the predicted position lags by A T²/β and
# the smoothed position by (1 − α) A T²/β. The table gives the lags per unit acceleration
# (in m per m/s², i.e. s²) and, as a numeric twin, the error after tracking a ramp and a
# parabola for 2000 samples with `abglib.track`. (The letter report's "ramp" is a finite
# 10-period ramp followed by a drop to zero, so its graphs show transients, not these
# steady states.)

# %%
display(Image(filename=figures["triangle"]))
display(damping)

# %% [markdown]
# ## 5. Every published number and claim
#
# `comparison.csv` (beside this report): tolerance is half a unit in the last printed digit.

# %%
display(comparison)

# %% [markdown]
# ## Provenance
#
# The Monte Carlo seed is the configuration key `faa_bendix.monte_carlo.seed`; it fixes every
# random number in this report.

# %%
if provenance is not None:
    from abglib.reporting.provenance import to_markdown

    display(Markdown(to_markdown(provenance)))

# %% [markdown]
# ## References
#
# 1. W. Elwell, *Bendix Alpha-Beta Tracking Filter Test*, FAA Technical Center letter
#    report, ACT-100J (seed 003).
# 2. A. I. Sinsky, memo to T. Potthast, *Expected Smoothing of Alpha-Beta Filter in TCAS
#    Simulation*, citing Bendix TN BCD-TN-81-033, FB-467-012, June 1981, p. 4 (seed 003).
# 3. T. R. Benedict and G. W. Bordner, "Synthesis of an Optimal Set of Radar Track-While-Scan
#    Smoothing Equations", IRE Trans. Automatic Control, 1962.
# 4. J. E. Steelman, *Frequency Response of α-β-γ Trackers*, 1978 (seed 000): eqs 1–6, 11–12, 41.
# 5. Al-Wagih and Abdulla (seed 001), eq 20: critically damped β.
