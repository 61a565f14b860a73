"""Stability: exact test vs numeric poles; the printed criteria of seeds 000, 001, 002 vs truth.

Truth = modulus of the eigenvalues of the closed-loop matrix F = (I - K H) Phi built from
eqs 1-6 (abglib.analysis._statespace), an independent route from the coefficient algebra.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from abglib import Gains
from abglib.analysis._stability import (
    characteristic_polynomial,
    is_stable,
    pole_radius,
    poles,
    stable_jury_steelman,
    stable_sufficient_eq49,
)
from abglib.analysis._statespace import state_space

# a box around the stability region of seed 000, eqs 45-48 (alpha < 2, beta < 4 - 2 alpha,
# gamma < alpha beta / (1 - alpha / 2) <= 4 when beta < 4 - 2 alpha), with margin on every side
box_a = st.floats(-0.5, 2.5)
box_b = st.floats(-0.5, 4.5)
box_g = st.floats(-0.5, 4.5)
# distance from the unit circle below which floating-point poles cannot decide (eigenvalues
# of a 3x3 companion matrix are accurate to ~1e-15; a double root near the circle to ~1e-8)
MARGIN = 1e-6


def truth(gains):
    """Spectral radius of F (2-state model when gamma == 0, see _statespace docstring)."""
    return max(abs(np.linalg.eigvals(state_space(gains).F)))


@settings(max_examples=300, deadline=None)
@given(box_a, box_b, box_g)
def test_is_stable_and_steelman_jury_agree_with_eigenvalues(a, b, g):
    gains = Gains(a, b, g)
    r = truth(gains)
    assume(abs(r - 1) > MARGIN)
    assert is_stable(gains) == (r < 1)
    # seed 000: eqs 45-48 are necessary and sufficient, as the paper says (no counterexample)
    assert stable_jury_steelman(gains) == (r < 1)


@settings(max_examples=200, deadline=None)
@given(box_a, box_b)
def test_alpha_beta_criteria_agree_with_eigenvalues(a, b):
    gains = Gains(a, b)
    r = truth(gains)
    assume(abs(r - 1) > MARGIN)
    assert is_stable(gains) == (r < 1)
    assert stable_jury_steelman(gains) == (r < 1)  # eqs 42-44
    assert pole_radius(gains) == pytest.approx(r, abs=1e-7)


@settings(max_examples=100, deadline=None)
@given(box_a, box_b, box_g)
def test_poles_equal_eigenvalues_of_F(a, b, g):
    gains = Gains(a, b, g)
    p = poles(gains)
    eig = np.linalg.eigvals(state_space(gains).F)
    assert p.shape == ((2,) if g == 0 else (3,))
    # compare as multisets of complex numbers: each pole against its nearest unmatched
    # eigenvalue (sorting by real part splits roots whose real parts tie to round-off, e.g.
    # a = 0, b = g = 1: 0.5 and 0.5 +- 1.32j); a triple root is only accurate to ~eps^(1/3)
    left = list(eig)
    matched = [left.pop(int(np.argmin(np.abs(np.array(left) - z)))) for z in p]
    np.testing.assert_allclose(p, matched, atol=1e-4)
    np.testing.assert_allclose(np.poly(p).real, np.poly(eig).real, atol=1e-10)


@pytest.mark.parametrize("theta", [0.1, 0.5, 0.8, 0.95])  # arbitrary points of (0, 1)
def test_standard_tracker_has_triple_pole_at_theta(theta):
    # fading-memory (critically damped) gains, seed 000 eqs 22-24: det(zI - F) = (z - theta)^3
    gains = Gains(1 - theta**3, 1.5 * (1 - theta) ** 2 * (1 + theta), (1 - theta) ** 3)
    np.testing.assert_allclose(characteristic_polynomial(gains), np.poly([theta] * 3), atol=1e-14)
    assert pole_radius(gains) == pytest.approx(theta, abs=1e-4)  # triple root: ~eps^(1/3)
    assert is_stable(gains)


@pytest.mark.parametrize(
    ("gains", "why"),
    [
        (Gains(0.5, 0.0), "beta = 0: pole at z = 1 (eq 43 boundary)"),
        (Gains(2.0, 0.0 + 1e-3), "alpha = 2 ... but 2 alpha + beta > 4"),
        (Gains(1.5, 1.0), "2 alpha + beta = 4: pole at z = -1 (eq 44 boundary)"),
        (Gains(0.0, 0.1), "alpha = 0: pole at |z| = 1 (1 - alpha = 1)"),
        (Gains(1.0, 0.5, 1.0), "alpha beta + alpha gamma/2 - gamma = 0 (eq 47 boundary)"),
        (Gains(0.5, 0.2, 0.0 - 1e-12), "gamma < 0 (eq 48): real pole > 1"),
    ],
)
def test_boundary_and_outside_are_unstable(gains, why):
    # the exact test classifies gains ON the boundary (a pole on the unit circle) as unstable
    assert not is_stable(gains), why
    assert not stable_jury_steelman(gains), why
    assert pole_radius(gains) >= 1 - 1e-12, why


def test_eq47_boundary_pole_is_on_the_circle():
    # (1, 0.5, 1): alpha beta + alpha gamma / 2 - gamma = 0.5 + 0.5 - 1 = 0 -> |z| = 1 exactly
    assert pole_radius(Gains(1.0, 0.5, 1.0)) == pytest.approx(1.0, abs=1e-12)


@settings(max_examples=200, deadline=None)
@given(box_a, box_b, box_g)
def test_eq49_is_sufficient(a, b, g):
    gains = Gains(a, b, g)
    if stable_sufficient_eq49(gains):
        assert is_stable(gains)
        # tiny beta, gamma put a double pole near z = 1, where eigenvalues are only accurate
        # to ~sqrt(eps) = 1.5e-8; they cannot decide there, so only a loose check
        assert truth(gains) < 1 + 1e-7


def test_eq49_is_not_necessary():
    # (1, 0.5, 0.6): alpha beta = 0.5 < gamma (eq 49 fails) but eq 47: 0.5 + 0.3 - 0.6 > 0
    gains = Gains(1.0, 0.5, 0.6)
    assert not stable_sufficient_eq49(gains)
    assert is_stable(gains) and truth(gains) < 1


@settings(max_examples=200, deadline=None)
@given(box_a, box_b, box_g)
def test_steelman_remarks_after_eq48(a, b, g):
    # "(42), (43), (44) imply (45)" and "(45), (47), (48) imply beta > 0 (43)"
    if a > 0 and b > 0 and 2 * a + b < 4:
        assert 0 < a < 2
    if 0 < a < 2 and a * b + a * g / 2 - g > 0 and g > 0:
        assert b > 0


def test_bank_shapes():
    # Table 1 of seed 000: standard alpha-beta-gamma, standard alpha-beta, QD columns
    bank = Gains(np.array([0.3, 0.3, 0.3]), np.array([0.0356, 0.0267, 0.0362]),
                 np.array([0.0014, 0.0, 0.00219]))  # fmt: skip
    p = poles(bank)
    assert p.shape == (3, 3) and np.isnan(p[1, 2])  # alpha-beta row: two poles (eq 41)
    np.testing.assert_allclose(pole_radius(bank), [truth(bank[i]) for i in range(3)], atol=1e-7)
    np.testing.assert_array_equal(is_stable(bank), [True, True, True])
    np.testing.assert_array_equal(stable_jury_steelman(bank), [True, True, True])
    np.testing.assert_array_equal(stable_sufficient_eq49(bank), [True, False, True])
    assert isinstance(is_stable(bank[0]), bool) and isinstance(pole_radius(bank[0]), float)


@pytest.mark.parametrize(
    ("call", "match"),
    [
        (lambda: is_stable([0.3, 0.03]), "gains must be an abglib.Gains, got list"),
        (lambda: poles("x"), "gains must be an abglib.Gains, got str"),
    ],
)
def test_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()
