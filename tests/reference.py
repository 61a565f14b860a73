"""Independent reference implementations used by the tests (plain Python, no numba).

Written straight from the printed equations, one sample at a time, so the compiled engine
is checked against the literal recursion and not against itself.
"""

from __future__ import annotations

import numpy as np


def literal_track(z, alpha, beta, gamma=0.0, dt=1.0, state=(0.0, 0.0, 0.0), detected=None):
    """Seed 000, eqs 1-6 for one series; gains and dt may be per-sample sequences.

    Returns arrays ``(x_pred, x_smooth, v_smooth, a_smooth)``.
    """
    z = [float(v) for v in z]
    n = len(z)

    def per_sample(v):
        return list(np.broadcast_to(np.asarray(v, dtype=float), (n,)))

    A, B, G, T = per_sample(alpha), per_sample(beta), per_sample(gamma), per_sample(dt)
    det = [True] * n if detected is None else [bool(d) for d in detected]
    x, v, a = (float(s) for s in state)
    out = np.zeros((4, n))
    for k in range(n):
        # predictor, eqs 4-6
        xnp = x + v * T[k] + 0.5 * a * T[k] ** 2
        vnp = v + a * T[k]
        anp = a
        if det[k]:
            # corrector, eqs 1-3
            resid = z[k] - xnp
            x = xnp + A[k] * resid
            v = vnp + B[k] / T[k] * resid
            a = anp + G[k] / T[k] ** 2 * resid
        else:
            x, v, a = xnp, vnp, anp
        out[:, k] = (xnp, x, v, a)
    return tuple(out)
