"""abglib.bench.variants: config entries -> canonical gains, and their error messages."""

import numpy as np
import pytest

from abglib import AbglibValueError, Gains, analysis, design
from abglib.bench.variants import RULES, Rule, register, variant_family, variant_gains, variant_rule


def test_every_rule_listed_in_the_module_doc():
    import abglib.bench.variants as v

    for name in RULES:
        assert f"\n{name} " in v.__doc__ or f"``{name}``" in v.__doc__, name


@pytest.mark.parametrize(
    "spec, expected",
    [
        # standard alpha-beta, theta = 0.8: alpha = 1 - theta^2, beta = (1 - theta)^2 (seed 000)
        ({"rule": "standard_theta", "theta": 0.8}, Gains(0.36, 0.04)),
        # standard alpha-beta-gamma, theta = 0.5: eqs 22-24 by hand
        ({"rule": "standard_theta", "theta": 0.5, "order": 3}, Gains(0.875, 0.5625, 0.125)),
        # Benedict-Bordner alpha = 0.5: beta = 0.25 / 1.5 (seed 001, eq 23b)
        ({"rule": "benedict_bordner", "alpha": 0.5}, Gains(0.5, 1 / 6)),
        # Simpson, alpha = 0.5, gamma = 0.2: beta = 0.5 * 0.6 / 1.5 (seed 000, eq 21)
        ({"rule": "simpson", "alpha": 0.5, "gamma": 0.05}, Gains(0.5, 0.175, 0.05)),
        # Kalata index 1: (0.75, 0.5) (Kalata 1984, worked by hand: r = 0.5)
        ({"rule": "kalata_ab", "tracking_index": 1.0}, Gains(0.75, 0.5)),
        # the memo's T = 3 s row (seed 003)
        ({"rule": "bendix", "period_s": 3}, Gains(0.465, 0.3)),
        ({"rule": "gains", "alpha": 0.4, "beta": 0.1}, Gains(0.4, 0.1)),
    ],
)
def test_gains_by_hand(spec, expected):
    assert variant_gains(spec, dt=1.0).isclose(expected, rtol=1e-12)


def test_standard_alpha_keeps_alpha():
    g = variant_gains({"rule": "standard_alpha", "alpha": 0.3, "order": 3}, dt=1.0)
    assert g.alpha == pytest.approx(0.3, rel=1e-12)
    # critically damped: a triple pole (seed 000, eq 40)
    p = analysis.poles(g)
    assert np.ptp(np.abs(p)) < 1e-4


@pytest.mark.parametrize("kind, order", [("type1", 2), ("type2", 2), ("type2", 3)])
@pytest.mark.parametrize("dt", [1.0, 0.01])
def test_huang_enbw_hits_the_bandwidth(kind, order, dt):
    # independent route: the ENBW of the designed gains (sum of h_k^2 / 2T, seed 002 eq 8)
    bn = 0.2 / dt
    g = variant_gains({"rule": "huang_enbw", "bn_hz": bn, "type": kind, "order": order}, dt)
    assert analysis.enbw(g, dt) == pytest.approx(bn, rel=1e-9)


def test_kalman_dare_equals_kalata():
    # Lambda = sqrt(q) T^2 / sqrt(r) (design.steady_state_kalman docstring): two routes
    q, r, dt = 4.0, 100.0, 2.0
    g = variant_gains({"rule": "steady_state_kalman", "q": q, "r": r}, dt)
    assert g.isclose(design.kalata_ab(np.sqrt(q) * dt**2 / np.sqrt(r)), rtol=1e-9)


def test_growing_memory_is_time_varying():
    g = variant_gains({"rule": "growing_memory"}, dt=1.0, n_samples=5)
    assert g.alpha.shape == (5,)
    # seed 001, eq 24a at n = 3: 2 * 5 / 12
    assert g.alpha[2] == pytest.approx(10 / 12)
    with pytest.raises(AbglibValueError, match="needs n_samples"):
        variant_gains({"rule": "growing_memory"}, dt=1.0)


@pytest.mark.parametrize(
    "spec, match",
    [
        ({"rule": "nope"}, r"variant 'v': rule must be one of .*benedict_bordner.*got 'nope'"),
        ({"alpha": 0.3}, "rule must be one of"),
        ({"rule": "qd_m", "m": 21, "alpha": 0.3}, r"unknown parameter\(s\) alpha .*allowed: m"),
        ({"rule": "standard_alpha"}, r"needs parameter\(s\) alpha; allowed: alpha, order"),
        ({"rule": "qd_m", "m": "21"}, "parameter m of rule 'qd_m' must be a number"),
        ({"rule": "simpson", "alpha": 0.5}, "exactly one of beta, gamma"),
        ({"rule": "simpson", "alpha": 0.5, "beta": 0.2, "gamma": 0.1}, "exactly one of beta"),
        (
            {"rule": "benedict_bordner", "alpha": 1.5},
            r"variant 'v' \(rule 'benedict_bordner'\): alpha must satisfy 0 < alpha <= 1, got 1.5",
        ),
        ({"rule": "huang_enbw", "bn_hz": 50.0}, "outside the ENBW range"),
        (
            {"rule": "huang_enbw", "bn_hz": 0.1, "type": "type9"},
            "rule must be one of 'type1', 'type2'",
        ),
        ({"rule": "bendix", "period_s": 9}, "period_s must be one of 1, 2"),
    ],
)
def test_errors_name_the_problem(spec, match):
    with pytest.raises(AbglibValueError, match=match):
        variant_gains(spec, dt=1.0, n_samples=10, name="v")


def test_not_a_mapping():
    with pytest.raises(AbglibValueError, match="must be a mapping"):
        variant_rule(["standard_alpha"], "v")


def test_family_and_register():
    assert variant_family({"rule": "huang_enbw", "bn_hz": 1, "type": "type2", "order": 3}) == (
        "Huang type II α-β-γ"
    )
    with pytest.raises(AbglibValueError, match="already registered"):
        register(Rule("gains", lambda p, dt, n: None))
    with pytest.raises(AbglibValueError, match="kind must be"):
        register(Rule("brand_new_rule", lambda p, dt, n: None, kind="other"))
    assert "brand_new_rule" not in RULES


def test_method_rule_runner(monkeypatch):
    from abglib import track
    from abglib.bench.variants import variant_runner

    rule = Rule(
        "test_method",
        lambda p, dt, n: lambda z: track(z, Gains(p["alpha"], 0.1), dt),
        ("alpha",),
        kind="method",
        fixed_gain=False,
    )
    monkeypatch.setitem(RULES, "test_method", rule)
    run = variant_runner({"rule": "test_method", "alpha": 0.5}, 1.0, 10)
    z = np.arange(10.0)
    assert np.array_equal(run(z).x_smooth, track(z, Gains(0.5, 0.1)).x_smooth)
    with pytest.raises(AbglibValueError, match="estimation method"):
        variant_gains({"rule": "test_method", "alpha": 0.5}, 1.0, 10)


def test_alwagih_methods_registered_when_present():
    from abglib import methods, track
    from abglib.bench.metrics import evaluate_cell
    from abglib.bench.variants import variant_runner

    z = np.cumsum(np.random.default_rng(4).normal(size=(3, 40)), axis=-1)
    # M1 is the Benedict-Bordner tracker from the two-point start (seed 001, eqs 9-10, 23)
    run = variant_runner({"rule": "alwagih_m1", "alpha0": 0.4}, 1.0, 40)
    ref = track(z, design.benedict_bordner(0.4), init="two_point").x_pred
    assert np.allclose(run(z).x_pred, ref, rtol=1e-12, atol=1e-12)
    m5 = variant_runner({"rule": "alwagih_m5", "causal": 1, "memory": 3}, 1.0, 40)
    assert np.array_equal(
        m5(z).x_pred, methods.m5(z, np.linspace(0.05, 1.0, 20), 1.0, True, 3).x_pred
    )
    coords = {"x": {"truth_pos": z, "truth_vel": np.zeros_like(z), "z": z, "sigma": 1.0}}
    row = evaluate_cell(coords, 1.0, runner=run, burn_in=5)[0]
    assert row["rmse_x_smooth"] is None and row["rmse_x_pred"] >= 0.0
    with pytest.raises(AbglibValueError, match="needs parameter"):
        variant_runner({"rule": "alwagih_m4", "alpha0": 0.1}, 1.0, 40)


def test_figure_curve_specs_use_the_variant_rules():
    from abglib import design
    from abglib.bench.variants import gains_from_spec

    assert gains_from_spec({"design": "qd", "m": 21}) == design.qd(21.0)
    assert gains_from_spec({"design": "qd", "alpha": 0.3}) == design.qd(design.qd_m_from_alpha(0.3))
    assert gains_from_spec({"design": "standard_abg", "alpha": 0.3}) == design.standard_from_alpha(
        0.3, 3
    )
    assert gains_from_spec({"design": "standard_ab", "alpha": 0.3}) == design.standard_from_alpha(
        0.3, 2
    )
    with pytest.raises(ValueError, match="design must be one of"):
        gains_from_spec({"design": "bogus", "alpha": 0.3})
    with pytest.raises(ValueError, match="alpha"):
        gains_from_spec({"design": "standard_ab", "alpha": 1.5})
