"""The steady-state Kalman filter's Riccati route (abglib.analysis._kalman) against
independent routes: Kalata's closed forms, the Riccati recursion iterated to its fixed
point, and the continuous process noise integrated numerically."""

import numpy as np
import pytest
from scipy.integrate import quad_vec
from scipy.linalg import expm

from abglib import design
from abglib._checks import AbglibValueError
from abglib.analysis import KALMAN_MODELS, kalman_gains, process_noise


@pytest.mark.parametrize(("q", "r", "T"), [(1.0, 1.0, 1.0), (0.3, 2.0, 0.5), (4.0, 0.1, 2.0)])
def test_piecewise_constant_is_kalata(q, r, T):
    """Kalata's tracking index Lambda = sqrt(q) T^2 / sqrt(r) (design.steady_state_kalman's
    Notes); both orders."""
    lam = np.sqrt(q) * T**2 / np.sqrt(r)
    a, b, g = kalman_gains(q, r, T, 2, "piecewise_constant")
    k = design.kalata_ab(lam)
    np.testing.assert_allclose([a, b, g], [k.alpha, k.beta, 0.0], rtol=1e-10, atol=1e-14)
    a, b, g = kalman_gains(q, r, T, 3, "piecewise_constant")
    k = design.kalata_abg(lam)
    np.testing.assert_allclose([a, b, g], [k.alpha, k.beta, k.gamma], rtol=1e-8)


@pytest.mark.parametrize("model", KALMAN_MODELS)
def test_dare_is_the_fixed_point_of_the_riccati_recursion(model):
    """The a-posteriori gain of the recursion P <- Phi (P - P H' H P / (H P H' + r)) Phi' + Q
    run from P = I until it stops moving (a route without scipy's DARE solver)."""
    q, r, T = 0.5, 1.5, 0.8
    Phi = np.array([[1.0, T, T**2 / 2], [0.0, 1.0, T], [0.0, 0.0, 1.0]])
    H = np.array([[1.0, 0.0, 0.0]])
    Q = q * process_noise(3, model, T)
    P = np.eye(3)
    for _ in range(5000):
        K = P @ H.T / (H @ P @ H.T + r)
        P = Phi @ (P - K @ H @ P) @ Phi.T + Q
    K = (P @ H.T / (H @ P @ H.T + r)).ravel() * np.array([1.0, T, T**2])
    np.testing.assert_allclose(kalman_gains(q, r, T, 3, model), K, rtol=1e-9)


def test_continuous_process_noise_is_the_integral():
    """Q = int_0^T e^{At} b b' e^{A't} dt for white noise on the highest derivative,
    integrated numerically (scipy's quad_vec of expm)."""
    T = 0.7
    for order in (2, 3):
        A = np.diag(np.ones(order - 1), 1)
        b = np.zeros(order)
        b[-1] = 1.0

        def f(t, A=A, b=b):
            e = expm(A * t) @ b
            return np.outer(e, e)

        expected, _ = quad_vec(f, 0.0, T, epsabs=1e-14)
        np.testing.assert_allclose(process_noise(order, "continuous", T), expected, rtol=1e-12)


def test_unknown_model_names_the_allowed_ones():
    with pytest.raises(AbglibValueError, match=r"model must be one of \['piecewise_constant'"):
        process_noise(2, "white", 1.0)
