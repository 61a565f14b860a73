"""The FAA Bendix alpha-beta filter test (seed 003): its program, its memo, and what lies beyond.

Seed 003 is two documents: W. Elwell's FAA Technical Center letter report "Bendix
alpha-beta tracking filter test" (a program that graphs impulse and ramp responses for
eight gain sets, one per update period 1-8 s) and A. I. Sinsky's memo "Expected smoothing
of alpha-beta filter in TCAS simulation" (a table of standard-deviation ratios for the same
gain sets). This module holds the science specific to them; everything general is in
:mod:`abglib.engine`, :mod:`abglib.analysis` and :mod:`abglib.design`.

``run_test_program``     the letter report's three difference equations, literally
``responses``            impulse and ramp responses of one gain set (via :func:`abglib.track`)
``memo_ratios``          the memo's two columns from the closed form (Benedict-Bordner)
``monte_carlo_ratios``   the same two ratios estimated by a seeded simulation, with a CI
``rounding_box``         the ratios attainable with gains inside their printed rounding
``power_of_ten_scale``   a reconstruction of the captions' y scale factor SFY
``beta_critical``        critically damped beta for an alpha (seed 001, eq 20)
``beta_benedict``        Benedict-Bordner beta for an alpha
``damping``              damping class, pole radius and equivalent damping ratio
``lags``                 steady-state lags to a ramp and to a constant acceleration
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ..._checks import AbglibValueError, check_in_range, check_positive
from ...analysis import is_stable, poles, steady_state_lag, vrf, vrf_benedict_ab
from ...engine import track
from ...gains import Gains
from ...simulate import bendix_impulse, bendix_ramp, rng_from

__all__ = [
    "GRAPHS",
    "INPUTS",
    "beta_benedict",
    "beta_critical",
    "damping",
    "lags",
    "memo_ratios",
    "monte_carlo_ratios",
    "responses",
    "rounding_box",
    "rounding_extremes",
    "power_of_ten_scale",
    "run_test_program",
    "simulated_lags",
    "program_input",
]

#: The program's two test inputs, in graph order (seed 003, "The graphs will appear ...").
INPUTS = ("impulse", "ramp")
#: The three outputs graphed per input, in graph order, with the captions' labels.
GRAPHS = {
    "x_smooth": "SMOOTHED POSITION X(K)",
    "v_smooth": "SMOOTHED VELOCITY XD(KB)",
    "x_pred": "PREDICTED POSITION XP(K)",
}


def program_input(kind: str, n: int, T: float, rise_samples: int) -> np.ndarray:
    """The program's impulse or ramp input (:func:`abglib.simulate.bendix_impulse`,
    :func:`abglib.simulate.bendix_ramp`), ``n`` samples at period ``T``."""
    if kind == "impulse":
        return bendix_impulse(n, T)
    if kind == "ramp":
        return bendix_ramp(n, T, rise_samples)
    raise AbglibValueError(f"kind must be one of {list(INPUTS)}, got {kind!r}")


def power_of_ten_scale(peak: float, divisions: float) -> float:
    """The smallest power of ten ``s`` with ``divisions * s >= peak``.

    A reconstruction of how the program could choose a graph's y scale factor SFY: every
    printed SFY (0.10, 1.00, 10.00; seed 003 captions) is a power of ten; the program's
    rule and the plot's height in grid divisions are not printed.
    """
    peak = float(check_positive("peak", peak))
    divisions = float(check_positive("divisions", divisions))
    e = int(np.ceil(np.log10(peak / divisions) - 1e-12))
    return float(10.0**e)


# --------------------------------------------------------------------------- the program
def run_test_program(z, alpha: float, beta: float, T: float) -> dict:
    r"""The letter report's difference equations, transcribed literally (seed 003).

    Parameters
    ----------
    z : array (n,)
        The input ``X_K``.
    alpha, beta : float
        ``A`` and ``B``.
    T : float
        Sampling interval (s).

    Returns
    -------
    dict
        ``x_smooth`` (``X_BK``), ``v_smooth`` (``X_DKB``) and ``x_pred`` (``X_PK``, the
        prediction for sample k made before ``X_K`` arrived), arrays (n,).

    Notes
    -----
    .. math::
        X_{BK} &= X_{PK} + A (X_K - X_{PK}) \\
        X_{DKB} &= X_{DKB1} + (B/T)(X_K - X_{PK}) \\
        X_{PK1} &= X_{BK} + T X_{DKB}

    The program states no initial values; FORTRAN-style zero-initialised variables
    (``X_PK = X_DKB1 = 0`` before the first sample) are the state it implies, i.e.
    :func:`abglib.track` with ``init="zero"``. This is seed 000's recursion with
    ``gamma = 0`` (``x_p = x̄ + T v̄``, ``v_p = v̄``).
    """
    z = np.asarray(z, dtype=float)
    T = float(check_positive("T", T))
    xp = np.zeros_like(z)
    xb = np.zeros_like(z)
    xd = np.zeros_like(z)
    x_pk, x_dkb1 = 0.0, 0.0
    for k, x_k in enumerate(z):
        x_bk = x_pk + alpha * (x_k - x_pk)
        x_dkb = x_dkb1 + (beta / T) * (x_k - x_pk)
        xp[k], xb[k], xd[k] = x_pk, x_bk, x_dkb
        x_pk = x_bk + T * x_dkb
        x_dkb1 = x_dkb
    return {"x_smooth": xb, "v_smooth": xd, "x_pred": xp}


def responses(
    gains: Gains, T: float, n: int = 40, rise_samples: int = 10, kinds=INPUTS
) -> pd.DataFrame:
    """Impulse and ramp responses of one gain set, as the test program computes them.

    Parameters
    ----------
    gains : Gains
        Scalar alpha-beta gains.
    T : float
        Update period (s).
    n : int, default 40
        Number of samples ("40 intervals").
    rise_samples : int, default 10
        Samples over which the ramp rises ("for 10 periods").
    kinds : sequence of {'impulse', 'ramp'}, default both
        The test inputs to run.

    Returns
    -------
    DataFrame
        Long table ``input, k, t, z, x_smooth, v_smooth, x_pred`` (``t = k T``), from
        :func:`abglib.track` with ``init="zero"`` (the program's implied initial state).
    """
    frames = []
    for kind in kinds:
        z = program_input(kind, n, T, rise_samples)
        r = track(z, gains, dt=T, init="zero")
        frames.append(
            pd.DataFrame(
                {
                    "input": kind,
                    "k": np.arange(n),
                    "t": np.arange(n) * float(T),
                    "z": z,
                    "x_smooth": r.x_smooth,
                    "v_smooth": r.v_smooth,
                    "x_pred": r.x_pred,
                }
            )
        )
    return pd.concat(frames, ignore_index=True)


# --------------------------------------------------------------------------- the memo
def memo_ratios(alpha, beta, T) -> dict:
    r"""The memo's two columns from the Benedict-Bordner closed form.

    Parameters
    ----------
    alpha, beta : float or array (...)
        Alpha-beta gains (stable).
    T : float or array (...)
        Update period in seconds.

    Returns
    -------
    dict
        ``position``: :math:`\sigma_{\bar x}/\sigma_x = \sqrt{k_x}` (dimensionless), the
        memo's column headed :math:`\sigma_{\dot x}/\sigma_x`; ``velocity``:
        :math:`\sigma_{\bar v}/\sigma_x = \sqrt{k_v}` in 1/s, the column headed
        :math:`\sigma_{\ddot x}/\sigma_x`.

    Notes
    -----
    Benedict & Bordner (1962) / Sklansky, the gamma -> 0 limit of seed 000, eqs 11-12:

    .. math::
        k_x = \frac{2\alpha^2 + 2\beta - 3\alpha\beta}{\alpha(4 - 2\alpha - \beta)},
        \qquad
        k_v = \frac{2\beta^2}{\alpha(4 - 2\alpha - \beta)\,T^2}.

    The memo's worked example ("0.69 x 1 deg = .69 deg" smoothed angle; "0.125 x 1 deg =
    .125 deg/sec" angle rate, T = 3 s) fixes the reading: the first column is the
    smoothed-position ratio, the second the smoothed-velocity ratio per second.
    """
    a = np.asarray(alpha, dtype=float)
    b = np.asarray(beta, dtype=float)
    T = np.asarray(check_positive("T", T), dtype=float)
    if not np.all(is_stable(Gains(a, b))):
        raise AbglibValueError(
            f"alpha, beta must be a stable pair (0 < alpha < 2, 0 < beta < 4 - 2 alpha), "
            f"got alpha={alpha!r}, beta={beta!r}"
        )
    den = a * (4.0 - 2.0 * a - b)
    kx = (2.0 * a * a + 2.0 * b - 3.0 * a * b) / den
    kv = 2.0 * b * b / den / T**2
    return {"position": _scalar(np.sqrt(kx)), "velocity": _scalar(np.sqrt(kv))}


def monte_carlo_ratios(
    gains: Gains, T: float, runs: int = 50, samples: int = 20_000, burn_in: int = 200, seed=0
) -> dict:
    """Seeded Monte Carlo estimate of the memo's two ratios, with 95 % confidence intervals.

    Parameters
    ----------
    gains : Gains
        Scalar alpha-beta gains.
    T : float
        Update period (s).
    runs : int, default 50
        Independent runs (the CI comes from their spread).
    samples : int, default 20000
        Samples kept per run (``runs * samples`` in all, >= 10^6 by default).
    burn_in : int, default 200
        Leading samples dropped per run (the zero-initialised transient).
    seed : int or numpy.random.Generator

    Returns
    -------
    dict
        ``position``, ``velocity`` (ratios of standard deviations, velocity in 1/s) and
        ``position_lo``, ``position_hi``, ``velocity_lo``, ``velocity_hi`` (95 % CI),
        ``position_var``, ``position_var_se``, ``velocity_var``, ``velocity_var_se`` (the
        variance ratio and its standard error) and ``n`` (samples used).

    Notes
    -----
    Unit-variance white Gaussian measurement noise on a stationary target, tracked by
    :func:`abglib.track`. Samples within a run are correlated, so the CI is built from
    the ``runs`` per-run variance estimates (mean +- 1.96 standard errors), then
    square-rooted.
    """
    for name, v in (("runs", runs), ("samples", samples)):
        if int(v) < 2:
            raise AbglibValueError(f"{name} must be >= 2, got {v!r}")
    if int(burn_in) < 0:
        raise AbglibValueError(f"burn_in must be >= 0, got {burn_in!r}")
    z = rng_from(seed).standard_normal((int(runs), int(burn_in) + int(samples)))
    r = track(z, gains, dt=T, init="zero", outputs=("x_smooth", "v_smooth"))
    out = {"n": int(runs) * int(samples)}
    for key, arr in (("position", r.x_smooth), ("velocity", r.v_smooth)):
        per_run = np.mean(arr[:, int(burn_in) :] ** 2, axis=1)  # zero-mean noise
        m = per_run.mean()
        se = per_run.std(ddof=1) / np.sqrt(per_run.size)
        out[key] = float(np.sqrt(m))
        out[f"{key}_var"], out[f"{key}_var_se"] = float(m), float(se)
        out[f"{key}_lo"] = float(np.sqrt(max(m - 1.96 * se, 0.0)))
        out[f"{key}_hi"] = float(np.sqrt(m + 1.96 * se))
    return out


def rounding_box(alpha: float, beta: float, T: float, half_unit: float = 5e-4, n: int = 101):
    """The memo ratios over every gain pair that prints as ``(alpha, beta)``.

    Parameters
    ----------
    alpha, beta : float
        Printed gains.
    T : float
        Update period (s).
    half_unit : float, default 5e-4
        Half a unit in the last printed digit of the gains (three decimals in the memo).
    n : int, default 101
        Grid points per gain across ``[g - half_unit, g + half_unit]``.

    Returns
    -------
    DataFrame
        ``alpha, beta, position, velocity`` on the ``n x n`` grid (exact Lyapunov VRFs).
    """
    h = float(check_positive("half_unit", half_unit))
    a = np.linspace(alpha - h, alpha + h, int(n))
    b = np.linspace(beta - h, beta + h, int(n))
    A, B = np.meshgrid(a, b, indexing="ij")
    v = vrf(Gains(A, B), dt=T)
    return pd.DataFrame(
        {
            "alpha": A.ravel(),
            "beta": B.ravel(),
            "position": np.sqrt(np.asarray(v["x_smooth"])).ravel(),
            "velocity": np.sqrt(np.asarray(v["v_smooth"])).ravel(),
        }
    )


#: Relative band around an extreme of the closed-form screen inside which
#: :func:`rounding_extremes` solves the Lyapunov equation exactly; the closed forms agree
#: with the exact VRFs to ~1e-15 relative (tests/replications/test_faa_bendix_program.py).
SCREEN_BAND = 1e-9


def _screen(values, lowest: bool):
    """Indices (ascending) whose value is within :data:`SCREEN_BAND` of the extreme."""
    v = np.asarray(values)
    ext = v.min() if lowest else v.max()
    band = SCREEN_BAND * max(abs(ext), 1e-300)
    return np.flatnonzero(v <= ext + band) if lowest else np.flatnonzero(v >= ext - band)


def rounding_extremes(alpha, beta, T, printed, tolerances, half_unit=5e-4, n=101) -> dict:
    """What :func:`rounding_box` is read for, without solving every grid point exactly.

    The ratio ranges over the box and the pair that best reproduces both ``printed``
    ratios (``(position, velocity)``, within ``tolerances``): the closed forms
    (:func:`abglib.analysis.vrf_benedict_ab`) screen the grid, and only the points within
    :data:`SCREEN_BAND` of each extreme are solved exactly (:func:`abglib.analysis.vrf`),
    so the result is that of the exact box, first index on ties included.
    """
    h = float(check_positive("half_unit", half_unit))
    a = np.linspace(alpha - h, alpha + h, int(n))
    b = np.linspace(beta - h, beta + h, int(n))
    A, B = (x.ravel() for x in np.meshgrid(a, b, indexing="ij"))
    cf = vrf_benedict_ab(Gains(A, B), dt=T)
    ratio = {"position": np.sqrt(cf["x_smooth"]), "velocity": np.sqrt(cf["v_smooth"])}

    def worst_of(pos, vel):
        ex = np.abs(pos - float(printed[0])) / tolerances[0]
        return np.maximum(ex, np.abs(vel - float(printed[1])) / tolerances[1])

    picks = [_screen(ratio[k], low) for k in ratio for low in (True, False)]
    picks.append(_screen(worst_of(ratio["position"], ratio["velocity"]), True))
    idx = np.unique(np.concatenate(picks))
    v = vrf(Gains(A[idx], B[idx]), dt=T)
    pos, vel = np.sqrt(np.asarray(v["x_smooth"])), np.sqrt(np.asarray(v["v_smooth"]))
    worst = worst_of(pos, vel)
    out = {}
    for i, (k, vals) in enumerate((("position", pos), ("velocity", vel))):
        out[f"{k}_min"] = vals[np.isin(idx, picks[2 * i])].min()
        out[f"{k}_max"] = vals[np.isin(idx, picks[2 * i + 1])].max()
    cand = np.isin(idx, picks[4])
    j = np.flatnonzero(cand)[int(np.argmin(worst[cand]))]
    out.update(
        best_alpha=A[idx[j]],
        best_beta=B[idx[j]],
        best_position=pos[j],
        best_velocity=vel[j],
        best_worst=float(worst[cand].min()),
    )
    return out


# --------------------------------------------------------------------------- beyond
def beta_critical(alpha):
    r"""Beta of the critically damped alpha-beta tracker (seed 001, eq 20).

    .. math:: \beta = 2 - \alpha - 2\sqrt{1 - \alpha}, \qquad 0 < \alpha < 1

    The characteristic polynomial :math:`z^2 - (2-\alpha-\beta) z + (1-\alpha)` (seed 000,
    eq 41) then has a double real root at :math:`z = \sqrt{1-\alpha}`.
    """
    a = np.asarray(check_in_range("alpha", alpha, 0.0, 1.0, high_inclusive=True), dtype=float)
    return _scalar(2.0 - a - 2.0 * np.sqrt(1.0 - a))


def beta_benedict(alpha):
    r"""Benedict-Bordner beta for an alpha: :math:`\beta = \alpha^2 / (2 - \alpha)`.

    Benedict & Bordner (1962), the gain pair minimising noise VRF plus transient
    (seed 000 ref. [7]).
    """
    a = np.asarray(check_in_range("alpha", alpha, 0.0, 2.0), dtype=float)
    return _scalar(a * a / (2.0 - a))


def damping(alpha: float, beta: float, T: float = 1.0, atol: float = 5e-4) -> dict:
    r"""Damping class of an alpha-beta pair.

    Parameters
    ----------
    alpha, beta : float
        Gains.
    T : float, default 1.0
        Update period (s), for the equivalent continuous-time damping ratio.
    atol : float, default 5e-4
        Half a unit in the third decimal: a pair counts as critically damped or
        Benedict-Bordner when ``|beta - beta_*(alpha)| <= atol``.

    Returns
    -------
    dict
        ``stable``; ``beta_critical``, ``beta_benedict``; ``cls`` one of
        ``'critically damped'``, ``'underdamped'`` (complex poles), ``'overdamped'``
        (distinct real poles), ``'unstable'``; ``benedict_bordner`` (bool);
        ``pole_radius``; ``zeta`` the damping ratio of the continuous system with poles
        ``s = ln(z) / T`` (1 for real poles).

    Notes
    -----
    The poles are the roots of :math:`z^2 - (2-\alpha-\beta) z + (1-\alpha)` (seed 000,
    eq 41). Their discriminant :math:`(2-\alpha-\beta)^2 - 4(1-\alpha)` vanishes at
    :math:`\beta = 2 - \alpha \mp 2\sqrt{1-\alpha}`; between the two roots the poles are
    complex (underdamped).
    """
    a, b = float(alpha), float(beta)
    g = Gains(a, b)
    stable = bool(is_stable(g))
    bc = 2.0 - a - 2.0 * np.sqrt(1.0 - a) if a <= 1.0 else np.nan
    bb = a * a / (2.0 - a) if a < 2.0 else np.nan
    p = np.asarray(poles(g))
    radius = float(np.max(np.abs(p)))
    disc = (2.0 - a - b) ** 2 - 4.0 * (1.0 - a)
    if not stable:
        cls = "unstable"
    elif np.isfinite(bc) and abs(b - bc) <= atol:
        cls = "critically damped"
    elif disc < 0:
        cls = "underdamped"
    else:
        cls = "overdamped"
    zeta = 1.0
    if disc < 0 and stable:
        s = np.log(complex(p[0])) / float(T)
        zeta = float(-s.real / abs(s))
    return {
        "stable": stable,
        "beta_critical": float(bc),
        "beta_benedict": float(bb),
        "cls": cls,
        "benedict_bordner": bool(np.isfinite(bb) and abs(b - bb) <= atol),
        "pole_radius": radius,
        "zeta": zeta,
    }


def lags(gains: Gains, T: float) -> dict:
    r"""Steady-state lags of an alpha-beta tracker to a ramp and to a constant acceleration.

    Returns
    -------
    dict
        ``ramp_x_smooth``, ``ramp_x_pred`` (0: the alpha-beta tracker is type 2) and
        ``accel_x_smooth`` :math:`= (1-\alpha) T^2/\beta`, ``accel_x_pred``
        :math:`= T^2/\beta`, per unit acceleration (m per m/s^2, i.e. s^2), from
        :func:`abglib.analysis.steady_state_lag` (seed 000 eqs 36-41, final value theorem).
    """
    return {
        "ramp_x_smooth": 0.0,
        "ramp_x_pred": 0.0,
        "accel_x_smooth": float(steady_state_lag(gains, T, "acceleration", 1.0, "x_smooth")),
        "accel_x_pred": float(steady_state_lag(gains, T, "acceleration", 1.0, "x_pred")),
    }


def simulated_lags(gains: Gains, T: float, n: int = 2000) -> dict:
    """Numeric twin of :func:`lags`: track a ramp and a parabola, read the final error."""
    t = np.arange(int(n)) * float(T)
    out = {}
    for kind, x in (("ramp", t), ("accel", 0.5 * t * t)):
        r = track(x, gains, dt=T, init="zero")
        out[f"{kind}_x_smooth"] = float(x[-1] - r.x_smooth[-1])
        out[f"{kind}_x_pred"] = float(x[-1] - r.x_pred[-1])
    return out


def _scalar(arr):
    arr = np.asarray(arr, dtype=float)
    return float(arr) if arr.ndim == 0 else arr
