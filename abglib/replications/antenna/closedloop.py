r"""Closed-loop simulations of the tracking antenna (seed 004, ch. 6, 8, app. H).

Object ``z(t) = amplitude sin(omega t)`` (ch. 6), sampled at ``t_i = i dt``; antenna at rest
at ``t = 0``. The control input is ``u_i = -K x_i - Kt xt_i`` (eqs 2.13, 4.5) with the true
antenna state ``x_i`` and an object state ``xt_i`` that is

``"known"``
    the exact state ``[z, z']`` with the exact sine generator in the preview (known
    desired output, infinite preview);
``"predicted"``
    the exact derivatives ``[z, ..., z^(q)]`` with the Taylor model of order ``q``
    (ch. 4, 6);
``"kalman"``
    the object part of the Kalman predictor on the extended model (ch. 7, 8) fed with
    the driver position and the tracking error rounded to ``resolution``;
``"abg"``
    (beyond the source) the predicted state ``[x_p, v_p, a_p]`` of a fixed-gain
    alpha-beta-gamma tracker (canonical convention, CONTRACTS section 1) fed with the
    object position ``phi_a - e_measured``, used with the order-2 Taylor preview.

For the linear cases (``known``, ``predicted``) :func:`steady_state_amplitudes` gives the
exact steady-state amplitudes of ``e`` and ``u`` by the frequency response; the
simulations give the transient.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from ..._checks import AbglibValueError, check_positive
from ...analysis._statespace import state_space
from ...gains import Gains
from .discretize import zoh
from .kalman import extended_model, kalman_gains
from .lq import TrackerMatrices, riccati_solve, tracker_matrices
from .model import AntennaParams, continuous_model
from .objectmodel import sine_state, taylor_model
from .preview import preview_gain, sine_model

__all__ = [
    "MODES",
    "Controller",
    "closed_loop_matrix",
    "design_controller",
    "discrete_plant",
    "kalman_object_enbw",
    "simulate",
    "steady_state_amplitudes",
]

MODES = ("known", "predicted", "kalman", "abg")


def discrete_plant(params: AntennaParams, dt: float):
    """ZOH-discretised antenna ``(A, B, C)`` (ch. 5, app. D)."""
    return tuple(m.copy() for m in _discrete_plant(params, float(check_positive("dt", dt))))


@lru_cache(maxsize=256)
def _discrete_plant(params: AntennaParams, dt: float):
    ac, bc, cc = continuous_model(params)
    a, b = zoh(ac, bc, dt)
    return a, b, cc


@dataclass(frozen=True)
class Controller:
    """Everything the designer computes from the (design) model."""

    params: AntennaParams
    dt: float
    tm: TrackerMatrices
    A: np.ndarray
    B: np.ndarray
    C: np.ndarray


def design_controller(
    params: AntennaParams, dt: float, q: float, r: float, fast: bool = False
) -> Controller:
    """LQ tracker of the antenna with scalar weights ``Q``, ``R`` (ch. 2, 6), memoised.

    ``fast``: solve eq 2.12 with :func:`.lq.riccati_solve` (compiled loops, the same fixed
    point to round-off) instead of :func:`.lq.riccati_iterate`.
    """
    return _design_controller(
        params, float(check_positive("dt", dt)), float(q), float(r), bool(fast)
    )


@lru_cache(maxsize=1024)
def _design_controller(
    params: AntennaParams, dt: float, q: float, r: float, fast: bool
) -> Controller:
    a, b, c = discrete_plant(params, dt)
    tm = tracker_matrices(a, b, c, [[q]], [[r]], solver=riccati_solve if fast else None)
    return Controller(params=params, dt=dt, tm=tm, A=a, B=b, C=c)


def _object_model(mode, order, omega, dt):
    if mode == "known":
        at, ct = sine_model(omega, dt)
        return at, ct, None
    if mode == "abg":
        order = 2
    if order is None:
        raise AbglibValueError(f"mode {mode!r} needs an order of prediction")
    return taylor_model(order, dt)


def steady_state_amplitudes(ctrl: Controller, omega, amplitude=1.0, mode="predicted", order=None):
    """Exact steady-state amplitudes of tracking error and control (Figs I.8-I.9).

    ``x_{i+1} = (A - BK) x_i - B Kt xt_i`` with ``xt_i = Re(c e^{j omega t_i})``; the
    steady state is ``Re(X e^{j omega t_i})`` with ``X = (e^{j omega dt} I - A + BK)^{-1}
    (-B Kt c)``. The maximum over a period of a sampled sinusoid is at most this amplitude.

    Returns
    -------
    dict with ``e`` and ``u`` (amplitudes) and ``phase_e`` (rad, of e relative to z).
    """
    if mode not in ("known", "predicted"):
        raise AbglibValueError(f"mode must be 'known' or 'predicted', got {mode!r}")
    w = float(check_positive("omega", omega))
    at, ct, _ = _object_model(mode, order, w, ctrl.dt)
    kt = preview_gain(ctrl.tm, at, ct)
    p = at.shape[0]
    # complex amplitude of [z, z', ...]: z = a sin(w t) = Re(-j a e^{j w t})
    c = -1j * amplitude * (1j * w) ** np.arange(p)
    acl = ctrl.A - ctrl.B @ ctrl.tm.K
    zi = np.exp(1j * w * ctrl.dt)
    x = np.linalg.solve(zi * np.eye(acl.shape[0]) - acl, -ctrl.B @ (kt @ c))
    e = (ctrl.C @ x)[0] - c[0]
    u = (-ctrl.tm.K @ x - kt @ c)[0]
    return {"e": float(abs(e)), "u": float(abs(u)), "phase_e": float(np.angle(e / c[0]))}


def kalman_object_enbw(gains_kf, model, dt: float) -> float:
    """One-sided ENBW (Hz per unit dimensionless time) of the Kalman object-position predictor.

    With the antenna known exactly, the tracking-error innovation is ``z - z_hat + v``, so
    the object part is ``xt_{i+1} = At xt_i + L (z_i - Ct xt_i)`` with ``L`` minus the
    error column of ``Kf``; its ``z -> z_hat`` (one step ahead) impulse response ``h_k``
    gives ``B_n = sum h_k^2 / (2 dt)``, the definition of :func:`abglib.analysis.enbw`.
    """
    import scipy.linalg

    n = model.n_antenna
    at = model.A[n:, n:]
    ct = -model.M[1:2, n:]
    ll = -gains_kf.Kf[n:, 1:2]
    f = at - ll @ ct
    w = scipy.linalg.solve_discrete_lyapunov(f.T, ct.T @ ct)
    return float((ll.T @ w @ ll)[0, 0] / (2.0 * dt))


def closed_loop_matrix(
    true_params: AntennaParams, ctrl: Controller, order: int, v_w, v_v, fast=False
):
    """Linear closed-loop map of ``[x, xhat]`` (object motion as input), app. H.

    Plant with ``true_params``, controller and Kalman filter designed with ``ctrl.params``;
    quantisation left out. The system is stable when the spectral radius is < 1 (up to the
    marginal modes that the exact antenna model leaves unexcited, see the report).
    ``fast``: :func:`.kalman.kalman_gains`'s compiled loops.
    """
    a, b, c = discrete_plant(true_params, ctrl.dt)
    at, ct, gt = taylor_model(order, ctrl.dt)
    em = extended_model(ctrl.A, ctrl.B, ctrl.C, at, ct, gt)
    kg = kalman_gains(em, v_w, v_v, fast=fast)
    kt = preview_gain(ctrl.tm, at, ct)
    n = a.shape[0]
    ne = em.A.shape[0]
    # u = -K x - Kt xhat_t ; measurements m = [phi_d ; c x - z]
    ku = np.hstack([ctrl.tm.K, np.zeros((1, ne))])
    ku[0, n + n :] = kt[0]
    mx = np.zeros((2, n))
    mx[0, 1] = 1.0
    mx[1] = c[0]
    big = np.zeros((n + ne, n + ne))
    big[:n, :n] = a
    big[:n] -= b @ ku
    big[n:, :n] = kg.Kf @ mx
    big[n:, n:] = em.A - kg.Kf @ em.M
    big[n:] -= em.B @ ku
    return big


def simulate(
    true_params: AntennaParams,
    ctrl: Controller,
    *,
    amplitude: float,
    omega: float,
    n_steps: int,
    mode: str,
    order: int | None = None,
    v_w: float | None = None,
    v_v=None,
    resolution: float = 0.1,
    abg: Gains | None = None,
):
    """Simulate the antenna tracking ``amplitude sin(omega t)`` (module docstring).

    Returns
    -------
    dict of arrays over ``i = 0 .. n_steps - 1``: ``t``, ``z``, ``y`` (antenna position),
    ``e = y - z``, ``u``; for ``kalman``/``abg`` also ``xt_err`` ``(p, n_steps)``, the
    estimated minus the true object derivatives.
    """
    if mode not in MODES:
        raise AbglibValueError(f"mode must be one of {MODES}, got {mode!r}")
    n_steps = int(n_steps)
    if n_steps < 1:
        raise AbglibValueError(f"n_steps must be >= 1, got {n_steps}")
    w = float(check_positive("omega", omega))
    dt = ctrl.dt
    a, b, c = discrete_plant(true_params, dt)
    at, ct, gt = _object_model(mode, order, w, dt)
    p = at.shape[0]
    kt = preview_gain(ctrl.tm, at, ct)[0]
    k = ctrl.tm.K[0]
    t = np.arange(n_steps) * dt
    xt_true = sine_state(amplitude, w, t, p - 1)  # (p, n)
    z = xt_true[0]
    x = np.zeros(a.shape[0])
    y = np.empty(n_steps)
    u = np.empty(n_steps)
    xt_err = None
    bcol = b[:, 0]

    if mode in ("known", "predicted"):
        for i in range(n_steps):
            y[i] = c[0] @ x
            u[i] = -k @ x - kt @ xt_true[:, i]
            x = a @ x + bcol * u[i]
    elif mode == "kalman":
        if v_w is None or v_v is None:
            raise AbglibValueError("mode 'kalman' needs v_w and v_v")
        em = extended_model(ctrl.A, ctrl.B, ctrl.C, at, ct, gt)
        kg = kalman_gains(em, v_w, v_v)
        n = a.shape[0]
        xh = np.concatenate([x, xt_true[:, 0]])  # initial estimate = real state (sec. 8.1)
        xt_err = np.empty((p, n_steps))
        res = float(check_positive("resolution", resolution))
        af, kf, be = em.A - kg.Kf @ em.M, kg.Kf, em.B[:, 0]
        for i in range(n_steps):
            y[i] = c[0] @ x
            xt_err[:, i] = xh[n:] - xt_true[:, i]
            u[i] = -k @ x - kt @ xh[n:]
            m = np.round(np.array([x[1], y[i] - z[i]]) / res) * res
            xh = af @ xh + be * u[i] + kf @ m
            x = a @ x + bcol * u[i]
    else:  # abg
        if abg is None:
            raise AbglibValueError("mode 'abg' needs alpha-beta-gamma gains")
        ss = state_space(abg, dt, reduced=False)
        res = float(check_positive("resolution", resolution))
        s = xt_true[:, 0].copy()  # smoothed state at t_0 taken as the real state
        xt_err = np.empty((3, n_steps))
        xp = s.copy()
        for i in range(n_steps):
            y[i] = c[0] @ x
            xt_err[:, i] = xp - xt_true[:, i]
            u[i] = -k @ x - kt @ xp
            zm = y[i] - np.round((y[i] - z[i]) / res) * res
            s = xp + np.ravel(ss.K) * (zm - xp[0])  # correction (CONTRACTS section 1)
            xp = ss.Phi @ s  # prediction for the next sample
            x = a @ x + bcol * u[i]
    out = {"t": t, "z": z, "y": y, "e": y - z, "u": u}
    if xt_err is not None:
        out["xt_err"] = xt_err
    return out
