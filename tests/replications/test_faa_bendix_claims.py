"""FAA Bendix filter test (seed 003): the program, the memo's closed form, verdicts, damping."""

from __future__ import annotations

import importlib.util
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from abglib import Gains, design, track
from abglib.analysis import vrf
from abglib.replications.faa_bendix import program as bendix
from abglib.reporting.compare import build_comparison, read_published
from abglib.simulate import bendix_impulse, bendix_ramp

ROOT = Path(__file__).resolve().parents[1]


def _script():
    spec = importlib.util.spec_from_file_location(
        "faa_bendix_script", ROOT / "workflow" / "scripts" / "faa_bendix.py"
    )
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


# --------------------------------------------------------------------------- the program
@pytest.mark.parametrize("period", bendix.PERIODS)
def test_inputs_as_the_letter_report_writes_them(period):
    T = float(period)
    imp = bendix_impulse(40, T)
    # "a pulse of amplitude 1/T and width T ... at the first sampling"
    assert imp[0] == 1.0 / T and np.count_nonzero(imp) == 1 and imp.size == 40
    ramp = bendix_ramp(40, T, rise_samples=10)
    # "zero at the first sampling ... raised by the value of T each sampling for 10
    # periods ... then held at zero"
    assert ramp[0] == 0.0 and np.allclose(np.diff(ramp[:11]), T) and ramp[10] == 10 * T
    assert np.all(ramp[11:] == 0.0)


@pytest.mark.parametrize("period", [1, 3, 8])
def test_literal_program_equals_track_with_zero_init(period):
    g = design.bendix(period, "captions")
    for z in (bendix_impulse(40, period), bendix_ramp(40, period)):
        lit = bendix.run_test_program(z, g.alpha, g.beta, period)
        r = track(z, g, dt=period, init="zero")
        for out in ("x_smooth", "v_smooth", "x_pred"):
            np.testing.assert_allclose(lit[out], getattr(r, out), rtol=0, atol=1e-14)


def test_impulse_response_first_samples_by_hand():
    # impulse 1/T at k=0 from zero state: x̄0 = α/T, v̄0 = β/T², x_p1 = x̄0 + T v̄0
    a, b, T = 0.46, 0.30, 3.0
    lit = bendix.run_test_program(bendix_impulse(40, T), a, b, T)
    assert lit["x_pred"][0] == 0.0
    assert lit["x_smooth"][0] == pytest.approx(a / T)
    assert lit["v_smooth"][0] == pytest.approx(b / T**2)
    assert lit["x_pred"][1] == pytest.approx(a / T + b / T)


def test_responses_table_and_sfy():
    r = bendix.responses(design.bendix(2), 2.0)
    assert set(r["input"]) == {"impulse", "ramp"} and len(r) == 80
    assert bendix.sfy("impulse", 5) == 0.10  # captions: SFY= 0.10
    assert bendix.sfy("ramp", 1) == 1.00 and bendix.sfy("ramp", 2) == 10.00
    with pytest.raises(ValueError, match="kind must be one of"):
        bendix.sfy("step", 1)


# --------------------------------------------------------------------------- the memo
@pytest.mark.parametrize("period", bendix.PERIODS)
def test_memo_closed_form_equals_lyapunov(period):
    g = design.bendix(period)
    cf = bendix.memo_ratios(g.alpha, g.beta, period)
    ly = vrf(g, dt=period)
    assert cf["position"] == pytest.approx(np.sqrt(ly["x_smooth"]), rel=1e-12)
    assert cf["velocity"] == pytest.approx(np.sqrt(ly["v_smooth"]), rel=1e-12)


def test_memo_worked_example():
    # memo: T = 3 s, "0.69 x 1 deg = .69 deg" and "0.125 x 1 deg = .125 deg/sec"
    cf = bendix.memo_ratios(0.465, 0.300, 3.0)
    assert round(cf["position"], 2) == 0.69
    assert round(cf["velocity"], 3) == 0.125


def test_memo_closed_form_vs_small_monte_carlo():
    g = design.bendix(4)
    cf = bendix.memo_ratios(g.alpha, g.beta, 4.0)
    mc = bendix.monte_carlo_ratios(g, 4.0, runs=20, samples=5000, burn_in=100, seed=123)
    assert mc["n"] == 100_000
    for k in ("position", "velocity"):
        # 4 standard errors: a seeded test that is not fragile
        z = (mc[f"{k}_var"] - cf[k] ** 2) / mc[f"{k}_var_se"]
        assert abs(z) < 4.0
        assert mc[f"{k}_lo"] < mc[k] < mc[f"{k}_hi"]


def test_memo_ratios_reject_unstable_gains():
    with pytest.raises(ValueError, match="stable pair"):
        bendix.memo_ratios(0.5, 3.5, 1.0)


# --------------------------------------------------------------------------- comparison rows
@pytest.fixture(scope="module")
def comparison(tmp_path_factory):
    mod = _script()
    published = read_published([ROOT / "data" / "published" / "faa_bendix" / "memo.csv"])
    periods = list(bendix.PERIODS)
    mc = {"runs": 4, "samples": 2000, "burn_in": 100, "seed": 7}
    memo = mod.memo_table(published, periods, mc)
    rounding = mod.rounding_table(published, periods, 41)
    rep, alts = mod.reproduced_tables(published, memo, rounding)
    return build_comparison("faa_bendix", published, rep, alts).set_index("item")


def test_row_7s_is_a_match(comparison):
    rows = comparison[comparison.index.str.contains("period 7 s")]
    assert list(rows["verdict"]) == ["match", "match"]


def test_row_1s_position_is_explained_by_rounding(comparison):
    row = comparison.loc[
        comparison.index.str.contains("period 1 s") & comparison.index.str.contains("sigma_xdot")
    ].iloc[0]
    assert row["verdict"] == "explained"
    assert "unrounded gains" in row["note"]
    assert row["abs_err"] == pytest.approx(0.00063, abs=1e-5)


def test_verdict_counts(comparison):
    counts = comparison["verdict"].value_counts().to_dict()
    assert counts == {"match": 19, "explained": 1, "not_reproducible": 1}


# --------------------------------------------------------------------------- damping
def test_critical_and_benedict_curves():
    a = 0.5
    # double root of z^2 - (2 - a - b) z + (1 - a) at sqrt(1 - a)
    b = bendix.beta_critical(a)
    assert (2 - a - b) ** 2 == pytest.approx(4 * (1 - a))
    assert bendix.damping(a, b)["cls"] == "critically damped"
    assert bendix.beta_benedict(a) == pytest.approx(0.25 / 1.5)
    d = bendix.damping(a, bendix.beta_benedict(a))
    assert d["benedict_bordner"] and d["cls"] == "underdamped"


@pytest.mark.parametrize(
    ("alpha", "beta", "cls"),
    [(0.5, 0.05, "overdamped"), (0.5, 0.5, "underdamped"), (0.5, 3.5, "unstable")],
)
def test_damping_classes(alpha, beta, cls):
    assert bendix.damping(alpha, beta)["cls"] == cls


def test_bendix_gain_sets_are_underdamped_not_benedict():
    for p in bendix.PERIODS:
        g = design.bendix(p)
        d = bendix.damping(g.alpha, g.beta, p)
        assert d["stable"] and d["cls"] == "underdamped" and not d["benedict_bordner"]
        assert 0 < d["zeta"] < 1


def test_lags_closed_form_vs_simulation():
    g = Gains(0.53, 0.431)  # memo, T = 4 s
    exact, sim = bendix.lags(g, 4.0), bendix.simulated_lags(g, 4.0, n=3000)
    assert exact["accel_x_pred"] == pytest.approx(16.0 / 0.431)
    assert exact["accel_x_smooth"] == pytest.approx(0.47 * 16.0 / 0.431)
    for k, v in exact.items():
        assert sim[k] == pytest.approx(v, abs=1e-6 * max(1.0, abs(v)))


def test_gains_table_columns():
    mod = _script()
    resp = mod.response_table([1, 2], 40, 10)
    gt = mod.gains_table(resp, [1, 2])
    assert isinstance(gt, pd.DataFrame) and len(gt) == 2
    assert gt.loc[0, "beta_memo"] == 0.066 and gt.loc[0, "beta_captions"] == 0.06
