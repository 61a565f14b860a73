r"""Discrete Kalman filter on the extended antenna + object model (seed 004, ch. 7, app. F-G).

Extended model (eqs 7.28-7.32): :math:`\bar x = [x; x_t]`,
:math:`\bar A = \mathrm{diag}(A, A_t)`, :math:`\bar B = [B; 0]`; measurements (sec. 7.3)
driver position :math:`\varphi_d` and tracking error :math:`e = \varphi_a - z`:
:math:`M = [[e_{\varphi_d}^T, 0], [C, -C_t]]`. The antenna model is exact (:math:`w = 0`);
the object model error enters through :math:`G_t` (:func:`.objectmodel.taylor_model`) with
variance :math:`V_w`, the measurement errors have covariance :math:`V_v`.

Riccati equation (eq 7.15):

.. math:: \mathcal{Q} = V_w + A\mathcal{Q}[I + M^TV_v^{-1}M\mathcal{Q}]^{-1}A^T,

gains (eqs 7.18-7.20) :math:`K_f = A\mathcal{Q}[I+M^TV_v^{-1}M\mathcal{Q}]^{-1}M^TV_v^{-1}`,
:math:`A_f = A - K_f M`, and the estimate of the present state (eqs 7.17, 7.27) is the
one-step predictor :math:`\hat x_{i+1} = A\hat x_i + Bu_i + K_f(m_i - M\hat x_i)`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numba import njit

from ..._checks import AbglibValueError, check_positive
from ..._kernels import read_only
from ._smallmat import gauss_solve, matmul, matmul_nt

__all__ = ["ExtendedModel", "KalmanGains", "extended_model", "kalman_gains", "kalman_riccati"]


@dataclass(frozen=True)
class ExtendedModel:
    """Matrices of the extended model (eqs 7.30-7.32) and the noise input."""

    A: np.ndarray
    B: np.ndarray
    M: np.ndarray
    G: np.ndarray
    n_antenna: int


def extended_model(a, b, c, at, ct, gt) -> ExtendedModel:
    """Extended model of antenna ``(a, b, c)`` and object ``(at, ct, gt)`` (eqs 7.28-7.32).

    The first measurement is the driver position (state 1 of :mod:`.model`), the second the
    tracking error ``c x - ct x_t``.
    """
    n, p = a.shape[0], at.shape[0]
    ae = np.zeros((n + p, n + p))  # diag(A, At); scipy.linalg.block_diag, without its overhead
    ae[:n, :n] = a
    ae[n:, n:] = at
    be = np.vstack([b, np.zeros((p, b.shape[1]))])
    m = np.zeros((2, n + p))
    m[0, 1] = 1.0
    m[1, :n] = c[0]
    m[1, n:] = -ct[0]
    g = np.vstack([np.zeros((n, gt.shape[1])), gt])
    return ExtendedModel(A=ae, B=be, M=m, G=g, n_antenna=n)


def _symmetric(x) -> bool:
    # np.allclose(x, x.T) with its default tolerances, without its overhead
    return bool(np.all(np.abs(x - x.T) <= 1e-8 + 1e-5 * np.abs(x.T)))


def kalman_riccati(a, m, vw, vv, tol=1e-12, max_iter=1_000_000, fast=False):
    """Solve eq 7.15 by iterating it from ``Q = Vw``.

    Parameters
    ----------
    a : array (n, n); m : array (k, n); vw : array (n, n) PSD; vv : array (k, k) PD
    tol : float
        Stop when every entry changes by less than ``tol`` relative to
        ``sqrt(Q_ii Q_jj)``.
    fast : bool
        Iterate on the states the noise reaches alone (below): the same iteration on
        smaller matrices, round-off apart (1e-15 relative in one step; where it stops can
        move by a step, 1e-11 relative in Q). Used where that round-off is below what is
        written (app. H's spectral radii, the phase ensemble's 32-bit filters).

    Both routes iterate on compiled small-matrix loops (:mod:`._smallmat`, no BLAS: the
    same bits on every CPU). Until v0.4.3 the default iterated on numba's BLAS/LAPACK
    (``@`` and ``np.linalg.solve``: some 5 s of compilation on a cold cache); the
    antenna's 11 default tables are byte-identical either way.
    """
    vv = np.atleast_2d(np.asarray(vv, dtype=float))
    if not _symmetric(vv) or np.linalg.eigvalsh(vv).min() <= 0.0:
        raise AbglibValueError(f"V_v must be symmetric positive definite, got {vv.tolist()}")
    vw = np.asarray(vw, dtype=float)
    if not _symmetric(vw) or np.linalg.eigvalsh(vw).min() < -1e-15 * max(1.0, np.abs(vw).max()):
        raise AbglibValueError("V_w must be symmetric positive semidefinite")
    a = np.ascontiguousarray(a, dtype=float)
    m = np.ascontiguousarray(m, dtype=float)
    # read-only whatever the caller passed: one compiled signature (abglib._kernels.read_only)
    vv = read_only(np.ascontiguousarray(vv))
    if not fast:
        qn, ok = _kalman_iterate(a, m, np.ascontiguousarray(vw), vv, float(tol), int(max_iter))
        if not ok:
            raise AbglibValueError(
                f"Kalman Riccati iteration (eq 7.15) did not converge in {max_iter}"
            )
        return qn
    # states the noise never reaches: where Vw's rows are zero and A does not feed them from
    # the others (the antenna block of the extended model, w = 0, sec. 7.3), Q stays exactly
    # zero (Q = 0 there makes every term of eq 7.15 zero there), so the iteration runs on
    # the rest alone; the skipped terms are exact zeros, the result is the same
    reached = np.any(vw != 0.0, axis=0) | np.any(vw != 0.0, axis=1)
    live = np.flatnonzero(reached)
    if 0 < live.size < len(reached) and not np.any(a[~reached][:, reached]):
        ql, ok = _kalman_iterate(
            np.ascontiguousarray(a[np.ix_(live, live)]),
            np.ascontiguousarray(m[:, live]),
            np.ascontiguousarray(vw[np.ix_(live, live)]),
            vv,
            float(tol),
            int(max_iter),
        )
        qn = np.zeros_like(vw)
        qn[np.ix_(live, live)] = ql
    else:
        qn, ok = _kalman_iterate(a, m, np.ascontiguousarray(vw), vv, float(tol), int(max_iter))
    if not ok:
        raise AbglibValueError(f"Kalman Riccati iteration (eq 7.15) did not converge in {max_iter}")
    return qn


@njit(cache=True)
def _kalman_iterate(a, m, vw, vv, tol, max_iter):
    # the iteration of kalman_riccati, compiled: Q <- Vw + A (Q - Q M^T S^-1 M Q) A^T with
    # S = M Q M^T + Vv (eq 7.15 by the matrix inversion lemma), written out on preallocated
    # buffers (_smallmat; A is block diagonal, eq 7.30, and its zeros are skipped)
    n = a.shape[0]
    k = m.shape[0]
    q = vw.copy()
    qn = np.empty((n, n))
    qmt = np.empty((n, k))
    s = np.empty((k, k))
    g = np.empty((k, n))
    t = np.empty((n, n))
    u = np.empty((n, n))
    d = np.empty(n)
    for _ in range(max_iter):
        matmul_nt(q, m, qmt)  # Q M^T
        matmul(m, qmt, s)
        for i in range(k):
            for j in range(k):
                s[i, j] += vv[i, j]
        matmul(m, q, g)  # M Q, then S^-1 M Q
        if not gauss_solve(s, g):
            return q, False
        matmul(qmt, g, t)
        for i in range(n):
            for j in range(n):
                t[i, j] = q[i, j] - t[i, j]
        matmul(a, t, u)  # A t
        for i in range(n):  # t = (A t)^T
            for j in range(n):
                t[j, i] = u[i, j]
        matmul(a, t, u)  # A (A t)^T = (A t A^T)^T
        for i in range(n):  # Qn = Vw + A t A^T, symmetrised
            for j in range(i, n):
                v = 0.5 * ((vw[i, j] + u[j, i]) + (vw[j, i] + u[i, j]))
                qn[i, j] = v
                qn[j, i] = v
        for i in range(n):
            d[i] = np.sqrt(max(qn[i, i], 1e-300))
        change = 0.0
        for i in range(n):
            for j in range(n):
                change = max(change, abs(qn[i, j] - q[i, j]) / (d[i] * d[j]))
        if change < tol:
            return qn, True
        q, qn = qn, q
    return q, False


@dataclass(frozen=True)
class KalmanGains:
    """Q (eq 7.15), Kf, Af, Cf (eqs 7.18-7.20)."""

    Q: np.ndarray
    Kf: np.ndarray
    Af: np.ndarray
    Cf: np.ndarray


def kalman_gains(model: ExtendedModel, v_w, v_v, fast=False) -> KalmanGains:
    """Steady-state predictor gains of the extended model (eqs 7.15, 7.18-7.20).

    Parameters
    ----------
    v_w : float
        Variance of the object-model error (sec. 7.3, 8.2), > 0.
    v_v : array (2, 2)
        Measurement-error covariance (sec. 8.2), positive definite.
    fast : bool
        :func:`kalman_riccati`'s compiled loops.
    """
    v_w = float(check_positive("V_w", v_w))
    vw = v_w * model.G @ model.G.T
    q = kalman_riccati(model.A, model.M, vw, v_v, fast=fast)
    vv = np.atleast_2d(np.asarray(v_v, dtype=float))
    s = model.M @ q @ model.M.T + vv
    kf = model.A @ q @ model.M.T @ np.linalg.inv(s)  # eq 7.19 (matrix inversion lemma)
    # Cf = -[I + M^T Vv^-1 M Q]^-1 M^T Vv^-1 = -M^T (Vv + M Q M^T)^-1, eq 7.18
    cf = -model.M.T @ np.linalg.inv(s)
    af = model.A - kf @ model.M
    return KalmanGains(Q=q, Kf=kf, Af=af, Cf=cf)
