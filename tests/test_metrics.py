"""abglib.bench.metrics and abglib.bench.benchmark: each number against an independent route."""

import numpy as np
import pandas as pd
import pytest
import scipy.signal
from hypothesis import given, settings
from hypothesis import strategies as st

from abglib import AbglibValueError, Gains, analysis, track
from abglib.analysis._statespace import state_space
from abglib.bench.benchmark import check_cell, league_table, run_cell, tradeoff_table
from abglib.bench.metrics import (
    OUTPUTS,
    VRFMismatchError,
    coloured_vrf,
    evaluate_cell,
    fail_threshold,
    settle_samples,
    v_pred,
)
from abglib.simulate import ar1_noise

from .strategies import stable_gain_strategies, standard_ab, standard_abg

STABLE_AB, STABLE_ABG = stable_gain_strategies(0.9, 1e-3)


def direct_sum(gains, output, rho, dt=1.0, n=3000):
    """sum_k sum_l h_k h_l rho^|k-l| from the impulse response (scipy.signal.lfilter)."""
    num, den = analysis.transfer_function(gains, output, dt)
    imp = np.zeros(n)
    imp[0] = 1.0
    h = scipy.signal.lfilter(num, den, imp)
    # the AR(1) autocovariance rho^|j| as a filter: sum_j rho^|j| c_j, c_j = sum_k h_k h_{k+j}
    c = np.correlate(h, h, mode="full")[n - 1 :]
    return float(c[0] + 2.0 * np.sum(c[1:] * rho ** np.arange(1, n)))


@settings(max_examples=40, deadline=None)
@given(g=st.one_of(STABLE_AB, STABLE_ABG), rho=st.floats(-0.9, 0.9))
def test_coloured_vrf_equals_direct_summation(g, rho):
    got = coloured_vrf(g, rho)
    for o in ("x_smooth", "x_pred", "v_smooth"):
        assert got[o] == pytest.approx(direct_sum(g, o, rho), rel=1e-7, abs=1e-12)


@settings(max_examples=20, deadline=None)
@given(g=st.one_of(STABLE_AB, STABLE_ABG), dt=st.sampled_from([0.5, 1.0, 3.0]))
def test_coloured_vrf_white_is_lyapunov(g, dt):
    a, b = coloured_vrf(g, 0.0, dt), analysis.vrf(g, dt)
    for k in b:
        assert a[k] == pytest.approx(b[k], rel=1e-9, abs=1e-15)


def test_coloured_vrf_errors():
    with pytest.raises(AbglibValueError, match="rho must satisfy -1 < rho < 1"):
        coloured_vrf(standard_ab(0.5), 1.0)
    with pytest.raises(AbglibValueError, match="unstable"):
        coloured_vrf(Gains(1.0, 2.5), 0.5)


def test_settle_samples():
    # pole radius 0.5 (standard alpha-beta theta = 0.5): ceil(ln 1e-8 / ln 0.5) = 27
    assert settle_samples(standard_ab(0.5)) == 27
    assert settle_samples(Gains(1.0, 1.0)) == 0  # deadbeat
    assert settle_samples(Gains(1.0, 2.5), cap=99) == 99  # unstable


def test_fail_threshold():
    # one check: the two-sided t quantile; more checks: wider
    assert fail_threshold(11, 1, 0.05) == pytest.approx(2.228138852, rel=1e-8)  # t_{10, .975}
    assert fail_threshold(11, 100, 0.05) > fail_threshold(11, 1, 0.05)
    with pytest.raises(AbglibValueError, match="runs must be >= 2"):
        fail_threshold(1, 1, 0.05)


def test_v_pred_matches_the_recursion():
    g = standard_abg(0.6)
    z = np.random.default_rng(0).normal(size=50).cumsum()
    r = track(z, g, dt=0.5)
    vp = v_pred(r.v_smooth, r.a_smooth, 0.5)
    # independent route: the state-space transition Phi of abglib.analysis applied to the
    # smoothed state; its first row must give the engine's own x_pred, its second v_pred
    phi = state_space(g, 0.5).Phi
    pred = np.stack([r.x_smooth, r.v_smooth, r.a_smooth])[:, :-1]
    pred = phi @ pred
    assert r.x_pred[1:] == pytest.approx(pred[0], rel=1e-12, abs=1e-12)
    assert vp[1:] == pytest.approx(pred[1], rel=1e-12, abs=1e-12)


def _coords(truth_fn, runs, n, dt, noise, sigma):
    t = np.arange(n) * dt
    pos, vel = truth_fn(t)
    return {
        "x": {
            "truth_pos": np.broadcast_to(pos, (runs, n)),
            "truth_vel": np.broadcast_to(vel, (runs, n)),
            "z": pos + noise,
            "sigma": sigma,
        }
    }


def test_noise_free_lag_is_the_closed_form():
    # constant acceleration A, alpha-beta: steady-state prediction lag A T^2 / beta (seed 000
    # eq 41 / abglib.analysis.steady_state_lag), error = estimate - truth = -lag
    A, dt, n = 2.0, 0.5, 600
    g = standard_ab(0.7)
    coords = _coords(lambda t: (A * t**2 / 2, A * t), 3, n, dt, np.zeros((3, n)), 1.0)
    row = evaluate_cell(coords, dt, gains=g, burn_in=400)[0]
    lag = analysis.steady_state_lag(g, dt, kind="acceleration", magnitude=A, output="x_pred")
    assert row["lag_x_pred"] == pytest.approx(-lag, rel=1e-9)
    assert row["rmse_x_pred"] == pytest.approx(lag, rel=1e-9)
    assert row["noise_rms_x_pred"] == 0.0
    assert row["lag_rms_x_pred"] == pytest.approx(lag, rel=1e-9)


@pytest.mark.parametrize("g", [standard_ab(0.8), standard_abg(0.7), Gains(0.465, 0.3)])
def test_white_noise_vrf_inside_interval(g):
    runs, n, dt, sigma = 400, 600, 2.0, 3.0
    noise = np.random.default_rng(7).normal(0.0, sigma, (runs, n))
    coords = _coords(lambda t: (100 + 5 * t, 5 + 0 * t), runs, n, dt, noise, sigma)
    row = evaluate_cell(coords, dt, gains=g, noise={"model": "white"}, burn_in=5)[0]
    exact = analysis.vrf(g, dt)
    thr = fail_threshold(runs, 8, 0.001)
    for o in ("x_smooth", "x_pred", "v_smooth", "v_pred"):
        assert row[f"vrf_{o}_theory"] == pytest.approx(exact[o], rel=1e-12)
        assert abs(row[f"vrf_{o}_t"]) < thr
        # the CI is built from the across-run spread: its width ~ 1/sqrt(runs) of a
        # per-run spread that is far larger than the naive pooled-sample one
        naive_se = row[f"vrf_{o}_measured"] * np.sqrt(2.0 / (runs * (n - row["vrf_from_sample"])))
        assert row[f"vrf_{o}_se"] > naive_se


def test_ar1_noise_vrf_inside_interval():
    runs, n, dt, sigma, rho = 400, 600, 1.0, 2.0, 0.8
    g = standard_ab(0.8)
    noise = ar1_noise((runs, n), sigma, rho, 3)
    coords = _coords(lambda t: (0 * t, 0 * t), runs, n, dt, noise, sigma)
    row = evaluate_cell(coords, dt, gains=g, noise={"model": "ar1", "rho": rho}, burn_in=5)[0]
    for o in ("x_smooth", "v_smooth"):
        assert abs(row[f"vrf_{o}_t"]) < fail_threshold(runs, 8, 0.001)
        assert row[f"vrf_{o}_theory"] == pytest.approx(coloured_vrf(g, rho)[o], rel=1e-12)


def test_unstable_gains_diverge():
    runs, n = 2, 300
    noise = np.random.default_rng(1).normal(size=(runs, n))
    coords = _coords(lambda t: (t, 1 + 0 * t), runs, n, 1.0, noise, 1.0)
    rows = evaluate_cell(coords, 1.0, gains=Gains(1.0, 2.5), noise={"model": "white"})
    assert all(r["diverged"] for r in rows)
    assert rows[0]["stable"] is False
    assert rows[0]["rmse_x_pred"] is None and rows[-1]["rmse_x_smooth"] is None


def test_runner_path_equals_gains_path():
    runs, n = 5, 100
    g = standard_ab(0.6)
    noise = np.random.default_rng(2).normal(size=(runs, n))
    coords = _coords(lambda t: (t**2 / 10, t / 5), runs, n, 1.0, noise, 1.0)
    a = evaluate_cell(coords, 1.0, gains=g, burn_in=10)[0]
    b = evaluate_cell(coords, 1.0, runner=lambda z: track(z, g, init="two_point"), burn_in=10)[0]
    for k in ("rmse_x_smooth", "max_x_pred", "lag_v_smooth", "rmse_v_pred"):
        assert a[k] == pytest.approx(b[k], rel=1e-12)
    assert b["noise_rms_x_smooth"] is None


def test_chunks_do_not_change_the_result():
    runs, n = 7, 200
    g = standard_abg(0.7)
    noise = np.random.default_rng(3).normal(size=(runs, n))
    coords = _coords(lambda t: (t, 1 + 0 * t), runs, n, 1.0, noise, 1.0)
    a = evaluate_cell(coords, 1.0, gains=g, noise={"model": "white"}, chunk_runs=1000)
    b = evaluate_cell(coords, 1.0, gains=g, noise={"model": "white"}, chunk_runs=3)
    for ra, rb in zip(a, b, strict=True):
        for k, v in ra.items():
            if isinstance(v, float):
                assert rb[k] == pytest.approx(v, rel=1e-12), k


@pytest.mark.parametrize("gains", [standard_ab(0.6), standard_abg(0.5)], ids=["ab", "abg"])
@pytest.mark.parametrize("subset", [("x_smooth",), ("v_pred",), ("x_pred", "v_smooth")])
def test_scoring_some_outputs_gives_the_same_bits(gains, subset):
    # the trade-off sweep scores x_smooth alone (the tracker computes only that output):
    # the columns it gets must be those of the full cell, bit for bit
    runs, n = 6, 300
    noise = np.random.default_rng(4).normal(size=(runs, n))
    coords = {
        **_coords(lambda t: (t**2 / 10, t / 5), runs, n, 0.5, noise, 1.0),
        "y": _coords(lambda t: (3 * t, 3 + 0 * t), runs, n, 0.5, noise[::-1], 1.0)["x"],
    }
    kw = dict(gains=gains, noise={"model": "white"}, burn_in=20)
    full = evaluate_cell(coords, 0.5, **kw)
    some = evaluate_cell(coords, 0.5, outputs=subset, **kw)
    others = [o for o in OUTPUTS if o not in subset]
    for rf, rs in zip(full, some, strict=True):
        assert not [k for k in rs if any(k.endswith(o) or f"_{o}_" in k for o in others)]
        assert rs == {k: rf[k] for k in rs}


def test_evaluate_cell_names_bad_outputs():
    coords = _coords(lambda t: (t, 1 + 0 * t), 2, 10, 1.0, np.zeros((2, 10)), 1.0)
    for bad in (("x_smooth", "a_pred"), (), ("x_pred", "x_pred")):
        with pytest.raises(AbglibValueError, match="outputs must be distinct names from"):
            evaluate_cell(coords, 1.0, gains=standard_ab(0.5), outputs=bad)


def test_evaluate_cell_errors():
    coords = _coords(lambda t: (t, 1 + 0 * t), 2, 10, 1.0, np.zeros((2, 10)), 1.0)
    with pytest.raises(AbglibValueError, match="exactly one of gains and runner"):
        evaluate_cell(coords, 1.0)
    with pytest.raises(AbglibValueError, match="burn_in must satisfy 0 <= burn_in < 10"):
        evaluate_cell(coords, 1.0, gains=standard_ab(0.5), burn_in=10)


class FakeDataset:
    """The fields of abglib.bench.datasets.Dataset that run_cell reads."""

    def __init__(self, name, noise_claimed, noise, truth, dt=1.0):
        runs, n = noise.shape
        self.name, self.dt, self.t = name, dt, np.arange(n) * dt
        self.coords = ("x",)
        self.truth_pos = {"x": np.broadcast_to(truth, (runs, n))}
        self.truth_vel = {"x": np.zeros((runs, n))}
        self.z = {"x": truth + noise}
        self.noise = noise_claimed


def test_build_check_fails_on_wrong_theory():
    # white-noise theory applied to strongly coloured noise: the measured VRF is far off,
    # and the check must stop the build
    runs, n = 100, 400
    noise = ar1_noise((runs, n), 1.0, 0.9, 11)
    ds = FakeDataset("wrong", {"sigma": 1.0, "colour": "white", "rho": 0.0}, noise, 0.0)
    cell = run_cell(ds, {"rule": "standard_alpha", "alpha": 0.3}, "std")
    with pytest.raises(VRFMismatchError, match=r"(?s)variant 'std' on scenario 'wrong'.*x_smooth"):
        check_cell(cell, fail_threshold(runs, 10000, 0.001))
    # the honest description passes
    ds = FakeDataset("right", {"sigma": 1.0, "colour": "ar1", "rho": 0.9}, noise, 0.0)
    cell = run_cell(ds, {"rule": "standard_alpha", "alpha": 0.3}, "std")
    check_cell(cell, fail_threshold(runs, 10000, 0.001), colours=("white", "ar1"))


def test_league_and_tradeoff_tables():
    runs, n = 20, 400
    noise = np.random.default_rng(5).normal(size=(runs, n))
    ds = FakeDataset("s", {"sigma": 1.0, "colour": "white", "rho": 0.0}, noise, np.zeros(n))
    cells = [
        run_cell(ds, {"rule": "standard_theta", "theta": th}, f"th{th}", burn_in=150)
        for th in (0.5, 0.9)
    ] + [run_cell(ds, {"rule": "gains", "alpha": 1.0, "beta": 2.5}, "bad", burn_in=150)]
    league = league_table(cells, threshold=5.0)
    # stationary target: the heavier smoothing (theta 0.9) has the smaller RMSE; diverged last
    assert list(league["variant"]) == ["th0.9", "th0.5", "bad"]
    assert list(league["rank"]) == [1, 2, 3]
    assert list(league["vrf_check"]) == ["pass", "pass", "n/a (unstable)"]
    trade = tradeoff_table(cells)
    assert set(trade["variant"]) == {"th0.5", "th0.9"}
    assert isinstance(trade, pd.DataFrame)
    with pytest.raises(AbglibValueError, match="rank_by must be a metric column"):
        league_table(cells, 5.0, rank_by="nonsense")


def test_noise_description_errors_name_the_problem():
    from abglib.bench.metrics import noise_vrf

    g = Gains(0.5, 0.2)
    with pytest.raises(AbglibValueError, match="noise model must be one of"):
        noise_vrf(g, {"colour": "white"})
    with pytest.raises(AbglibValueError, match="needs 'rho'"):
        noise_vrf(g, {"model": "ar1"})


def _scored(monkeypatch, fast, **kw):
    """evaluate_cell with the compiled scoring (fast) or the numpy form only."""
    import abglib.bench.metrics as mm

    monkeypatch.setattr(mm, "_fast_scoring", lambda cols: fast)
    return mm.evaluate_cell(**kw)


def _same(a, b):
    """Rows equal bit for bit (None, NaN and -0.0 included)."""
    assert len(a) == len(b)
    for ra, rb in zip(a, b, strict=True):
        assert ra.keys() == rb.keys()
        for k in ra:
            x, y = ra[k], rb[k]
            if isinstance(x, float) and isinstance(y, float):
                assert np.float64(x).tobytes() == np.float64(y).tobytes(), (ra["coord"], k, x, y)
            else:
                assert x == y, (ra["coord"], k, x, y)


@pytest.mark.parametrize(
    ("runs", "n", "chunk", "burn_in", "gains", "colour"),
    [
        (300, 400, 128, 10, Gains(0.3, 0.05), "white"),  # strided sums in buffer chunks
        (200, 60, 1000, 10, Gains(0.5, 0.2, 0.02), "ar1"),  # several rows per chunk
        (50, 9000, 1000, 5, Gains(0.2, 0.02), "white"),  # rows longer than the buffer
        (40, 97, 7, 0, Gains(0.4, 0.1, 0.01), "white"),  # no burn-in: contiguous error
        (30, 50, 1000, 3, Gains(1.0, 2.5), "white"),  # unstable: overflow and NaN
        (25, 80, 10, 2, Gains(np.linspace(0.9, 0.3, 80), np.linspace(0.5, 0.05, 80)), "white"),
    ],
)
def test_compiled_scoring_gives_the_numpy_bits(monkeypatch, runs, n, chunk, burn_in, gains, colour):
    """The compiled one-pass scoring (abglib.bench._metric_kernels) returns exactly the
    bits of the numpy form it replaced, for every column of every row."""
    rng = np.random.default_rng(runs + n)
    t = np.arange(n, dtype=float)
    coords = {}
    for c, acc in (("x", 0.0), ("y", 0.3)):
        pos = 100.0 + 20.0 * t + 0.5 * acc * t**2
        noise = rng.standard_normal((runs, n)) * 7.0
        coords[c] = {
            "truth_pos": np.broadcast_to(pos, (runs, n)).copy(),
            "truth_vel": np.broadcast_to(20.0 + acc * t, (runs, n)).copy(),
            "z": pos + noise,
            "sigma": 7.0,
        }
    kw = dict(
        coords=coords,
        dt=1.0,
        gains=gains,
        noise={"model": "white"} if colour == "white" else {"model": "ar1", "rho": 0.5},
        burn_in=burn_in,
        chunk_runs=chunk,
    )
    _same(_scored(monkeypatch, True, **kw), _scored(monkeypatch, False, **kw))
    # a method returning predictions only (the runner path)
    kw.pop("gains")
    kw.pop("noise")
    runner = lambda z: track(z, Gains(0.5, 0.1), init="two_point", outputs=("x_pred",))  # noqa: E731
    kw["runner"] = runner
    _same(_scored(monkeypatch, True, **kw), _scored(monkeypatch, False, **kw))
