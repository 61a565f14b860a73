r"""Seed 002, Figures 5-7: the simulated range track and the summary of each run.

``START``                 what a loop knows when it starts (the paper does not say)
``simulate_range_track``  constant-jerk target, Gaussian noise, several loops (seeded)
``error_metrics``         lag, peak, settling and overshoot of one run
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ..._checks import AbglibValueError, check_positive
from ...engine import track
from ...simulate import polynomial_track, sample_times, white_noise

__all__ = ["START", "error_metrics", "simulate_range_track"]

#: What a loop knows when it starts, after acquisition: the range and the range rate
#: (``true_state``), or the range only (``range_only``: zero rate); the acceleration is
#: unknown (zero) either way. The range itself may be off by ``initial_range_error``.
START = ("true_state", "range_only")


def simulate_range_track(
    trackers: dict,
    dt,
    n,
    accel,
    jerk,
    sigma_m,
    seed,
    r0=0.0,
    v0=0.0,
    start="true_state",
    initial_range_error=0.0,
) -> pd.DataFrame:
    r"""Range track of seed 002's simulation: constant jerk, Gaussian noise, several loops.

    Parameters
    ----------
    trackers : dict
        ``{name: Gains}`` (canonical gains).
    dt : float
        ``T = 1/F_r`` (s).
    n : int
        Number of samples.
    accel, jerk : float
        Initial target acceleration ``A`` (m/s^2) and its rate ``B`` (m/s^3).
    sigma_m : float
        Standard deviation of the white Gaussian range noise per pulse (m).
    seed : int
        Seed of the noise (the same noise for every tracker).
    r0, v0 : float
        Initial range (m) and range rate (m/s).
    start : {"true_state", "range_only"}, default "true_state"
        ``"true_state"``: each loop starts with the true range rate and zero
        acceleration; ``"range_only"``: with zero range rate and zero acceleration (the
        rate is unknown, a rate error of ``v0``). The paper does not say how its loops
        start.
    initial_range_error : float, default 0.0
        Range error (m) the loop starts with: its first predicted range is
        ``r0 - initial_range_error``, so the first error ``truth - prediction`` is
        ``initial_range_error`` (a target acquired inside the range gate is off by at most
        the gate's half-width).

    Returns
    -------
    DataFrame
        Columns ``t`` (s), ``truth`` (m), ``z`` (m) and, per tracker ``name``,
        ``err_<name>`` = truth - predicted position with noise and ``lag_<name>`` the
        same without noise (m).

    Notes
    -----
    Truth :math:`R(t) = r_0 + v_0 t + A t^2/2 + B t^3/6` (seed 002: "the target's
    acceleration is A, and the acceleration changing rate is B"). Each loop starts from
    an explicit initial state of :func:`abglib.track` (the smoothed state one sample
    before ``t = 0``) whose prediction for ``t = 0`` is the range ``r0 -
    initial_range_error`` with rate ``v0`` (``true_state``) or 0 (``range_only``) and zero
    acceleration. With ``true_state`` and no range error the transient is the response to
    the unknown acceleration alone; the loop is linear, so a range error ``e0`` adds the
    loop's free response to an initial error ``e0`` (and ``range_only`` that to a rate
    error ``v0``). The error is that of the predicted position, the output of the paper's
    ``H(z)``.
    """
    if start not in START:
        raise AbglibValueError(f"start must be one of {list(START)}, got {start!r}")
    e0 = float(initial_range_error)
    if not np.isfinite(e0):
        raise AbglibValueError(f"initial_range_error must be finite, got {initial_range_error!r}")
    T = float(check_positive("dt", dt))
    t = sample_times(int(n), T)
    truth = polynomial_track(t, r0, v0, accel, jerk)
    z = truth + white_noise(t.shape, sigma_m, seed)
    # ``track``'s explicit init is the state one sample before t = 0, so that its first
    # prediction is the range r0 - e0 with the rate v1 (v0, or 0 if the rate is unknown)
    v1 = float(v0) if start == "true_state" else 0.0
    init = np.array([r0 - e0 - v1 * T, v1, 0.0])
    out = {"t": t, "truth": truth, "z": z}
    for name, g in trackers.items():
        noisy = track(z, g, dt=T, init=init, outputs=("x_pred",)).x_pred
        clean = track(truth, g, dt=T, init=init, outputs=("x_pred",)).x_pred
        out[f"err_{name}"] = truth - noisy
        out[f"lag_{name}"] = truth - clean
    return pd.DataFrame(out)


def error_metrics(t, lag, err, gate_m=None, settle_fraction=0.05) -> dict:
    r"""Summary of one simulated run (see :func:`simulate_range_track`).

    Parameters
    ----------
    t, lag, err : array (n,)
        Time (s), noise-free error and noisy error (m) of one loop.
    gate_m : float, optional
        Half-width of the range discriminator's linear region (m): a loop whose error
        leaves it has lost the track (``lost`` is given only with a gate).
    settle_fraction : float, default 0.05
        Settling band, a fraction of the peak noise-free error.

    Returns
    -------
    dict
        ``peak_lag`` (max ``|lag|``), ``overshoot`` (``max(0, -min(lag) / max(lag))``, how far
        the error swings past zero relative to its peak), ``settle_s`` (last time the
        noise-free error is outside the band around its final drift line),
        ``lag_intercept`` (the settled noise-free error extrapolated linearly to
        ``t = 0``: the lag the loop would have if it had followed the initial
        acceleration from the start), ``lag_end`` (noise-free error at the end),
        ``rms_settled`` (RMS of the noisy error over the second half), ``peak_err``
        (max ``|err|``) and, with ``gate_m``, ``lost`` (``peak_err > gate_m``).
    """
    t = np.asarray(t, float)
    lag = np.asarray(lag, float)
    err = np.asarray(err, float)
    half = len(t) // 2
    slope, icpt = np.polyfit(t[half:], lag[half:], 1)
    drift = icpt + slope * t
    peak = float(np.max(np.abs(lag)))
    outside = np.nonzero(np.abs(lag - drift) > settle_fraction * max(peak, 1e-300))[0]
    top = float(np.max(lag))
    out = {
        "peak_lag": peak,
        "overshoot": max(0.0, float(-np.min(lag) / top)) if top > 0 else np.nan,
        "settle_s": float(t[outside[-1]]) if outside.size else 0.0,
        "lag_intercept": float(icpt),
        "lag_slope": float(slope),
        "lag_end": float(lag[-1]),
        "rms_settled": float(np.sqrt(np.mean(err[half:] ** 2))),
        "peak_err": float(np.max(np.abs(err))),
    }
    if gate_m is not None:
        out["lost"] = bool(out["peak_err"] > gate_m)
    return out
