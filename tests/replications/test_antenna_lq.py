"""Seed 004, ch. 2 and app. B-C: Riccati eq 2.12, matrices 2.16-2.21, preview laws 2.28/2.37."""

import control
import numpy as np
import pytest
import scipy.linalg
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from abglib._checks import AbglibValueError
from abglib.replications.antenna import (
    AntennaParams,
    discrete_plant,
    finite_preview_u0,
    newton_polish,
    preview_steps,
    riccati_iterate,
    tracker_matrices,
    truncated_preview_u0,
)

from .antenna_common import DT, NOMINAL_VALUES

NOMINAL = AntennaParams(**NOMINAL_VALUES)


@pytest.fixture(scope="module")
def plant():
    return discrete_plant(NOMINAL, DT)


@pytest.mark.parametrize("q", [100.0, 1e4])
def test_riccati_iteration_vs_scipy_and_dlqr(plant, q):
    a, b, c = plant
    p_it = riccati_iterate(a, b, c.T @ [[q]] @ c, [[1.0]])
    p_are = scipy.linalg.solve_discrete_are(a, b, c.T @ [[q]] @ c, [[1.0]])
    np.testing.assert_allclose(p_it, p_are, rtol=1e-8, atol=1e-8 * np.abs(p_are).max())
    k_ctl, p_ctl, e_ctl = control.dlqr(a, b, c.T @ [[q]] @ c, [[1.0]])
    tm = tracker_matrices(a, b, c, [[q]], [[1.0]])
    # python-control's gain and closed-loop poles against eq 2.19 and eq 2.16
    np.testing.assert_allclose(tm.K, k_ctl, rtol=1e-7, atol=1e-9)
    np.testing.assert_allclose(
        np.sort_complex(np.linalg.eigvals(tm.Ag)), np.sort_complex(e_ctl), atol=1e-8
    )


def test_matrix_identities(plant):
    """Eqs 2.16-2.21 against each other: Ag = A - B K, Bg = -B Kv, K = Kv P A."""
    a, b, c = plant
    tm = tracker_matrices(a, b, c, [[100.0]], [[1.0]])
    np.testing.assert_allclose(tm.Ag, a - b @ tm.K, atol=1e-12)
    np.testing.assert_allclose(tm.Bg, -b @ tm.Kv, atol=1e-14)
    np.testing.assert_allclose(tm.H, tm.P - c.T @ [[100.0]] @ c, atol=1e-12)
    # the co-state recursion matrix of app. B, A^T (I - P B [B^T P B + R]^-1 B^T) = Ag^T
    m = a.T @ (np.eye(6) - tm.P @ b @ np.linalg.solve(b.T @ tm.P @ b + 1.0, b.T))
    np.testing.assert_allclose(m, tm.Ag.T, atol=1e-10)


def _dp_u0(a, b, c, q, r, x0, z):
    """Finite-horizon LQ tracking by backward dynamic programming (textbook route):
    V_i(x) = x'P_i x/2 - s_i'x + const, P_n = C'QC, s_n = C'Q z_n."""
    n = len(z)
    p = c.T @ q @ c
    s = (c.T @ q * z[-1]).ravel()
    for i in range(n - 1, -1, -1):
        g = np.linalg.solve(r + b.T @ p @ b, b.T)
        if i == 0:
            return -(g @ (p @ a @ x0 - s))
        lgain = g @ p @ a
        s = (a - b @ lgain).T @ s + (c.T @ q * z[i - 1]).ravel()
        p = c.T @ q @ c + a.T @ p @ (a - b @ lgain)


@pytest.mark.parametrize("n", [1, 2, 5, 30])
def test_finite_preview_eq_2_28_equals_dynamic_programming(plant, n):
    a, b, c = plant
    rng = np.random.default_rng(4)  # fixed seed: arbitrary state and desired outputs
    x0 = rng.normal(size=6)
    z = rng.normal(size=n)
    q, r = np.array([[100.0]]), np.array([[1.0]])
    tm = tracker_matrices(a, b, c, q, r)
    u_report = finite_preview_u0(tm, x0, z)
    u_dp = _dp_u0(a, b, c, q, r, x0, z)
    np.testing.assert_allclose(u_report, u_dp, rtol=1e-8, atol=1e-10)


def test_truncated_preview_converges_to_exact(plant):
    """Eq 2.37 (terminal term dropped) -> eq 2.28 as n grows beyond I_p (eq 2.35)."""
    a, b, c = plant
    tm = tracker_matrices(a, b, c, [[100.0]], [[1.0]])
    ip = preview_steps(tm.Ag, 1e-10)
    t = np.arange(1, 3 * ip + 1) * DT
    z = np.sin(0.3 * t)
    x0 = np.zeros(6)
    gaps = [
        abs(finite_preview_u0(tm, x0, z[:n])[0] - truncated_preview_u0(tm, x0, z[:n])[0])
        for n in (ip // 4, ip // 2, ip, 2 * ip)
    ]
    assert gaps[-1] < 1e-7 * np.abs(tm.Kv).max() * 100
    assert gaps[-1] < gaps[0]


def test_preview_steps_definition(plant):
    a, b, c = plant
    tm = tracker_matrices(a, b, c, [[100.0]], [[1.0]])
    n = preview_steps(tm.Ag, 1e-6)
    assert np.linalg.norm(np.linalg.matrix_power(tm.Ag, n), 2) <= 1e-6
    assert np.linalg.norm(np.linalg.matrix_power(tm.Ag, n - 1), 2) > 1e-6
    # eq 2.32's premise ||Ag||_2 < 1 does not hold although Ag is stable
    assert np.linalg.norm(tm.Ag, 2) > 1.0 > np.abs(np.linalg.eigvals(tm.Ag)).max()
    with pytest.raises(AbglibValueError, match="inside the unit circle"):
        preview_steps(np.eye(2), 1e-3)


def test_weight_errors(plant):
    a, b, c = plant
    with pytest.raises(AbglibValueError, match="R must be symmetric positive definite"):
        tracker_matrices(a, b, c, [[1.0]], [[0.0]])
    with pytest.raises(AbglibValueError, match="Q must be symmetric positive semidefinite"):
        tracker_matrices(a, b, c, [[-1.0]], [[1.0]])
    with pytest.raises(AbglibValueError, match=r"Q must be \(1, 1\)"):
        tracker_matrices(a, b, c, np.eye(2), [[1.0]])
    with pytest.raises(AbglibValueError, match="did not converge"):
        riccati_iterate(a, b, c.T @ c, np.eye(1), max_iter=2)


@settings(max_examples=15, deadline=None, derandomize=True)
@given(st.integers(2, 5), st.floats(0.5, 1.2), st.floats(0.1, 100.0), st.integers(0, 2**31 - 1))
def test_riccati_iteration_random_systems(n, rho, q, seed):
    """Eq 2.12 by iteration against scipy's Schur-based DARE on random (possibly unstable)
    controllable, observable systems."""
    rng = np.random.default_rng(seed)
    a = rng.normal(size=(n, n))
    a *= rho / np.abs(np.linalg.eigvals(a)).max()
    b = rng.normal(size=(n, 1))
    c = rng.normal(size=(1, n))
    ctrb = np.hstack([np.linalg.matrix_power(a, k) @ b for k in range(n)])
    obsv = np.vstack([c @ np.linalg.matrix_power(a, k) for k in range(n)])
    assume(np.linalg.cond(ctrb) < 1e6 and np.linalg.cond(obsv) < 1e6)
    qx = c.T @ [[q]] @ c
    p_are = scipy.linalg.solve_discrete_are(a, b, qx, [[1.0]])
    p_it = riccati_iterate(a, b, qx, [[1.0]])
    np.testing.assert_allclose(p_it, p_are, rtol=1e-7, atol=1e-9 * np.abs(p_are).max())


def test_riccati_newton_polish_reaches_the_fixed_point():
    """Q/R = 10^4 on a lightly damped antenna (beta_a = 0.02): the value iteration converges
    slowly and stops 3.6e-13 (relative) from the fixed point at a kernel-dependent step;
    the Newton polish lands on the fixed point to round-off, whatever the start."""
    params = AntennaParams(**{**NOMINAL_VALUES, "beta_a": 0.02, "beta_d": 0.002, "beta_f": 0.04})
    a, b, c = discrete_plant(params, DT)
    qx = c.T @ [[1e4]] @ c
    p_are = scipy.linalg.solve_discrete_are(a, b, qx, [[1.0]])
    p_it = riccati_iterate(a, b, qx, [[1.0]])
    scale = np.abs(p_are).max()
    assert np.max(np.abs(p_it - p_are)) / scale < 1e-14
    # from a start 1e-9 off the fixed point (a coarse iteration), the same answer
    p_off = p_are * (1.0 + 1e-9)
    p_pol = newton_polish(a, b, qx, [[1.0]], p_off)
    assert np.max(np.abs(p_pol - p_are)) / scale < 1e-14
    # and a one-ulp perturbation of the start does not move the answer beyond round-off
    p_ulp = newton_polish(a, b, qx, [[1.0]], np.nextafter(p_it, np.inf))
    assert np.max(np.abs(p_ulp - p_it)) / scale < 1e-14
