"""Tests of abglib.conventions: Huang (seed 002) and FilterPy conventions vs canonical."""

from __future__ import annotations

import numpy as np
import pytest
from filterpy.gh import GHFilter, GHKFilter
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.polynomial import Polynomial as P

from abglib import Gains, track
from abglib.conventions import from_filterpy, from_huang, to_filterpy, to_huang

# values near the subnormal range excluded: there x / 2 loses bits (a float limit, not a
# convention issue); everywhere else x / 2 * 2 == x exactly
finite = st.floats(-1e6, 1e6, allow_nan=False, allow_infinity=False).filter(
    lambda x: x == 0.0 or abs(x) > 1e-300
)

# a stable alpha-beta-gamma set (seed 000, eqs 45-48 hold: 0.1 + 0.005 - 0.02 > 0), and a
# stable alpha-beta set, chosen by hand for the behavioural tests
ABG = Gains(0.5, 0.2, 0.02)
AB = Gains(0.4, 0.1)


# --------------------------------------------------------------------------- round trips
@settings(max_examples=200, deadline=None)
@given(finite, finite, finite)
def test_huang_round_trip(a, b, g):
    assert to_huang(from_huang(a, b, g)) == (a, b, g)
    assert from_huang(*to_huang(Gains(a, b, g))) == Gains(a, b, g)


@settings(max_examples=200, deadline=None)
@given(finite, finite, finite)
def test_filterpy_round_trip(a, b, g):
    assert to_filterpy(from_filterpy(a, b, g)) == (a, b, g)
    assert from_filterpy(*to_filterpy(Gains(a, b, g))) == Gains(a, b, g)


def test_converters_broadcast_arrays():
    g = Gains(np.array([0.3, 0.5]), 0.1, np.array([0.02, 0.04]))
    _, _, gh = to_huang(g)
    np.testing.assert_array_equal(gh, [0.01, 0.02])
    assert from_huang(*to_huang(g)) == g
    assert from_huang(0.5, 0.2) == Gains(0.5, 0.2, 0.0)  # default gamma_h = 0
    assert from_filterpy(0.5, 0.2) == Gains(0.5, 0.2, 0.0)  # GHFilter: no k


# --------------------------------------------------------------------------- the proof
def _steelman_eq40(alpha, beta, gamma):
    """Seed 000, eq 40 expanded with numpy polynomial algebra (ascending powers)."""
    z = P([0.0, 1.0])
    zm1 = P([-1.0, 1.0])
    return zm1**3 + alpha * zm1**2 + (beta + gamma / 2) * z * zm1 + gamma * z


def _huang_eq4(alpha, beta, gamma_h):
    """Seed 002, eq 4 as printed (ascending powers)."""
    return P([-(1 - alpha), 3 - beta - 2 * alpha + gamma_h, -3 + alpha + beta + gamma_h, 1.0])


def _steelman_eq39_num(alpha, beta, gamma):
    """Numerator of seed 000, eq 39 (x_pred / x)."""
    zm1 = P([-1.0, 1.0])
    return (alpha + beta + gamma / 2) * zm1**2 + (beta + 1.5 * gamma) * zm1 + gamma


def _huang_eq3_num(alpha, beta, gamma_h):
    """Numerator of seed 002, eq 3 (its trailing 'a' read as alpha)."""
    return P([alpha, -beta - 2 * alpha + gamma_h, alpha + beta + gamma_h])


def _coef(poly, n=4):
    """Ascending coefficients padded to length n (numpy trims trailing zeros)."""
    return np.pad(poly.coef, (0, n - len(poly.coef)))


def _affine_map(func):
    """(c0, A) with coeffs(func(p)) = c0 + A @ p; func is affine in p, so 4 points fix it."""
    c0 = _coef(func(0.0, 0.0, 0.0))
    cols = [_coef(func(*e)) - c0 for e in np.eye(3)]
    return c0, np.column_stack(cols)


@pytest.mark.parametrize(
    ("steelman", "huang"),
    [(_steelman_eq40, _huang_eq4), (_steelman_eq39_num, _huang_eq3_num)],
    ids=["characteristic eq40 vs eq4", "x_pred numerator eq39 vs eq3"],
)
def test_huang_gamma_is_half_canonical(steelman, huang):
    # Both polynomials are affine in their gains, so comparing the affine maps is a proof
    # for all gains: Steelman(a, b, g) == Huang(a, b, g_h) for all a, b, g exactly when
    # g_h = g / 2.
    c_s, A_s = _affine_map(steelman)
    c_h, A_h = _affine_map(huang)
    np.testing.assert_allclose(c_s, c_h, atol=1e-15)
    # the unique linear map M with A_s = A_h @ M (A_h has full column rank)
    assert np.linalg.matrix_rank(A_h) == 3
    M, *_ = np.linalg.lstsq(A_h, A_s, rcond=None)
    np.testing.assert_allclose(M, np.diag([1.0, 1.0, 0.5]), atol=1e-14)


def test_huang_polynomial_with_converter():
    rng = np.random.default_rng(20240601)  # seeded: arbitrary gains
    for a, b, g in rng.uniform(0.0, 1.0, size=(20, 3)):
        ah, bh, gh = to_huang(Gains(a, b, g))
        np.testing.assert_allclose(_steelman_eq40(a, b, g).coef, _huang_eq4(ah, bh, gh).coef)
        # the naive reading (gamma_H = gamma) does not give Steelman's polynomial
        assert not np.allclose(_steelman_eq40(a, b, g).coef, _huang_eq4(a, b, g).coef)


# --------------------------------------------------------------------------- behaviour
def _measurements(n=300, seed=7):
    rng = np.random.default_rng(seed)  # seeded: a manoeuvring target plus noise
    t = np.arange(n)
    return 5.0 + 0.3 * t + 0.002 * t**2 + rng.normal(0.0, 1.0, n)


@pytest.mark.parametrize("dt", [1.0, 0.25])
def test_ghkfilter_update_matches_track(dt):
    z = _measurements()
    g, h, k = to_filterpy(ABG)
    f = GHKFilter(x=0.0, dx=0.0, ddx=0.0, dt=dt, g=g, h=h, k=k)
    cols = np.array([(f.update(zi), (f.x_prediction, f.x, f.dx, f.ddx))[1] for zi in z]).T
    out = track(z, ABG, dt=dt, init="zero")
    for ours, theirs in zip(out, cols, strict=True):
        np.testing.assert_allclose(ours, theirs, rtol=1e-9, atol=1e-12 * np.abs(theirs).max())


def test_ghkfilter_naive_k_disagrees():
    # negative control: passing canonical gamma as FilterPy k doubles the acceleration gain
    z = _measurements()
    f = GHKFilter(x=0.0, dx=0.0, ddx=0.0, dt=1.0, g=ABG.alpha, h=ABG.beta, k=ABG.gamma)
    xs = [(f.update(zi), f.x)[1] for zi in z]
    assert not np.allclose(xs, track(z, ABG).x_smooth, rtol=1e-3)


@pytest.mark.parametrize("dt", [1.0, 2.0])
def test_ghfilter_batch_filter_matches_track(dt):
    z = _measurements(seed=11)
    g, h, k = to_filterpy(AB)
    assert k == 0.0
    f = GHFilter(x=0.0, dx=0.0, dt=dt, g=g, h=h)
    results, predictions = f.batch_filter(z, save_predictions=True)
    out = track(z, AB, dt=dt, init="zero")
    scale = np.abs(results).max()
    np.testing.assert_allclose(out.x_smooth, results[1:, 0], rtol=1e-9, atol=1e-12 * scale)
    np.testing.assert_allclose(out.v_smooth, results[1:, 1], rtol=1e-9, atol=1e-12 * scale)
    np.testing.assert_allclose(out.x_pred, predictions, rtol=1e-9, atol=1e-12 * scale)


# --------------------------------------------------------------------------- errors
def test_errors():
    with pytest.raises(ValueError, match=r"gains must be an abglib.Gains, got tuple"):
        to_huang((0.5, 0.2, 0.1))
    with pytest.raises(ValueError, match=r"gains must be an abglib.Gains, got list"):
        to_filterpy([0.5, 0.2])
    with pytest.raises(ValueError, match=r"gamma_h must be finite, got nan"):
        from_huang(0.5, 0.2, float("nan"))
    with pytest.raises(ValueError, match=r"k must be finite, got inf"):
        from_filterpy(0.5, 0.2, float("inf"))
