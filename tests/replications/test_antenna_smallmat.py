"""Seed 004: the written-out small-matrix kernels of the Riccati solvers against numpy/scipy
and against the BLAS route they replaced (the same formulas with ``@`` and ``solve``)."""

import numpy as np
import pytest
import scipy.linalg

from abglib.replications.antenna import (
    AntennaParams,
    discrete_plant,
    extended_model,
    lq,
    taylor_model,
)
from abglib.replications.antenna import kalman as kalman_mod
from abglib.replications.antenna._smallmat import gauss_solve, matmul, matmul_nt, matmul_tn

from .antenna_common import DT, NOMINAL_VALUES, OWN_KERNEL_SIGNATURES

pytestmark = OWN_KERNEL_SIGNATURES

NOMINAL = AntennaParams(**NOMINAL_VALUES)
VV = 1e-3 * np.eye(2)


def test_kernels_vs_numpy():
    rng = np.random.default_rng(4)
    a, b = rng.normal(size=(5, 3)), rng.normal(size=(3, 4))
    a[1, 2] = 0.0  # a skipped zero
    out = np.empty((5, 4))
    matmul(a, b, out)
    np.testing.assert_allclose(out, a @ b, rtol=1e-14, atol=1e-14)
    out = np.empty((3, 3))
    matmul_tn(a, a, out)
    np.testing.assert_allclose(out, a.T @ a, rtol=1e-14, atol=1e-14)
    out = np.empty((4, 4))
    matmul_nt(b.T, b.T, out)
    np.testing.assert_allclose(out, b.T @ b, rtol=1e-14, atol=1e-14)
    w = rng.normal(size=(6, 6))
    w[0, 0] = 0.0  # needs a pivot
    x = rng.normal(size=(6, 2))
    y = x.copy()
    assert gauss_solve(w.copy(), y)
    np.testing.assert_allclose(y, np.linalg.solve(w, x), rtol=1e-12)
    assert not gauss_solve(np.zeros((2, 2)), np.ones((2, 1)))


def _value_iteration_blas(a, b, qx, r, tol=1e-13):
    # the route of abglib <= 0.3: numpy's @ and solve (BLAS/LAPACK), before the Newton polish
    p = qx.copy()
    brb = b @ np.linalg.solve(r, b.T)
    for _ in range(200000):
        p_new = qx + a.T @ p @ np.linalg.solve(np.eye(len(a)) + brb @ p, a)
        p_new = 0.5 * (p_new + p_new.T)
        if np.max(np.abs(p_new - p)) <= tol * max(1.0, np.max(np.abs(p_new))):
            return p_new
        p = p_new
    raise AssertionError("no convergence")


@pytest.mark.parametrize("q", [100.0, 1e4])
def test_lq_kernels_vs_blas_route_and_scipy(q):
    a, b, c = discrete_plant(NOMINAL, DT)
    qx = c.T @ [[q]] @ c
    r = np.eye(1)
    p_are = scipy.linalg.solve_discrete_are(a, b, qx, r)
    scale = np.abs(p_are).max()
    p_blas = _value_iteration_blas(a, b, qx, r)
    p_loop, ok = lq._riccati_loops(a, b, np.linalg.solve(r, b.T), qx, qx.copy(), 1e-13, 200000)
    assert ok
    # the same iteration: round-off apart
    assert np.max(np.abs(p_loop - p_blas)) / scale < 1e-12
    # polished: the fixed point, that of the BLAS route to round-off (scipy's Schur route
    # agrees to its own round-off)
    p = lq.riccati_solve(a, b, qx, r)
    assert np.max(np.abs(p - lq.riccati_iterate(a, b, qx, r))) / scale < 1e-14
    assert np.max(np.abs(p - p_are)) / scale < 1e-13
    # one Newton step's Lyapunov solve against scipy's direct (Kronecker) method
    k = np.linalg.solve(r + b.T @ p @ b, b.T @ p @ a)
    acl = a - b @ k
    w = qx + k.T @ r @ k
    ref = scipy.linalg.solve_discrete_lyapunov(acl.T, w, method="direct")
    np.testing.assert_allclose(lq._dlyap(acl, w), ref, rtol=1e-10, atol=1e-12 * scale)
    assert lq._residual_loops(a, b, qx, r, p) == pytest.approx(
        lq._residual(a, b, qx, r, p), abs=1e-12 * scale
    )


def _kalman_blas(a, m, vw, vv, tol=1e-12):
    # the route of abglib <= 0.3 (numba @ and solve, i.e. BLAS/LAPACK), in numpy
    q = vw.copy()
    for _ in range(1_000_000):
        s = m @ q @ m.T + vv
        qn = vw + a @ (q - q @ m.T @ np.linalg.solve(s, m @ q)) @ a.T
        qn = 0.5 * (qn + qn.T)
        d = np.sqrt(np.maximum(np.diag(qn), 1e-300))
        if np.max(np.abs(qn - q) / np.outer(d, d)) < tol:
            return qn
        q = qn
    raise AssertionError("no convergence")


@pytest.mark.parametrize(("order", "vw"), [(3, 5e-6), (5, 5e-10), (5, 5e-2)])
def test_kalman_kernel_vs_blas_route_and_scipy(order, vw):
    a, b, c = discrete_plant(NOMINAL, DT)
    at, ct, gt = taylor_model(order, DT)
    em = extended_model(a, b, c, at, ct, gt)
    vwm = vw * em.G @ em.G.T
    q = kalman_mod.kalman_riccati(em.A, em.M, vwm, VV, fast=True)
    n = em.n_antenna
    assert np.abs(q[:n]).max() == 0.0 and np.abs(q[:, :n]).max() == 0.0
    # the reduced iteration (object block) is the full one with the exact zeros left out
    q_full, ok = kalman_mod._kalman_iterate(em.A, em.M, vwm, VV, 1e-12, 1_000_000)
    assert ok and q.tobytes() == q_full.tobytes()
    # against the BLAS route (numba's, the default, and numpy's): the same iteration,
    # round-off apart
    q_blas = _kalman_blas(em.A, em.M, vwm, VV)
    scale = np.abs(q_blas).max()
    assert np.max(np.abs(q - q_blas)) / scale < 1e-11
    q_default = kalman_mod.kalman_riccati(em.A, em.M, vwm, VV)
    assert np.max(np.abs(q_default - q_blas)) / scale < 1e-11
    # and the dual DARE of the object model (scipy)
    q_dare = scipy.linalg.solve_discrete_are(at.T, ct.T, vw * gt @ gt.T, VV[1:, 1:])
    assert np.max(np.abs(q[n:, n:] - q_dare)) / scale < 1e-9


@pytest.mark.parametrize("factor", [0.1, 0.5, 2.0])
def test_spectral_radius_vs_blas_route(factor):
    """App. H's radius (compiled solvers) against the same loop designed by the BLAS
    routes: a stable design's radius is the marginal mode's 1 to ~1e-8 (a double
    eigenvalue: below the RADIUS_DIGITS written), an unstable one's agrees to round-off."""
    from abglib.replications.antenna.closedloop import closed_loop_matrix, design_controller
    from abglib.replications.antenna.robustness import RADIUS_DIGITS, spectral_radius

    args = (NOMINAL, "beta_d", factor, DT, 100.0, 1.0, 5, 5e-9, VV)
    ctrl = design_controller(NOMINAL.scaled("beta_d", factor), DT, 100.0, 1.0)
    big = closed_loop_matrix(NOMINAL, ctrl, 5, 5e-9, VV)
    r0 = float(np.max(np.abs(np.linalg.eigvals(big))))
    r1 = spectral_radius(*args)
    assert abs(r1 - r0) < 0.05 * 10.0 ** (1 - RADIUS_DIGITS)  # a tenth of a written half unit
    if r0 > 1.0 + 1e-6:
        assert r1 == pytest.approx(r0, rel=1e-12)
