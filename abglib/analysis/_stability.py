"""Poles and stability of the tracker: the exact test and the printed criteria of the seeds.

:func:`is_stable` is the exact test (all poles strictly inside the unit circle), decided by
Jury's inequalities in closed form in the gains (from eq 40), so
that gains exactly on the boundary (a pole exactly on the unit circle) are classified
without rounding. :func:`poles` and :func:`pole_radius` give the numeric poles. The
criteria printed in the seeds are kept *as printed* under their own names
(``stable_jury_steelman``, ``stable_sufficient_eq49``; seed 001's eqs 12-14 are in
:mod:`abglib.replications.alwagih.stability`, seed 002's eqs 5 and 7 in
:mod:`abglib.replications.huang.printed`); the tests compare each with the truth and
pin the gains where a printed criterion is wrong.
"""

from __future__ import annotations

import numpy as np

from .._checks import AbglibValueError, scalar_or_array
from ..gains import Gains, require_gains

__all__ = [
    "characteristic_polynomial",
    "require_stable",
    "is_stable",
    "pole_radius",
    "poles",
    "stable_jury_steelman",
    "stable_sufficient_eq49",
]


def characteristic_polynomial(gains: Gains):
    """Monic characteristic polynomial of the tracker, descending powers of ``z``.

    Parameters
    ----------
    gains : Gains
        Canonical gains, scalars or a bank of shape ``S``.

    Returns
    -------
    array (S..., 4)
        ``[1, a2, a1, a0]`` of seed 000, eq 40 expanded. Where ``gamma == 0`` the
        uncontrollable pole at ``z = 1`` is divided out and the row is
        ``[0, 1, a1, a0]``, the quadratic of eq 41 (left-padded with 0).

    Notes
    -----
    Seed 000, eq 40 expanded:
    :math:`z^3 + (\\alpha + \\beta + \\gamma/2 - 3) z^2 + (3 - 2\\alpha - \\beta + \\gamma/2) z
    - (1 - \\alpha)`; eq 41 (:math:`\\gamma = 0`):
    :math:`z^2 + (\\alpha + \\beta - 2) z + (1 - \\alpha)`.

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eq 40 (eq 41 for gamma = 0).
    """
    a, b, g = require_gains(gains).as_arrays()
    cubic = np.stack(
        [np.ones_like(a), a + b + g / 2 - 3.0, 3.0 - 2.0 * a - b + g / 2, a - 1.0], axis=-1
    )
    quad = np.stack([np.zeros_like(a), np.ones_like(a), a + b - 2.0, 1.0 - a], axis=-1)
    return np.where((g == 0.0)[..., None], quad, cubic)


def poles(gains: Gains):
    """Poles of the tracker: roots of seed 000, eq 40 (eq 41 where ``gamma == 0``).

    Parameters
    ----------
    gains : Gains
        Canonical gains, scalars or a bank of shape ``S``.

    Returns
    -------
    complex array (S..., 3)
        The three roots of eq 40, sorted by decreasing modulus. Where ``gamma == 0`` only
        the two roots of eq 41 are meaningful (the third, the uncontrollable acceleration
        pole at ``z = 1``, is not a pole of any transfer function) and the last entry is
        ``nan + nanj``; if every ``gamma`` is zero the last axis has length 2.

    Notes
    -----
    Computed as the eigenvalues of the companion matrix of
    :func:`characteristic_polynomial` (vectorised over the bank).

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eq 40 (eq 41 where gamma = 0).
    """
    coeffs = characteristic_polynomial(gains)
    g = np.asarray(gains.as_arrays()[2])
    a2, a1, a0 = coeffs[..., 1], coeffs[..., 2], coeffs[..., 3]
    comp = np.zeros(coeffs.shape[:-1] + (3, 3))
    comp[..., 0, 0], comp[..., 0, 1], comp[..., 0, 2] = -a2, -a1, -a0
    comp[..., 1, 0] = comp[..., 2, 1] = 1.0
    # quadratic rows: companion of z^2 + a1 z + a0 in the upper-left 2x2 block
    zg = g == 0.0
    comp2 = np.zeros(coeffs.shape[:-1] + (2, 2))
    comp2[..., 0, 0], comp2[..., 0, 1], comp2[..., 1, 0] = -a1, -a0, 1.0
    r3 = np.linalg.eigvals(comp).astype(complex)
    r2 = np.linalg.eigvals(comp2).astype(complex)
    r2 = np.concatenate([r2, np.full(r2.shape[:-1] + (1,), np.nan + 1j * np.nan)], axis=-1)
    r = np.where(zg[..., None], r2, r3)
    order = np.argsort(-np.nan_to_num(np.abs(r), nan=-1.0), axis=-1, kind="stable")
    r = np.take_along_axis(r, order, axis=-1)
    if np.all(zg):
        r = r[..., :2]
    return r


def pole_radius(gains: Gains):
    """Largest pole modulus (spectral radius of the closed loop), ``max |z_k|``.

    Parameters
    ----------
    gains : Gains
        Canonical gains, scalars or a bank of shape ``S``.

    Returns
    -------
    float or array (S...)
        ``max_k |z_k|`` over the poles of :func:`poles` (eq 41's two where ``gamma == 0``).

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eq 40 (eq 41 for gamma = 0): the roots.
    """
    return scalar_or_array(np.nanmax(np.abs(poles(gains)), axis=-1))


def check_n_max(n_max) -> int:
    """``n_max`` of a route that sums an impulse response (:func:`summation_length`), as
    an int, or a clear error."""
    n = int(n_max)
    if n < 16:
        raise AbglibValueError(f"n_max must be >= 16, got {n_max}")
    return n


def summation_length(
    alpha: float, beta: float, gamma: float, n_max: int, route: str, instead: str
) -> int:
    """Samples after which an impulse response of one gain set has decayed below 1e-20 of
    its start (twice the count for the pole radius, and 64 more), for the numeric routes
    that sum it (``route`` names the route in the error, ``instead`` the exact one).

    Raises
    ------
    AbglibValueError
        When that count exceeds ``n_max``, naming the gains; and when the computed pole
        radius is not below 1 for gains the exact Jury test calls stable: poles within
        round-off of the unit circle, whose roots eq 40's expanded coefficients cannot
        resolve (a gamma or beta far below alpha: gamma 1e-18 at alpha 0.3, beta 0.02),
        where no length would do.
    """
    r = float(pole_radius(Gains(alpha, beta, gamma)))
    gains = f"(alpha={alpha!r}, beta={beta!r}, gamma={gamma!r})"
    if not r < 1.0:
        raise AbglibValueError(
            f"{route}: the poles of gains {gains} lie within round-off of the unit circle "
            f"(computed radius {r!r}), so no summation length reaches the response's tail; "
            f"use {instead}"
        )
    n = 64 if r < 1e-3 else int(np.ceil(2.0 * np.log(1e-20) / np.log(r))) + 64
    if n > n_max:
        raise AbglibValueError(
            f"{route} needs about {n} samples for gains {gains} but n_max={n_max}; increase n_max"
        )
    return n


def _jury(gains: Gains):
    r"""Jury's inequalities for eq 40 (eq 41 where gamma == 0), in cancellation-free form.

    For :math:`P(z) = z^3 + a_2 z^2 + a_1 z + a_0` of eq 40 the Jury quantities reduce to
    :math:`P(1) = \gamma`, :math:`-P(-1) = 2(4 - 2\alpha - \beta)`,
    :math:`a_0 = \alpha - 1`, :math:`|a_0^2 - 1| = \alpha|2 - \alpha|` and
    :math:`a_0 a_2 - a_1 = u - \alpha(2 - \alpha)` with
    :math:`u = \alpha\beta + \alpha\gamma/2 - \gamma`; evaluating these forms (instead
    of the expanded coefficients) keeps e.g. :math:`P(1) = \gamma` exact for tiny gamma.
    """
    a, b, g = gains.as_arrays()
    c = a * (2.0 - a)
    u = a * b + a * g / 2.0 - g
    inside0 = (a > 0) & (a < 2.0)  # |a0| = |1 - alpha| < 1
    # |a0^2 - 1| > |a0 a2 - a1|  <=>  |c| > |u - c|  <=>  0 < u < 2c  (c > 0 when |a0| < 1)
    ok3 = (g > 0) & (4.0 - 2.0 * a - b > 0) & inside0 & (u > 0) & (u < 2.0 * c)
    # quadratic z^2 + (a + b - 2) z + 1 - a: P(1) = beta, P(-1) = 4 - 2 alpha - beta
    ok2 = (b > 0) & (4.0 - 2.0 * a - b > 0) & inside0
    return np.where(g == 0.0, ok2, ok3)


def is_stable(gains: Gains):
    """True where every pole of the tracker lies strictly inside the unit circle.

    Parameters
    ----------
    gains : Gains
        Canonical gains, scalars or a bank of shape ``S``.

    Returns
    -------
    bool or bool array (S...)

    Notes
    -----
    Decided by Jury's inequalities (E. I. Jury, *Theory and Application of the
    z-Transform Method*, 1964) on :func:`characteristic_polynomial`: for the cubic
    :math:`P(z) = z^3 + a_2 z^2 + a_1 z + a_0` of seed 000, eq 40, :math:`P(1) > 0`,
    :math:`-P(-1) > 0`, :math:`|a_0| < 1`, :math:`|a_0^2 - 1| > |a_0 a_2 - a_1|`; for the
    quadratic of eq 41 (``gamma == 0``), :math:`P(\\pm 1) > 0`, :math:`|a_0| < 1`. Each
    quantity is evaluated in a closed form in the gains (e.g. :math:`P(1) = \\gamma`), free
    of the cancellation of the expanded coefficients. Where
    ``gamma == 0`` the 3-state model's extra pole at ``z = 1`` (the acceleration state,
    uncontrollable from the measurements and never excited) is excluded. Boundary gains
    (a pole exactly on the circle) are unstable. The tests check this against the
    modulus of the numeric poles and against the state-space matrix ``F``.

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eqs 40-41 (poles) and eqs 41-49 (Jury).
    """
    return scalar_or_array(_jury(require_gains(gains)))


def require_stable(gains: Gains, what: str = "steady-state response is undefined") -> None:
    """Raise unless every gain set of ``gains`` is strictly stable (:func:`is_stable`).

    ``what`` completes the message "the <what>: gains (...) are unstable", e.g.
    ``"steady-state variance is unbounded"``; the first unstable set of a bank is named
    with its index and its largest pole radius.

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eqs 40-41 (poles), as :func:`is_stable`.
    """
    ok = np.asarray(_jury(require_gains(gains)))
    if ok.all():
        return
    idx = tuple(int(i) for i in np.argwhere(~ok)[0]) if ok.ndim else ()
    a, b, g = (float(v[idx]) for v in gains.as_arrays())
    r = pole_radius(Gains(a, b, g))
    where = f" at index {idx if len(idx) != 1 else idx[0]}" if idx else ""
    raise AbglibValueError(
        f"the {what}: gains (alpha={a!r}, beta={b!r}, gamma={g!r}){where} are unstable "
        f"(largest pole radius {r:.6g} >= 1); gains must be stable (all poles strictly "
        "inside the unit circle)"
    )


def stable_jury_steelman(gains: Gains):
    """Stability criterion of seed 000 as printed: eqs 42-44 (``gamma == 0``), else 45-48.

    Parameters
    ----------
    gains : Gains
        Canonical gains, scalars or a bank of shape ``S``.

    Returns
    -------
    bool or bool array (S...)

    Notes
    -----
    Seed 000, eqs 42-44 (alpha-beta): :math:`\\alpha > 0`, :math:`\\beta > 0`,
    :math:`2\\alpha + \\beta < 4`. Eqs 45-48 (alpha-beta-gamma): :math:`0 < \\alpha < 2`,
    :math:`2\\alpha + \\beta < 4`, :math:`\\alpha\\beta + \\alpha\\gamma/2 - \\gamma > 0`,
    :math:`\\gamma > 0`. The full Jury test also needs
    :math:`\\alpha\\beta + \\alpha\\gamma/2 - \\gamma < 2\\alpha(2 - \\alpha)`, which the
    paper omits; it is implied by eqs 45, 46 and 48, so the printed set is necessary and
    sufficient, as the paper says (the tests confirm it against the poles).

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eqs 42-48, as printed.
    """
    a, b, g = require_gains(gains).as_arrays()
    ab = (a > 0) & (b > 0) & (2 * a + b < 4)
    abg = (0 < a) & (a < 2) & (2 * a + b < 4) & (a * b + a * g / 2 - g > 0) & (g > 0)
    return scalar_or_array(np.where(g == 0.0, ab, abg))


def stable_sufficient_eq49(gains: Gains):
    """Seed 000's sufficient condition as printed: eqs 45, 46, 48 and 49 (eq 49 for 47).

    Parameters
    ----------
    gains : Gains
        Canonical gains, scalars or a bank of shape ``S``.

    Returns
    -------
    bool or bool array (S...)

    Notes
    -----
    :math:`0 < \\alpha < 2`, :math:`2\\alpha + \\beta < 4`, :math:`\\gamma > 0` and
    :math:`\\alpha\\beta > \\gamma` (seed 000, eq 49, "sufficient but not necessary").
    As printed, eq 48 (:math:`\\gamma > 0`) makes it False for every alpha-beta tracker.

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eqs 45, 46, 48 and 49, as printed.
    """
    a, b, g = require_gains(gains).as_arrays()
    return scalar_or_array((0 < a) & (a < 2) & (2 * a + b < 4) & (a * b > g) & (g > 0))
