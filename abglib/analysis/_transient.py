"""Transient measures D^2, A^2 (Simpson, seed 000 eqs 15-20) and steady-state lag errors.

``D^2`` is the sum of squared errors (ideal minus actual output) after a unit step in
velocity, ``A^2`` after a unit step in acceleration (seed 000, "Performance measures").
The printed closed forms are kept as printed (:func:`transient_d2_simpson`,
:func:`transient_a2_simpson`); the exact twins (:func:`transient_d2`,
:func:`transient_a2`) sum the error sequences of :func:`abglib.track` directly.

The reading under which the printed forms hold exactly (found numerically; see the
tests): the tracker starts from the zero state, the input is ``z(n) = n`` (velocity
step: one position unit per sample, i.e. velocity ``1/T``) or ``z(n) = n^2 / 2``
(acceleration step: ``1/T^2``), the errors are those of the *smoothed* outputs, and the
sums start at ``n = 0`` (the first sample, where the velocity error of ``D_v^2`` and the
acceleration error of ``A_a^2`` are already 1 per-sample unit).

:func:`steady_state_lag` gives the steady-state position error for a constant
acceleration or a constant jerk from the final-value theorem; Huang et al.'s printed
formulas (seed 002, "Tracking errors") are
``abglib.replications.huang.printed.steady_state_lag_huang``.
"""

from __future__ import annotations

import numpy as np

from .._checks import AbglibValueError, check_finite, scalar_or_array
from ..engine import track
from ..gains import Gains
from ._stability import check_n_max, require_stable, summation_length
from ._variance import _broadcast

__all__ = [
    "steady_state_lag",
    "transient_a2",
    "transient_a2_simpson",
    "transient_d2",
    "transient_d2_simpson",
]

_UNSTABLE = "transient error sums are unbounded"


# --------------------------------------------------------------------------- printed
def transient_d2_simpson(gains: Gains, dt=1.0) -> dict:
    r"""Simpson's D^2 for a unit velocity step, as printed (seed 000, eqs 15-17).

    Parameters
    ----------
    gains : Gains
        Canonical gains, scalar or a bank ``(...)``; stable.
    dt : float or array (...), default 1.0
        Sample interval ``T`` > 0.

    Returns
    -------
    dict
        Keys ``x``, ``v``, ``a``: ``D_x^2``, ``D_v^2``, ``D_a^2`` (floats or arrays).

    Notes
    -----
    Seed 000, eqs 15-17, with ``Y^2`` of eq 14:

    .. math::
        D_x^2 Y^2 &= 2\gamma(2-\alpha)(1-\alpha)^2 \\
        D_v^2 Y^2 T^2 &= 2\gamma[\alpha^2(2-\alpha) + 2\beta(1-\alpha)]
            + (\gamma^3/8)(2-\alpha) - (\gamma^2/4)[2(4-3\alpha)(2-\alpha) + \alpha\beta] \\
        D_a^2 Y^2 T^4 &= \alpha\gamma^2(4-2\alpha-\beta) + (\gamma^3/2)(2-\alpha)

    They equal :func:`transient_d2` (input ``z(n) = n``, smoothed outputs, sums from
    ``n = 0``) exactly. At ``gamma = 0`` every term has a factor ``gamma`` (0/0); the
    ``gamma -> 0`` limit is returned there:
    ``D_x^2 = (2-\alpha)(1-\alpha)^2 / (\alpha\beta(4-2\alpha-\beta))``,
    ``D_v^2 T^2 = [\alpha^2(2-\alpha) + 2\beta(1-\alpha)] / (\alpha\beta(4-2\alpha-\beta))``,
    ``D_a^2 = 0`` -- which equal the exact alpha-beta sums.

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eqs 15-17, as printed.
    """
    a, b, g, T = _broadcast(gains, dt)
    require_stable(Gains(a, b, g), _UNSTABLE)
    q = 4.0 - 2.0 * a - b
    ab = g == 0.0
    with np.errstate(divide="ignore", invalid="ignore"):
        Y2 = g * (a * (2.0 * b + g) - 2.0 * g) * q  # eq 14
        dx = 2.0 * g * (2.0 - a) * (1.0 - a) ** 2 / Y2  # eq 15
        dv = (
            2.0 * g * (a * a * (2.0 - a) + 2.0 * b * (1.0 - a))
            + (g**3 / 8.0) * (2.0 - a)
            - (g * g / 4.0) * (2.0 * (4.0 - 3.0 * a) * (2.0 - a) + a * b)
        ) / (Y2 * T**2)  # eq 16
        da = (a * g * g * q + (g**3 / 2.0) * (2.0 - a)) / (Y2 * T**4)  # eq 17
        lim = a * b * q  # Y^2 / (2 gamma) at gamma -> 0
        dx = np.where(ab, (2.0 - a) * (1.0 - a) ** 2 / lim, dx)
        dv = np.where(ab, (a * a * (2.0 - a) + 2.0 * b * (1.0 - a)) / lim / T**2, dv)
        da = np.where(ab, 0.0, da)
    return {"x": scalar_or_array(dx), "v": scalar_or_array(dv), "a": scalar_or_array(da)}


def transient_a2_simpson(gains: Gains, dt=1.0) -> dict:
    r"""Simpson's A^2 for a unit acceleration step, as printed (seed 000, eqs 18-20).

    Parameters
    ----------
    gains : Gains
        Canonical gains, scalar or a bank ``(...)``; stable.
    dt : float or array (...), default 1.0
        Sample interval ``T`` > 0.

    Returns
    -------
    dict
        Keys ``x``, ``v``, ``a``: ``A_x^2``, ``A_v^2``, ``A_a^2`` (floats or arrays);
        ``inf`` where the error does not die out (alpha-beta, see Notes).

    Notes
    -----
    Seed 000, eqs 18-20, with ``Y^2`` of eq 14 (the scan prints ``y^2`` for ``Y^2``
    and, in eq 20, ``A_x^2`` for ``A_a^2``):

    .. math::
        A_x^2 Y^2 &= \alpha(4-2\alpha-\beta)(1-\alpha)^2 \\
        A_v^2 Y^2 T^2 &= (\alpha/4)(\beta-2\alpha)^2(4-2\alpha-\beta)
            + (\gamma/8)(2-\alpha)(4-2\alpha-\beta)^2 \\
        A_a^2 Y^2 T^4 &= \alpha\beta^2(4-2\alpha-\beta)
            + (\gamma/2)[2\alpha^2 - (2-\alpha)\beta](4-2\alpha-\beta)

    They equal :func:`transient_a2` (input ``z(n) = n^2/2``, smoothed outputs, sums from
    ``n = 0``) exactly. An alpha-beta tracker (``gamma = 0``, ``Y^2 = 0``) keeps a
    constant error under acceleration, so the sums diverge: the ``gamma -> 0`` limit is
    ``inf``, except where the numerator vanishes too -- ``A_x^2 = 0`` at ``alpha = 1``
    (the smoothed position is the measurement) and ``A_v^2 = (2-\alpha)(4-2\alpha-\beta)
    / (16\alpha\beta T^2)`` at ``beta = 2 alpha`` (no steady velocity error).

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eqs 18-20, as printed.
    """
    a, b, g, T = _broadcast(gains, dt)
    require_stable(Gains(a, b, g), _UNSTABLE)
    q = 4.0 - 2.0 * a - b
    ab = g == 0.0
    with np.errstate(divide="ignore", invalid="ignore"):
        Y2 = g * (a * (2.0 * b + g) - 2.0 * g) * q  # eq 14
        ax = a * q * (1.0 - a) ** 2 / Y2  # eq 18
        av = ((a / 4.0) * (b - 2.0 * a) ** 2 * q + (g / 8.0) * (2.0 - a) * q * q) / (Y2 * T**2)
        aa = (a * b * b * q + (g / 2.0) * (2.0 * a * a - (2.0 - a) * b) * q) / (Y2 * T**4)
        ax = np.where(ab, np.where(a == 1.0, 0.0, np.inf), ax)
        av = np.where(ab, np.where(b == 2.0 * a, (2.0 - a) * q / (16.0 * a * b * T**2), np.inf), av)
        aa = np.where(ab, np.inf, aa)
    return {"x": scalar_or_array(ax), "v": scalar_or_array(av), "a": scalar_or_array(aa)}


# --------------------------------------------------------------------------- exact
#: the closed form beside each summed route (the exact one where summation cannot go)
_CLOSED_FORM = {"velocity": "transient_d2_simpson", "acceleration": "transient_a2_simpson"}


def _summed(gains, dt, n_max, rtol, kind: str) -> dict:
    a, b, g, T = _broadcast(gains, dt)
    require_stable(Gains(a, b, g), _UNSTABLE)
    n_max = check_n_max(n_max)
    keys = ("x", "v", "a", "x_pred")
    out = np.empty(a.shape + (len(keys),))
    for idx in np.ndindex(a.shape):
        al, be, ga, dt_ = (float(v[idx]) for v in (a, b, g, T))
        diverge = np.zeros(4, dtype=bool)
        if kind == "acceleration" and ga == 0.0:
            # alpha-beta under acceleration: steady errors (per-sample units) of
            # x_smooth, v_smooth, a_smooth, x_pred (final-value theorem, seed 000 eq 36-39)
            e_ss = ((1.0 - al) / be, al / be - 0.5, 1.0, 1.0 / be)
            diverge = np.array([e != 0.0 for e in e_ss])
        N = summation_length(
            al, be, ga, n_max, "direct summation", "the closed form " + _CLOSED_FORM[kind]
        )
        n = np.arange(N, dtype=float)
        if kind == "velocity":
            z = n
            ideal = (n, np.full(N, 1.0 / dt_), np.zeros(N))
        else:
            z = 0.5 * n * n
            ideal = (z, n / dt_, np.full(N, 1.0 / dt_**2))
        res = track(z, Gains(al, be, ga), dt=dt_)
        errs = (
            ideal[0] - res.x_smooth,
            ideal[1] - res.v_smooth,
            ideal[2] - res.a_smooth,
            z - res.x_pred,
        )
        for i, e in enumerate(errs):
            if diverge[i]:
                out[idx + (i,)] = np.inf
                continue
            sq = e * e
            total = sq.sum()
            tail = sq[-(N // 4) :].sum()
            # rounding floor of z - estimate for |z| up to z[-1]
            floor = (N // 4) * (8.0 * np.finfo(float).eps * max(abs(z[-1]), 1.0)) ** 2
            if tail > max(rtol * total, floor):
                raise AbglibValueError(
                    f"direct summation did not converge for gains (alpha={al!r}, "
                    f"beta={be!r}, gamma={ga!r}): the last {N // 4} of {N} terms of the "
                    f"{keys[i]} sum add {tail:.3g} of {total:.3g}"
                )
            out[idx + (i,)] = total
    return {k: scalar_or_array(out[..., i]) for i, k in enumerate(keys)}


def transient_d2(gains: Gains, dt=1.0, n_max=2_000_000, rtol=1e-12) -> dict:
    r"""Exact D^2 transient measures by direct summation of :func:`abglib.track` errors.

    Parameters
    ----------
    gains : Gains
        Canonical gains, scalar or a bank ``(...)``; stable.
    dt : float or array (...), default 1.0
        Sample interval ``T`` > 0.
    n_max : int, default 2_000_000
        Largest number of samples to sum; the length is chosen from the pole radius so
        that the terms fall below 1e-20 of the first ones.
    rtol : float, default 1e-12
        Convergence check: the last quarter of the terms may add at most ``rtol`` of the
        sum (or the rounding floor of ``z - estimate``), else ``ValueError``.

    Returns
    -------
    dict
        Keys ``x``, ``v``, ``a`` (smoothed position, velocity, acceleration) and
        ``x_pred`` (predicted position): floats or arrays ``(...)``.

    Notes
    -----
    The tracker starts from the zero state and sees ``z(n) = n``, ``n = 0, 1, ...``: a
    velocity step of one position unit per sample (velocity ``1/T``). With the ideal
    outputs ``x = n``, ``v = 1/T``, ``a = 0``,

    .. math:: D_x^2 = \sum_{n \ge 0} (n - \bar x_n)^2,\quad
              D_v^2 = \sum_{n \ge 0} (1/T - \bar v_n)^2,\quad
              D_a^2 = \sum_{n \ge 0} \bar a_n^2,

    which is the reading under which Simpson's eqs 15-17 (seed 000,
    :func:`transient_d2_simpson`) hold exactly. For a velocity step ``V`` (units/s)
    multiply every entry by ``(V T)^2``.

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eqs 15-17 (the measure), summed exactly.
    """
    return _summed(gains, dt, n_max, rtol, "velocity")


def transient_a2(gains: Gains, dt=1.0, n_max=2_000_000, rtol=1e-12) -> dict:
    r"""Exact A^2 transient measures by direct summation of :func:`abglib.track` errors.

    Parameters
    ----------
    gains : Gains
        Canonical gains, scalar or a bank ``(...)``; stable.
    dt : float or array (...), default 1.0
        Sample interval ``T`` > 0.
    n_max : int, default 2_000_000
        Largest number of samples to sum (see :func:`transient_d2`).
    rtol : float, default 1e-12
        Convergence tolerance (see :func:`transient_d2`).

    Returns
    -------
    dict
        Keys ``x``, ``v``, ``a``, ``x_pred`` as in :func:`transient_d2`; ``inf`` where
        the error tends to a nonzero constant (alpha-beta trackers).

    Notes
    -----
    Zero initial state, input ``z(n) = n^2 / 2`` (an acceleration step of one unit per
    sample squared, ``1/T^2``), ideal outputs ``x = n^2/2``, ``v = n/T``, ``a = 1/T^2``;
    sums from ``n = 0`` of the squared smoothed-output errors -- the reading under which
    seed 000, eqs 18-20 (:func:`transient_a2_simpson`) hold exactly. For an
    acceleration step ``A`` (units/s^2) multiply every entry by ``(A T^2)^2``.

    An alpha-beta tracker (``gamma = 0``) has the steady errors (final-value theorem on
    seed 000, eqs 36-39; per-sample units) ``(1-\alpha)/\beta`` (smoothed position),
    ``\alpha/\beta - 1/2`` (velocity), ``1`` (acceleration, never estimated) and
    ``1/\beta`` (predicted position): those sums are ``inf``; the others are summed.

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eqs 18-20 (the measure) and eqs 36-39.
    """
    return _summed(gains, dt, n_max, rtol, "acceleration")


# --------------------------------------------------------------------------- lag
_KINDS = ("acceleration", "jerk")
_LAG_OUTPUTS = ("x_pred", "x_smooth")


def steady_state_lag(gains: Gains, dt=1.0, kind="acceleration", magnitude=1.0, output="x_pred"):
    r"""Steady-state position error for a constant acceleration or constant jerk input.

    Parameters
    ----------
    gains : Gains
        Canonical gains, scalar or a bank ``(...)``; stable.
    dt : float or array (...), default 1.0
        Sample interval ``T`` > 0 (seconds).
    kind : {"acceleration", "jerk"}, default "acceleration"
        Input ``x(t) = A t^2 / 2`` or ``x(t) = J t^3 / 6``.
    magnitude : float or array (...), default 1.0
        ``A`` (units/s^2) or ``J`` (units/s^3).
    output : {"x_pred", "x_smooth"}, default "x_pred"
        The predicted position (seed 002's ``H(z)``) or the smoothed position.

    Returns
    -------
    float or array (...)
        ``lim (x(nT) - estimate)`` as ``n -> inf`` (positive for positive input):
        0 where the tracker follows the input exactly, ``inf`` where the error grows
        without bound.

    Notes
    -----
    Final-value theorem on seed 000, eqs 36, 39, 40: ``1 - X_p/X = (z-1)^3 / Delta``
    and ``1 - Xbar/X = (1-\alpha)(z-1)^3 / Delta`` with ``Delta(1) = \gamma``; for
    ``gamma = 0`` they reduce to ``(z-1)^2 / Delta'`` and ``(1-\alpha)(z-1)^2 /
    Delta'`` with ``Delta'(1) = \beta`` (seed 000, eq 41). Hence

    .. math::
        e_{x_p} &= A T^2 / \beta, & e_{\bar x} &= (1-\alpha) A T^2 / \beta
            \quad (\gamma = 0,\ \text{acceleration}) \\
        e_{x_p} &= J T^3 / \gamma, & e_{\bar x} &= (1-\alpha) J T^3 / \gamma
            \quad (\text{jerk}),

    0 for an alpha-beta-gamma tracker under acceleration and ``inf`` for an alpha-beta
    tracker under jerk. ``gamma`` is canonical: in Huang et al.'s convention
    (``gamma_H = gamma / 2``) the jerk lag is ``J T^3 / (2 gamma_H)``, half of seed 002's
    printed ``B / (gamma F_r^3)``
    (``abglib.replications.huang.printed.steady_state_lag_huang``).

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eqs 36, 39-41 (final-value theorem);
    Huang, Yang & Ma, seed 002 (``huang``), the steady-state errors A/(beta F_r^2)
    and B/(gamma F_r^3) after eq 14.
    """
    if kind not in _KINDS:
        raise AbglibValueError(f"kind must be one of {', '.join(map(repr, _KINDS))}, got {kind!r}")
    if output not in _LAG_OUTPUTS:
        raise AbglibValueError(
            f"output must be one of {', '.join(map(repr, _LAG_OUTPUTS))}, got {output!r}"
        )
    a, b, g, T = _broadcast(gains, dt)
    require_stable(Gains(a, b, g), "steady-state lag is undefined")
    m = check_finite("magnitude", magnitude)
    try:
        a, b, g, T, m = np.broadcast_arrays(a, b, g, T, m)
    except ValueError:
        raise AbglibValueError(
            f"magnitude of shape {m.shape} does not broadcast against gains of shape {a.shape}"
        ) from None
    factor = 1.0 if output == "x_pred" else 1.0 - a
    with np.errstate(divide="ignore", invalid="ignore"):
        if kind == "acceleration":
            lag = np.where(g == 0.0, factor * m * T**2 / b, 0.0)
        else:
            grow = np.where(m == 0.0, 0.0, np.copysign(np.inf, m))
            lag = np.where(g == 0.0, np.where(factor == 0.0, 0.0, grow), factor * m * T**3 / g)
    return scalar_or_array(np.asarray(lag, dtype=float))
