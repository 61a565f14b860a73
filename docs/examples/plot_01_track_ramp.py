"""
Track a noisy ramp
==================

A target at constant speed, measured with white noise, tracked by a critically damped
alpha-beta tracker (``design.standard_from_alpha``: seed 000, the alpha-beta gains
before eq 31). On a ramp the
alpha-beta tracker has no steady-state lag: once the start-up transient has decayed, the
smoothed position is unbiased and only its noise is left, at the variance reduction factor
of :func:`abglib.analysis.vrf`.
"""

import matplotlib.pyplot as plt
import numpy as np

import abglib
from abglib import analysis, design, simulate

dt, n, sigma = 1.0, 120, 5.0
t = simulate.sample_times(n, dt)
truth = simulate.polynomial_track(t, x0=0.0, v0=20.0)
# 200 noisy runs of the same track (batch axes first, time last); the plot shows the first
z_runs = truth + simulate.white_noise((200, n), sigma, seed=1)

gains = design.standard_from_alpha(0.3, order=2)
runs = abglib.track(z_runs, gains, dt=dt, init="two_point")

settled = slice(40, None)
rms = np.sqrt(np.mean((runs.x_smooth[:, settled] - truth[settled]) ** 2))
theory = sigma * np.sqrt(analysis.vrf(gains, dt)["x_smooth"])
print(f"{gains}")
print(f"rms error after sample 40 over 200 runs: {rms:.2f} m (from the VRF: {theory:.2f} m)")

z, out = z_runs[0], abglib.track(z_runs[0], gains, dt=dt, init="two_point")

fig, (ax1, ax2) = plt.subplots(2, 1, sharex=True, figsize=(7, 5))
ax1.plot(t, z, ".", ms=3, color="0.6", label="measurements")
ax1.plot(t, truth, "k-", lw=1, label="truth")
ax1.plot(t, out.x_smooth, "C0-", lw=1.2, label="smoothed position")
ax1.set_ylabel("position (m)")
ax1.legend(loc="upper left")
ax2.plot(t, z - truth, ".", ms=3, color="0.6")
ax2.plot(t, out.x_smooth - truth, "C0-", lw=1.2)
ax2.axhspan(-theory, theory, color="C0", alpha=0.15, label="±1 sigma from the VRF")
ax2.set_xlabel("time (s)")
ax2.set_ylabel("error (m)")
ax2.legend(loc="upper right")
fig.tight_layout()
plt.show()
