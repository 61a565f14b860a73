"""Frequency-domain features of the position response (seed 000, "Analytical expressions").

Exact features of :math:`|\\bar X/X|` (and of :math:`|X_p/X|`): the value at
:math:`\\omega T = \\pi` (eq 50), the frequency at which the response crosses a level
(-3 dB, -6 dB, unity), the passband peak and overshoot, and the first undesired maximum
of the design example; next to them, Steelman's printed approximations, eqs 50-59, kept
*as printed*.

The exact routes work on :math:`|H|^2` as a rational function of
:math:`q = |e^{j\\omega T} - 1|^2 = 2(1 - \\cos\\omega T) = 4\\sin^2(\\omega T/2)`,
:math:`0 \\le q \\le 4`, which is well conditioned at the small :math:`\\omega T` where the
features of a smoothing tracker lie. Each exact feature has two routes selected by
``method``: ``"poly"`` (roots of a polynomial in ``q``) and ``"grid"`` (dense grid of the
complex response, then ``brentq`` / bounded scalar refinement); the tests check them
against each other.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np
from numpy.polynomial import Polynomial
from numpy.polynomial import polynomial as P

from .._checks import AbglibValueError, check_finite, check_in_range, describe, scalar_or_array
from ..gains import Gains, require_gains
from ._stability import require_stable
from ._transfer import _check_output, _w_forms, frequency_response

__all__ = [
    "POSITION_OUTPUTS",
    "first_undesired_max",
    "min_gain_at_pi",
    "min_gain_steelman_eq50",
    "omega_3db_eq53",
    "omega_at_gain",
    "omega_max_eq54",
    "omega_unity_eq51",
    "omega_unity_eq52",
    "overshoot_eq55",
    "overshoot_eq55_terms",
    "peak",
]

#: Outputs with unit DC gain, for which a level, a peak and an overshoot are defined.
POSITION_OUTPUTS = ("x_smooth", "x_pred")
_METHODS = ("poly", "grid")

# dense grid of the "grid" route: uniform on [0, pi] plus geometric towards 0, where the
# passband of a heavily smoothing tracker lies (alpha = 0.01 peaks near wT = 0.004)
_GRID = np.union1d(np.linspace(0.0, np.pi, 8193), np.geomspace(1e-7, np.pi, 4097))


# --------------------------------------------------------------------------- helpers


def _check_method(method):
    if method not in _METHODS:
        raise AbglibValueError(
            f"method must be one of {', '.join(map(repr, _METHODS))}, got {method!r}"
        )
    return method


def _each(gains: Gains, fn):
    """Apply ``fn`` (scalar Gains -> tuple of floats) over a bank; arrays of shape S."""
    if gains.shape == ():
        return fn(gains)
    results = [fn(gains[idx]) for idx in np.ndindex(gains.shape)]
    return tuple(np.array(col).reshape(gains.shape) for col in zip(*results, strict=True))


def _mag2_q(coeffs_w) -> list:
    """:math:`|p|^2` on the unit circle as a polynomial in :math:`q = |z - 1|^2`
    (coefficients in ascending powers; exact for exact input).

    ``coeffs_w`` are the coefficients of ``p`` in ascending powers of :math:`w = z - 1`
    (the form of seed 000, eqs 36-40). With :math:`w\\bar w = q` and
    :math:`w + \\bar w = -q`, the power sums :math:`s_d = w^d + \\bar w^d` obey
    :math:`s_0 = 2`, :math:`s_1 = -q`, :math:`s_d = -q(s_{d-1} + s_{d-2})`, and
    :math:`|p|^2 = \\sum_k c_k^2 q^k + \\sum_{k<l} c_k c_l q^k s_{l-k}` -- no cancellation
    at small :math:`q`, where the features of a smoothing tracker lie.
    """
    # Fractions throughout: numpy's series functions keep them (object arrays), but make
    # a series of plain integers float
    c = [Fraction(v) for v in coeffs_w]
    zero, minus_q = Fraction(0), [Fraction(0), Fraction(-1)]
    sums = [[Fraction(2)], minus_q]
    for _ in range(2, len(c)):
        sums.append(P.polymul(minus_q, P.polyadd(sums[-1], sums[-2])))
    out = [zero]
    for k, ck in enumerate(c):
        out = P.polyadd(out, [zero] * k + [ck * ck])
        for l in range(k + 1, len(c)):
            out = P.polyadd(out, [zero] * k + [ck * c[l] * s for s in sums[l - k]])
    return list(out)


def _rounded(p: list) -> Polynomial:
    """An exact coefficient list as a float :class:`~numpy.polynomial.Polynomial`, each
    coefficient rounded once."""
    return Polynomial([float(x) for x in p] or [0.0])


def _omega_of_q(q):
    return 2.0 * np.arcsin(np.sqrt(np.clip(q, 0.0, 4.0)) / 2.0)


def _real_roots_q(poly: Polynomial):
    coef = poly.coef
    if not np.any(coef):
        return np.array([])
    roots = poly.roots()
    scale = 1.0 + np.abs(roots)
    real = roots[np.abs(roots.imag) <= 1e-7 * scale].real
    return real[(real >= -1e-12) & (real <= 4.0 + 1e-12)]


def _mag2_polys(gains: Gains, output: str):
    """``(P, Q)``, exact coefficient lists (:class:`~fractions.Fraction`) with
    :math:`|H|^2 = P(q)/Q(q)` for one scalar gain set (a factor :math:`z^k` of the
    numerator has modulus 1 and drops out).

    Exact from the gains' float values: the polynomials the poly routes solve
    (:math:`P'Q - PQ'`, :math:`P - L^2 Q`) are differences of nearly equal terms where a
    gain is small against another or near the edge of stability (:math:`P - Q` has the
    coefficient :math:`2\\beta(1 - \\alpha)` as a difference of terms of order
    :math:`\\alpha^2`: in floats the unity crossing was 9 % off at beta 1e-16); formed
    exactly, each is rounded once (:func:`_rounded`) before its roots are found."""
    a, b, g = (Fraction(float(v)) for v in gains)
    num_w, _, den_w = _w_forms(a, b, g, output, 1, reduced=g == 0)
    return _mag2_q(num_w), _mag2_q(den_w)


def _peak_scalar(gains: Gains, output: str, method: str):
    if method == "poly":
        num, den = _mag2_polys(gains, output)
        slope = P.polysub(P.polymul(P.polyder(num), den), P.polymul(num, P.polyder(den)))
        stationary = _real_roots_q(_rounded(slope))
        w = _omega_of_q(np.concatenate([[0.0, 4.0], stationary]))
        # |H|^2 at each candidate from the transfer function itself, not P(q)/Q(q): near
        # the edge of stability (2 alpha + beta -> 4, a pole near z = -1) Q's expanded
        # coefficients cancel to a remainder below their round-off and P/Q lost every
        # digit (alpha 1.9, beta 0.2 - 1e-8: (0, 0) against an overshoot of 3.6e8 at pi)
        m2 = np.abs(frequency_response(gains, output, w)) ** 2
        # the global maximum; on ties (flat response, alpha = 1) the lowest frequency
        top = np.flatnonzero(m2 >= m2.max() * (1.0 - 1e-15))
        i = int(top[np.argmin(w[top])])
        return float(w[i]), float(np.sqrt(m2[i]) - 1.0)

    from scipy.optimize import minimize_scalar  # here: the exact route needs no scipy

    def neg_mag2(w):
        return -(abs(frequency_response(gains, output, w)) ** 2)

    m2 = np.abs(frequency_response(gains, output, _GRID)) ** 2
    # Every local maximum of the grid is refined, not only its largest value: a resonance
    # about as narrow as the grid's spacing (poles within ~2e-4 of the unit circle) shows
    # on the grid far below its height and may lose to an end point (alpha 1.945, beta
    # 0.0017, gamma 0.068: grid maximum 36.1 at pi, true peak 43.4 at wT 0.188 between two
    # grid points); its true peak lies between the local maximum's two neighbours. The
    # intervals next to 0 and pi are searched too where the response rises towards the
    # end, a peak inside them having no grid point on its far side. The margin leaves out
    # round-off ripple of a flat response (|H| = 1 near DC, alpha = 1).
    last = len(_GRID) - 1
    margin = 1.0 + 1e-12
    inner = m2[1:-1]
    # not below either neighbour and clearly above one (a peak midway between two grid
    # points leaves them nearly equal)
    clear = (inner > m2[:-2] * margin) | (inner > m2[2:] * margin)
    local = np.flatnonzero((inner >= m2[:-2]) & (inner >= m2[2:]) & clear) + 1
    brackets = [(_GRID[i - 1], _GRID[i + 1]) for i in local]
    if m2[0] > m2[1] * margin:
        brackets.append((_GRID[0], _GRID[1]))
    if m2[last] > m2[last - 1] * margin:
        brackets.append((_GRID[last - 1], _GRID[last]))
    found = [(_GRID[0], m2[0]), (_GRID[last], m2[last])]
    found += [(_GRID[i], m2[i]) for i in local]
    for lo, hi in brackets:
        res = minimize_scalar(neg_mag2, bounds=(lo, hi), method="bounded", options={"xatol": 1e-13})
        found.append((res.x, -res.fun))
    # the global maximum; on ties (a flat response) the lowest frequency, as the poly route
    top = max(v for _, v in found)
    w, v = min((w, v) for w, v in found if v >= top * (1.0 - 1e-15))
    return float(w), float(np.sqrt(v) - 1.0)


def _omega_at_gain_scalar(gains: Gains, level: float, output: str, method: str):
    w_pk, _ = _peak_scalar(gains, output, method)
    if method == "poly":
        num, den = _mag2_polys(gains, output)
        excess = P.polysub(num, P.polymul([Fraction(level**2)], den))
        w = _omega_of_q(_real_roots_q(_rounded(excess)))
        w = w[w > w_pk * (1 + 1e-9) + 1e-12]
        return (float(w.min()) if w.size else float("nan"),)

    from scipy.optimize import brentq  # here: the exact route needs no scipy

    def excess(x):
        return abs(frequency_response(gains, output, x)) ** 2 - level**2

    # from the peak itself, so that a fall through the level before the next grid point is
    # seen (a sharp resonance); the first sign change is then a fall, and a level at or
    # above the peak is never reached above it
    grid = np.union1d(_GRID[_GRID > w_pk], [w_pk, np.pi])
    vals = np.abs(frequency_response(gains, output, grid)) ** 2 - level**2
    if vals[0] <= 0.0:
        return (float("nan"),)
    change = np.flatnonzero(np.sign(vals[1:]) != np.sign(vals[:-1]))
    if change.size == 0:
        return (float("nan"),)
    k = int(change[0])
    if vals[k + 1] == 0.0:
        return (float(grid[k + 1]),)
    return (float(brentq(excess, grid[k], grid[k + 1], xtol=1e-15, rtol=4 * np.finfo(float).eps)),)


# --------------------------------------------------------------------------- exact
def min_gain_at_pi(gains: Gains, output: str = "x_smooth"):
    """Exact :math:`|H(e^{j\\pi})|`, the response at the Nyquist frequency.

    Parameters
    ----------
    gains : Gains
        Canonical gains, scalars or a bank of shape ``S``.
    output : {"x_smooth", "x_pred"}, default "x_smooth"

    Returns
    -------
    float or array (S...)

    Notes
    -----
    From eq 36 at :math:`z = -1`:
    :math:`\\bar X/X = (2\\alpha - \\beta)/(4 - 2\\alpha - \\beta)` exactly, for every
    :math:`\\gamma` -- seed 000, eq 50, is exact (in modulus) and indeed independent of
    :math:`\\gamma`. Whether it is the *minimum* of the response depends on the gains
    (for :math:`\\alpha > 1` it exceeds 1 and is a maximum); the tests check where.

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eq 50.
    """
    _check_output(output, POSITION_OUTPUTS)
    return scalar_or_array(np.abs(frequency_response(gains, output, np.pi)))


def peak(gains: Gains, output: str = "x_smooth", method: str = "poly"):
    """Exact passband peak: frequency of the maximum of ``|H|`` and the overshoot.

    Parameters
    ----------
    gains : Gains
        Stable canonical gains, scalars or a bank of shape ``S``.
    output : {"x_smooth", "x_pred"}, default "x_smooth"
    method : {"poly", "grid"}, default "poly"
        ``"poly"``: stationary points of :math:`|H|^2` as the real roots in
        :math:`0 < q < 4` of :math:`P'Q - PQ'` (:math:`|H|^2 = P(q)/Q(q)`), plus the
        end points, each evaluated by the transfer function (:func:`frequency_response`).
        ``"grid"``: every local maximum of a dense grid (and a rise towards either end)
        refined by bounded Brent search.

    Returns
    -------
    wT_max, overshoot : float or array (S...)
        ``wT_max`` in radians per sample (0 if the response never exceeds its DC value 1);
        ``overshoot = max |H| - 1`` (seed 000's definition before eq 55).

    Notes
    -----
    The global maximum of :math:`|H(e^{j\\omega T})|` over :math:`0 \\le \\omega T \\le
    \\pi`. For ``x_smooth`` and :math:`0 < \\alpha < 1`,
    :math:`|H|^2 - 1 = (1-\\alpha) q^2 (2\\beta - q) / |\\Delta|^2`, so the response
    exceeds 1 exactly for :math:`q < 2\\beta` and the peak lies below eq 51's frequency.
    Compare the approximations :func:`omega_max_eq54` and :func:`overshoot_eq55`.

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), the overshoot defined before eq 55 (exact);
    eqs 54-55 are its printed approximations.
    """
    gains = require_gains(gains)
    _check_output(output, POSITION_OUTPUTS)
    _check_method(method)
    require_stable(gains, "steady-state frequency response is undefined")
    return _each(gains, lambda g: _peak_scalar(g, output, method))


def omega_at_gain(gains: Gains, level_db, output: str = "x_smooth", method: str = "poly"):
    """Exact ``wT`` where ``|H|`` first falls through a level above the passband peak.

    Parameters
    ----------
    gains : Gains
        Stable canonical gains, scalars or a bank of shape ``S``.
    level_db : float
        The level :math:`20\\log_{10}|H|` in dB: -3 (pass-band edge), -6, 0 (unity), ...
    output : {"x_smooth", "x_pred"}, default "x_smooth"
    method : {"poly", "grid"}, default "poly"
        ``"poly"``: real roots in ``q`` of :math:`|N|^2 - L^2|\\Delta|^2` (a cubic in
        :math:`\\cos\\omega T` for the alpha-beta-gamma tracker, the equation Steelman
        calls intractable before eq 51). ``"grid"``: first sign change on a dense grid
        starting at the grid route's peak, then :func:`scipy.optimize.brentq`.

    Returns
    -------
    float or array (S...)
        The smallest :math:`\\omega T > \\omega T_{max}` (:func:`peak`) with
        :math:`|H| = 10^{L_{dB}/20}`; ``nan`` where the response does not reach the level
        above the peak (a level above the peak, or below the value at :math:`\\pi`).

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), Figures 1-6 and eqs 51-53 (the
    printed approximations this solves exactly).
    """
    gains = require_gains(gains)
    _check_output(output, POSITION_OUTPUTS)
    _check_method(method)
    level = check_finite("level_db", level_db)
    if level.ndim:
        raise AbglibValueError(f"level_db must be a scalar, got shape {level.shape}")
    require_stable(gains, "steady-state frequency response is undefined")
    lin = 10.0 ** (float(level) / 20.0)
    (w,) = _each(gains, lambda g: _omega_at_gain_scalar(g, lin, output, method))
    return scalar_or_array(w)


def first_undesired_max(gains: Gains, output: str = "x_smooth", method: str = "poly"):
    """Exact ``wT`` of the first maximum above the pass band: the alias of the peak.

    Parameters
    ----------
    gains : Gains
        Stable canonical gains, scalars or a bank of shape ``S``.
    output : {"x_smooth", "x_pred"}, default "x_smooth"
    method : {"poly", "grid"}, default "poly"

    Returns
    -------
    float or array (S...)
        :math:`2\\pi - \\omega T_{max}`.

    Notes
    -----
    The response is periodic in :math:`\\omega T` with period :math:`2\\pi` and
    :math:`|H(e^{-j\\omega T})| = |H(e^{j\\omega T})|`, so the passband peak recurs at
    :math:`2\\pi - \\omega T_{max}`: seed 000, design example, step 3
    (":math:`\\omega = (2\\pi - .04)/T`" for :math:`\\alpha = .1`).

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), design example, step 3.
    """
    w, _ = peak(gains, output, method)
    return scalar_or_array(2.0 * np.pi - np.asarray(w))


# --------------------------------------------------------------------------- printed
def min_gain_steelman_eq50(gains: Gains):
    """Seed 000, eq 50, as printed: :math:`(2\\alpha - \\beta)/(4 - 2\\alpha - \\beta)`.

    Parameters
    ----------
    gains : Gains
        Canonical gains, scalars or a bank of shape ``S`` (``gamma`` is not used).

    Returns
    -------
    float or array (S...)
        The signed value (it is :math:`\\bar X/X` at :math:`z = -1`, a real number,
        negative when :math:`\\beta > 2\\alpha`); compare its modulus with
        :func:`min_gain_at_pi`.

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eq 50, as printed.
    """
    a, b, _ = require_gains(gains).as_arrays()
    den = 4.0 - 2.0 * a - b
    if np.any(den == 0.0):
        raise AbglibValueError(
            f"eq 50 needs 4 - 2 alpha - beta != 0 (the stability boundary), got {describe(den)}"
        )
    return scalar_or_array((2.0 * a - b) / den)


def _beta(gains, low=0.0, high=None, **kw):
    _, b, _ = require_gains(gains).as_arrays()
    return check_in_range("beta", b, low, high, **kw)


def omega_unity_eq51(gains: Gains):
    """Seed 000, eq 51: :math:`\\omega T = \\arccos(1 - \\beta)`, where :math:`|\\bar X/X| = 1`.

    Parameters
    ----------
    gains : Gains
        Canonical gains with :math:`0 \\le \\beta \\le 2`, scalars or a bank of shape ``S``.

    Returns
    -------
    float or array (S...)

    Notes
    -----
    Exact, for every :math:`\\alpha \\ne 1` and every :math:`\\gamma`: from eqs 36 and 40,
    :math:`\\Delta - N = (1 - \\alpha)(z-1)^3`, which gives
    :math:`|\\Delta|^2 - |N|^2 = (1-\\alpha)\\,q^2(q - 2\\beta)`,
    :math:`q = 2(1 - \\cos\\omega T)`; the only nonzero root is :math:`\\cos\\omega T =
    1 - \\beta`. (For :math:`\\alpha = 1`, :math:`\\bar X \\equiv X`.)

    Evaluated as :math:`2\\arcsin\\sqrt{\\beta/2}`, the same angle
    (:math:`1 - \\cos\\omega T = 2\\sin^2(\\omega T/2)`): ``arccos(1 - beta)`` rounds
    ``1 - beta`` first and loses the digits of a small ``beta`` (0 at ``beta = 1e-17``
    instead of 4.47e-9; 1e-5 relative at ``1e-12``).

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eq 51, as printed.
    """
    b = _beta(gains, 0.0, 2.0, low_inclusive=True, high_inclusive=True)
    return scalar_or_array(2.0 * np.arcsin(np.sqrt(0.5 * b)))


def omega_unity_eq52(gains: Gains):
    """Seed 000, eq 52: :math:`\\omega T \\approx \\sqrt{2\\beta}` (small-angle form of eq 51).

    Parameters
    ----------
    gains : Gains
        Canonical gains with :math:`\\beta \\ge 0`, scalars or a bank of shape ``S``.

    Returns
    -------
    float or array (S...)

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eq 52, as printed.
    """
    return scalar_or_array(np.sqrt(2.0 * _beta(gains, 0.0, low_inclusive=True)))


def omega_3db_eq53(gains: Gains, exponent: float = -0.15):
    """Seed 000, eq 53: straight-line (log-log) estimate of the -3 dB frequency.

    Parameters
    ----------
    gains : Gains
        Canonical gains with :math:`0 < \\alpha < 2`, :math:`\\beta > 0`; scalars or a bank.
    exponent : float, default -0.15
        ``-0.15`` for -3 dB (eq 53 as printed); ``-0.3`` for the -6 dB estimate of
        Table 3 ("-.15 in the exponent of (53) becomes -.3"). In general
        ``level_db / 20``.

    Returns
    -------
    float or array (S...)

    Notes
    -----
    .. math::
        \\omega T \\approx \\sqrt{2\\beta}\\;
        10^{\\,e\\,\\ln(\\pi/\\sqrt{2\\beta})/\\ln(\\alpha/2)},\\qquad e = -0.15,

    the line from (:math:`\\sqrt{2\\beta}`, 0 dB) to (:math:`\\pi`,
    :math:`20\\log_{10}(\\alpha/2)` dB, eq 50 for small :math:`\\beta`) on log-log axes.

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eq 53, as printed.
    """
    a, _, _ = require_gains(gains).as_arrays()
    a = check_in_range("alpha", a, 0.0, 2.0)
    b = _beta(gains, 0.0)
    e = check_finite("exponent", exponent)
    w1 = np.sqrt(2.0 * b)
    return scalar_or_array(w1 * 10.0 ** (e * np.log(np.pi / w1) / np.log(a / 2.0)))


def omega_max_eq54(gains: Gains):
    """Seed 000, eq 54: :math:`\\omega T_{max} \\approx \\sqrt{\\beta/2}`.

    Parameters
    ----------
    gains : Gains
        Canonical gains with :math:`\\beta \\ge 0`, scalars or a bank of shape ``S``.

    Returns
    -------
    float or array (S...)
        Half of eq 52's unity-gain frequency.

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eq 54, as printed.
    """
    return scalar_or_array(np.sqrt(_beta(gains, 0.0, low_inclusive=True) / 2.0))


def overshoot_eq55_terms(gains: Gains) -> dict:
    """The auxiliary quantities of seed 000, eqs 56-59, as printed.

    Parameters
    ----------
    gains : Gains
        Canonical gains, scalars or a bank of shape ``S``.

    Returns
    -------
    dict
        ``n`` (eq 59), ``M`` (eq 56), ``N2`` (eq 57), ``D`` (eq 58), each a float or
        array (S...).

    Notes
    -----
    :math:`n = \\alpha\\beta/2 - \\gamma + 3\\beta^2/8`,
    :math:`M = \\tfrac38\\beta^2(1-\\alpha)(n + \\beta/3)`,
    :math:`N^2 = \\beta^3(1-\\alpha)^2 n^2/16`, :math:`D = n^2 + \\beta^3/8`.

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eqs 56-59, as printed.
    """
    a, b, g = require_gains(gains).as_arrays()
    n = a * b / 2.0 - g + 3.0 / 8.0 * b**2
    M = 3.0 / 8.0 * b**2 * (1.0 - a) * (n + b / 3.0)
    N2 = b**3 * (1.0 - a) ** 2 * n**2 / 16.0
    D = n**2 + b**3 / 8.0
    return {
        "n": scalar_or_array(n),
        "M": scalar_or_array(M),
        "N2": scalar_or_array(N2),
        "D": scalar_or_array(D),
    }


def overshoot_eq55(gains: Gains):
    """Seed 000, eq 55, as printed: overshoot :math:`\\approx M/D + (M^2 + N^2)/(2D^2)`.

    Parameters
    ----------
    gains : Gains
        Canonical gains with :math:`D \\ne 0` (eq 58; :math:`D > 0` whenever
        :math:`\\beta > 0`), scalars or a bank of shape ``S``.

    Returns
    -------
    float or array (S...)

    Notes
    -----
    Steelman's approximation of ``max |Xbar/X| - 1`` at :math:`\\omega T_{max}`, with
    ``M, N^2, D, n`` from eqs 56-59 (:func:`overshoot_eq55_terms`). Compare the exact
    :func:`peak`.

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eqs 55-59, as printed.
    """
    t = overshoot_eq55_terms(gains)
    M, N2, D = (np.asarray(t[k]) for k in ("M", "N2", "D"))
    if np.any(D == 0.0):
        raise AbglibValueError(f"eq 55 needs D != 0 (eq 58), got {describe(D)}")
    return scalar_or_array(M / D + (M**2 + N2) / (2.0 * D**2))
