r"""Closed loop with quantised measurements over an ensemble of object phases (seed 004, ch. 8).

The quantiser of sec. 8.1 (measurements rounded to the resolution) makes the closed loop
chaotic where the loop without the Kalman measurement term has spectral radius above about
1.09: a one-ulp difference flips a rounding decision some hundred steps on, and one run's
maximum |e| or |u| then moves by up to 25 %.
The maximum of ONE run is therefore not a reproducible number; its distribution is. This
module runs the loop of :func:`.closedloop.simulate` (modes ``kalman`` and ``abg``) for the
objects ``z = amplitude sin(omega t + phi_j)``, ``phi_j = 2 pi j / n`` (``j = 0`` is the
printed track), compiled with numba (explicit loops: no BLAS kernel enters the result), and
the claims use the median over the phases of the per-run maxima.
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np
from numba import njit

from ..._checks import AbglibValueError, check_positive
from ...analysis._statespace import state_space
from ...gains import Gains
from .._numerics import snap as snap_bits
from .closedloop import Controller, _object_model, discrete_plant
from .kalman import extended_model, kalman_gains
from .model import AntennaParams
from .objectmodel import taylor_model
from .preview import preview_gain

__all__ = ["phase_grid", "phase_states", "simulate_phases"]


def phase_grid(n: int) -> np.ndarray:
    """Object phases ``2 pi j / n``, ``j = 0 .. n-1`` (``0``: the printed track)."""
    n = int(n)
    if n < 1:
        raise AbglibValueError(f"n must be >= 1, got {n}")
    return 2.0 * np.pi * np.arange(n) / n


def phase_states(amplitude, omega, t, order: int, phases) -> np.ndarray:
    """Exact object states ``[z, ..., z^(order)]`` of ``amplitude sin(omega t + phi)``.

    Returns an array ``(n_phases, order + 1, len(t))``.
    """
    t = np.asarray(t, dtype=float)
    ph = np.asarray(phases, dtype=float)[:, None, None]
    j = np.arange(order + 1)[None, :, None]
    return amplitude * omega**j * np.sin(omega * t[None, None, :] + ph + j * np.pi / 2.0)


@lru_cache(maxsize=128)
def _snapped_states(amplitude, omega, n_steps, dt, order, phases, shape):
    """``snap(phase_states(...))`` at ``t = k dt``, memoised (read-only): a robustness sweep
    simulates the same object track under many designs."""
    t = np.arange(n_steps) * dt
    xt = snap(phase_states(amplitude, omega, t, order, np.frombuffer(phases).reshape(shape)))
    xt.setflags(write=False)
    return xt


@lru_cache(maxsize=64)
def _snapped_plant(params, dt):
    """The real plant ``(A, B[:, 0], C[0])`` snapped, memoised (read-only): every run of a
    study has the nominal plant."""
    a, b, c = discrete_plant(params, dt)
    out = (snap(a), snap(b[:, 0]), snap(c[0]))
    for x in out:
        x.setflags(write=False)
    return out


@lru_cache(maxsize=1024)
def _filter(a, b, c, n, order, dt, v_w, vv):
    """Kalman predictor matrices (A - Kf M, Kf, B) of one design, memoised: the object model
    does not depend on omega or the amplitude, so sweeps reuse the filter."""
    a = np.frombuffer(a).reshape(n, n)
    b = np.frombuffer(b).reshape(n, -1)
    c = np.frombuffer(c).reshape(-1, n)
    at, ct, gt = taylor_model(order, dt)
    em = extended_model(a, b, c, at, ct, gt)
    # the compiled Riccati loops: their round-off (1e-11 relative in Kf) stays below snap's
    # 32 bits (2.3e-10)
    kg = kalman_gains(em, v_w, np.frombuffer(vv).reshape(2, 2), fast=True)
    out = (snap(em.A - kg.Kf @ em.M), snap(kg.Kf), snap(em.B[:, 0]))
    for x in out:
        x.setflags(write=False)
    return out


#: Mantissa bits kept of every matrix and object state fed to the compiled loops.
SNAP_BITS = 32


def snap(x) -> np.ndarray:
    """``x`` rounded to :data:`SNAP_BITS` mantissa bits (relative 2^-33, about 1e-10).

    The design matrices differ in their last bits between BLAS kernels (FMA or not); in the
    chaotic quantised loop such a difference grows until it flips a rounding decision.
    Rounding the inputs of the loop to a coarser binary grid makes them identical on every
    machine unless a value lies within those last bits of a grid boundary, and changes the
    design by far less than any physical tolerance.
    """
    return np.ascontiguousarray(snap_bits(x, SNAP_BITS))


@njit(cache=True)
def _rint(v):
    # round half to even, as numpy.round in closedloop.simulate
    r = math.floor(v)
    d = v - r
    if d > 0.5 or (d == 0.5 and r % 2.0 != 0.0):
        r += 1.0
    return r


@njit(cache=True)
def _matvec(m, v, out):
    for r in range(m.shape[0]):
        s = 0.0
        for c in range(m.shape[1]):
            s += m[r, c] * v[c]
        out[r] = s


@njit(cache=True)
def _kalman_loop(a, b, c, k, kt, af, kf, be, xt, res, y, u, err, skip):
    # time-major: every phase advances one step at a time, the phases in the innermost loops
    # (independent lanes the compiler vectorises); each phase sees exactly the operations of
    # _kalman_loop_by_phase in the same order, so the results are bit for bit the same.
    # skip: leave out the zero entries of af (about half of them: the antenna rows get no
    # correction, the Taylor model is triangular). Adding 0 * x to a finite sum changes no
    # bit, so that is exact while every state is finite; where a run diverges, 0 * inf = nan
    # would have entered. Returns whether the final states are all finite: with af's
    # diagonal nonzero a non-finite state stays non-finite, so True means every state of
    # every step was finite (simulate_phases reruns with skip=False otherwise).
    n_ph, p, n_steps = xt.shape
    na = a.shape[0]
    ne = af.shape[0]
    x = np.zeros((na, n_ph))
    xn = np.zeros((na, n_ph))
    xh = np.zeros((ne, n_ph))
    xhn = np.zeros((ne, n_ph))
    yv = np.zeros(n_ph)
    uv = np.zeros(n_ph)
    m0 = np.zeros(n_ph)
    m1 = np.zeros(n_ph)
    for j in range(p):
        for ph in range(n_ph):
            xh[na + j, ph] = xt[ph, j, 0]  # initial estimate = real state (sec. 8.1)
    for i in range(n_steps):
        for ph in range(n_ph):
            yv[ph] = 0.0
            uv[ph] = 0.0
        for r in range(na):
            cr = c[r]
            for ph in range(n_ph):
                yv[ph] += cr * x[r, ph]
        for r in range(na):
            kr = k[r]
            for ph in range(n_ph):
                uv[ph] -= kr * x[r, ph]
        for j in range(p):
            ktj = kt[j]
            for ph in range(n_ph):
                err[ph, j, i] = xh[na + j, ph] - xt[ph, j, i]
                uv[ph] -= ktj * xh[na + j, ph]
        for ph in range(n_ph):
            y[ph, i] = yv[ph]
            u[ph, i] = uv[ph]
            m0[ph] = _rint(x[1, ph] / res) * res
            m1[ph] = _rint((yv[ph] - xt[ph, 0, i]) / res) * res
        for r in range(ne):
            for ph in range(n_ph):
                xhn[r, ph] = 0.0
            for cc in range(ne):
                m = af[r, cc]
                if skip and m == 0.0:
                    continue
                for ph in range(n_ph):
                    xhn[r, ph] += m * xh[cc, ph]
            ber, kf0, kf1 = be[r], kf[r, 0], kf[r, 1]
            for ph in range(n_ph):
                xhn[r, ph] += ber * uv[ph] + kf0 * m0[ph] + kf1 * m1[ph]
        for r in range(na):
            for ph in range(n_ph):
                xn[r, ph] = 0.0
            for cc in range(na):
                m = a[r, cc]
                for ph in range(n_ph):
                    xn[r, ph] += m * x[cc, ph]
            br = b[r]
            for ph in range(n_ph):
                xn[r, ph] += br * uv[ph]
        xh, xhn = xhn, xh
        x, xn = xn, x
    for ph in range(n_ph):
        for r in range(na):
            if not math.isfinite(x[r, ph]):
                return False
        for r in range(ne):
            if not math.isfinite(xh[r, ph]):
                return False
    return True


@njit(cache=True)
def _kalman_loop_by_phase(a, b, c, k, kt, af, kf, be, xt, res, y, u, err):
    # the reference loop, one phase after the other (tests: _kalman_loop must equal it bit
    # for bit)
    n_ph, p, n_steps = xt.shape
    na = a.shape[0]
    ne = af.shape[0]
    x = np.zeros(na)
    xn = np.zeros(na)
    xh = np.zeros(ne)
    xhn = np.zeros(ne)
    for ph in range(n_ph):
        for r in range(na):
            x[r] = 0.0
            xh[r] = 0.0
        for j in range(p):
            xh[na + j] = xt[ph, j, 0]  # initial estimate = real state (sec. 8.1)
        for i in range(n_steps):
            yi = 0.0
            for r in range(na):
                yi += c[r] * x[r]
            ui = 0.0
            for r in range(na):
                ui -= k[r] * x[r]
            for j in range(p):
                err[ph, j, i] = xh[na + j] - xt[ph, j, i]
                ui -= kt[j] * xh[na + j]
            y[ph, i] = yi
            u[ph, i] = ui
            m0 = _rint(x[1] / res) * res
            m1 = _rint((yi - xt[ph, 0, i]) / res) * res
            _matvec(af, xh, xhn)
            for r in range(ne):
                xhn[r] += be[r] * ui + kf[r, 0] * m0 + kf[r, 1] * m1
            _matvec(a, x, xn)
            for r in range(na):
                xn[r] += b[r] * ui
            for r in range(ne):
                xh[r] = xhn[r]
            for r in range(na):
                x[r] = xn[r]


@njit(cache=True)
def _abg_loop(a, b, c, k, kt, phi, kg, xt, res, y, u, err):
    n_ph, p, n_steps = xt.shape
    na = a.shape[0]
    x = np.zeros(na)
    xn = np.zeros(na)
    xp = np.zeros(p)
    s = np.zeros(p)
    for ph in range(n_ph):
        for r in range(na):
            x[r] = 0.0
        for j in range(p):
            xp[j] = xt[ph, j, 0]  # smoothed state at t_0 taken as the real state
        for i in range(n_steps):
            yi = 0.0
            for r in range(na):
                yi += c[r] * x[r]
            ui = 0.0
            for r in range(na):
                ui -= k[r] * x[r]
            for j in range(p):
                err[ph, j, i] = xp[j] - xt[ph, j, i]
                ui -= kt[j] * xp[j]
            y[ph, i] = yi
            u[ph, i] = ui
            zm = yi - _rint((yi - xt[ph, 0, i]) / res) * res
            innov = zm - xp[0]
            for j in range(p):
                s[j] = xp[j] + kg[j] * innov
            _matvec(phi, s, xp)
            _matvec(a, x, xn)
            for r in range(na):
                x[r] = xn[r] + b[r] * ui


def simulate_phases(
    true_params: AntennaParams,
    ctrl: Controller,
    *,
    amplitude: float,
    omega: float,
    n_steps: int,
    phases,
    mode: str = "kalman",
    order: int | None = None,
    v_w: float | None = None,
    v_v=None,
    resolution: float = 0.1,
    abg: Gains | None = None,
):
    """:func:`.closedloop.simulate` (``kalman`` or ``abg``) for every object phase.

    Returns
    -------
    dict: ``t`` ``(n_steps,)``, ``z``, ``y``, ``e``, ``u`` ``(n_phases, n_steps)``, ``xt_err``
    ``(n_phases, p, n_steps)`` (estimated minus true object derivatives).
    """
    if mode not in ("kalman", "abg"):
        raise AbglibValueError(f"mode must be 'kalman' or 'abg', got {mode!r}")
    n_steps = int(n_steps)
    if n_steps < 1:
        raise AbglibValueError(f"n_steps must be >= 1, got {n_steps}")
    w = float(check_positive("omega", omega))
    res = float(check_positive("resolution", resolution))
    dt = ctrl.dt
    a, bcol, cc = _snapped_plant(true_params, dt)
    at, ct, gt = _object_model(mode, order, w, dt)
    p = at.shape[0]
    kt = snap(preview_gain(ctrl.tm, at, ct)[0])
    k = snap(ctrl.tm.K[0])
    t = np.arange(n_steps) * dt
    ph = np.ascontiguousarray(phases, dtype=float)
    xt = _snapped_states(float(amplitude), w, n_steps, dt, p - 1, ph.tobytes(), ph.shape)
    n_ph = xt.shape[0]
    y = np.empty((n_ph, n_steps))
    u = np.empty((n_ph, n_steps))
    err = np.empty((n_ph, p, n_steps))
    if mode == "kalman":
        if v_w is None or v_v is None:
            raise AbglibValueError("mode 'kalman' needs v_w and v_v")
        vv = np.atleast_2d(np.asarray(v_v, dtype=float))
        af, kf, be = _filter(
            ctrl.A.tobytes(),
            ctrl.B.tobytes(),
            ctrl.C.tobytes(),
            ctrl.A.shape[0],
            order,
            dt,
            float(v_w),
            vv.tobytes(),
        )
        skip = bool(np.all(np.diag(af) != 0.0))
        if not _kalman_loop(a, bcol, cc, k, kt, af, kf, be, xt, res, y, u, err, skip) and skip:
            # a run diverged: the dense loop, whose 0 * inf = nan the results keep
            _kalman_loop(a, bcol, cc, k, kt, af, kf, be, xt, res, y, u, err, False)
    else:
        if abg is None:
            raise AbglibValueError("mode 'abg' needs alpha-beta-gamma gains")
        ss = state_space(abg, dt, reduced=False)
        _abg_loop(
            a,
            bcol,
            cc,
            k,
            kt,
            snap(ss.Phi),
            snap(np.ravel(ss.K)),
            xt,
            res,
            y,
            u,
            err,
        )
    z = xt[:, 0, :]
    return {"t": t, "z": z, "y": y, "e": y - z, "u": u, "xt_err": err}
