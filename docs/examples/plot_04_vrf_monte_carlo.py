"""
VRF by Monte Carlo against the closed form
==========================================

The variance reduction factor (VRF) is the steady-state output variance per unit
measurement variance. :func:`abglib.analysis.vrf` computes it exactly from a discrete
Lyapunov equation; for the critically damped alpha-beta tracker seed 000's eqs 31-32 give
the one-step prediction's VRF in closed form (:func:`abglib.analysis.vrf_standard_ab`,
Morrison's). Here a batch of
noise-only runs through :func:`abglib.track` measures it, with a 95 % interval from the
spread between runs.
"""

import matplotlib.pyplot as plt
import numpy as np

import abglib
from abglib import analysis, design, simulate

runs, n, burn = 200, 400, 150
thetas = np.linspace(0.3, 0.9, 7)
noise = simulate.white_noise((runs, n), 1.0, seed=2)  # zero truth: the output is the error

measured, low, high, closed = [], [], [], []
for theta in thetas:
    gains = design.standard_ab(theta)
    out = abglib.track(noise, gains)
    per_run = np.mean(out.x_pred[:, burn:] ** 2, axis=-1)
    m, s = per_run.mean(), per_run.std(ddof=1) / np.sqrt(runs)
    measured.append(m)
    low.append(m - 1.96 * s)
    high.append(m + 1.96 * s)
    closed.append(analysis.vrf_standard_ab(theta)["x"])  # the one-step prediction
    exact = analysis.vrf(gains)["x_pred"]
    print(
        f"theta {theta:.1f}: Monte Carlo {m:.4f} ± {1.96 * s:.4f}, "
        f"closed form {closed[-1]:.4f}, Lyapunov {exact:.4f}"
    )

fig, ax = plt.subplots(figsize=(7, 4))
ax.fill_between(thetas, low, high, color="C0", alpha=0.25, label="Monte Carlo, 95 %")
ax.plot(thetas, measured, "C0o", ms=4, label="Monte Carlo mean")
ax.plot(thetas, closed, "k-", lw=1, label="closed form (seed 000, eq 31)")
ax.set_xlabel("theta (fading-memory parameter)")
ax.set_ylabel("VRF of the predicted position")
ax.set_yscale("log")
ax.legend()
fig.tight_layout()
plt.show()
