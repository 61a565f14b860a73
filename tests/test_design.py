"""Tests of abglib.design: every rule against an independent route, and the printed tables.

Sources: seed 000 (Steelman 1978), 001 (Al-Wagih & Abdulla), 002 (Huang et al.),
003 (FAA Bendix letter report); Kalata 1984 and Gray & Murray 1993 for the tracking index.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.linalg import expm

from abglib import AbglibValueError, Gains, track
from abglib.conventions import to_huang
from abglib.design import (
    BENDIX_CAPTIONS,
    BENDIX_MEMO,
    bendix,
    benedict_bordner,
    growing_memory,
    huang_for_enbw,
    huang_type1,
    huang_type2,
    kalata_ab,
    kalata_abg,
    m1,
    qd,
    qd_m_from_alpha,
    simpson,
    simpson_beta,
    simpson_gamma,
    standard_ab,
    standard_abg,
    standard_from_alpha,
    standard_theta_from_alpha,
    steady_state_kalman,
)

FAST = settings(max_examples=60, deadline=None)
unit_open = st.floats(0.0, 1.0, exclude_min=True, exclude_max=True)


def half_unit(printed: str) -> float:
    """Half a unit in the last printed digit of a number printed as ``printed``."""
    decimals = len(printed.split(".")[1]) if "." in printed else 0
    return 0.5 * 10.0**-decimals


def printed_match(value: float, printed: str) -> bool:
    # 1e-12 slack so that an exact tie (e.g. 0.0975 printed as 0.098) counts as a match
    return abs(value - float(printed)) <= half_unit(printed) + 1e-12


def char_poly(g: Gains) -> np.ndarray:
    """Seed 000, eq 40 expanded by hand (descending powers of z), canonical gains."""
    a, b, c = g.alpha, g.beta, g.gamma
    return np.array([1.0, a + b + c / 2 - 3.0, 3.0 - 2 * a - b + c / 2, a - 1.0])


# --------------------------------------------------------------------------- ENBW routes
def enbw_twin(gains: Gains, dt: float, n: int = 40000) -> float:
    """Sum of squared x_pred impulse response / (2 dt) (seed 002, eq 8), by simulation."""
    z = np.zeros(n)
    z[0] = 1.0  # unit impulse
    h = track(z, gains, dt=1.0).x_pred  # x_pred impulse response does not depend on dt
    return float(np.sum(h * h) / (2.0 * dt))


@pytest.fixture
def enbw_func():
    """abglib.analysis.enbw as a float (what design's rules invert)."""
    from abglib.analysis import enbw

    return lambda g, dt: float(enbw(g, dt))


def test_analysis_enbw_agrees_with_twin():
    from abglib.analysis import enbw as real

    for g in (huang_type1(0.3), huang_type2(0.7, 3), Gains(0.5, 0.2, 0.02)):
        assert float(real(g, 0.01)) == pytest.approx(enbw_twin(g, 0.01), rel=1e-9)


# --------------------------------------------------------------------------- standard
@FAST
@given(st.floats(0.0, 0.999))
def test_standard_ab_double_pole_at_theta(theta):
    g = standard_ab(theta)
    # seed 000, eq 41: z^2 + (alpha + beta - 2) z + (1 - alpha) == (z - theta)^2
    np.testing.assert_allclose(
        [1.0, g.alpha + g.beta - 2, 1 - g.alpha], np.poly([theta] * 2), atol=1e-14
    )
    # a double root is found by numpy.roots only to ~sqrt(eps)
    np.testing.assert_allclose(np.roots([1.0, g.alpha + g.beta - 2, 1 - g.alpha]), theta, atol=1e-6)


@FAST
@given(st.floats(0.0, 0.999))
def test_standard_abg_triple_pole_at_theta(theta):
    g = standard_abg(theta)
    np.testing.assert_allclose(char_poly(g), np.poly([theta] * 3), atol=1e-14)


@FAST
@given(st.floats(1e-9, 1.0), st.sampled_from([2, 3]))  # alpha < eps: 1 - alpha == 1
def test_standard_inverse_round_trip(alpha, order):
    theta = standard_theta_from_alpha(alpha, order)
    assert 0.0 <= theta < 1.0
    g = standard_from_alpha(alpha, order)
    assert g.alpha == pytest.approx(alpha, rel=1e-12, abs=1e-15)
    assert g.order == order or (alpha == 1.0 and order == 3)  # alpha = 1, order 3: gamma 1
    rule = standard_ab if order == 2 else standard_abg
    assert standard_theta_from_alpha(rule(theta).alpha, order) == pytest.approx(theta, abs=1e-12)


def test_standard_vectorised():
    theta = np.array([0.0, 0.5, 0.9])
    g = standard_abg(theta)
    assert g.shape == (3,)
    np.testing.assert_allclose(g.alpha, 1 - theta**3)
    assert isinstance(standard_ab(0.5).alpha, float)  # scalar in, scalar out


# --------------------------------------------------------------------------- QD
@FAST
@given(st.floats(1.2, 1e4))
def test_qd_round_trip(m):
    assert qd_m_from_alpha(qd(m).alpha) == pytest.approx(m, rel=1e-9)


@FAST
@given(st.floats(1.0001, 1e4))
def test_qd_eq29_30_structure(m):
    g = qd(m)
    # eqs 29-30 give gamma = beta^2 / (2 alpha) (Huang type I's second equation)
    assert g.gamma == pytest.approx(g.beta**2 / (2 * g.alpha), rel=1e-12)
    # eq 28 at the cubic's root
    a = g.alpha
    assert 10 * a * m**3 + (33 * a - 60) * m**2 + 23 * a * m - 6 * a == pytest.approx(
        0.0, abs=1e-9 * 60 * m**2
    )


def test_qd_alpha_is_one_at_m_1_and_1_2():
    # 10 m^3 - 27 m^2 + 23 m - 6 = (m - 1)(10 m^2 - 17 m + 6): roots 1, 1.2 (and 0.5)
    assert qd(1.2).alpha == pytest.approx(1.0, rel=1e-14)
    assert qd(1.1).alpha > 1.0
    assert qd_m_from_alpha(1.0) == pytest.approx(1.2, rel=1e-12)


def test_steelman_m_for_alpha_03_and_alpha_for_m_21():
    # seed 000, after Table 1: "The m required to produce alpha = .3 is 16.6"
    m = qd_m_from_alpha(0.3)
    assert m == pytest.approx(16.56332603811807, rel=1e-12)  # this implementation
    assert printed_match(m, "16.6")
    # "Table 2 shows the more typical m = 21 values" with alpha printed .246
    assert qd(21).alpha == pytest.approx(0.24581939799331104, rel=1e-12)
    assert printed_match(qd(21).alpha, "0.246")


# Steelman's Tables 1 and 2 (seed 000): (alpha, column, gain, printed value)
STEELMAN_TABLES = [
    ("0.3", "standard_abg", "beta", "0.0356"),
    ("0.3", "standard_abg", "gamma", "0.0014"),
    ("0.3", "standard_ab", "beta", "0.0267"),
    ("0.3", "qd", "beta", "0.0362"),
    ("0.3", "qd", "gamma", "0.00219"),
    ("0.246", "standard_abg", "beta", "0.0231"),
    ("0.246", "standard_abg", "gamma", "0.00072"),
    ("0.246", "standard_ab", "beta", "0.0173"),
    ("0.246", "qd", "beta", "0.0234"),
    ("0.246", "qd", "gamma", "0.0011"),
]


def _steelman_rule(alpha: float, column: str) -> Gains:
    if column == "standard_abg":
        return standard_from_alpha(alpha, order=3)
    if column == "standard_ab":
        return standard_from_alpha(alpha, order=2)
    return qd(qd_m_from_alpha(alpha))


@pytest.mark.parametrize(("alpha", "column", "gain", "printed"), STEELMAN_TABLES)
def test_steelman_tables_1_2(alpha, column, gain, printed):
    g = _steelman_rule(float(alpha), column)
    assert printed_match(getattr(g, gain), printed), (getattr(g, gain), printed)


def test_steelman_table_1_qd_needs_exact_m():
    # with m rounded to the printed 16.6 the QD column does not hold: beta = 2 alpha / m
    assert not printed_match(2 * 0.3 / 16.6, "0.0362")  # 0.036145 vs 0.0362
    assert not printed_match(2 * 0.3 / 16.6**2, "0.00219")  # 0.0021774 vs 0.00219
    assert not printed_match(qd(16.6).beta, "0.0362")  # 0.036079 (alpha(16.6) = 0.29946)
    # Table 2 holds with either m = 21 (alpha 0.24582) or the exact m = 20.982 for 0.246
    g21 = qd(21)
    assert printed_match(g21.beta, "0.0234") and printed_match(g21.gamma, "0.0011")


# --------------------------------------------------------------------------- BB, Simpson
@FAST
@given(st.floats(0.0, 1.0, exclude_min=True))
def test_benedict_bordner_is_simpson_with_zero_gamma(alpha):
    g = benedict_bordner(alpha)
    assert m1 is benedict_bordner
    assert g.beta == pytest.approx(alpha**2 / (2 - alpha), rel=1e-15)  # seed 001, eq 23b
    assert simpson_beta(alpha, 0.0, allow_unstable=True).isclose(g, rtol=1e-14)
    assert 2 * g.beta - alpha * (alpha + g.beta) == pytest.approx(0.0, abs=1e-15)  # eq 21


@FAST
@given(st.floats(0.01, 1.9), st.floats(0.0, 5.0))
def test_simpson_eq21_both_ways(alpha, gamma):
    g = simpson(alpha, gamma=gamma, allow_unstable=True)  # the algebra, stable or not
    lhs = 2 * g.beta - alpha * (alpha + g.beta + g.gamma / 2)  # seed 000, eq 21
    assert lhs == pytest.approx(0.0, abs=1e-12 * (1 + g.beta))
    back = simpson(alpha, beta=g.beta, allow_unstable=True)
    assert back.gamma == pytest.approx(gamma, rel=1e-9, abs=1e-9)


def test_simpson_gamma_values():
    g = simpson_gamma(0.5, 0.2, allow_unstable=True)  # 4*0.2/0.5 - 1 - 0.4 = 0.2 (by hand)
    assert g.gamma == pytest.approx(0.2, rel=1e-14)
    g = simpson_gamma(0.5, 0.175)  # 4*0.175/0.5 - 1 - 0.35 = 0.05 (by hand), stable
    assert g.gamma == pytest.approx(0.05, rel=1e-13)
    assert simpson_gamma(0.5, 0.25 / 1.5).gamma == pytest.approx(0.0, abs=1e-15)  # BB beta


# --------------------------------------------------------------------------- growing memory
def test_growing_memory_values():
    g = growing_memory(4)
    # seed 001, eqs 24a-b at n = 1..4 by hand: alpha 1, 1, 10/12, 14/20; beta 3, 1, 1/2, 3/10
    np.testing.assert_allclose(g.alpha, [1.0, 1.0, 10 / 12, 14 / 20], rtol=1e-15)
    np.testing.assert_allclose(g.beta, [3.0, 1.0, 0.5, 0.3], rtol=1e-15)
    g5 = growing_memory(2, start=5)  # n = 5, 6
    np.testing.assert_allclose(g5.alpha, [18 / 30, 22 / 42])
    np.testing.assert_allclose(g5.beta, [6 / 30, 6 / 42])


def test_growing_memory_is_least_squares_line():
    rng = np.random.default_rng(3)  # seeded: arbitrary noisy ramp
    n, dt = 30, 0.5
    z = 2.0 + 1.5 * dt * np.arange(n) + rng.normal(0, 0.3, n)
    out = track(z, growing_memory(n), dt=dt, init="zero")
    for k in range(1, n):
        t = dt * np.arange(k + 1)
        slope, icpt = np.polyfit(t, z[: k + 1], 1)  # independent route: least squares
        assert out.x_smooth[k] == pytest.approx(icpt + slope * t[-1], rel=1e-9, abs=1e-9)
        assert out.v_smooth[k] == pytest.approx(slope, rel=1e-9, abs=1e-9)


def test_growing_memory_reproduces_two_point_initialisation():
    rng = np.random.default_rng(5)  # seeded: arbitrary measurements
    n, dt = 25, 2.0
    z = rng.normal(10.0, 3.0, n)
    g = growing_memory(n)
    zero = track(z, g, dt=dt, init="zero")
    two = track(z, g, dt=dt, init="two_point")
    # what is true: smoothed positions agree at every sample, smoothed velocities from
    # sample 1 on, predictions from sample 2 on ...
    np.testing.assert_allclose(zero.x_smooth, two.x_smooth, rtol=1e-12)
    np.testing.assert_allclose(zero.v_smooth[1:], two.v_smooth[1:], rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(zero.x_pred[2:], two.x_pred[2:], rtol=1e-12)
    assert zero.v_smooth[1] == pytest.approx((z[1] - z[0]) / dt)  # seed 001, eq 9
    # ... but not before: beta_1 = 3 leaves v = 3 z0 / T after sample 0, and the zero
    # state predicts 0 then 4 z0 where two_point takes z0, z1 as the predictions
    assert zero.v_smooth[0] == pytest.approx(3 * z[0] / dt) and two.v_smooth[0] == 0.0
    assert zero.x_pred[0] == 0.0 and zero.x_pred[1] == pytest.approx(4 * z[0])
    assert two.x_pred[0] == z[0] and two.x_pred[1] == z[1]
    # beta_1 is irrelevant from sample 1 on (alpha_2 = beta_2 = 1 overwrite the state)
    other = Gains(g.alpha, np.concatenate([[-7.0], g.beta[1:]]))
    np.testing.assert_allclose(track(z, other, dt=dt).x_pred[2:], zero.x_pred[2:], rtol=1e-12)


# --------------------------------------------------------------------------- Huang
@FAST
@given(unit_open)
def test_huang_type1_satisfies_its_equations(xi):
    a, b, gh = to_huang(huang_type1(xi, order=3))
    assert a == xi
    assert 2 * b == pytest.approx(a * (a + b + gh), rel=1e-12, abs=1e-300)  # seed 002
    assert b**2 == pytest.approx(4 * a * gh, rel=1e-12, abs=1e-300)  # seed 002
    assert 2 * a + b < 4  # the root chosen is the stable one (seed 000, eq 46)
    assert huang_type1(xi, order=2).isclose(benedict_bordner(xi), rtol=1e-15)


@FAST
@given(st.floats(0.001, 0.999))
def test_huang_type1_abg_is_kalata(xi):
    g = huang_type1(xi, order=3)
    lam = g.gamma / math.sqrt(1 - g.alpha)  # Lambda^2 = gamma^2 / (1 - alpha)
    assert kalata_abg(lam).isclose(g, rtol=1e-9)


@FAST
@given(st.floats(0.0, 0.999))
def test_huang_type2_is_steelman_standard(xi):
    assert huang_type2(xi, order=2).isclose(standard_ab(xi), rtol=1e-15)
    assert huang_type2(xi, order=3).isclose(standard_abg(xi), rtol=1e-15)
    assert to_huang(huang_type2(xi, 3))[2] == pytest.approx((1 - xi) ** 3 / 2, rel=1e-14)


# Huang et al. Tables 1-2 (seed 002): (table, ENBW Hz, order, printed xi, printed alpha,
# beta, gamma_H in Huang's convention, expected verdict of each of alpha, beta, gamma_H)
HUANG_TABLES = [
    (1, 2, 2, "0.02", "0.02", "0.0002", None, (True, True, True)),
    (1, 10, 2, "0.09", "0.09", "0.0042", None, (True, True, True)),
    (1, 20, 2, "0.16", "0.16", "0.0139", None, (True, True, True)),
    (1, 2, 3, "0.45", "0.45", "0.14", "0.01", (True, False, True)),  # beta rule 0.1335
    (1, 10, 3, "0.61", "0.61", "0.28", "0.18", (True, True, False)),  # gamma_H 0.0326
    (1, 20, 3, "0.68", "0.68", "0.38", "0.23", (True, True, False)),  # gamma_H 0.0523
    (2, 2, 2, "0.99", "0.02", "0.0001", None, (True, True, True)),
    (2, 10, 2, "0.95", "0.098", "0.0025", None, (True, True, True)),  # 0.0975: a tie
    (2, 20, 2, "0.9", "0.19", "0.01", None, (True, True, True)),
    (2, 2, 3, "0.66", "0.71", "0.29", "0.020", (True, True, True)),
    (2, 10, 3, "0.55", "0.83", "0.47", "0.046", (True, True, True)),
    (2, 20, 3, "0.51", "0.87", "0.54", "0.059", (True, True, True)),
]


@pytest.mark.parametrize("row", HUANG_TABLES, ids=lambda r: f"T{r[0]}-{r[1]}Hz-order{r[2]}")
def test_huang_tables_gains_vs_rule(row):
    table, _, order, xi, *printed, expected = row
    rule = huang_type1 if table == 1 else huang_type2
    ours = to_huang(rule(float(xi), order))
    verdicts = tuple(
        True if p is None else printed_match(v, p) for v, p in zip(ours, printed, strict=True)
    )
    assert verdicts == expected, (ours, printed)


@pytest.mark.parametrize("row", HUANG_TABLES, ids=lambda r: f"T{r[0]}-{r[1]}Hz-order{r[2]}")
def test_huang_tables_enbw(row, enbw_func):
    table, bn, order, xi, *_ = row
    rule = huang_type1 if table == 1 else huang_type2
    dt = 1 / 300  # seed 002, simulation: F_r = 300 Hz
    got = enbw_func(rule(float(xi), order), dt)
    if order == 2:
        # alpha-beta rows: the printed 2-digit xi gives the ENBW within 15 %
        assert got == pytest.approx(bn, rel=0.15)
    else:
        # alpha-beta-gamma rows: the printed gains are 5-50x too wide (95-340 Hz)
        assert got > 4 * bn


@pytest.mark.parametrize("rule", ["type1", "type2"])
@pytest.mark.parametrize("order", [2, 3])
@pytest.mark.parametrize("bn", [2.0, 10.0, 20.0, 200.0])
def test_huang_for_enbw_round_trip(rule, order, bn, enbw_func):
    dt = 1 / 300  # seed 002: F_r = 300 Hz
    g = huang_for_enbw(bn, dt, rule=rule, order=order)
    assert enbw_func(g, dt) == pytest.approx(bn, rel=1e-9)
    assert g.order == order


def test_huang_for_enbw_alpha_beta_xi(enbw_func):
    # the xi that really give 2/10/20 Hz at F_r = 300 Hz (compare the printed xi)
    dt = 1 / 300
    xi1 = [huang_for_enbw(b, dt, "type1").alpha for b in (2, 10, 20)]
    np.testing.assert_allclose(xi1, [0.017518, 0.082751, 0.154786], atol=5e-6)
    xi2 = [standard_theta_from_alpha(huang_for_enbw(b, dt, "type2").alpha) for b in (2, 10, 20)]
    np.testing.assert_allclose(xi2, [0.989435, 0.949095, 0.902572], atol=5e-6)


def test_huang_for_enbw_out_of_reach(enbw_func):
    dt = 1 / 300
    # type I / II alpha-beta top out at the deadbeat alpha = beta = 1: B_n T = 2.5
    with pytest.raises(
        ValueError,
        match=r"bn_hz=1000.0 with dt=0.00333.* reaches over "
        r"0 < xi <= 1: 0 < bn_hz <= 750 Hz",
    ):
        huang_for_enbw(1000.0, dt, rule="type1", order=2)
    # type II alpha-beta-gamma at xi = 0: impulse response 3, -3, 1 -> B_n T = 19 / 2
    with pytest.raises(ValueError, match=r"type2 order-3 rule .* 0 < bn_hz <= 2850 Hz"):
        huang_for_enbw(3000.0, dt, rule="type2", order=3)
    with pytest.raises(ValueError, match=r"rule must be one of 'type1', 'type2', got 'x'"):
        huang_for_enbw(2.0, dt, rule="x")
    with pytest.raises(ValueError, match=r"bn_hz must be > 0, got -1.0"):
        huang_for_enbw(-1.0, dt)


# --------------------------------------------------------------------------- Bendix
def test_bendix_tables():
    assert bendix(1) == Gains(0.250, 0.066)  # seed 003 memo, first row
    assert bendix(8.0, table="captions") == Gains(0.66, 0.91)  # seed 003, T= 8.00 captions
    assert sorted(BENDIX_MEMO) == sorted(BENDIX_CAPTIONS) == list(range(1, 9))


def test_bendix_captions_are_truncated_memo_values():
    for p, (a, b) in BENDIX_MEMO.items():
        trunc = tuple(math.floor(v * 100 + 1e-9) / 100 for v in (a, b))
        assert BENDIX_CAPTIONS[p] == pytest.approx(trunc, abs=1e-12), p
    # rounding half up would not give the captions: e.g. beta .066 -> .07, alpha .465 -> .47
    rounded_up = {
        p: tuple(math.floor(v * 100 + 0.5 + 1e-9) / 100 for v in ab)
        for p, ab in BENDIX_MEMO.items()
    }
    differ = [p for p in BENDIX_MEMO if rounded_up[p] != pytest.approx(BENDIX_CAPTIONS[p])]
    assert differ == [1, 2, 3, 5, 6, 7, 8]


# --------------------------------------------------------------------------- Kalman
def _riccati_iteration(Phi, Q, r, n_iter=20000):
    """Independent route: iterate the Kalman covariance recursion to its fixed point."""
    H = np.zeros((1, Phi.shape[0]))
    H[0, 0] = 1.0
    P = np.eye(Phi.shape[0]) * 1e3
    for _ in range(n_iter):
        S = (H @ P @ H.T).item() + r
        K = P @ H.T / S
        Pn = Phi @ (P - K @ H @ P) @ Phi.T + Q
        if np.allclose(Pn, P, rtol=1e-15, atol=0):
            break
        P = Pn
    return (P @ H.T / ((H @ P @ H.T).item() + r)).ravel()


@pytest.mark.parametrize("lam", [0.01, 0.3, 1.0, 5.0, 50.0])
@pytest.mark.parametrize("dt", [1.0, 0.1])
def test_kalata_vs_dare(lam, dt):
    sigma_n = 2.0  # arbitrary measurement std
    sigma_w = lam * sigma_n / dt**2  # Lambda = sigma_w T^2 / sigma_n
    ab = steady_state_kalman(sigma_w**2, sigma_n**2, dt, order=2)
    assert kalata_ab(lam).isclose(ab, rtol=1e-10)
    abg = steady_state_kalman(sigma_w**2, sigma_n**2, dt, order=3)
    assert kalata_abg(lam).isclose(abg, rtol=1e-10)


@pytest.mark.parametrize("lam", [0.05, 0.5, 3.0])
def test_kalata_abg_not_the_jerk_model(lam):
    T = 1.0
    jerk = steady_state_kalman((lam / T**3) ** 2, 1.0, T, order=3, model="piecewise_constant_jerk")
    k = kalata_abg(lam)
    assert not k.isclose(jerk, rtol=1e-4)
    # but Lambda^2 = gamma^2 / (1 - alpha) holds for it too (with Lambda = sigma_j T^3 / sigma_n)
    assert jerk.gamma**2 / (1 - jerk.alpha) == pytest.approx(lam**2, rel=1e-9)


@FAST
@given(st.floats(1e-3, 1e3))
def test_kalata_relations(lam):
    g = kalata_ab(lam)
    r = (4 + lam - math.sqrt(8 * lam + lam**2)) / 4  # Kalata 1984 as printed
    assert g.alpha == pytest.approx(1 - r**2, rel=1e-12)
    assert g.beta == pytest.approx(2 * (2 - g.alpha) - 4 * math.sqrt(1 - g.alpha), abs=1e-12)
    assert g.beta**2 / (1 - g.alpha) == pytest.approx(lam**2, rel=1e-9)
    h = kalata_abg(lam)
    assert h.beta == pytest.approx(2 * (2 - h.alpha) - 4 * math.sqrt(1 - h.alpha), abs=1e-12)
    assert h.gamma == pytest.approx(h.beta**2 / (2 * h.alpha), rel=1e-12)
    assert h.gamma**2 / (1 - h.alpha) == pytest.approx(lam**2, rel=1e-9)
    # Simpson's condition, seed 000, eq 21
    assert 2 * h.beta - h.alpha * (h.alpha + h.beta + h.gamma / 2) == pytest.approx(0.0, abs=1e-12)


@pytest.mark.parametrize(
    ("order", "model"),
    [
        (2, "piecewise_constant"),
        (3, "piecewise_constant"),
        (3, "piecewise_constant_jerk"),
        (2, "continuous"),
        (3, "continuous"),
    ],
)
def test_steady_state_kalman_vs_riccati_iteration(order, model):
    q, r, T = 0.7, 1.3, 0.5  # arbitrary
    g = steady_state_kalman(q, r, T, order=order, model=model)
    Phi = expm(np.diag(np.full(order - 1, T), 1))  # polynomial transition (eqs 4-6)
    if model == "continuous":
        # Van Loan's method for Q = q * int e^{At} b b^T e^{A^T t} dt (independent route)
        A = np.diag(np.ones(order - 1), 1)
        B = np.zeros((order, order))
        B[-1, -1] = q
        M = expm(np.block([[-A, B], [np.zeros_like(A), A.T]]) * T)
        Q = M[order:, order:].T @ M[:order, order:]
    else:
        G = {
            (2, "piecewise_constant"): [T**2 / 2, T],
            (3, "piecewise_constant"): [T**2 / 2, T, 1.0],
            (3, "piecewise_constant_jerk"): [T**3 / 6, T**2 / 2, T],
        }[order, model]
        Q = q * np.outer(G, G)
    K = _riccati_iteration(Phi, Q, r)
    expected = K * np.array([1.0, T, T**2])[:order]  # alpha, beta / T, gamma / T^2
    np.testing.assert_allclose([g.alpha, g.beta, g.gamma][:order], expected, rtol=1e-9)


def test_steady_state_kalman_broadcasts():
    g = steady_state_kalman(np.array([0.1, 1.0, 10.0]), 1.0, 1.0)
    assert g.shape == (3,)
    assert np.all(np.diff(g.alpha) > 0)  # more process noise, wider filter


# --------------------------------------------------------------------------- errors
@pytest.mark.parametrize(
    ("call", "message"),
    [
        (lambda: standard_ab(1.2), r"theta must satisfy 0 <= theta < 1, got 1.2"),
        (lambda: standard_abg(-0.1), r"theta must satisfy 0 <= theta < 1, got -0.1"),
        (lambda: standard_theta_from_alpha(0.0), r"alpha must satisfy 0 < alpha <= 1, got 0.0"),
        (
            lambda: standard_from_alpha(0.5, order=4),
            r"order must be 2 \(alpha-beta\) or 3 \(alpha-beta-gamma\), got 4",
        ),
        (lambda: qd(1.0), r"m must satisfy 1 < m, got 1.0"),
        (lambda: qd_m_from_alpha(1.5), r"alpha must satisfy 0 < alpha <= 1, got 1.5"),
        (lambda: benedict_bordner(1.5), r"alpha must satisfy 0 < alpha <= 1, got 1.5"),
        (lambda: simpson(0.5), r"simpson needs exactly one of beta and gamma"),
        (lambda: simpson(0.5, 0.1, 0.1), r"simpson needs exactly one of beta and gamma"),
        (
            lambda: simpson_gamma(0.5, 0.1),
            r"beta must satisfy beta >= alpha\*\*2 / \(2 - alpha\).*alpha=0.5 that is "
            r"beta >= 0.166667, got 0.1",
        ),
        (lambda: simpson_beta(2.0, 0.1), r"alpha must satisfy 0 < alpha < 2, got 2.0"),
        (lambda: simpson_beta(0.5, -0.1), r"gamma must satisfy 0 <= gamma, got -0.1"),
        (lambda: growing_memory(0), r"n_samples must be an integer >= 1, got 0"),
        (lambda: growing_memory(3, start=0), r"start must be an integer >= 1, got 0"),
        (lambda: growing_memory(2.5), r"n_samples must be an integer >= 1, got 2.5"),
        (lambda: huang_type1(1.0, order=3), r"xi must satisfy 0 < xi < 1, got 1.0"),
        (lambda: huang_type1(0.0), r"xi must satisfy 0 < xi <= 1, got 0.0"),
        (lambda: huang_type2(1.0), r"xi must satisfy 0 <= xi < 1, got 1.0"),
        (
            lambda: bendix(9),
            r"period_s must be one of 1, 2, 3, 4, 5, 6, 7, 8 \(seconds; "
            r"seed 003 memo\), got 9",
        ),
        (lambda: bendix(2.5), r"period_s must be one of 1, 2, .*, 8 .*got 2.5"),
        (lambda: bendix(1, table="plots"), r"table must be one of 'memo', 'captions', got 'plots'"),
        (lambda: kalata_ab(0.0), r"tracking_index must be > 0, got 0.0"),
        (lambda: kalata_abg(-1.0), r"tracking_index must be > 0, got -1.0"),
        (lambda: steady_state_kalman(1.0, 0.0), r"r must be > 0, got 0.0"),
        (
            lambda: steady_state_kalman(1.0, 1.0, model="cv"),
            r"model must be one of 'piecewise_constant', 'piecewise_constant_jerk', "
            r"'continuous', got 'cv'",
        ),
        (
            lambda: steady_state_kalman(1.0, 1.0, order=2, model="piecewise_constant_jerk"),
            r"model='piecewise_constant_jerk' needs order=3",
        ),
    ],
)
def test_error_messages(call, message):
    with pytest.raises(ValueError, match=message):
        call()


@pytest.mark.parametrize(
    "call, match",
    [
        # beta = 1.99 (1.99 + 0.025) / 0.01 = 400.985 (seed 000, eq 21 solved for beta)
        (lambda: simpson(1.99, gamma=0.05), r"alpha=1.99, gamma=0.05 are unstable.*beta=400.985"),
        # (0.5, 0.2, 0.2) satisfies eq 21 but violates Jury's eq 47: pole radius 1.055
        (lambda: simpson_gamma(0.5, 0.2), r"alpha=0.5, beta=0.2 are unstable.*pole radius 1.055"),
        (lambda: simpson(np.array([0.5, 1.99]), gamma=0.05), r"alpha=1.99"),
    ],
)
def test_simpson_refuses_unstable_gains(call, match):
    with pytest.raises(AbglibValueError, match=match):
        call()


def test_kalata_ab_large_index_is_stable_and_accurate():
    from abglib.analysis import is_stable

    # the textbook form r = (4 + L - sqrt(8 L + L^2)) / 4 cancels to 0 at L = 1e12 and
    # gives the unstable (1, 2); r = (8/L) / (1 + sqrt(1 + 8/L))^2 is the same number
    for lam in (1e8, 1e12, 1e15):
        g = kalata_ab(lam)
        r = 2.0 / lam  # leading term of the series of r in 1/L
        assert g.beta == pytest.approx(2.0 * (1.0 - r) ** 2, rel=1e-12)
        assert g.beta < 2.0 and is_stable(g)
    for lam in (1e-3, 0.5, 1.0, 30.0):
        r = (4.0 + lam - np.sqrt(8.0 * lam + lam**2)) / 4.0  # no cancellation at small L
        assert kalata_ab(lam).alpha == pytest.approx(1.0 - r**2, rel=1e-13)
