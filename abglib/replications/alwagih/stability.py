"""Seed 001, section 4: the stability statements of Al-Wagih and Abdulla, as printed.

:func:`stable_alwagih_eq12_14` is the stability triangle of eqs 12-14 (after Llinas et
al.); :func:`eq20_double_pole_gap` and :func:`eq21_22_region` check eq 20 and the "final
stability boundaries" of eqs 21-22 against the exact poles (:func:`abglib.analysis.poles`);
:func:`alpha_above_one_has_negative_root` checks the claim that for ``alpha > 1`` the
roots of eq 15 are never negative; :func:`eq11_response` is the printed transfer function
and :func:`eq23_tradeoff` the smoothing/manoeuvre compromise of section 5.1 along eq 23b.
"""

from __future__ import annotations

import numpy as np

from ..._checks import check_finite, scalar_or_array
from ...analysis import is_stable, poles
from ...gains import Gains

__all__ = [
    "alpha_above_one_has_negative_root",
    "eq11_response",
    "eq23_tradeoff",
    "eq20_double_pole_gap",
    "eq21_22_region",
    "random_gains",
    "stable_alwagih_eq12_14",
]


def stable_alwagih_eq12_14(alpha, beta):
    """Stability triangle of the alpha-beta tracker, seed 001, eqs 12-14, as printed.

    Parameters
    ----------
    alpha, beta : float or array (S...)
        Canonical alpha-beta gains.

    Returns
    -------
    bool or bool array (S...)

    Notes
    -----
    Seed 001, eqs 12-14 (after Llinas et al.): :math:`0 < \\alpha < 2`, :math:`\\beta > 0`,
    :math:`2\\alpha + \\beta < 4`. These are exactly the Jury conditions of the quadratic
    eq 15 (:math:`|1-\\alpha| < 1`, :math:`P(1) = \\beta > 0`,
    :math:`P(-1) = 4 - 2\\alpha - \\beta > 0`), hence necessary and sufficient; eq 12's
    upper bound :math:`\\alpha < 2` is implied by eqs 13-14.
    """
    a = check_finite("alpha", alpha)
    b = check_finite("beta", beta)
    return scalar_or_array((0 < a) & (a < 2) & (b > 0) & (2 * a + b < 4))


def random_gains(seed: int, samples: int):
    """``(alpha, beta)``: uniform random gains on a box around the triangle of eqs 12-14."""
    rng = np.random.default_rng(int(seed))
    a = rng.uniform(-0.2, 2.2, int(samples))
    b = rng.uniform(-0.2, 4.2, a.size)
    return a, b


def eq20_double_pole_gap(alphas, sign: float = -1.0) -> float:
    """Largest distance between the two poles of eq 15 on eq 20,
    ``beta = 2 - alpha +- 2 sqrt(1 - alpha)`` (``sign`` picks the branch): zero where eq 20
    gives the double pole of eq 18."""
    a = np.asarray(alphas, float)
    b = 2.0 - a + sign * 2.0 * np.sqrt(1.0 - a)
    p = np.asarray(poles(Gains(a, b)))
    return float(np.max(np.abs(p[..., 0] - p[..., 1])))


def eq21_22_region(a, b) -> dict:
    """Eqs 21-22 read as a region (``0 < alpha <= 1``, ``0 < beta < 4 - 2 alpha``) against
    the exact stability test: counts of stable gains outside it and unstable inside it."""
    exact = np.asarray(is_stable(Gains(a, b)))
    printed = (a > 0) & (a <= 1) & (b > 0) & (b < 4 - 2 * a)
    return {
        "samples": int(a.size),
        "stable": int(exact.sum()),
        "stable_outside": int((exact & ~printed).sum()),
        "unstable_inside": int((~exact & printed).sum()),
        "example_alpha": float(a[exact & ~printed][0]) if (exact & ~printed).any() else None,
        "example_beta": float(b[exact & ~printed][0]) if (exact & ~printed).any() else None,
    }


def alpha_above_one_has_negative_root(a, b) -> dict:
    """For gains with ``alpha > 1``: how many have a negative real root of eq 15 (the
    product of the roots is ``1 - alpha < 0``, so one root is real and negative)."""
    sel = a > 1
    p = np.asarray(poles(Gains(a[sel], b[sel])))
    real = np.abs(p.imag) < 1e-12
    neg = (real & (p.real < 0)).any(axis=-1)
    return {"samples": int(sel.sum()), "with_negative_root": int(neg.sum())}


def eq11_response(alpha, beta, wT):
    """Eq 11 as printed, ``G(z) = (alpha (z - 1) + beta z) / (z^2 + (alpha + beta - 2) z
    + (1 - alpha))``, on the unit circle ``z = exp(j wT)``."""
    z = np.exp(1j * np.asarray(wT, float))
    return (alpha * (z - 1) + beta * z) / (z**2 + (alpha + beta - 2) * z + (1 - alpha))


def eq23_tradeoff(alphas, dt: float = 1.0, steps: int = 400) -> dict:
    """Along eq 23b (``beta = alpha^2 / (2 - alpha)``): the noise gain of the one-step
    prediction (variance reduction factor, :func:`abglib.analysis.vrf`) and its
    steady-state lag behind a unit constant acceleration (noise-free simulation with
    :func:`abglib.track`), per alpha - section 5.1's compromise between "good noise
    smoothing, i.e. small alpha and beta" and "good maneuver following, i.e. large"."""
    from ...analysis import vrf
    from ...engine import track

    a = np.asarray(alphas, float)
    b = a**2 / (2 - a)
    t = np.arange(steps) * dt
    z = 0.5 * t**2
    lag = np.array(
        [
            float(
                z[-1]
                - track(z, Gains(x, y), dt=dt, init="two_point", outputs=("x_pred",)).x_pred[-1]
            )
            for x, y in zip(a, b, strict=True)
        ]
    )
    return {"alpha": a, "vrf_pred": np.asarray(vrf(Gains(a, b))["x_pred"], float), "lag": lag}
