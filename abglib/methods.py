r"""Gain-selection methods M1-M5 of Al-Wagih & Abdulla (seed 001, section 5), batched.

Every method takes measurements ``z`` of shape ``(..., n)`` (batch axes, e.g. Monte Carlo
runs, first; time last) and returns the one-step predictions ``x_pred`` (seed 001, eq 3:
``x_p(t+1) = x_s(t) + T v_s(t)``), the quantity whose error the paper's RMSE (eq 26)
measures. All start with the two-point initialisation of seed 001, section 3 (eqs 9-10):
samples 0 and 1 are taken as their own predictions, ``v_s(2) = (x_m(2) - x_m(1)) / T``,
and filtering starts at the third sample.

Methods
-------
m1
    Fixed ``alpha``, ``beta = alpha^2 / (2 - alpha)`` (eqs 23a-b).
m2
    Growing memory, ``alpha_n = 2(2n-1)/(n(n+1))``, ``beta_n = 6/(n(n+1))`` (eqs 24a-b).
m3
    Linear combination ``beta_LC = w beta~ + (1 - w) beta^`` (eq 25) with ``alpha = alpha^``
    (eq 24a) and the weight found by a search over a grid (Algorithm 1).
m4
    Moving-window re-optimisation of ``alpha`` (``beta`` by eq 23b) (Algorithm 2).
m5
    A bank of K fixed-gain trackers; at each step the prediction with the lowest absolute
    innovation is taken (Algorithm 3) - or, ``causal=True``, the tracker whose recent
    innovations (before the current measurement) were smallest.
rmse, percentage_change
    eq 26 and eq 27.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

from ._checks import AbglibValueError, as_float_array, check_in_range, check_positive
from ._perturb import perturb
from .design import benedict_bordner, growing_memory
from .engine import track
from .gains import Gains

__all__ = [
    "MethodResult",
    "beta_eq23b",
    "m1",
    "m2",
    "m3",
    "m3_gains",
    "m4",
    "m5",
    "percentage_change",
    "rmse",
]


@dataclass(frozen=True, eq=False)
class MethodResult:
    """Output of a method.

    Attributes
    ----------
    x_pred : array (..., n)
        One-step predictions (seed 001, eq 3); samples 0 and 1 are the measurements
        (two-point initialisation, section 3).
    param : array or None
        What the method chose: M3 the weight ``w`` per series ``(...)``; M4 the ``alpha``
        in use at every sample ``(..., n)``; M5 the index of the chosen tracker of the
        bank at every sample ``(..., n)``; None for M1, M2.

    References
    ----------
    Al-Wagih & Abdulla, seed 001 (``alwagih``), eq 3 (the predictions) and eqs 9-10 (their start).
    """

    x_pred: np.ndarray
    param: np.ndarray | None = None


# --------------------------------------------------------------------------- helpers
def beta_eq23b(alpha):
    r"""``beta = alpha^2 / (2 - alpha)`` (seed 001, eq 23b), for ``0 < alpha <= 1``.

    References
    ----------
    Al-Wagih & Abdulla, seed 001 (``alwagih``), eq 23b.
    """
    return benedict_bordner(alpha).beta


def _z(z) -> np.ndarray:
    # perturbed arithmetic (ABGLIB_PERTURB, abglib._perturb; a no-op in a plain build): M4
    # runs its own recursion and never reaches abglib.track, where the other methods' z is
    # perturbed (idempotent: perturbing it twice is perturbing it once)
    z = perturb(as_float_array("z", z))
    if z.ndim == 0 or z.shape[-1] < 3:
        raise AbglibValueError(
            f"z must have a time axis of at least 3 samples (two-point initialisation, "
            f"seed 001 section 3), got shape {z.shape}"
        )
    if not np.isfinite(z).all():
        raise AbglibValueError("z must be finite")
    return z


def _dt(dt) -> float:
    arr = check_positive("dt", dt)
    if arr.ndim:
        raise AbglibValueError(f"dt must be a scalar for the seed 001 methods, got {arr.shape}")
    return float(perturb(arr))  # as abglib.track perturbs it (M4's own recursion)


def _grid(name: str, values, low, high, low_inclusive=False, high_inclusive=True):
    g = np.atleast_1d(
        check_in_range(
            name, values, low, high, low_inclusive=low_inclusive, high_inclusive=high_inclusive
        )
    )
    if g.ndim != 1 or g.size < 1:
        raise AbglibValueError(f"{name} must be a non-empty 1-D grid, got shape {g.shape}")
    return g


def _pred(z, gains: Gains, dt: float) -> np.ndarray:
    return track(z, gains, dt=dt, init="two_point", outputs=("x_pred",)).x_pred


# --------------------------------------------------------------------------- M1, M2
def m1(z, alpha0, dt=1.0) -> MethodResult:
    r"""Method M1: fixed gains ``alpha0`` and ``beta = alpha0^2 / (2 - alpha0)``.

    Parameters
    ----------
    z : array (..., n)
        Measured positions.
    alpha0 : float
        ``0 < alpha0 <= 1`` (seed 001, eq 23a).
    dt : float
        Sample interval ``T`` (s).

    Notes
    -----
    Seed 001, eqs 23a-b (the Benedict-Bordner relation), run by the recursion of eqs 3, 6,
    8 with the initialisation of eqs 9-10.

    References
    ----------
    Al-Wagih & Abdulla, seed 001 (``alwagih``), eqs 23a-23b (method M1).
    """
    return MethodResult(_pred(_z(z), benedict_bordner(alpha0), _dt(dt)))


def m2(z, dt=1.0) -> MethodResult:
    r"""Method M2: growing-memory gains (seed 001, eqs 24a-b).

    ``alpha_n = 2(2n-1)/(n(n+1))``, ``beta_n = 6/(n(n+1))`` with ``n`` the 1-based sample
    number, so the first filtered sample (``n = 3``) gets ``alpha = 5/6``, ``beta = 1/2``:
    each prediction extrapolates the least-squares line through all samples so far.

    References
    ----------
    Al-Wagih & Abdulla, seed 001 (``alwagih``), eqs 24a-b (method M2).
    """
    z = _z(z)
    return MethodResult(_pred(z, growing_memory(z.shape[-1]), _dt(dt)))


# --------------------------------------------------------------------------- M3
def m3_gains(n_samples: int, w) -> Gains:
    r"""Gains of M3 for weight(s) ``w``: ``alpha = alpha^_n`` and ``beta_LC`` (eq 25).

    Parameters
    ----------
    n_samples : int
        Length of the time axis.
    w : float or array (...)
        Weight, ``0 <= w <= 1``.

    Returns
    -------
    Gains
        ``alpha`` of shape ``(n,)`` (eq 24a) and ``beta`` of shape ``(..., n)``:

        .. math:: \beta_{LC} = w\,\tilde\beta_n + (1 - w)\,\hat\beta_n,\quad
           \tilde\beta_n = \frac{\hat\alpha_n^2}{2 - \hat\alpha_n}\ \text{(eq 23b)},\quad
           \hat\beta_n = \frac{6}{n(n+1)}\ \text{(eq 24b)} .

    Notes
    -----
    Seed 001, eq 25 and Algorithm 1. The paper fixes alpha "at alpha_0" (step 1) and
    recommends the growing-memory estimate (24a) for it "to avoid the arbitrary choice of
    alpha"; this reads alpha_0 as alpha^_n and evaluates eq 23b at that alpha.

    References
    ----------
    Al-Wagih & Abdulla, seed 001 (``alwagih``), eq 25 and Algorithm 1.
    """
    w = np.asarray(check_in_range("w", w, 0.0, 1.0, low_inclusive=True, high_inclusive=True))
    gm = growing_memory(n_samples)
    a = gm.alpha
    beta_tilde = a**2 / (2.0 - a)
    beta = w[..., None] * beta_tilde + (1.0 - w[..., None]) * gm.beta
    return Gains(a, beta)


def m3(z, w_grid, dt=1.0) -> MethodResult:
    r"""Method M3 (seed 001, eq 25, Algorithm 1): the weight ``w`` chosen by search.

    Parameters
    ----------
    z : array (..., n)
    w_grid : array (g,)
        Candidate weights in ``[0, 1]``.
    dt : float

    Returns
    -------
    MethodResult
        ``x_pred`` of the chosen weight, ``param`` = the weight per series ``(...)``.

    Notes
    -----
    Algorithm 1, step 3 "search for optimal weight w" by "minimization of the mean square
    error": the error a tracker can see is its innovation ``z - x_pred`` (eq 4), so each
    series gets the grid weight minimising its mean squared innovation over the filtered
    samples (first grid point on a tie). This uses the whole series, as the paper's
    search does.

    References
    ----------
    Al-Wagih & Abdulla, seed 001 (``alwagih``), eq 25 and Algorithm 1 (method M3).
    """
    z = _z(z)
    dt = _dt(dt)
    grid = _grid("w_grid", w_grid, 0.0, 1.0, low_inclusive=True)
    n = z.shape[-1]
    g = m3_gains(n, grid)
    # the grid's trackers, their costs and the choice in one kernel: the bits of track()
    # and of np.argmin(np.mean(...)) on the bank (tests/test_methods.py), without the bank
    from ._kernels import best_of_bank2, pairwise_workspace, read_only

    z2 = np.ascontiguousarray(z.reshape(-1, n))
    alpha = np.ascontiguousarray(np.broadcast_to(g.alpha, (n,)))
    beta = np.ascontiguousarray(np.broadcast_to(g.beta, (grid.size, n)))
    xp, best = np.empty(z2.shape), np.empty(z2.shape[0], dtype=np.intp)
    best_of_bank2(*map(read_only, (z2, alpha, beta)), dt, *pairwise_workspace(), xp, best)
    return MethodResult(xp.reshape(z.shape), grid[best.reshape(z.shape[:-1])])


# --------------------------------------------------------------------------- M4
def m4(z, alpha0, window, alpha_grid, dt=1.0) -> MethodResult:
    r"""Method M4 (seed 001, Algorithm 2): alpha re-optimised over a moving window.

    Parameters
    ----------
    z : array (..., n)
    alpha0 : float
        Starting ``alpha`` (step 1), ``0 < alpha0 <= 1``; ``beta`` always by eq 23b.
    window : int
        Window length ``W >= 1`` (samples).
    alpha_grid : array (g,)
        Candidate alphas in ``(0, 1]`` for the search of step 3.
    dt : float

    Returns
    -------
    MethodResult
        ``x_pred`` and ``param`` = the alpha used at each sample ``(..., n)`` (NaN at the
        two initialisation samples).

    Notes
    -----
    Steps 2-5 of Algorithm 2, each time step ``k`` (0-based): predict and correct with the
    current gains (eqs 3, 6, 8); then, once the window ``k-W+1 .. k`` lies after the
    initialisation (``k - W + 1 >= 2``), re-run every grid alpha (with its eq 23b beta)
    over the window from the tracker's smoothed state just before it, and adopt the alpha
    whose window innovations (eq 4) have the smallest sum of squares for the next step
    (first grid point on a tie).

    References
    ----------
    Al-Wagih & Abdulla, seed 001 (``alwagih``), Algorithm 2 (method M4).
    """
    z = _z(z)
    dt = _dt(dt)
    a0 = float(check_in_range("alpha0", alpha0, 0.0, 1.0, high_inclusive=True))
    if isinstance(window, bool) or not isinstance(window, (int, np.integer)) or window < 1:
        raise AbglibValueError(f"window must be an integer >= 1, got {window!r}")
    grid = _grid("alpha_grid", alpha_grid, 0.0, 1.0)
    bgrid = grid**2 / (2.0 - grid)
    z2 = np.ascontiguousarray(z.reshape(-1, z.shape[-1]))
    xp, used = np.empty(z2.shape), np.empty(z2.shape)
    _m4_kernel()(z2, a0, a0**2 / (2.0 - a0), int(window), grid, bgrid, dt, xp, used)
    xp, used = xp.reshape(z.shape), used.reshape(z.shape)
    return MethodResult(xp, used)


def _m4_series(z, a0, b0, window, grid, bgrid, dt, xp, used):  # pragma: no cover (numba)
    """M4 over each row of ``z`` (b, n), written into ``xp`` and ``used``: the arithmetic of
    Algorithm 2 element by element, in the order of the array form it replaced (so the
    results are the same bits); ``argmin`` as numpy's (first NaN, else first minimum)."""
    nb, n = z.shape
    g = grid.size
    xs, vs, cost = np.empty(n), np.empty(n), np.empty(g)
    xq, vq, gbd = np.empty(g), np.empty(g), np.empty(g)
    for q in range(g):
        gbd[q] = bgrid[q] / dt
    for i in range(nb):
        xs[0], vs[0], xp[i, 0], used[i, 0] = z[i, 0], 0.0, z[i, 0], np.nan
        xs[1], vs[1], xp[i, 1], used[i, 1] = z[i, 1], (z[i, 1] - z[i, 0]) / dt, z[i, 1], np.nan
        a, b = a0, b0
        for k in range(2, n):
            p = xs[k - 1] + dt * vs[k - 1]
            r = z[i, k] - p
            xp[i, k], used[i, k] = p, a
            xs[k] = p + a * r
            vs[k] = vs[k - 1] + (b / dt) * r
            s = k - window + 1
            if s >= 2 and k + 1 < n:
                # every grid alpha over the window, all of them advanced together sample
                # by sample (independent recursions: the loop over q vectorises; each
                # q's arithmetic is the same sequence as one q at a time)
                for q in range(g):
                    xq[q], vq[q], cost[q] = xs[s - 1], vs[s - 1], 0.0
                for j in range(s, k + 1):
                    zj = z[i, j]
                    for q in range(g):
                        pj = xq[q] + dt * vq[q]
                        rj = zj - pj
                        cost[q] = cost[q] + rj * rj
                        xq[q] = pj + grid[q] * rj
                        vq[q] = vq[q] + gbd[q] * rj
                best = 0
                for q in range(g):
                    if np.isnan(cost[q]):
                        best = q
                        break
                    if cost[q] < cost[best]:
                        best = q
                a, b = grid[best], bgrid[best]


@functools.cache
def _m4_kernel():
    """:func:`_m4_series` compiled by numba on first use (cached on disk, GIL released)."""
    from numba import njit

    return njit(cache=True, nogil=True)(_m4_series)


# --------------------------------------------------------------------------- M5
def m5(z, alphas, dt=1.0, causal=False, memory=1) -> MethodResult:
    r"""Method M5 (seed 001, Algorithm 3): a bank of K fixed-gain trackers.

    Parameters
    ----------
    z : array (..., n)
    alphas : array (K,)
        The bank: tracker ``j`` has ``alpha_j`` and ``beta_j = alpha_j^2/(2 - alpha_j)``
        (eq 23b), ``0 < alpha_j <= 1``.
    dt : float
    causal : bool, default False
        False: the paper's rule (step 3) - at each step the prediction with the lowest
        absolute error against the *current* measurement, which that prediction is meant
        to predict (so the choice looks at the answer). True: the choice at step ``k``
        uses only measurements up to ``k - 1``: the tracker with the smallest mean absolute
        innovation over the previous ``memory`` steps.
    memory : int, default 1
        Steps averaged by the causal rule (``>= 1``).

    Returns
    -------
    MethodResult
        ``x_pred`` and ``param`` = index of the chosen tracker at every sample (first on a
        tie; 0 where all predictions coincide, e.g. at initialisation).

    Notes
    -----
    The K trackers run independently in parallel (step 2); the selection never feeds back
    into them.

    References
    ----------
    Al-Wagih & Abdulla, seed 001 (``alwagih``), Algorithm 3 (method M5).
    """
    z = _z(z)
    dt = _dt(dt)
    grid = _grid("alphas", alphas, 0.0, 1.0)
    if isinstance(memory, bool) or not isinstance(memory, (int, np.integer)) or memory < 1:
        raise AbglibValueError(f"memory must be an integer >= 1, got {memory!r}")
    shape = (grid.size,) + (1,) * z.ndim
    bank = _pred(z, benedict_bordner(grid.reshape(shape)), dt)  # (K, ..., n), abglib.track
    zb = np.ascontiguousarray(z.reshape(-1, z.shape[-1]))
    xp, choice = np.empty(zb.shape), np.empty(zb.shape, dtype=np.intp)
    bank = np.ascontiguousarray(bank.reshape((grid.size,) + zb.shape))
    _m5_kernel()(zb, bank, bool(causal), int(memory), xp, choice)
    xp, choice = xp.reshape(z.shape), choice.reshape(z.shape)
    return MethodResult(xp, choice)


def _m5_select(z, bank, causal, memory, xp, choice):  # pragma: no cover (numba)
    """M5's choice over the bank ``(K, b, n)`` (the trackers' predictions, from
    :func:`abglib.track`) for each row of ``z`` ``(b, n)``: the score of the array form it
    replaced (``|z - x_pred|``, or its sum over the previous ``memory`` steps as a
    difference of running sums, causal), ``argmin`` as numpy's (first NaN, else first
    minimum)."""
    k_n, nb, n = bank.shape
    csum = np.zeros((n + 1, k_n))  # row i: the trackers' |innovation| summed before sample i
    err, score = np.empty(k_n), np.empty(k_n)
    for b in range(nb):
        for i in range(n):
            for q in range(k_n):
                err[q] = abs(z[b, i] - bank[q, b, i])
            if causal:
                lo = max(i - memory, 0)
                for q in range(k_n):
                    score[q] = csum[i, q] - csum[lo, q]
                    csum[i + 1, q] = csum[i, q] + err[q]
            else:
                for q in range(k_n):
                    score[q] = err[q]
            # numpy's argmin: the first minimum, or the first NaN if there is one
            best, low = 0, score[0]
            for q in range(1, k_n):
                if score[q] < low:
                    best, low = q, score[q]
            for q in range(k_n):
                if np.isnan(score[q]):
                    best = q
                    break
            choice[b, i] = best
            xp[b, i] = bank[best, b, i]


@functools.cache
def _m5_kernel():
    """:func:`_m5_select` compiled by numba on first use (cached on disk, GIL released)."""
    from numba import njit

    return njit(cache=True, nogil=True)(_m5_select)


# --------------------------------------------------------------------------- metrics
def rmse(x_pred, truth, axis=-1):
    r"""Root mean square prediction error (seed 001, eq 26) along ``axis`` (time).

    .. math:: \mathrm{RMSE} = \sqrt{\frac{\sum (x - x_p)^2}{N}} .

    References
    ----------
    Al-Wagih & Abdulla, seed 001 (``alwagih``), eq 26.
    """
    d = as_float_array("x_pred", x_pred) - as_float_array("truth", truth)
    return np.sqrt(np.mean(d * d, axis=axis))


def percentage_change(rmse_m1, rmse_mi):
    r"""Percentage change of RMSE relative to M1 (seed 001, eq 27).

    .. math:: PC_{i,1} = \frac{RMSE_{M1} - RMSE_{Mi}}{RMSE_{M1}} \cdot 100\% .

    References
    ----------
    Al-Wagih & Abdulla, seed 001 (``alwagih``), eq 27.
    """
    r1 = check_positive("rmse_m1", rmse_m1)
    return (r1 - as_float_array("rmse_mi", rmse_mi)) / r1 * 100.0
