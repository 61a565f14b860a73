"""The engine against the literal recursion (seed 000, eqs 1-6), FilterPy, and exact inputs."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from abglib import AbglibValueError, Gains, track
from abglib.engine import OUTPUTS

from .reference import literal_track

RTOL = 1e-12  # rounding only: the engine and the reference evaluate the same expressions

gain_sets = st.tuples(
    st.floats(0.01, 1.9),  # alpha anywhere in the alpha-beta stability interval (seed 000, eq 45)
    st.floats(0.0, 1.5),
    st.floats(0.0, 0.3),
)


def _assert_matches_reference(out, ref, index=()):
    for name, r in zip(OUTPUTS, ref, strict=True):
        got = getattr(out, name)[index]
        np.testing.assert_allclose(got, r, rtol=RTOL, atol=1e-12 * np.abs(r).max(), err_msg=name)


@settings(max_examples=40, deadline=None)
@given(gains=gain_sets, dt=st.floats(0.01, 10.0), seed=st.integers(0, 2**32 - 1))
def test_matches_literal_recursion(gains, dt, seed):
    z = np.random.default_rng(seed).normal(size=60).cumsum()
    out = track(z, Gains(*gains), dt=dt)
    _assert_matches_reference(out, literal_track(z, *gains, dt=dt))


def test_explicit_initial_state():
    z = np.random.default_rng(1).normal(size=50)
    state = (3.0, -0.5, 0.02)
    out = track(z, Gains(0.4, 0.1, 0.005), dt=0.5, init=state)
    _assert_matches_reference(out, literal_track(z, 0.4, 0.1, 0.005, 0.5, state=state))
    # [x, v] is [x, v, 0]
    two = track(z, Gains(0.4, 0.1, 0.005), dt=0.5, init=state[:2])
    three = track(z, Gains(0.4, 0.1, 0.005), dt=0.5, init=(*state[:2], 0.0))
    np.testing.assert_array_equal(two.x_smooth, three.x_smooth)


def test_alpha_beta_has_zero_acceleration():
    z = np.random.default_rng(2).normal(size=30)
    out = track(z, Gains(0.5, 0.2))
    assert np.all(out.a_smooth == 0.0)


def test_time_varying_gains_and_irregular_dt():
    rng = np.random.default_rng(3)
    n = 80
    z = rng.normal(size=n).cumsum()
    alpha = rng.uniform(0.1, 0.9, n)
    beta = rng.uniform(0.01, 0.3, n)
    gamma = rng.uniform(0.0, 0.02, n)
    dt = rng.uniform(0.1, 2.0, n)
    out = track(z, Gains(alpha, beta, gamma), dt=dt)
    _assert_matches_reference(out, literal_track(z, alpha, beta, gamma, dt))


def test_constant_dt_array_equals_scalar():
    z = np.random.default_rng(4).normal(size=40)
    g = Gains(0.3, 0.05, 0.002)
    a = track(z, g, dt=0.25)
    b = track(z, g, dt=np.full(40, 0.25))
    for name in OUTPUTS:
        np.testing.assert_array_equal(getattr(a, name), getattr(b, name))


def test_bank_of_gains_broadcasts_against_monte_carlo_runs():
    rng = np.random.default_rng(5)
    z = rng.normal(size=(7, 50))  # 7 Monte Carlo runs
    alphas = np.array([0.2, 0.5, 0.8])
    betas = alphas**2 / (2 - alphas)  # Benedict-Bordner (seed 001, eq 23b)
    bank = Gains(alphas[:, None, None], betas[:, None, None])
    out = track(z, bank, dt=2.0)
    assert out.x_smooth.shape == (3, 7, 50)
    for k in range(3):
        for r in range(7):
            _assert_matches_reference(
                out, literal_track(z[r], alphas[k], betas[k], 0.0, 2.0), index=(k, r)
            )


def test_missed_detections_coast_on_prediction():
    rng = np.random.default_rng(6)
    z = rng.normal(size=60).cumsum()
    det = rng.uniform(size=60) > 0.3
    det[:2] = True
    z_missing = np.where(det, z, np.nan)  # missed samples may hold NaN
    g = Gains(0.6, 0.3, 0.02)
    out = track(z_missing, g, dt=0.7, detected=det)
    ref = literal_track(z, 0.6, 0.3, 0.02, 0.7, detected=det)
    _assert_matches_reference(out, ref)
    # where missed, the smoothed position is the prediction
    np.testing.assert_array_equal(out.x_smooth[~det], out.x_pred[~det])
    # a masked array says the same thing
    masked = track(np.ma.masked_array(z, mask=~det), g, dt=0.7)
    np.testing.assert_array_equal(masked.x_smooth, out.x_smooth)


def test_two_point_initialisation_seed001_eqs9_10():
    z = np.array([10.0, 12.5, 14.0, 17.0, 19.5, 21.0])
    T = 2.0
    out = track(z, Gains(0.5, 0.2), dt=T, init="two_point")
    # the first two measurements are taken as the predictions (seed 001, section 3)
    np.testing.assert_array_equal(out.x_pred[:2], z[:2])
    v2 = (z[1] - z[0]) / T  # eq 9
    assert out.v_smooth[1] == v2
    assert out.x_pred[2] == z[1] + T * v2  # eq 10
    # from sample 2 on it is the recursion started from (z1, v2)
    ref = literal_track(z[2:], 0.5, 0.2, 0.0, T, state=(z[1], v2, 0.0))
    np.testing.assert_allclose(out.x_smooth[2:], ref[1], rtol=RTOL)


def test_point_initialisations_track_their_polynomial_exactly():
    t = np.cumsum(np.r_[0.0, np.random.default_rng(7).uniform(0.5, 1.5, 29)])
    dt = np.r_[1.0, np.diff(t)]
    line = 3.0 - 2.0 * t
    out = track(line, Gains(0.3, 0.05), dt=dt, init="two_point")
    np.testing.assert_allclose(out.x_smooth, line, rtol=0, atol=1e-9)
    np.testing.assert_allclose(out.v_smooth[1:], -2.0, rtol=1e-9)
    parabola = 1.0 + 0.5 * t - 0.8 * t**2
    out = track(parabola, Gains(0.3, 0.05, 0.002), dt=dt, init="three_point")
    np.testing.assert_allclose(out.x_pred, parabola, rtol=0, atol=1e-9)
    np.testing.assert_allclose(out.a_smooth[2:], -1.6, rtol=1e-9)


def test_unstable_gains_still_run():
    z = np.ones(200)
    out = track(z, Gains(2.5, 0.5))  # alpha > 2 violates seed 000, eq 45
    assert np.isfinite(out.x_smooth).all()
    assert np.abs(out.x_smooth[-1]) > 1e6  # and it diverges, as it should


def test_outputs_subset():
    z = np.random.default_rng(8).normal(size=(4, 30))
    g = Gains(0.4, 0.1, 0.01)
    full = track(z, g)
    part = track(z, g, outputs=("x_smooth", "a_smooth"))
    assert part.x_pred is None and part.v_smooth is None
    np.testing.assert_array_equal(part.x_smooth, full.x_smooth)
    np.testing.assert_array_equal(part.a_smooth, full.a_smooth)


def test_matches_filterpy_gh_and_ghk():
    gh = pytest.importorskip("filterpy.gh")
    z = np.random.default_rng(9).normal(size=500).cumsum()
    dt = 0.5
    # FilterPy's g, h are alpha, beta; its k is gamma / 2 (GHKFilter.update uses 2k/dt^2)
    f = gh.GHFilter(x=0.0, dx=0.0, dt=dt, g=0.4, h=0.1)
    res, pred = f.batch_filter(z, save_predictions=True)
    out = track(z, Gains(0.4, 0.1), dt=dt)
    np.testing.assert_allclose(out.x_smooth, res[1:, 0], rtol=1e-9)
    np.testing.assert_allclose(out.v_smooth, res[1:, 1], rtol=1e-9)
    np.testing.assert_allclose(out.x_pred, pred, rtol=1e-9)
    k = gh.GHKFilter(x=0.0, dx=0.0, ddx=0.0, dt=dt, g=0.4, h=0.1, k=0.005)
    xs = np.array([k.update(v)[0] for v in z])
    out = track(z, Gains(0.4, 0.1, 2 * 0.005), dt=dt)
    np.testing.assert_allclose(out.x_smooth, xs, rtol=1e-9)


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"z": [1.0, np.nan, 2.0]}, r"z must be finite where detected, got nan at index \(1,\)"),
        ({"z": [1.0, np.inf]}, r"z must be finite where detected, got inf"),
        ({"z": []}, r"z must not be empty"),
        ({"z": np.zeros((0, 5))}, r"z must not be empty, got shape \(0, 5\)"),
        ({"z": 3.0}, r"z must have a time axis"),
        ({"dt": 0.0}, r"dt must be > 0, got 0.0"),
        ({"dt": -1.0}, r"dt must be > 0, got -1.0"),
        ({"dt": np.nan}, r"dt must be finite, got nan"),
        ({"dt": [1.0, 1.0]}, r"dt has last \(time\) axis of length 2, but z has 3 samples"),
        ({"init": "one_point"}, r"init must be one of 'zero', 'two_point', 'three_point'"),
        ({"init": [1.0, 2.0, 3.0, 4.0]}, r"explicit init state must have last axis"),
        ({"init": [np.nan, 0.0]}, r"init state must be finite"),
        ({"init": "three_point"}, r"three_point.*gamma=0"),
        ({"z": [1.0], "init": "two_point"}, r"needs at least 2 samples, got n=1"),
        ({"detected": [1, 0, 1]}, r"detected must be a boolean array"),
        ({"detected": [False, True, True], "init": "two_point"}, r"needs detections at samples"),
        ({"outputs": ("x_filt",)}, r"outputs must be a non-empty subset"),
        ({"gains": (0.5, 0.1)}, r"gains must be an abglib.Gains, got tuple"),
        (
            {"gains": Gains(np.array([0.1, 0.2]), 0.01)},
            r"alpha has last \(time\) axis of length 2, but z has 3 samples.*alpha\[:, None\]",
        ),
        (
            {"z": np.zeros((2, 3)), "gains": Gains(np.array([[0.1], [0.2], [0.3]]), 0.01)},
            r"operands do not broadcast together",
        ),
    ],
)
def test_bad_input_messages(kwargs, match):
    args = {"z": [1.0, 2.0, 3.0], "gains": Gains(0.5, 0.1), **kwargs}
    with pytest.raises(ValueError, match=match):
        track(**args)


def test_alpha_beta_fast_path_is_bit_identical_to_general_kernel():
    from abglib.engine import _kernel

    rng = np.random.default_rng(10)
    z = rng.normal(size=(3, 200)).cumsum(axis=-1)
    det = (rng.uniform(size=200) > 0.2).astype(np.uint8)
    det[:2] = 1
    fast = track(z, Gains(0.45, 0.12), dt=0.3, detected=det.astype(bool), init="two_point")
    bufs = [np.empty(z.shape) for _ in range(4)]
    n = z.shape[-1]
    _kernel(3)(
        z,
        *(np.broadcast_to(v, (n,)) for v in (0.45, 0.12, 0.0, 0.3)),
        det,
        np.zeros(3),
        2,
        *bufs,
    )
    for name, b in zip(OUTPUTS, bufs, strict=True):
        np.testing.assert_array_equal(getattr(fast, name), b, err_msg=name)


@pytest.mark.parametrize(
    "kwargs, match",
    [
        ({"z": np.ones(5) + 1j}, r"z must be real, got complex"),
        ({"z": ["1", "2"]}, r"z must be a real number or array of them, got strings"),
        ({"dt": "0.1"}, r"dt must be a real number or array of them, got '0.1'"),
        ({"dt": None}, r"dt must be a real number or array of them, got None"),
    ],
)
def test_track_refuses_strings_and_complex(kwargs, match):
    args = {"z": np.ones(5), "dt": 1.0, **kwargs}
    with pytest.raises(AbglibValueError, match=match):
        track(args["z"], Gains(0.5, 0.2), dt=args["dt"])
