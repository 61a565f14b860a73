"""Test-input generators (seed 003) and seeded noise."""

from __future__ import annotations

import numpy as np
import pytest

from abglib import Gains, track
from abglib.simulate import (
    ar1_noise,
    bendix_impulse,
    bendix_ramp,
    polynomial_kinematics,
    polynomial_track,
    sample_times,
    white_noise,
)


def test_bendix_impulse_has_unit_area():
    z = bendix_impulse(40, dt=4.0)
    assert z[0] == 0.25 and np.all(z[1:] == 0)  # amplitude 1/T, width T (seed 003)
    assert z.sum() * 4.0 == 1.0


def test_bendix_ramp_shape():
    z = bendix_ramp(40, dt=3.0)
    # zero at the first sampling, raised by T each sampling for 10 periods, then zero
    np.testing.assert_array_equal(z[:11], 3.0 * np.arange(11))
    assert np.all(z[11:] == 0.0) and z.size == 40


def test_impulse_response_is_the_transfer_function_impulse_response():
    # the impulse response of x_smooth to z[0] = 1/T is (1/T) * h_k; at k = 0 it is alpha/T
    T = 2.0
    out = track(bendix_impulse(10, T), Gains(0.25, 0.066), dt=T)  # Bendix 1 s row values
    assert out.x_smooth[0] == pytest.approx(0.25 / T)
    assert out.v_smooth[0] == pytest.approx(0.066 / T / T)


def test_noise_is_seeded_and_has_the_stated_statistics():
    a = white_noise((4, 1000), 2.0, seed=1)
    np.testing.assert_array_equal(a, white_noise((4, 1000), 2.0, seed=1))
    assert abs(a.std() - 2.0) < 0.1  # 4000 samples: std error of std ~ 2/sqrt(8000) = 0.02
    w = ar1_noise((200, 500), 1.5, 0.8, seed=2)
    assert abs(w.std() - 1.5) < 0.05
    lag1 = np.mean(w[:, 1:] * w[:, :-1]) / w.var()
    assert abs(lag1 - 0.8) < 0.02


def test_polynomial_track():
    t = sample_times(5, 0.5)
    np.testing.assert_allclose(polynomial_track(t, 1.0, 2.0, 4.0, 6.0), 1 + 2 * t + 2 * t**2 + t**3)


def test_polynomial_kinematics_derivatives():
    """Velocity and acceleration against the derivatives of the position written out by
    hand (x = 1 + 2t + 2t^2 + t^3: v = 2 + 4t + 3t^2, a = 4 + 6t), and against central
    differences of polynomial_track (exact to round-off for a cubic: the t^3 term's
    truncation error is h^2 * jerk / 6 = 1e-6 for h = 1e-3, jerk = 6)."""
    t = sample_times(7, 0.25)
    pos, vel, acc = polynomial_kinematics(t, 1.0, 2.0, 4.0, 6.0)
    np.testing.assert_allclose(pos, polynomial_track(t, 1.0, 2.0, 4.0, 6.0), rtol=0, atol=0)
    np.testing.assert_allclose(vel, 2 + 4 * t + 3 * t**2, rtol=1e-15)
    np.testing.assert_allclose(acc, 4 + 6 * t, rtol=1e-15)
    h = 1e-3
    central = (
        polynomial_track(t + h, 1.0, 2.0, 4.0, 6.0) - polynomial_track(t - h, 1.0, 2.0, 4.0, 6.0)
    ) / (2 * h)
    np.testing.assert_allclose(central, vel, atol=2e-6)
    # a constant velocity: the acceleration is an array of zeros shaped like t
    _, vel0, acc0 = polynomial_kinematics(t, 0.0, 3.0)
    assert acc0.shape == t.shape and not acc0.any()
    np.testing.assert_array_equal(vel0, np.full_like(t, 3.0))


@pytest.mark.parametrize(
    ("call", "match"),
    [
        (
            lambda: bendix_ramp(40, 1.0, rise_samples=40),
            r"rise_samples must satisfy 0 <= rise_samples < n=40",
        ),
        (lambda: bendix_impulse(0), r"n must be a positive integer, got 0"),
        (lambda: bendix_impulse(5, dt=-1), r"dt must be > 0"),
        (lambda: ar1_noise(10, 1.0, 1.0, seed=0), r"rho must satisfy -1 < rho < 1, got 1.0"),
        (lambda: white_noise(10, 1.0, seed=-3), r"seed must be a non-negative integer, got -3"),
    ],
)
def test_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()
