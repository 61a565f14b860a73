"""Every published claim of seed 000 (Steelman 1978), each against an independent route.

The independent routes are written out here from the printed equations: the transfer
functions of eqs 36-40 typed as polynomials in Z, the standard and QD gain rules typed
from eqs 22-24, p. 5 and eq 28, sums of squared impulse responses and step errors of the
simulated tracker (``abglib.track``), and bisection on the typed |X̄/X|. The study is
built once per module at the small test config.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq, minimize_scalar

import abglib
from abglib import Gains
from abglib.replications import claims_of, reproduce
from abglib.replications._claims import config_with
from abglib.replications.steelman1978.equations import impulse_length
from abglib.replications.steelman1978.figures import response_table
from abglib.replications.steelman1978.study import SteelmanStudy, fading_memory_weights

from .conftest import ROOT, claim_test, published, published_paths, small_config, study_for

DOC = "steelman1978"
CLAIMS, _ = claims_of(DOC)
# one worker makes the module's study and comparison (0.6 s each) for all its tests,
# instead of each worker making them again (pytest-xdist --dist loadgroup)
pytestmark = pytest.mark.xdist_group("steelman1978_claims")


@pytest.fixture(scope="module")
def s() -> SteelmanStudy:
    return study_for(DOC, small_config())


@pytest.fixture(scope="module")
def comparison():
    cfg = small_config()
    over = cfg["tolerance_overrides"][DOC]
    tables = reproduce(DOC, {DOC: cfg[DOC]}, published_paths(DOC), over)
    return tables["comparison"].assign(key=list(published(DOC)["key"])).set_index("key")


def value(s, key):
    return CLAIMS.compute(s, key).value


def variant(s, path, v) -> SteelmanStudy:
    return SteelmanStudy(config_with(s.config, path, v), s.published)


# ---------------------------------------------------------------- typed printed forms
def std_typed(alpha, order=3) -> Gains:
    """Eqs 22-24 (order 3) and p. 5 (order 2), typed from the text."""
    if order == 3:
        th = (1 - alpha) ** (1 / 3)
        return Gains(1 - th**3, 1.5 * (1 - th) ** 2 * (1 + th), (1 - th) ** 3)
    th = (1 - alpha) ** 0.5
    return Gains(1 - th**2, (1 - th) ** 2)


def qd_alpha(m):
    """Eq 28."""
    return 60 * m**2 / (10 * m**3 + 33 * m**2 + 23 * m - 6)


def qd_typed(m) -> Gains:
    a = qd_alpha(m)
    return Gains(a, 2 * a / m, 2 * a / m**2)  # eqs 29-30


def H(g: Gains, out: str, wt):
    """Eqs 36-40 typed, T = 1, Z = e^{jωT}."""
    a, b, c = (float(v) for v in g)
    Z = np.exp(1j * np.asarray(wt, dtype=float))
    D = (Z - 1) ** 3 + a * (Z - 1) ** 2 + (b + c / 2) * Z * (Z - 1) + c * Z
    return {
        "x_smooth": Z * (a * (Z - 1) ** 2 + (b + c / 2) * (Z - 1) + c),
        "v_smooth": Z * (b * (Z - 1) ** 2 + c * (Z - 1)),
        "a_smooth": Z * c * (Z - 1) ** 2,
        "x_pred": (a + b + c / 2) * (Z - 1) ** 2 + (b + 1.5 * c) * (Z - 1) + c,
    }[out] / D


def db(g, out, wt, scale=1.0):
    return 20 * np.log10(scale * np.abs(H(g, out, wt)))


def crossing(g, level_db, lo=1e-4, hi=np.pi):
    """First ωT after the peak where 20 log|X̄/X| = level_db (bisection on the typed form)."""
    wmax = peak(g)[0]
    return brentq(lambda w: db(g, "x_smooth", w) - level_db, wmax, hi)


def peak(g):
    """(ωT_max, overshoot) by a dense scan and a bounded refinement on the typed form."""
    w = np.geomspace(1e-4, 1.0, 20001)
    i = int(np.argmax(np.abs(H(g, "x_smooth", w))))
    r = minimize_scalar(
        lambda x: -abs(H(g, "x_smooth", x)),
        bounds=(w[max(i - 1, 0)], w[i + 1]),
        method="bounded",
        options={"xatol": 1e-13},
    )
    return r.x, -r.fun - 1.0


def impulse(g, n, out="x_smooth"):
    z = np.zeros(n)
    z[0] = 1.0
    return getattr(abglib.track(z, g), out)


# ---------------------------------------------------------------- Tables 1-2
GAIN_KEYS = [
    "table1.std_abg.beta",
    "table1.std_abg.gamma",
    "table1.std_ab.beta",
    "table2.std_abg.beta",
    "table2.std_abg.gamma",
    "table2.std_ab.beta",
    "table2.qd.alpha",
    "table2.qd.beta",
    "table2.qd.gamma",
    "table1.qd.beta",
    "table1.qd.gamma",
]


@pytest.mark.parametrize("key", [pytest.param(k, marks=claim_test(DOC, k)) for k in GAIN_KEYS])
def test_table_gains_are_the_typed_rules(s, key, comparison):
    table, kind, name = key.split(".")
    alpha = 0.3 if table == "table1" else 0.246  # Tables 1-2 headers
    if kind == "qd":
        m = brentq(lambda m: qd_alpha(m) - 0.3, 5, 50) if table == "table1" else 21.0
        g = qd_typed(m)
    else:
        g = std_typed(alpha, 3 if kind == "std_abg" else 2)
    assert value(s, key) == pytest.approx(getattr(g, name), rel=1e-12)
    assert comparison.loc[key, "verdict"] == "match"


@claim_test(DOC, "text.qd_m_alpha_0.3")
def test_qd_m_for_alpha_03(s):
    m = value(s, "text.qd_m_alpha_0.3")
    assert qd_alpha(m) == pytest.approx(0.3, abs=1e-13)
    assert m == pytest.approx(16.5633, abs=1e-4)  # the exact root; printed 16.6


@claim_test(DOC, "table1.qd.alpha")
def test_qd_alpha_uses_the_printed_m(s):
    assert value(s, "table1.qd.alpha") == pytest.approx(qd_alpha(16.6), rel=1e-13)  # m printed


# ---------------------------------------------------------------- Tables 3-5
ALPHAS = ("0.1", "0.3", "0.488")
T345 = [f"table{t}.{k}.{a}" for t in (3, 4, 5) for k in ("approx", "exact") for a in ALPHAS]
# verdicts of v0.2.0, kept (see the notes: none is rescued by guessing the author's rounding)
T345_MISMATCH = {
    "table3.approx.0.1",
    "table3.exact.0.1",
    "table3.exact.0.3",
    "table3.exact.0.488",
    "table4.approx.0.1",
    "table4.approx.0.488",
    "table5.exact.0.488",
    "table5.approx.0.488",
}
# v0.4.0: the reading catalogue (abglib.verdicts.readings) explains two of them as slips
# of the last printed digit, at a chance far below the budget: 0.1332450 rounded twice
# (.133245 -> .13325) and sqrt(beta/2) = 0.1333861 truncated (.13338)
T345_EXPLAINED = {
    "table5.exact.0.3": "typo:double rounding",
    "table5.approx.0.3": "typo:truncated",
}


def t345_typed(key):
    table, kind, a = key.split(".", 2)
    g = std_typed(float(a))
    al, be, ga = (float(v) for v in g)
    if table == "table3" and kind == "exact":
        return crossing(g, -6.0)
    if table == "table3":
        # eq 53 with -.3 in the exponent (text after eq 53)
        w1 = np.sqrt(2 * be)
        return w1 * 10 ** (-0.3 * np.log(np.pi / w1) / np.log(al / 2))
    if table == "table4" and kind == "exact":
        return peak(g)[1]
    if table == "table4":
        n = al * be / 2 - ga + 3 / 8 * be**2  # eq 59
        M = 3 / 8 * be**2 * (1 - al) * (n + be / 3)  # eq 56
        N2 = be**3 * (1 - al) ** 2 * n**2 / 16  # eq 57
        D = n**2 + be**3 / 8  # eq 58
        return M / D + (M**2 + N2) / (2 * D**2)  # eq 55
    if kind == "exact":
        return peak(g)[0]
    return np.sqrt(be / 2)  # eq 54


@pytest.mark.parametrize("key", [pytest.param(k, marks=claim_test(DOC, k)) for k in T345])
def test_tables_3_to_5(s, key, comparison):
    assert value(s, key) == pytest.approx(t345_typed(key), rel=1e-7)
    want = "mismatch" if key in T345_MISMATCH else "match"
    if key in T345_EXPLAINED:
        want = "explained"
        assert comparison.loc[key, "reading"] == T345_EXPLAINED[key]
    assert comparison.loc[key, "verdict"] == want


# ---------------------------------------------------------------- design example (p. 8)
DESIGN = {
    # key: (expected verdict, typed exact value)
    "design.wT_3db": "match",
    "design.T": "match",
    "design.rate": "mismatch",
    "design.wT_60hz": "explained",
    "design.attenuation_60hz_db": "match",
    "design.first_max_offset": "match",
    "design.omega_first_max": "explained",
    "design.f_first_max": "explained",
}


@pytest.mark.parametrize("key", [pytest.param(k, marks=claim_test(DOC, k)) for k in DESIGN])
def test_design_example(s, key, comparison):
    g = std_typed(0.1)  # "standard α-β-γ tracker with α = .1", pass 5 Hz, 60 Hz interference
    wt = crossing(g, -3.0)
    T = wt / (2 * np.pi * 5)
    d = peak(g)[0]
    typed = {
        "design.wT_3db": wt,
        "design.T": T,
        "design.rate": 1 / T,
        "design.wT_60hz": 12 * wt,
        "design.attenuation_60hz_db": -db(g, "x_smooth", 12 * wt),
        "design.first_max_offset": d,
        "design.omega_first_max": (2 * np.pi - d) / T,
        "design.f_first_max": (2 * np.pi - d) / T / (2 * np.pi),
    }
    # the typed peak location is found by a bounded search on a flat maximum: ~1e-8
    assert value(s, key) == pytest.approx(typed[key], rel=1e-7)
    assert comparison.loc[key, "verdict"] == DESIGN[key]
    if DESIGN[key] == "explained":
        # the printed arithmetic: (60/5) x .135 = 1.62; (2π - .04)/.0043 = 1451.9/s = 231.08 Hz
        printed = {
            "design.wT_60hz": 12 * 0.135,
            "design.omega_first_max": (2 * np.pi - 0.04) / 0.0043,
            "design.f_first_max": (2 * np.pi - 0.04) / 0.0043 / (2 * np.pi),
        }[key]
        reading = CLAIMS.compute(s, key).readings[0]
        assert reading.value == pytest.approx(printed, rel=1e-12)


# ---------------------------------------------------------------- equations (table of agreement)
def simpson_typed(g):
    """Eqs 11-14 typed."""
    a, b, c = (float(v) for v in g)
    Y2 = c * (a * (2 * b + c) - 2 * c) * (4 - 2 * a - b)
    kx = (2 * b * c * (2 * a**2 + 2 * b - 3 * a * b) - a * c**2 * (4 - 2 * a - b)) / Y2
    kv = (4 * b**3 * c - 4 * b**2 * c**2 + 2 * c**3 * (2 - a)) / Y2
    ka = 4 * b * c**3 / Y2
    return {"x_smooth": kx, "v_smooth": kv, "a_smooth": ka}


def step_errors(g, kind, n):
    """Sums of squared errors of x̄, v̄, ā after a unit velocity (D²) or acceleration (A²)
    step (tracker at rest, z(n) = n or n²/2 from n = 0, T = 1): Simpson's eqs 15-20 by
    direct summation of the simulated tracker's errors."""
    t = np.arange(n, dtype=float)
    if kind == "D":
        x, v, acc = t, np.ones(n), np.zeros(n)
    else:
        x, v, acc = t**2 / 2, t, np.ones(n)
    r = abglib.track(x, g)
    return {
        "x": float(np.sum((r.x_smooth - x) ** 2)),
        "v": float(np.sum((r.v_smooth - v) ** 2)),
        "a": float(np.sum((r.a_smooth - acc) ** 2)),
    }


def simpson_transient_typed(g):
    """Eqs 15-20 typed (eq 20 printed A_x², read as A_a²)."""
    a, b, c = (float(v) for v in g)
    Y2 = c * (a * (2 * b + c) - 2 * c) * (4 - 2 * a - b)
    q = 4 - 2 * a - b
    D = {
        "x": 2 * c * (2 - a) * (1 - a) ** 2,
        "v": 2 * c * (a**2 * (2 - a) + 2 * b * (1 - a))
        + (c**3 / 8) * (2 - a)
        - (c**2 / 4) * (2 * (4 - 3 * a) * (2 - a) + a * b),
        "a": a * c**2 * q + (c**3 / 2) * (2 - a),
    }
    Asq = {
        "x": a * q * (1 - a) ** 2,
        "v": (a / 4) * (b - 2 * a) ** 2 * q + (c / 8) * (2 - a) * q**2,
        "a": a * b**2 * q + (c / 2) * (2 * a**2 - (2 - a) * b) * q,
    }
    return {k: v / Y2 for k, v in D.items()}, {k: v / Y2 for k, v in Asq.items()}


EQ_GAINS = [std_typed(0.3), qd_typed(brentq(lambda m: qd_alpha(m) - 0.3, 5, 50))]


@pytest.mark.parametrize(
    ("key", "out"),
    [
        pytest.param("eq.11", "x_smooth", marks=claim_test(DOC, "eq.11")),
        pytest.param("eq.12", "v_smooth", marks=claim_test(DOC, "eq.12")),
        pytest.param("eq.13", "a_smooth", marks=claim_test(DOC, "eq.13")),
    ],
)
def test_simpson_vrf_is_the_smoothed_sum_of_squares(s, key, out):
    for g in EQ_GAINS:
        h = impulse(g, impulse_length(g, 4096), out)
        assert simpson_typed(g)[out] == pytest.approx(np.sum(h**2), rel=1e-10)
    assert value(s, key) is True


@pytest.mark.parametrize(
    "key", [pytest.param(f"eq.{n}", marks=claim_test(DOC, f"eq.{n}")) for n in range(15, 21)]
)
def test_simpson_transients_by_direct_summation(s, key):
    n = int(key.split(".")[1])
    kind, comp = ("D" if n <= 17 else "A"), "xva"[(n - 15) % 3]
    for g in EQ_GAINS:
        typed = simpson_transient_typed(g)[0 if kind == "D" else 1][comp]
        assert typed == pytest.approx(step_errors(g, kind, 6000)[comp], rel=1e-9)
    assert value(s, key) is True


def morrison_typed(theta, order):
    """Eqs 25-27 (order 3) and 31-32 (order 2), typed."""
    th = theta
    if order == 3:
        return {
            "x": (1 - th) / (1 + th) ** 5 * (19 + 24 * th + 16 * th**2 + 6 * th**3 + th**4),
            "v": (1 - th) ** 3 / (1 + th) ** 5 * (49 + 50 * th + 13 * th**2) / 2,
            "a": 6 * (1 - th) ** 5 / (1 + th) ** 5,
        }
    return {
        "x": (1 - th) / (1 + th) ** 3 * (5 + 4 * th + th**2),
        "v": 2 * (1 - th) ** 3 / (1 + th) ** 3,
    }


MORRISON = {
    # key: (order, component, holds as the smoothed VRF, the output it equals)
    "eq.25": (3, "x", False, "x_pred"),
    "eq.26": (3, "v", False, "v_pred"),
    "eq.27": (3, "a", True, "a_smooth"),
    "eq.31": (2, "x", False, "x_pred"),
    "eq.32": (2, "v", True, "v_smooth"),
}


@pytest.mark.parametrize("key", [pytest.param(k, marks=claim_test(DOC, k)) for k in MORRISON])
def test_morrison_vrfs_are_prediction_vrfs(s, key, comparison):
    order, comp, holds, equals = MORRISON[key]
    alpha = 0.3
    theta = (1 - alpha) ** (1 / order)
    g = std_typed(alpha, order)
    n = impulse_length(g, 4096)
    printed = morrison_typed(theta, order)[comp]
    smoothed = {"x": "x_smooth", "v": "v_smooth", "a": "a_smooth"}[comp]
    if equals == "v_pred":
        # one-step predicted velocity v̄(n-1) + T ā(n-1) (eq 5), from the smoothed states
        r = abglib.track(np.eye(1, n)[0], g)
        h = np.concatenate([[0.0], r.v_smooth[:-1] + r.a_smooth[:-1]])
    else:
        h = impulse(g, n, equals)
    assert printed == pytest.approx(np.sum(h**2), rel=1e-9)
    same = np.isclose(printed, np.sum(impulse(g, n, smoothed) ** 2), rtol=1e-9)
    assert bool(same) is holds
    assert value(s, key) is holds
    # v0.4.0: the reading 'predicted instead of smoothed' explains the rows that do not
    # hold as printed (chance 2 rtol / 0.9 per gain set, the claim's bound)
    assert comparison.loc[key, "verdict"] == ("match" if holds else "explained")
    if not holds:
        assert "one-step" in comparison.loc[key, "note"]
        assert comparison.loc[key, "reading"] == "convention:predicted instead of smoothed estimate"


@claim_test(DOC, "eq.22_24")
def test_standard_gains_put_three_poles_at_theta(s):
    for alpha in (0.1, 0.3, 0.488):
        g = std_typed(alpha)
        a, b, c = (float(v) for v in g)
        # the closed-loop matrix (I - K H) Phi of eqs 1-6, written out
        Phi = np.array([[1.0, 1.0, 0.5], [0.0, 1.0, 1.0], [0.0, 0.0, 1.0]])
        F = (np.eye(3) - np.outer([a, b, c], [1, 0, 0])) @ Phi
        np.testing.assert_allclose(np.linalg.eigvals(F), (1 - alpha) ** (1 / 3), atol=2e-5)
        # a triple root is ill-conditioned (error ~ eps^(1/3)); the polynomial is exact
        np.testing.assert_allclose(np.poly(F), np.poly([(1 - alpha) ** (1 / 3)] * 3), atol=1e-14)
    assert value(s, "eq.22_24") is True


@claim_test(DOC, "eq.33_35")
def test_z_transformed_equations_hold_for_the_typed_responses(s):
    g = EQ_GAINS[1]
    a, b, c = (float(v) for v in g)
    w = np.linspace(0.1, 3.0, 7)
    Z = np.exp(1j * w)
    X, V, Acc = (H(g, o, w) for o in ("x_smooth", "v_smooth", "a_smooth"))
    np.testing.assert_allclose((Z + a - 1) * X + (a - 1) * V + (a - 1) / 2 * Acc, a * Z, atol=1e-13)
    np.testing.assert_allclose(b * X + (Z + b - 1) * V + (b / 2 - 1) * Acc, b * Z, atol=1e-13)
    np.testing.assert_allclose(c * X + c * V + (Z + c / 2 - 1) * Acc, c * Z, atol=1e-13)
    assert value(s, "eq.33_35") is True


@pytest.mark.parametrize(
    ("key", "out"),
    [
        pytest.param(f"eq.{n}", o, marks=claim_test(DOC, f"eq.{n}"))
        for n, o in zip(
            (36, 37, 38, 39), ("x_smooth", "v_smooth", "a_smooth", "x_pred"), strict=True
        )
    ],
)
def test_transfer_functions_are_the_dft_of_the_impulse_response(s, key, out):
    g = EQ_GAINS[0]
    n = 2048
    h = impulse(g, n, out)
    w = 2 * np.pi * np.arange(n // 2 + 1) / n
    np.testing.assert_allclose(np.fft.rfft(h), H(g, out, w), atol=1e-12)
    assert value(s, key) is True


@pytest.mark.parametrize(
    ("key", "order"),
    [
        pytest.param("eq.40", 3, marks=claim_test(DOC, "eq.40")),
        pytest.param("eq.41", 2, marks=claim_test(DOC, "eq.41")),
    ],
)
def test_characteristic_polynomials_give_the_poles(s, key, order):
    g = std_typed(0.3, order)
    a, b, c = (float(v) for v in g)
    if order == 3:
        W, Z = np.poly1d([1.0, -1.0]), np.poly1d([1.0, 0.0])
        delta = W**3 + a * W**2 + (b + c / 2) * Z * W + c * Z  # eq 40
    else:
        delta = np.poly1d([1.0, a + b - 2.0, 1.0 - a])  # eq 41
    # poles of the simulated tracker: the impulse response decays like the largest root
    h = impulse(g, 400)
    rate = np.exp(np.polyfit(np.arange(200, 400), np.log(np.abs(h[200:400]) + 1e-300), 1)[0])
    assert rate == pytest.approx(max(abs(np.roots(delta.coeffs))), rel=1e-2)
    assert value(s, key) is True


@claim_test(DOC, "eq.50")
def test_eq50_value_at_pi(s):
    for g in EQ_GAINS + [std_typed(0.3, 2)]:
        a, b = float(g.alpha), float(g.beta)
        assert abs(H(g, "x_smooth", np.pi)) == pytest.approx(
            (2 * a - b) / (4 - 2 * a - b), rel=1e-13
        )
    assert value(s, "eq.50") is True


# ---------------------------------------------------------------- stability (eqs 41-49)
def random_gains(n=3000, seed=7):
    rng = np.random.default_rng(seed)  # a seed of its own: an independent sample
    return rng.uniform(0, 2.2, n), rng.uniform(-0.2, 4.2, n), rng.uniform(-0.2, 4.2, n)


def stable_by_roots(a, b, c):
    out = []
    for ai, bi, ci in zip(a, b, c, strict=True):
        if ci == 0:
            coeffs = [1.0, ai + bi - 2.0, 1.0 - ai]
        else:
            coeffs = [1.0, ai + bi + ci / 2 - 3.0, 3.0 - 2 * ai - bi + ci / 2, ai - 1.0]
        out.append(np.max(np.abs(np.roots(coeffs))) < 1)
    return np.array(out)


@pytest.fixture(scope="module")
def sample():
    a, b, c = random_gains()
    return a, b, c, stable_by_roots(a, b, c), stable_by_roots(a, b, np.zeros_like(c))


@claim_test(DOC, "claim.jury_exact")
def test_eqs45_48_exact(s, sample):
    a, b, c, st3, _ = sample
    crit = (a > 0) & (a < 2) & (2 * a + b < 4) & (a * b + a * c / 2 - c > 0) & (c > 0)
    assert np.array_equal(crit, st3)
    assert value(s, "claim.jury_exact") is True


@claim_test(DOC, "claim.eqs42_44_exact")
def test_eqs42_44_exact(s, sample):
    a, b, _, _, st2 = sample
    assert np.array_equal((a > 0) & (b > 0) & (2 * a + b < 4), st2)
    assert value(s, "claim.eqs42_44_exact") is True


@claim_test(DOC, "claim.eq49_sufficient")
def test_eq49_sufficient(s, sample):
    a, b, c, st3, _ = sample
    crit = (a > 0) & (a < 2) & (2 * a + b < 4) & (a * b > c) & (c > 0)
    assert not np.any(crit & ~st3)
    assert value(s, "claim.eq49_sufficient") is True


@claim_test(DOC, "claim.eq49_not_necessary")
def test_eq49_not_necessary(s):
    # a pinned counterexample: α = 1, β = 0.5, γ = 0.6 > αβ, yet eqs 45-48 hold (1·0.5 + 0.3 - 0.6
    # = 0.2 > 0), so it is stable
    assert stable_by_roots([1.0], [0.5], [0.6])[0]
    assert value(s, "claim.eq49_not_necessary") is True


@claim_test(DOC, "claim.eqs42_44_imply_45")
def test_eqs42_44_imply_45(s, sample):
    a, b, _, _, _ = sample
    prem = (a > 0) & (b > 0) & (2 * a + b < 4)
    assert np.all(a[prem] < 2)  # 2α < 4 - β < 4
    assert value(s, "claim.eqs42_44_imply_45") is True


@claim_test(DOC, "claim.eqs45_47_48_imply_43")
def test_eqs45_47_48_imply_43(s, sample):
    a, b, c, _, _ = sample
    prem = (a > 0) & (a < 2) & (a * b + a * c / 2 - c > 0) & (c > 0)
    assert np.all(b[prem] > 0)  # αβ > γ(1 - α/2) > 0
    assert value(s, "claim.eqs45_47_48_imply_43") is True


@claim_test(DOC, "claim.gamma0_reduces_stability")
def test_gamma0_reduces_stability(s, sample):
    a, b, _, _, st2 = sample
    assert np.array_equal((a > 0) & (a < 2) & (2 * a + b < 4) & (a * b > 0), st2)
    assert value(s, "claim.gamma0_reduces_stability") is True
    assert "left out" in CLAIMS.compute(s, "claim.gamma0_reduces_stability").note


# ---------------------------------------------------------------- frequency-domain statements
@claim_test(DOC, "claim.eq50_min_at_pi")
def test_min_at_pi(s):
    w = np.linspace(0.01, np.pi, 5000)
    for alpha in (0.1, 0.3, 0.488, 0.8):
        assert np.argmin(np.abs(H(std_typed(alpha), "x_smooth", w))) == w.size - 1
    assert value(s, "claim.eq50_min_at_pi") is True


@claim_test(DOC, "claim.eq50_gamma_free")
def test_eq50_gamma_free(s):
    vals = [abs(H(Gains(0.3, 0.04, c), "x_smooth", np.pi)) for c in (0.0, 0.001, 0.003)]
    assert np.ptp(vals) < 1e-15
    assert value(s, "claim.eq50_gamma_free") is True


@claim_test(DOC, "claim.eq51_exact")
def test_eq51(s):
    for alpha in (0.1, 0.3, 0.488):
        g = std_typed(alpha)
        w = np.arccos(1 - float(g.beta))
        assert abs(H(g, "x_smooth", w)) == pytest.approx(1.0, abs=1e-13)
    assert value(s, "claim.eq51_exact") is True


@claim_test(DOC, "claim.fig3_phase_monotone")
def test_phase_of_prediction_first_rises(s, comparison):
    w = np.linspace(1e-3, 0.2, 2000)
    ph = np.degrees(np.unwrap(np.angle(H(std_typed(0.3), "x_pred", w))))
    assert ph.max() == pytest.approx(1.378, abs=2e-3)  # +1.3777° at ωT ≈ 0.048 (v0.2.0 note)
    assert value(s, "claim.fig3_phase_monotone") is False
    assert comparison.loc["claim.fig3_phase_monotone", "verdict"] == "mismatch"


@claim_test(DOC, "claim.fig3_magnitude_similar")
def test_fig3_magnitudes(s, comparison):
    g = std_typed(0.3)
    w = np.geomspace(0.01, np.pi, 4001)
    gap = np.max(np.abs(db(g, "x_pred", w) - db(g, "x_smooth", w)))
    assert s.fig3_gap[0] == pytest.approx(gap, abs=1e-9)  # the gap is largest at ωT = π
    assert gap == pytest.approx(1.0315, abs=1e-3)
    for th, holds in ((0.5, False), (1.0, False), (2.0, True), (3.0, True)):
        assert (
            value(variant(s, "steelman1978.judging.similar_db", th), "claim.fig3_magnitude_similar")
            is holds
        )
    row = comparison.loc["claim.fig3_magnitude_similar"]
    assert (row["verdict"], row["robust"]) == ("not_reproducible", "false")


@claim_test(DOC, "claim.fig4_similar_above_0.2")
def test_fig4_magnitudes(s, comparison):
    g = std_typed(0.3)
    w = s.wt_log[s.wt_log > 0.2]
    gap = np.max(np.abs(db(g, "a_smooth", w, 200) - db(g, "x_smooth", w)))
    assert s.fig4_gap[0] == pytest.approx(gap, abs=1e-9)
    assert 0.5 < gap < 1.0  # 0.61 dB just above ωT = 0.2 on a fine grid
    for th, holds in ((0.5, False), (1.0, True), (3.0, True)):
        assert (
            value(variant(s, "steelman1978.judging.similar_db", th), "claim.fig4_similar_above_0.2")
            is holds
        )
    row = comparison.loc["claim.fig4_similar_above_0.2"]
    assert (row["verdict"], row["robust"]) == ("not_reproducible", "false")
    assert "mismatch at 0.5, match at 1-3" in row["note"]


@claim_test(DOC, "claim.log_straight_line")
def test_straight_line(s):
    g = std_typed(0.1)
    w1 = np.arccos(1 - float(g.beta))  # eq 51
    w = np.geomspace(w1, np.pi, 2001)
    m = db(g, "x_smooth", w)
    chord = m[0] + (m[-1] - m[0]) * np.log(w / w1) / np.log(np.pi / w1)
    assert s.straight_line[0.1] == pytest.approx(np.max(np.abs(m - chord)), abs=5e-3)
    assert 1.5 < s.straight_line[0.1] < 2.0  # 1.92 dB below the chord at α = .1
    assert value(s, "claim.log_straight_line") is False  # nominal 1 dB
    assert value(variant(s, "steelman1978.judging.similar_db", 2.0), "claim.log_straight_line")


APPROX = {
    # key: the column of the study's approximations table
    "claim.eq52_good": "eq52_rel_err",
    "claim.eq53_reasonable": "eq53_rel_err",
    "claim.max_near_midpoint": "midpoint_rel_err",
}


@pytest.mark.parametrize("key", [pytest.param(k, marks=claim_test(DOC, k)) for k in APPROX])
def test_approximation_claims(s, key, comparison):
    errs = []
    for alpha in (0.1, 0.3, 0.488):
        g = std_typed(alpha)
        be = float(g.beta)
        w1 = np.arccos(1 - be)
        if key == "claim.eq52_good":
            errs.append(abs(np.sqrt(2 * be) / w1 - 1))
        elif key == "claim.eq53_reasonable":
            w53 = np.sqrt(2 * be) * 10 ** (
                -0.15 * np.log(np.pi / np.sqrt(2 * be)) / np.log(alpha / 2)
            )
            errs.append(abs(w53 / crossing(g, -3.0) - 1))
        else:
            errs.append(abs(2 * peak(g)[0] / w1 - 1))
    np.testing.assert_allclose(s.approximations[APPROX[key]], errs, rtol=0, atol=1e-6)
    worst = max(errs)
    assert value(s, key) is bool(worst <= 0.05)
    row = comparison.loc[key]
    if key == "claim.eq52_good":
        assert worst < 0.01 and (row["verdict"], row["robust"]) == ("match", "true")
    else:
        assert 0.02 < worst < 0.1 and (row["verdict"], row["robust"]) == (
            "not_reproducible",
            "false",
        )


@claim_test(DOC, "claim.cubic_0707")
def test_0707_is_a_cubic(s):
    from abglib.analysis._features import _mag2_polys, _rounded

    for alpha in (0.1, 0.3, 0.488):
        # |X̄/X|² = P(q)/Q(q), q = 2 - 2cos ωT (exact coefficients, rounded once)
        P, Q = (_rounded(p) for p in _mag2_polys(std_typed(alpha), "x_smooth"))
        assert (P - 0.5 * Q).degree() == 3
        deg, root, exact = s.cubic[alpha]
        # the fitted root holds to ~2e-9 relative at alpha = 0.1 (|N|^2 - |D|^2/2 cancels
        # near DC; 2.2e-9 on this CPU, within 1e-9 on the one v0.3.1 was tested on, ~2e-9
        # under ABGLIB_PERTURB),
        # ~1e-12 at 0.3 and ~1e-13 at 0.488: rel 1e-7 leaves a margin of 50
        assert deg == 3 and root == pytest.approx(
            crossing(std_typed(alpha), 20 * np.log10(0.5**0.5)), rel=1e-7
        )
    assert value(s, "claim.cubic_0707") is True


@claim_test(DOC, "claim.cubic_0707")
def test_0707_notes_name_their_targets(s, comparison):
    # the cubic's row solves |X̄/X| = 1/√2, the abstract's row the printed 0.707 (a larger
    # ωT): v0.4.5 gave 0.437137 and 0.4372 at alpha = 0.3 without saying the targets differ
    cubic = comparison.loc["claim.cubic_0707", "note"]
    abstract = comparison.loc["claim.abstract_0707", "note"]
    assert "the target is |X̄/X| = 1/√2 exactly, the half-power point the text's 0.707" in cubic
    assert "(the abstract's row takes 0.707 as printed: a slightly larger ωT)" in cubic
    assert "|X̄/X| = 0.707, the abstract's level as printed" in abstract
    assert "not 1/√2, whose slightly smaller ωT is the cubic's row" in abstract
    t = s.abstract_0707.set_index("alpha")
    for alpha, (_, root, exact) in s.cubic.items():
        assert exact < t.loc[alpha, "wT_0707"]
        # the digits written (6 decimals of the fitted root, 4 of Brent's) hold with a
        # margin: the fit's error (< 3e-9 relative, test above) is far below the distance
        # to the next rounding boundary
        for w, n in ((root, 6), (t.loc[alpha, "wT_0707"], 4)):
            assert abs((w * 10**n) % 1 - 0.5) > 0.01
        assert f"root ωT = {root:.6f} (exact {exact:.6f})" in cubic
        assert f"vs {t.loc[alpha, 'wT_0707']:.4f}" in abstract


@claim_test(DOC, "claim.overshoot_decreasing_alpha")
def test_overshoot_decreases_with_alpha(s):
    overs = [peak(std_typed(a))[1] for a in (0.1, 0.3, 0.488)]
    assert overs == sorted(overs, reverse=True)
    assert value(s, "claim.overshoot_decreasing_alpha") is True


@claim_test(DOC, "claim.decrease_alpha_attenuation")
def test_smaller_alpha_attenuates_more(s):
    att = [-db(std_typed(a), "x_smooth", 1.609) for a in (0.1, 0.3, 0.488)]
    assert att == sorted(att, reverse=True) and att[0] == pytest.approx(22.9, abs=0.1)
    assert value(s, "claim.decrease_alpha_attenuation") is True


@claim_test(DOC, "claim.overshoot_increasing_gamma")
def test_overshoot_grows_with_gamma(s):
    g = std_typed(0.3)
    a, b = float(g.alpha), float(g.beta)
    overs = [peak(Gains(a, b, f * a * b / 2))[1] for f in (0.0, 0.5, 0.9)]
    assert overs == sorted(overs)
    assert value(s, "claim.overshoot_increasing_gamma") is True


# ---------------------------------------------------------------- definitions and conclusions
@pytest.mark.parametrize(
    ("key", "order"),
    [
        pytest.param(
            "claim.std_abg_fading_memory", 3, marks=claim_test(DOC, "claim.std_abg_fading_memory")
        ),
        pytest.param(
            "claim.std_ab_fading_memory", 2, marks=claim_test(DOC, "claim.std_ab_fading_memory")
        ),
    ],
)
def test_standard_gains_are_discounted_least_squares(s, key, order):
    # the fit by brute force: minimize sum θ^k (z[n-k] - p(-k))² with lstsq on weighted rows
    alpha, n = 0.3, 400
    theta = (1 - alpha) ** (1 / order)
    rng = np.random.default_rng(3)
    z = rng.normal(size=n)
    k = np.arange(n)
    V = np.vander(-k.astype(float), order, increasing=True) * np.sqrt(theta**k)[:, None]
    coef = np.linalg.lstsq(V, z[::-1] * np.sqrt(theta**k), rcond=None)[0]
    r = abglib.track(z, std_typed(alpha, order))
    assert r.x_smooth[-1] == pytest.approx(coef[0], abs=1e-9)
    assert r.v_smooth[-1] == pytest.approx(coef[1], abs=1e-9)
    np.testing.assert_allclose(
        fading_memory_weights(theta, order - 1, n) @ z[::-1], coef, atol=1e-9
    )
    assert value(s, key) is True


@claim_test(DOC, "claim.simpson_reduces_to_bb")
def test_simpson_reduces_to_benedict_bordner(s):
    g = std_typed(0.3, 2)
    a, b = float(g.alpha), float(g.beta)
    near = Gains(a, b, 1e-10)
    bb = (2 * a**2 + 2 * b - 3 * a * b) / (a * (4 - 2 * a - b))  # Benedict-Bordner k_x
    assert simpson_typed(near)["x_smooth"] == pytest.approx(bb, rel=1e-7)
    assert bb == pytest.approx(np.sum(impulse(g, 2000) ** 2), rel=1e-10)
    assert value(s, "claim.simpson_reduces_to_bb") is True


@claim_test(DOC, "claim.eq21_minimizes")
def test_eq21_not_reproducible(s, comparison):
    res = CLAIMS.compute(s, "claim.eq21_minimizes")
    assert res.value is None and "Simpson 1963" in res.note
    g = std_typed(0.3)
    a, b, c = (float(v) for v in g)
    assert 2 * b - a * (a + b + c / 2) == pytest.approx(-0.0297, abs=1e-4)  # not eq 21's zero
    assert comparison.loc["claim.eq21_minimizes", "verdict"] == "not_reproducible"


@claim_test(DOC, "claim.qd_least_squares")
def test_qd_least_squares_not_reproducible(s, comparison):
    res = CLAIMS.compute(s, "claim.qd_least_squares")
    assert res.value is None and "not stated" in res.note
    assert f"{qd_alpha(21.0):.5f}" in res.note  # eq 28 at m = 21: 0.24582
    assert comparison.loc["claim.qd_least_squares", "verdict"] == "not_reproducible"


@claim_test(DOC, "claim.summary_useful")
def test_summary_not_reproducible(s, comparison):
    res = CLAIMS.compute(s, "claim.summary_useful")
    assert res.value is None and "17.4%" in res.note  # eq 55 at α = .488: .2259 vs .1925
    assert comparison.loc["claim.summary_useful", "verdict"] == "not_reproducible"


# ---------------------------------------------------------------- wiring
def test_every_key_is_judged_and_notes_cite_report_sections(comparison):
    assert list(comparison.index) == list(published(DOC)["key"])
    notebook = (ROOT / "workflow" / "notebooks" / f"{DOC}.py").read_text(encoding="utf-8")
    cited = set()
    for note in comparison["note"]:
        cited |= set(re.findall(r"see (?:report section )?'([^']+)'", note))
        cited |= set(re.findall(r" and '([^']+)'", note))
    assert cited
    for section in cited:
        assert f"## {section}" in notebook, section
    hinges = comparison[comparison["note"].str.contains("hinges on")]
    assert (hinges["depends_on"] != "").all()


def test_response_table_scales_and_labels():
    fig = {
        "axes": "bode",
        "curves": [{"design": "standard_abg", "alpha": 0.3, "output": "a_smooth", "scale": 200}],
    }
    grids = {
        "log": {"start": 0.1, "stop_over_pi": 1.0, "n": 5},
        "linear": {"start": 0, "stop_over_pi": 1, "n": 3},
    }
    t = response_table(fig, grids)
    np.testing.assert_allclose(
        t["magnitude"], 200 * np.abs(H(std_typed(0.3), "a_smooth", t["wT"])), rtol=1e-12
    )
    assert t["curve"].iloc[0].startswith("200·")


def test_no_test_loads_a_steelman_script():
    for p in (ROOT / "tests").rglob("*.py"):
        text = p.read_text(encoding="utf-8")
        if p.name != Path(__file__).name:
            assert "steelman_reproduce" not in text and "steelman_equations" not in text


# ---------------------------------------------------------------- abstract (added in v0.4.0)
@claim_test(DOC, "claim.abstract_0707")
def test_abstract_0707(s, comparison):
    # independent route: bisection on the typed eqs 36, 40 at 20 log10(0.707) dB (the
    # abstract's level) and eq 53 typed from the text (exponent -.15)
    errs = []
    for alpha in (0.1, 0.3, 0.488):
        g = std_typed(alpha)
        be = float(g.beta)
        w = crossing(g, 20 * np.log10(0.707))
        assert abs(H(g, "x_smooth", w)) == pytest.approx(0.707, abs=1e-10)
        w53 = np.sqrt(2 * be) * 10 ** (-0.15 * np.log(np.pi / np.sqrt(2 * be)) / np.log(alpha / 2))
        errs.append(abs(w53 / w - 1))
    t = s.abstract_0707
    np.testing.assert_allclose(t["rel_err"], errs, rtol=0, atol=1e-9)
    # eq 53 undershoots by 4-7 %: inside the lenient reading (10 %), outside the strict ones
    assert 0.04 < min(errs) and max(errs) < 0.07
    assert value(s, "claim.abstract_0707") is bool(max(errs) <= 0.05)
    assert value(variant(s, "steelman1978.judging.approx_rtol", 0.1), "claim.abstract_0707")
    row = comparison.loc["claim.abstract_0707"]
    assert (row["verdict"], row["robust"]) == ("not_reproducible", "false")
    assert "0.01-0.05" in row["note"] and "match at 0.1" in row["note"]
    # judged like the eq 53 row of the body (same equation, same reading of the vague word)
    assert row["verdict"] == comparison.loc["claim.eq53_reasonable", "verdict"]
