"""The steady-state Kalman filter of a polynomial target model: the discrete algebraic
Riccati equation (DARE) that :func:`abglib.design.steady_state_kalman` designs gains from.

Seed 000, eqs 1-6: the tracker's corrector is the Kalman update with gain
``[alpha, beta/T, gamma/T^2]`` for the transition ``Phi`` of eqs 4-6, so the steady state of
the Riccati recursion gives fixed gains; :func:`process_noise` is the process-noise
covariance of each target model and :func:`kalman_gains` solves the DARE (the numeric twin
of Kalata's closed forms, :func:`abglib.design.kalata_ab`, :func:`abglib.design.kalata_abg`).
"""

from __future__ import annotations

import numpy as np

from .._checks import AbglibValueError

__all__ = ["KALMAN_MODELS", "kalman_gains", "process_noise"]

#: Process-noise models of :func:`abglib.design.steady_state_kalman` (its ``model``).
KALMAN_MODELS = ("piecewise_constant", "piecewise_constant_jerk", "continuous")


def process_noise(order: int, model: str, T: float) -> np.ndarray:
    """Process-noise covariance per unit ``q`` of a target model (order x order).

    ``model`` is one of :data:`~abglib.analysis.KALMAN_MODELS` (described at
    :func:`abglib.design.steady_state_kalman`); ``order`` 2 (state ``[x, v]``) or 3
    (``[x, v, a]``); ``T`` the sample interval.

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eqs 4-6 (the transition the noise
    enters); the piecewise-constant and continuous white-noise models are the standard
    ones of target tracking (Bar-Shalom, Li and Kirubarajan, *Estimation with
    Applications to Tracking and Navigation*, 2001, §6.2-6.3).
    """
    if model not in KALMAN_MODELS:
        raise AbglibValueError(f"model must be one of {list(KALMAN_MODELS)}, got {model!r}")
    if model == "piecewise_constant":
        G = np.array([T**2 / 2, T]) if order == 2 else np.array([T**2 / 2, T, 1.0])
        return np.outer(G, G)
    if model == "piecewise_constant_jerk":
        G = np.array([T**3 / 6, T**2 / 2, T])
        return np.outer(G, G)
    if order == 2:
        return np.array([[T**3 / 3, T**2 / 2], [T**2 / 2, T]])
    return np.array(
        [
            [T**5 / 20, T**4 / 8, T**3 / 6],
            [T**4 / 8, T**3 / 3, T**2 / 2],
            [T**3 / 6, T**2 / 2, T],
        ]
    )


def kalman_gains(q: float, r: float, T: float, order: int, model: str) -> tuple:
    """Canonical ``(alpha, beta, gamma)`` of the steady-state Kalman filter of one model.

    Solves the filtering DARE for the a-priori covariance ``P`` and returns the
    a-posteriori gain ``K = P H^T / (H P H^T + r)`` scaled to the canonical convention
    (``alpha = K_1``, ``beta = K_2 T``, ``gamma = K_3 T^2``; gamma 0 for order 2).
    Scalars only: :func:`abglib.design.steady_state_kalman` checks the inputs and
    broadcasts.

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eqs 1-6 (the corrector as a Kalman
    update with gain ``[alpha, beta/T, gamma/T^2]``).
    """
    if order == 2:
        Phi = np.array([[1.0, T], [0.0, 1.0]])
    else:
        Phi = np.array([[1.0, T, T**2 / 2], [0.0, 1.0, T], [0.0, 0.0, 1.0]])
    H = np.zeros((1, order))
    H[0, 0] = 1.0
    Q = q * process_noise(order, model, T)
    # filtering DARE (dual of the control one): P is the a-priori (predicted) covariance
    from scipy.linalg import solve_discrete_are  # here: importing scipy costs ~0.3 s

    P = solve_discrete_are(Phi.T, H.T, Q, np.array([[r]]))
    K = (P @ H.T / (H @ P @ H.T + r)).ravel()  # a-posteriori (filter) gain
    scale = np.array([1.0, T, T**2])[:order]  # K = [alpha, beta/T, gamma/T^2]
    out = K * scale
    return (out[0], out[1], out[2] if order == 3 else 0.0)
