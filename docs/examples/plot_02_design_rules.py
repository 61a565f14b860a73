"""
Compare the design rules
========================

Four ways to choose the other gains for a given ``alpha``: the critically damped
"standard" alpha-beta gains (seed 000, before eq 31), Benedict-Bordner's relation
beta = alpha^2 / (2 - alpha) (seed 001, eq 23b; method M1), Kalata's steady-state Kalman
gains (parametrised by the tracking index) and the QD tracker of seed 000, eqs 28-30 (an
alpha-beta-gamma tracker: its gamma is not drawn).
Each rule is one point per alpha on the noise-versus-transient trade-off: the variance
reduction factor of the smoothed position against the summed squared error of its
response to a unit ramp (seed 000, eq 15: ``transient_d2``), both exact.
"""

import matplotlib.pyplot as plt
import numpy as np

from abglib import analysis, design

alphas = np.linspace(0.1, 0.8, 15)
rules = {
    "standard (critically damped)": lambda a: design.standard_from_alpha(a, order=2),
    "Benedict-Bordner": design.benedict_bordner,
    "QD (seed 000, eqs 28-30)": lambda a: design.qd(design.qd_m_from_alpha(a)),
}

fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(9, 4))
for label, rule in rules.items():
    gains = [rule(a) for a in alphas]
    betas = [float(g.beta) for g in gains]
    noise = [analysis.vrf(g)["x_smooth"] for g in gains]
    lag = [analysis.transient_d2(g)["x"] for g in gains]
    ax1.plot(alphas, betas, "o-", ms=3, label=label)
    ax2.loglog(noise, lag, "o-", ms=3, label=label)

# Kalata: sweep the tracking index instead of alpha
gains = [design.kalata_ab(lam) for lam in np.geomspace(0.01, 3.0, 15)]
ax1.plot([g.alpha for g in gains], [g.beta for g in gains], "s-", ms=3, label="Kalata")
ax2.loglog(
    [analysis.vrf(g)["x_smooth"] for g in gains],
    [analysis.transient_d2(g)["x"] for g in gains],
    "s-",
    ms=3,
    label="Kalata",
)
ax1.set_xlabel("alpha")
ax1.set_ylabel("beta")
ax1.set_xlim(0.05, 0.85)
ax1.set_ylim(0, 0.6)
ax1.legend(fontsize=8)
ax2.set_xlabel("VRF of the smoothed position")
ax2.set_ylabel("ramp transient D^2 (seed 000, eq 15)")
fig.tight_layout()
plt.show()
