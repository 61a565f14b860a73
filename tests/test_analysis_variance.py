"""Variance reduction factors: Lyapunov vs printed closed forms vs direct summation vs Monte Carlo.

Findings pinned here (seed 000): Simpson's eqs 11-14 are the *smoothed* VRFs exactly;
Morrison's eqs 25-27 and 31-32 are the one-step *prediction* VRFs exactly; the
Benedict-Bordner alpha-beta forms are the gamma -> 0 limit of eqs 11-13. The Sinsky memo
(seed 003) tabulates sqrt(VRF) of the smoothed position and of the smoothed velocity
(the latter in 1/s with T in seconds).
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from abglib import Gains, track
from abglib.analysis._variance import (
    VRF_KEYS,
    vrf,
    vrf_benedict_ab,
    vrf_simpson,
    vrf_standard_ab,
    vrf_standard_abg,
)

from .strategies import stable_gain_strategies, standard_ab, standard_abg

# --------------------------------------------------------------------------- strategies
# pole radius < 0.95 keeps the sums short
stable_ab, stable_abg = stable_gain_strategies(0.95, 1e-6)

dts = st.sampled_from([0.01, 0.5, 1.0, 3.0])  # sample intervals in seconds (arbitrary)


# --------------------------------------------------------------------------- helpers
def impulse_sums(gains, dt):
    """Sum of squared impulse responses of every output, from abglib.track."""
    n = 3000  # 0.95**3000 ~ 1e-67: the tails are far below double precision
    z = np.zeros(n)
    z[0] = 1.0
    r = track(z, gains, dt=dt)
    v_pred = np.concatenate([[0.0], r.v_smooth[:-1] + dt * r.a_smooth[:-1]])
    a_pred = np.concatenate([[0.0], r.a_smooth[:-1]])
    return {
        "x_smooth": np.sum(r.x_smooth**2),
        "v_smooth": np.sum(r.v_smooth**2),
        "a_smooth": np.sum(r.a_smooth**2),
        "x_pred": np.sum(r.x_pred**2),
        "v_pred": np.sum(v_pred**2),
        "a_pred": np.sum(a_pred**2),
    }


# --------------------------------------------------------------------------- exact route
@settings(max_examples=40, deadline=None)
@given(st.one_of(stable_ab, stable_abg), dts)
def test_lyapunov_equals_direct_summation(gains, dt):
    exact = vrf(gains, dt)
    summed = impulse_sums(gains, dt)
    for k in VRF_KEYS:
        assert exact[k] == pytest.approx(summed[k], rel=1e-9, abs=1e-300), k


@pytest.mark.parametrize(
    "gains",
    [
        Gains(3e-6, 4.5e-12),  # poles crowding z = 1
        Gains(2 - 1e-10, 5e-11),  # alpha at its edge
        Gains(1.99999, 1e-10),
        Gains(1.9, 0.2 - 1e-8),  # 2 alpha + beta at 4: a pole at z = -1
        standard_ab(1 - 1e-9),
        Gains(1.5, 0.5, 1e-15),  # a gamma far below the others
        Gains(0.5, 0.2, 1e-17),
    ],
)
def test_lyapunov_is_exact_at_the_edges_of_stability(gains):
    """Where a float Lyapunov solver failed (scipy's bilinear route: negative variances,
    e.g. x_smooth -2.7e-7 for 2.25e-6 at the first set; its Kronecker route: a_smooth off by
    a factor 5 at gamma 1e-17), the exact solve agrees with the printed closed forms, whose
    rounding is a few ulps here (Benedict and Bordner for alpha-beta; Simpson, eqs 11-14,
    for the smoothed alpha-beta-gamma outputs; Morrison, eqs 25-27, for the standard
    gains' predictions), and every variance is positive."""
    exact = vrf(gains)
    assert all(exact[k] > 0 for k in ("x_smooth", "v_smooth", "x_pred", "v_pred"))
    if gains.gamma == 0:
        bb = vrf_benedict_ab(gains)
        for k in ("x_smooth", "v_smooth", "x_pred", "v_pred"):
            assert exact[k] == pytest.approx(bb[k], rel=1e-10), k
        return
    simpson = vrf_simpson(gains)
    for k in "xva":
        assert exact[f"{k}_smooth"] == pytest.approx(simpson[k], rel=1e-10), k


def kronecker_vrf(gains) -> tuple[float, ...]:
    """The VRFs at T = 1 by an independent exact route: the full n^2 x n^2 Kronecker system
    ``(I - F (x) F) vec P = vec K K^T`` (no symmetry used) with ``F = (I - K H) Phi`` formed
    in :class:`fractions.Fraction` from the state-space form's Phi, H and K (numpy's F is
    rounded), solved by plain Gauss-Jordan elimination, then ``Phi P Phi^T``; each VRF
    rounded once (``float(Fraction)``)."""
    from fractions import Fraction

    from abglib.analysis._statespace import state_space

    ss = state_space(gains, 1.0)
    n = len(ss.K)
    k = [Fraction(v) for v in ss.K]
    h = [Fraction(v) for v in ss.H]
    phi = [[Fraction(v) for v in row] for row in ss.Phi]
    h_phi = [sum(h[u] * phi[u][j] for u in range(n)) for j in range(n)]
    f = [[phi[i][j] - k[i] * h_phi[j] for j in range(n)] for i in range(n)]
    m = n * n
    a = [
        [Fraction(int(r == c)) - f[r // n][c // n] * f[r % n][c % n] for c in range(m)]
        + [k[r // n] * k[r % n]]
        for r in range(m)
    ]
    for c in range(m):
        p = next(r for r in range(c, m) if a[r][c] != 0)
        a[c], a[p] = a[p], a[c]
        for r in range(m):
            if r != c and a[r][c] != 0:
                q = a[r][c] / a[c][c]
                a[r] = [x - q * y for x, y in zip(a[r], a[c], strict=True)]
    p = [[a[i * n + j][m] / a[i * n + j][i * n + j] for j in range(n)] for i in range(n)]
    smooth = [p[i][i] for i in range(n)]
    pred = [
        sum(phi[i][u] * phi[i][v] * p[u][v] for u in range(n) for v in range(n)) for i in range(n)
    ]
    out = [float(v) for v in (*smooth, *pred)]
    if n == 2:
        return out[0], out[1], 0.0, out[2], out[3], 0.0
    return tuple(out)


@settings(max_examples=60, deadline=None)
@given(st.one_of(stable_ab, stable_abg))
def test_lyapunov_is_the_correctly_rounded_exact_solution(gains):
    """Bit for bit the correctly rounded exact VRFs of another exact route (the full
    Kronecker system in fractions): the integer (Bareiss) solve of the symmetric system
    changes the route, not one bit of the result."""
    exact = vrf(gains)
    assert tuple(exact[key] for key in VRF_KEYS) == kronecker_vrf(gains)


@pytest.mark.parametrize(
    "gains",
    [
        Gains(3e-6, 4.5e-12),
        Gains(1.9, 0.2 - 1e-8),
        Gains(0.5, 0.2, 1e-17),
        Gains(0.5, 1e-16, 1e-18),
        Gains(1e-7, 1e-14, 1e-22),
        Gains(0.5, 0.2, 1e-300),  # the integers of the exact solve run to thousands of bits
    ],
)
def test_lyapunov_is_the_correctly_rounded_exact_solution_at_the_edges(gains):
    exact = vrf(gains)
    assert tuple(exact[key] for key in VRF_KEYS) == kronecker_vrf(gains)


@pytest.mark.parametrize("theta", [0.999997, 0.9999])
def test_lyapunov_is_morrisons_prediction_vrf_for_the_slowest_standard_gains(theta):
    """Morrison's eqs 25-27 for standard gains with poles at theta, close to z = 1 (a
    float Lyapunov solver gave x_pred -4.7e-6 for 6.2e-6 at theta 0.999997). The gains
    are rounded from theta (alpha = 1 - theta^3), the closed form is not: a few 1e-10."""
    exact, morrison = vrf(standard_abg(theta)), vrf_standard_abg(theta)
    for k in "xva":
        assert exact[f"{k}_pred"] == pytest.approx(morrison[k], rel=1e-8), k


@pytest.mark.parametrize(
    "gains",
    [standard_abg(0.5), standard_ab(0.6), Gains(0.5, 0.2, 0.02)],  # hand-picked stable sets
)
def test_lyapunov_equals_monte_carlo(gains):
    dt = 2.0  # seconds: checks the 1/T^2 and 1/T^4 units too
    rng = np.random.default_rng(20240611)  # fixed seed: reproducible
    batches, n, warm = 40, 25_000, 500  # 1e6 samples in 40 batches; warm-up discarded
    z = rng.standard_normal((batches, n + warm))
    r = track(z, gains, dt=dt)
    exact = vrf(gains, dt)
    series = {"x_smooth": r.x_smooth, "v_smooth": r.v_smooth, "x_pred": r.x_pred}
    if gains.gamma != 0.0:
        series["a_smooth"] = r.a_smooth
    for k, s in series.items():
        per_batch = np.mean(s[:, warm:] ** 2, axis=1)  # zero-mean output
        est = per_batch.mean()
        se = per_batch.std(ddof=1) / np.sqrt(batches)  # standard error by batch means
        assert abs(est - exact[k]) < 5.0 * se, (k, est, exact[k], se)


def test_units_scale_with_dt():
    g = standard_abg(0.4)
    one, T = vrf(g, 1.0), 0.25  # arbitrary interval
    other = vrf(g, T)
    for k, p in (("x", 0), ("v", 2), ("a", 4)):
        for kind in ("smooth", "pred"):
            key = f"{k}_{kind}"
            assert other[key] == pytest.approx(one[key] / T**p, rel=1e-12)


def test_bank_and_scalar_shapes():
    theta = np.array([0.2, 0.5, 0.8])  # three standard gain sets
    bank = vrf(standard_abg(theta), dt=np.array([1.0, 2.0, 3.0]))
    for k in VRF_KEYS:
        assert bank[k].shape == (3,)
        assert bank[k][1] == pytest.approx(vrf(standard_abg(0.5), 2.0)[k], rel=1e-14)
    scalar = vrf(Gains(0.5, 0.2))
    assert all(isinstance(v, float) for v in scalar.values())
    assert scalar["a_smooth"] == 0.0 and scalar["a_pred"] == 0.0


def test_doc_example_alpha_beta():
    # alpha = 0.5, beta = 0.2: Benedict-Bordner by hand, 0.6 / 1.4 and 1.0 / 1.4
    r = vrf(Gains(0.5, 0.2))
    assert r["x_smooth"] == pytest.approx(0.6 / 1.4, rel=1e-14)
    assert r["x_pred"] == pytest.approx(1.0 / 1.4, rel=1e-14)


# --------------------------------------------------------------------------- printed forms
@settings(max_examples=60, deadline=None)
@given(stable_abg, dts)
def test_simpson_eqs_11_14_are_the_smoothed_vrfs(gains, dt):
    exact, printed = vrf(gains, dt), vrf_simpson(gains, dt)
    assert printed["x"] == pytest.approx(exact["x_smooth"], rel=1e-7)
    assert printed["v"] == pytest.approx(exact["v_smooth"], rel=1e-7)
    assert printed["a"] == pytest.approx(exact["a_smooth"], rel=1e-7)


@settings(max_examples=60, deadline=None)
@given(stable_ab, dts)
def test_benedict_bordner_forms_are_exact(gains, dt):
    exact, bb = vrf(gains, dt), vrf_benedict_ab(gains, dt)
    for k in ("x_smooth", "v_smooth", "x_pred", "v_pred"):
        assert bb[k] == pytest.approx(exact[k], rel=1e-9)
    simpson = vrf_simpson(gains, dt)  # gamma = 0 branch
    assert (simpson["x"], simpson["v"], simpson["a"]) == (
        pytest.approx(exact["x_smooth"], rel=1e-9),
        pytest.approx(exact["v_smooth"], rel=1e-9),
        0.0,
    )


@pytest.mark.parametrize("alpha, beta", [(0.5, 0.2), (0.3, 0.0267), (1.2, 0.9)])  # stable
def test_simpson_tends_to_benedict_bordner(alpha, beta):
    # seed 000: "setting gamma to zero ... all of Simpson's results reduce to those given
    # by Benedict and Bordner"; the printed form at small gamma approaches the limit
    small = vrf_simpson(Gains(alpha, beta, 1e-7))
    bb = vrf_benedict_ab(Gains(alpha, beta))
    assert small["x"] == pytest.approx(bb["x_smooth"], rel=1e-5)
    assert small["v"] == pytest.approx(bb["v_smooth"], rel=1e-5)
    assert small["a"] == pytest.approx(0.0, abs=1e-12)


@given(st.floats(0.0, 0.99), dts)
@settings(max_examples=60, deadline=None)
def test_morrison_eqs_25_27_are_the_prediction_vrfs(theta, dt):
    exact, printed = vrf(standard_abg(theta), dt), vrf_standard_abg(theta, dt)
    assert printed["x"] == pytest.approx(exact["x_pred"], rel=1e-8)
    assert printed["v"] == pytest.approx(exact["v_pred"], rel=1e-8)
    assert printed["a"] == pytest.approx(exact["a_pred"], rel=1e-8)


@given(st.floats(0.0, 0.99), dts)
@settings(max_examples=60, deadline=None)
def test_morrison_eqs_31_32_are_the_prediction_vrfs(theta, dt):
    exact, printed = vrf(standard_ab(theta), dt), vrf_standard_ab(theta, dt)
    assert printed["x"] == pytest.approx(exact["x_pred"], rel=1e-8)
    assert printed["v"] == pytest.approx(exact["v_pred"], rel=1e-8)


def test_eq_25_is_not_the_smoothed_vrf():
    # the distinction matters: at theta = 0.5 (arbitrary) eq 25 gives 2.358 (= x_pred,
    # 191/81) while the smoothed position VRF (eq 11) is 0.8025 (= 65/81)
    theta = 0.5
    assert vrf_standard_abg(theta)["x"] == pytest.approx(191 / 81, rel=1e-12)
    assert vrf(standard_abg(theta))["x_smooth"] == pytest.approx(65 / 81, rel=1e-12)


# --------------------------------------------------------------------------- Sinsky memo
# seed 003, Sinsky memo table: update period T (s), alpha, beta, sigma ratio columns
# headed sigma_xdot/sigma_x and sigma_xddot/sigma_x, described as smoothed position and
# smoothed velocity
SINSKY = [
    (1, 0.250, 0.066, 0.491, 0.101),
    (2, 0.370, 0.175, 0.613, 0.116),
    (3, 0.465, 0.300, 0.690, 0.125),
    (4, 0.530, 0.431, 0.745, 0.132),
    (5, 0.580, 0.565, 0.788, 0.139),
    (6, 0.620, 0.685, 0.820, 0.142),
    (7, 0.645, 0.855, 0.861, 0.158),
    (8, 0.665, 0.910, 0.872, 0.149),
]


def test_sinsky_memo_columns():
    T, a, b, col1, col2 = (np.array(c, dtype=float) for c in zip(*SINSKY, strict=True))
    r = vrf(Gains(a, b), dt=T)
    d1 = np.sqrt(r["x_smooth"]) - col1
    d2 = np.sqrt(r["v_smooth"]) - col2  # 1/s, T in seconds
    # column 2: all 8 within half a unit of the printed third decimal (max 0.00039)
    assert np.max(np.abs(d2)) < 0.0005
    # column 1: 7 of 8 within half a unit; T = 1 s prints .491 for 0.49163
    assert np.max(np.abs(d1[1:])) < 0.0005
    assert d1[0] == pytest.approx(0.00063, abs=0.00001)
    # the other readings fail: predicted position, and velocity in per-sample units
    assert np.min(np.abs(np.sqrt(r["x_pred"]) - col1)) > 0.05
    assert np.min(np.abs(np.sqrt(r["v_smooth"]) * T - col2)[1:]) > 0.05


# --------------------------------------------------------------------------- bad input
def test_unstable_gains_raise_naming_them():
    with pytest.raises(ValueError, match=r"variance is unbounded: gains \(alpha=1\.9, beta=0\.5"):
        vrf(Gains(1.9, 0.5))  # 2 alpha + beta > 4 violates seed 000, eq 44
    with pytest.raises(ValueError, match=r"at index 1 are unstable"):
        vrf(Gains(np.array([0.5, 1.9]), np.array([0.2, 0.5])))
    with pytest.raises(ValueError, match=r"variance is unbounded"):
        vrf_simpson(Gains(0.5, 0.2, 0.2))  # alpha beta + alpha gamma/2 - gamma < 0 (eq 47)


def test_bad_arguments():
    with pytest.raises(ValueError, match=r"gains must be an abglib.Gains, got tuple"):
        vrf((0.5, 0.2))
    with pytest.raises(ValueError, match=r"dt must be > 0, got -1\.0"):
        vrf(Gains(0.5, 0.2), dt=-1.0)
    with pytest.raises(ValueError, match=r"theta must satisfy 0 <= theta < 1, got 1\.2"):
        vrf_standard_abg(1.2)
    with pytest.raises(ValueError, match=r"theta must satisfy 0 <= theta < 1, got 1\.0"):
        vrf_standard_ab(1.0)
    with pytest.raises(ValueError, match=r"needs gamma == 0, got gamma=0\.02"):
        vrf_benedict_ab(Gains(0.5, 0.2, 0.02))
