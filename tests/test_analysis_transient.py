"""Transient measures D^2, A^2 (seed 000, eqs 15-20) and steady-state lags (seed 002).

Findings pinned here: eqs 15-20 hold exactly for a tracker started from the zero state,
fed z(n) = n (velocity step) or z(n) = n^2/2 (acceleration step), with the squared
errors of the *smoothed* outputs summed from n = 0. Huang's A/(beta F_r^2) is the
predicted-position lag; his B/(gamma F_r^3) holds for the canonical gamma (twice his own).
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from abglib import Gains, track
from abglib.analysis._transient import (
    steady_state_lag,
    transient_a2,
    transient_a2_simpson,
    transient_d2,
    transient_d2_simpson,
)

from .strategies import stable_gain_strategies, standard_abg

stable_ab, stable_abg = stable_gain_strategies(0.9, 1e-4)  # pole radius < 0.9 keeps the sums short

dts = st.sampled_from([0.1, 1.0, 2.5])  # sample intervals in seconds (arbitrary)


# --------------------------------------------------------------------------- D^2, A^2
@settings(max_examples=40, deadline=None)
@given(stable_abg, dts)
def test_simpson_d2_eqs_15_17_exact(gains, dt):
    exact, printed = transient_d2(gains, dt), transient_d2_simpson(gains, dt)
    for k in ("x", "v", "a"):
        assert printed[k] == pytest.approx(exact[k], rel=1e-7, abs=1e-12), k


@settings(max_examples=40, deadline=None)
@given(stable_abg, dts)
def test_simpson_a2_eqs_18_20_exact(gains, dt):
    exact, printed = transient_a2(gains, dt), transient_a2_simpson(gains, dt)
    for k in ("x", "v", "a"):
        assert printed[k] == pytest.approx(exact[k], rel=1e-7, abs=1e-12), k


def test_reading_smoothed_outputs_from_n_zero():
    # the literal sums by hand for the standard gains at theta = 0.6 (arbitrary), T = 1
    g, n = standard_abg(0.6), np.arange(400.0)  # 0.6**400 ~ 1e-89: converged
    r = track(n, g)
    d2 = transient_d2_simpson(g)
    assert np.sum((n - r.x_smooth) ** 2) == pytest.approx(d2["x"], rel=1e-10)
    assert np.sum((1.0 - r.v_smooth) ** 2) == pytest.approx(d2["v"], rel=1e-10)
    assert np.sum(r.a_smooth**2) == pytest.approx(d2["a"], rel=1e-10)
    # other readings fail: starting at n = 1 drops the first velocity error (1),
    # and the predicted position gives a different sum
    assert np.sum((1.0 - r.v_smooth[1:]) ** 2) == pytest.approx(d2["v"] - 1.0, rel=1e-10)
    assert abs(np.sum((n - r.x_pred) ** 2) - d2["x"]) > 1.0
    r = track(0.5 * n**2, g)
    a2 = transient_a2_simpson(g)
    assert np.sum((0.5 * n**2 - r.x_smooth) ** 2) == pytest.approx(a2["x"], rel=1e-9)
    assert np.sum((n - r.v_smooth) ** 2) == pytest.approx(a2["v"], rel=1e-9)
    assert np.sum((1.0 - r.a_smooth) ** 2) == pytest.approx(a2["a"], rel=1e-9)


@settings(max_examples=40, deadline=None)
@given(stable_ab, dts)
def test_alpha_beta_d2_limit(gains, dt):
    # gamma = 0: eqs 15-17 are 0/0; their gamma -> 0 limit equals the exact sums
    exact, printed = transient_d2(gains, dt), transient_d2_simpson(gains, dt)
    for k in ("x", "v", "a"):
        assert printed[k] == pytest.approx(exact[k], rel=1e-8, abs=1e-12), k


def test_alpha_beta_d2_limit_is_the_small_gamma_value():
    g0, g1 = Gains(0.5, 0.2), Gains(0.5, 0.2, 1e-7)  # arbitrary stable alpha-beta
    lim, near = transient_d2_simpson(g0), transient_d2_simpson(g1)
    assert near["x"] == pytest.approx(lim["x"], rel=1e-5)
    assert near["v"] == pytest.approx(lim["v"], rel=1e-5)


def test_alpha_beta_a2_diverges():
    g = Gains(0.5, 0.2)  # arbitrary stable alpha-beta
    for res in (transient_a2(g), transient_a2_simpson(g)):
        assert res["x"] == np.inf and res["v"] == np.inf and res["a"] == np.inf
    # alpha = 1: the smoothed position is the measurement, no position error at all
    assert transient_a2(Gains(1.0, 0.5))["x"] == 0.0
    assert transient_a2_simpson(Gains(1.0, 0.5))["x"] == 0.0
    # beta = 2 alpha: no steady velocity error (alpha/beta - 1/2 = 0), a finite A_v^2
    # equal to the gamma -> 0 limit of eq 19, (2 - alpha)(4 - 2 alpha - beta)/(16 alpha beta)
    g = Gains(0.5, 1.0)
    assert transient_a2(g, 2.0)["v"] == pytest.approx(1.5 * 2.0 / 8.0 / 4.0, rel=1e-10)
    assert transient_a2_simpson(g, 2.0)["v"] == pytest.approx(1.5 * 2.0 / 8.0 / 4.0, rel=1e-12)
    assert transient_a2(g)["x"] == np.inf


def test_bank_shapes():
    theta = np.array([0.3, 0.7])  # two standard gain sets
    d2 = transient_d2(standard_abg(theta))
    assert d2["x"].shape == (2,)
    assert d2["v"][1] == pytest.approx(transient_d2(standard_abg(0.7))["v"], rel=1e-14)
    assert isinstance(transient_d2_simpson(standard_abg(0.3))["x"], float)


# --------------------------------------------------------------------------- lag
def simulated_lag(gains, dt, kind, magnitude, n):
    """Final errors (x - x_pred, x - x_smooth) after n samples of a polynomial input."""
    t = np.arange(n) * dt
    x = magnitude * (t**2 / 2 if kind == "acceleration" else t**3 / 6)
    r = track(x, gains, dt=dt)
    return x[-1] - r.x_pred[-1], x[-1] - r.x_smooth[-1]


@pytest.mark.parametrize("dt", [0.1, 1.0])
@pytest.mark.parametrize("gains", [Gains(0.5, 0.2), Gains(0.3, 0.0267)])  # stable alpha-beta
def test_acceleration_lag_alpha_beta(gains, dt):
    A = 9.81  # units/s^2, arbitrary
    pred, smooth = simulated_lag(gains, dt, "acceleration", A, 2000)
    exact = steady_state_lag(gains, dt, "acceleration", A)
    assert exact == pytest.approx(A * dt**2 / gains.beta, rel=1e-12)
    assert pred == pytest.approx(exact, rel=1e-8)
    assert smooth == pytest.approx(
        steady_state_lag(gains, dt, "acceleration", A, output="x_smooth"), rel=1e-8
    )
    assert smooth == pytest.approx((1 - gains.alpha) * exact, rel=1e-8)


@pytest.mark.parametrize("theta", [0.3, 0.6])  # standard gains, arbitrary
def test_jerk_lag_alpha_beta_gamma(theta):
    g, dt, J = standard_abg(theta), 0.5, 3.0  # interval (s) and jerk (units/s^3) arbitrary
    pred, smooth = simulated_lag(g, dt, "jerk", J, 400)  # 0.6**400 ~ 1e-89
    assert pred == pytest.approx(steady_state_lag(g, dt, "jerk", J), rel=1e-7)
    assert pred == pytest.approx(J * dt**3 / g.gamma, rel=1e-7)
    assert smooth == pytest.approx(steady_state_lag(g, dt, "jerk", J, "x_smooth"), rel=1e-7)
    # constant acceleration: no lag for alpha-beta-gamma
    pred, smooth = simulated_lag(g, dt, "acceleration", J, 400)
    assert steady_state_lag(g, dt, "acceleration", J) == 0.0
    assert abs(pred) < 1e-7 and abs(smooth) < 1e-7


def test_jerk_lag_alpha_beta_grows():
    g = Gains(0.5, 0.2)  # arbitrary stable alpha-beta
    assert steady_state_lag(g, 1.0, "jerk", 2.0) == np.inf
    assert steady_state_lag(g, 1.0, "jerk", -2.0) == -np.inf
    e1, _ = simulated_lag(g, 1.0, "jerk", 2.0, 500)
    e2, _ = simulated_lag(g, 1.0, "jerk", 2.0, 1000)
    assert e2 > 1.9 * e1 > 0  # grows linearly with time


# --------------------------------------------------------------------------- bad input
def test_bad_input_messages():
    with pytest.raises(ValueError, match=r"transient error sums are unbounded: gains"):
        transient_d2(Gains(1.9, 0.5))  # 2 alpha + beta > 4, seed 000 eq 44
    with pytest.raises(ValueError, match=r"transient error sums are unbounded"):
        transient_a2_simpson(Gains(0.5, 0.2, 0.2))  # violates seed 000 eq 47
    with pytest.raises(ValueError, match=r"n_max=100; increase n_max"):
        transient_d2(standard_abg(0.9), n_max=100)
    # stable gains whose poles the expanded eq 40 cannot tell from the unit circle (a
    # gamma or beta far below alpha): a clear error, not an OverflowError or numpy's
    # "negative dimensions are not allowed"
    for call, gains, exact in (
        (transient_d2, Gains(0.5, 1e-16), "transient_d2_simpson"),
        (transient_d2, Gains(0.3, 0.02, 1e-18), "transient_d2_simpson"),
        (transient_a2, Gains(0.3, 0.02, 1e-18), "transient_a2_simpson"),
    ):
        with pytest.raises(ValueError, match=rf"within round-off of the unit circle.*{exact}"):
            call(gains)
    with pytest.raises(ValueError, match=r"kind must be one of 'acceleration', 'jerk', got 'snap'"):
        steady_state_lag(Gains(0.5, 0.2), kind="snap")
    with pytest.raises(ValueError, match=r"output must be one of 'x_pred', 'x_smooth', got 'v'"):
        steady_state_lag(Gains(0.5, 0.2), output="v")
    with pytest.raises(ValueError, match=r"steady-state lag is undefined: gains"):
        steady_state_lag(Gains(2.5, 0.2))
