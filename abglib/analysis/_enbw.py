r"""Equivalent noise bandwidth (ENBW) of the predicted-position transfer function.

Huang et al. (seed 002) characterise a tracker by the ENBW ``B_n`` of its closed loop
``H(z) = X_p / X`` (their eqs 3, 6; seed 000, eq 39). With the impulse response
``h_k`` of ``H``,

.. math:: B_n = \frac{1}{2T}\sum_{k \ge 0} h_k^2
              = \int_0^{1/(2T)} |H(e^{j 2\pi f T})|^2\, df
              = \frac{\mathrm{VRF}_{x_p}}{2T}\ \text{Hz},

the *one-sided* bandwidth (noise power passed, per unit two-sided noise density, over
``0 <= f <= 1/(2T)``). This is the bandwidth of seed 002, eq 14 and eqs 9-13; the first
expression of eq 8, ``(1/2pi) int |H|^2 d omega`` over the whole band, is the
*two-sided* one, twice as large.

Routes: :func:`enbw` (exact, Lyapunov) and :func:`enbw_numeric` (quadrature of ``|H|^2``
over frequency, or summed impulse response). Huang et al.'s printed closed forms (eq 14,
and eqs 8-13 reconstructed from the garbled scan) live with their document, in
:mod:`abglib.replications.huang.printed`.
"""

from __future__ import annotations

import numpy as np

from .._checks import AbglibValueError, scalar_or_array
from ..engine import track
from ..gains import Gains
from ._stability import check_n_max, require_stable, summation_length
from ._variance import _broadcast, vrf

__all__ = ["enbw", "enbw_numeric"]

_UNSTABLE = "noise bandwidth is unbounded"


def enbw(gains: Gains, dt=1.0):
    r"""One-sided equivalent noise bandwidth in Hz of the predicted position, exact.

    Parameters
    ----------
    gains : Gains
        Canonical gains, scalar or a bank ``(...)``; stable.
    dt : float or array (...), default 1.0
        Sample interval ``T`` > 0 (seconds).

    Returns
    -------
    float or array (...)
        ``B_n`` in Hz.

    Notes
    -----
    .. math:: B_n = \frac{1}{2T}\sum_k h_k^2 = \frac{\mathrm{VRF}_{x_p}}{2T},

    ``h_k`` the impulse response of ``X_p/X`` (seed 000, eq 39; seed 002, eq 3) and the
    VRF from the discrete Lyapunov equation (:func:`abglib.analysis.vrf`). This is the
    one-sided bandwidth of seed 002, eq 14 (which it equals exactly for alpha-beta).

    References
    ----------
    Huang, Yang & Ma, seed 002 (``huang``), eq 8 (definition) and eq 14 (alpha-beta); Steelman
    (1978), seed 000 (``steelman1978``), eq 39 (the predicted position's transfer function).

    Examples
    --------
    >>> round(enbw(Gains(0.5, 0.2), dt=0.1), 6)
    3.571429
    """
    a, b, g, T = _broadcast(gains, dt)
    require_stable(Gains(a, b, g), _UNSTABLE)
    return scalar_or_array(np.asarray(vrf(Gains(a, b, g), T)["x_pred"]) / (2.0 * T))


# --------------------------------------------------------------------------- numeric
def _hp(alpha: float, beta: float, gamma: float, wT: np.ndarray) -> np.ndarray:
    """``X_p/X`` at ``z = e^{j wT}``, written out from seed 000, eqs 39-40."""
    z = np.exp(1j * wT)
    u = z - 1.0
    num = (alpha + beta + gamma / 2.0) * u * u + (beta + 1.5 * gamma) * u + gamma  # eq 39
    den = u**3 + alpha * u * u + (beta + gamma / 2.0) * z * u + gamma * z  # eq 40
    return num / den


def _integral_one(alpha: float, beta: float, gamma: float) -> float:
    """``(1/pi) int_0^pi |H|^2 d(wT)`` (= sum h_k^2) by adaptive quadrature."""
    import scipy.integrate  # here, as _kalman does: the design rules' callers need no scipy

    def f(x):
        return float(np.abs(_hp(alpha, beta, gamma, np.asarray(x))) ** 2)

    # the passband and resonance sit near wT ~ sqrt(beta); split the range there
    edges = np.unique(np.concatenate([[0.0, np.pi], np.geomspace(1e-5, np.pi, 41)]))
    total = 0.0
    for lo, hi in zip(edges[:-1], edges[1:], strict=True):
        val, _ = scipy.integrate.quad(f, lo, hi, limit=200, epsabs=0.0, epsrel=1e-12)
        total += val
    return total / np.pi


def _impulse_one(alpha: float, beta: float, gamma: float, n_max: int) -> float:
    """``sum h_k^2`` from :func:`abglib.track` on a unit impulse."""
    n = summation_length(
        alpha, beta, gamma, n_max, "enbw_numeric(method='impulse')", "enbw (the exact route)"
    )
    z = np.zeros(n)
    z[0] = 1.0
    h = track(z, Gains(alpha, beta, gamma)).x_pred
    # x_pred[k] is predicted before z[k] arrives: the response to z[0] starts at k = 1
    return float(np.sum(h[1:] ** 2))


def enbw_numeric(gains: Gains, dt=1.0, method="integral", n_max=2_000_000):
    r"""One-sided ENBW in Hz by a numeric route independent of :func:`enbw`.

    Parameters
    ----------
    gains : Gains
        Canonical gains, scalar or a bank ``(...)``; stable.
    dt : float or array (...), default 1.0
        Sample interval ``T`` > 0.
    method : {"integral", "impulse"}, default "integral"
        ``"integral"``: adaptive quadrature (:func:`scipy.integrate.quad`) of
        ``|H(e^{j omega T})|^2``, ``H`` evaluated from the polynomials of seed 000,
        eqs 39-40. ``"impulse"``: sum of the squared impulse response of
        :func:`abglib.track`'s ``x_pred``.
    n_max : int, default 2_000_000
        ``"impulse"``: the longest response summed (the length follows from the pole
        radius); gains that need more raise instead of filling the memory.

    Returns
    -------
    float or array (...)
        ``B_n`` in Hz.

    Notes
    -----
    .. math:: B_n = \frac{1}{2\pi}\int_0^{\pi/T} |H(e^{j\omega T})|^2\, d\omega
              = \frac{1}{2T}\sum_{k \ge 1} h_k^2 .

    References
    ----------
    Huang, Yang & Ma, seed 002 (``huang``), eq 8: the integral of ``|H|^2``, summed;
    Steelman (1978), seed 000 (``steelman1978``), eq 39.
    """
    methods = ("integral", "impulse")
    if method not in methods:
        raise AbglibValueError(
            f"method must be one of {', '.join(map(repr, methods))}, got {method!r}"
        )
    a, b, g, T = _broadcast(gains, dt)
    require_stable(Gains(a, b, g), _UNSTABLE)
    n_max = check_n_max(n_max)
    out = np.empty(a.shape)
    for idx in np.ndindex(a.shape):
        al, be, ga = float(a[idx]), float(b[idx]), float(g[idx])
        s = _integral_one(al, be, ga) if method == "integral" else _impulse_one(al, be, ga, n_max)
        out[idx] = s / (2.0 * float(T[idx]))
    return scalar_or_array(out)
