"""Transfer functions and frequency responses of the tracker (seed 000, eqs 33-40; seed 002).

Every output of the canonical tracker (``shared/CONTRACTS.md`` section 1) is a rational
function of ``z`` with the common denominator of seed 000, eq 40. The printed closed forms
(eqs 36-40) are written in powers of ``w = z - 1``; this module keeps them in that form and
expands them into descending powers of ``z`` in one helper, so the code reads like the
paper. The numeric twins (state space ``C (zI - F)^-1 B``, the DFT of the impulse
response of :func:`abglib.track`, scipy and python-control) live in the tests.
"""

from __future__ import annotations

from math import comb

import numpy as np

from .._checks import AbglibValueError, check_finite, check_positive
from ..gains import Gains, require_gains

__all__ = [
    "OUTPUTS",
    "frequency_response",
    "transfer_function",
]

#: Output names accepted by :func:`transfer_function` and :func:`frequency_response`.
OUTPUTS = ("x_smooth", "v_smooth", "a_smooth", "x_pred", "v_pred", "a_pred")


# --------------------------------------------------------------------------- checks


def _check_output(output, allowed=OUTPUTS) -> str:
    if not isinstance(output, str) or output not in allowed:
        raise AbglibValueError(
            f"output must be one of {', '.join(map(repr, allowed))}, got {output!r}"
        )
    return output


def _check_dt(dt) -> float:
    arr = check_positive("dt", dt)
    if arr.ndim != 0:
        raise AbglibValueError(f"dt must be a scalar sample interval, got shape {arr.shape}")
    return float(arr)


# --------------------------------------------------------------------------- (z-1) forms
def _w_forms(alpha, beta, gamma, output, dt, reduced):
    """Numerator and denominator as coefficient lists in ascending powers of ``w = z - 1``.

    Returns ``(num_w, z_factor, den_w)``: the numerator is ``z**z_factor * sum num_w[k] w**k``.
    Coefficients are arrays broadcast over the bank. ``reduced`` divides numerator and
    denominator by the common factor ``w`` that every output has when ``gamma == 0``.
    Scalars of another number type (:class:`fractions.Fraction`, with an integer ``dt``)
    give coefficients of that type: the exact route of :mod:`._features`.
    """
    if isinstance(alpha, np.ndarray):
        one, zero = np.ones_like(alpha), np.zeros_like(alpha)
    else:
        one, zero = alpha * 0 + 1, alpha * 0
    g2 = gamma / 2  # integer literals: the same bits as 2.0, 3.0 in floats, exact otherwise
    if not reduced:
        # eq 40: (z-1)^3 + a (z-1)^2 + (b + g/2) z (z-1) + g z, with z = w + 1:
        #        w^3 + (a + b + g/2) w^2 + (b + 3g/2) w + g
        den = [gamma, beta + 3 * g2, alpha + beta + g2, one]
        num, zf = {
            # eq 36: z [a w^2 + (b + g/2) w + g]
            "x_smooth": ([gamma, beta + g2, alpha], 1),
            # eq 37: z [b w^2 + g w] / T
            "v_smooth": ([zero, gamma / dt, beta / dt], 1),
            # eq 38: z g w^2 / T^2
            "a_smooth": ([zero, zero, gamma / dt**2], 1),
            # eq 39: (a + b + g/2) w^2 + (b + 3g/2) w + g
            "x_pred": ([gamma, beta + 3 * g2, alpha + beta + g2], 0),
            # eq 5 with eqs 37-38: V_p = z^-1 (Vbar + T Abar) = [(b + g) w^2 + g w] / T
            "v_pred": ([zero, gamma / dt, (beta + gamma) / dt], 0),
            # eq 6 with eq 38: A_p = z^-1 Abar = g w^2 / T^2
            "a_pred": ([zero, zero, gamma / dt**2], 0),
        }[output]
    else:
        # gamma = 0: eq 40 is w [w^2 + (a + b) w + b] = w * eq 41; the factor w cancels
        den = [beta, alpha + beta, one]
        num, zf = {
            "x_smooth": ([beta, alpha], 1),
            "v_smooth": ([zero, beta / dt], 1),
            "a_smooth": ([zero], 1),
            "x_pred": ([beta, alpha + beta], 0),
            "v_pred": ([zero, beta / dt], 0),
            "a_pred": ([zero], 0),
        }[output]
    return num, zf, den


def _expand(coeffs_w, z_factor, length):
    """Expand ``z**z_factor * sum_k c_k (z - 1)**k`` into descending powers of ``z``.

    ``coeffs_w`` is a list of arrays (ascending powers of ``w``); the result has shape
    ``bank + (length,)`` (zero-padded on the left).
    """
    shape = np.shape(coeffs_w[0])
    asc = np.zeros(shape + (length,))
    for k, c in enumerate(coeffs_w):
        # (z - 1)^k = sum_i C(k, i) z^i (-1)^(k - i)
        for i in range(k + 1):
            asc[..., i + z_factor] += c * comb(k, i) * (-1.0) ** (k - i)
    return asc[..., ::-1]


def _gain_arrays(gains: Gains):
    a, b, g = (np.asarray(v, dtype=float) for v in gains.as_arrays())
    return a, b, g


# --------------------------------------------------------------------------- public
def transfer_function(gains: Gains, output: str, dt: float = 1.0):
    """Transfer function ``Y(z)/X(z)`` from the measurement to one tracker output.

    Parameters
    ----------
    gains : Gains
        Canonical gains, scalars or a bank of shape ``S``.
    output : {"x_smooth", "v_smooth", "a_smooth", "x_pred", "v_pred", "a_pred"}
        ``x_smooth`` = Xbar/X (eq 36), ``v_smooth`` = Vbar/X (eq 37), ``a_smooth`` = Abar/X
        (eq 38), ``x_pred`` = X_p/X (eq 39); ``v_pred`` and ``a_pred`` follow from eqs 5-6.
    dt : float, default 1.0
        Sample interval ``T`` > 0 (scales the velocity and acceleration outputs).

    Returns
    -------
    num, den : array (S..., m)
        Coefficients in descending powers of ``z``. ``num`` is zero-padded on the left to
        the length of ``den``, so ``(num, den)`` can be passed unchanged to
        :func:`scipy.signal.freqz` or :class:`scipy.signal.dlti`. ``m = 4`` (the cubic of
        eq 40) unless every ``gamma`` is zero, in which case the common factor ``z - 1``
        is cancelled and ``den`` is the quadratic of eq 41 (``m = 3``).

    Notes
    -----
    Seed 000, eqs 36-40, with :math:`w = z - 1`:

    .. math::
        \\Delta = w^3 + \\alpha w^2 + (\\beta + \\gamma/2) z w + \\gamma z,\\qquad
        \\frac{\\bar X}{X} = \\frac{z[\\alpha w^2 + (\\beta + \\gamma/2) w + \\gamma]}{\\Delta},

    :math:`\\bar V/X = z[\\beta w^2 + \\gamma w]/(T\\Delta)`,
    :math:`\\bar A/X = z\\gamma w^2/(T^2\\Delta)`,
    :math:`X_p/X = [(\\alpha+\\beta+\\gamma/2) w^2 + (\\beta + 3\\gamma/2) w + \\gamma]/\\Delta`
    (which equals :math:`1 - w^3/\\Delta`). The predicted velocity and acceleration
    (not printed) follow from eqs 5-6: :math:`V_p = z^{-1}(\\bar V + T\\bar A)`,
    :math:`A_p = z^{-1}\\bar A`. With :math:`\\gamma = 0`, :math:`\\Delta = w\\,(z^2 +
    (\\alpha + \\beta - 2) z + 1 - \\alpha)` (eq 41 times :math:`w`); the factor :math:`w`
    is the uncontrollable acceleration pole at :math:`z = 1` and is cancelled.

    References
    ----------
    .. [1] J. E. Steelman, *Frequency Response of alpha-beta-gamma Trackers*, STEWS-ID-78-3,
       1978 (seed 000), eqs 33-41.

    Examples
    --------
    >>> from abglib import Gains
    >>> num, den = transfer_function(Gains(0.5, 0.2), "x_pred")
    >>> num, den
    (array([ 0. ,  0.7, -0.5]), array([ 1. , -1.3,  0.5]))
    """
    gains = require_gains(gains)
    output = _check_output(output)
    T = _check_dt(dt)
    a, b, g = _gain_arrays(gains)
    reduced = gains.order == 2
    num_w, zf, den_w = _w_forms(a, b, g, output, T, reduced)
    length = len(den_w)
    return _expand(num_w, zf, length), _expand(den_w, 0, length)


def frequency_response(gains: Gains, output: str, wT, dt: float = 1.0):
    """Complex frequency response ``H(e^{j wT})`` of one tracker output.

    Parameters
    ----------
    gains : Gains
        Canonical gains, scalars or a bank of shape ``S``.
    output : str
        One of :data:`~abglib.analysis.OUTPUTS` (see :func:`transfer_function`).
    wT : float or array (W...)
        Normalised angular frequency ``omega T`` in radians per sample; any grid, finite.
    dt : float, default 1.0
        Sample interval ``T`` > 0.

    Returns
    -------
    complex or complex array (S... + W...)
        The response of every gain set at every frequency (outer product: bank axes
        first, frequency axes last, like :func:`scipy.signal.freqz` for several filters).
        A Python complex for scalar gains and scalar ``wT``.

    Notes
    -----
    Seed 000, "Frequency response curves": replace ``z`` by :math:`e^{+j\\omega T}` in
    eqs 36-40. The rational function is evaluated in its :math:`w = z - 1` form; where
    :math:`\\gamma = 0` the common factor :math:`w` is cancelled first (eq 41), so that
    :math:`\\omega T = 0` gives the DC gain, not 0/0.

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eqs 36-40 with z = exp(j wT)
    ("Frequency response curves"); eq 41.
    """
    gains = require_gains(gains)
    output = _check_output(output)
    T = _check_dt(dt)
    w_arr = check_finite("wT", wT)
    a, b, g = _gain_arrays(gains)
    bank_nd = a.ndim
    expand = (Ellipsis,) + (None,) * w_arr.ndim
    a, b, g = a[expand], b[expand], g[expand]
    z = np.exp(1j * w_arr)
    # w = z - 1 without cancellation at small wT
    w = 2j * np.sin(w_arr / 2.0) * np.exp(0.5j * w_arr)

    def evaluate(reduced):
        num_w, zf, den_w = _w_forms(a, b, g, output, T, reduced)
        num = sum(c * w**k for k, c in enumerate(num_w)) * z**zf
        den = sum(c * w**k for k, c in enumerate(den_w))
        with np.errstate(divide="ignore", invalid="ignore"):
            return num / den

    zero_g = g == 0.0
    if np.all(zero_g):
        h = evaluate(True)
    elif not np.any(zero_g):
        h = evaluate(False)
    else:
        h = np.where(zero_g, evaluate(True), evaluate(False))
    h = np.broadcast_to(h, a.shape[:bank_nd] + w_arr.shape)
    return complex(h) if h.ndim == 0 else np.array(h)
