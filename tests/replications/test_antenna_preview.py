"""Seed 004, ch. 3-4 and app. E: Taylor object model and the infinite-preview law."""

import math

import numpy as np
import pytest
import scipy.linalg
from hypothesis import given, settings
from hypothesis import strategies as st

from abglib._checks import AbglibValueError
from abglib.replications.antenna import (
    AntennaParams,
    discrete_plant,
    preview_gain,
    preview_series,
    sine_model,
    sine_state,
    stein_solve,
    taylor_model,
    taylor_predict,
    tracker_matrices,
    truncated_preview_u0,
)

from .antenna_common import DT, NOMINAL_VALUES

NOMINAL = AntennaParams(**NOMINAL_VALUES)


@pytest.fixture(scope="module")
def tm():
    a, b, c = discrete_plant(NOMINAL, DT)
    return tracker_matrices(a, b, c, [[100.0]], [[1.0]])


@pytest.mark.parametrize("order", [0, 1, 3, 5])
def test_taylor_model_is_the_taylor_polynomial(order):
    """Fig. I.4: C_t A_t^k x_t0 equals the Taylor polynomial of sin about t0 = 0.5 (closed
    form with math.factorial), and the remainder obeys the Lagrange bound."""
    dt, i0 = 0.01, 50
    at, ct, _ = taylor_model(order, dt)
    x0 = sine_state(1.0, 1.0, i0 * dt, order)
    k = np.arange(0, 200)
    model = np.array([(ct @ np.linalg.matrix_power(at, int(kk)) @ x0)[0] for kk in k])
    h = k * dt
    closed = sum(
        math.sin(i0 * dt + j * math.pi / 2) * h**j / math.factorial(j) for j in range(order + 1)
    )
    np.testing.assert_allclose(model, closed, atol=1e-12)
    np.testing.assert_allclose(taylor_predict(x0, order, dt, k), closed, atol=1e-13)
    err = np.abs(closed - np.sin((i0 + k) * dt))
    assert np.all(err <= h ** (order + 1) / math.factorial(order + 1) + 1e-15)


def test_taylor_errors():
    with pytest.raises(AbglibValueError, match="order of prediction must be an integer >= 0"):
        taylor_model(-1, 0.1)
    with pytest.raises(AbglibValueError, match="order of prediction"):
        taylor_model(1.5, 0.1)
    with pytest.raises(AbglibValueError, match="x0 needs order \\+ 1 = 4"):
        taylor_predict([1.0, 2.0], 3, 0.1, [1])


@pytest.mark.parametrize("order", [1, 3, 5])
def test_stein_two_routes_and_series(tm, order):
    at, ct, _ = taylor_model(order, DT)
    c = tm.Cg @ ct @ at
    x1 = stein_solve(tm.Ag, at, c, "kron")
    x2 = stein_solve(tm.Ag, at, c, "sylvester")
    np.testing.assert_allclose(x1, x2, rtol=1e-9, atol=1e-12 * np.abs(x1).max())
    # residual of the equation itself
    np.testing.assert_allclose(x1, tm.Ag.T @ x1 @ at + c, atol=1e-9 * np.abs(x1).max())
    # finite preview converges to the infinite law (ch. 4): long horizon for high orders,
    # since A_t^n grows like n^order
    kt = preview_gain(tm, at, ct)
    gaps = [np.abs(preview_series(tm, at, ct, n) - kt).max() for n in (100, 200, 1600)]
    assert gaps[2] <= gaps[1] <= gaps[0]
    assert gaps[2] < 1e-9 * np.abs(kt).max()
    assert gaps[0] > gaps[2]


@settings(max_examples=20, deadline=None, derandomize=True)
@given(st.integers(2, 5), st.floats(0.1, 0.9), st.integers(0, 2**31 - 1))
def test_stein_symmetric_case_is_scipy_lyapunov(n, rho, seed):
    """With At = Ag and symmetric C, X = Ag^T X Ag + C is scipy's discrete Lyapunov equation."""
    rng = np.random.default_rng(seed)
    a = rng.normal(size=(n, n))
    a *= rho / np.abs(np.linalg.eigvals(a)).max()
    c = rng.normal(size=(n, n))
    c = c + c.T
    x_ly = scipy.linalg.solve_discrete_lyapunov(a.T, c)
    np.testing.assert_allclose(stein_solve(a, a, c, "kron"), x_ly, atol=1e-9 * np.abs(x_ly).max())
    np.testing.assert_allclose(
        stein_solve(a, a, c, "sylvester"), x_ly, atol=1e-8 * np.abs(x_ly).max()
    )


def test_known_output_preview_equals_truncated_future(tm):
    """Known output: the exact sine generator in the Stein equation equals eq 2.37 applied
    to the true future sine over a long horizon."""
    w, amp = 0.3, 2.0
    as_, cs = sine_model(w, DT)
    kt = preview_gain(tm, as_, cs)
    x0 = np.linspace(-0.1, 0.1, 6)
    zstate = np.array([amp * np.sin(0.4), amp * w * np.cos(0.4)])
    u_stein = -tm.K @ x0 - kt @ zstate
    t = 0.4 / w + np.arange(1, 400) * DT
    u_trunc = truncated_preview_u0(tm, x0, amp * np.sin(w * t))
    np.testing.assert_allclose(u_stein, u_trunc, rtol=1e-9)


def test_stein_errors(tm):
    with pytest.raises(AbglibValueError, match="inside the unit circle"):
        stein_solve(np.eye(2), np.eye(2), np.eye(2))
    with pytest.raises(AbglibValueError, match="method must be"):
        stein_solve(0.5 * np.eye(2), np.eye(2), np.eye(2), method="x")
    with pytest.raises(AbglibValueError, match=r"c must be \(2, 3\)"):
        stein_solve(0.5 * np.eye(2), np.eye(3), np.eye(2))
    with pytest.raises(AbglibValueError, match="omega must be > 0"):
        sine_model(0.0, 0.1)
