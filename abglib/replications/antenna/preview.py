r"""Infinite-preview control with a predicted desired output (seed 004, ch. 4, app. E).

With the prediction :math:`s_k = C_t A_t^k x_{t,0}` (eq 4.3) and :math:`I_p = \infty`, the
co-state is :math:`r_1 = \sum_{k\ge1} (A_g^T)^{k-1} C_g C_t A_t^k x_{t,0} = X x_{t,0}`
(eq 4.5), where :math:`X` solves the Stein ("Lyapunov", app. E) equation

.. math:: X = A_g^T X A_t + C_g C_t A_t ,

and :math:`u_0 = -K x_0 - K^v X x_{t,0}` (eq 4.5). The series converges because the
eigenvalues of :math:`A_g` lie inside the unit circle while those of :math:`A_t` are on it
(a Jordan block at 1: polynomial growth against geometric decay).

Routes: :func:`stein_solve` (Kronecker, ``method="kron"``, or Bartels-Stewart through
:func:`scipy.linalg.solve_sylvester`, ``method="sylvester"``) and the partial sums
:func:`preview_series` (the finite-preview gain of eq 2.37 with the prediction inserted).
"""

from __future__ import annotations

import numpy as np
import scipy.linalg

from ..._checks import AbglibValueError
from .lq import TrackerMatrices

__all__ = ["preview_gain", "preview_series", "sine_model", "stein_solve"]


def stein_solve(ag, at, c, method="kron"):
    """Solve ``X = Ag^T X At + C`` (app. E, eq E.4).

    Parameters
    ----------
    ag : array (n, n), spectral radius < 1
    at : array (p, p), spectral radius <= 1 (invertible for ``method="sylvester"``)
    c : array (n, p)
    method : {"kron", "sylvester"}
    """
    ag, at, c = (np.atleast_2d(np.asarray(m, dtype=float)) for m in (ag, at, c))
    n, p = ag.shape[0], at.shape[0]
    if c.shape != (n, p):
        raise AbglibValueError(f"c must be ({n}, {p}), got {c.shape}")
    if np.max(np.abs(np.linalg.eigvals(ag))) >= 1.0:
        raise AbglibValueError("Ag must have all eigenvalues inside the unit circle")
    if method == "kron":
        lhs = np.eye(n * p) - np.kron(at.T, ag.T)
        return np.linalg.solve(lhs, c.flatten(order="F")).reshape((n, p), order="F")
    if method == "sylvester":
        # X At^-1 - Ag^T X = C At^-1   <=>   (-Ag^T) X + X At^-1 = C At^-1
        ati = np.linalg.inv(at)
        return scipy.linalg.solve_sylvester(-ag.T, ati, c @ ati)
    raise AbglibValueError(f"method must be 'kron' or 'sylvester', got {method!r}")


def _stein_rhs(tm: TrackerMatrices, at, ct):
    return tm.Cg @ np.atleast_2d(ct) @ at


def preview_gain(tm: TrackerMatrices, at, ct, method="kron"):
    """Object-state gain ``Kt = Kv X`` of ``u_0 = -K x_0 - Kt x_t0`` (eq 4.5), memoised on
    the bytes of what it reads (a sweep over omega or V_w previews with the same design and
    object model thousands of times); a fresh copy each call."""
    at, ct = np.asarray(at, dtype=float), np.atleast_2d(np.asarray(ct, dtype=float))
    key = (method,) + tuple((m.shape, m.tobytes()) for m in (tm.Ag, tm.Cg, tm.Kv, at, ct))
    hit = _PREVIEW.get(key)
    if hit is None:
        x = stein_solve(tm.Ag, at, _stein_rhs(tm, at, ct), method=method)
        hit = tm.Kv @ x
        if len(_PREVIEW) >= _PREVIEW_SIZE:
            _PREVIEW.pop(next(iter(_PREVIEW)))
        _PREVIEW[key] = hit
    return hit.copy()


#: :func:`preview_gain`'s memo (oldest entry dropped beyond the size).
_PREVIEW: dict = {}
_PREVIEW_SIZE = 4096


def preview_series(tm: TrackerMatrices, at, ct, n: int):
    """``Kv X_n``, ``X_n = sum_{j<n} (Ag^T)^j Cg Ct At^{j+1}``: ``n`` preview steps (eq 2.37)."""
    c = _stein_rhs(tm, at, ct)
    x = np.zeros_like(c)
    term = c.copy()
    for _ in range(int(n)):
        x = x + term
        term = tm.Ag.T @ term @ at
    return tm.Kv @ x


def sine_model(omega: float, dt: float):
    """Exact discrete generator of ``z = a sin(omega t)`` on ``[z, z']`` (the known-output case).

    Returns ``(As, Cs)`` with ``As`` the rotation ``exp([[0, 1], [-omega^2, 0]] dt)``; used in
    :func:`preview_gain` it gives the infinite preview of the *known* future sine.
    """
    w = float(omega)
    if w <= 0.0:
        raise AbglibValueError(f"omega must be > 0, got {omega!r}")
    cw, sw = np.cos(w * dt), np.sin(w * dt)
    return np.array([[cw, sw / w], [-w * sw, cw]]), np.array([[1.0, 0.0]])
