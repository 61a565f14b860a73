"""Variance reduction factors: the exact Lyapunov solution and the printed closed forms.

A variance reduction factor (VRF) is the steady-state variance of a tracker output per
unit variance of white measurement noise (seed 000, "Performance measures"). The exact
route (:func:`vrf`) solves the discrete Lyapunov equation of the state-space form
(:mod:`abglib.analysis._statespace`) in exact rational arithmetic, each VRF rounded once
to a float; the closed forms are kept exactly as printed:

- :func:`vrf_simpson`: Simpson's eqs 11-14 (seed 000) -- the *smoothed* outputs;
- :func:`vrf_benedict_ab`: the standard alpha-beta results that eqs 11-14 reduce to at
  ``gamma = 0`` (seed 000, section "alpha-beta tracker", ref. [7]);
- :func:`vrf_standard_abg`: Morrison's eqs 25-27 for the standard (fading-memory) gains --
  these are the one-step *prediction* VRFs;
- :func:`vrf_standard_ab`: Morrison's eqs 31-32 (printed ``k_y`` is ``k_v``) -- likewise
  the one-step prediction VRFs.

Units: velocity VRFs carry ``1/T^2`` and acceleration VRFs ``1/T^4``, so with ``dt = T``
in seconds they are variances in (units/s)^2 and (units/s^2)^2 per unit^2 of noise.
"""

from __future__ import annotations

import numpy as np

from .._checks import AbglibValueError, check_in_range, check_positive, scalar_or_array
from ..gains import Gains, require_gains
from ._stability import require_stable
from ._statespace import state_space

__all__ = [
    "VRF_KEYS",
    "vrf",
    "vrf_benedict_ab",
    "vrf_simpson",
    "vrf_standard_ab",
    "vrf_standard_abg",
]

#: Keys of the dictionary returned by :func:`vrf` (``shared/CONTRACTS.md``, section 2).
VRF_KEYS = ("x_smooth", "v_smooth", "a_smooth", "x_pred", "v_pred", "a_pred")


# --------------------------------------------------------------------------- helpers


def _broadcast(gains, dt):
    """``(alpha, beta, gamma, T)`` as float64 arrays of one broadcast shape."""
    g = require_gains(gains)
    T = check_positive("dt", dt)
    try:
        return np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in g), T)
    except ValueError:
        raise AbglibValueError(
            f"dt of shape {T.shape} does not broadcast against gains of shape {g.shape}"
        ) from None


# --------------------------------------------------------------------------- exact
def _dyadic(values) -> tuple[list[int], int]:
    """Integers ``N`` and an exponent ``e`` with ``values[i] == N[i] / 2**e`` exactly (a
    finite float is a dyadic rational: its ``as_integer_ratio`` denominator is a power of
    two)."""
    ratios = [float(v).as_integer_ratio() for v in values]
    e = max(d.bit_length() - 1 for _, d in ratios)
    return [n << (e - d.bit_length() + 1) for n, d in ratios], e


def _solve_exact(rows: list[list[int]]) -> tuple[list[int], int]:
    """Solve the augmented integer system ``rows`` (each ``[a_1 .. a_m, b]``) exactly:
    returns integers ``y`` and ``d`` with the solution ``x = y / d``.

    Bareiss' fraction-free elimination: every division is exact, so every entry stays an
    integer (a minor of the system) and the last pivot is the determinant ``d``; ``d x``
    is then an integer vector (Cramer's rule) and the back substitution's divisions are
    exact too. The system must be nonsingular. The solution is the exact rational one,
    whatever the route: this one only avoids the gcd that normalises every operation of
    :class:`fractions.Fraction` (4x faster for the 6 unknowns of :func:`_vrf_one`)."""
    m = len(rows)
    rows = [r[:] for r in rows]
    prev = 1
    for c in range(m):
        p = next(r for r in range(c, m) if rows[r][c] != 0)
        rows[c], rows[p] = rows[p], rows[c]
        piv = rows[c]
        pc = piv[c]
        for r in range(c + 1, m):
            row = rows[r]
            f = row[c]
            rows[r] = [0] * (c + 1) + [
                (pc * row[k] - f * piv[k]) // prev for k in range(c + 1, m + 1)
            ]
        prev = pc
    d = prev
    y = [0] * m
    for c in range(m - 1, -1, -1):
        row = rows[c]
        s = row[m] * d - sum(row[k] * y[k] for k in range(c + 1, m) if row[k])
        y[c] = s // row[c]
    return y, d


def _vrf_one(alpha: float, beta: float, gamma: float, T: float) -> tuple[float, ...]:
    # The discrete Lyapunov equation P = F P F^T + K K^T at T = 1, solved in exact rational
    # arithmetic from the gains' float values, each VRF then rounded once to a float: so
    # every VRF is the exact one of the gains as given, on every CPU. A float solver was
    # wrong where the problem is not: scipy's bilinear (Bartels-Stewart) route gave
    # negative variances near the edges of stability and for gains whose poles crowd
    # z = 1 (alpha 3e-6, beta 4.5e-12: x_smooth -2.7e-7 for 2.25e-6; Kalata's design at
    # lambda 1e-14), and its Kronecker route lost the acceleration VRFs of a small gamma
    # (gamma 1e-17: off by a factor 5). The symmetric P has 3 (alpha-beta) or 6 unknowns.
    # Every entry of the state-space form at T = 1 (Phi, H, K: 0, 1/2, 1 and the gains) is
    # a dyadic rational, so scaled by powers of two the system is one of integers
    # (_dyadic, _solve_exact).
    # Rescaled to T afterwards: with S = diag(1, 1/T, 1/T^2) the state at interval T is S
    # times the state at T = 1 (F_T = S F_1 S^-1, K_T = S K_1), so P_T = S P_1 S:
    # velocity variances carry 1/T^2, acceleration variances 1/T^4.
    ss = state_space(Gains(alpha, beta, gamma), 1.0)  # exact in floats at T = 1
    n = len(ss.K)
    # Phi and H (0, 1/2, 1) at one scale 2**a, the gains K at another, 2**b: the integers
    # stay as small as the gains' own (a single scale made them 3x wider, 1.6x slower)
    ints, a = _dyadic([*ss.Phi.ravel().tolist(), *ss.H.tolist()])
    ph = [ints[i * n : (i + 1) * n] for i in range(n)]  # Phi 2**a
    h = ints[n * n :]  # H 2**a
    k, b = _dyadic(ss.K.tolist())  # K 2**b
    # F = (I - K H) Phi = Phi - K (H Phi), times 2**s
    s = 2 * a + b
    h_phi = [sum(h[u] * ph[u][j] for u in range(n)) for j in range(n)]  # H Phi 2**(2a)
    f = [[(ph[i][j] << (a + b)) - k[i] * h_phi[j] for j in range(n)] for i in range(n)]
    kk = [v << (2 * a) for v in k]  # K 2**s
    one = 1 << (2 * s)  # the identity's coefficient, times 2**(2s) as F F is
    pairs = [(i, j) for i in range(n) for j in range(i, n)]
    col = {ij: c for c, ij in enumerate(pairs)}
    col.update({(j, i): c for (i, j), c in list(col.items())})
    rows = []
    for i, j in pairs:  # P_ij - sum_kl F_ik F_jl P_kl = K_i K_j, times 2**(2s)
        row = [0] * (len(pairs) + 1)
        row[col[i, j]] += one
        for u in range(n):
            for v in range(n):
                row[col[u, v]] -= f[i][u] * f[j][v]
        row[-1] = kk[i] * kk[j]
        rows.append(row)
    y, d = _solve_exact(rows)  # P = y / d
    # the one-step prediction Phi s(n-1): covariance Phi P Phi^T, times d 2**(2a)
    yp = [
        sum(
            ph[i][u] * ph[i][v] * y[col[u, v]]
            for u in range(n)
            for v in range(n)
            if ph[i][u] and ph[i][v]
        )
        for i in range(n)
    ]
    # each rounded once: Python's int / int is the correctly rounded quotient
    scale = (1.0, T**-2, T**-4)
    p = [(y[col[i, i]] / d) * t for i, t in zip(range(n), scale, strict=False)]
    pp = [(v / (d << (2 * a))) * t for v, t in zip(yp, scale, strict=False)]
    if n == 2:  # alpha-beta: no acceleration state, zero acceleration output
        return p[0], p[1], 0.0, pp[0], pp[1], 0.0
    return p[0], p[1], p[2], pp[0], pp[1], pp[2]


def vrf(gains: Gains, dt=1.0) -> dict:
    r"""Exact steady-state variance reduction factors, from the discrete Lyapunov equation.

    Parameters
    ----------
    gains : Gains
        Canonical gains (seed 000, eqs 1-3), scalar or a bank of shape ``(...)``.
    dt : float or array (...), default 1.0
        Sample interval ``T`` > 0 (seconds); broadcasts against the bank.

    Returns
    -------
    dict
        Keys ``x_smooth, v_smooth, a_smooth, x_pred, v_pred, a_pred``
        (:data:`~abglib.analysis.VRF_KEYS`):
        the steady-state variance of each output per unit variance of white measurement
        noise; floats for scalar gains, arrays ``(...)`` for a bank. Velocity entries
        carry ``1/T^2``, acceleration entries ``1/T^4``. ``*_pred`` is the one-step
        prediction made before a measurement arrives (``x_pred`` is :func:`abglib.track`'s
        ``x_pred``). For an alpha-beta tracker the acceleration entries are 0.

    Raises
    ------
    ValueError
        (:class:`~abglib.AbglibValueError`) for unstable gains: the variance is unbounded.

    Notes
    -----
    With the state-space form ``s(n) = F s(n-1) + K z(n)``, ``F = (I - K H) Phi``
    (seed 000, eqs 1-6) and unit white noise ``z``, the steady-state covariance ``P`` of
    the smoothed state solves

    .. math:: P = F P F^T + K K^T,

    and the one-step predicted state ``Phi s(n-1)`` has covariance ``Phi P Phi^T``.
    The diagonals are the VRFs. The equation is solved in exact rational arithmetic from
    the gains' float values (integers scaled by powers of two, Bareiss' elimination; 0.1
    ms for alpha-beta gains, 0.17 ms for alpha-beta-gamma), so each VRF is the exact one
    of the gains as given, rounded once: right at the edges of stability and for poles
    crowding z = 1, where a float Lyapunov solver returned negative variances, and the
    same bits on every CPU.
    Simpson's closed forms (seed 000, eqs 11-14, :func:`vrf_simpson`) are the smoothed
    entries; Morrison's (eqs 25-27, 31-32) the predicted ones.

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eqs 1-6 (the recursion) and eqs 11-14, 25-27,
    31-32 (the closed forms it is checked against).

    Examples
    --------
    >>> r = vrf(Gains(0.5, 0.2))
    >>> round(r["x_smooth"], 6), round(r["x_pred"], 6)
    (0.428571, 0.714286)
    """
    a, b, g, T = _broadcast(gains, dt)
    require_stable(Gains(a, b, g), "steady-state variance is unbounded")
    out = np.empty(a.shape + (len(VRF_KEYS),))
    for idx in np.ndindex(a.shape):
        out[idx] = _vrf_one(float(a[idx]), float(b[idx]), float(g[idx]), float(T[idx]))
    return {k: scalar_or_array(out[..., i]) for i, k in enumerate(VRF_KEYS)}


# --------------------------------------------------------------------------- printed
def vrf_benedict_ab(gains: Gains, dt=1.0) -> dict:
    r"""Standard alpha-beta VRFs (Benedict & Bordner 1962, reference [7] of seed 000).

    Parameters
    ----------
    gains : Gains
        Canonical gains with ``gamma == 0``, scalar or a bank ``(...)``.
    dt : float or array (...), default 1.0
        Sample interval ``T`` > 0.

    Returns
    -------
    dict
        ``x_smooth``, ``v_smooth``, ``x_pred``, ``v_pred`` (floats or arrays ``(...)``).

    Notes
    -----
    Seed 000 states that at ``gamma = 0`` Simpson's eqs 11-14 reduce to Benedict and
    Bordner's results; dividing numerator and denominator of eqs 11-12 by ``gamma`` and
    letting ``gamma -> 0`` gives

    .. math::
        k_x = \frac{2\alpha^2 + 2\beta - 3\alpha\beta}{\alpha(4 - 2\alpha - \beta)},\quad
        k_v T^2 = \frac{2\beta^2}{\alpha(4 - 2\alpha - \beta)},\quad
        k_{x_p} = \frac{2\alpha^2 + 2\beta + \alpha\beta}{\alpha(4 - 2\alpha - \beta)},

    and ``v_pred = v_smooth`` (the alpha-beta predictor does not change the velocity).
    All four equal the exact Lyapunov values of :func:`vrf`.

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), ref. [7] (Benedict & Bordner 1962);
    Al-Wagih & Abdulla, seed 001 (``alwagih``), eq 23b (their gain relation).
    """
    a, b, g, T = _broadcast(gains, dt)
    if np.any(g != 0.0):
        raise AbglibValueError(
            "vrf_benedict_ab is the alpha-beta closed form and needs gamma == 0, got "
            f"gamma={float(g[g != 0.0].flat[0])!r}; use vrf_simpson for alpha-beta-gamma"
        )
    require_stable(Gains(a, b, g), "steady-state variance is unbounded")
    den = a * (4.0 - 2.0 * a - b)
    kv = 2.0 * b * b / den / T**2
    return {
        "x_smooth": scalar_or_array((2.0 * a * a + 2.0 * b - 3.0 * a * b) / den),
        "v_smooth": scalar_or_array(kv),
        "x_pred": scalar_or_array((2.0 * a * a + 2.0 * b + a * b) / den),
        "v_pred": scalar_or_array(kv.copy()),
    }


def vrf_simpson(gains: Gains, dt=1.0) -> dict:
    r"""Simpson's variance reduction factors, as printed (seed 000, eqs 11-14).

    Parameters
    ----------
    gains : Gains
        Canonical gains, scalar or a bank ``(...)``; stable.
    dt : float or array (...), default 1.0
        Sample interval ``T`` > 0.

    Returns
    -------
    dict
        Keys ``x``, ``v``, ``a`` (floats or arrays ``(...)``), as printed.

    Notes
    -----
    Seed 000, eqs 11-14 (from Simpson 1963, its ref. [1]):

    .. math::
        k_x Y^2 &= 2\beta\gamma(2\alpha^2 + 2\beta - 3\alpha\beta)
                   - \alpha\gamma^2(4 - 2\alpha - \beta) \\
        k_v Y^2 T^2 &= 4\beta^3\gamma - 4\beta^2\gamma^2 + 2\gamma^3(2 - \alpha) \\
        k_a Y^2 T^4 &= 4\beta\gamma^3 \\
        Y^2 &= \gamma[\alpha(2\beta + \gamma) - 2\gamma](4 - 2\alpha - \beta)

    These are exactly the *smoothed* VRFs (``x_smooth``, ``v_smooth``, ``a_smooth`` of
    :func:`vrf`). At ``gamma = 0`` every term carries the factor ``gamma`` (0/0); there
    the standard alpha-beta results (:func:`vrf_benedict_ab`, the ``gamma -> 0`` limit)
    are returned, with ``a = 0``.

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eqs 11-14, as printed.
    """
    a, b, g, T = _broadcast(gains, dt)
    require_stable(Gains(a, b, g), "steady-state variance is unbounded")
    ab = g == 0.0
    with np.errstate(divide="ignore", invalid="ignore"):
        q = 4.0 - 2.0 * a - b
        Y2 = g * (a * (2.0 * b + g) - 2.0 * g) * q  # eq 14
        kx = (2.0 * b * g * (2.0 * a * a + 2.0 * b - 3.0 * a * b) - a * g * g * q) / Y2  # eq 11
        kv = (4.0 * b**3 * g - 4.0 * b * b * g * g + 2.0 * g**3 * (2.0 - a)) / (Y2 * T**2)  # 12
        ka = 4.0 * b * g**3 / (Y2 * T**4)  # eq 13
        # gamma = 0: the Benedict-Bordner limit of eqs 11-13
        kx = np.where(ab, (2.0 * a * a + 2.0 * b - 3.0 * a * b) / (a * q), kx)
        kv = np.where(ab, 2.0 * b * b / (a * q) / T**2, kv)
        ka = np.where(ab, 0.0, ka)
    return {"x": scalar_or_array(kx), "v": scalar_or_array(kv), "a": scalar_or_array(ka)}


def _theta(theta) -> np.ndarray:
    return check_in_range("theta", theta, 0.0, 1.0, low_inclusive=True)


def _theta_dt(theta, dt):
    th = _theta(theta)
    T = check_positive("dt", dt)
    try:
        return np.broadcast_arrays(th, T)
    except ValueError:
        raise AbglibValueError(
            f"dt of shape {T.shape} does not broadcast against theta of shape {th.shape}"
        ) from None


def vrf_standard_abg(theta, dt=1.0) -> dict:
    r"""Morrison's VRFs of the standard alpha-beta-gamma tracker, as printed (seed 000, eqs 25-27).

    Parameters
    ----------
    theta : float or array (...)
        Fading-memory parameter, ``0 <= theta < 1``; the gains are seed 000, eqs 22-24:
        ``alpha = 1 - theta^3``, ``beta = 1.5 (1 - theta)^2 (1 + theta)``,
        ``gamma = (1 - theta)^3``.
    dt : float or array (...), default 1.0
        Sample interval ``T`` > 0.

    Returns
    -------
    dict
        Keys ``x``, ``v``, ``a`` (floats or arrays ``(...)``), as printed.

    Notes
    -----
    Seed 000, eqs 25-27 (from Morrison 1969, p. 526):

    .. math::
        k_x &= \frac{1-\theta}{(1+\theta)^5}(19 + 24\theta + 16\theta^2 + 6\theta^3
               + \theta^4) \\
        k_v T^2 &= \frac{(1-\theta)^3}{(1+\theta)^5}\,\frac{49 + 50\theta + 13\theta^2}{2} \\
        k_a T^4 &= 6\,\frac{(1-\theta)^5}{(1+\theta)^5}

    They are exactly the one-step *prediction* VRFs (``x_pred``, ``v_pred``, ``a_pred``
    of :func:`vrf`), not the smoothed ones that Simpson's eqs 11-14 give.

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eqs 25-27, as printed (Morrison).
    """
    th, T = _theta_dt(theta, dt)
    p5 = (1.0 + th) ** 5
    kx = (1.0 - th) / p5 * (19.0 + 24.0 * th + 16.0 * th**2 + 6.0 * th**3 + th**4)  # eq 25
    kv = (1.0 - th) ** 3 / p5 * (49.0 + 50.0 * th + 13.0 * th**2) / 2.0 / T**2  # eq 26
    ka = 6.0 * (1.0 - th) ** 5 / p5 / T**4  # eq 27
    return {"x": scalar_or_array(kx), "v": scalar_or_array(kv), "a": scalar_or_array(ka)}


def vrf_standard_ab(theta, dt=1.0) -> dict:
    r"""Morrison's VRFs of the standard alpha-beta tracker, as printed (seed 000, eqs 31-32).

    Parameters
    ----------
    theta : float or array (...)
        Fading-memory parameter, ``0 <= theta < 1``; gains ``alpha = 1 - theta^2``,
        ``beta = (1 - theta)^2`` (seed 000, unnumbered, before eq 31).
    dt : float or array (...), default 1.0
        Sample interval ``T`` > 0.

    Returns
    -------
    dict
        Keys ``x``, ``v`` (floats or arrays ``(...)``), as printed.

    Notes
    -----
    Seed 000, eqs 31-32 (the scan prints ``k_y(0)`` for ``k_v(0)`` in eq 32):

    .. math::
        k_x = \frac{1-\theta}{(1+\theta)^3}(5 + 4\theta + \theta^2),\qquad
        k_v T^2 = \frac{2(1-\theta)^3}{(1+\theta)^3}

    They are exactly the one-step *prediction* VRFs (``x_pred``, ``v_pred`` of
    :func:`vrf`; for alpha-beta ``v_pred = v_smooth``).

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eqs 31-32, as printed (Morrison).
    """
    th, T = _theta_dt(theta, dt)
    p3 = (1.0 + th) ** 3
    kx = (1.0 - th) / p3 * (5.0 + 4.0 * th + th**2)  # eq 31
    kv = 2.0 * (1.0 - th) ** 3 / p3 / T**2  # eq 32
    return {"x": scalar_or_array(kx), "v": scalar_or_array(kv)}
