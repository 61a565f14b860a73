"""FAA Bendix filter test (seed 003): every published claim, through the claim model.

Each claim's compute function is checked against an independent route (a transfer function
run by scipy, the discrete Lyapunov solution, a Monte Carlo, inputs and roundings written
out by hand) or a pinned value with its derivation; the module's own science (the literal
program, the closed form, damping, lags) keeps its tests from before the port.
"""

from __future__ import annotations

import re

import numpy as np
import pandas as pd
import pytest
from scipy.signal import lfilter

from abglib import Gains, design, track
from abglib.analysis import vrf
from abglib.replications import evaluate
from abglib.replications.faa_bendix import printed
from abglib.replications.faa_bendix import program as bendix
from abglib.replications.faa_bendix.claims import CLAIMS
from abglib.simulate import bendix_impulse, bendix_ramp
from abglib.verdicts import tolerance_from_printed

from .conftest import claim_test, published, small_config, study_for

DOC = "faa_bendix"
# one worker evaluates the module's study fixtures (and compiles their loops) for all its
# tests, instead of each worker doing it again (pytest-xdist --dist loadgroup)
pytestmark = pytest.mark.xdist_group("faa_bendix_claims")
PERIODS = range(1, 9)
KINDS = ("impulse", "ramp")


@pytest.fixture(scope="module")
def study():
    return study_for(DOC, small_config())


@pytest.fixture(scope="module")
def judged(study):
    """comparison and robustness at the small config (the sweep is the nominal one)."""
    pub = published(DOC)
    comp, points = evaluate(DOC, CLAIMS, pub, study, lambda c: type(study)(c, pub))
    return comp.assign(key=pub["key"].to_numpy()).set_index("key"), points


def value(study, key):
    return CLAIMS.compute(study, key).value


def keys(pattern):
    return [k for k in published(DOC)["key"] if re.fullmatch(pattern, k)]


def params(pattern):
    return [pytest.param(k, marks=claim_test(DOC, k), id=k) for k in keys(pattern)]


# --------------------------------------------------------------------------- the letter report
@claim_test(DOC, "program.equations")
def test_program_equations_are_the_alpha_beta_transfer_function(study):
    assert value(study, "program.equations") is True
    # independent route: X̄/X = z(αz + β - α) / (z² - (2 - α - β)z + (1 - α)) (seed 000 with
    # γ = 0), run by scipy from rest on the same inputs
    resp = study.responses
    for (table, p, kind), d in resp.groupby(["table", "period_s", "input"]):
        g = study.gains(p, table, kind)
        a, b = g.alpha, g.beta
        xs = lfilter([a, b - a], [1.0, a + b - 2.0, 1.0 - a], d["z"].to_numpy())
        np.testing.assert_allclose(d["x_smooth"], xs, rtol=0, atol=1e-12)


@pytest.mark.parametrize("period", PERIODS)
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


@claim_test(DOC, "program.impulse")
@pytest.mark.parametrize("period", PERIODS)
def test_impulse_input_as_the_letter_report_writes_it(study, period):
    assert value(study, "program.impulse") is True
    T = float(period)
    imp = study.input("impulse", period)
    # "a pulse of amplitude 1/T and width T ... at the first sampling"
    assert imp[0] == 1.0 / T and np.count_nonzero(imp) == 1 and imp.size == 40


@claim_test(DOC, "program.impulse")
def test_impulse_note_writes_one_area_when_its_ends_agree(study):
    # every period's area T * sum(z) prints as 1: one value, not the range '1-1' of v0.4.5
    note = CLAIMS.compute(study, "program.impulse").note
    assert note.endswith("area T * sum(z) = 1 for every T") and "1-1" not in note


@claim_test(DOC, "program.ramp")
@pytest.mark.parametrize("period", PERIODS)
def test_ramp_input_as_the_letter_report_writes_it(study, period):
    assert value(study, "program.ramp") is True
    T = float(period)
    ramp = study.input("ramp", period)
    # "zero at the first sampling ... raised by the value of T each sampling for 10
    # periods ... then held at zero", written out by hand
    expected = np.concatenate([np.arange(11) * T, np.zeros(29)])
    np.testing.assert_array_equal(ramp, expected)
    assert ramp[0] == 0.0 and np.allclose(np.diff(ramp[:11]), T) and ramp[10] == 10 * T
    assert np.all(ramp[11:] == 0.0)


@claim_test(DOC, "program.ramp.periods")
def test_ramp_rises_for_the_configured_periods(study):
    assert value(study, "program.ramp.periods") == 10.0
    # the count is read off the generated input, not the config: another rise shows
    cfg = {DOC: dict(small_config()[DOC], ramp_rise_samples=7)}
    other = type(study)(cfg, published(DOC))
    assert value(other, "program.ramp.periods") == 7.0


@claim_test(DOC, "program.intervals")
def test_forty_intervals(study):
    assert value(study, "program.intervals") == 40.0
    assert len(study.responses) == 2 * 8 * 2 * 40  # tables x periods x inputs x samples


@claim_test(DOC, "program.graphs")
def test_six_graphs(study):
    # "1. IMPULSE RESPONSE, SMOOTHED POSITION ... 6. RAMP RESPONSE, PREDICTED POSITION"
    assert value(study, "program.graphs") == 6.0
    assert bendix.INPUTS == ("impulse", "ramp") and len(bendix.GRAPHS) == 3


def test_program_input_rejects_other_kinds():
    with pytest.raises(ValueError, match="kind must be one of"):
        bendix.program_input("step", 40, 1.0, 10)


# --------------------------------------------------------------------------- the memo
def _zeta(a, b, T):
    """Damping ratio of s = ln(z)/T, z a root of z² - (2 - α - β)z + (1 - α)."""
    z = np.roots([1.0, a + b - 2.0, 1.0 - a])[0]
    s = np.log(complex(z)) / T
    return -s.real / abs(s)


@pytest.mark.parametrize("key", params(r"memo\.T\d+\.(alpha|beta)"))
def test_memo_gains_are_inputs_not_reproducible(study, judged, key):
    p = int(key.split(".")[1][1:])
    res = CLAIMS.compute(study, key)
    assert res.value is None and "not among the seeds" in res.note
    g = study.gains(p)
    assert f"zeta = {_zeta(g.alpha, g.beta, p):.3f}" in res.note
    assert judged[0].loc[key, "verdict"] == "not_reproducible"


def test_memo_gains_are_the_library_tables():
    # abglib.design's Bendix tables (public API) transcribe the same printed numbers
    memo = printed.memo_gains(published(DOC))
    caps = printed.captions(published(DOC))
    for p in PERIODS:
        assert design.bendix(p) == Gains(*memo.loc[p, ["alpha", "beta"]])
        c = caps[(caps["period_s"] == p)]
        assert len(c) == 2
        for r in c.itertuples():
            assert design.bendix(p, "captions") == Gains(r.alpha, r.beta)


@pytest.mark.parametrize("key", params(r"memo\.T\d+\.(position|velocity)"))
def test_memo_ratio_is_the_lyapunov_vrf(study, key):
    _, p, k = key.split(".")
    p = int(p[1:])
    g = study.gains(p)
    ly = vrf(g, dt=p)
    exact = np.sqrt(ly["x_smooth" if k == "position" else "v_smooth"])
    assert value(study, key) == pytest.approx(exact, rel=1e-12)


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


def test_row_7s_is_a_match(judged):
    comp = judged[0]
    assert list(comp.loc[["memo.T7.position", "memo.T7.velocity"], "verdict"]) == [
        "match",
        "match",
    ]


def test_row_1s_position_is_explained_by_rounding(judged):
    row = judged[0].loc["memo.T1.position"]
    assert row["verdict"] == "explained"
    assert "unrounded gains" in row["note"]
    assert float(row["abs_err"]) == pytest.approx(0.00063, abs=1e-5)


@claim_test(DOC, "memo.example.angle")
def test_memo_worked_example_angle(study):
    # memo: T = 3 s, "0.69 x 1 deg = .69 deg" (alpha .465, beta .300)
    assert round(value(study, "memo.example.angle"), 2) == 0.69
    assert value(study, "memo.example.angle") == bendix.memo_ratios(0.465, 0.300, 3.0)["position"]


@claim_test(DOC, "memo.example.rate")
def test_memo_worked_example_rate(study):
    # memo: "0.125 x 1 deg = .125 deg/sec"
    assert round(value(study, "memo.example.rate"), 3) == 0.125
    assert value(study, "memo.example.rate") == bendix.memo_ratios(0.465, 0.300, 3.0)["velocity"]


@claim_test(DOC, "memo.claim.columns")
def test_memo_columns_are_per_second_not_per_sample(study):
    assert value(study, "memo.claim.columns") is True
    for p in range(2, 9):
        g = study.gains(p)
        printed_v = study.printed(f"memo.T{p}.velocity")
        per_sample = np.sqrt(vrf(g, dt=1.0)["v_smooth"])  # sqrt(k_v) T, T-free
        assert abs(per_sample - float(printed_v)) > tolerance_from_printed(printed_v)


@claim_test(DOC, "memo.claim.reduction")
def test_memo_ratios_are_reductions(study):
    assert value(study, "memo.claim.reduction") is True
    assert all(np.sqrt(vrf(study.gains(p), dt=p)["x_smooth"]) < 1 for p in PERIODS)


@claim_test(DOC, "memo.claim.optimum")
def test_optimum_is_not_reproducible_and_gives_the_damping(study):
    res = CLAIMS.compute(study, "memo.claim.optimum")
    assert res.value is None
    # beta / (alpha^2 / (2 - alpha)): 0.066 / (0.0625 / 1.75) = 1.85 ... 0.855 / 0.3082 = 2.77
    ratios = [g.beta / (g.alpha**2 / (2 - g.alpha)) for g in map(study.gains, PERIODS)]
    assert f"{min(ratios):.1f}-{max(ratios):.1f} times" in res.note
    assert "1.8-2.8 times" in res.note and "underdamped" in res.note


# --------------------------------------------------------------------------- the captions
@pytest.mark.parametrize("key", params(r"captions\.(impulse|ramp)\.T\d+\.(alpha|beta)"))
def test_caption_gain_is_the_memo_gain_cut_to_two_decimals(study, judged, key):
    _, kind, p, name = key.split(".")
    p = int(p[1:])
    memo_printed = study.printed(f"memo.T{p}.{name}")
    res = CLAIMS.compute(study, key)
    assert res.value == float(memo_printed)
    # by hand: the memo's three decimals truncated to two
    truncated = np.floor(round(float(memo_printed) * 1000) / 10) / 100
    assert res.readings[0].value == pytest.approx(truncated, abs=1e-12)
    assert float(study.printed(key)) == pytest.approx(truncated, abs=1e-12)
    # only beta = .066 (T = 1 s) is more than half a unit from its caption; v0.4.0: its
    # truncation no longer explains the one-digit caption '0.06' (an unrelated one-digit
    # number lands on it with chance 1/9 > 0.05, abglib.verdicts.readings)
    expected = "mismatch" if (p, name) == (1, "beta") else "match"
    assert judged[0].loc[key, "verdict"] == expected


def test_caption_truncation_differs_from_rounding_for_eight_gains(study):
    c = study.captions_table[study.captions_table["input"] == "ramp"]
    differ = sum(
        int((c[f"{n}_memo_rounded"] != c[f"{n}_memo_truncated"]).sum()) for n in ("alpha", "beta")
    )
    # .465, .645, .665 (alpha); .066, .175, .565, .685, .855 (beta) round up, the captions cut
    assert differ == 8
    assert (
        printed.round_half_up(".465", "0.46") == 0.47 and printed.truncate(".465", "0.46") == 0.46
    )


@pytest.mark.parametrize("key", params(r"captions\.(impulse|ramp)\.T\d+\.period"))
def test_caption_period_pairs_with_the_memo_row(study, key):
    p = int(key.split(".")[2][1:])
    assert value(study, key) == float(p) == float(study.printed(key))


@pytest.mark.parametrize("key", params(r"captions\.(impulse|ramp)\.T\d+\.sfy"))
def test_caption_sfy_reconstruction_and_its_robustness(study, judged, key):
    _, kind, p, _ = key.split(".")
    p = int(p[1:])
    # by hand: the input peaks at 1/T (impulse) or 10 T (ramp); 10 divisions of a power of ten
    peak = 1.0 / p if kind == "impulse" else 10.0 * p
    by_hand = 10.0 ** np.ceil(np.log10(peak / 10.0) - 1e-12)
    assert value(study, key) == pytest.approx(by_hand)
    assert value(study, key) == float(study.printed(key))
    comp, points = judged
    row = comp.loc[key]
    assert row["depends_on"] == "faa_bendix.plot_divisions"
    # at 8 divisions the T = 1 s inputs (peak 1 and 10) need the next decade: flip
    if p == 1:
        assert row["verdict"] == "not_reproducible" and row["robust"] == "false"
        # v0.4.0: at 8 divisions the scale is a power of ten off, which the reading
        # catalogue explains as a shifted decimal point for the ramp's '1.00' (chance
        # 1/900), not for the impulse's two-digit '0.10' (1/90, above the budget)
        at8 = "explained" if kind == "ramp" else "mismatch"
        assert f"{at8} at 8, match at 10-12" in row["note"]
    else:
        assert row["verdict"] == "match" and row["robust"] == "true"
    assert len(points[points["key"] == key]) == 3


def test_power_of_ten_scale():
    assert bendix.power_of_ten_scale(1.0, 10) == pytest.approx(0.1)
    assert bendix.power_of_ten_scale(10.0, 10) == pytest.approx(1.0)
    assert bendix.power_of_ten_scale(10.0, 8) == pytest.approx(10.0)
    assert bendix.power_of_ten_scale(0.125, 10) == pytest.approx(0.1)


def test_captions_table_and_sfy(study):
    c = study.caption_values.set_index(["input", "period_s"])["sfy"]
    assert c[("impulse", 5)] == 0.10  # captions: SFY= 0.10
    assert c[("ramp", 1)] == 1.00 and c[("ramp", 2)] == 10.00


# --------------------------------------------------------------------------- the report tables
def test_verdict_counts(judged):
    counts = judged[0]["verdict"].value_counts().to_dict()
    # + 1 mismatch in v0.4.0: captions.ramp.T5.predicted_twice (a misprinted caption);
    # v0.4.0: the two T = 1 s BETA= 0.06 captions are no longer explained (chance 1/9)
    assert counts == {"match": 85, "explained": 1, "mismatch": 3, "not_reproducible": 19}


def test_gains_table_columns(study):
    gt = study.gains_table
    assert isinstance(gt, pd.DataFrame) and len(gt) == 8
    assert gt.loc[0, "beta_memo"] == 0.066 and gt.loc[0, "beta_captions"] == 0.06


def test_tables_are_the_rule_outputs(study):
    from abglib.replications.faa_bendix.study import TABLES

    assert tuple(study.tables()) == TABLES


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


def test_bendix_gain_sets_are_underdamped_not_benedict(study):
    d = study.damping_lags
    assert d["stable"].all() and (d["damping"] == "underdamped").all()
    assert not d["benedict_bordner"].any()
    for r in d.itertuples():
        assert r.zeta == pytest.approx(_zeta(r.alpha, r.beta, r.period_s))
        assert 0 < r.zeta < 1


def test_lags_closed_form_vs_simulation():
    g = Gains(0.53, 0.431)  # memo, T = 4 s
    exact, sim = bendix.lags(g, 4.0), bendix.simulated_lags(g, 4.0, n=3000)
    assert exact["accel_x_pred"] == pytest.approx(16.0 / 0.431)
    assert exact["accel_x_smooth"] == pytest.approx(0.47 * 16.0 / 0.431)
    for k, v in exact.items():
        assert sim[k] == pytest.approx(v, abs=1e-6 * max(1.0, abs(v)))


# --------------------------------------------------------------------------- added in v0.4.0
@claim_test(DOC, "captions.ramp.T5.predicted_twice")
def test_t5_ramp_captions_predicted_twice(study, judged):
    # independent route: the letter report's three equations typed here, run on its ramp
    # (0, T, 2T, ... for 10 periods, then 0) at the T = 5 s captions' gains
    a, b, T = 0.58, 0.56, 5.0
    z = [k * T for k in range(11)] + [0.0] * 29
    xp, xd1, out = 0.0, 0.0, {"x_smooth": [], "v_smooth": [], "x_pred": []}
    for xk in z:
        xb = xp + a * (xk - xp)
        xd = xd1 + (b / T) * (xk - xp)
        out["x_pred"].append(xp)
        out["x_smooth"].append(xb)
        out["v_smooth"].append(xd)
        xp, xd1 = xb + T * xd, xd
    out = {k: np.array(v) for k, v in out.items()}
    # the three graphs of one run are three different curves: no two are the same output
    for p, q in (("x_pred", "v_smooth"), ("x_pred", "x_smooth"), ("x_smooth", "v_smooth")):
        assert np.max(np.abs(out[p] - out[q])) > 10.0
    # on the printed SFY = 10 grid the velocity graph stays within about half a division
    assert 0.4 < np.max(np.abs(out["v_smooth"])) / 10.0 < 0.6
    assert 5.0 < np.max(np.abs(out["x_pred"])) / 10.0 < 6.0
    res = CLAIMS.compute(study, "captions.ramp.T5.predicted_twice")
    assert res.value is False
    assert f"{np.max(np.abs(out['v_smooth'])) / 10.0:.2f} divisions" in res.note
    row = judged[0].loc["captions.ramp.T5.predicted_twice"]
    assert row["verdict"] == "mismatch" and "SMOOTHED VELOCITY graph" in row["note"]


@pytest.mark.parametrize("like", ["0.06", "0.1"])
def test_cut_kind_against_integer_arithmetic(like):
    """cut_kind (exact decimals) against the same four cases in integer units of the
    memo's last digit: every three-decimal gain from .000 to .999."""
    step = {"0.06": 10, "0.1": 100}[like]  # thousandths per unit of the caption's last digit
    for k in range(1000):
        rest = k % step
        want = (
            "exact"
            if rest == 0
            else "tie"
            if 2 * rest == step
            else "same"
            if 2 * rest < step
            else "beyond"
        )
        assert printed.cut_kind(f"{k / 1000:.3f}", like) == want, k
