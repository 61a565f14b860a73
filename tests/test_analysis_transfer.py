"""Transfer functions (seed 000, eqs 36-41) against independent twins (seed 002's printed
eqs 3, 6: tests/replications/test_huang_printed.py).

Twins: the state-space form C (zI - F)^-1 K built from eqs 1-6 (abglib.analysis._statespace),
the DFT of the impulse response of the compiled recursion (abglib.track), scipy.signal.freqz
and python-control's ss2tf.
"""

from __future__ import annotations

import control
import numpy as np
import pytest
import scipy.signal
from hypothesis import given, settings
from hypothesis import strategies as st

from abglib import Gains, track
from abglib.analysis._statespace import state_space
from abglib.analysis._transfer import (
    OUTPUTS,
    frequency_response,
    transfer_function,
)

# frequency grid avoiding wT = 0 (where the 3-state model of an alpha-beta tracker is
# singular: its acceleration pole at z = 1) and spanning the half period (seed 000, Fig. 1)
W = np.linspace(0.01, np.pi, 37)


def standard(theta):
    """Standard (critically damped) alpha-beta-gamma gains, seed 000, eqs 22-24."""
    return Gains(1 - theta**3, 1.5 * (1 - theta) ** 2 * (1 + theta), (1 - theta) ** 3)


# theta in (0.05, 0.95): the whole useful range of the fading-memory filter, every gain set
# stable (triple pole at theta)
thetas = st.floats(0.05, 0.95)
# alpha-beta-gamma gains inside the Jury region of seed 000, eqs 45-48 (gamma drawn as a
# fraction of its upper bound alpha beta / (1 - alpha/2) from eq 47); margins keep the poles
# away from the unit circle so truncated impulse responses converge
alphas = st.floats(0.05, 1.9)


@st.composite
def stable_gains(draw, gamma_zero=None):
    a = draw(alphas)
    b = draw(st.floats(0.02, 0.9)) * (4 - 2 * a)
    zero = draw(st.booleans()) if gamma_zero is None else gamma_zero
    g = 0.0 if zero else draw(st.floats(0.05, 0.9)) * a * b / (1 - a / 2)
    return Gains(a, b, g)


def ss_response(gains, output, w, dt):
    """Frequency response from the 3-state model s(n) = F s(n-1) + K z(n) (seed 000, 1-6).

    Smoothed outputs are rows of S = (I - F/z)^-1 K; predicted outputs are rows of
    Phi S / z (eqs 4-6)."""
    ss = state_space(gains, dt, reduced=False)
    row = {"x": 0, "v": 1, "a": 2}[output[0]]
    out = []
    for wk in np.atleast_1d(w):
        z = np.exp(1j * wk)
        s = np.linalg.solve(np.eye(3) - ss.F / z, ss.K)
        if output.endswith("pred"):
            s = ss.Phi @ s / z
        out.append(s[row])
    return np.array(out)


def test_hand_expansion_alpha_beta():
    # Gains(0.5, 0.2): eq 39 reduced -> ((a+b) z - a) / (z^2 + (a+b-2) z + 1 - a), by hand
    num, den = transfer_function(Gains(0.5, 0.2), "x_pred")
    np.testing.assert_allclose(num, [0.0, 0.7, -0.5], atol=1e-15)
    np.testing.assert_allclose(den, [1.0, -1.3, 0.5], atol=1e-15)


def test_hand_expansion_table1_standard_abg():
    # Steelman Table 1 standard column (0.3, 0.0356, 0.0014); eq 40 expanded by hand:
    # z^3 + (a+b+g/2-3) z^2 + (3-2a-b+g/2) z - (1-a)
    a, b, g = 0.3, 0.0356, 0.0014
    num, den = transfer_function(Gains(a, b, g), "x_smooth")
    np.testing.assert_allclose(den, [1, a + b + g / 2 - 3, 3 - 2 * a - b + g / 2, a - 1])
    # eq 36: z [a (z-1)^2 + (b+g/2)(z-1) + g] = a z^3 + (b+g/2-2a) z^2 + (a-b+g/2) z
    np.testing.assert_allclose(num, [a, b + g / 2 - 2 * a, a - b + g / 2, 0.0], atol=1e-15)


@settings(max_examples=40, deadline=None)
@given(stable_gains(), st.sampled_from(OUTPUTS), st.floats(0.1, 5.0))
def test_matches_state_space(gains, output, dt):
    h = frequency_response(gains, output, W, dt=dt)
    np.testing.assert_allclose(h, ss_response(gains, output, W, dt), rtol=1e-8, atol=1e-10)


@settings(max_examples=30, deadline=None)
@given(stable_gains())
def test_denominator_is_characteristic_polynomial_of_F(gains):
    # eq 40 (eq 41 when gamma = 0) == det(zI - F) of the (reduced) state-space model
    _, den = transfer_function(gains, "x_smooth")
    np.testing.assert_allclose(den, np.poly(state_space(gains).F), atol=1e-12)


@settings(max_examples=20, deadline=None)
@given(thetas, st.sampled_from(["x_smooth", "v_smooth", "a_smooth", "x_pred"]))
def test_matches_dft_of_impulse_response(theta, output):
    # 4096 samples: the impulse response decays like n^2 theta^n, < 1e-80 at theta = 0.95
    n, dt = 4096, 0.25  # dt = 0.25 s: arbitrary, exercises the 1/T and 1/T^2 scaling
    gains = standard(theta)
    z = np.zeros(n)
    z[0] = 1.0
    h = getattr(track(z, gains, dt=dt), output)
    k = np.arange(1, 200)  # bins 2 pi k / n, up to wT ~ 0.3
    dft = np.fft.fft(h)[k]
    np.testing.assert_allclose(
        dft, frequency_response(gains, output, 2 * np.pi * k / n, dt=dt), rtol=1e-9, atol=1e-12
    )


@settings(max_examples=30, deadline=None)
@given(stable_gains(), st.sampled_from(OUTPUTS))
def test_coefficients_match_scipy_freqz(gains, output):
    # same-length num/den in descending powers of z == powers of z^-1 for freqz
    num, den = transfer_function(gains, output, dt=2.0)
    _, h = scipy.signal.freqz(num, den, worN=W)
    np.testing.assert_allclose(h, frequency_response(gains, output, W, dt=2.0), rtol=1e-9)


@pytest.mark.parametrize("output", ["x_smooth", "x_pred"])
@pytest.mark.parametrize("theta", [0.2, 0.8])  # two arbitrary standard trackers
def test_coefficients_match_python_control(output, theta):
    gains = standard(theta)
    ss = state_space(gains)
    # with xi(n) = s(n-1): xi(n+1) = F xi(n) + K z(n); x_smooth = e1 F xi + alpha z,
    # x_pred = e1 Phi xi (eqs 1-6)
    C, D = (ss.F[:1], [[gains.alpha]]) if output == "x_smooth" else (ss.Phi[:1], [[0.0]])
    sys = control.ss2tf(control.ss(ss.F, ss.K[:, None], C, D, True))
    num_c = np.asarray(sys.num[0][0], dtype=float)
    den_c = np.asarray(sys.den[0][0], dtype=float)
    num, den = transfer_function(gains, output)
    np.testing.assert_allclose(den_c / den_c[0], den, atol=1e-12)
    num_c = np.trim_zeros(num_c / den_c[0], "f")
    np.testing.assert_allclose(num_c, np.trim_zeros(num, "f")[: num_c.size], atol=1e-12)


@settings(max_examples=30, deadline=None)
@given(stable_gains(), st.floats(0.1, 5.0))
def test_dc_gain_and_ramp_following(gains, dt):
    # unit DC gain of the position outputs (type-2/3 loop), and Vbar/X -> j w / T at low
    # frequency (a ramp of slope 1/T per sample is followed with no velocity error)
    for out in ("x_smooth", "x_pred"):
        assert frequency_response(gains, out, 0.0) == pytest.approx(1.0, abs=1e-12)
    # the relative error of jw/T is O(w alpha / beta) <= 1e-9 * 1.9 / 0.004 = 5e-7 here
    w = 1e-9
    hv = frequency_response(gains, "v_smooth", w, dt=dt)
    assert hv / (1j * w / dt) == pytest.approx(1.0, rel=1e-5)


def test_bank_broadcast_matches_scalars():
    # a mixed bank: Table 1's standard alpha-beta-gamma and alpha-beta columns, and QD
    a = np.array([0.3, 0.3, 0.3])
    b = np.array([0.0356, 0.0267, 0.0362])
    g = np.array([0.0014, 0.0, 0.00219])
    bank = Gains(a, b, g)
    h = frequency_response(bank, "x_smooth", W)
    assert h.shape == (3, W.size)
    for i in range(3):
        np.testing.assert_allclose(h[i], frequency_response(bank[i], "x_smooth", W), rtol=1e-13)
    num, den = transfer_function(bank, "x_pred")
    assert num.shape == den.shape == (3, 4)  # the cubic of eq 40 for a mixed bank
    # the mixed bank's alpha-beta row has the cancelling factor (z - 1) (eq 40 = w * eq 41)
    n2, d2 = transfer_function(bank[1], "x_pred")
    np.testing.assert_allclose(den[1], np.convolve(d2, [1, -1]), atol=1e-15)
    np.testing.assert_allclose(num[1], np.convolve(n2, [1, -1]), atol=1e-15)
    assert isinstance(frequency_response(bank[0], "x_smooth", 0.5), complex)


@pytest.mark.parametrize(
    ("call", "match"),
    [
        (lambda: transfer_function((0.3, 0.03), "x_smooth"), "gains must be an abglib.Gains"),
        (lambda: transfer_function(Gains(0.3, 0.03), "x_filt"), "output must be one of 'x_smooth'"),
        (lambda: transfer_function(Gains(0.3, 0.03), "x_pred", dt=0.0), r"dt must be > 0, got 0.0"),
        (lambda: transfer_function(Gains(0.3, 0.03), "x_pred", dt=[1, 2]), "dt must be a scalar"),
        (
            lambda: frequency_response(Gains(0.3, 0.03), "x_pred", [0.1, np.nan]),
            r"wT must be finite, got nan at index 1",
        ),
        (lambda: frequency_response(Gains(0.3, 0.03), "v_pred", 0.1, dt=-1), "dt must be > 0"),
    ],
)
def test_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()
