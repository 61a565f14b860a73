"""Claims of chapter 8, the summary and chapter 9 of seed 004 (Kalman estimation, quantiser).

Every maximum under quantisation is the median over the phase ensemble of the study
(``kalman.phases`` object phases, :mod:`.ensemble`): one run's maximum is chaotic.
"""

from __future__ import annotations

import numpy as np

from .._claims import Result
from ._claimset import CLAIMS, EST, SPREAD

__all__: list[str] = []

MED = "median over the object phases of the per-run maximum"
EST_SPREAD = (*EST, SPREAD)


def fig(s, name):
    d = s.kalman_sweep
    return d[d["figure"] == name]


def curve(s, name, which: int):
    """One curve (0 model emphasis, 1 optimum, 2 measurement emphasis) of Figs I.14-I.16."""
    d = fig(s, name)
    order = 3 if name == "I.16" else 5
    return d[d["v_w"] == s.settings[order][which]].set_index("omega")


def opt_best(s, order):
    return s.stats(order, s.vw_optimum(order))


# ----------------------------------------------------------------------------- sec. 8.2
@CLAIMS.claim("sec82.vw_opt_fifth", depends_on=EST)
def _vw5(s):
    return Result(
        None,
        f"the exponent is lost in the scan; in the reconstructed model the "
        f"optimum on 5 x 10^k (printed units) is V_w = {s.vw_opt5:.0e} ({MED})",
    )


@CLAIMS.claim("sec82.pos_err_lt_1pct", depends_on=EST)
def _pos(s):
    e = opt_best(s, 5).est_med(0)
    return Result(
        bool(e < 0.01 * s.amp),
        f"max position-estimation error {e:.3g} = {100 * e / s.amp:.3g} % of the amplitude ({MED})",
    )


@CLAIMS.family(r"sec82\.(vel|acc|fifth_deriv)_err", depends_on=EST)
def _deriv(s, key):
    j = {"vel": 1, "acc": 2, "fifth_deriv": 5}[key.split(".")[1].rsplit("_", 1)[0]]
    e = opt_best(s, 5).est_med(j)
    return Result(
        100 * e / (s.amp * s.omega**j),
        f"derivative {j}: {MED}, in % of amplitude x omega^{j}, at the optimal V_w {s.vw_opt5:.0e}",
    )


@CLAIMS.claim("sec82.opt_smallest_tracking", depends_on=EST)
def _smallest(s):
    est, trk = s.vw_optimum(5, "est_err_d0"), s.vw_opt5
    return Result(
        bool(est == trk),
        f"V_w minimising the position-estimation error {est:.0e}, "
        f"the tracking error {trk:.0e} ({MED})",
    )


@CLAIMS.claim("sec82.lower_order_larger_vw", depends_on=EST)
def _lower(s):
    qs = [q for q in s.cfg["kalman"]["orders"] if q >= 3]
    opts = [s.vw_optimum(q) for q in qs]
    return Result(
        bool(np.all(np.diff(opts) < 0)),
        "optimal V_w for orders "
        + ", ".join(f"{q}: {v:.0e}" for q, v in zip(qs, opts, strict=True)),
    )


#: The three printed third-order settings of Fig. I.16 (sec. 8.3: 0.01, 0.1 and 1).
def printed_third(s) -> list[float]:
    return [0.1 * 10.0**k for k in (-1, 0, 1)]


@CLAIMS.claim("sec82.vw_opt_third", depends_on=EST)
def _vw3(s):
    e = {v: s.stats(3, v).e_med for v in printed_third(s)}
    best = min(e, key=e.get)
    return Result(
        best,
        "max tracking error for printed V_w = 0.01, 0.1, 1: "
        + ", ".join(f"{v:.3g}" for v in e.values())
        + f" ({MED}); on the fine grid the third-order optimum is "
        f"{s.vw_optimum(3):.0e}",
    )


@CLAIMS.claim("sec82.off_optimum_larger", depends_on=EST_SPREAD)
def _off(s):
    st = [s.stats(5, v) for v in s.settings[5]]
    worse = all(st[i].est_med(j) > st[1].est_med(j) for i in (0, 2) for j in (0, 1, 2))
    return Result(
        worse,
        "max estimation error of position, speed, acceleration at model "
        "emphasis / optimum / measurement emphasis: "
        + "; ".join(", ".join(f"{x.est_med(j):.3g}" for x in st) for j in (0, 1, 2)),
    )


def sharpness(s, order) -> float:
    """Mean factor by which the (median) max error grows one decade either side of the optimum."""
    d = s.vw_search[s.vw_search["order"] == order].set_index("v_w")["e_max"]
    o = s.vw_optimum(order)
    side = [d[v] / d[o] for v in d.index if np.isclose(v, o * 10) or np.isclose(v, o / 10)]
    return float(np.mean(side))


@CLAIMS.family(r"(sec82\.lower_order_less_critical|ch9\.order_more_critical)", depends_on=EST)
def _critical(s, key):
    qs = [q for q in s.cfg["kalman"]["orders"] if q >= 3]
    sh = [sharpness(s, q) for q in qs]
    return Result(
        bool(np.all(np.diff(sh) > 0)),
        "mean growth of the max error one decade of V_w "
        "either side of the optimum, orders "
        + ", ".join(f"{q}: {v:.3g}" for q, v in zip(qs, sh, strict=True)),
    )


@CLAIMS.claim("sec82.larger_omega_larger_vw", depends_on=EST)
def _larger_w(s):
    w2 = 2 * s.omega
    exps = range(
        int(s.cfg["kalman"]["vw_exponents"][0]), int(s.cfg["kalman"]["vw_exponents"][1]) + 1
    )
    e = {5 * 10.0**k: s.stats(5, 5 * 10.0**k, omega=w2).e_med for k in exps}
    best = min(e, key=e.get)
    return Result(
        bool(best > s.vw_opt5),
        f"fifth order: optimal V_w {s.vw_opt5:.0e} at omega = "
        f"{s.omega:g}, {best:.0e} at omega = {w2:g} ({MED})",
    )


@CLAIMS.claim("sec82.larger_amplitude_larger_vw", depends_on=EST)
def _larger_a(s):
    a2 = float(max(s.cfg["kalman"]["amplitudes"]))
    exps = range(
        int(s.cfg["kalman"]["vw_exponents"][0]), int(s.cfg["kalman"]["vw_exponents"][1]) + 1
    )
    e = {5 * 10.0**k: s.stats(5, 5 * 10.0**k, amplitude=a2).e_med for k in exps}
    best = min(e, key=e.get)
    return Result(
        bool(best > s.vw_opt5),
        f"fifth order: optimal V_w {s.vw_opt5:.0e} at amplitude "
        f"{s.amp:g}, {best:.0e} at amplitude {a2:g} ({MED})",
    )


# ----------------------------------------------------------------------------- sec. 8.3
@CLAIMS.claim("sec83.w_gt_02_gt_10pct", depends_on=EST_SPREAD)
def _w02(s):
    d = fig(s, "I.14")
    hi = d[d["omega"] > 0.2]
    m = hi["e_max"].min() / s.amp
    return Result(bool(m > 0.1), f"smallest max error for omega > 0.2: {m:.3g} of the amplitude")


@CLAIMS.claim("sec83.qr_small_decrease", depends_on=EST_SPREAD)
def _qr_small(s):
    k14, k15 = fig(s, "I.14"), fig(s, "I.15")
    ratio_k = float(
        np.median(k14.groupby("omega")["e_max"].min() / k15.groupby("omega")["e_max"].min())
    )
    d = s.omega_sweep
    pp = d[d["case"] == f"order {max(s.cfg['omega_sweep']['orders'])}"].pivot(
        index="omega", columns="q_over_r", values="e_max"
    )
    ratio_p = float(np.median(pp.iloc[:, 0] / pp.iloc[:, 1]))
    return Result(
        bool(ratio_k < ratio_p),
        f"median error ratio Q/R 100 : 10^4, with estimation "
        f"{ratio_k:.3g}, exact states {ratio_p:.3g}",
    )


@CLAIMS.claim("sec83.qr_more_control", depends_on=EST_SPREAD)
def _qr_more(s):
    k14, k15 = fig(s, "I.14"), fig(s, "I.15")
    inc = [
        float(
            np.median(
                k15[k15["v_w"] == v]["u_max"].to_numpy() / k14[k14["v_w"] == v]["u_max"].to_numpy()
            )
        )
        for v in s.settings[5]
    ]
    thr = float(s.thresholds["considerable_ratio"])
    return Result(
        bool(inc[2] > thr and inc[2] == max(inc)),
        "median control ratio Q/R 10^4 : "
        "100 for the three V_w: " + ", ".join(f"{v:.3g}" for v in inc),
    )


def spread_at_low(s, name) -> float:
    d = fig(s, name)
    lo = d[d["omega"] == d["omega"].min()]["e_max"]
    return float(lo.max() / lo.min())


@CLAIMS.claim("sec83.third_less_critical", depends_on=EST_SPREAD)
def _third_less(s):
    r3, r5 = spread_at_low(s, "I.16"), spread_at_low(s, "I.14")
    return Result(
        bool(r3 < r5),
        f"max/min error over the three V_w at the smallest omega: "
        f"{r3:.3g} for the third order (decade spacing, as printed), {r5:.3g} for the "
        f"fifth (spread {s.cfg['kalman']['spread_fifth']:g}, lost in the scan)",
    )


@CLAIMS.claim("sec83.third_more_control", depends_on=EST_SPREAD)
def _third_more(s):
    u3 = float(curve(s, "I.16", 1)["u_max"].median())
    u5 = float(curve(s, "I.14", 1)["u_max"].median())
    thr = float(s.thresholds["considerable_ratio"])
    return Result(
        bool(u3 > thr * u5),
        f"median over omega of the max control at the optimal V_w: "
        f"third order {u3:.3g}, fifth {u5:.3g}, ratio {u3 / u5:.3g} ('considerably "
        f"larger' read as a ratio above {thr:g})",
    )


def curve_minimum(c) -> tuple[float, float]:
    """(omega, value) of a curve's minimum, refined by a parabola in log-log coordinates."""
    w, e = np.log(c.index.to_numpy()), np.log(c["e_max"].to_numpy())
    i = int(np.argmin(e))
    if 0 < i < len(e) - 1:
        a, b, _ = np.polyfit(w[i - 1 : i + 2], e[i - 1 : i + 2], 2)
        if a > 0:
            x = -b / (2 * a)
            return float(np.exp(x)), float(np.exp(np.polyval([a, b, _], x)))
    return float(np.exp(w[i])), float(np.exp(e[i]))


def range_edge(c, factor) -> float:
    """Largest omega (log-interpolated) up to which a curve stays within ``factor`` x its min."""
    w, e = c.index.to_numpy(), c["e_max"].to_numpy()
    i0 = int(np.argmin(e))
    lim = factor * e[i0]
    for i in range(i0, len(e) - 1):
        if e[i + 1] > lim:
            f = (np.log(lim) - np.log(e[i])) / (np.log(e[i + 1]) - np.log(e[i]))
            return float(np.exp(np.log(w[i]) + f * (np.log(w[i + 1]) - np.log(w[i]))))
    return float(w[-1])


WHICH = {"model": 0, "opt": 1}


@CLAIMS.family(r"sec83\.(model|opt)_best_omega", depends_on=EST_SPREAD)
def _best_omega(s, key):
    w, e = curve_minimum(curve(s, "I.14", WHICH[key.split(".")[1].split("_")[0]]))
    return Result(
        w,
        f"omega of the minimum of the Fig. I.14 curve (parabola in log-log through "
        f"the grid minimum): max error there {100 * e / s.amp:.3g} % of the amplitude",
    )


@CLAIMS.family(r"sec83\.(model|opt)_min_err", depends_on=EST_SPREAD)
def _min_err(s, key):
    _, e = curve_minimum(curve(s, "I.14", WHICH[key.split(".")[1].split("_")[0]]))
    return Result(
        100 * e / s.amp, f"smallest max error of the Fig. I.14 curve ({MED}), % of the amplitude"
    )


@CLAIMS.family(r"sec83\.(model|opt)_range", depends_on=EST_SPREAD)
def _range(s, key):
    thr = float(s.thresholds["near_ratio"])
    w = range_edge(curve(s, "I.14", WHICH[key.split(".")[1].split("_")[0]]), thr)
    return Result(
        w,
        f"largest omega up to which the Fig. I.14 curve stays within {thr:g} x its "
        "minimum (the text's 'range in which this tracking error is obtained')",
    )


@CLAIMS.claim("sec83.larger_vw_best_omega_same", depends_on=EST_SPREAD)
def _larger_same(s):
    w1, _ = curve_minimum(curve(s, "I.14", 1))
    w2, _ = curve_minimum(curve(s, "I.14", 2))
    thr = float(s.thresholds["near_ratio"])
    r = max(w1, w2) / min(w1, w2)
    return Result(
        bool(r < thr),
        f"omega of the minimum: optimal V_w {w1:.3g}, larger V_w "
        f"{w2:.3g} (ratio {r:.3g}, 'very little' below {thr:g})",
    )


@CLAIMS.claim("sec83.model_w02_amplitude", depends_on=EST_SPREAD)
def _model_w02(s):
    c = curve(s, "I.14", 0)
    r = float(np.exp(np.interp(np.log(0.2), np.log(c.index), np.log(c["e_max"])))) / s.amp
    thr = float(s.thresholds["near_ratio"])
    return Result(
        bool(1 / thr < r < thr),
        f"model-emphasis V_w at omega = 0.2: max error "
        f"{r:.3g} x the amplitude ('about as big' within a factor {thr:g})",
    )


@CLAIMS.claim("sec83.fig16_same_small_omega", depends_on=EST)
def _fig16_same(s):
    r = spread_at_low(s, "I.16")
    thr = float(s.thresholds["near_ratio"])
    return Result(
        bool(r < thr),
        f"Fig. I.16, smallest omega: max/min error over the three V_w "
        f"{r:.3g} ('about the same' below {thr:g})",
    )


def steepest(c) -> float:
    w, e = np.log(c.index.to_numpy()), np.log(c["e_max"].to_numpy())
    return float(np.max(np.diff(e) / np.diff(w)))


@CLAIMS.claim("sec83.fig16_smoother", depends_on=EST_SPREAD)
def _fig16_smooth(s):
    k3, k5 = steepest(curve(s, "I.16", 1)), steepest(curve(s, "I.14", 1))
    return Result(
        bool(k3 < k5),
        f"steepest log-log slope of the max error against omega at the "
        f"optimal V_w: third order {k3:.3g}, fifth {k5:.3g}",
    )


# ----------------------------------------------------------------------------- sec. 8.4
def amp_stats(s, amp):
    return s.stats(5, s.vw_opt5, amplitude=amp)


@CLAIMS.claim("fig17.err_lt_3pct", depends_on=EST)
def _lt3(s):
    e = amp_stats(s, s.amp).e_med
    return Result(bool(e < 0.03 * s.amp), f"{100 * e / s.amp:.3g} % of the amplitude ({MED})")


@CLAIMS.claim("fig17.u_max", depends_on=EST)
def _u17(s):
    return Result(amp_stats(s, s.amp).u_med, f"max |u| at the optimal settings ({MED})")


@CLAIMS.family(r"(fig18\.err_a100|fig19\.err_a1|ch8\.normal_3pct)", depends_on=EST)
def _err_amp(s, key):
    a = {"fig18.err_a100": 100.0, "fig19.err_a1": 1.0, "ch8.normal_3pct": s.amp}[key]
    e = amp_stats(s, a).e_med
    return Result(100 * e / a, f"amplitude {a:g}: max |e| {e:.3g} ({MED}), in % of the amplitude")


@CLAIMS.claim("fig18.err_a100_larger_vw", depends_on=EST)
def _a100_larger(s):
    fs = s.cfg["kalman"]["larger_vw_factors"]
    e = [s.stats(5, s.vw_opt5 * f, amplitude=100.0).e_med for f in fs]
    return Result(
        100 * min(e) / 100.0, "best over V_w x " + ", ".join(f"{f:g}" for f in fs) + f" ({MED})"
    )


def sine_fraction(s, amp) -> float:
    """Share of the error's variance (after the transient) in a sine at the track's omega."""
    r = s.stats(5, s.vw_opt5, amplitude=amp, keep=True).run
    sel = r["t"] >= s.transient
    t, fr = r["t"][sel], []
    basis = np.column_stack([np.sin(s.omega * t), np.cos(s.omega * t), np.ones_like(t)])
    for e in r["e"][:, sel]:
        coef, *_ = np.linalg.lstsq(basis, e, rcond=None)
        fr.append(1.0 - np.var(e - basis @ coef) / np.var(e))
    return float(np.median(fr))


@CLAIMS.claim("fig18.more_sine_like", depends_on=EST)
def _sine(s):
    f10, f100 = sine_fraction(s, s.amp), sine_fraction(s, 100.0)
    return Result(
        bool(f100 > f10),
        f"share of the error variance in a sine at omega (median "
        f"over phases): amplitude 100: {f100:.3g}, amplitude {s.amp:g}: {f10:.3g}",
    )


@CLAIMS.claim("fig18.u_much_larger", depends_on=EST)
def _u100(s):
    r = amp_stats(s, 100.0).u_med / amp_stats(s, s.amp).u_med
    thr = float(s.thresholds["considerable_ratio"])
    return Result(bool(r > thr), f"max |u| at amplitude 100 / at {s.amp:g}: {r:.3g} ({MED})")


@CLAIMS.claim("fig19.same_absolute", depends_on=EST)
def _abs_same(s):
    r = amp_stats(s, 1.0).e_med / amp_stats(s, s.amp).e_med
    thr = float(s.thresholds["near_ratio"])
    return Result(
        bool(1 / thr < r < thr),
        f"max |e| at amplitude 1 / at {s.amp:g}: {r:.3g} "
        f"('about as large' within a factor {thr:g}; {MED})",
    )


@CLAIMS.claim("ch8.low_w_005", depends_on=EST_SPREAD)
def _low(s):
    ws = s.cfg["kalman"]["low_omegas"]
    low = [min(s.stats(5, v, omega=float(w)).e_med for v in s.settings[5]) for w in ws]
    return Result(
        min(low),
        "best over the three V_w settings at omega = "
        + ", ".join(f"{w:g}" for w in ws)
        + f" ({MED})",
    )


@CLAIMS.claim("ch8.w_gt_03", depends_on=EST_SPREAD)
def _w03(s):
    d = s.kalman_sweep
    hi = d[(d["omega"] > 0.3) & (d["figure"] != "I.15")]
    m = hi["e_max"].min() / s.amp
    return Result(bool(m > 0.1), f"smallest max error for omega > 0.3: {m:.3g} of the amplitude")


@CLAIMS.claim("summary.three_resolutions", depends_on=EST)
def _three(s):
    e = amp_stats(s, s.amp).e_med
    return Result(e / s.res, f"max |e| {e:.3g} at the optimal settings, normal track ({MED})")


@CLAIMS.claim("ch9.unacceptable_above_015", depends_on=EST_SPREAD)
def _above015(s):
    c = curve(s, "I.14", 1)
    m = c[c.index > 0.15]["e_max"].min() / s.amp
    return Result(
        bool(m > 0.1),
        f"smallest max error at the optimal V_w for omega > 0.15: {m:.3g} of the amplitude",
    )


@CLAIMS.claim("ch9.estimation_increase", depends_on=EST)
def _est_inc(s):
    from .closedloop import steady_state_amplitudes

    ex = s.amp * steady_state_amplitudes(s.ctrl, s.omega, 1.0, "predicted", 5)["e"]
    e = amp_stats(s, s.amp).e_med
    thr = float(s.thresholds["considerable_ratio"])
    return Result(
        bool(e > thr * ex),
        f"normal track, fifth order: max |e| {e:.3g} with "
        f"estimation ({MED}), {ex:.3g} with exact states",
    )


@CLAIMS.claim("ch9.model_emphasis", depends_on=EST_SPREAD)
def _model_emph(s):
    m, o = curve(s, "I.14", 0), curve(s, "I.14", 1)
    low = float(m["e_max"].iloc[0])
    thr = float(s.thresholds["near_ratio"])
    ok = bool(low < thr * s.res and steepest(m) > steepest(o))
    return Result(
        ok,
        f"model-emphasis V_w: max |e| {low:.3g} at omega = {m.index[0]:.3g} "
        f"(resolution {s.res:g}; 'about' within a factor {thr:g}); steepest log-log "
        f"slope {steepest(m):.3g} against {steepest(o):.3g} at the optimum",
    )


@CLAIMS.claim("ch9.measurement_emphasis", depends_on=EST_SPREAD)
def _meas_emph(s):
    m, o = curve(s, "I.14", 2), curve(s, "I.14", 1)
    lo_m, lo_o = float(m["e_max"].iloc[0]), float(o["e_max"].iloc[0])
    return Result(
        bool(lo_m > lo_o),
        f"smallest omega {m.index[0]:.3g}: max |e| {lo_m:.3g} "
        f"(measurement emphasis) against {lo_o:.3g} (optimum)",
    )


@CLAIMS.claim("ch9.optimal_small_below_01", depends_on=EST_SPREAD)
def _small01(s):
    c = curve(s, "I.14", 1)
    m = c[c.index <= s.omega * (1 + 1e-9)]["e_max"].max() / s.amp
    return Result(
        bool(m < 0.1),
        f"largest max error at the optimal V_w for omega <= "
        f"{s.omega:g}: {100 * m:.3g} % of the amplitude ('small' below 10 %)",
    )


@CLAIMS.claim("ch9.fifth_best", depends_on=EST)
def _fifth_best(s):
    best = {
        q: float(s.vw_search[s.vw_search["order"] == q]["e_max"].min())
        for q in s.cfg["kalman"]["orders"]
    }
    return Result(
        bool(min(best, key=best.get) == 5),
        "smallest max error over V_w per order: "
        + ", ".join(f"{q}: {v:.3g}" for q, v in best.items())
        + f" ({MED})",
    )


@CLAIMS.claim("ch9.half_resolution_floor", depends_on=EST_SPREAD)
def _floor(s):
    m = min(float(s.kalman_sweep["e_max"].min()), float(s.vw_search["e_max"].min()))
    return Result(
        bool(m >= s.res / 2),
        f"smallest max error of every Kalman run of the study: "
        f"{m:.3g} (half the resolution {s.res / 2:g})",
    )


@CLAIMS.claim("ch9.finer_resolution", depends_on=EST)
def _finer(s):
    e = amp_stats(s, s.amp).e_med
    f = s.stats(5, s.vw_opt5, resolution=s.res / 10).e_med
    thr = float(s.thresholds["considerable_ratio"])
    return Result(
        bool(e / f > thr),
        f"normal track, optimal settings: max |e| {e:.3g} at resolution {s.res:g}, {f:.3g} at "
        f"{s.res / 10:g} (same V_w and V_v; {MED})",
    )


@CLAIMS.claim("ch9.speed_error_small")
def _speed(s):
    return Result(
        None,
        "the functional with a speed-error term and its weights are not given; not attempted",
    )
