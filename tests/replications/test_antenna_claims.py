"""Unit tests of every seed-004 claim (abglib.replications.antenna.claims).

Each claim's compute function is checked against an independent route on the small config
(``tests/data/config_small.yaml``: same reconstructed antenna, short runs, coarse grids):
exact-state claims against time-domain simulations of the closed loop (the claims read the
frequency response), Kalman claims against direct calls of the phase-ensemble simulator or
numpy over its raw maxima, app. H against spectral radii computed directly.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg

from abglib.replications.antenna import claims_estimation as ce
from abglib.replications.antenna import claims_exact as cx
from abglib.replications.antenna import (
    design_controller,
    preview_gain,
    preview_series,
    simulate,
    spectral_radius,
    steady_state_amplitudes,
    taylor_model,
)
from abglib.replications.antenna.claims import CLAIMS
from abglib.replications.antenna.ensemble import phase_grid, simulate_phases

from .conftest import claim_test, small_config, study_for

DOC = "antenna"
# one worker evaluates the module's study fixtures (and compiles their loops) for all its
# tests, instead of each worker doing it again (pytest-xdist --dist loadgroup)
pytestmark = pytest.mark.xdist_group("antenna_claims")


@pytest.fixture(scope="module")
def s():
    return study_for(DOC, small_config())


def value(s, key):
    return CLAIMS.compute(s, key).value


def long_max(s, ctrl, omega, order=None, mode="predicted", amplitude=1.0, t_end=600.0):
    """max |e|, |u| of a long linear simulation after its transient (the time-domain route)."""
    n = int(np.ceil(t_end / s.dt))
    r = simulate(
        s.params, ctrl, amplitude=amplitude, omega=omega, n_steps=n, mode=mode, order=order
    )
    sel = r["t"] > t_end / 2
    return float(np.max(np.abs(r["e"][sel]))), float(np.max(np.abs(r["u"][sel])))


# ----------------------------------------------------------------------------- ch. 2, 4
@claim_test(DOC, "ch2.hamiltonian_pairs")
def test_hamiltonian_pairs_and_closed_loop_poles(s):
    from abglib.replications.antenna.study_exact import hamiltonian_eigenvalues

    ev = hamiltonian_eigenvalues(s.ctrl, s.q, s.r)
    stable = np.sort_complex(ev[np.abs(ev) < 1 - 1e-9])
    # independent route: the stable half of the spectrum is the LQ closed loop's poles
    poles = np.sort_complex(np.linalg.eigvals(s.ctrl.A - s.ctrl.B @ s.ctrl.tm.K))
    np.testing.assert_allclose(stable, poles, atol=1e-6)
    assert value(s, "ch2.hamiltonian_pairs") is True


@claim_test(DOC, "ch2.norm_ag_lt_1")
def test_norm_of_ag_exceeds_one_though_stable(s):
    sv = scipy.linalg.svdvals(s.ctrl.tm.Ag)[0]
    rho = np.max(np.abs(np.linalg.eigvals(s.ctrl.tm.Ag)))
    assert sv > 1.0 > rho  # 5.84 and 0.945 on the reconstruction (v0.2.0 report)
    assert value(s, "ch2.norm_ag_lt_1") is False


@claim_test(DOC, "ch4.preview_converges")
def test_preview_converges_to_the_stein_gain(s):
    at, ct, _ = taylor_model(5, s.dt)
    kt = preview_gain(s.ctrl.tm, at, ct, method="sylvester")  # other Stein route than the table
    d = np.max(np.abs(preview_series(s.ctrl.tm, at, ct, 1600) - kt)) / np.max(np.abs(kt))
    assert d < 1e-8
    assert cx.preview_differences(s)[-1] == pytest.approx(d, abs=1e-12)
    assert value(s, "ch4.preview_converges") is True


# ----------------------------------------------------------------------------- Fig. I.4
def direct_taylor_errors(cfg):
    """|sin(i dt) - sum_k sin^(k)(t0) (i-i0)^k dt^k / k!| by direct summation."""
    from math import factorial

    dt, i0 = cfg["dt"], cfg["start"]
    i = np.arange(i0, cfg["stop"] + 1)
    h = (i - i0) * dt
    out = {}
    for q in cfg["orders"]:
        p = sum(np.sin(i0 * dt + k * np.pi / 2) * h**k / factorial(k) for k in range(q + 1))
        out[q] = np.abs(p - np.sin(i * dt))
    return out


@claim_test(DOC, "fig4.deviation_grows")
def test_taylor_deviation_grows(s):
    direct = direct_taylor_errors(s.cfg["taylor"])
    for q, e in cx.taylor_errors(s).items():
        np.testing.assert_allclose(e, direct[q], atol=1e-12)
        assert e[-1] > e[1]
    assert value(s, "fig4.deviation_grows") is True


@claim_test(DOC, "fig4.longer_with_order")
def test_taylor_horizon_grows_with_order(s):
    tol = s.cfg["taylor"]["tolerance"]
    direct = [int(np.argmax(e > tol)) for e in direct_taylor_errors(s.cfg["taylor"]).values()]
    assert cx.taylor_horizons(s) == direct == [20, 42, 80]  # orders 1, 2, 3 (v0.2.0 report)
    assert value(s, "fig4.longer_with_order") is True


# ----------------------------------------------------------------------------- ch. 6
@claim_test(DOC, "fig5.smaller_no_phase")
def test_known_output_smaller_in_phase(s):
    n = int(np.ceil(400 / s.dt))
    r = simulate(s.params, s.ctrl, amplitude=1.0, omega=s.omega, n_steps=n, mode="known")
    sel = r["t"] > 200
    t, y = r["t"][sel], r["y"][sel]
    # least-squares sine fit of the output: amplitude below 1, phase below 1e-3 deg
    c, sn = np.linalg.lstsq(
        np.column_stack([np.cos(s.omega * t), np.sin(s.omega * t)]), y, rcond=None
    )[0]
    assert np.hypot(c, sn) < 1.0 and abs(np.degrees(np.arctan2(c, sn))) < 1e-3
    assert value(s, "fig5.smaller_no_phase") is True


@claim_test(DOC, "fig7.toward_known")
def test_error_approaches_known_output_error(s):
    n = int(np.ceil(400 / s.dt))
    kw = dict(amplitude=1.0, omega=s.omega, n_steps=n)
    ek = simulate(s.params, s.ctrl, mode="known", **kw)["e"]
    d = [
        np.max(
            np.abs(simulate(s.params, s.ctrl, mode="predicted", order=q, **kw)["e"] - ek)[n // 2 :]
        )
        for q in cx.orders(s)
    ]
    np.testing.assert_allclose(d, cx.distances_to_known(s), rtol=0.05)
    assert value(s, "fig7.toward_known") is True


@claim_test(DOC, "fig7.phase_decreases")
def test_error_phase_decreases_with_order(s):
    ph = cx.phase_offsets(s)
    # independent route: the phase of the steady-state amplitudes recomputed here
    k = steady_state_amplitudes(s.ctrl, s.omega, 1.0, "known")["phase_e"]
    for q, p in zip(cx.orders(s), ph, strict=True):
        d = abs(steady_state_amplitudes(s.ctrl, s.omega, 1.0, "predicted", q)["phase_e"] - k)
        assert p == pytest.approx(min(d, 2 * np.pi - d), abs=1e-12)
    assert value(s, "fig7.phase_decreases") is True


@pytest.mark.parametrize(
    "key",
    [
        pytest.param("fig8.third_near_known", marks=claim_test(DOC, "fig8.third_near_known")),
        pytest.param("fig8.max_err_lt_002pct", marks=claim_test(DOC, "fig8.max_err_lt_002pct")),
    ],
)
def test_third_order_at_the_normal_track(s, key):
    e3, ek = cx.third_up(s)
    e_sim = max(long_max(s, s.ctrl, s.omega, q)[0] for q in cx.orders(s) if q >= 3)
    assert e_sim == pytest.approx(e3, rel=0.05)  # sampled max of a sinusoid ~ its amplitude
    # 5.71e-6 against 1.25e-6 known: ratio 4.6 > 2, yet < 0.02 % of the amplitude
    expected = {"fig8.third_near_known": e3 / ek < 2.0, "fig8.max_err_lt_002pct": 100 * e3 < 0.02}
    assert value(s, key) is bool(expected[key])
    assert expected == {"fig8.third_near_known": False, "fig8.max_err_lt_002pct": True}


@claim_test(DOC, "fig8.known_lt_10pct")
def test_known_error_below_ten_percent(s):
    e = max(long_max(s, s.ctrl, w, mode="known")[0] for w in (0.5, 1.0))
    assert e < 0.1 and value(s, "fig8.known_lt_10pct") is True


@claim_test(DOC, "fig8.pred_exceeds_amplitude")
def test_predicted_error_stays_below_amplitude(s):
    e = max(long_max(s, s.ctrl, 1.0, q)[0] for q in cx.orders(s))
    assert e < 1.0  # 0.23 of the amplitude at omega = 1 (order 2)
    assert value(s, "fig8.pred_exceeds_amplitude") is False


@claim_test(DOC, "fig8.higher_order_not_always")
def test_higher_order_not_always_better_q100(s):
    piv = cx.order_pivot(s)
    worse = np.diff(piv.to_numpy(), axis=1) > 0
    assert value(s, "fig8.higher_order_not_always") is bool(np.any(worse))


@claim_test(DOC, "fig9.higher_order_better")
def test_higher_order_better_q10000(s):
    e = [long_max(s, s.ctrl_high, 1.0, q)[0] for q in cx.orders(s)]
    assert np.all(np.diff(e) < 0)
    assert value(s, "fig9.higher_order_better") is True


@claim_test(DOC, "fig9.known_w1_lt_01pct")
def test_known_error_at_omega_one(s):
    e, _ = long_max(s, s.ctrl_high, 1.0, mode="known")
    assert 100 * e < 0.1 and value(s, "fig9.known_w1_lt_01pct") is True


@pytest.mark.parametrize(
    "key, order",
    [
        pytest.param("fig9.fifth_w1", 5, marks=claim_test(DOC, "fig9.fifth_w1")),
        pytest.param("fig9.second_w1", 2, marks=claim_test(DOC, "fig9.second_w1")),
        pytest.param("fig9.third_w1", 3, marks=claim_test(DOC, "fig9.third_w1")),
    ],
)
def test_error_at_omega_one_by_order(s, key, order):
    e, _ = long_max(s, s.ctrl_high, 1.0, order)
    # 10 samples per period: the sampled maximum is between cos(pi/10) and 1 x the amplitude
    assert np.cos(np.pi / 10) * value(s, key) <= 100 * e <= value(s, key) * (1 + 1e-9)


@claim_test(DOC, "fig89.u_known_same")
def test_known_control_same_for_both_weights(s):
    u1 = steady_state_amplitudes(s.ctrl, 0.5, 1.0, "known")["u"]
    u2 = steady_state_amplitudes(s.ctrl_high, 0.5, 1.0, "known")["u"]
    assert abs(u2 - u1) / u1 < 0.1 and value(s, "fig89.u_known_same") is True


@claim_test(DOC, "fig89.u_pred_closer")
def test_predicted_control_closer_for_high_weight(s):
    lo = cx.control_deviation(s, s.q / s.r)
    hi = cx.control_deviation(s, s.q_high / s.r)
    assert value(s, "fig89.u_pred_closer") is bool(hi < lo) is True


@pytest.mark.parametrize(
    "key",
    [
        pytest.param("fig8.increase_with_omega", marks=claim_test(DOC, "fig8.increase_with_omega")),
        pytest.param("fig9.increase_with_omega", marks=claim_test(DOC, "fig9.increase_with_omega")),
    ],
)
def test_error_and_control_increase_with_omega(s, key):
    ctrl = s.ctrl if key.startswith("fig8") else s.ctrl_high
    e = [long_max(s, ctrl, w, 5) for w in (0.1, 0.3, 1.0)]
    assert all(b[0] > a[0] and b[1] > a[1] for a, b in zip(e[:-1], e[1:], strict=True))
    assert value(s, key) is True


@claim_test(DOC, "fig8.difference_grows")
def test_difference_to_known_grows(s):
    d = [
        long_max(s, s.ctrl, w, 2)[0] - long_max(s, s.ctrl, w, mode="known")[0]
        for w in (0.1, 0.3, 1.0)
    ]
    assert np.all(np.diff(d) > 0) and value(s, "fig8.difference_grows") is True


def test_a_step_down_within_the_roundoff_is_no_decrease():
    assert cx.non_decreasing([1.0, 2.0, 3.0]) and cx.non_decreasing([1.0, 1.0])
    assert not cx.non_decreasing([1.0, 2.0, 2.0 - 1e-15, 3.0])
    assert cx.non_decreasing([1.0, 2.0, 2.0 - 1e-15, 3.0], tol=1e-10)
    assert not cx.non_decreasing([1.0, 2.0, 2.0 - 2e-10, 3.0], tol=1e-10)
    assert cx.non_decreasing([0.0, 5e-15, 2e-15, 3e-14], tol=cx.E_RESOLVED)


def roundoff_sweep(noise: float, seed: int = 20261203):
    """A Figs I.8-I.9 sweep whose trends are known, with e_max moved by ``noise``.

    e_known = 1e-4 w^2 and e_order q = e_known + 1e-2 w^(q+2) at both Q/R: every
    |e_predicted - e_known| grows with omega, a higher order is always better, u grows.
    At omega = 0.01 orders 4 and 5 are within 1e-14 of the known output, the size of e's
    round-off (another BLAS kernel, or the Riccati fixed point reached by another route,
    moves e by ~1e-14: study_exact.omega_sweep_table), so ``noise`` of that size reorders
    them there as round-off does.
    """
    import types

    import pandas as pd

    rng = np.random.default_rng(seed)
    omega = np.geomspace(0.01, 1.0, 9)
    rows = []
    for qr in (1e2, 1e4):
        for w in omega:
            known = 1e-4 * w**2
            for case, e in [("known", known)] + [
                (f"order {q}", known + 1e-2 * w ** (q + 2)) for q in (2, 4, 5)
            ]:
                rows.append({"q_over_r": qr, "omega": w, "case": case, "e_max": e, "u_max": w})
    sw = pd.DataFrame(rows)
    sw["e_max"] += rng.uniform(-noise, noise, len(sw))
    return types.SimpleNamespace(
        omega_sweep=sw, q=1e2, q_high=1e4, r=1.0, cfg={"omega_sweep": {"orders": [2, 4, 5]}}
    )


@pytest.mark.parametrize("noise", [0.0, 1e-14, 2e-14])
def test_the_omega_trends_do_not_hang_on_roundoff(noise):
    """Figs I.8-I.9's trend and order claims judge e_max to its round-off: moved by e's
    round-off (and by twice it), every verdict is the one of the exact sweep. Judged
    strictly, round-off at omega = 0.01 made a higher order "worse" there and
    |e_predicted - e_known| "decrease" (v0.4.2: 2 robustness rows and 2 notes)."""
    for seed in range(20 if noise else 1):
        s = roundoff_sweep(noise, seed)
        assert cx._diff_grows(s).value is True, seed
        assert cx._increase(s, "fig8.increase_with_omega").value is True, seed
        assert cx._increase(s, "fig9.increase_with_omega").value is True, seed
        assert cx._notalways(s).value is False, seed
        assert cx._better(s).value is True, seed
        assert not cx.higher_order_worse(cx.order_pivot(s)).any(), seed


@pytest.mark.parametrize("excess", [5e-13, 1e-3])  # 50 times e's error, and large
def test_a_higher_order_worse_beyond_roundoff_is_seen(excess):
    """An excess of order 5 over order 4 beyond the round-off is seen, at low omega too:
    a tolerance at e's write bound (1e-10) hid the antenna's real ~omega^6 excess below
    omega = 0.056 (study_exact.E_ROUNDOFF is not e's error)."""
    s = roundoff_sweep(0.0)
    sw = s.omega_sweep
    w = np.sort(sw["omega"].unique())[1]
    for qr in (s.q, s.q_high):
        row = (sw["omega"] == w) & (sw["q_over_r"] == qr)
        four = sw.loc[row & (sw["case"] == "order 4"), "e_max"].to_numpy()
        sw.loc[row & (sw["case"] == "order 5"), "e_max"] = four + excess
    assert cx._notalways(s).value is True
    assert cx._notalways(s).note.endswith(f"{w:.3g} and up")
    assert cx._better(s).value is False and f"{w:.3g}" in cx._better(s).note


@claim_test(DOC, "ch6.linear_in_amplitude")
def test_linear_in_amplitude(s):
    re, ru = cx.amplitude_ratio(s, 3.0)
    assert re == pytest.approx(3.0, rel=1e-12) and ru == pytest.approx(3.0, rel=1e-12)
    assert value(s, "ch6.linear_in_amplitude") is True


@claim_test(DOC, "ch9.known_any_error")
def test_known_error_shrinks_with_weight(s):
    e1, _ = long_max(s, s.ctrl, 1.0, mode="known")
    e2, _ = long_max(s, s.ctrl_high, 1.0, mode="known")
    assert e1 / e2 > 10 and value(s, "ch9.known_any_error") is True


@claim_test(DOC, "ch9.high_order_small")
def test_high_order_small_error(s):
    e5, _ = long_max(s, s.ctrl_high, 1.0, 5)
    assert e5 < 0.1 and value(s, "ch9.high_order_small") is True
    note = CLAIMS.compute(s, "ch9.high_order_small").note
    # a negative change is not called an increase, and the bound on 'almost zero' says
    # where it comes from and over which bounds the verdict holds
    assert "relative change of the max error" in note and "increase over" not in note
    assert "'nearly equals' ratio below 2 of the source's sec. 6.2" in note
    assert "holds for any positive bound on the increase" in note


# ----------------------------------------------------------------------------- ch. 8
def test_ensemble_equals_the_reference_loop(s):
    """The compiled ensemble loop (phase 0) against closedloop.simulate with a resolution so
    fine that no rounding decision can differ (the ensemble snaps its inputs to 32 mantissa
    bits, 1e-10 relative: with the printed resolution one flipped rounding decision would
    part the two chaotic runs)."""
    from abglib import design

    abg = design.huang_for_enbw(0.01, s.dt, rule="type2", order=3)
    for mode, extra in (("kalman", dict(order=5, v_w=5e-10, v_v=s.vv)), ("abg", dict(abg=abg))):
        kw = dict(amplitude=10.0, omega=0.1, n_steps=478, mode=mode, resolution=1e-12, **extra)
        ref = simulate(s.params, s.ctrl, **kw)
        ens = simulate_phases(s.params, s.ctrl, phases=[0.0], **kw)
        np.testing.assert_allclose(ens["e"][0], ref["e"], rtol=0, atol=1e-6)
        np.testing.assert_allclose(ens["xt_err"][0], ref["xt_err"], rtol=0, atol=1e-6)


def test_rounding_is_numpy_round_half_to_even():
    from abglib.replications.antenna.ensemble import _rint

    v = np.array([-2.5, -1.5, -0.5, 0.5, 1.5, 2.5, 0.49999999, 3.2, -3.7])
    assert [_rint(x) for x in v] == list(np.round(v))


def test_snap_is_a_tiny_relative_change():
    from abglib.replications.antenna.ensemble import snap

    x = np.random.default_rng(4).normal(size=1000) * 10.0 ** np.linspace(-200, 200, 1000)
    y = snap(x)
    assert np.all(np.abs(y - x) <= 2.0**-32 * np.abs(x))
    assert np.array_equal(snap(y), y)  # idempotent: a snapped matrix stays on the grid


def direct_stats(s, order, vw, omega=None, amplitude=None):
    """Median of max |e|, |u| and |estimation error| after the transient, straight from the
    simulator (no memo, no RunStats)."""
    from abglib.replications.antenna.study_estimation import n_steps_for

    omega = s.omega if omega is None else omega
    r = simulate_phases(
        s.params,
        s.ctrl,
        amplitude=s.amp if amplitude is None else amplitude,
        omega=omega,
        n_steps=n_steps_for(omega, s.dt, s.sim),
        phases=phase_grid(s.cfg["kalman"]["phases"]),
        mode="kalman",
        order=order,
        v_w=s.vw_filter(vw),
        v_v=s.vv,
        resolution=s.res,
    )
    sel = r["t"] >= s.transient
    return (
        np.median(np.abs(r["e"][:, sel]).max(axis=1)),
        np.median(np.abs(r["u"][:, sel]).max(axis=1)),
        np.median(np.abs(r["xt_err"][:, :, sel]).max(axis=2), axis=0),
    )


@claim_test(DOC, "sec82.vw_opt_fifth")
def test_fifth_order_optimum_is_the_grid_argmin(s):
    vws = [
        5 * 10.0**k
        for k in range(s.cfg["kalman"]["vw_exponents"][0], s.cfg["kalman"]["vw_exponents"][1] + 1)
    ]
    e = [direct_stats(s, 5, v)[0] for v in vws]
    assert s.vw_opt5 == vws[int(np.argmin(e))]
    res = CLAIMS.compute(s, "sec82.vw_opt_fifth")
    assert res.value is None and f"{s.vw_opt5:.0e}" in res.note  # the exponent is lost


@claim_test(DOC, "sec82.pos_err_lt_1pct")
def test_position_estimation_error(s):
    est = direct_stats(s, 5, s.vw_opt5)[2]
    assert value(s, "sec82.pos_err_lt_1pct") is bool(est[0] < 0.01 * s.amp)


@pytest.mark.parametrize(
    "key, j",
    [
        pytest.param("sec82.vel_err", 1, marks=claim_test(DOC, "sec82.vel_err")),
        pytest.param("sec82.acc_err", 2, marks=claim_test(DOC, "sec82.acc_err")),
        pytest.param("sec82.fifth_deriv_err", 5, marks=claim_test(DOC, "sec82.fifth_deriv_err")),
    ],
)
def test_derivative_estimation_errors(s, key, j):
    est = direct_stats(s, 5, s.vw_opt5)[2]
    assert value(s, key) == pytest.approx(100 * est[j] / (s.amp * s.omega**j), rel=1e-12)


@claim_test(DOC, "sec82.opt_smallest_tracking")
def test_position_and_tracking_optima(s):
    vw = s.vw_search[s.vw_search["order"] == 5]
    pos = float(vw.loc[vw["est_err_d0"].idxmin(), "v_w"])
    assert value(s, "sec82.opt_smallest_tracking") is bool(pos == s.vw_opt5)


@claim_test(DOC, "sec82.lower_order_larger_vw")
def test_lower_order_larger_optimum(s):
    opts = [s.vw_optimum(q) for q in (3, 5)]
    assert value(s, "sec82.lower_order_larger_vw") is bool(opts[0] > opts[1])


@claim_test(DOC, "sec82.vw_opt_third")
def test_third_order_printed_settings(s):
    e = [direct_stats(s, 3, v)[0] for v in (0.01, 0.1, 1.0)]
    assert value(s, "sec82.vw_opt_third") == pytest.approx((0.01, 0.1, 1.0)[int(np.argmin(e))])


@claim_test(DOC, "sec82.off_optimum_larger")
def test_off_optimum_estimation_errors(s):
    est = [direct_stats(s, 5, v)[2] for v in s.settings[5]]
    worse = all(est[i][j] > est[1][j] for i in (0, 2) for j in (0, 1, 2))
    assert value(s, "sec82.off_optimum_larger") is worse


@pytest.mark.parametrize(
    "key",
    [
        pytest.param(
            "sec82.lower_order_less_critical",
            marks=claim_test(DOC, "sec82.lower_order_less_critical"),
        ),
        pytest.param("ch9.order_more_critical", marks=claim_test(DOC, "ch9.order_more_critical")),
    ],
)
def test_sharpness_of_the_optimum(s, key):
    sh = []
    for q in (3, 5):
        d = s.vw_search[s.vw_search["order"] == q].set_index("v_w")["e_max"]
        o = d.idxmin()
        sh.append(np.mean([d[v] / d[o] for v in d.index if v != o]))  # the small grid: 2 points
    assert value(s, key) is bool(sh[1] > sh[0])


@pytest.mark.parametrize(
    "key, kw",
    [
        pytest.param(
            "sec82.larger_omega_larger_vw",
            {"omega": 0.2},
            marks=claim_test(DOC, "sec82.larger_omega_larger_vw"),
        ),
        pytest.param(
            "sec82.larger_amplitude_larger_vw",
            {"amplitude": 100.0},
            marks=claim_test(DOC, "sec82.larger_amplitude_larger_vw"),
        ),
    ],
)
def test_optimum_moves_with_omega_and_amplitude(s, key, kw):
    vws = [5e-10, 5e-9]  # the small config's grid
    e = [direct_stats(s, 5, v, **kw)[0] for v in vws]
    assert value(s, key) is bool(vws[int(np.argmin(e))] > s.vw_opt5)


def sweep_direct(s, order, vw, omega, weight="q"):
    from abglib.replications.antenna.study_estimation import n_steps_for

    r = simulate_phases(
        s.params,
        s.controller(weight),
        amplitude=s.amp,
        omega=omega,
        n_steps=n_steps_for(omega, s.dt, s.sim),
        phases=phase_grid(s.cfg["kalman"]["phases"]),
        mode="kalman",
        order=order,
        v_w=s.vw_filter(vw),
        v_v=s.vv,
        resolution=s.res,
    )
    sel = r["t"] >= s.transient
    return np.median(np.abs(r["e"][:, sel]).max(axis=1)), np.median(
        np.abs(r["u"][:, sel]).max(axis=1)
    )


def test_sweep_table_equals_direct_runs(s):
    """Figs I.14-I.16 table entries against direct ensemble runs (the route every sec. 8.3
    claim reads)."""
    for f, order, weight in (("I.14", 5, "q"), ("I.15", 5, "q_high"), ("I.16", 3, "q")):
        row = ce.fig(s, f).iloc[-1]
        e, u = sweep_direct(s, order, row["v_w"], row["omega"], weight)
        assert (row["e_max"], row["u_max"]) == pytest.approx((e, u), rel=1e-12)


@claim_test(DOC, "sec83.w_gt_02_gt_10pct")
def test_error_above_omega_02(s):
    e, _ = sweep_direct(s, 5, s.settings[5][1], 0.4)
    assert e > 0.1 * s.amp and value(s, "sec83.w_gt_02_gt_10pct") is True


@claim_test(DOC, "sec83.qr_small_decrease")
def test_weight_helps_little_with_estimation(s):
    w = float(s.sweep_grid[0])
    e100 = min(sweep_direct(s, 5, v, w)[0] for v in s.settings[5])
    e10k = min(sweep_direct(s, 5, v, w, "q_high")[0] for v in s.settings[5])
    exact = (
        steady_state_amplitudes(s.ctrl, w, 1.0, "predicted", 5)["e"]
        / steady_state_amplitudes(s.ctrl_high, w, 1.0, "predicted", 5)["e"]
    )
    assert e100 / e10k < exact  # ~1 against ~100
    assert value(s, "sec83.qr_small_decrease") is True


@claim_test(DOC, "sec83.qr_more_control")
def test_weight_raises_control(s):
    w = float(s.sweep_grid[0])
    r = [sweep_direct(s, 5, v, w, "q_high")[1] / sweep_direct(s, 5, v, w)[1] for v in s.settings[5]]
    assert all(x > 1 for x in r)
    assert isinstance(value(s, "sec83.qr_more_control"), bool)


@pytest.mark.parametrize(
    "key, fig_",
    [
        pytest.param(
            "sec83.third_less_critical", None, marks=claim_test(DOC, "sec83.third_less_critical")
        ),
        pytest.param(
            "sec83.fig16_same_small_omega",
            "I.16",
            marks=claim_test(DOC, "sec83.fig16_same_small_omega"),
        ),
    ],
)
def test_spread_over_the_three_settings(s, key, fig_):
    w = float(s.sweep_grid[0])
    r3 = [sweep_direct(s, 3, v, w)[0] for v in s.settings[3]]
    r5 = [sweep_direct(s, 5, v, w)[0] for v in s.settings[5]]
    sp3, sp5 = max(r3) / min(r3), max(r5) / min(r5)
    expected = sp3 < 2.0 if fig_ else sp3 < sp5
    assert value(s, key) is bool(expected)


@claim_test(DOC, "sec83.third_more_control")
def test_third_order_control(s):
    u3 = np.median([sweep_direct(s, 3, s.settings[3][1], w)[1] for w in s.sweep_grid])
    u5 = np.median([sweep_direct(s, 5, s.settings[5][1], w)[1] for w in s.sweep_grid])
    assert value(s, "sec83.third_more_control") is bool(u3 > 1.2 * u5)


def test_curve_minimum_refines_a_parabola():
    import pandas as pd

    w = np.geomspace(0.02, 1.0, 9)
    e = np.exp((np.log(w) - np.log(0.07)) ** 2)  # log-log parabola with its minimum at 0.07
    c = pd.DataFrame({"e_max": e}, index=w)
    assert ce.curve_minimum(c) == pytest.approx((0.07, 1.0), rel=1e-9)
    # within 2x its minimum: (ln w - ln 0.07)^2 <= ln 2 -> w <= 0.07 exp(sqrt(ln 2))
    assert ce.range_edge(c, 2.0) == pytest.approx(0.07 * np.exp(np.sqrt(np.log(2))), rel=0.05)


@pytest.mark.parametrize(
    "key",
    [
        pytest.param(k, marks=claim_test(DOC, k))
        for k in (
            "sec83.model_best_omega",
            "sec83.opt_best_omega",
            "sec83.model_min_err",
            "sec83.opt_min_err",
            "sec83.model_range",
            "sec83.opt_range",
        )
    ],
)
def test_fig14_curve_readings(s, key):
    which = 0 if ".model_" in key else 1
    c = ce.curve(s, "I.14", which)
    w, e = ce.curve_minimum(c)
    expected = {"best_omega": w, "min_err": 100 * e / s.amp, "range": ce.range_edge(c, 2.0)}[
        key.split("_", 1)[1]
    ]
    assert value(s, key) == pytest.approx(expected)
    # the small config's curve has two points (0.1, 0.4): the minimum is at the first
    assert w == pytest.approx(float(s.sweep_grid[0]))


@claim_test(DOC, "sec83.larger_vw_best_omega_same")
def test_larger_vw_same_best_omega(s):
    w1 = ce.curve_minimum(ce.curve(s, "I.14", 1))[0]
    w2 = ce.curve_minimum(ce.curve(s, "I.14", 2))[0]
    assert value(s, "sec83.larger_vw_best_omega_same") is bool(max(w1, w2) / min(w1, w2) < 2)


@claim_test(DOC, "sec83.model_w02_amplitude")
def test_model_emphasis_at_omega_02(s):
    c = ce.curve(s, "I.14", 0)
    # log-linear interpolation between the small grid's 0.1 and 0.4
    f = np.log(2) / np.log(4)
    r = np.exp((1 - f) * np.log(c["e_max"].iloc[0]) + f * np.log(c["e_max"].iloc[1])) / s.amp
    assert value(s, "sec83.model_w02_amplitude") is bool(0.5 < r < 2)


@claim_test(DOC, "sec83.fig16_smoother")
def test_fig16_smoother(s):
    k3 = ce.steepest(ce.curve(s, "I.16", 1))
    k5 = ce.steepest(ce.curve(s, "I.14", 1))
    assert value(s, "sec83.fig16_smoother") is bool(k3 < k5)


# ----------------------------------------------------------------------------- sec. 8.4, ch. 9
@pytest.mark.parametrize(
    "key, amp",
    [
        pytest.param("fig18.err_a100", 100.0, marks=claim_test(DOC, "fig18.err_a100")),
        pytest.param("fig19.err_a1", 1.0, marks=claim_test(DOC, "fig19.err_a1")),
        pytest.param("ch8.normal_3pct", 10.0, marks=claim_test(DOC, "ch8.normal_3pct")),
    ],
)
def test_error_by_amplitude(s, key, amp):
    e = direct_stats(s, 5, s.vw_opt5, amplitude=amp)[0]
    assert value(s, key) == pytest.approx(100 * e / amp, rel=1e-12)


@claim_test(DOC, "fig17.err_lt_3pct")
def test_normal_track_below_three_percent(s):
    e = direct_stats(s, 5, s.vw_opt5)[0]
    assert value(s, "fig17.err_lt_3pct") is bool(e < 0.03 * s.amp) is True


@claim_test(DOC, "fig17.u_max")
def test_normal_track_control(s):
    assert value(s, "fig17.u_max") == pytest.approx(direct_stats(s, 5, s.vw_opt5)[1], rel=1e-12)


@claim_test(DOC, "summary.three_resolutions")
def test_error_in_resolutions(s):
    e = direct_stats(s, 5, s.vw_opt5)[0]
    assert value(s, "summary.three_resolutions") == pytest.approx(e / 0.1, rel=1e-12)


@claim_test(DOC, "fig18.err_a100_larger_vw")
def test_amplitude_100_larger_vw(s):
    e = min(
        direct_stats(s, 5, s.vw_opt5 * f, amplitude=100.0)[0]
        for f in s.cfg["kalman"]["larger_vw_factors"]
    )
    assert value(s, "fig18.err_a100_larger_vw") == pytest.approx(e, rel=1e-12)


@claim_test(DOC, "fig18.more_sine_like")
def test_amplitude_100_more_sine_like(s):
    f10, f100 = ce.sine_fraction(s, 10.0), ce.sine_fraction(s, 100.0)
    assert 0 <= f10 <= 1 and 0 <= f100 <= 1
    assert value(s, "fig18.more_sine_like") is bool(f100 > f10)


@claim_test(DOC, "fig18.u_much_larger")
def test_amplitude_100_control(s):
    u = direct_stats(s, 5, s.vw_opt5, amplitude=100.0)[1] / direct_stats(s, 5, s.vw_opt5)[1]
    assert value(s, "fig18.u_much_larger") is bool(u > 1.2)


@claim_test(DOC, "fig19.same_absolute")
def test_amplitude_1_same_absolute(s):
    r = direct_stats(s, 5, s.vw_opt5, amplitude=1.0)[0] / direct_stats(s, 5, s.vw_opt5)[0]
    assert value(s, "fig19.same_absolute") is bool(0.5 < r < 2)


@claim_test(DOC, "ch8.low_w_005")
def test_low_omega_best(s):
    w = s.cfg["kalman"]["low_omegas"][0]
    e = min(sweep_direct(s, 5, v, w)[0] for v in s.settings[5])
    assert value(s, "ch8.low_w_005") == pytest.approx(e, rel=1e-12)


@pytest.mark.parametrize(
    "key",
    [
        pytest.param("ch8.w_gt_03", marks=claim_test(DOC, "ch8.w_gt_03")),
        pytest.param(
            "ch9.unacceptable_above_015", marks=claim_test(DOC, "ch9.unacceptable_above_015")
        ),
    ],
)
def test_high_omega_unacceptable(s, key):
    e = min(sweep_direct(s, 5, v, 0.4)[0] for v in s.settings[5])
    assert e > 0.1 * s.amp and value(s, key) is True


@claim_test(DOC, "ch9.estimation_increase")
def test_estimation_increases_error(s):
    e = direct_stats(s, 5, s.vw_opt5)[0]
    exact = long_max(s, s.ctrl, s.omega, 5, amplitude=s.amp)[0]
    assert e > 100 * exact and value(s, "ch9.estimation_increase") is True


@pytest.mark.parametrize(
    "key",
    [
        pytest.param("ch9.model_emphasis", marks=claim_test(DOC, "ch9.model_emphasis")),
        pytest.param("ch9.measurement_emphasis", marks=claim_test(DOC, "ch9.measurement_emphasis")),
        pytest.param(
            "ch9.optimal_small_below_01", marks=claim_test(DOC, "ch9.optimal_small_below_01")
        ),
    ],
)
def test_emphasis_at_low_omega(s, key):
    w = float(s.sweep_grid[0])
    e = [sweep_direct(s, 5, v, w)[0] for v in s.settings[5]]
    expected = {
        "ch9.model_emphasis": e[0] < 2 * s.res
        and ce.steepest(ce.curve(s, "I.14", 0)) > ce.steepest(ce.curve(s, "I.14", 1)),
        "ch9.measurement_emphasis": e[2] > e[1],
        "ch9.optimal_small_below_01": e[1] < 0.1 * s.amp,
    }[key]
    assert value(s, key) is bool(expected)


@claim_test(DOC, "ch9.fifth_best")
def test_fifth_order_best(s):
    best = {q: min(direct_stats(s, q, v)[0] for v in (5e-10, 5e-9)) for q in (2, 3, 5)}
    assert min(best, key=best.get) == 5 and value(s, "ch9.fifth_best") is True


@claim_test(DOC, "ch9.half_resolution_floor")
def test_half_resolution_floor(s):
    # the smallest error of any run is bounded below by half the resolution
    assert min(s.kalman_sweep["e_max"].min(), s.vw_search["e_max"].min()) >= 0.05
    assert value(s, "ch9.half_resolution_floor") is True


# ----------------------------------------------------------------------------- app. H
@claim_test(DOC, "appH.nominal_err")
def test_long_run_error(s):
    from abglib.replications.antenna.study_estimation import run_stats

    n = int(np.ceil(s.cfg["robustness"]["duration"] / s.dt))
    st = run_stats(
        s.params,
        s.ctrl,
        transient=s.transient,
        amplitude=s.amp,
        omega=s.omega,
        n_steps=n,
        phases=s.phases,
        mode="kalman",
        order=5,
        v_w=s.vw_filter(s.vw_opt5),
        v_v=s.vv,
        resolution=s.res,
    )
    assert value(s, "appH.nominal_err") == pytest.approx(np.median(st.e), rel=1e-12)


def radius(s, name, f):
    return spectral_radius(s.params, name, f, s.dt, s.q, s.r, 5, s.vw_filter(s.vw_opt5), s.vv)


@pytest.mark.parametrize(
    "key",
    [
        pytest.param(k, marks=claim_test(DOC, k))
        for k in (
            "appH.beta_d_upper",
            "appH.beta_a_lower",
            "appH.beta_a_upper",
            "appH.p_a_lower",
            "appH.p_a_upper",
        )
    ],
)
def test_stability_edges(s, key):
    v = value(s, key)
    name = key.split(".")[1].rsplit("_", 1)[0]
    tol = s.cfg["robustness"]["radius_tolerance"]
    res = CLAIMS.compute(s, key)
    if res.bound:  # a grid end: still stable there, judged as a bound (no reading tried)
        assert res.bound == ("<" if key.endswith("lower") else ">")
        assert radius(s, name, v) <= 1 + tol
        assert "reproduced is the grid's end" in res.note
    else:  # a located edge: stable just inside, unstable just outside
        inside = v * (1.001 if key.endswith("lower") else 0.999)
        outside = v * (0.999 if key.endswith("lower") else 1.001)
        assert radius(s, name, inside) <= 1 + tol < radius(s, name, outside)


@claim_test(DOC, "appH.beta_d_stable_below")
def test_beta_d_stable_below_four(s):
    fs = [f for f in s.radii_of("beta_d")["factor"] if f < 4]
    ok = all(radius(s, "beta_d", f) <= 1 + 1e-6 for f in fs)
    assert value(s, "appH.beta_d_stable_below") is ok


@claim_test(DOC, "appH.p_a_inertia")
def test_p_a_inertia_is_circular(s):
    res = CLAIMS.compute(s, "appH.p_a_inertia")
    # p_a = 0.9 was solved from 0.005 = (1 - p_a) x 0.05: the claim cannot test itself
    assert res.value is None and "5 %" in res.note


@claim_test(DOC, "appH.others_never")
def test_others_never_unstable(s):
    ok = all(radius(s, n, f) <= 1 + 1e-6 for n in ("p_f", "beta_f", "kappa") for f in (0.5, 2.0))
    assert ok and value(s, "appH.others_never") is True


@claim_test(DOC, "appH.beta_a_p_a_most_sensitive")
def test_most_sensitive_parameters(s):
    res = CLAIMS.compute(s, "appH.beta_a_p_a_most_sensitive")
    # the small config's factor grid (0.5-2) ends before beta_d's and beta_a's edges: both
    # stable to the grid's ends, so their margins are bounds and cannot be ordered
    for n in ("beta_d", "beta_a"):
        r = s.stability_of(n)
        assert np.isnan(r["lower"]) and np.isnan(r["upper"])
        assert radius(s, n, r["grid_min"]) <= 1 + 1e-6 and radius(s, n, r["grid_max"]) <= 1 + 1e-6
    assert res.value is None and "beta_a cannot be told to be more sensitive" in res.note
    # p_a's lower edge is inside even this grid
    assert "p_a is more sensitive than beta_d" in res.note
    assert design_controller(s.params, s.dt, s.q, s.r) is s.ctrl  # memoised design


class _Edges:
    """A stand-in study whose stability rows are given (``name: (lower, upper, lo, hi)``)."""

    def __init__(self, rows):
        self.rows = rows

    def stability_of(self, name):
        lo, hi, gmin, gmax = self.rows[name]
        return {"lower": lo, "upper": hi, "grid_min": gmin, "grid_max": gmax}

    def printed(self, key):  # the printed edges of Figs I.20-I.22
        return PRINTED_EDGES[key]


PRINTED_EDGES = {
    "appH.beta_d_upper": "4",
    "appH.beta_a_lower": "0.8",
    "appH.beta_a_upper": "1.2",
    "appH.p_a_lower": "0.995",
    "appH.p_a_upper": "1.005",
}


# release v0.4.5's stability.csv: beta_d and beta_a stable to the grid's end 10
RELEASE_EDGES = {
    "beta_d": (0.49991, np.nan, 0.1, 10.0),
    "beta_a": (0.28106, np.nan, 0.1, 10.0),
    "p_a": (0.98172, 1.0277, 0.1, 1.05),
}


def test_most_sensitive_compares_located_edges_only():
    from abglib.replications.antenna.claims_apph import _most

    res = _most(_Edges(RELEASE_EDGES))
    # the nearer edges are located: beta_a tolerates a factor 0.281, beta_d only 0.5, so
    # beta_a is not the more sensitive (margins ln(1/0.5) = 0.693, ln(1/0.281) = 1.27)
    assert res.value is False
    assert "|ln| of the design factor at the nearer edge" in res.note
    assert "beta_d 0.693 (edges 0.5 to > 10)" in res.note
    assert "beta_a 1.27 (edges 0.281 to > 10)" in res.note
    assert "beta_a is not more sensitive than beta_d, p_a is more sensitive" in res.note
    # on the printed edges the claim holds: margins ln 4, ln 1.2 and -ln 0.995
    assert "printed edges (Figs I.20-I.22) the margins are beta_d 1.39, beta_a 0.182, p_a " in (
        res.note
    )
    assert "the claim holds there: the disagreement is in the reconstructed windows" in res.note
    # widths counting a grid end are lower bounds, and beta_a against beta_d is open
    assert "do not decide it (beta_d >= 3, beta_a >= 3.57, p_a 0.0458)" in res.note


def test_most_sensitive_is_open_when_a_nearer_edge_is_past_the_grid():
    from abglib.replications.antenna.claims_apph import _most

    # beta_a stable over its whole grid 0.1-1.5: its margin is only bounded, >= ln 1.5 =
    # 0.405, which beta_d's located 0.693 neither exceeds nor falls below for sure
    rows = {**RELEASE_EDGES, "beta_a": (np.nan, np.nan, 0.1, 1.5)}
    res = _most(_Edges(rows))
    assert res.value is None and "beta_a >= 0.405" in res.note
    # the text's own window 0.8-1.2 (margin ln 1.2 = 0.182): decided, more sensitive
    rows["beta_a"] = (0.8, 1.2, 0.1, 10.0)
    assert _most(_Edges(rows)).value is True


def test_every_claim_declares_the_inputs_it_reads():
    """No Kalman claim without the measurement and V_w inputs; nothing model-free with inputs."""
    for key in ("fig17.u_max", "sec83.opt_range", "appH.p_a_lower"):
        assert {"antenna.kalman.v_v", "antenna.kalman.vw_scale"} <= set(CLAIMS.depends_on(key))
    assert CLAIMS.depends_on("fig4.deviation_grows") == ()
    assert "antenna.samples_per_period" in CLAIMS.depends_on("fig9.third_w1")


@claim_test(DOC, "ch9.finer_resolution")
def test_finer_resolution(s):
    from abglib.replications.antenna.study_estimation import n_steps_for

    r = simulate_phases(
        s.params, s.ctrl, amplitude=s.amp, omega=s.omega,
        n_steps=n_steps_for(s.omega, s.dt, s.sim), phases=s.phases, mode="kalman", order=5,
        v_w=s.vw_filter(s.vw_opt5), v_v=s.vv, resolution=s.res / 10,
    )  # fmt: skip
    sel = r["t"] >= s.transient
    fine = np.median(np.abs(r["e"][:, sel]).max(axis=1))
    coarse = direct_stats(s, 5, s.vw_opt5)[0]
    assert value(s, "ch9.finer_resolution") is bool(coarse / fine > 1.2)


@claim_test(DOC, "ch9.speed_error_small")
def test_speed_error_not_attempted(s):
    assert CLAIMS.compute(s, "ch9.speed_error_small").value is None


def test_stability_edges_written_at_their_precision(s):
    """The edges are located to 1e-6 relative (brentq): the table declares 5 digits and the
    edge claims return the edge rounded to them (the 7th digit moves with the BLAS kernel)."""
    from abglib.replications.antenna.claims_apph import EDGE_DIGITS

    assert s.stability.attrs["precision"] == {"lower": EDGE_DIGITS, "upper": EDGE_DIGITS}
    lo = s.stability_of("p_a")["lower"]
    assert value(s, "appH.p_a_lower") == float(f"{lo:.{EDGE_DIGITS}g}")


def test_simulate_phases_reuses_the_object_states_read_only(s):
    from abglib.replications.antenna.ensemble import phase_states, snap

    kw = dict(amplitude=10.0, omega=0.1, n_steps=200, phases=phase_grid(3), mode="kalman")
    kw.update(order=3, v_w=5e-10, v_v=s.vv)
    a = simulate_phases(s.params, s.ctrl, **kw)
    b = simulate_phases(s.params, s.ctrl, **kw)
    assert a["z"].base is b["z"].base and not a["z"].flags.writeable
    t = np.arange(200) * s.ctrl.dt
    order = a["xt_err"].shape[1] - 1
    xt = snap(phase_states(10.0, 0.1, t, order, phase_grid(3)))
    np.testing.assert_array_equal(a["z"], xt[:, 0])


# ----------------------------------------------------------------------------- added in v0.4.0
def _object_dare(s, order, v_w):
    """The object block of eq 7.15 alone, by scipy's DARE (the filter's dual problem): the
    Taylor model (eqs 3.4-3.5) observed through the tracking error with variance V_v[e]."""
    at, ct, gt = taylor_model(order, s.dt)
    q = scipy.linalg.solve_discrete_are(at.T, ct.T, v_w * gt @ gt.T, np.atleast_2d(s.vv[1, 1]))
    k = at @ q @ ct.T / (ct @ q @ ct.T + s.vv[1, 1])
    return q, at - k @ ct


@claim_test(DOC, "ch7.af_inside_unit_circle")
def test_af_keeps_the_antennas_unit_eigenvalue(s):
    from abglib.replications.antenna.model import continuous_model

    # the reconstructed antenna has a free rotation (no rotor-stator stiffness): a zero
    # eigenvalue of the continuous model, z = exp(0 dt) = 1 of the discrete one
    ac, _, _ = continuous_model(s.params)
    assert np.min(np.abs(np.linalg.eigvals(ac))) < 1e-9
    ad = scipy.linalg.expm(ac * s.dt)
    assert np.max(np.abs(np.linalg.eigvals(ad))) == pytest.approx(1.0, abs=1e-9)
    t = s.kalman_af
    for order, v_w in zip(t["order"], t["v_w"], strict=True):
        _, af_obj = _object_dare(s, order, s.vw_filter(v_w))
        r_obj = np.max(np.abs(np.linalg.eigvals(af_obj)))
        assert r_obj < 0.99  # the filter does stabilise the object model (its poles are at 1)
        row = t[(t["order"] == order) & (t["v_w"] == v_w)].iloc[0]
        # the object eigenvalues of A_f by the DARE route; the antenna's are the plant's
        assert row["radius_object"] == pytest.approx(r_obj, rel=1e-6)
        assert row["radius_af"] == pytest.approx(1.0, abs=1e-9)
    res = CLAIMS.compute(s, "ch7.af_inside_unit_circle")
    assert res.value is False and "z = 1" in res.note


@claim_test(DOC, "ch7.q_positive_definite")
def test_q_is_only_semidefinite(s):
    from abglib.replications.antenna.kalman import extended_model

    order = 5
    v_w = s.vw_filter(s.vw_opt5)
    at, ct, gt = taylor_model(order, s.dt)
    em = extended_model(s.ctrl.A, s.ctrl.B, s.ctrl.C, at, ct, gt)
    n = em.n_antenna
    # eq 7.15 iterated as printed, Q <- V_w + A Q [I + M^T V_v^-1 M Q]^-1 A^T, from Q = V_w:
    # V_w has no antenna part (w = 0) and A is block diagonal, so the antenna block stays 0
    vw = v_w * em.G @ em.G.T
    vvi = np.linalg.inv(s.vv)
    q = vw.copy()
    for _ in range(300):
        q = vw + em.A @ q @ np.linalg.solve(np.eye(q.shape[0]) + em.M.T @ vvi @ em.M @ q, em.A.T)
    assert np.max(np.abs(q[:n, :n])) == 0.0 and np.max(np.abs(q[:n, n:])) == 0.0
    q_obj, _ = _object_dare(s, order, v_w)
    assert np.linalg.eigvalsh(q_obj).min() > 0  # positive definite on the object block
    t = s.kalman_af
    assert (t["q_rank"] == t["q_size"] - n).all() and (t["q_min_eig"] == 0.0).all()
    assert CLAIMS.compute(s, "ch7.q_positive_definite").value is False


@claim_test(DOC, "sec82.vw_list_order")
def test_sec82_list_contradicts_sec83(s):
    # whatever the lost exponents k, 5 * 10^-k is never 0.1 (sec. 8.3's third order), and
    # 0.1 is never 5 * 10^-k (sec. 8.2's fifth order); the reversed list fits both
    fives = [5 * 10.0**-k for k in range(0, 16)]
    assert not any(np.isclose(f, 0.1, rtol=1e-9) for f in fives)
    assert float(s.printed("sec82.vw_opt_third")) == 0.1
    res = CLAIMS.compute(s, "sec82.vw_list_order")
    assert res.value is False and "(checked)" in res.note


@claim_test(DOC, "ch9.acceleration_hardly")
def test_acceleration_term_by_time_domain_simulation(s):
    from abglib.replications.antenna.lq import riccati_iterate, tracker_matrices
    from abglib.replications.antenna.model import continuous_model

    t = s.acceleration_term.set_index("k")
    c, w = s.ctrl, s.omega
    # k = 0 is the design of the text: the study's own controller, same amplitudes
    base = steady_state_amplitudes(c, w, s.amp, "predicted", 5)
    assert t.loc[0.0, "e"] == pytest.approx(base["e"], rel=1e-6)
    assert t.loc[0.0, "u"] == pytest.approx(base["u"], rel=1e-9)
    # k = 0.1: P by the value iteration of eq 2.12 (not scipy's DARE), then the closed loop
    # run in time on the exact Taylor states of z = a sin(omega t) (not the frequency response)
    ac, _, _ = continuous_model(s.params)
    k = 0.1
    cy = np.vstack([c.C, ac[3:4]])
    qy = np.diag([s.q, k * s.q / w**4])
    p = riccati_iterate(c.A, c.B, cy.T @ qy @ cy, [[s.r]], max_iter=2_000_000)
    tm = tracker_matrices(c.A, c.B, cy, qy, [[s.r]], p=p)
    at, ct, _ = taylor_model(5, s.dt)
    ct2 = np.zeros_like(ct)
    ct2[0, 2] = 1.0
    kt = preview_gain(tm, at, np.vstack([ct, ct2]))
    n = int(np.ceil(6 * 2 * np.pi / w / s.dt))
    x, e = np.zeros(6), []
    for i in range(n):
        ti = i * s.dt
        xt = np.array([s.amp * w**j * np.sin(w * ti + j * np.pi / 2) for j in range(6)])
        e.append(x[0] - xt[0])
        x = c.A @ x + c.B[:, 0] * float((-tm.K @ x - kt @ xt)[0])
    tail = np.abs(np.array(e[n // 2 :]))  # the last three periods, after the transient
    assert tail.max() == pytest.approx(t.loc[k, "e"], rel=2e-3)
    # the text's "hardly": the control input moves by well under 1 %, the error does not
    assert abs(t.loc[1.0, "u"] / t.loc[0.0, "u"] - 1) < 0.01
    assert t.loc[k, "e"] / t.loc[0.0, "e"] > 100
    assert CLAIMS.compute(s, "ch9.acceleration_hardly").value is None


@claim_test(DOC, "sec82.off_optimum_character")
def test_off_optimum_estimation_errors_sine_or_noise_like(s):
    from abglib.replications.antenna.study_estimation import n_steps_for

    # independent route: the simulator called directly, and the share of the error's power
    # in the periodogram bins within 30 % of omega (not a least-squares sine fit)
    shares = []
    for v_w in s.settings[5]:
        r = simulate_phases(
            s.params,
            s.ctrl,
            amplitude=s.amp,
            omega=s.omega,
            n_steps=n_steps_for(s.omega, s.dt, s.sim),
            phases=phase_grid(s.cfg["kalman"]["phases"]),
            mode="kalman",
            order=5,
            v_w=s.vw_filter(v_w),
            v_v=s.vv,
            resolution=s.res,
        )
        sel = r["t"] >= s.transient
        e = r["xt_err"][:, 0, sel]
        e = e - e.mean(axis=1, keepdims=True)
        power = np.abs(np.fft.rfft(e, axis=1)) ** 2
        freq = 2 * np.pi * np.fft.rfftfreq(e.shape[1], d=s.dt)
        near = np.abs(freq - s.omega) <= 0.3 * s.omega
        shares.append(float(np.median(power[:, near].sum(axis=1) / power.sum(axis=1))))
    model, opt, meas = shares
    assert model > opt > meas
    assert value(s, "sec82.off_optimum_character") is True


def test_p_a_edge_search_reaches_the_admissible_limit():
    """At a plausible model (beta_a = 0.1) the loop is still stable at p_a's last grid
    factor 1.05: the search goes on towards 1 / p_a and locates the edge (near 1.07), where
    v0.4.5 had only the bound 1.05 (and read the printed 1.005 as a misprint of it)."""
    import copy

    from .conftest import repo_config

    cfg = copy.deepcopy(repo_config())
    cfg["antenna"]["parameters"]["beta_a"] = 0.1
    s = study_for("antenna", cfg)
    row = s.stability_of("p_a")
    limit = 1.0 / s.params.p_a
    assert 1.05 < row["upper"] < row["grid_max"] < limit
    tol = s.cfg["robustness"]["radius_tolerance"]
    assert (
        radius(s, "p_a", row["upper"] * 0.999) <= 1 + tol < radius(s, "p_a", row["upper"] * 1.001)
    )
    # an independent route: the first factor above 1.05 on a fine scan that is unstable
    scan = np.arange(1.05, limit, 1e-3)
    first = next(f for f in scan if radius(s, "p_a", f) > 1 + tol)
    assert abs(first - row["upper"]) <= 1e-3
