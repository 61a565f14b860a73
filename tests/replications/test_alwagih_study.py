"""The seed 001 study (abglib.replications.alwagih): tables, statistics, printed-table check,
the reconstruction knobs and the RMSE cache."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from scipy import stats

from abglib import methods
from abglib.bench import datasets
from abglib.replications.alwagih import printed as printed_tables
from abglib.replications.alwagih import study as alwagih

CFG = {
    "m1_alpha": 0.2,
    "m3_w_grid": {"start": 0.0, "stop": 1.0, "n": 3},
    "m4": {"alpha0": 0.2, "window": 4, "alpha_grid": {"start": 0.1, "stop": 1.0, "n": 4}},
    "m5": {"alphas": {"start": 0.1, "stop": 1.0, "n": 4}, "causal_memory": 2},
    "kalman": {"sigma_a_floor": 0.1},
}


def _dataset(seed, colour="white"):
    noise = {"sigma": 5.0, "colour": colour}
    if colour == "ar1":
        noise["rho"] = 0.5
    spec = {
        "dt": 1.0,
        "n_samples": 30,
        "runs": 6,
        "seed": seed,
        "noise": noise,
        "tracks": {
            "x": {"kind": "constant_velocity", "p0": 0.0, "v0": 50.0},
            "y": {
                "kind": "segments",
                "p0": 0.0,
                "v0": 0.0,
                "segments": [{"t_start": 0.0, "t_end": 5.0, "acc": 10.0}],
            },
        },
    }
    return datasets.generate(f"d{seed}", spec)


def test_compare_methods_rmse_equals_the_methods_directly():
    data = {"white": [_dataset(1), _dataset(2)], "coloured": [_dataset(3, "ar1")]}
    table = alwagih.compare_methods(data, CFG)
    assert set(table["method"]) == set(alwagih.METHODS)
    assert len(table) == (2 + 1) * 2 * len(alwagih.METHODS) * 6
    ds = data["white"][1]
    got = table[
        (table["noise"] == "white")
        & (table["experiment"] == 2)
        & (table["coord"] == "Y")
        & (table["method"] == "M4")
    ]["rmse"].to_numpy()
    want = methods.rmse(
        methods.m4(ds.z["y"], 0.2, 4, np.linspace(0.1, 1.0, 4), 1.0).x_pred, ds.truth_pos["y"]
    )
    np.testing.assert_allclose(got, want, rtol=1e-15)


def test_mc_summary_interval_is_the_student_t_interval():
    rng = np.random.default_rng(4)
    x = rng.normal(10, 2, 37)
    df = pd.DataFrame(
        {
            "noise": "white",
            "experiment": 1,
            "coord": "X",
            "method": "M1",
            "run": range(37),
            "rmse": x,
        }
    )
    s = alwagih.mc_summary(df, 0.9).iloc[0]
    lo, hi = stats.t.interval(0.9, 36, loc=x.mean(), scale=stats.sem(x))
    assert s["mean"] == pytest.approx(x.mean())
    assert s["ci_low"] == pytest.approx(lo) and s["ci_high"] == pytest.approx(hi)


def test_mc_summary_is_the_grouped_mean_std_and_interval_bit_for_bit():
    # groups interleaved, of unequal sizes and one of a single run (NaN spread); the route
    # is pandas' groupby(...).agg of numpy's reductions of each group (the bits the former
    # groupby(...).apply gave), and the interval is scipy's
    rng = np.random.default_rng(11)
    keys = [("white", 1, "X", "M1"), ("coloured", 2, "Y", "M5"), ("white", 1, "Y", "M1")]
    sizes = [7, 12, 1]
    rows = [k for k, n in zip(keys, sizes, strict=True) for _ in range(n)]
    order = rng.permutation(len(rows))
    df = pd.DataFrame(
        [rows[i] for i in order], columns=["noise", "experiment", "coord", "method"]
    ).assign(run=0, rmse=rng.gamma(2.0, 30.0, len(rows)))
    got = alwagih.mc_summary(df, 0.95)
    g = df.groupby(["noise", "experiment", "coord", "method"], sort=False)["rmse"]
    want = g.agg(
        size="size",
        mean=lambda x: x.to_numpy().mean(),
        std=lambda x: x.to_numpy().std(ddof=1) if x.size > 1 else np.nan,
    ).reset_index()
    assert list(got.columns) == [*want.columns[:4], "runs", "mean", "std", "ci_low", "ci_high"]
    assert got[want.columns[:4]].equals(want[want.columns[:4]])  # dtypes included
    first_seen = df[list(want.columns[:4])].drop_duplicates().reset_index(drop=True)
    assert got[want.columns[:4]].equals(first_seen)
    assert got["runs"].tolist() == want["size"].astype(float).tolist()
    np.testing.assert_array_equal(got["mean"], want["mean"])
    single = got["runs"] == 1.0
    np.testing.assert_array_equal(got["std"][~single], want["std"][~single])
    for i in np.flatnonzero(~single):
        x = df["rmse"][g.indices[tuple(got.iloc[i, :4])]].to_numpy()
        lo, hi = stats.t.interval(0.95, x.size - 1, loc=x.mean(), scale=stats.sem(x))
        assert got["ci_low"][i] == pytest.approx(lo, rel=1e-14)
        assert got["ci_high"][i] == pytest.approx(hi, rel=1e-14)
    assert single.sum() == 1
    assert got.loc[single, ["std", "ci_low", "ci_high"]].isna().all(axis=None)


def _wide(values):
    """(noise=white, experiment, coord=X) x methods table from {method: [per experiment]}."""
    idx = pd.MultiIndex.from_tuples(
        [("white", e, "X") for e in range(1, 6)], names=["noise", "experiment", "coord"]
    )
    return pd.DataFrame(values, index=idx)


def test_differences_ttest_and_percentages_by_hand():
    v = {
        "M1": [30.0, 40.0, 35.0, 50.0, 45.0],
        "M2": [20.0, 30.0, 33.0, 20.0, 41.0],
        "M3": [21.0, 29.0, 30.0, 22.0, 40.0],
        "M4": [25.0, 20.0, 15.0, 30.0, 20.0],
        "M5": [10.0, 11.0, 12.0, 10.0, 13.0],
    }
    wide = _wide(v)
    d = alwagih.paper_differences(wide).set_index(["base", "method"])["mean_difference"]
    assert d[("M1", "M4")] == pytest.approx(np.mean(np.subtract(v["M1"], v["M4"])))
    assert d[("M2", "M3")] == pytest.approx(np.mean(np.subtract(v["M2"], v["M3"])))
    t = alwagih.paired_ttests(wide).set_index(["base", "method"])
    diff = np.subtract(v["M1"], v["M5"])
    t_hand = diff.mean() / (diff.std(ddof=1) / np.sqrt(5))
    assert t.loc[("M1", "M5"), "t"] == pytest.approx(t_hand)
    assert t.loc[("M1", "M5"), "p_value"] == pytest.approx(2 * stats.t.sf(abs(t_hand), 4))
    pc = alwagih.paper_percentages(wide)
    np.testing.assert_allclose(pc["M3"], (np.array(v["M1"]) - v["M3"]) / np.array(v["M1"]) * 100)
    assert alwagih.rank_methods(wide.mean().to_dict()) == "M5<M4<M3<M2<M1"


def test_printed_consistency_reproduces_the_paper_where_it_is_consistent():
    # Table 1 (seed 001), experiment 1, X and Y, as printed; other experiments zero-filled
    rows = []
    printed = {
        ("X", 1): [28.4589, 26.6355, 26.6802, 25.3460, 10.4094],
        ("Y", 1): [291.7924, 63.6673, 66.8815, 265.2983, 17.7988],
    }
    for noise in ("white", "coloured"):
        for (c, e), vals in printed.items():
            for m, val in zip(alwagih.PAPER_METHODS, vals, strict=True):
                rows.append(
                    {
                        "noise": noise,
                        "experiment": e,
                        "coord": c,
                        "method": m,
                        "value": val,
                        "half_unit": 5e-5,
                    }
                )
    out = printed_tables.printed_consistency(pd.DataFrame(rows))
    r = out[(out["table"] == 5) & (out["coord"] == "X") & (out["method"] == "M3")].iloc[0]
    # Table 5 prints 6.2501 for experiment 1, X, M3
    assert r["central"] == pytest.approx(6.2501, abs=5e-5)
    assert r["low"] <= r["central"] <= r["high"]
    # one experiment: the average difference is the difference, and its rounding interval
    # is +- (half unit of each input) = +- 1e-4
    d = out[(out["table"] == 3) & (out["row"] == "M1") & (out["coord"] == "Y")]
    d = d.set_index("method")
    assert d.loc["M5", "central"] == pytest.approx(291.7924 - 17.7988)
    assert d.loc["M5", "high"] - d.loc["M5", "low"] == pytest.approx(2e-4)


def test_printed_consistency_needs_its_columns():
    with pytest.raises(ValueError, match="t12 needs columns"):
        printed_tables.printed_consistency(pd.DataFrame({"noise": []}))


SCENARIOS = {
    "w": {
        "dt": 1.0,
        "n_samples": 20,
        "runs": 3,
        "seed": 1,
        "noise": {"sigma": 4.0, "colour": "white"},
        "tracks": {
            "x": {"kind": "constant_acceleration", "p0": 0.0, "v0": 1.0, "a0": 0.5},
            "y": {
                "kind": "segments",
                "p0": 0.0,
                "v0": 0.0,
                "segments": [{"t_start": 0.0, "t_end": 5.0, "acc": 2.0}],
            },
        },
    },
    "c": {
        "dt": 1.0,
        "n_samples": 20,
        "runs": 3,
        "seed": 2,
        "noise": {"sigma": 4.0, "colour": "ar1", "rho": 0.7},
        "tracks": {"x": {"kind": "constant_velocity", "p0": 0.0, "v0": 1.0}},
    },
}
AW = {"experiments": {"white": ["w"], "coloured": ["c"]}}


def test_reconstruction_knobs_at_one_leave_the_scenarios_unchanged():
    cfg = dict(AW, reconstruction={"noise_scale": 1.0, "manoeuvre_scale": 1.0, "coloured_rho": 0.7})
    out = alwagih.reconstructed_scenarios(SCENARIOS, cfg)
    assert out["white"] == [("w", SCENARIOS["w"])] and out["coloured"] == [("c", SCENARIOS["c"])]


def test_reconstruction_knobs_scale_noise_and_accelerations_and_set_rho():
    cfg = dict(AW, reconstruction={"noise_scale": 2.0, "manoeuvre_scale": 0.5, "coloured_rho": 0.3})
    out = alwagih.reconstructed_scenarios(SCENARIOS, cfg)
    w = out["white"][0][1]
    assert w["noise"]["sigma"] == 8.0
    assert w["tracks"]["x"]["a0"] == 0.25 and w["tracks"]["y"]["segments"][0]["acc"] == 1.0
    assert out["coloured"][0][1]["noise"] == {"sigma": 8.0, "colour": "ar1", "rho": 0.3}
    assert SCENARIOS["w"]["noise"]["sigma"] == 4.0  # the config is not modified


def test_run_method_refuses_an_unknown_method():
    with pytest.raises(ValueError, match="method must be one of"):
        alwagih.run_method("M9", np.zeros((1, 5)), np.zeros(5), 1.0, 1.0, CFG)


def test_sensitivity_sets_alpha0_of_m1_and_m4_together():
    seen = []

    def mean_rmse(cfg):
        seen.append((cfg["m1_alpha"], cfg["m4"]["alpha0"], cfg["m4"]["window"]))
        idx = pd.MultiIndex.from_tuples(
            [("white", "X", m) for m in alwagih.PAPER_METHODS], names=["noise", "coord", "method"]
        )
        return pd.Series([5.0, 4.0, 3.0, 2.0, 1.0], index=idx)

    t = alwagih.sensitivity(mean_rmse, CFG, [0.05, 0.3], [4, 8])
    assert seen == [(0.05, 0.05, 4), (0.05, 0.05, 8), (0.3, 0.3, 4), (0.3, 0.3, 8)]
    assert t["M5_then_M4_then_M3"].all() and set(t["ranking"]) == {"M5<M4<M3<M2<M1"}
