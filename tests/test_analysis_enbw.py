"""Equivalent noise bandwidth: the routes against each other (seed 002, eqs 8-14).

Routes: Lyapunov (enbw), quadrature of |H|^2 over frequency and the summed impulse
response from abglib.track (enbw_numeric). Finding pinned here: the first expression of
eq 8 integrated over the whole band is the two-sided bandwidth, twice enbw. Huang's
printed closed forms (eqs 8-14): tests/replications/test_huang_printed.py.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.integrate
from hypothesis import given, settings
from hypothesis import strategies as st

from abglib import Gains
from abglib.analysis._enbw import enbw, enbw_numeric
from abglib.analysis._variance import vrf

from .strategies import stable_gain_strategies, standard_ab, standard_abg

stable_ab, stable_abg = stable_gain_strategies(0.95, 1e-6)

dts = st.sampled_from([1 / 300, 0.1, 1.0])  # 1/300 s: seed 002's F_r = 300 Hz


# --------------------------------------------------------------------------- exact routes
@settings(max_examples=30, deadline=None)
@given(st.one_of(stable_ab, stable_abg), dts)
def test_enbw_routes_agree(gains, dt):
    exact = enbw(gains, dt)
    assert exact == pytest.approx(vrf(gains, dt)["x_pred"] / (2 * dt), rel=1e-14)
    assert enbw_numeric(gains, dt, method="integral") == pytest.approx(exact, rel=1e-8)
    assert enbw_numeric(gains, dt, method="impulse") == pytest.approx(exact, rel=1e-9)


@pytest.mark.parametrize("theta", [0.05, 0.5, 0.9, 0.98])  # standard gains, wide and narrow
def test_enbw_routes_agree_standard_gains(theta):
    for g in (standard_abg(theta), standard_ab(theta)):
        exact = enbw(g, 0.01)  # 100 Hz sampling, arbitrary
        assert enbw_numeric(g, 0.01) == pytest.approx(exact, rel=1e-8)
        assert enbw_numeric(g, 0.01, method="impulse") == pytest.approx(exact, rel=1e-9)


def test_eq8_first_form_is_two_sided():
    # seed 002, eq 8: B_n = (1/2pi) int |H(omega)|^2 d omega over the whole band
    # (-pi/T, pi/T); H from seed 000, eqs 39-40, written out here independently
    g, dt = standard_abg(0.7), 1 / 300  # arbitrary standard gains, F_r = 300 Hz
    a, b, c = g.alpha, g.beta, g.gamma

    def h2(w):
        z = np.exp(1j * w * dt)
        num = (a + b + c / 2) * (z - 1) ** 2 + (b + 1.5 * c) * (z - 1) + c
        den = (z - 1) ** 3 + a * (z - 1) ** 2 + (b + c / 2) * z * (z - 1) + c * z
        return abs(num / den) ** 2

    lim = np.pi / dt
    eq8, _ = scipy.integrate.quad(h2, -lim, lim, limit=400, points=[0.0], epsrel=1e-12)
    eq8 /= 2 * np.pi
    assert eq8 == pytest.approx(2 * enbw(g, dt), rel=1e-8)


# --------------------------------------------------------------------------- shapes, errors
def test_bank_shapes():
    theta = np.array([0.3, 0.6, 0.9])
    g = standard_abg(theta)
    assert enbw(g, 0.1).shape == (3,)
    assert enbw_numeric(g, 0.1).shape == (3,)
    assert isinstance(enbw(Gains(0.5, 0.2), 0.1), float)
    assert enbw(Gains(0.5, 0.2), dt=0.1) == pytest.approx(1.0 / 1.4 / 0.2, rel=1e-14)


def test_bad_input_messages():
    with pytest.raises(ValueError, match=r"noise bandwidth is unbounded: gains \(alpha=1\.9"):
        enbw(Gains(1.9, 0.5))  # 2 alpha + beta > 4, seed 000 eq 44
    with pytest.raises(ValueError, match=r"noise bandwidth is unbounded: gains"):
        enbw_numeric(Gains(1.9, 0.5))
    with pytest.raises(ValueError, match=r"method must be one of 'integral', 'impulse', got 'fft'"):
        enbw_numeric(Gains(0.5, 0.2), method="fft")


def test_impulse_route_refuses_a_response_longer_than_n_max():
    """Poles 1e-9 inside the unit circle: some 9e10 samples (686 GiB) were allocated, a
    MemoryError; the route now says what it would need, and n_max lets a user allow it."""
    slow = Gains(0.5, 1e-9, 1e-20)
    with pytest.raises(ValueError, match=r"needs about \d+ samples .* n_max=2000000"):
        enbw_numeric(slow, method="impulse")
    with pytest.raises(ValueError, match=r"n_max must be >= 16, got 3"):
        enbw_numeric(Gains(0.5, 0.2), method="impulse", n_max=3)
    assert enbw_numeric(Gains(0.5, 0.2), method="impulse", n_max=400) == pytest.approx(
        enbw(Gains(0.5, 0.2)), rel=1e-12
    )
