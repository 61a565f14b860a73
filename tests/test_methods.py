"""Methods M1-M5 of seed 001 against literal transcriptions of the paper's algorithms."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from abglib import AbglibValueError, Gains, methods

RNG = np.random.default_rng(20240601)


def _series(runs=3, n=25, seed=0):
    rng = np.random.default_rng(seed)
    t = np.arange(n, dtype=float)
    truth = 5.0 + 3.0 * t + 0.4 * t**2 * (t > 8)
    return truth + rng.normal(0.0, 2.0, size=(runs, n)), truth


# --------------------------------------------------------------------------- literal paper
def literal_tracker(z, alphas, betas, T):
    """Seed 001 eqs 3, 4, 6, 8 with the initialisation of eqs 9-10, one sample at a time.

    ``alphas[k]``, ``betas[k]`` are the gains used at sample k (0-based). Returns x_p.
    """
    n = len(z)
    xp = [0.0] * n
    xp[0], xp[1] = z[0], z[1]  # "the measured position is the predicted position"
    xs = z[1]
    vs = (z[1] - z[0]) / T  # eq 9
    for k in range(2, n):
        p = xs + T * vs  # eq 3 (eq 10 for k = 2)
        e = z[k] - p  # eq 4
        xs = p + alphas[k] * e  # eq 6
        vs = vs + betas[k] / T * e  # eq 8
        xp[k] = p
    return np.array(xp)


def bb(a):
    return a * a / (2.0 - a)  # eq 23b


def test_m1_is_the_literal_fixed_gain_tracker():
    z, _ = _series()
    out = methods.m1(z, 0.3, dt=0.5).x_pred
    for r in range(z.shape[0]):
        lit = literal_tracker(z[r], [0.3] * 25, [bb(0.3)] * 25, 0.5)
        np.testing.assert_allclose(out[r], lit, rtol=1e-13, atol=1e-10)


def test_m2_is_the_literal_growing_memory_tracker_and_the_least_squares_line():
    z, _ = _series(runs=2, n=20)
    out = methods.m2(z, dt=1.0).x_pred
    for r in range(2):
        a = [2 * (2 * n - 1) / (n * (n + 1)) for n in range(1, 21)]  # eq 24a
        b = [6 / (n * (n + 1)) for n in range(1, 21)]  # eq 24b
        np.testing.assert_allclose(out[r], literal_tracker(z[r], a, b, 1.0), rtol=1e-12)
        # independent route: extrapolate the least-squares line through samples 0..k-1
        for k in range(3, 20):
            coef = np.polyfit(np.arange(k), z[r, :k], 1)
            assert out[r, k] == pytest.approx(np.polyval(coef, k), rel=1e-9, abs=1e-8)


def test_m3_gains_and_search_equal_a_literal_grid_search():
    z, _ = _series(runs=3, n=30, seed=3)
    grid = [0.0, 0.25, 0.5, 0.75, 1.0]
    res = methods.m3(z, grid, dt=1.0)
    for r in range(3):
        best, best_cost, best_xp = None, np.inf, None
        for w in grid:
            a, b = [], []
            for n in range(1, 31):
                ah = 2 * (2 * n - 1) / (n * (n + 1))  # eq 24a
                bt = bb(ah)  # eq 23b at alpha^
                bh = 6 / (n * (n + 1))  # eq 24b
                a.append(ah)
                b.append(w * bt + (1 - w) * bh)  # eq 25
            xp = literal_tracker(z[r], a, b, 1.0)
            cost = np.mean((z[r, 2:] - xp[2:]) ** 2)
            if cost < best_cost:
                best, best_cost, best_xp = w, cost, xp
        assert res.param[r] == best
        np.testing.assert_allclose(res.x_pred[r], best_xp, rtol=1e-12)
    # w = 0 is M2 exactly
    np.testing.assert_allclose(methods.m3(z, [0.0]).x_pred, methods.m2(z).x_pred, rtol=1e-14)


def literal_m4(z, alpha0, window, grid, T):
    """Algorithm 2 as a plain loop (one series)."""
    n = len(z)
    xs, vs, xp = [0.0] * n, [0.0] * n, [0.0] * n
    xs[0], xp[0], vs[0] = z[0], z[0], 0.0
    xs[1], xp[1], vs[1] = z[1], z[1], (z[1] - z[0]) / T
    a = alpha0
    used = [np.nan, np.nan]
    for k in range(2, n):
        p = xs[k - 1] + T * vs[k - 1]
        e = z[k] - p
        xp[k] = p
        used.append(a)
        xs[k] = p + a * e
        vs[k] = vs[k - 1] + bb(a) / T * e
        s = k - window + 1
        if s >= 2 and k + 1 < n:
            costs = []
            for g in grid:
                x, v, c = xs[s - 1], vs[s - 1], 0.0
                for j in range(s, k + 1):
                    pj = x + T * v
                    ej = z[j] - pj
                    c += ej * ej
                    x = pj + g * ej
                    v = v + bb(g) / T * ej
                costs.append(c)
            a = grid[int(np.argmin(costs))]
    return np.array(xp), np.array(used)


@pytest.mark.parametrize("window", [1, 4, 9])
def test_m4_equals_the_literal_algorithm_2(window):
    z, _ = _series(runs=3, n=24, seed=window)
    grid = [0.1, 0.3, 0.6, 0.9]
    res = methods.m4(z, 0.2, window, grid, dt=2.0)
    for r in range(3):
        xp, used = literal_m4(z[r], 0.2, window, grid, 2.0)
        np.testing.assert_allclose(res.x_pred[r], xp, rtol=1e-12, atol=1e-9)
        np.testing.assert_array_equal(np.isnan(res.param[r]), np.isnan(used))
        np.testing.assert_allclose(res.param[r, 2:], used[2:])


def test_m4_with_a_one_point_grid_is_m1():
    z, _ = _series()
    np.testing.assert_allclose(
        methods.m4(z, 0.4, 5, [0.4]).x_pred, methods.m1(z, 0.4).x_pred, rtol=1e-13
    )


def literal_m5(z, alphas, T, causal=False, memory=1):
    """Algorithm 3 as a plain loop (one series): K independent trackers, pick per step."""
    preds = [literal_tracker(z, [a] * len(z), [bb(a)] * len(z), T) for a in alphas]
    out, choice = [], []
    for k in range(len(z)):
        if not causal:
            scores = [abs(z[k] - p[k]) for p in preds]  # step 3: lowest absolute error
        else:
            lo = max(k - memory, 0)
            scores = [sum(abs(z[j] - p[j]) for j in range(lo, k)) for p in preds]
        j = int(np.argmin(scores))
        choice.append(j)
        out.append(preds[j][k])
    return np.array(out), np.array(choice)


@pytest.mark.parametrize("causal, memory", [(False, 1), (True, 1), (True, 4)])
def test_m5_bank_and_choice_equal_the_literal_algorithm_3(causal, memory):
    z, _ = _series(runs=3, n=30, seed=7)
    bank = [0.05, 0.2, 0.5, 0.8, 1.0]
    res = methods.m5(z, bank, dt=1.0, causal=causal, memory=memory)
    for r in range(3):
        xp, ch = literal_m5(z[r], bank, 1.0, causal, memory)
        np.testing.assert_allclose(res.x_pred[r], xp, rtol=1e-12, atol=1e-9)
        np.testing.assert_array_equal(res.param[r], ch)


def test_m5_noncausal_is_never_worse_against_the_measurement_than_any_bank_member():
    z, _ = _series(runs=4, n=40, seed=9)
    bank = np.linspace(0.05, 1.0, 8)
    res = methods.m5(z, bank)
    for a in bank:
        single = methods.m1(z, a).x_pred
        assert np.all(np.abs(z - res.x_pred) <= np.abs(z - single) + 1e-12)


def test_causal_m5_does_not_look_at_the_current_measurement():
    z, _ = _series(runs=1, n=30, seed=5)
    bank = [0.1, 0.5, 1.0]
    base = methods.m5(z, bank, causal=True, memory=2)
    nc0 = methods.m5(z, bank)
    # move the current measurement onto the prediction of another tracker of the bank
    other = (int(nc0.param[0, 20]) + 1) % 3
    z2 = z.copy()
    z2[0, 20] = methods.m1(z, bank[other]).x_pred[0, 20]
    moved = methods.m5(z2, bank, causal=True, memory=2)
    # the choice and the prediction at k = 20 do not change; the non-causal rule's do
    assert moved.param[0, 20] == base.param[0, 20]
    assert moved.x_pred[0, 20] == base.x_pred[0, 20]
    assert methods.m5(z2, bank).param[0, 20] == other != nc0.param[0, 20]


@settings(max_examples=25, deadline=None)
@given(
    runs=st.integers(1, 4),
    n=st.integers(3, 30),
    seed=st.integers(0, 2**31),
    window=st.integers(1, 6),
)
def test_batching_equals_looping(runs, n, seed, window):
    z = np.random.default_rng(seed).normal(0, 10, size=(2, runs, n)).cumsum(axis=-1)
    calls = [
        lambda x: methods.m1(x, 0.3),
        lambda x: methods.m2(x),
        lambda x: methods.m3(x, [0.0, 0.5, 1.0]),
        lambda x: methods.m4(x, 0.3, window, [0.1, 0.5, 1.0]),
        lambda x: methods.m5(x, [0.1, 0.5, 1.0]),
        lambda x: methods.m5(x, [0.1, 0.5, 1.0], causal=True, memory=2),
    ]
    for f in calls:
        batched = f(z)
        for i in range(2):
            for r in range(runs):
                single = f(z[i, r])
                np.testing.assert_allclose(batched.x_pred[i, r], single.x_pred, rtol=1e-12)
                if single.param is not None:
                    np.testing.assert_array_equal(batched.param[i, r], single.param)


# --------------------------------------------------------------------------- metrics
def test_rmse_and_percentage_change_reproduce_the_printed_table5_entry():
    # Table 1, experiment 1, X: M1 28.4589, M3 26.6802; Table 5 prints 6.2501 (eq 27)
    assert methods.percentage_change(28.4589, 26.6802) == pytest.approx(6.2501, abs=5e-5)
    assert methods.rmse([1.0, 2.0, 3.0], [1.0, 0.0, 3.0]) == pytest.approx(2 / np.sqrt(3))


@pytest.mark.parametrize(
    "call, match",
    [
        (lambda z: methods.m1(z, 1.5), r"alpha must satisfy 0 < alpha <= 1, got 1.5"),
        (lambda z: methods.m3(z, [0.5, 1.2]), r"w_grid must satisfy 0 <= w_grid <= 1, got 1.2"),
        (lambda z: methods.m4(z, 0.2, 0, [0.5]), r"window must be an integer >= 1, got 0"),
        (lambda z: methods.m4(z, 0.2, 3, [0.0, 0.5]), r"alpha_grid must satisfy 0 < alpha_grid"),
        (lambda z: methods.m5(z, [0.5], memory=0), r"memory must be an integer >= 1, got 0"),
        (lambda z: methods.m2(z[..., :2]), r"at least 3 samples"),
        (lambda z: methods.m1(z, 0.5, dt=-1.0), r"dt must be > 0, got -1.0"),
    ],
)
def test_bad_input_raises_naming_the_value(call, match):
    z, _ = _series()
    with pytest.raises(AbglibValueError, match=match):
        call(z)


def _m4_array_form(z, alpha0, window, grid, dt):
    """M4 as the array program it was before the numba kernel (the bit-for-bit reference)."""
    bgrid = grid**2 / (2.0 - grid)
    gshape = (grid.size,) + (1,) * (z.ndim - 1)
    ga, gb = grid.reshape(gshape), bgrid.reshape(gshape)
    n, batch = z.shape[-1], z.shape[:-1]
    xs, vs, xp = np.empty(z.shape), np.empty(z.shape), np.empty(z.shape)
    used = np.full(z.shape, np.nan)
    xs[..., 0], vs[..., 0], xp[..., 0] = z[..., 0], 0.0, z[..., 0]
    xs[..., 1], vs[..., 1], xp[..., 1] = z[..., 1], (z[..., 1] - z[..., 0]) / dt, z[..., 1]
    a, b = np.full(batch, alpha0), np.full(batch, alpha0**2 / (2.0 - alpha0))
    for k in range(2, n):
        p = xs[..., k - 1] + dt * vs[..., k - 1]
        r = z[..., k] - p
        xp[..., k], used[..., k] = p, a
        xs[..., k] = p + a * r
        vs[..., k] = vs[..., k - 1] + (b / dt) * r
        s = k - window + 1
        if s >= 2 and k + 1 < n:
            x = np.broadcast_to(xs[..., s - 1], gshape[:1] + batch)
            v = np.broadcast_to(vs[..., s - 1], gshape[:1] + batch)
            cost = np.zeros(gshape[:1] + batch)
            for j in range(s, k + 1):
                pj = x + dt * v
                rj = z[..., j] - pj
                cost = cost + rj * rj
                x = pj + ga * rj
                v = v + (gb / dt) * rj
            best = np.argmin(cost, axis=0)
            a, b = grid[best], bgrid[best]
    return xp, used


@pytest.mark.parametrize(
    "shape, window, dt", [((3, 4, 60), 10, 0.5), ((80,), 1, 2.0), ((5, 40), 7, 1.0)]
)
def test_m4_kernel_equals_the_array_form_bit_for_bit(shape, window, dt):
    rng = np.random.default_rng(7)
    z = np.cumsum(rng.standard_normal(shape), axis=-1) + rng.standard_normal(shape)
    grid = np.linspace(0.05, 1.0, 20)
    got = methods.m4(z, 0.1, window, grid, dt)
    xp, used = _m4_array_form(z, 0.1, window, grid, dt)
    np.testing.assert_array_equal(got.x_pred, xp)
    np.testing.assert_array_equal(got.param, used)


def _m3_array_form(z, grid, dt):
    """M3 as the array program it was before its kernel (the bit-for-bit reference): the
    bank through track(), the costs by np.mean, the choice by np.argmin."""
    from abglib.engine import track

    n = z.shape[-1]
    g = methods.m3_gains(n, grid)
    shape = (grid.size,) + (1,) * (z.ndim - 1) + (n,)
    bank = track(z, Gains(g.alpha, g.beta.reshape(shape)), dt=dt, init="two_point").x_pred
    best = np.argmin(np.mean((z - bank)[..., 2:] ** 2, axis=-1), axis=0)
    return np.take_along_axis(bank, best[None, ..., None], axis=0)[0], grid[best]


@pytest.mark.parametrize(
    "shape, dt",
    # n - 2 below 8, within numpy's pairwise block of 128, at its end, beyond (its halves)
    [
        ((3, 4, 60), 1.0),
        ((80,), 0.37),
        ((5, 9), 2.0),
        ((2, 3), 1.0),
        ((2, 130), 1.0),
        ((4, 300), 0.5),
    ],
)
def test_m3_kernel_equals_the_array_form_bit_for_bit(shape, dt):
    rng = np.random.default_rng(13)
    z = np.cumsum(rng.standard_normal(shape), axis=-1) * 10 + rng.standard_normal(shape)
    # a repeated weight ties: the first of the two, as np.argmin
    for grid in (np.linspace(0.0, 1.0, 21), np.array([0.3, 0.3, 0.0, 1.0])):
        got = methods.m3(z, grid, dt)
        xp, w = _m3_array_form(z, grid, dt)
        np.testing.assert_array_equal(got.x_pred, xp)
        np.testing.assert_array_equal(got.param, w)
        assert got.x_pred.shape == z.shape and got.param.shape == z.shape[:-1]


def test_pairwise_sum_is_numpys_sum_to_the_bit():
    """The sum M3's kernel ranks its costs by (and the benchmark metrics sum by):
    numpy's pairwise summation, in blocks of up to 128 values and halves above."""
    from abglib._kernels import pairwise_sum, pairwise_workspace

    rng = np.random.default_rng(17)
    wi, wf = pairwise_workspace()
    for n in [*range(0, 300), 1000, 4099, 10_007]:
        a = rng.standard_normal(n + 3) ** 2 * rng.lognormal(0.0, 3.0)
        assert pairwise_sum(a, 3, n, wi, wf) == np.sum(a[3:]), n


def _m5_array_form(z, grid, dt, causal, memory):
    """M5 as the array program it was before the numba kernel (the bit-for-bit reference)."""
    from abglib.design import benedict_bordner
    from abglib.engine import track

    shape = (grid.size,) + (1,) * z.ndim
    bb = benedict_bordner(grid.reshape(shape))
    bank = track(z, bb, dt=dt, init="two_point", outputs=("x_pred",)).x_pred
    err = np.abs(z - bank)
    if causal:
        csum = np.cumsum(err, axis=-1)
        csum = np.concatenate([np.zeros(csum.shape[:-1] + (1,)), csum], axis=-1)
        k = np.arange(z.shape[-1])
        score = csum[..., k] - csum[..., np.maximum(k - memory, 0)]
    else:
        score = err
    choice = np.argmin(score, axis=0)
    return np.take_along_axis(bank, choice[None], axis=0)[0], choice


@pytest.mark.parametrize(
    "shape, causal, memory",
    [((3, 4, 60), False, 1), ((80,), True, 1), ((5, 40), True, 3), ((2, 50), True, 70)],
)
def test_m5_kernel_equals_the_array_form_bit_for_bit(shape, causal, memory):
    rng = np.random.default_rng(11)
    z = np.cumsum(rng.standard_normal(shape), axis=-1) + rng.standard_normal(shape)
    grid = np.linspace(0.05, 1.0, 20)
    got = methods.m5(z, grid, 0.5, causal=causal, memory=memory)
    xp, choice = _m5_array_form(z, grid, 0.5, causal, memory)
    np.testing.assert_array_equal(got.x_pred, xp)
    np.testing.assert_array_equal(got.param, choice)
    assert got.param.dtype == choice.dtype
