"""Gain sets and hypothesis strategies shared by the analysis tests.

Written from the printed equations, independently of :mod:`abglib.design` and of the
library's stability code, so that the tests do not check the library against itself.
"""

from __future__ import annotations

import numpy as np
from hypothesis import strategies as st

from abglib import Gains


def standard_abg(theta):
    """Critically damped alpha-beta-gamma gains (seed 000, eqs 22-24)."""
    return Gains(1 - theta**3, 1.5 * (1 - theta) ** 2 * (1 + theta), (1 - theta) ** 3)


def standard_ab(theta):
    """Critically damped alpha-beta gains (seed 000, the pair after eq 30)."""
    return Gains(1 - theta**2, (1 - theta) ** 2)


def gains_from_poles(p):
    """Gains whose characteristic polynomial (seed 000, eq 40) has the roots ``p``.

    eq 40 expands to z^3 + (a + b + g/2 - 3) z^2 + (3 - 2a - b + g/2) z - (1 - a); for two
    roots (alpha-beta, eq 41): z^2 + (a + b - 2) z + (1 - a). Any roots inside the unit
    circle give stable gains, independently of the library's stability code.
    """
    c = np.real(np.poly(p))
    if len(p) == 2:
        alpha = 1.0 - c[2]
        return Gains(alpha, c[1] + 2.0 - alpha)
    alpha = 1.0 + c[3]
    gamma = c[2] + c[1] + alpha
    return Gains(alpha, c[1] + 3.0 - alpha - gamma / 2.0, gamma)


def stable_gain_strategies(max_radius: float, gamma_floor: float):
    """``(stable_ab, stable_abg)``: gains with all poles within ``max_radius``.

    ``gamma_floor`` keeps alpha-beta-gamma sets away from gamma = 0 (a pole at z = 1).
    """
    radius = st.floats(0.0, max_radius)
    angle = st.floats(0.05, np.pi - 0.05)
    real_pole = st.floats(-max_radius, max_radius)
    pole_pair = st.tuples(radius, angle).map(
        lambda ra: [ra[0] * np.exp(1j * ra[1]), ra[0] * np.exp(-1j * ra[1])]
    )
    two_real = st.tuples(real_pole, real_pole).map(list)
    stable_ab = st.one_of(pole_pair, two_real).map(gains_from_poles)
    stable_abg = (
        st.tuples(st.one_of(pole_pair, two_real), real_pole)
        .map(lambda t: gains_from_poles(t[0] + [t[1]]))
        .filter(lambda g: g.gamma > gamma_floor)
    )
    return stable_ab, stable_abg
