r"""Gain-design rules of the sources: each function returns canonical :class:`~abglib.Gains`.

Every rule cites the equation it implements; conventions other than the canonical one
(seed 000, eqs 1-6) are converted in :mod:`abglib.conventions` only.

Rules
-----
standard_ab, standard_abg
    Critically damped / fading-memory gains in terms of theta (seed 000, eqs 22-24 and
    the alpha-beta pair after eq 30).
standard_theta_from_alpha, standard_from_alpha
    Their inverse: theta (and the gains) for a given alpha.
qd, qd_m_from_alpha
    Second-order QD tracker (seed 000, eqs 28-30) and the m giving a wanted alpha.
benedict_bordner (alias m1)
    beta = alpha^2 / (2 - alpha) (seed 001, eq 23b; method M1).
simpson, simpson_gamma, simpson_beta
    Simpson's optimality condition (seed 000, eq 21) solved for the missing gain.
growing_memory
    Time-varying least-squares gains (seed 001, eqs 24a-b; method M2).
huang_type1, huang_type2, huang_for_enbw
    Huang et al.'s type I / type II selections (seed 002) and the inverse for a wanted
    equivalent noise bandwidth.
bendix
    The gains of the Bendix filter test (seed 003): memo table and plot captions.
kalata_ab, kalata_abg, steady_state_kalman
    Steady-state Kalman gains: Kalata's tracking-index closed forms and the discrete
    algebraic Riccati equation.
"""

from __future__ import annotations

import numbers

import numpy as np

from ._checks import (
    AbglibValueError,
    check_in_range,
    check_positive,
    describe,
    scalar_or_array,
)
from .conventions import from_huang
from .gains import Gains

__all__ = [
    "BENDIX_CAPTIONS",
    "BENDIX_MEMO",
    "benedict_bordner",
    "bendix",
    "growing_memory",
    "huang_for_enbw",
    "huang_type1",
    "huang_type2",
    "kalata_ab",
    "kalata_abg",
    "m1",
    "qd",
    "qd_m_from_alpha",
    "simpson",
    "simpson_beta",
    "simpson_gamma",
    "standard_ab",
    "standard_abg",
    "standard_from_alpha",
    "standard_theta_from_alpha",
    "steady_state_kalman",
]


# --------------------------------------------------------------------------- helpers
def _check_order(order) -> int:
    if isinstance(order, bool) or order not in (2, 3):
        raise AbglibValueError(
            f"order must be 2 (alpha-beta) or 3 (alpha-beta-gamma), got {order!r}"
        )
    return int(order)


def _check_choice(name: str, value, allowed) -> str:
    if value not in allowed:
        raise AbglibValueError(
            f"{name} must be one of {', '.join(map(repr, allowed))}, got {value!r}"
        )
    return value


def _check_int(name: str, value, low: int) -> int:
    ok = isinstance(value, numbers.Integral) and not isinstance(value, bool)
    if not ok and isinstance(value, numbers.Real) and float(value).is_integer():
        ok, value = True, int(value)
    if not ok or value < low:
        raise AbglibValueError(f"{name} must be an integer >= {low}, got {value!r}")
    return int(value)


def _gains(alpha, beta, gamma=0.0) -> Gains:
    return Gains(scalar_or_array(alpha), scalar_or_array(beta), scalar_or_array(gamma))


def _require_stable_design(gains: Gains, rule: str, **inputs) -> Gains:
    """``gains`` if every gain set of the bank is stable, else an error naming the inputs.

    For rules whose domain does not guarantee stability (Simpson's condition leaves one
    degree of freedom, and large alpha with a given gamma gives beta beyond the Jury
    bounds of seed 000, eqs 45-47).
    """
    from .analysis import is_stable, pole_radius

    stable = np.asarray(is_stable(gains))
    if stable.all():
        return gains
    i = tuple(np.argwhere(~stable)[0]) if stable.ndim else ()
    given = ", ".join(
        f"{k}={describe(np.asarray(v)[i] if np.ndim(v) else v)}" for k, v in inputs.items()
    )
    g = gains[i] if stable.ndim else gains
    raise AbglibValueError(
        f"{rule}: the gains for {given} are unstable ({g!r}, pole radius "
        f"{float(pole_radius(g)):.6g} >= 1, against seed 000, eqs 45-47); the rule does not "
        "imply stability: choose other inputs or another rule"
    )


# --------------------------------------------------------------------------- standard
def standard_ab(theta) -> Gains:
    r"""Critically damped ("standard", fading-memory degree 1) alpha-beta gains.

    Parameters
    ----------
    theta : float or array (...)
        Fading-memory parameter (the double pole of the tracker), ``0 <= theta < 1``.

    Returns
    -------
    Gains
        ``alpha``, ``beta`` (``gamma = 0``), shaped like ``theta``.

    Notes
    -----
    Seed 000, the unnumbered pair after eq 30 (Kahrilas; Morrison's fading-memory
    polynomial of degree 1):

    .. math:: \alpha = 1 - \theta^2,\qquad \beta = (1 - \theta)^2 .

    The characteristic polynomial (seed 000, eq 41) is then :math:`(z - \theta)^2`.

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), unnumbered gains before eq 31 (critically damped
    alpha-beta) and eq 41 (characteristic polynomial).

    Examples
    --------
    >>> g = standard_ab(0.5)
    >>> g.alpha, g.beta
    (0.75, 0.25)
    """
    th = check_in_range("theta", theta, 0.0, 1.0, low_inclusive=True)
    return _gains(1.0 - th**2, (1.0 - th) ** 2)


def standard_abg(theta) -> Gains:
    r"""Critically damped ("standard", fading-memory degree 2) alpha-beta-gamma gains.

    Parameters
    ----------
    theta : float or array (...)
        Fading-memory parameter (the triple pole of the tracker), ``0 <= theta < 1``.

    Returns
    -------
    Gains
        Canonical ``alpha``, ``beta``, ``gamma``, shaped like ``theta``.

    Notes
    -----
    Seed 000, eqs 22-24 (Kahrilas; Morrison's fading-memory polynomial of degree 2):

    .. math::
        \alpha = 1 - \theta^3,\qquad
        \beta = \tfrac32 (1 - \theta)^2 (1 + \theta),\qquad
        \gamma = (1 - \theta)^3 .

    The characteristic polynomial (seed 000, eq 40) is then :math:`(z - \theta)^3`.

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eqs 22-24 (critically damped alpha-beta-gamma)
    and eq 40 (characteristic polynomial).

    Examples
    --------
    >>> g = standard_abg(0.5)
    >>> g.alpha, g.beta, g.gamma
    (0.875, 0.5625, 0.125)
    """
    th = check_in_range("theta", theta, 0.0, 1.0, low_inclusive=True)
    return _gains(1.0 - th**3, 1.5 * (1.0 - th) ** 2 * (1.0 + th), (1.0 - th) ** 3)


def standard_theta_from_alpha(alpha, order=2):
    r"""The theta of the standard (critically damped) tracker with the given alpha.

    Parameters
    ----------
    alpha : float or array (...)
        Position gain, ``0 < alpha <= 1`` (theta in ``[0, 1)``).
    order : {2, 3}, default 2
        2 for alpha-beta (seed 000, after eq 30), 3 for alpha-beta-gamma (eq 22).

    Returns
    -------
    theta : float or array (...)

    Notes
    -----
    Inverse of seed 000, eq 22 (order 3) and of the alpha-beta pair after eq 30:

    .. math:: \theta = (1 - \alpha)^{1/2}\ \text{(order 2)},\qquad
              \theta = (1 - \alpha)^{1/3}\ \text{(order 3)} .

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eq 22 (order 3) and the unnumbered
    alpha-beta gains after eq 30 (order 2), inverted.

    Examples
    --------
    >>> round(standard_theta_from_alpha(0.3, order=3), 6)
    0.887904
    """
    order = _check_order(order)
    a = check_in_range("alpha", alpha, 0.0, 1.0, high_inclusive=True)
    theta = np.sqrt(1.0 - a) if order == 2 else np.cbrt(1.0 - a)
    return scalar_or_array(theta)


def standard_from_alpha(alpha, order=2) -> Gains:
    r"""Standard (critically damped) gains with the given alpha.

    Parameters
    ----------
    alpha : float or array (...)
        Position gain, ``0 < alpha <= 1``.
    order : {2, 3}, default 2
        2: :func:`standard_ab`; 3: :func:`standard_abg`.

    Returns
    -------
    Gains

    Notes
    -----
    :func:`standard_theta_from_alpha` followed by seed 000, eqs 22-24 (order 3) or the
    alpha-beta pair after eq 30 (order 2). Steelman's Tables 1-2 use this rule for
    alpha = 0.3 and 0.246.

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eqs 22-24 (order 3) and the unnumbered
    alpha-beta gains before eq 31 (order 2).

    Examples
    --------
    >>> g = standard_from_alpha(0.3, order=3)
    >>> round(g.beta, 4), round(g.gamma, 4)
    (0.0356, 0.0014)
    """
    theta = standard_theta_from_alpha(alpha, order)
    return standard_ab(theta) if _check_order(order) == 2 else standard_abg(theta)


# --------------------------------------------------------------------------- QD
def qd(m) -> Gains:
    r"""Gains of the second-order QD tracker over ``m`` points.

    Parameters
    ----------
    m : float or array (...)
        Number of points of the least-squares fit, ``m > 1`` (Steelman treats it as a
        continuous parameter, e.g. 16.6).

    Returns
    -------
    Gains

    Notes
    -----
    Seed 000, eqs 28-30 (McCool; Shepherd):

    .. math::
        \alpha = \frac{60 m^2}{10 m^3 + 33 m^2 + 23 m - 6},\qquad
        \beta = \frac{2\alpha}{m},\qquad \gamma = \frac{2\alpha}{m^2} .

    Alpha is 1 at ``m = 1`` and ``m = 1.2``, slightly above 1 in between, and decreases
    for ``m > 1.2``.

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eqs 28-30 (the QD tracker; McCool, Shepherd).

    Examples
    --------
    >>> round(qd(21).alpha, 3)
    0.246
    """
    m = check_in_range("m", m, 1.0, None)
    alpha = 60.0 * m**2 / (10.0 * m**3 + 33.0 * m**2 + 23.0 * m - 6.0)
    return _gains(alpha, 2.0 * alpha / m, 2.0 * alpha / m**2)


def _qd_m_scalar(a: float) -> float:
    # seed 000, eq 28 rearranged: 10 a m^3 + (33 a - 60) m^2 + 23 a m - 6 a = 0
    coeffs = [10.0 * a, 33.0 * a - 60.0, 23.0 * a, -6.0 * a]
    roots = np.roots(coeffs)
    m = float(max(r.real for r in roots if abs(r.imag) <= 1e-9 * max(1.0, abs(r))))
    for _ in range(3):  # Newton polish on the cubic
        f = np.polyval(coeffs, m)
        df = np.polyval(np.polyder(coeffs), m)
        if df == 0.0:
            break
        m -= f / df
    return m


def qd_m_from_alpha(alpha):
    r"""The ``m`` for which the QD tracker (seed 000, eq 28) has the given alpha.

    Parameters
    ----------
    alpha : float or array (...)
        Position gain, ``0 < alpha <= 1``.

    Returns
    -------
    m : float or array (...)
        The root ``m >= 1.2`` of the cubic (on the branch where alpha decreases with m).

    Notes
    -----
    Seed 000, eq 28 rearranged as a cubic in ``m``:

    .. math:: 10\alpha m^3 + (33\alpha - 60) m^2 + 23\alpha m - 6\alpha = 0 .

    Its largest real root is returned. Steelman's "the m required to produce
    alpha = .3 is 16.6" is this root, 16.5633, rounded.

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eq 28, solved for ``m``.

    Examples
    --------
    >>> round(qd_m_from_alpha(0.3), 4)
    16.5633
    """
    a = check_in_range("alpha", alpha, 0.0, 1.0, high_inclusive=True)
    m = np.vectorize(_qd_m_scalar, otypes=[float])(a)
    return scalar_or_array(m)


# --------------------------------------------------------------------------- BB, Simpson
def benedict_bordner(alpha) -> Gains:
    r"""Benedict-Bordner alpha-beta gains: ``beta = alpha^2 / (2 - alpha)``.

    Parameters
    ----------
    alpha : float or array (...)
        Position gain, ``0 < alpha <= 1`` (seed 001, eq 23a).

    Returns
    -------
    Gains
        ``gamma = 0``.

    Notes
    -----
    Seed 001, eq 23b (method M1; Benedict & Bordner 1962). It is Simpson's condition
    (seed 000, eq 21) with ``gamma = 0``:

    .. math:: \beta = \frac{\alpha^2}{2 - \alpha} .

    References
    ----------
    Al-Wagih & Abdulla, seed 001 (``alwagih``), eqs 23a-23b (method M1; Benedict & Bordner 1962).
    Steelman (1978), seed 000 (``steelman1978``), eq 21 (Simpson's condition) with gamma = 0.

    Examples
    --------
    >>> benedict_bordner(0.5).beta
    0.16666666666666666
    """
    a = check_in_range("alpha", alpha, 0.0, 1.0, high_inclusive=True)
    return _gains(a, a**2 / (2.0 - a))


# Method M1 of seed 001 is the Benedict-Bordner rule (seed 001, eqs 23a-b): the same
# function under the paper's name (listed with the functions, not as a constant)
m1 = benedict_bordner


def simpson_gamma(alpha, beta, *, allow_unstable: bool = False) -> Gains:
    r"""Complete ``(alpha, beta)`` with the gamma of Simpson's condition.

    Parameters
    ----------
    alpha : float or array (...)
        ``0 < alpha < 2``.
    beta : float or array (...)
        ``beta >= alpha^2 / (2 - alpha)`` (the Benedict-Bordner value, where
        ``gamma = 0``), so that ``gamma >= 0`` (seed 000, eq 48).

    allow_unstable : bool, default False
        Return the gains even where they are unstable (Simpson's condition does not
        imply stability: e.g. alpha = 1.99, gamma = 0.05 gives beta = 401).

    Returns
    -------
    Gains


    Raises
    ------
    AbglibValueError
        Inputs outside their domain, or (unless ``allow_unstable``) inputs whose Simpson
        gains are unstable, naming them and the pole radius.

    Notes
    -----
    Seed 000, eq 21, :math:`2\beta - \alpha(\alpha + \beta + \gamma/2) = 0`, solved
    for gamma:

    .. math:: \gamma = \frac{4\beta}{\alpha} - 2\alpha - 2\beta .

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eq 21, solved for gamma; stability: eqs 45-48.

    Examples
    --------
    >>> round(simpson_gamma(0.5, 0.175).gamma, 12)
    0.05
    """
    a = check_in_range("alpha", alpha, 0.0, 2.0)
    b = check_positive("beta", beta)
    a, b = np.broadcast_arrays(a, b)
    b_min = a**2 / (2.0 - a)
    bad = b < b_min * (1.0 - 1e-12)
    if bad.any():
        i = np.argwhere(bad)[0] if bad.ndim else ()
        i = tuple(i)
        raise AbglibValueError(
            "beta must satisfy beta >= alpha**2 / (2 - alpha) (the Benedict-Bordner value) "
            f"so that Simpson's gamma >= 0 (seed 000, eqs 21, 48); for alpha={describe(a[i])} "
            f"that is beta >= {b_min[i]:.6g}, got {describe(b[i])}"
        )
    gamma = np.maximum(4.0 * b / a - 2.0 * a - 2.0 * b, 0.0)
    g = _gains(a, b, gamma)
    return g if allow_unstable else _require_stable_design(g, "simpson_gamma", alpha=a, beta=b)


def simpson_beta(alpha, gamma, *, allow_unstable: bool = False) -> Gains:
    r"""Complete ``(alpha, gamma)`` with the beta of Simpson's condition.

    Parameters
    ----------
    alpha : float or array (...)
        ``0 < alpha < 2``.
    gamma : float or array (...)
        ``gamma >= 0`` (canonical convention).

    allow_unstable : bool, default False
        Return the gains even where they are unstable (Simpson's condition does not
        imply stability: e.g. alpha = 1.99, gamma = 0.05 gives beta = 401).

    Returns
    -------
    Gains


    Raises
    ------
    AbglibValueError
        Inputs outside their domain, or (unless ``allow_unstable``) inputs whose Simpson
        gains are unstable, naming them and the pole radius.

    Notes
    -----
    Seed 000, eq 21 solved for beta:

    .. math:: \beta = \frac{\alpha(\alpha + \gamma/2)}{2 - \alpha} .

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eq 21, solved for beta.

    Examples
    --------
    >>> round(simpson_beta(0.5, 0.05).beta, 12)
    0.175
    """
    a = check_in_range("alpha", alpha, 0.0, 2.0)
    g = check_in_range("gamma", gamma, 0.0, None, low_inclusive=True)
    out = _gains(a, a * (a + g / 2.0) / (2.0 - a), g)
    return out if allow_unstable else _require_stable_design(out, "simpson_beta", alpha=a, gamma=g)


def simpson(alpha, beta=None, gamma=None, *, allow_unstable: bool = False) -> Gains:
    r"""Gains satisfying Simpson's optimality condition, given alpha and one other gain.

    Parameters
    ----------
    alpha : float or array (...)
        ``0 < alpha < 2``.
    beta, gamma : float or array (...), optional
        Exactly one of them; the other is solved for (:func:`simpson_gamma`,
        :func:`simpson_beta`).

    allow_unstable : bool, default False
        Return the gains even where they are unstable (Simpson's condition does not
        imply stability: e.g. alpha = 1.99, gamma = 0.05 gives beta = 401).

    Returns
    -------
    Gains


    Raises
    ------
    AbglibValueError
        Inputs outside their domain, or (unless ``allow_unstable``) inputs whose Simpson
        gains are unstable, naming them and the pole radius.

    Notes
    -----
    Seed 000, eq 21 (Simpson 1963), which minimises all the performance measures of
    eqs 11-20 but leaves one degree of freedom:

    .. math:: 2\beta - \alpha\left(\alpha + \beta + \frac{\gamma}{2}\right) = 0 .

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eq 21 (Simpson 1963), minimising eqs 11-20.

    Examples
    --------
    >>> simpson(0.5, gamma=0.05) == simpson_beta(0.5, 0.05)
    True
    """
    if (beta is None) == (gamma is None):
        raise AbglibValueError(
            "simpson needs exactly one of beta and gamma (the other is solved from "
            f"seed 000, eq 21), got beta={beta!r}, gamma={gamma!r}"
        )
    if gamma is None:
        return simpson_gamma(alpha, beta, allow_unstable=allow_unstable)
    return simpson_beta(alpha, gamma, allow_unstable=allow_unstable)


# --------------------------------------------------------------------------- growing memory
def growing_memory(n_samples, start=1) -> Gains:
    r"""Time-varying (growing-memory, least-squares line) alpha-beta gains.

    Parameters
    ----------
    n_samples : int
        Number of samples (length of the time axis), ``>= 1``.
    start : int, default 1
        1-based sample number ``n`` of the first sample (``>= 1``).

    Returns
    -------
    Gains
        ``alpha`` and ``beta`` arrays of shape ``(n_samples,)`` for
        ``n = start, ..., start + n_samples - 1``; pass to :func:`abglib.track` as
        time-varying gains.

    Notes
    -----
    Seed 001, eqs 24a-b (method M2; the expanding-memory polynomial filter of degree 1):

    .. math:: \alpha_n = \frac{2(2n - 1)}{n(n + 1)},\qquad \beta_n = \frac{6}{n(n + 1)} .

    ``n = 1`` gives ``alpha = 1, beta = 3`` and ``n = 2`` gives ``alpha = beta = 1``: run
    from a zero state, the first two samples leave exactly the two-point initial state of
    seed 001, eqs 9-10 (``x = z_2``, ``v = (z_2 - z_1) / T``, whatever beta_1 is), and
    each later smoothed position is the least-squares line through all samples so far.
    Seed 001 states the rule for ``n > 2``.

    References
    ----------
    Al-Wagih & Abdulla, seed 001 (``alwagih``), eqs 24a-b (method M2) and the two-point start
    of eqs 9-10.

    Examples
    --------
    >>> g = growing_memory(4)
    >>> g.alpha.tolist(), g.beta.tolist()
    ([1.0, 1.0, 0.8333333333333334, 0.7], [3.0, 1.0, 0.5, 0.3])
    """
    n_samples = _check_int("n_samples", n_samples, 1)
    start = _check_int("start", start, 1)
    n = np.arange(start, start + n_samples, dtype=float)
    return Gains(2.0 * (2.0 * n - 1.0) / (n * (n + 1.0)), 6.0 / (n * (n + 1.0)))


# --------------------------------------------------------------------------- Huang
def huang_type1(xi, order=2) -> Gains:
    r"""Huang et al.'s type I selection (minimum mean-square tracking error).

    Parameters
    ----------
    xi : float or array (...)
        ``alpha = xi``; ``0 < xi <= 1`` for ``order=2``, ``0 < xi < 1`` for ``order=3``
        (``xi = 1`` puts a pole on the unit circle).
    order : {2, 3}, default 2

    Returns
    -------
    Gains
        Canonical gains (converted from Huang's convention by
        :func:`abglib.conventions.from_huang`).

    Notes
    -----
    Seed 002, "Loop parameters selecting", type I, in Huang's convention
    (``gamma_H = gamma / 2``). Alpha-beta (Benedict-Bordner, seed 001 eq 23b):

    .. math:: \alpha = \xi,\qquad \beta = \frac{\alpha^2}{2 - \alpha} .

    Alpha-beta-gamma: :math:`\alpha = \xi`, :math:`2\beta = \alpha(\alpha + \beta +
    \gamma_H)`, :math:`\beta^2 = 4\alpha\gamma_H`. Eliminating :math:`\gamma_H` gives
    :math:`\beta^2/4 + (\alpha - 2)\beta + \alpha^2 = 0`, whose root with
    :math:`2\alpha + \beta < 4` is

    .. math:: \beta = 2\left(1 - \sqrt{1 - \alpha}\right)^2,\qquad
              \gamma_H = \frac{\beta^2}{4\alpha} .

    The first equation is Simpson's (seed 000, eq 21); together they are the
    steady-state Kalman gains of the white-acceleration-increment model
    (:func:`kalata_abg`).

    References
    ----------
    Huang, Yang & Ma, seed 002 (``huang``), type I selection (Fig 2), gains in its eq 3
    convention; Steelman (1978), seed 000 (``steelman1978``), eq 21 (Simpson's condition).

    Examples
    --------
    >>> g = huang_type1(0.61, order=3)
    >>> round(g.beta, 2), round(g.gamma / 2, 4)
    (0.28, 0.0326)
    """
    order = _check_order(order)
    if order == 2:
        x = check_in_range("xi", xi, 0.0, 1.0, high_inclusive=True)
        return from_huang(scalar_or_array(x), scalar_or_array(x**2 / (2.0 - x)), 0.0)
    x = check_in_range("xi", xi, 0.0, 1.0)
    beta = 2.0 * (x / (1.0 + np.sqrt(1.0 - x))) ** 2  # = 2(1 - sqrt(1 - x))^2, no cancellation
    gamma_h = beta**2 / (4.0 * x)
    return from_huang(scalar_or_array(x), scalar_or_array(beta), scalar_or_array(gamma_h))


def huang_type2(xi, order=2) -> Gains:
    r"""Huang et al.'s type II selection (critical damping).

    Parameters
    ----------
    xi : float or array (...)
        Smoothing factor, ``0 <= xi < 1`` (``xi -> 1``: deep smoothing).
    order : {2, 3}, default 2

    Returns
    -------
    Gains
        Canonical gains (via :func:`abglib.conventions.from_huang`).

    Notes
    -----
    Seed 002, "Loop parameters selecting", type II, in Huang's convention:

    .. math::
        \alpha = 1 - \xi^2,\ \beta = (1 - \xi)^2\ \text{(alpha-beta)};\qquad
        \alpha = 1 - \xi^3,\ \beta = 1.5(1 - \xi)^2(1 + \xi),\quad
        \gamma_H = \frac{(1 - \xi)^3}{2}\ \text{(alpha-beta-gamma)} .

    In the canonical convention this is Steelman's standard tracker with
    ``theta = xi`` (seed 000, eqs 22-24 and after eq 30).

    References
    ----------
    Huang, Yang & Ma, seed 002 (``huang``), type II selection (Fig 3);
    Steelman (1978), seed 000 (``steelman1978``), eqs 22-24: the standard tracker with theta = xi.

    Examples
    --------
    >>> g = huang_type2(0.55, order=3)
    >>> round(g.alpha, 2), round(g.beta, 2), round(g.gamma / 2, 3)
    (0.83, 0.47, 0.046)
    """
    order = _check_order(order)
    x = check_in_range("xi", xi, 0.0, 1.0, low_inclusive=True)
    if order == 2:
        return from_huang(scalar_or_array(1.0 - x**2), scalar_or_array((1.0 - x) ** 2), 0.0)
    return from_huang(
        scalar_or_array(1.0 - x**3),
        scalar_or_array(1.5 * (1.0 - x) ** 2 * (1.0 + x)),
        scalar_or_array((1.0 - x) ** 3 / 2.0),
    )


def _enbw(gains: Gains, dt: float) -> float:
    """One-sided ENBW in Hz of the x_pred transfer function (:func:`abglib.analysis.enbw`)."""
    from .analysis import enbw

    return float(enbw(gains, dt))


def huang_for_enbw(bn_hz, dt, rule="type1", order=2) -> Gains:
    r"""Huang type I or type II gains with a given equivalent noise bandwidth.

    Parameters
    ----------
    bn_hz : float
        Wanted one-sided ENBW ``B_n`` in Hz, > 0.
    dt : float
        Sample interval ``T`` in seconds, > 0 (seed 002 uses ``1 / F_r``).
    rule : {"type1", "type2"}, default "type1"
        :func:`huang_type1` or :func:`huang_type2`.
    order : {2, 3}, default 2

    Returns
    -------
    Gains
        The gains of the rule at the ``xi`` whose ENBW is ``bn_hz`` (``xi = alpha`` for
        type I; ``xi = theta`` of :func:`standard_theta_from_alpha` for type II).

    Raises
    ------
    ValueError
        If ``bn_hz`` is outside what the rule reaches over its ``xi`` domain; the
        message gives that range.

    Notes
    -----
    ``B_n`` is :func:`abglib.analysis.enbw` (seed 002, eq 8: :math:`B_n =
    \sum_k h_k^2 / (2T)` for the impulse response :math:`h_k` of the x_pred transfer
    function, seed 002 eq 3; eq 14 for alpha-beta). It increases monotonically with
    ``xi`` for type I and decreases for type II, so ``B_n T = f(xi)`` is solved with
    :func:`scipy.optimize.brentq`. Reachable ``B_n T``: type I order 2 and type II
    order 2 up to 2.5 (deadbeat ``alpha = beta = 1``), type II order 3 up to 9.5
    (``xi = 0``), type I order 3 unbounded (``xi -> 1``).

    References
    ----------
    Huang, Yang & Ma, seed 002 (``huang``), eq 8 (ENBW), eqs 9-14 and Figs 2-3 (B_n T against
    xi for the type I and type II selections).

    Examples
    --------
    >>> g = huang_for_enbw(20.0, 1 / 300, rule="type2", order=2)
    >>> round(standard_theta_from_alpha(g.alpha), 3)  # seed 002 Table 2 prints xi = 0.9
    0.903
    """
    bn = float(check_positive("bn_hz", bn_hz))
    T = float(check_positive("dt", dt))
    rule = _check_choice("rule", rule, ("type1", "type2"))
    order = _check_order(order)
    design = huang_type1 if rule == "type1" else huang_type2

    # t: distance from the zero-bandwidth end of the xi domain; ENBW increases with t
    def xi_of(t):
        return t if rule == "type1" else 1.0 - t

    def f(t):
        return _enbw(design(xi_of(t), order), T) - bn

    domain = {
        ("type1", 2): "0 < xi <= 1",
        ("type1", 3): "0 < xi < 1",
        ("type2", 2): "0 <= xi < 1",
        ("type2", 3): "0 <= xi < 1",
    }[rule, order]

    def out_of_reach(lo: float, hi: float, lo_open: bool = True):
        return AbglibValueError(
            f"bn_hz={bn!r} with dt={T!r} is outside the ENBW range the {rule} order-{order} "
            f"rule reaches over {domain}: {lo:.6g} {'<' if lo_open else '<='} bn_hz <= "
            f"{hi:.6g} Hz"
        )

    if rule == "type1" and order == 3:
        t_hi = None
        for k in range(1, 13):  # xi -> 1 puts a pole on the unit circle: B_n -> infinity
            t = 1.0 - 10.0**-k
            if f(t) >= 0.0:
                t_hi = t
                break
        if t_hi is None:
            raise out_of_reach(0.0, bn + f(1.0 - 1e-12))
    else:
        t_hi = 1.0
        f_hi = f(t_hi)
        if f_hi < 0.0:
            raise out_of_reach(0.0, bn + f_hi)
    t_lo = 0.5 * t_hi
    while f(t_lo) > 0.0:
        if t_lo < 1e-9:
            raise out_of_reach(bn + f(t_lo), bn + f(t_hi), lo_open=False)
        t_lo *= 0.5
    if f(t_lo) == 0.0:
        return design(xi_of(t_lo), order)
    from scipy.optimize import brentq  # here: importing scipy costs ~0.3 s

    t = brentq(f, t_lo, t_hi, xtol=1e-15, rtol=4 * np.finfo(float).eps, maxiter=200)
    return design(xi_of(t), order)


# --------------------------------------------------------------------------- Bendix
#: The gains of the Bendix memo (seed 003), period (s) -> (alpha, beta), printed to three
#: decimals. The memo is A. I. Sinsky's "Expected Smoothing of Alpha-Beta Filter in TCAS
#: Simulation", its table "Update Rate Periods (sec) | Alpha | Beta | ...".
BENDIX_MEMO = {
    1: (0.250, 0.066),
    2: (0.370, 0.175),
    3: (0.465, 0.300),
    4: (0.530, 0.431),
    5: (0.580, 0.565),
    6: (0.620, 0.685),
    7: (0.645, 0.855),
    8: (0.665, 0.910),
}

#: The gains of the Bendix plot captions (seed 003), period (s) -> (alpha, beta), printed
#: to two decimals. They are the memo's values truncated, not rounded (beta 0.066 -> 0.06,
#: alpha 0.465 -> 0.46), in the 48 captions "... ALPHA= 0.25 BETA= 0.06 T= 1.00 SECONDS ...".
BENDIX_CAPTIONS = {
    1: (0.25, 0.06),
    2: (0.37, 0.17),
    3: (0.46, 0.30),
    4: (0.53, 0.43),
    5: (0.58, 0.56),
    6: (0.62, 0.68),
    7: (0.64, 0.85),
    8: (0.66, 0.91),
}


def bendix(period_s, table="memo") -> Gains:
    r"""Alpha-beta gains of the Bendix TCAS filter test for an update period.

    Parameters
    ----------
    period_s : int
        Update period in seconds, one of 1, 2, ..., 8.
    table : {"memo", "captions"}, default "memo"
        ``"memo"``: Sinsky's memo table (3 decimals, :data:`BENDIX_MEMO`);
        ``"captions"``: the values printed in the plot captions (2 decimals,
        :data:`BENDIX_CAPTIONS`), which are the ones the plotted runs used.

    Returns
    -------
    Gains
        ``gamma = 0``.

    Notes
    -----
    Seed 003 gives the gains as a table, not a formula (selected by S. Guarino; Bendix
    TN FB-467-012, p. 4).

    References
    ----------
    Elwell and Sinsky, FAA Bendix letter report, seed 003 (``faa_bendix``): the memo's table of
    gains and smoothing ratios for update periods 1-8 s (``table="memo"``) and the 48 plot captions
    (``table="captions"``).

    Examples
    --------
    >>> bendix(3)
    Gains(alpha=0.465, beta=0.3, gamma=0)
    >>> bendix(3, table="captions")
    Gains(alpha=0.46, beta=0.3, gamma=0)
    """
    table = _check_choice("table", table, ("memo", "captions"))
    source = BENDIX_MEMO if table == "memo" else BENDIX_CAPTIONS
    p = None
    if isinstance(period_s, numbers.Real) and not isinstance(period_s, bool):
        if float(period_s).is_integer():
            p = int(period_s)
    if p not in source:
        raise AbglibValueError(
            "period_s must be one of "
            f"{', '.join(str(k) for k in source)} (seconds; seed 003 {table}), got {period_s!r}"
        )
    return Gains(*source[p])


# --------------------------------------------------------------------------- Kalman
def kalata_ab(tracking_index) -> Gains:
    r"""Steady-state Kalman alpha-beta gains from Kalata's tracking index.

    Parameters
    ----------
    tracking_index : float or array (...)
        :math:`\Lambda = \sigma_w T^2 / \sigma_n` > 0, with :math:`\sigma_w` the standard
        deviation of the (piecewise-constant, white) target acceleration and
        :math:`\sigma_n` that of the position measurement noise.

    Returns
    -------
    Gains

    Notes
    -----
    Kalata (1984), "The tracking index: a generalized parameter for alpha-beta and
    alpha-beta-gamma target trackers", IEEE Trans. AES-20:

    .. math::
        r = \frac{4 + \Lambda - \sqrt{8\Lambda + \Lambda^2}}{4},\qquad
        \alpha = 1 - r^2,\qquad \beta = 2(2 - \alpha) - 4\sqrt{1 - \alpha}
        \ (= 2(1 - r)^2) .

    These are exactly (to rounding) the a-posteriori steady-state Kalman gains of the
    piecewise-constant white-acceleration model, :math:`\Gamma = [T^2/2, T]^T`
    (:func:`steady_state_kalman` with ``model="piecewise_constant"``); equivalently
    :math:`\Lambda^2 = \beta^2 / (1 - \alpha)`.

    References
    ----------
    P. R. Kalata, The tracking index: a generalized parameter for
    alpha-beta and alpha-beta-gamma target trackers, IEEE Trans. AES-20,
    1984 (not a seed document; cited by seed 001); the gains drive
    Steelman (1978), seed 000 (``steelman1978``), eqs 1-3.

    Examples
    --------
    >>> g = kalata_ab(1.0)
    >>> round(g.alpha, 6), round(g.beta, 6)
    (0.75, 0.5)
    """
    lam = check_positive("tracking_index", tracking_index)
    # r = (4 + lam - sqrt(8 lam + lam^2)) / 4 without the cancellation that makes it 0
    # (and the gains the unstable (1, 2)) for a large index: with s = sqrt(1 + 8/lam),
    # r = (8/lam) / (1 + s)^2 exactly
    s = np.sqrt(1.0 + 8.0 / lam)
    r = (8.0 / lam) / (1.0 + s) ** 2
    return _gains(1.0 - r**2, 2.0 * (1.0 - r) ** 2)


def kalata_abg(tracking_index) -> Gains:
    r"""Steady-state Kalman alpha-beta-gamma gains from the tracking index.

    Parameters
    ----------
    tracking_index : float or array (...)
        :math:`\Lambda = \sigma_w T^2 / \sigma_n` > 0, :math:`\sigma_w` the standard
        deviation of the white acceleration increment per sample (Wiener-process
        acceleration, :math:`\Gamma = [T^2/2, T, 1]^T`).

    Returns
    -------
    Gains
        Canonical gains (``gamma`` multiplies ``r / T^2``).

    Notes
    -----
    Kalata (1984) and Gray & Murray (1993), "A derivation of an analytic expression for
    the tracking index for the alpha-beta-gamma filter", IEEE Trans. AES-29. With
    :math:`s = \sqrt{1 - \alpha}` the steady-state gains satisfy (canonical convention)

    .. math::
        \alpha = 1 - s^2,\quad \beta = 2(1 - s)^2 = 2(2 - \alpha) - 4\sqrt{1 - \alpha},
        \quad \gamma = \frac{\beta^2}{2\alpha} = \frac{2(1 - s)^3}{1 + s},\quad
        \Lambda^2 = \frac{\gamma^2}{1 - \alpha},

    so :math:`s` is the root in (0, 1) of the cubic
    :math:`2(1 - s)^3 = \Lambda s (1 + s)` (Gray & Murray solve it in closed form; it
    is solved here by bisection to machine precision). These relations hold exactly for
    the :math:`\Gamma = [T^2/2, T, 1]^T` model (``model="piecewise_constant"`` of
    :func:`steady_state_kalman`, order 3), not for the piecewise-constant-jerk model
    :math:`\Gamma = [T^3/6, T^2/2, T]^T`. They also satisfy Simpson's condition
    (seed 000, eq 21) and Huang's type I equations (seed 002).

    References
    ----------
    P. R. Kalata, IEEE Trans. AES-20, 1984 (not a seed document); Steelman (1978), seed 000
    (``steelman1978``), eq 21 (Simpson's condition, which these gains satisfy).

    Examples
    --------
    >>> g = kalata_abg(0.5)
    >>> round(g.alpha, 4), round(g.beta, 4), round(g.gamma, 4)
    (0.7954, 0.5998, 0.2262)
    """
    lam = check_positive("tracking_index", tracking_index)
    lo = np.zeros_like(lam)
    hi = np.ones_like(lam)
    # g(s) = 2(1-s)^3 - lam s (1+s) is strictly decreasing on [0, 1]: g(0)=2, g(1)=-2 lam
    for _ in range(64):
        mid = 0.5 * (lo + hi)
        pos = 2.0 * (1.0 - mid) ** 3 - lam * mid * (1.0 + mid) > 0.0
        lo = np.where(pos, mid, lo)
        hi = np.where(pos, hi, mid)
    s = 0.5 * (lo + hi)
    return _gains(1.0 - s**2, 2.0 * (1.0 - s) ** 2, 2.0 * (1.0 - s) ** 3 / (1.0 + s))


def steady_state_kalman(q, r, dt=1.0, order=2, model="piecewise_constant") -> Gains:
    r"""Steady-state Kalman gains of a polynomial target model, from the DARE.

    Parameters
    ----------
    q : float or array (...)
        Process-noise intensity, > 0: the variance of the white input for the
        piecewise-constant models, its power spectral density for ``"continuous"``.
    r : float or array (...)
        Measurement-noise variance, > 0.
    dt : float or array (...), default 1.0
        Sample interval ``T``, > 0.
    order : {2, 3}, default 2
        2: state ``[x, v]``; 3: state ``[x, v, a]`` (transition of seed 000, eqs 4-6).
    model : {"piecewise_constant", "piecewise_constant_jerk", "continuous"}
        ``"piecewise_constant"``: :math:`x_{k+1} = \Phi x_k + \Gamma w_k` with
        :math:`\Gamma = [T^2/2, T]^T` (order 2: white acceleration held over each
        interval) or :math:`[T^2/2, T, 1]^T` (order 3: white acceleration increment,
        the "Wiener-process acceleration" model); ``"piecewise_constant_jerk"`` (order 3
        only): :math:`\Gamma = [T^3/6, T^2/2, T]^T`; ``"continuous"``: continuous white
        noise on the highest derivative, :math:`Q = q\int_0^T e^{A t} b b^T e^{A^T t} dt`.

    Returns
    -------
    Gains
        Canonical gains from the a-posteriori steady-state gain :math:`K = P^- H^T
        (H P^- H^T + r)^{-1}`: :math:`\alpha = K_1`, :math:`\beta = K_2 T`,
        :math:`\gamma = K_3 T^2`.

    Notes
    -----
    :math:`P^-` solves the filtering Riccati equation
    :math:`P = \Phi P \Phi^T - \Phi P H^T (H P H^T + r)^{-1} H P \Phi^T + Q`
    (:func:`abglib.analysis.kalman_gains`, one model at a time). The
    corrector of seed 000, eqs 1-3 is the Kalman update with gain
    :math:`[\alpha, \beta/T, \gamma/T^2]^T`. For ``"piecewise_constant"`` the result
    equals :func:`kalata_ab` / :func:`kalata_abg` with :math:`\Lambda = \sqrt{q}\,T^2 /
    \sqrt{r}`.

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eqs 1-6: the corrector (a Kalman update with
    gain [alpha, beta/T, gamma/T^2]) and the transition.

    Examples
    --------
    >>> g = steady_state_kalman(1.0, 1.0, dt=1.0, order=2)
    >>> round(g.alpha, 6), round(g.beta, 6)
    (0.75, 0.5)
    """
    from .analysis import KALMAN_MODELS, kalman_gains  # here: the analysis imports scipy

    order = _check_order(order)
    model = _check_choice("model", model, KALMAN_MODELS)
    if model == "piecewise_constant_jerk" and order != 3:
        raise AbglibValueError(
            f"model='piecewise_constant_jerk' needs order=3 (state [x, v, a]), got order={order}"
        )
    q = check_positive("q", q)
    r = check_positive("r", r)
    T = check_positive("dt", dt)
    q, r, T = np.broadcast_arrays(q, r, T)
    out = np.empty((3,) + q.shape)
    for idx in np.ndindex(q.shape):
        out[(slice(None),) + idx] = kalman_gains(
            float(q[idx]), float(r[idx]), float(T[idx]), order, model
        )
    alpha, beta, gamma = out
    return _gains(alpha, beta, gamma if order == 3 else 0.0)
