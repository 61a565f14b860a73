"""Seed 004: the reconstructed antenna model and its zero-order-hold discretisation."""

import numpy as np
import pytest
import scipy.linalg
import scipy.signal
from hypothesis import given, settings
from hypothesis import strategies as st

from abglib._checks import AbglibValueError
from abglib.replications.antenna import AntennaParams, continuous_model, discrete_plant, zoh

from .antenna_common import NOMINAL_VALUES

# the reconstruction of config.yaml (antenna.parameters)
NOMINAL = NOMINAL_VALUES


@pytest.mark.parametrize(
    ("name", "value", "match"),
    [
        ("p_a", 1.0, r"p_a must satisfy 0 < p_a < 1 \(p_d = 1 - p_a\), got 1.0"),
        ("p_a", 0.0, r"p_a must satisfy 0 < p_a < 1"),
        ("p_f", -1.0, r"p_f must be > 0, got -1.0"),
        ("kappa", 0.0, r"kappa must be > 0, got 0.0"),
        ("beta_d", -0.1, r"beta_d must be >= 0, got -0.1"),
        ("beta_a", float("nan"), r"beta_a must be finite"),
        ("beta_f", "x", r"beta_f must be a real number, got 'x'"),
    ],
)
def test_parameter_validation(name, value, match):
    with pytest.raises(AbglibValueError, match=match):
        AntennaParams(**{**NOMINAL, name: value})


def test_scaled_and_mapping_errors():
    p = AntennaParams(**NOMINAL)
    assert p.scaled("beta_a", 2.0).beta_a == pytest.approx(0.1)
    assert p.p_d == pytest.approx(0.1)
    with pytest.raises(AbglibValueError, match="name must be one of"):
        p.scaled("p_d", 2.0)  # p_d = 1 - p_a is not free (app. H)
    with pytest.raises(AbglibValueError, match=r"missing \['kappa'\]"):
        AntennaParams.from_mapping({k: v for k, v in NOMINAL.items() if k != "kappa"})


def test_model_physics():
    """Undamped modes by hand: rigid body (0), carriage sqrt(kappa p_a/p_f), antenna on the
    free rotor sqrt(1 + p_a/p_d) (rigid carriage limit p_f -> inf)."""
    p = AntennaParams(**{**NOMINAL, "beta_a": 0.0, "beta_d": 0.0, "beta_f": 0.0, "p_f": 1e9})
    ac, bc, cc = continuous_model(p)
    w = np.sort(np.abs(np.linalg.eigvals(ac)))
    assert w[:2] == pytest.approx([0.0, 0.0], abs=1e-6)
    assert w[-1] == pytest.approx(np.sqrt(1 + 0.9 / 0.1), rel=1e-9)
    # the torque acts +u on the rotor and -u on the stator: no net torque on rotor+stator
    # inertias (p_d, p_f) when the springs are slack
    m = np.array([1.0, p.p_d / p.p_a, p.p_f / p.p_a])
    assert m @ bc[3:, 0] == pytest.approx(0.0, abs=1e-6)
    assert cc.tolist() == [[1, 0, 0, 0, 0, 0]]


@settings(max_examples=25, deadline=None, derandomize=True)
@given(
    st.floats(0.05, 0.95),
    st.floats(0.1, 10.0),
    st.floats(0.0, 0.3),
    st.floats(0.01, 2.0),
)
def test_zoh_matches_scipy_cont2discrete(p_a, p_f, beta, dt):
    p = AntennaParams(p_a=p_a, p_f=p_f, beta_a=beta, beta_d=beta / 10, beta_f=2 * beta, kappa=1)
    ac, bc, cc = continuous_model(p)
    a, b = zoh(ac, bc, dt)
    ad, bd, *_ = scipy.signal.cont2discrete((ac, bc, cc, np.zeros((1, 1))), dt, method="zoh")
    np.testing.assert_allclose(a, ad, atol=1e-12)
    np.testing.assert_allclose(b, bd, atol=1e-12)


def test_zoh_against_integral():
    """B = int_0^dt exp(Ac s) ds Bc by quadrature (eq D.10)."""
    ac, bc, _ = continuous_model(AntennaParams(**NOMINAL))
    dt = 2 * np.pi / 10
    s = np.linspace(0.0, dt, 2001)
    vals = np.array([scipy.linalg.expm(ac * si) @ bc for si in s])[:, :, 0]
    b_quad = scipy.integrate.simpson(vals, x=s, axis=0)
    a, b = discrete_plant(AntennaParams(**NOMINAL), dt)[:2]
    np.testing.assert_allclose(b[:, 0], b_quad, atol=1e-10)
    np.testing.assert_allclose(a, scipy.linalg.expm(ac * dt), atol=1e-13)


def test_zoh_errors():
    with pytest.raises(AbglibValueError, match="dt"):
        zoh(np.eye(2), np.ones(2), 0.0)
    with pytest.raises(AbglibValueError, match=r"ac must be square"):
        zoh(np.ones((2, 3)), np.ones(2), 0.1)
