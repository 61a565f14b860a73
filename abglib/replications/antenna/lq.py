r"""Discrete LQ tracker with preview (seed 004, ch. 2, app. A-C).

Plant :math:`x_{i+1} = A x_i + B u_i`, :math:`y_i = C x_i`, error :math:`e_i = y_i - z_i`,
cost :math:`J = \tfrac12\sum_{i=1}^n e_i^T Q e_i + \tfrac12\sum_{i=0}^{n-1} u_i^T R u_i`
(eq 2.5). With :math:`P` the stabilising solution of the Riccati equation (eq 2.12)

.. math:: P = C^TQC + A^T P\,[I + BR^{-1}B^TP]^{-1}A,

the optimal input is :math:`u_0 = -Kx_0 - K^v r_1` (eq 2.13) with the matrices of eqs
2.16-2.21 and the co-state :math:`r_1` of eqs 2.22-2.27 (finite horizon, exact) or eq 2.36
(truncated to :math:`I_p` preview steps, eq 2.35).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numba import njit

from ..._checks import AbglibValueError, check_positive
from ._smallmat import gauss_solve, matmul, matmul_tn

__all__ = [
    "TrackerMatrices",
    "finite_preview_u0",
    "newton_polish",
    "preview_steps",
    "riccati_iterate",
    "riccati_solve",
    "tracker_matrices",
    "truncated_preview_u0",
]


def _weights(q, r, ny, nu):
    q = np.atleast_2d(np.asarray(q, dtype=float))
    r = np.atleast_2d(np.asarray(r, dtype=float))
    if q.shape != (ny, ny) or r.shape != (nu, nu):
        raise AbglibValueError(
            f"Q must be ({ny}, {ny}) and R ({nu}, {nu}), got {q.shape} and {r.shape}"
        )
    if not np.allclose(q, q.T) or np.linalg.eigvalsh(q).min() < -1e-12:
        raise AbglibValueError(f"Q must be symmetric positive semidefinite, got {q.tolist()}")
    if not np.allclose(r, r.T) or np.linalg.eigvalsh(r).min() <= 0.0:
        raise AbglibValueError(f"R must be symmetric positive definite, got {r.tolist()}")
    return q, r


def riccati_iterate(a, b, qx, r, tol=1e-13, max_iter=200000):
    """Solve eq 2.12 by iterating it from ``P = Qx`` (value iteration), then polish.

    The iteration runs on compiled small-matrix loops (:func:`_riccati_loops`, no BLAS:
    the same bits on every CPU), and :func:`newton_polish` (scipy's Lyapunov solver)
    refines where it stops to the fixed point. Until v0.4.3 the iteration ran on numba's
    BLAS/LAPACK (``@`` and ``np.linalg.solve``: some 12 s of compilation on a cold cache);
    the antenna's 11 default tables are byte-identical either way.

    Parameters
    ----------
    a : array (n, n); b : array (n, m); qx : array (n, n), the state weight C^T Q C;
    r : array (m, m)
    tol : float
        Stop when the largest change is below ``tol`` times the largest entry of P.

    Raises
    ------
    AbglibValueError
        If the iteration has not converged after ``max_iter`` steps.
    """
    p = np.array(qx, dtype=float)
    rinv_bt = np.ascontiguousarray(np.linalg.solve(r, b.T))
    p, ok = _riccati_loops(
        np.ascontiguousarray(a, dtype=float),
        np.ascontiguousarray(b, dtype=float),
        rinv_bt,
        np.ascontiguousarray(qx, dtype=float),
        p,
        float(tol),
        int(max_iter),
    )
    if not ok:
        raise AbglibValueError(f"Riccati iteration (eq 2.12) did not converge in {max_iter} steps")
    return newton_polish(a, b, qx, r, p)


def _residual(a, b, qx, r, p) -> float:
    k = np.linalg.solve(r + b.T @ p @ b, b.T @ p @ a)
    return float(np.max(np.abs(qx + a.T @ p @ (a - b @ k) - p)))


def newton_polish(a, b, qx, r, p, steps: int = 4):
    """Refine a converged Riccati solution ``p`` of eq 2.12 by Newton (Kleinman) steps.

    The value iteration stops when one step changes P by less than ``tol``; when it
    converges slowly (Q/R = 10^4 and a lightly damped antenna: rate close to 1), the
    distance to the fixed point is many times ``tol`` and where it stops depends on the
    round-off of the iteration's arithmetic (3.6e-13 relative between the default OpenBLAS
    kernel and ``OPENBLAS_CORETYPE=Prescott`` at beta_a = 0.02, when the iteration ran on
    BLAS, enough to move K across a grid line of :func:`.ensemble.snap`). Each Newton step
    solves the closed-loop Lyapunov equation ``P = Acl^T P Acl + Qx + K^T R K``
    (``K = (R + B^T P B)^-1 B^T P A``) and converges quadratically, so the result is the
    fixed point to within round-off, whatever the kernel. A step is kept only while the
    residual of eq 2.12 decreases.
    """
    import scipy.linalg

    a, b, qx = (np.asarray(x, dtype=float) for x in (a, b, qx))
    r = np.atleast_2d(np.asarray(r, dtype=float))
    res = _residual(a, b, qx, r, p)
    for _ in range(int(steps)):
        k = np.linalg.solve(r + b.T @ p @ b, b.T @ p @ a)
        acl = a - b @ k
        p_new = scipy.linalg.solve_discrete_lyapunov(acl.T, qx + k.T @ r @ k, method="direct")
        p_new = 0.5 * (p_new + p_new.T)
        res_new = _residual(a, b, qx, r, p_new)
        if not res_new < res:
            break
        p, res = p_new, res_new
    return p


def riccati_solve(a, b, qx, r, tol=1e-13, max_iter=200000):
    """:func:`riccati_iterate` with its Newton polish on compiled small-matrix loops too
    (:mod:`._smallmat`), about 10x faster: the same formulas, the Lyapunov equation by its
    Kronecker system as scipy's ``direct`` method.

    The result is the same fixed point to round-off (1e-15 relative, not the same bits: no
    LAPACK kernel). ``design_controller(..., fast=True)`` uses it, for app. H's spectral
    radii (:func:`.robustness.spectral_radius`); the exact tables keep
    :func:`riccati_iterate`, whose bits they were built with.
    """
    a, b, qx = (np.ascontiguousarray(x, dtype=float) for x in (a, b, qx))
    r = np.ascontiguousarray(np.atleast_2d(np.asarray(r, dtype=float)))
    rinv_bt = np.ascontiguousarray(np.linalg.solve(r, b.T))
    p, ok = _riccati_loops(a, b, rinv_bt, qx, qx.copy(), float(tol), int(max_iter))
    if not ok:
        raise AbglibValueError(f"Riccati iteration (eq 2.12) did not converge in {max_iter} steps")
    return _newton(a, b, qx, r, p, 4)


@njit(cache=True)
def _gain(a, b, r, p):
    # K = (R + B^T P B)^-1 B^T P A (eq 2.19 with 2.20)
    n, m = b.shape
    pb = np.empty((n, m))
    matmul(p, b, pb)
    w = np.empty((m, m))
    matmul_tn(b, pb, w)
    for i in range(m):
        for j in range(m):
            w[i, j] += r[i, j]
    pa = np.empty((n, n))
    matmul(p, a, pa)
    k = np.empty((m, n))
    matmul_tn(b, pa, k)
    gauss_solve(w, k)
    return k


@njit(cache=True)
def _residual_loops(a, b, qx, r, p):
    # max |Qx + A^T P (A - B K) - P|, the residual of eq 2.12
    n = a.shape[0]
    k = _gain(a, b, r, p)
    acl = _closed(a, b, k)
    pa = np.empty((n, n))
    matmul(p, acl, pa)
    t = np.empty((n, n))
    matmul_tn(a, pa, t)
    res = 0.0
    for i in range(n):
        for j in range(n):
            res = max(res, abs(qx[i, j] + t[i, j] - p[i, j]))
    return res


@njit(cache=True)
def _closed(a, b, k):
    # A - B K
    out = a.copy()
    n, m = b.shape
    for i in range(n):
        for l in range(m):
            bil = b[i, l]
            for j in range(n):
                out[i, j] -= bil * k[l, j]
    return out


@njit(cache=True)
def _dlyap(acl, w):
    # P = Acl^T P Acl + W by the Kronecker system (I - kron(Acl^T, Acl^T)) vec P = vec W,
    # scipy.linalg.solve_discrete_lyapunov(Acl^T, W, method="direct")
    n = acl.shape[0]
    big = np.empty((n * n, n * n))
    x = np.empty((n * n, 1))
    for i in range(n):
        for j in range(n):
            row = i * n + j
            x[row, 0] = w[i, j]
            for kk in range(n):
                for ll in range(n):
                    big[row, kk * n + ll] = -acl[kk, i] * acl[ll, j]
            big[row, row] += 1.0
    gauss_solve(big, x)
    return x.reshape(n, n)


@njit(cache=True)
def _newton(a, b, qx, r, p, steps):
    # the Newton steps of newton_polish written out: Lyapunov equation by its Kronecker
    # system (_dlyap), residual and gain as in _residual
    n = a.shape[0]
    res = _residual_loops(a, b, qx, r, p)
    for _ in range(steps):
        k = _gain(a, b, r, p)
        acl = _closed(a, b, k)
        rk = np.empty_like(k)
        matmul(r, k, rk)
        w = qx.copy()
        kr = np.empty((n, n))
        matmul_tn(k, rk, kr)
        w += kr
        p_new = _dlyap(acl, w)
        p_new = 0.5 * (p_new + p_new.T)
        res_new = _residual_loops(a, b, qx, r, p_new)
        if not res_new < res:
            break
        p, res = p_new, res_new
    return p


@njit(cache=True)
def _riccati_loops(a, b, rinv_bt, qx, p, tol, max_iter):
    # the iteration of riccati_iterate written out on preallocated buffers (_smallmat):
    # P <- Qx + A^T P (I + B R^-1 B^T P)^-1 A
    n = a.shape[0]
    brb = np.empty((n, n))
    matmul(b, rinv_bt, brb)
    p = p.copy()
    p_new = np.empty((n, n))
    w = np.empty((n, n))
    x = np.empty((n, n))
    y = np.empty((n, n))
    for _ in range(max_iter):
        matmul(brb, p, w)
        for i in range(n):
            w[i, i] += 1.0
        # element by element: a slice assignment compiles numba's shape-mismatch
        # message (string formatting), 3.4 of this loop's 5.5 s of cold compile
        for i in range(n):
            for j in range(n):
                x[i, j] = a[i, j]
        if not gauss_solve(w, x):
            return p, False
        matmul(p, x, y)
        matmul_tn(a, y, p_new)
        big = 0.0
        for i in range(n):
            for j in range(n):
                p_new[i, j] += qx[i, j]
        for i in range(n):
            for j in range(i + 1, n):
                v = 0.5 * (p_new[i, j] + p_new[j, i])
                p_new[i, j] = v
                p_new[j, i] = v
        change = 0.0
        for i in range(n):
            for j in range(n):
                big = max(big, abs(p_new[i, j]))
                change = max(change, abs(p_new[i, j] - p[i, j]))
        if change <= tol * max(1.0, big):
            return p_new, True
        p, p_new = p_new, p
    return p, False


@dataclass(frozen=True)
class TrackerMatrices:
    """P (eq 2.12) and Ag, Bg, Cg, K, Kv, H (eqs 2.16-2.21)."""

    P: np.ndarray
    Ag: np.ndarray
    Bg: np.ndarray
    Cg: np.ndarray
    K: np.ndarray
    Kv: np.ndarray
    H: np.ndarray


def tracker_matrices(a, b, c, q, r, p=None, solver=None) -> TrackerMatrices:
    """Matrices of the optimal tracker (eqs 2.12, 2.16-2.21).

    Parameters
    ----------
    a : array (n, n); b : array (n, m); c : array (ny, n)
    q : array (ny, ny)
        Error weight, symmetric positive semidefinite.
    r : array (m, m)
        Effort weight, symmetric positive definite.
    p : array (n, n), optional
        A Riccati solution to use; default ``solver(A, B, C^T Q C, R)``.
    solver : callable, optional
        :func:`riccati_iterate` (default) or :func:`riccati_solve`.
    """
    a = np.atleast_2d(np.asarray(a, dtype=float))
    b = np.asarray(b, dtype=float).reshape(a.shape[0], -1)
    c = np.atleast_2d(np.asarray(c, dtype=float))
    q, r = _weights(q, r, c.shape[0], b.shape[1])
    if p is None:
        p = (solver or riccati_iterate)(a, b, c.T @ q @ c, r)
    kv = np.linalg.solve(r + b.T @ p @ b, b.T)  # eq 2.20
    bg = -b @ kv  # eq 2.17
    k = kv @ p @ a  # eq 2.19
    ag = a + bg @ p @ a  # eq 2.16
    cg = -c.T @ q  # eq 2.18
    h = p - c.T @ q @ c  # eq 2.21
    return TrackerMatrices(P=p, Ag=ag, Bg=bg, Cg=cg, K=k, Kv=kv, H=h)


def preview_steps(ag, eps) -> int:
    """Number of preview steps ``I_p`` (eq 2.35): the least n with ``||Ag^n||_2 <= eps``.

    The source bounds ``||Ag^n||`` by ``a^n`` with ``a = ||Ag||_2 < 1`` (eqs 2.32-2.33);
    that premise can fail (``||Ag||_2 >= 1`` with all eigenvalues inside the unit circle),
    so the powers themselves are used.
    """
    eps = float(check_positive("eps", eps))
    ag = np.asarray(ag, dtype=float)
    if np.max(np.abs(np.linalg.eigvals(ag))) >= 1.0:
        raise AbglibValueError("Ag must have all eigenvalues inside the unit circle")
    m = np.eye(ag.shape[0])
    n = 0
    while np.linalg.norm(m, 2) > eps:
        m = ag @ m
        n += 1
    return n


def _zcol(z, ny):
    z = np.asarray(z, dtype=float)
    return z.reshape(-1, ny)


def finite_preview_u0(tm: TrackerMatrices, x0, z):
    """Exact optimal ``u_0`` for the horizon ``n = len(z)`` (eqs 2.22-2.28).

    Parameters
    ----------
    z : array (n,) or (n, ny)
        Desired outputs ``z_1 .. z_n``.

    Notes
    -----
    ``r_i = -Phi_{n-i}^T H x_n + sum_k Phi_k^T Cg z_{i+k}`` (eq 2.22, ``Phi_k = Ag^k``),
    ``x_n = [I + G_n H]^{-1}(Phi_n x_0 + sum_k R_k Cg z_k)`` (eq 2.27) with
    ``G_n = sum_j Phi_{n-j} Bg Phi_{n-j}^T`` and ``R_k = sum_{j<=k} Phi_{n-j} Bg Phi_{k-j}^T``
    (eqs 2.25-2.26), then ``u_0 = -K x_0 - Kv r_1`` (eq 2.13).
    """
    ag, bg, cg = tm.Ag, tm.Bg, tm.Cg
    nx = ag.shape[0]
    zz = _zcol(z, cg.shape[1])
    n = zz.shape[0]
    if n < 1:
        raise AbglibValueError("z must hold at least one future desired output")
    x0 = np.asarray(x0, dtype=float).reshape(nx)
    phi = [np.eye(nx)]
    for _ in range(n):
        phi.append(ag @ phi[-1])
    gz = [cg @ zz[k - 1] for k in range(1, n + 1)]  # Cg z_k, k = 1..n
    # G_n and sum_k R_k Cg z_k
    gn = np.zeros((nx, nx))
    s = np.zeros(nx)
    # w_j = sum_{k>=j} Phi_{k-j}^T Cg z_k (co-state sum without the terminal term, eq 2.22)
    w = np.zeros((n + 2, nx))
    for j in range(n, 0, -1):
        w[j] = ag.T @ w[j + 1] + gz[j - 1]
    for j in range(1, n + 1):
        gn += phi[n - j] @ bg @ phi[n - j].T
        s += phi[n - j] @ bg @ w[j]
    xn = np.linalg.solve(np.eye(nx) + gn @ tm.H, phi[n] @ x0 + s)
    r1 = -phi[n - 1].T @ tm.H @ xn + w[1]
    return -tm.K @ x0 - tm.Kv @ r1


def truncated_preview_u0(tm: TrackerMatrices, x0, z):
    """``u_0`` with the terminal term dropped and ``n = I_p = len(z)`` steps (eqs 2.36-2.37)."""
    zz = _zcol(z, tm.Cg.shape[1])
    nx = tm.Ag.shape[0]
    r1 = np.zeros(nx)
    for k in range(zz.shape[0], 0, -1):
        r1 = tm.Ag.T @ r1 + tm.Cg @ zz[k - 1]
    return -tm.K @ np.asarray(x0, dtype=float).reshape(nx) - tm.Kv @ r1
