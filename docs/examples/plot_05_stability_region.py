"""
The stability region
====================

Which gains give a stable tracker? :func:`abglib.analysis.is_stable` decides it exactly
from the poles of the transfer function (all strictly inside the unit circle); for the
alpha-beta tracker the Jury conditions (seed 000, eqs 41-49; seed 001, eqs 12-14) reduce
to the triangle ``0 < alpha < 2``, ``0 < beta < 4 - 2 alpha``. A ``Gains`` bank of arrays
evaluates the whole grid in one call; the largest pole radius shows how fast each tracker
forgets its start.
"""

import matplotlib.pyplot as plt
import numpy as np

import abglib
from abglib import analysis

alpha, beta = np.meshgrid(np.linspace(0.005, 2.2, 221), np.linspace(0.005, 4.5, 226))
bank = abglib.Gains(alpha, beta)
stable = analysis.is_stable(bank)
radius = np.where(stable, analysis.pole_radius(bank), np.nan)
print(f"{stable.mean():.1%} of the grid is stable")

fig, ax = plt.subplots(figsize=(6.5, 5))
im = ax.pcolormesh(alpha, beta, radius, shading="auto", cmap="viridis", vmin=0, vmax=1)
fig.colorbar(im, ax=ax, label="largest pole radius")
ax.plot([0, 2, 0, 0], [0, 0, 4, 0], "r--", lw=1, label="0 < alpha < 2, 0 < beta < 4 - 2 alpha")
ax.set_xlabel("alpha")
ax.set_ylabel("beta")
ax.set_title("alpha-beta trackers: stable gains", fontsize=10)
ax.legend(loc="upper right", fontsize=8)
fig.tight_layout()
plt.show()
