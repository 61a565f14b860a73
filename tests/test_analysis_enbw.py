"""Equivalent noise bandwidth: the routes against each other (seed 002, eqs 8-14).

Routes: Lyapunov (enbw), quadrature of |H|^2 over frequency and the summed impulse
response from abglib.track (enbw_numeric), Huang's eq 14 (alpha-beta) and the
reconstructed eqs 8-13 (alpha-beta-gamma; table integral and partial fractions).
Findings pinned here: eqs 9-14 are the one-sided bandwidth sum h^2 / (2T); the first
expression of eq 8 integrated over the whole band is the two-sided one, twice as large.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.integrate
from hypothesis import given, settings
from hypothesis import strategies as st

from abglib import Gains
from abglib.analysis._enbw import enbw, enbw_huang_eq8_13, enbw_huang_eq14, enbw_numeric
from abglib.analysis._variance import vrf
from abglib.conventions import from_huang, to_huang

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


# --------------------------------------------------------------------------- Huang
@settings(max_examples=60, deadline=None)
@given(stable_ab, dts)
def test_huang_eq14_is_the_one_sided_enbw(gains, dt):
    printed = enbw_huang_eq14(gains.alpha, gains.beta, dt)
    assert printed == pytest.approx(enbw(gains, dt), rel=1e-9)


@settings(max_examples=60, deadline=None)
@given(st.one_of(stable_ab, stable_abg), dts)
def test_huang_eq8_13_reconstruction(gains, dt):
    a, b, gh = to_huang(gains)
    exact = enbw(gains, dt)
    assert enbw_huang_eq8_13(a, b, gh, dt) == pytest.approx(exact, rel=1e-7)
    # partial fractions (eqs 11-12) lose digits near repeated roots (cond ~ eps^(1/3))
    # and refuse exactly repeated ones (e.g. two equal real poles)
    try:
        pf = enbw_huang_eq8_13(a, b, gh, dt, method="eq11_12")
    except ValueError as exc:
        assert "need distinct roots" in str(exc)
    else:
        assert pf == pytest.approx(exact, rel=1e-4)


@pytest.mark.parametrize("theta", [0.2, 0.5, 0.9])  # standard gains (triple pole at theta)
def test_huang_eq8_13_standard_gains(theta):
    g, dt = standard_abg(theta), 1 / 300  # F_r = 300 Hz, seed 002
    a, b, gh = to_huang(g)
    exact = enbw(g, dt)
    assert enbw_huang_eq8_13(a, b, gh, dt) == pytest.approx(exact, rel=1e-10)
    assert enbw_huang_eq8_13(a, b, gh, dt, method="eq11_12") == pytest.approx(exact, rel=1e-5)
    # at gamma_H = 0 the reconstruction reduces to eq 14
    ab = standard_ab(theta)
    assert enbw_huang_eq8_13(ab.alpha, ab.beta, 0.0, dt) == pytest.approx(
        enbw_huang_eq14(ab.alpha, ab.beta, dt), rel=1e-10
    )


def test_huang_gamma_convention():
    # the same numbers read as canonical gains give a different bandwidth
    a, b, gh, dt = 0.5, 0.2, 0.02, 0.1  # arbitrary stable gains (Huang convention)
    assert enbw_huang_eq8_13(a, b, gh, dt) == pytest.approx(enbw(from_huang(a, b, gh), dt))
    assert enbw_huang_eq8_13(a, b, gh, dt) != pytest.approx(enbw(Gains(a, b, gh), dt))


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


# seed 002, Tables 1-2, alpha-beta columns: (table ENBW in Hz, alpha, beta), F_r = 300 Hz
HUANG_AB_ROWS = [
    (2, 0.02, 0.0002),  # Table 1, type I
    (10, 0.09, 0.0042),
    (20, 0.16, 0.0139),
    (2, 0.02, 0.0001),  # Table 2, type II
    (10, 0.098, 0.0025),
    (20, 0.19, 0.01),
]


def test_huang_tables_use_the_one_sided_bandwidth():
    # the tabulated gains are rounded, so only the side is tested: one-sided values are
    # within 15 % of the table headings, two-sided ones about twice them
    for bn, a, b in HUANG_AB_ROWS:
        one = enbw_huang_eq14(a, b, 1 / 300)
        assert abs(one / bn - 1) < 0.15
        assert abs(2 * one / bn - 1) > 0.8


# --------------------------------------------------------------------------- shapes, errors
def test_bank_shapes():
    theta = np.array([0.3, 0.6, 0.9])
    g = standard_abg(theta)
    assert enbw(g, 0.1).shape == (3,)
    assert enbw_numeric(g, 0.1).shape == (3,)
    a, b, gh = to_huang(g)
    assert enbw_huang_eq8_13(a, b, gh, 0.1).shape == (3,)
    assert isinstance(enbw(Gains(0.5, 0.2), 0.1), float)
    assert enbw(Gains(0.5, 0.2), dt=0.1) == pytest.approx(1.0 / 1.4 / 0.2, rel=1e-14)


def test_bad_input_messages():
    with pytest.raises(ValueError, match=r"noise bandwidth is unbounded: gains \(alpha=1\.9"):
        enbw(Gains(1.9, 0.5))  # 2 alpha + beta > 4, seed 000 eq 44
    with pytest.raises(ValueError, match=r"noise bandwidth is unbounded: gains"):
        enbw_numeric(Gains(1.9, 0.5))
    with pytest.raises(ValueError, match=r"noise bandwidth is unbounded: gains \(alpha=0\.61"):
        # seed 002, Table 1 type I, 10 Hz: gamma_H = 0.18 is unstable (canonical 0.36)
        enbw_huang_eq8_13(0.61, 0.28, 0.18, 1 / 300)
    with pytest.raises(ValueError, match=r"method must be one of 'integral', 'impulse', got 'fft'"):
        enbw_numeric(Gains(0.5, 0.2), method="fft")
    with pytest.raises(ValueError, match=r"method must be one of 'eq13', 'eq11_12', got 'x'"):
        enbw_huang_eq8_13(0.5, 0.2, 0.01, 1.0, method="x")
    with pytest.raises(ValueError, match=r"eqs 11-12 need distinct roots"):
        enbw_huang_eq8_13(1.0, 1.0, 0.0, 1.0, method="eq11_12")  # deadbeat: double root
    with pytest.raises(ValueError, match=r"dt must be > 0, got 0\.0"):
        enbw_huang_eq14(0.5, 0.2, 0.0)
