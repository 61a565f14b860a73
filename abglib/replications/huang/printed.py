r"""The printed forms of Huang, Yang and Ma (seed 002), each as printed and, where the scan
garbles it, reconstructed; the tests compare each with abglib's exact analysis.

Huang et al. write the acceleration gain as ``gamma_H = gamma / 2`` (their eqs 1, 3-4):
every function taking ``*_h`` gains takes them in that convention (no conversion here;
see :mod:`abglib.conventions`).

``run_eqs_1_2``                 the loop of eqs 1-2, transcribed literally
``transfer_function_huang``     eqs 3 and 6 (closed loop ``H(z)``)
``transfer_function_huang_eq3`` eq 3 at any ``gamma_H`` (also ``gamma_H = 0``)
``stable_huang_eq5``            eq 5 (alpha-beta-gamma stability, "Routh")
``stable_huang_eq7``            eq 7 (alpha-beta stability)
``enbw_eq8_two_sided``          the first form of eq 8 (whole band), by quadrature
``enbw_huang_eq8_13``           eqs 8-13 reconstructed (alpha-beta-gamma ENBW)
``enbw_huang_eq13_as_printed``  eq 13 read literally
``enbw_huang_eq14``             eq 14 (alpha-beta ENBW)
``steady_state_lag_huang``      "Tracking errors": A/(beta F_r^2), B/(gamma F_r^3)
``thermal_sigma``               "Tracking errors": the thermal-noise range error
``bandwidth_for_sigma``         its inverse (the ENBW at a given error)
``measurement_sigma``           the per-pulse noise that makes the printed error exact
``C_LIGHT``                     speed of light (m/s)
"""

from __future__ import annotations

import numpy as np
import scipy.integrate

from ..._checks import AbglibValueError, check_finite, check_positive, scalar_or_array
from ...analysis import require_stable
from ...analysis._transfer import _w_forms
from ...conventions import from_huang
from ...gains import Gains

__all__ = [
    "C_LIGHT",
    "bandwidth_for_sigma",
    "enbw_eq8_two_sided",
    "enbw_huang_eq8_13",
    "enbw_huang_eq13_as_printed",
    "enbw_huang_eq14",
    "measurement_sigma",
    "run_eqs_1_2",
    "stable_huang_eq5",
    "stable_huang_eq7",
    "steady_state_lag_huang",
    "thermal_sigma",
    "transfer_function_huang",
    "transfer_function_huang_eq3",
]

#: Speed of light in vacuum, m/s (the paper's "c is light velocity").
C_LIGHT = 299_792_458.0
_FORMS = ("printed", "barton")
_UNSTABLE = "noise bandwidth is unbounded"
_KINDS = ("acceleration", "jerk")


# --------------------------------------------------------------------------- eqs 1-7
def run_eqs_1_2(z, alpha_h, beta_h, gamma_h, dt, half=True) -> np.ndarray:
    r"""The loop of seed 002, eqs 1-2, transcribed literally; returns ``R_p`` (array (n,)).

    Parameters
    ----------
    z : array (n,)
        Measured ranges ``R_m(kT)``.
    alpha_h, beta_h, gamma_h : float
        Gains in Huang's convention.
    dt : float
        ``T``.
    half : bool, default True
        True: predict with ``T^2 R''_s / 2`` (what eqs 3-4 assume); False: with
        ``T^2 R''_s`` exactly as eq 2 prints it.

    Notes
    -----
    Eq 1: ``R_s = R_p + alpha r``, ``R'_s = R'_p + (beta/T) r``,
    ``R''_s = R''_p + (2 gamma_H / T^2) r``, ``r = R_m - R_p``. Eq 2:
    ``R_p = R_s + T R'_s + c T^2 R''_s`` (``c = 1/2`` or 1), ``R'_p = R'_s + T R''_s``
    (eq 2 prints ``T R'_s``, a dimensional slip), ``R''_p = R''_s``. State zero before
    the first sample.
    """
    z = check_finite("z", z)
    T = float(check_positive("dt", dt))
    c = 0.5 if half else 1.0
    rs = vs = as_ = 0.0
    out = np.empty(z.shape)
    for k, zk in enumerate(z):
        rp = rs + T * vs + c * T * T * as_
        vp = vs + T * as_
        ap = as_
        out[k] = rp
        r = zk - rp
        rs = rp + alpha_h * r
        vs = vp + beta_h / T * r
        as_ = ap + 2.0 * gamma_h / (T * T) * r
    return out


def transfer_function_huang(alpha_h, beta_h, gamma_h=0.0):
    """Closed-loop transfer function of Huang et al., seed 002, eqs 3 and 6, as printed.

    Parameters
    ----------
    alpha_h, beta_h, gamma_h : float or array (S...)
        Gains in *Huang's* convention (seed 002, eq 1): ``gamma_h`` is half the canonical
        ``gamma`` (their acceleration update is ``2 gamma_h / T^2``). No conversion is done
        here; see :mod:`abglib.conventions`.

    Returns
    -------
    num, den : array (S..., m)
        Descending powers of ``z``; ``num`` zero-padded to the length of ``den``. Eq 3
        (``m = 4``) unless every ``gamma_h`` is zero, then eq 6 (``m = 3``).

    Notes
    -----
    Seed 002, eq 3:

    .. math::
        H(z) = \\frac{(\\alpha+\\beta+\\gamma)z^2 + (-\\beta-2\\alpha+\\gamma)z + \\alpha}
        {z^3 + (-3+\\alpha+\\beta+\\gamma)z^2 + (3-\\beta-2\\alpha+\\gamma)z - (1-\\alpha)}

    and eq 6 (:math:`\\gamma = 0`):
    :math:`H(z) = ((\\alpha+\\beta)z - \\alpha)/(z^2 + (-2+\\alpha+\\beta)z + (1-\\alpha))`.
    The scan prints the last numerator coefficient of both as ``a``: an OCR slip for
    :math:`\\alpha` (only with :math:`\\alpha` there does the loop have unit DC gain,
    ``H(1) = 1``, as a tracking loop must). With :math:`\\gamma_H = \\gamma/2` this is the
    canonical :math:`X_p/X` (seed 000, eq 39) -- Huang's ``H`` is the *predicted*
    position, which the tests check.
    """
    a = check_finite("alpha_h", alpha_h)
    b = check_finite("beta_h", beta_h)
    g = check_finite("gamma_h", gamma_h)
    a, b, g = np.broadcast_arrays(a, b, g)
    if np.all(g == 0.0):
        # eq 6
        num = np.stack([np.zeros_like(a), a + b, -a], axis=-1)
        den = np.stack([np.ones_like(a), -2.0 + a + b, 1.0 - a], axis=-1)
    else:
        # eq 3
        num = np.stack([np.zeros_like(a), a + b + g, -b - 2.0 * a + g, a], axis=-1)
        den = np.stack([np.ones_like(a), -3.0 + a + b + g, 3.0 - b - 2.0 * a + g, -(1.0 - a)], -1)
    return num, den


def transfer_function_huang_eq3(alpha_h, beta_h, gamma_h):
    r"""Seed 002, eq 3 as printed (``a`` read as alpha), at any ``gamma_h``, even 0.

    Returns
    -------
    num, den : array (S..., 4)
        Descending powers of ``z``. At ``gamma_h = 0`` numerator and denominator share the
        factor ``z - 1`` whose quotient is eq 6 (the paper: "the alpha-beta-tracker can be
        considered as the special case gamma = 0").
    """
    a = check_finite("alpha_h", alpha_h)
    b = check_finite("beta_h", beta_h)
    g = check_finite("gamma_h", gamma_h)
    a, b, g = np.broadcast_arrays(a, b, g)
    num = np.stack([np.zeros_like(a), a + b + g, -b - 2.0 * a + g, a], axis=-1)
    den = np.stack([np.ones_like(a), -3.0 + a + b + g, 3.0 - b - 2.0 * a + g, -(1.0 - a)], -1)
    return num, den


def stable_huang_eq5(alpha_h, beta_h, gamma_h):
    """Stability condition of seed 002, eq 5, as printed (Huang's gain convention).

    Parameters
    ----------
    alpha_h, beta_h, gamma_h : float or array (S...)
        Gains in Huang et al.'s convention (``gamma_h = gamma / 2``).

    Returns
    -------
    bool or bool array (S...)

    Notes
    -----
    Seed 002, eq 5 ("according to Routh principle"): :math:`4 - 2\\alpha - \\beta > 0`,
    :math:`2\\alpha - \\gamma > 0`, :math:`\\beta > 0`, :math:`\\gamma > 0`. This is
    necessary but **not sufficient**: it lacks the Jury condition
    :math:`\\alpha\\beta + \\alpha\\gamma_H - 2\\gamma_H > 0` (seed 000, eq 47 with
    :math:`\\gamma = 2\\gamma_H`); e.g. :math:`(\\alpha, \\beta, \\gamma_H) = (0.1, 0.01, 0.1)`
    satisfies eq 5 but has a pole at :math:`|z| > 1` (pinned in the tests).
    """
    a = check_finite("alpha_h", alpha_h)
    b = check_finite("beta_h", beta_h)
    g = check_finite("gamma_h", gamma_h)
    return scalar_or_array((4 - 2 * a - b > 0) & (2 * a - g > 0) & (b > 0) & (g > 0))


def stable_huang_eq7(alpha_h, beta_h):
    """Stability condition of the alpha-beta loop, seed 002, eq 7, as printed.

    Parameters
    ----------
    alpha_h, beta_h : float or array (S...)
        Gains (the alpha-beta gains are the same in Huang's and the canonical convention).

    Returns
    -------
    bool or bool array (S...)

    Notes
    -----
    Seed 002, eq 7: :math:`\\alpha > -\\beta`, :math:`\\beta > 0`. Necessary but far from
    sufficient: the true region (seed 000, eqs 42-44) also needs :math:`\\alpha > 0` and
    :math:`2\\alpha + \\beta < 4`; e.g. :math:`(\\alpha, \\beta) = (3, 0.1)` and
    :math:`(-0.05, 0.5)` satisfy eq 7 but are unstable (pinned in the tests).
    """
    a = check_finite("alpha_h", alpha_h)
    b = check_finite("beta_h", beta_h)
    return scalar_or_array((a > -b) & (b > 0))


# --------------------------------------------------------------------------- eqs 8-14
def enbw_eq8_two_sided(gains: Gains, dt=1.0) -> float:
    r"""The first form of seed 002, eq 8 as printed, in Hz: the whole-band integral.

    Parameters
    ----------
    gains : Gains
        Canonical gains (scalar), stable.
    dt : float, default 1.0
        Sample interval ``T`` > 0.

    Returns
    -------
    float
        :math:`\frac{1}{2\pi}\int_{-\pi/T}^{\pi/T}|H(e^{j\omega T})|^2\,d\omega`
        (``H = X_p/X``; the printed infinite limits are the Nyquist band of a sampled
        loop), by adaptive quadrature of :func:`abglib.analysis.frequency_response`.

    Notes
    -----
    ``|H|^2`` is even in ``omega``, so this is twice the one-sided
    :func:`abglib.analysis.enbw` of eqs 9-14: eq 8 as printed is the two-sided
    bandwidth.
    """
    require_stable(gains, _UNSTABLE)
    T = float(check_positive("dt", dt))
    f = _x_pred_power(gains)
    edges = np.concatenate([-np.geomspace(np.pi, 1e-5, 30), [0.0], np.geomspace(1e-5, np.pi, 30)])
    total = sum(
        scipy.integrate.quad(f, lo, hi, limit=200, epsrel=1e-11, epsabs=0.0)[0]
        for lo, hi in zip(edges[:-1], edges[1:], strict=True)
    )
    return total / (2.0 * np.pi * T)


def _x_pred_power(gains: Gains):
    """``f(wT) = |H(e^{j wT})|^2`` of the prediction ``X_p/X`` for scalar gains: the
    arithmetic of :func:`abglib.analysis.frequency_response` (eq 39 in powers of
    ``w = z - 1``, its coefficients from the same ``_w_forms``), in the same order on the
    same numpy types, so every value is the same bits (tested), with the gains' checks
    and coefficients done once instead of at each of quadrature's ~1300 points."""
    a, b, g = (np.asarray(v, dtype=float) for v in gains.as_arrays())
    if a.ndim or b.ndim or g.ndim:
        raise AbglibValueError(f"gains must be scalar, got shapes {a.shape}, {b.shape}, {g.shape}")
    num_w, zf, den_w = _w_forms(a, b, g, "x_pred", 1.0, bool(g == 0.0))

    def f(x):
        w_arr = np.asarray(x, dtype=np.float64)
        z = np.exp(1j * w_arr)
        w = 2j * np.sin(w_arr / 2.0) * np.exp(0.5j * w_arr)
        num = sum(c * w**k for k, c in enumerate(num_w)) * z**zf
        den = sum(c * w**k for k, c in enumerate(den_w))
        with np.errstate(divide="ignore", invalid="ignore"):
            h = num / den
        return float(np.abs(complex(h)) ** 2)

    return f


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


def enbw_huang_eq13_as_printed(alpha_h, beta_h, gamma_h, dt):
    r"""Seed 002, eq 13 read literally, in Hz (no reconstruction).

    Parameters
    ----------
    alpha_h, beta_h, gamma_h : float
        Gains in Huang's convention (``gamma_h > 0``).
    dt : float
        Sample interval ``T`` > 0.

    Returns
    -------
    float
        :math:`B_n = \frac{1}{2TK_5}\,\frac{K_0\sqrt{K_2}\,b + K_1\sqrt{K_2} + K_2 a}{c}`
        with :math:`b^2 = K_4 + 2\alpha\sqrt{K_2}`, :math:`a^2 = K_3 + 2b`,
        :math:`ab = \sqrt{K_2} + c` exactly as printed (``alpha`` the gain, ``K_2``
        the denominator constant of eqs 11-12) and ``K0..K5`` of eq 11.

    Notes
    -----
    The correct result is :func:`enbw_huang_eq8_13` (three corrections:
    the constant ``K2/K5``, the Hurwitz coefficient ``a`` in place of the gain ``alpha``
    under ``b^2``, and ``c`` multiplied by ``sqrt K2``). Read literally, the printed
    formula gives values of the order of the paper's nominal bandwidths for the printed
    type II alpha-beta-gamma gains, where the exact ENBW is 100-340 Hz.
    """
    a, b, g = (
        float(check_finite(n, v))
        for n, v in (("alpha_h", alpha_h), ("beta_h", beta_h), ("gamma_h", gamma_h))
    )
    T = float(check_positive("dt", dt))
    if g <= 0.0:
        raise AbglibValueError(f"gamma_h must be > 0 (eq 13 is for alpha-beta-gamma), got {g!r}")
    K0, K1, K2, K3, K4, K5 = _huang_k(a, b, g)
    s = np.sqrt(K2)
    b2 = K4 + 2.0 * a * s
    if b2 <= 0.0:
        raise AbglibValueError(f"eq 13 as printed has no real b for gains ({a}, {b}, {g})")
    bb = np.sqrt(b2)
    a2 = K3 + 2.0 * bb
    if a2 <= 0.0:
        raise AbglibValueError(f"eq 13 as printed has no real a for gains ({a}, {b}, {g})")
    aa = np.sqrt(a2)
    c = aa * bb - s
    return float((K0 * s * bb + K1 * s + K2 * aa) / c / (2.0 * T * K5))


# --------------------------------------------------------------------------- tracking errors
def steady_state_lag_huang(gain, magnitude, dt, kind="acceleration"):
    r"""Huang et al.'s steady-state errors, as printed (seed 002, "Tracking errors").

    Parameters
    ----------
    gain : float or array (...)
        ``beta`` for ``kind="acceleration"``; Huang's ``gamma_H`` (half the canonical
        gamma) for ``kind="jerk"``.
    magnitude : float or array (...)
        Target acceleration ``A`` (units/s^2) or its rate of change ``B`` (units/s^3).
    dt : float or array (...)
        Sample interval ``T = 1/F_r`` > 0.
    kind : {"acceleration", "jerk"}, default "acceleration"

    Returns
    -------
    float or array (...)
        ``A / (beta F_r^2)`` or ``B / (gamma_H F_r^3)``.

    Notes
    -----
    Seed 002: ``e = A / (beta F_r^2)`` (alpha-beta, acceleration) and
    ``e = B / (gamma F_r^3)`` (alpha-beta-gamma, acceleration change), ``F_r = 1/T``.
    The first is exactly the steady-state *predicted*-position error (their ``H(z)`` is
    ``X_p/X``; :func:`steady_state_lag` with ``output="x_pred"``). The second is exact
    only if ``gamma`` is read as the canonical gain; with their own ``gamma_H`` (eq 3)
    the predicted-position lag is ``B T^3 / (2 gamma_H)``, half the printed value.
    """
    if kind not in _KINDS:
        raise AbglibValueError(f"kind must be one of {', '.join(map(repr, _KINDS))}, got {kind!r}")
    k = check_positive("gain", gain)
    m = check_finite("magnitude", magnitude)
    T = check_positive("dt", dt)
    fr = 1.0 / T
    power = 2 if kind == "acceleration" else 3
    return scalar_or_array(np.asarray(m / (k * fr**power), dtype=float))


def _snr(snr_db):
    return 10.0 ** (check_finite("snr_db", snr_db) / 10.0)


def thermal_sigma(bn_hz, fr_hz, tau_s, snr_db, k=1.4, form="printed"):
    r"""Thermal-noise range tracking error in metres (seed 002, "Tracking errors").

    Parameters
    ----------
    bn_hz : float or array (...)
        Equivalent noise bandwidth ``B_n`` of the range loop, Hz, > 0.
    fr_hz : float
        Pulse repetition (sampling) frequency ``F_r = 1/T``, Hz.
    tau_s : float
        Pulse width ``tau``, s.
    snr_db : float
        Single-pulse signal-to-noise ratio ``(S/N)_0`` in dB (power ratio).
    k : float, default 1.4
        Normalised slope of the range discriminator.
    form : {"printed", "barton"}, default "printed"
        ``"printed"``: the paper's formula; ``"barton"``: the same with the
        ``2E/N_0`` of Barton's range-error formula (a factor ``sqrt 2`` smaller).

    Returns
    -------
    float or array (...)
        ``sigma`` in m.

    Notes
    -----
    Seed 002 (unnumbered, section "Tracking errors"):

    .. math:: \sigma = \frac{\tau c}{2k\sqrt{(S/N)_0\,(F_r/B_n)}},

    the range extent of the pulse ``tau c / 2`` over the discriminator slope and the
    square root of the signal-to-noise ratio integrated over ``F_r / B_n`` pulses.
    Barton's form writes ``2 E/N_0 = 2 (S/N)_0 F_r / B_n`` under the root; it is the
    printed formula with ``B_n`` replaced by ``B_n / 2``, i.e. the printed formula
    evaluated at the *two-sided* bandwidth of eq 8.
    """
    if form not in _FORMS:
        raise AbglibValueError(f"form must be one of {', '.join(map(repr, _FORMS))}, got {form!r}")
    bn = check_positive("bn_hz", bn_hz)
    fr = check_positive("fr_hz", fr_hz)
    tau = check_positive("tau_s", tau_s)
    kk = check_positive("k", k)
    factor = 1.0 if form == "printed" else 2.0
    return scalar_or_array(tau * C_LIGHT / (2.0 * kk * np.sqrt(factor * _snr(snr_db) * fr / bn)))


def bandwidth_for_sigma(sigma_m, fr_hz, tau_s, snr_db, k=1.4, form="printed"):
    r"""The ENBW (Hz) at which :func:`thermal_sigma` equals ``sigma_m``.

    Notes
    -----
    Inverting the formula of :func:`thermal_sigma`:
    :math:`B_n = f\,(S/N)_0 F_r\,(2k\sigma/(\tau c))^2`, ``f = 1`` (printed) or 2 (Barton).
    The error grows with ``B_n``, so ``sigma <= sigma_m`` needs ``B_n <=`` this value
    (seed 002, "Assuming the sigma <= 7m, the ENBW should be under 40Hz").
    """
    if form not in _FORMS:
        raise AbglibValueError(f"form must be one of {', '.join(map(repr, _FORMS))}, got {form!r}")
    s = check_positive("sigma_m", sigma_m)
    fr = check_positive("fr_hz", fr_hz)
    tau = check_positive("tau_s", tau_s)
    kk = check_positive("k", k)
    factor = 1.0 if form == "printed" else 2.0
    return scalar_or_array(factor * _snr(snr_db) * fr * (2.0 * kk * s / (tau * C_LIGHT)) ** 2)


def measurement_sigma(tau_s, snr_db, k=1.4):
    r"""Per-pulse range noise (m) for which the printed thermal error is exact.

    Returns
    -------
    float
        :math:`\sigma_m = \tau c / (2k\sqrt{2 (S/N)_0})` (Barton's single-pulse error).

    Notes
    -----
    White measurement noise of standard deviation ``sigma_m`` leaves a predicted-position
    error of variance :math:`\sigma_m^2\,\mathrm{VRF}_{x_p} = \sigma_m^2\, 2 B_n T`
    (:func:`abglib.analysis.enbw`, one-sided). With this ``sigma_m`` that is exactly
    :func:`thermal_sigma` ``(B_n, 1/T, ...)`` as printed: the printed formula is the
    single-pulse error of Barton's ``2E/N_0`` form smoothed by a loop of one-sided
    bandwidth ``B_n``.
    """
    return thermal_sigma(0.5, 1.0, tau_s, snr_db, k, form="printed")
