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

Routes: :func:`enbw` (exact, Lyapunov), :func:`enbw_numeric` (quadrature of ``|H|^2``
over frequency, or summed impulse response), and the printed closed forms
:func:`enbw_huang_eq14` (alpha-beta) and :func:`enbw_huang_eq8_13` (alpha-beta-gamma,
reconstructed from the garbled scan).
"""

from __future__ import annotations

import numpy as np
import scipy.integrate

from .._checks import AbglibValueError, check_finite, check_positive, scalar_or_array
from ..conventions import from_huang
from ..engine import track
from ..gains import Gains
from ._stability import pole_radius, require_stable
from ._variance import _broadcast, vrf

__all__ = ["enbw", "enbw_huang_eq8_13", "enbw_huang_eq14", "enbw_numeric"]

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

    def f(x):
        return float(np.abs(_hp(alpha, beta, gamma, np.asarray(x))) ** 2)

    # the passband and resonance sit near wT ~ sqrt(beta); split the range there
    edges = np.unique(np.concatenate([[0.0, np.pi], np.geomspace(1e-5, np.pi, 41)]))
    total = 0.0
    for lo, hi in zip(edges[:-1], edges[1:], strict=True):
        val, _ = scipy.integrate.quad(f, lo, hi, limit=200, epsabs=0.0, epsrel=1e-12)
        total += val
    return total / np.pi


def _impulse_one(alpha: float, beta: float, gamma: float) -> float:
    """``sum h_k^2`` from :func:`abglib.track` on a unit impulse."""
    r = pole_radius(Gains(alpha, beta, gamma))
    n = 64 if r < 1e-3 else int(np.ceil(2.0 * np.log(1e-20) / np.log(r))) + 64
    z = np.zeros(n)
    z[0] = 1.0
    h = track(z, Gains(alpha, beta, gamma)).x_pred
    # x_pred[k] is predicted before z[k] arrives: the response to z[0] starts at k = 1
    return float(np.sum(h[1:] ** 2))


def enbw_numeric(gains: Gains, dt=1.0, method="integral"):
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

    Returns
    -------
    float or array (...)
        ``B_n`` in Hz.

    Notes
    -----
    .. math:: B_n = \frac{1}{2\pi}\int_0^{\pi/T} |H(e^{j\omega T})|^2\, d\omega
              = \frac{1}{2T}\sum_{k \ge 1} h_k^2 .
    """
    methods = ("integral", "impulse")
    if method not in methods:
        raise AbglibValueError(
            f"method must be one of {', '.join(map(repr, methods))}, got {method!r}"
        )
    a, b, g, T = _broadcast(gains, dt)
    require_stable(Gains(a, b, g), _UNSTABLE)
    one = _integral_one if method == "integral" else _impulse_one
    out = np.empty(a.shape)
    for idx in np.ndindex(a.shape):
        out[idx] = one(float(a[idx]), float(b[idx]), float(g[idx])) / (2.0 * float(T[idx]))
    return scalar_or_array(out)


# --------------------------------------------------------------------------- printed
def _huang_stable(alpha_h, beta_h, gamma_h):
    """Stability check of gains given in Huang's convention (canonical gamma = 2 gamma_H)."""
    g = from_huang(alpha_h, beta_h, gamma_h)
    require_stable(g, _UNSTABLE)


def enbw_huang_eq14(alpha, beta, dt):
    r"""Huang et al.'s alpha-beta ENBW in Hz, as printed (seed 002, eq 14).

    Parameters
    ----------
    alpha, beta : float or array (...)
        Alpha-beta gains (the same in every convention); stable.
    dt : float or array (...)
        Sample interval ``T`` > 0.

    Returns
    -------
    float or array (...)
        ``B_n`` in Hz.

    Notes
    -----
    Seed 002, eq 14:

    .. math:: B_n = \frac{2\beta + \alpha\beta + 2\alpha^2}{2T(4\alpha - 2\alpha^2 - \alpha\beta)}

    It is exactly the one-sided :func:`enbw`, i.e. the Benedict-Bordner prediction VRF
    divided by ``2T``.
    """
    a = check_finite("alpha", alpha)
    b = check_finite("beta", beta)
    T = check_positive("dt", dt)
    _huang_stable(a, b, 0.0)
    return scalar_or_array(
        (2.0 * b + a * b + 2.0 * a * a) / (2.0 * T * (4.0 * a - 2.0 * a * a - a * b))
    )


def _huang_k(a, b, g):
    """Seed 002, eq 10-11 coefficients K0..K5 (Huang's gamma)."""
    K5 = (4.0 - 2.0 * a - b) ** 2
    K0 = (2.0 * a + b) ** 2
    K1 = b * b + g * g - 4.0 * a * g
    K2 = g * g
    K3 = (4.0 * a * a + 4.0 * a * b + 2.0 * b * b - 4.0 * a * g + g * g - 8.0 * b) / K5
    K4 = (b * b - 4.0 * a * g + 2.0 * g * g) / K5
    return K0, K1, K2, K3, K4, K5


def _eq13_one(a: float, b: float, g: float) -> float:
    """``2 T K5 B_n`` from the (reconstructed) table integral of eq 13."""
    K0, K1, K2, K3, K4, K5 = _huang_k(a, b, g)
    c = g / np.sqrt(K5)  # sqrt of the denominator constant K2 / K5
    # a_h^2 = K3 + 2 b_h, b_h^2 = K4 + 2 a_h c: with b_h = (a_h^2 - K3)/2 a quartic in a_h
    roots = np.roots([0.25, 0.0, -0.5 * K3, -2.0 * c, 0.25 * K3 * K3 - K4])
    for r in roots:
        if abs(r.imag) > 1e-9 * max(1.0, abs(r.real)):
            continue
        ah = r.real
        bh = 0.5 * (ah * ah - K3)
        if ah > 0.0 and bh > 0.0 and ah * bh > c:  # Hurwitz: the stable spectral factor
            ch = ah * bh - c  # eq 13: a b = sqrt(K2) + c
            # eq 13 with the sqrt(K2) of the denominator restored and divided out:
            # (K0 sqrt(K2) b + K1 sqrt(K2) + K2 a) / (sqrt(K2) c)
            ratio = g * np.sqrt(K5) if g != 0.0 else 0.0  # K2 / sqrt(K2 / K5)
            return (K0 * bh + K1 + ratio * ah) / ch
    raise AbglibValueError(  # pragma: no cover - stable gains always have the factor
        f"no Hurwitz factor found for Huang gains ({a!r}, {b!r}, {g!r})"
    )


def _eq11_12_one(a: float, b: float, g: float) -> float:
    """``2 T K5 B_n`` from the partial fractions of eqs 11-12."""
    K0, K1, K2, K3, K4, K5 = _huang_k(a, b, g)
    if K2 == 0.0:
        # alpha-beta: u^2 cancels, (K0 s + K1) / (s^2 + K3 s + K4) = sum A / (s + B)
        num, den = [K0, K1], [1.0, K3, K4]
    else:
        # (K0 s^2 + K1 s + K2) / (s^3 + K3 s^2 + K4 s + K2/K5), s = u^2
        num, den = [K0, K1, K2], [1.0, K3, K4, K2 / K5]
    Bs = -np.roots(den).astype(complex)  # the factors are (s + B), (s + D), (s + F)
    gap = min(abs(Bs[i] - Bs[j]) for i in range(len(Bs)) for j in range(i))
    if not gap > 1e-9 * max(1.0, float(np.max(np.abs(Bs)))):
        raise AbglibValueError(
            "the partial fractions of seed 002, eqs 11-12 need distinct roots B, D, F; "
            f"Huang gains (alpha={a!r}, beta={b!r}, gamma={g!r}) give repeated ones "
            "(use method='eq13')"
        )
    total = 0.0 + 0.0j
    for i, Bi in enumerate(Bs):
        # eq 12: residue of num/den at s = -B (A, C, E)
        others = np.prod([Bj - Bi for j, Bj in enumerate(Bs) if j != i])
        Ai = np.polyval(num, -Bi) / others
        total += Ai / np.sqrt(Bi)  # int_0^inf du / (u^2 + B) = pi / (2 sqrt(B))
    return float(total.real)


def enbw_huang_eq8_13(alpha_h, beta_h, gamma_h, dt, method="eq13"):
    r"""Huang et al.'s alpha-beta-gamma ENBW in Hz, reconstructed (seed 002, eqs 8-13).

    Parameters
    ----------
    alpha_h, beta_h, gamma_h : float or array (...)
        Gains in Huang's convention (``gamma_h`` is half the canonical gamma); stable.
    dt : float or array (...)
        Sample interval ``T`` > 0.
    method : {"eq13", "eq11_12"}, default "eq13"
        ``"eq13"``: the table-integral result of eq 13; ``"eq11_12"``: the partial
        fractions of eqs 11-12 (they need distinct roots: repeated ones raise
        ``ValueError``, and nearly repeated ones, e.g. the standard gains whose three
        poles coincide, cost digits: about ``eps^(1/3)`` relative).

    Returns
    -------
    float or array (...)
        One-sided ``B_n`` in Hz.

    Notes
    -----
    The bilinear map ``z = (1+w)/(1-w)``, ``w = ju`` (eqs 8-9) turns the integral into
    (eq 10, with the coefficients ``K0..K5`` of eq 11 as printed)

    .. math::
        B_n = \frac{1}{\pi T K_5}\int_0^\infty
              \frac{K_0 u^4 + K_1 u^2 + K_2}{u^6 + K_3 u^4 + K_4 u^2 + K_2/K_5}\, du,

    ``K0 = (2a+b)^2``, ``K1 = b^2 + g^2 - 4ag``, ``K2 = g^2``,
    ``K3 = (4a^2 + 4ab + 2b^2 - 4ag + g^2 - 8b)/K5``, ``K4 = (b^2 - 4ag + 2g^2)/K5``,
    ``K5 = (4 - 2a - b)^2``. Reconstruction (the scan garbles eqs 10, 11 and 13):

    1. The constant of the denominator is ``K2/K5 = g^2/(4-2a-b)^2``; eqs 11-12 print
       ``K2`` (checked against ``|D(ju)|^2`` of eq 3).
    2. Eq 11's bracket is ``A/sqrt(B) + C/sqrt(D) + E/sqrt(F)`` (the integrals
       ``int_0^inf du/(u^2+B) = pi/(2 sqrt B)``), with ``-B, -D, -F`` the roots in
       ``s = u^2`` of ``s^3 + K3 s^2 + K4 s + K2/K5`` and ``A, C, E`` of eq 12.
    3. Eq 13 is the standard table integral for a Hurwitz factor
       ``u^6 + K3 u^4 + K4 u^2 + K2/K5 = |(ju)^3 + a (ju)^2 + b (ju) + c'|^2``,
       ``c' = sqrt(K2/K5)``, ``b^2 = K4 + 2 a c'``, ``a^2 = K3 + 2b``,
       ``c = ab - c'`` (``a, b, c > 0``):

       .. math:: B_n = \frac{1}{2 T K_5}\,
                 \frac{K_0 c' b + K_1 c' + K_2 a}{c' \, c}

       (the printed fraction lacks the ``c' = sqrt(K2)`` under ``c``).

    The result is the one-sided :func:`enbw` of ``Gains(alpha_h, beta_h,
    2 gamma_h)`` and reduces to eq 14 at ``gamma_h = 0``. The factor in front of eq 9
    (``1/(2 pi T)`` instead of ``1/(pi T)`` from ``z^{-1}dz = 2dw/(1-w^2)``) halves the
    two-sided integral of eq 8: eq 8 is two-sided, eqs 9-14 one-sided.
    """
    methods = ("eq13", "eq11_12")
    if method not in methods:
        raise AbglibValueError(
            f"method must be one of {', '.join(map(repr, methods))}, got {method!r}"
        )
    ah = check_finite("alpha_h", alpha_h)
    bh = check_finite("beta_h", beta_h)
    gh = check_finite("gamma_h", gamma_h)
    T = check_positive("dt", dt)
    try:
        ah, bh, gh, T = np.broadcast_arrays(ah, bh, gh, T)
    except ValueError:
        raise AbglibValueError(
            "alpha_h, beta_h, gamma_h and dt must broadcast together, got shapes "
            f"{ah.shape}, {bh.shape}, {gh.shape}, {T.shape}"
        ) from None
    _huang_stable(ah, bh, gh)
    one = _eq13_one if method == "eq13" else _eq11_12_one
    out = np.empty(ah.shape)
    for idx in np.ndindex(ah.shape):
        a, b, g = float(ah[idx]), float(bh[idx]), float(gh[idx])
        out[idx] = one(a, b, g) / (2.0 * float(T[idx]) * (4.0 - 2.0 * a - b) ** 2)
    return scalar_or_array(out)
