"""Seed 002's printed forms (abglib.replications.huang.printed) against abglib's exact analysis.

Moved here from tests/test_analysis_*.py with the forms themselves: eq 14 and the
reconstructed eqs 8-13 against the Lyapunov ENBW; eqs 5 and 7 against the eigenvalues of
the closed-loop matrix; eqs 3 and 6 against the canonical X_p/X; the printed lag formulas
against the final-value theorem and simulation.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from abglib import Gains
from abglib.analysis import enbw, is_stable, steady_state_lag, transfer_function
from abglib.conventions import from_huang, to_huang
from abglib.replications.huang.printed import (
    enbw_huang_eq8_13,
    enbw_huang_eq14,
    stable_huang_eq5,
    stable_huang_eq7,
    steady_state_lag_huang,
    transfer_function_huang,
    transfer_function_huang_eq3,
)

from ..strategies import stable_gain_strategies, standard_ab, standard_abg
from ..test_analysis_stability import MARGIN, box_a, box_b, box_g, truth
from ..test_analysis_transfer import stable_gains
from ..test_analysis_transient import simulated_lag

stable_ab, stable_abg = stable_gain_strategies(0.95, 1e-6)
dts = st.sampled_from([1 / 300, 0.1, 1.0])  # 1/300 s: seed 002's F_r = 300 Hz


# --------------------------------------------------------------------------- ENBW, eqs 8-14
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


def test_bank_shapes():
    a, b, gh = to_huang(standard_abg(np.array([0.3, 0.6, 0.9])))
    assert enbw_huang_eq8_13(a, b, gh, 0.1).shape == (3,)


def test_bad_input_messages():
    with pytest.raises(ValueError, match=r"noise bandwidth is unbounded: gains \(alpha=0\.61"):
        # seed 002, Table 1 type I, 10 Hz: gamma_H = 0.18 is unstable (canonical 0.36)
        enbw_huang_eq8_13(0.61, 0.28, 0.18, 1 / 300)
    with pytest.raises(ValueError, match=r"method must be one of 'eq13', 'eq11_12', got 'x'"):
        enbw_huang_eq8_13(0.5, 0.2, 0.01, 1.0, method="x")
    with pytest.raises(ValueError, match=r"eqs 11-12 need distinct roots"):
        enbw_huang_eq8_13(1.0, 1.0, 0.0, 1.0, method="eq11_12")  # deadbeat: double root
    with pytest.raises(ValueError, match=r"dt must be > 0, got 0\.0"):
        enbw_huang_eq14(0.5, 0.2, 0.0)
    with pytest.raises(ValueError, match="beta_h must be finite, got nan"):
        stable_huang_eq5(0.3, np.nan, 0.01)
    with pytest.raises(ValueError, match="beta_h must be finite, got inf"):
        transfer_function_huang(0.3, np.inf)
    with pytest.raises(ValueError, match=r"gain must be > 0, got 0\.0"):
        steady_state_lag_huang(0.0, 1.0, 1.0)


# --------------------------------------------------------------------------- eqs 5, 7
def test_huang_eq5_counterexample_unstable():
    # Huang's convention (seed 002): gamma_H = gamma / 2. (0.1, 0.01, 0.1) satisfies every line
    # of eq 5 (4 - 0.2 - 0.01 > 0, 0.2 - 0.1 > 0, beta, gamma > 0) but violates the missing
    # Jury condition alpha beta + alpha gamma_H - 2 gamma_H = 0.001 + 0.01 - 0.2 < 0
    a, b, gh = 0.1, 0.01, 0.1
    assert stable_huang_eq5(a, b, gh)
    canonical = Gains(a, b, 2 * gh)
    assert not is_stable(canonical)
    assert truth(canonical) == pytest.approx(1.2981, abs=1e-4)  # complex pair 1.128 +- 0.643j


@settings(max_examples=300, deadline=None)
@given(box_a, box_b, box_g)
def test_huang_eq5_is_necessary_but_not_sufficient(a, b, gh):
    # stable => eq 5 (its 2 alpha > gamma_H follows from Jury: gamma_H (2 - alpha) < alpha beta
    # and beta < 4 - 2 alpha); eq 5 and unstable => the missing condition fails
    assume(gh != 0)  # eq 5 is Huang's alpha-beta-gamma criterion; eq 7 covers gamma = 0
    gains = Gains(a, b, 2 * gh)
    r = truth(gains)
    assume(abs(r - 1) > MARGIN)
    if r < 1:
        assert stable_huang_eq5(a, b, gh)
    elif stable_huang_eq5(a, b, gh):
        assert a * b + a * gh - 2 * gh <= 0


@pytest.mark.parametrize(
    ("a", "b"),
    [
        (3.0, 0.1),  # alpha > 2: eq 7 holds (3 > -0.1, 0.1 > 0), pole at z = -2.05
        (-0.05, 0.5),  # alpha < 0: eq 7 holds (-0.05 > -0.5), pole |1 - alpha| product > 1
        (1.9, 0.5),  # 2 alpha + beta = 4.3 > 4: eq 7 holds, real pole < -1
    ],
)
def test_huang_eq7_counterexamples(a, b):
    assert stable_huang_eq7(a, b)
    assert not is_stable(Gains(a, b)) and truth(Gains(a, b)) > 1


@settings(max_examples=100, deadline=None)
@given(box_a, box_b)
def test_huang_eq7_is_necessary(a, b):
    if truth(Gains(a, b)) < 1 - MARGIN:
        assert stable_huang_eq7(a, b)


# --------------------------------------------------------------------------- eqs 3, 6
@settings(max_examples=30, deadline=None)
@given(stable_gains())
def test_huang_eq3_eq6_is_canonical_predicted_position(gains):
    # seed 002: gamma_H = gamma / 2 (CONTRACTS.md section 1); their H(z) is X_p / X (eq 39)
    hn, hd = transfer_function_huang(gains.alpha, gains.beta, gains.gamma / 2)
    num, den = transfer_function(gains, "x_pred")
    np.testing.assert_allclose(hn, num, atol=1e-14)
    np.testing.assert_allclose(hd, den, atol=1e-14)


def test_huang_eq6_as_printed():
    # eq 6 with alpha = 0.5, beta = 0.2 (arbitrary): ((a+b) z - a) / (z^2 + (a+b-2) z + 1-a)
    num, den = transfer_function_huang(0.5, 0.2)
    np.testing.assert_allclose(num, [0.0, 0.7, -0.5], atol=1e-15)
    np.testing.assert_allclose(den, [1.0, -1.3, 0.5], atol=1e-15)


@settings(max_examples=30, deadline=None)
@given(stable_gains())
def test_eq3_at_gamma_zero_has_the_factor_z_minus_1(gains):
    a, b = gains.alpha, gains.beta
    num, den = transfer_function_huang_eq3(a, b, 0.0)
    # multiply eq 6 by (z - 1): numerator and denominator of eq 3 at gamma = 0
    n6, d6 = transfer_function_huang(a, b, 0.0)
    np.testing.assert_allclose(num, np.convolve(n6, [1.0, -1.0]), atol=1e-14)
    np.testing.assert_allclose(den, np.convolve(d6, [1.0, -1.0]), atol=1e-14)


# --------------------------------------------------------------------------- lags
def test_huang_acceleration_lag_is_the_predicted_position():
    # seed 002, "Simulation analysis": F_r = 300 Hz, A = 1000 m/s^2, Table 2 type II
    # alpha-beta at 10 Hz: alpha = 0.098, beta = 0.0025; printed lag 4.44 m
    A, dt, alpha, beta = 1000.0, 1 / 300, 0.098, 0.0025
    huang = steady_state_lag_huang(beta, A, dt)
    assert huang == pytest.approx(4.44, abs=0.005)
    assert huang == pytest.approx(steady_state_lag(Gains(alpha, beta), dt, "acceleration", A))
    assert huang != pytest.approx(
        steady_state_lag(Gains(alpha, beta), dt, "acceleration", A, "x_smooth")
    )


def test_huang_jerk_lag_is_twice_the_truth_in_his_convention():
    # seed 002, Table 2 type II alpha-beta-gamma at 2 Hz: alpha = 0.71, beta = 0.29,
    # gamma_H = 0.020 (his convention); B = 40 m/s^3, F_r = 300 Hz ("Simulation analysis")
    B, dt, a, b, gh = 40.0, 1 / 300, 0.71, 0.29, 0.020
    g = from_huang(a, b, gh)
    exact = steady_state_lag(g, dt, "jerk", B)
    pred, _ = simulated_lag(g, dt, "jerk", B, 3000)
    assert pred == pytest.approx(exact, rel=1e-7)
    assert steady_state_lag_huang(gh, B, dt, kind="jerk") == pytest.approx(2 * exact, rel=1e-12)
    # read with the canonical gamma (= 2 gamma_H), the printed formula is exact
    assert steady_state_lag_huang(g.gamma, B, dt, kind="jerk") == pytest.approx(exact, rel=1e-12)


@pytest.mark.parametrize(
    "gains", [Gains(0.3, 0.05), Gains(0.02, 0.0002), Gains(0.5, 0.2, 0.02), Gains(0.1, 0.005, 1e-5)]
)
def test_eq8_integrand_is_frequency_response_bit_for_bit(gains):
    """eq 8's quadrature integrand (gains' work hoisted) gives the very bits of
    |frequency_response|^2, so the quadrature and its digits are unchanged."""
    from abglib.analysis import frequency_response
    from abglib.replications.huang.printed import _x_pred_power

    f = _x_pred_power(gains)
    rng = np.random.default_rng(5)
    xs = np.concatenate(
        [rng.uniform(-np.pi, np.pi, 500), np.geomspace(1e-9, np.pi, 50), [0.0, np.pi, -np.pi]]
    )
    for x in map(float, xs):
        want = float(np.abs(frequency_response(gains, "x_pred", np.asarray(x))) ** 2)
        assert f(x) == want, x
