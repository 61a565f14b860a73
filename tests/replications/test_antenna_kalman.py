"""Seed 004, ch. 7 and app. G: the Kalman filter on the extended model."""

import control
import numpy as np
import pytest
import scipy.linalg

from abglib._checks import AbglibValueError
from abglib.replications.antenna import (
    AntennaParams,
    discrete_plant,
    extended_model,
    kalman_gains,
    kalman_object_enbw,
    kalman_riccati,
    taylor_model,
)

from .antenna_common import DT, NOMINAL_VALUES

NOMINAL = AntennaParams(**NOMINAL_VALUES)
VV = 1e-3 * np.eye(2)


@pytest.fixture(scope="module", params=[(3, 5e-6), (5, 5e-10)])
def setup(request):
    order, vw = request.param
    a, b, c = discrete_plant(NOMINAL, DT)
    at, ct, gt = taylor_model(order, DT)
    em = extended_model(a, b, c, at, ct, gt)
    return em, kalman_gains(em, vw, VV), vw, (at, ct, gt)


def test_riccati_7_15_vs_dual_dare_and_dlqe(setup):
    em, kg, vw, (at, ct, gt) = setup
    n = em.n_antenna
    # the antenna block stays zero (w = 0 for the antenna, sec. 7.3)
    assert np.abs(kg.Q[:n, :]).max() == 0.0
    # object block: the dual DARE (scipy) and python-control's dlqe on the object model
    # measured through the tracking error (noise V_v[1, 1])
    q_dare = scipy.linalg.solve_discrete_are(at.T, ct.T, vw * gt @ gt.T, VV[1:, 1:])
    np.testing.assert_allclose(kg.Q[n:, n:], q_dare, rtol=1e-6, atol=1e-9 * np.abs(q_dare).max())
    ll, p_ctl, _ = control.dlqe(at, gt, ct, [[vw]], VV[1:, 1:])
    # the error measurement is phi_a - z: the object gain is minus python-control's
    np.testing.assert_allclose(-kg.Kf[n:, 1:2], ll, rtol=1e-6, atol=1e-12)
    np.testing.assert_allclose(kg.Kf[n:, 0], 0.0, atol=1e-12)


def test_gain_identities(setup):
    em, kg, _, _ = setup
    s = em.M @ kg.Q @ em.M.T + VV
    # eq 7.19 in the source's form, A Q [I + M^T Vv^-1 M Q]^-1 M^T Vv^-1
    vinv = np.linalg.inv(VV)
    k_src = (
        em.A
        @ kg.Q
        @ np.linalg.solve(np.eye(len(kg.Q)) + em.M.T @ vinv @ em.M @ kg.Q, em.M.T @ vinv)
    )
    np.testing.assert_allclose(kg.Kf, k_src, atol=1e-9 * max(1.0, np.abs(kg.Kf).max()))
    np.testing.assert_allclose(kg.Kf, -em.A @ kg.Q @ kg.Cf, atol=1e-12)  # eq 7.20
    np.testing.assert_allclose(kg.Af, em.A - kg.Kf @ em.M, atol=1e-14)
    assert np.abs(np.linalg.eigvals(kg.Af[em.n_antenna :, em.n_antenna :])).max() < 1.0
    assert s.shape == (2, 2)


def test_enbw_by_impulse_response(setup):
    """Object-estimator ENBW (Lyapunov) against the summed impulse response."""
    em, kg, _, _ = setup
    n = em.n_antenna
    at, ct = em.A[n:, n:], -em.M[1:2, n:]
    ll = -kg.Kf[n:, 1:2]
    f = at - ll @ ct
    h, x = [], ll.copy()
    for _ in range(20000):
        h.append((ct @ x)[0, 0])
        x = f @ x
    assert kalman_object_enbw(kg, em, DT) == pytest.approx(
        np.sum(np.square(h)) / (2 * DT), rel=1e-9
    )


def test_kalman_errors():
    with pytest.raises(AbglibValueError, match="V_v must be symmetric positive definite"):
        kalman_riccati(np.eye(2), np.ones((1, 2)), np.eye(2), [[0.0]])
    with pytest.raises(AbglibValueError, match="V_w must be symmetric positive semidefinite"):
        kalman_riccati(np.eye(2), np.ones((1, 2)), -np.eye(2), [[1.0]])
    a, b, c = discrete_plant(NOMINAL, DT)
    em = extended_model(a, b, c, *taylor_model(2, DT))
    with pytest.raises(AbglibValueError, match="V_w"):
        kalman_gains(em, 0.0, VV)
