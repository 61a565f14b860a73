"""
Frequency response against scipy.signal.freqz
=============================================

:func:`abglib.analysis.transfer_function` gives the z-transform of each output
(seed 000, eqs 36-40) as polynomial coefficients in descending powers of z, and
:func:`abglib.analysis.frequency_response` evaluates it on the unit circle. Here the same
polynomials go through :func:`scipy.signal.freqz`, an independent evaluation, for an
alpha-beta-gamma tracker: the two curves lie on top of each other (the difference is
printed), and the smoothed position shows the passband overshoot that Steelman's Figures 1-6
plot (:func:`abglib.analysis.peak` finds it exactly; the grey line).
"""

import matplotlib.pyplot as plt
import numpy as np
from scipy import signal

from abglib import analysis, design

gains = design.standard_from_alpha(0.5, order=3)
wT = np.linspace(1e-3, np.pi, 400)

fig, ax = plt.subplots(figsize=(7, 4))
for output in ("x_smooth", "x_pred", "v_smooth"):
    h = analysis.frequency_response(gains, output, wT)
    num, den = analysis.transfer_function(gains, output)
    # descending powers of z: pad the numerator so that both have the same length
    b = np.r_[np.zeros(len(den) - len(num)), num]
    _, h_scipy = signal.freqz(b, den, worN=wT)
    print(f"{output:9s} max |abglib - freqz| = {np.max(np.abs(h - h_scipy)):.1e}")
    ax.plot(wT, 20 * np.log10(np.abs(h)), lw=2, label=f"{output} (abglib)")
    ax.plot(wT, 20 * np.log10(np.abs(h_scipy)), "k--", lw=0.8)
ax.plot([], [], "k--", lw=0.8, label="scipy.signal.freqz")
wT_max, overshoot = analysis.peak(gains)
ax.axvline(wT_max, color="0.7", lw=0.8)
ax.set_xlabel("wT (radians per sample)")
ax.set_ylabel("|H| (dB)")
ax.set_title(f"{gains}, peak {overshoot:.2f} at wT = {wT_max:.2f}", fontsize=9)
ax.legend(fontsize=8)
fig.tight_layout()
plt.show()
