"""The engine against the literal recursion (seed 000, eqs 1-6), FilterPy, and exact inputs."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from abglib import AbglibValueError, Gains, track
from abglib.engine import OUTPUTS

from .conftest import require_module
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
    gh = require_module("filterpy.gh")  # skips without it; fails under CI
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


def test_the_batched_kernels_compile_once_whatever_the_inputs_writeability():
    """numba types read-only arrays apart: fresh, read-only and broadcast (read-only)
    measurements, detections and states give the literal recursion's bits and never
    compile a second machine code of a batched kernel."""
    from abglib import _kernels

    z = np.cumsum(np.ones((4, 16)), axis=-1) + np.arange(4)[:, None] ** 2
    frozen = z.copy()
    frozen.flags.writeable = False
    det = np.ones(16, bool)
    det[5] = False
    for zz in (z, frozen, np.broadcast_to(z[0], (4, 16))):
        for g, s0 in ((Gains(0.5, 0.2), [1.0, 0.5]), (Gains(0.5, 0.2, 0.05), [1.0, 0.5, 0.1])):
            for d in (None, det, np.broadcast_to(det, (4, 16))):
                for init in (np.array(s0), np.broadcast_to(s0, (4, len(s0)))):
                    out = track(zz, g, detected=d, init=init)
                    for k in range(4):
                        dk = None if d is None else np.broadcast_to(d, (4, 16))[k]
                        ref = literal_track(zz[k], *g, state=[*s0, 0.0][:3], detected=dk)
                        np.testing.assert_array_equal(out.x_smooth[k], ref[1])
    for kernel in (_kernels.run2, _kernels.run3):
        assert len(kernel.signatures) == 1, kernel.signatures


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
        ({"z": np.ones(5) + 1j}, r"z must be real, got complex .*pass z\.real or abs\(z\)"),
        ({"z": np.ones(5, bool)}, r"z must be a real number or array of them, got booleans"),
        ({"dt": True}, r"dt must be a real number or array of them, got booleans \(True\)"),
        ({"z": ["1", "2"]}, r"z must be a real number or array of them, got strings"),
        ({"dt": "0.1"}, r"dt must be a real number or array of them, got '0.1'"),
        ({"dt": None}, r"dt must be a real number or array of them, got None"),
    ],
)
def test_track_refuses_strings_booleans_and_complex(kwargs, match):
    args = {"z": np.ones(5), "dt": 1.0, **kwargs}
    with pytest.raises(AbglibValueError, match=match):
        track(args["z"], Gains(0.5, 0.2), dt=args["dt"])


# --------------------------------------------------------------------------- batched kernel
# Gains and dt constant in time go through abglib._kernels.run2/run3 (four series per loop,
# threads for large batches); time-varying ones through the per-series gufunc. Both are
# checked against the literal recursion, and against each other bit for bit.

ORDERS = {"alpha-beta": (0.45, 0.12, 0.0), "alpha-beta-gamma": (0.5, 0.2, 0.01)}


@pytest.mark.parametrize("gains", ORDERS.values(), ids=ORDERS.keys())
@pytest.mark.parametrize("runs", [1, 3, 4, 9, 70])  # leftovers of the four-series blocks
def test_batched_kernel_matches_literal_recursion(gains, runs):
    rng = np.random.default_rng(runs)
    z = rng.normal(size=(runs, 40)).cumsum(axis=-1)
    out = track(z, Gains(*gains), dt=0.3)
    for r in range(runs):
        _assert_matches_reference(out, literal_track(z[r], *gains, dt=0.3), index=(r,))


@pytest.mark.parametrize("gains", ORDERS.values(), ids=ORDERS.keys())
@pytest.mark.parametrize("init", ["zero", "two_point", "three_point", "state"])
@pytest.mark.parametrize("with_det", [False, True])
def test_batched_equals_per_series_bit_for_bit(gains, init, with_det):
    """The same expressions in the same order: both paths give identical bits."""
    rng = np.random.default_rng(11)
    runs, n = 13, 64
    z = rng.normal(size=(runs, n)).cumsum(axis=-1)
    det = rng.uniform(size=(runs, n)) > 0.25 if with_det else None
    if with_det:
        det[:, :3] = True
        z = np.where(det, z, np.nan)  # missed samples are never read
    state = rng.normal(size=(runs, 3)) if init == "state" else init
    if init == "state" and gains[2] == 0.0:
        state[:, 2] = 0.0
    g = Gains(*gains)
    if init == "three_point" and gains[2] == 0.0:
        # both paths refuse: an alpha-beta tracker never corrects the estimated acceleration
        for dt in (0.4, np.full(n, 0.4)):
            with pytest.raises(AbglibValueError, match="init='three_point'.*gamma=0"):
                track(z, g, dt=dt, init=state, detected=det)
        return
    fast = track(z, g, dt=0.4, init=state, detected=det)
    # an all-equal time-varying dt forces the per-series gufunc with the same values
    slow = track(z, g, dt=np.full(n, 0.4), init=state, detected=det)
    for name in OUTPUTS:
        np.testing.assert_array_equal(getattr(fast, name), getattr(slow, name), err_msg=name)
    ref = literal_track(
        np.nan_to_num(z[5]), *gains, dt=0.4, detected=None if det is None else det[5],
        state=state[5] if init == "state" else (0.0, 0.0, 0.0),
    )  # fmt: skip
    if init == "zero" or init == "state":
        _assert_matches_reference(fast, ref, index=(5,))


def test_large_batch_uses_threads_and_stays_exact():
    from abglib import engine

    rng = np.random.default_rng(12)
    runs, n = 203, 400  # > engine._PARALLEL_SAMPLES samples: the prange kernel
    assert runs * n >= engine._PARALLEL_SAMPLES
    z = rng.normal(size=(runs, n)).cumsum(axis=-1)
    g = Gains(0.5, 0.2, 0.01)
    out = track(z, g, dt=0.25)
    one = track(z[:3], g, dt=0.25)  # serial kernel
    for name in OUTPUTS:
        np.testing.assert_array_equal(getattr(out, name)[:3], getattr(one, name), err_msg=name)
    for r in (0, 101, 202):
        _assert_matches_reference(out, literal_track(z[r], 0.5, 0.2, 0.01, 0.25), index=(r,))


def test_concurrent_callers_from_threads_give_identical_results():
    """Snakemake runs in-process jobs in threads: concurrent large batches take the
    threaded kernel one at a time (the others run the serial one), without a crash and
    bit for bit equal to a lone call."""
    from concurrent.futures import ThreadPoolExecutor

    from abglib import engine

    rng = np.random.default_rng(14)
    z = rng.normal(size=(64, 2048)).cumsum(axis=-1)
    assert z.size >= engine._PARALLEL_SAMPLES
    g = Gains(0.4, 0.1, 0.005)
    alone = track(z, g, dt=0.5)
    with ThreadPoolExecutor(4) as pool:
        results = list(pool.map(lambda _: track(z, g, dt=0.5), range(8)))
    assert not engine._PARALLEL_LOCK.locked()
    for res in results:
        for name in OUTPUTS:
            np.testing.assert_array_equal(getattr(res, name), getattr(alone, name))


def test_gain_bank_with_broadcast_z_dt_and_state():
    """A bank (k, 1, 1) against runs (r, n), dt per run (r, 1), z shared rows."""
    rng = np.random.default_rng(13)
    k, runs, n = 3, 6, 30
    z = rng.normal(size=(runs, n)).cumsum(axis=-1)
    alphas = np.array([0.2, 0.5, 0.8])
    bank = Gains(alphas[:, None, None], 0.1, np.array([0.0, 0.01, 0.02])[:, None, None])
    dts = rng.uniform(0.1, 2.0, size=(runs, 1))
    state = (1.0, -0.5, 0.0)
    out = track(z, bank, dt=dts, init=state)
    assert out.x_smooth.shape == (k, runs, n)
    for j in range(k):
        for r in range(runs):
            ref = literal_track(z[r], alphas[j], 0.1, 0.01 * j, dts[r, 0], state=state)
            _assert_matches_reference(out, ref, index=(j, r))
    # one series against a bank: z (n,) gives outputs (k, 1, n)
    single = track(z[2], bank, dt=dts[2, 0], init=state)
    np.testing.assert_array_equal(single.x_pred[:, 0], out.x_pred[:, 2])


def test_non_contiguous_and_read_only_inputs():
    rng = np.random.default_rng(14)
    big = rng.normal(size=(40, 8)).cumsum(axis=0)
    z = big.T[:, ::2]  # (8, 20), strided both ways
    assert not z.flags.c_contiguous
    g = Gains(0.5, 0.2, 0.01)
    out = track(z, g, dt=0.5)
    ref = track(np.ascontiguousarray(z), g, dt=0.5)
    for name in OUTPUTS:
        np.testing.assert_array_equal(getattr(out, name), getattr(ref, name), err_msg=name)
    ro = np.ascontiguousarray(z)
    ro.setflags(write=False)
    np.testing.assert_array_equal(track(ro, g, dt=0.5).x_smooth, ref.x_smooth)
    _assert_matches_reference(out, literal_track(z[3], 0.5, 0.2, 0.01, 0.5), index=(3,))


@pytest.mark.parametrize("gains", ORDERS.values(), ids=ORDERS.keys())
@pytest.mark.parametrize("time_varying", [False, True])
def test_out_buffers_are_filled_and_returned(gains, time_varying):
    rng = np.random.default_rng(15)
    z = rng.normal(size=(9, 50)).cumsum(axis=-1)
    dt = np.full(50, 0.2) if time_varying else 0.2  # gufunc or batched path
    g = Gains(*gains)
    ref = track(z, g, dt=dt)
    bufs = {name: np.full(z.shape, np.nan) for name in OUTPUTS}
    out = track(z, g, dt=dt, out=bufs)
    for name in OUTPUTS:
        assert getattr(out, name) is bufs[name]
        np.testing.assert_array_equal(bufs[name], getattr(ref, name), err_msg=name)
    # a previous result as out, with other data: overwritten in place, no stale values
    z2 = rng.normal(size=z.shape).cumsum(axis=-1)
    again = track(z2, g, dt=dt, out=out)
    assert again.x_pred is bufs["x_pred"]
    np.testing.assert_array_equal(again.v_smooth, track(z2, g, dt=dt).v_smooth)
    assert np.all(again.a_smooth == 0.0) == (gains[2] == 0.0)
    # only some outputs, one of them in a buffer
    xs = np.empty(z.shape)
    part = track(z, g, dt=dt, outputs=("x_smooth", "v_smooth"), out={"x_smooth": xs})
    assert part.x_smooth is xs and part.x_pred is None
    np.testing.assert_array_equal(xs, ref.x_smooth)
    np.testing.assert_array_equal(part.v_smooth, ref.v_smooth)


def test_non_contiguous_out_buffer_and_bank_shape():
    rng = np.random.default_rng(16)
    z = rng.normal(size=(5, 30)).cumsum(axis=-1)
    bank = Gains(np.array([0.3, 0.6])[:, None, None], 0.1, 0.005)
    ref = track(z, bank)
    big = np.zeros((2, 5, 60))
    view = big[..., ::2]  # (2, 5, 30), not contiguous: written through a copy
    out = track(z, bank, out={"x_smooth": view})
    assert out.x_smooth is view
    np.testing.assert_array_equal(big[..., ::2], ref.x_smooth)
    assert np.all(big[..., 1::2] == 0.0)  # the gaps untouched


def test_out_buffers_give_the_error_even_after_writing():
    z = np.array([[1.0, 2.0, 3.0], [1.0, np.nan, 3.0]])
    with pytest.raises(AbglibValueError, match=r"got nan at index \(1, 1\)"):
        track(z, Gains(0.5, 0.1), out={"x_pred": np.empty(z.shape)})


@pytest.mark.parametrize(
    ("out", "match"),
    [
        ([np.empty(3)], r"out must be a dict of arrays keyed by x_pred, .* got list"),
        ({"x_filt": np.empty(3)}, r"out has an unknown key 'x_filt'; the keys are x_pred"),
        ({"x_pred": [0.0, 0.0, 0.0]}, r"out\['x_pred'\] must be a numpy array, got list"),
        (
            {"x_pred": np.empty(3, np.float32)},
            r"out\['x_pred'\] must have dtype float64, got float32",
        ),  # noqa: E501
        (
            {"x_pred": np.empty(4)},
            r"out\['x_pred'\] has shape \(4,\), but the outputs have shape \(3,\)",
        ),  # noqa: E501
        ({"x_pred": np.empty((1, 3))}, r"has shape \(1, 3\), but the outputs have shape \(3,\)"),
        ({"x_pred": np.broadcast_to(np.empty(1), (3,))}, r"out\['x_pred'\] is read-only"),
        ({"x_pred": "z"}, r"out\['x_pred'\] shares memory with z"),
        (
            {"x_pred": "same", "x_smooth": "same"},
            r"out\['x_smooth'\] shares memory with out\['x_pred'\]",
        ),  # noqa: E501
    ],
)
def test_out_buffer_errors(out, match):
    z = np.array([1.0, 2.0, 3.0])
    shared = np.empty(3)
    named = {"z": z, "same": shared}
    if isinstance(out, dict):
        out = {k: named[v] if isinstance(v, str) else v for k, v in out.items()}
    with pytest.raises(AbglibValueError, match=match):
        track(z, Gains(0.5, 0.1), out=out)


def test_out_buffer_for_an_output_not_requested():
    with pytest.raises(
        AbglibValueError, match=r"out\['x_pred'\] is given but 'x_pred' is not in outputs"
    ):  # noqa: E501
        track(np.ones(3), Gains(0.5, 0.1), outputs=("x_smooth",), out={"x_pred": np.empty(3)})


def test_buffer_errors_leave_the_buffers_alone():
    z = np.ones(3)
    good = np.full(3, 7.0)
    with pytest.raises(AbglibValueError, match="dtype float64"):
        track(z, Gains(0.5, 0.1), out={"x_smooth": good, "x_pred": np.empty(3, np.float32)})
    assert np.all(good == 7.0)


def test_alpha_beta_a_smooth_is_a_writeable_zero_array_at_every_size():
    """The alpha-beta path's a_smooth (lazily mapped zero pages when large) is a real
    array: zeros, writeable, reusable as an out= buffer, independent between calls."""
    z = np.random.default_rng(3).normal(size=(3, 200_000)).cumsum(axis=-1)  # 4.8 MB
    g = Gains(0.5, 0.1)
    for zz in (z, z[:, :50]):
        res = track(zz, g, init="two_point")
        a = res.a_smooth
        assert a.shape == zz.shape and a.dtype == np.float64 and a.flags.writeable
        assert not np.any(a)
        a[...] = 7.0  # the caller owns it
        again = track(zz, g, init="two_point", out=res)
        assert again.a_smooth is a and not np.any(a)
        other = track(zz, g, init="two_point").a_smooth
        assert not np.shares_memory(other, a)
        np.testing.assert_array_equal(again.x_smooth, track(zz, g, init="two_point").x_smooth)


# --------------------------------------------------------------------------- exact bits
# The kernels evaluate seed 000, eqs 1-6 in one fixed order without fast-math; these
# tests hold every path to that order bit for bit (signs of zero included), against a
# plain-Python transcription of it (Python floats are IEEE doubles, rounded per operation).


def _exact_series(z, alpha, beta, gamma, dt, state, npoints, detected):
    """One series in the kernels' own operation order (abglib._kernels._step3 / _step2)."""
    T = float(dt)
    h, b, c = 0.5 * T * T, beta / T, gamma / (T * T)
    x, v, a = (float(s) for s in state)
    order2 = npoints < 3 and gamma == 0.0 and a == 0.0
    n = len(z)
    out = np.zeros((4, n))
    for i in range(n):
        zi = float(z[i])
        if i < npoints:  # seed 001, section 3: the measurements fix the state
            z0, z1, z2 = float(z[0]), float(z[min(1, n - 1)]), float(z[min(2, n - 1)])
            if i == 0:
                x, v, a = z0, 0.0, 0.0
            elif i == 1:
                x, v, a = z1, (z1 - z0) / T, 0.0
            else:
                d1, d2 = (z1 - z0) / T, (z2 - z1) / T
                a = 2.0 * (d2 - d1) / (T + T)
                x, v = z2, d2 + 0.5 * a * T
            x_p = zi
        elif order2:
            x_p = x + T * v
            if detected is None or detected[i]:
                r = zi - x_p
                x, v = x_p + alpha * r, v + b * r
            else:
                x = x_p
        else:
            x_p = x + T * v + h * a
            v_p = v + T * a
            if detected is None or detected[i]:
                r = zi - x_p
                x, v, a = x_p + alpha * r, v_p + b * r, a + c * r
            else:
                x, v = x_p, v_p
        out[:, i] = (x_p, x, v, a)
    return out


def _same_bits(got, want, what):
    got, want = np.ascontiguousarray(got), np.ascontiguousarray(want)
    same = got.view(np.uint64) == want.view(np.uint64)
    if not same.all():
        i = tuple(int(k) for k in np.argwhere(~same)[0])
        raise AssertionError(f"{what}: {got[i]!r} != {want[i]!r} at {i}")


@pytest.mark.parametrize("dt", [1.0, 0.1, 0.37])  # 1.0: the loop without T * v (exact there)
@pytest.mark.parametrize("gains", ORDERS.values(), ids=ORDERS.keys())
@pytest.mark.parametrize("init", ["zero", "two_point", "three_point", "state"])
@pytest.mark.parametrize("with_det", [False, True])
def test_every_path_gives_the_exact_bits_of_the_recursion(dt, gains, init, with_det):
    """Random series (one alone: the single-series loop; 6: a block and two leftovers),
    through the batched kernel and the per-series gufunc (a constant dt array), against
    the plain-Python transcription, bit for bit."""
    if init == "three_point" and gains[2] == 0.0:
        return  # refused (test_batched_equals_per_series_bit_for_bit)
    rng = np.random.default_rng(int(dt * 100) + 7 * with_det + len(init))
    for runs in (1, 6):
        n = 300
        z = rng.normal(size=(runs, n)).cumsum(axis=-1) * 10.0 ** rng.uniform(-3, 3)
        det = rng.uniform(size=(runs, n)) > 0.3 if with_det else None
        if with_det:
            det[:, :3] = True
            z = np.where(det, z, np.nan)
        state = np.zeros((runs, 3))
        if init == "state":
            state = rng.normal(size=(runs, 3))
            if gains[2] == 0.0:
                state[:, 2] = 0.0  # an alpha-beta state has no acceleration
        npoints = {"zero": 0, "two_point": 2, "three_point": 3, "state": 0}[init]
        how = state if init == "state" else init
        g = Gains(*gains)
        for label, step in (("batched", dt), ("per-series", np.full(n, dt))):
            out = track(z, g, dt=step, init=how, detected=det)
            for r in range(runs):
                want = _exact_series(
                    z[r], *gains, dt, state[r], npoints, None if det is None else det[r]
                )
                for k, name in enumerate(OUTPUTS):
                    _same_bits(getattr(out, name)[r], want[k], f"{label} {name} run {r}")


def test_single_series_unit_dt_matches_the_old_route_bit_for_bit():
    """dt = 1 takes a loop without the multiplications by T (exact products): the same
    bits as the per-series gufunc, which multiplies, on long random series of both orders."""
    rng = np.random.default_rng(2026)
    z = rng.normal(size=20_000).cumsum()
    for gains in (Gains(0.45, 0.12), Gains(0.5, 0.2, 0.01)):
        for init in ("zero", "two_point"):
            new = track(z, gains, init=init)
            old = track(z, gains, dt=np.ones(z.size), init=init)
            for name in OUTPUTS:
                _same_bits(getattr(new, name), getattr(old, name), name)
