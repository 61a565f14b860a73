"""Every published claim of seed 000 (Steelman 1978), one declaration each.

The printed side is ``data/published/steelman1978/*.csv``; the numbers come from
:class:`~.study.SteelmanStudy`. Notes cite the report sections (headings of
``workflow/notebooks/steelman1978.py``) that demonstrate them.
"""

from __future__ import annotations

import numpy as np

from ... import analysis as A
from ...common.tables import roundoff
from ...gains import Gains
from .._claims import ClaimSet, Reading, Result
from .study import SteelmanStudy

__all__ = ["CLAIMS", "STUDY"]

CLAIMS = ClaimSet("steelman1978")
STUDY = SteelmanStudy

# report sections cited by notes
SEC_FIGS = "1. Figures 1–6"
SEC_GAINS = "2. Tables 1 and 2: the gains of Figures 5 and 6"
SEC_DESIGN = "3. The design example"
SEC_T345 = "4. Tables 3–5: analytical expressions"
SEC_EQS = "5. Equations: table of agreement"
SEC_STAB = "6. Stability criteria"
SEC_TEXT = "7. Statements of the text"

SIMILAR = "steelman1978.judging.similar_db"
APPROX = "steelman1978.judging.approx_rtol"


def _f(x, digits=4) -> str:
    return f"{x:.{digits}g}"


# ------------------------------------------------------------------ Tables 1-2
def _table_gains(s: SteelmanStudy, key: str) -> Gains:
    table, kind, _ = key.split(".")
    alpha = s.t1_alpha if table == "table1" else s.t2_alpha
    if kind == "std_abg":
        return s.std(alpha)
    if kind == "std_ab":
        return s.std(alpha, 2)
    return s.qd_t1 if table == "table1" else s.qd_t2


@CLAIMS.family(r"table[12]\.(std_abg|std_ab)\.(beta|gamma)|table2\.qd\.(alpha|beta|gamma)")
def _gain(s: SteelmanStudy, key: str) -> Result:
    g = _table_gains(s, key)
    return Result(float(getattr(g, key.rsplit(".", 1)[1])))


@CLAIMS.claim("table1.qd.alpha")
def _qd_alpha_printed_m(s: SteelmanStudy) -> Result:
    m = s.printed("text.qd_m_alpha_0.3")
    return Result(s.qd_printed_m.alpha, f"QD with m = {m} as stated in the text")


@CLAIMS.family(r"table1\.qd\.(beta|gamma)")
def _qd_t1(s: SteelmanStudy, key: str) -> Result:
    g = s.qd_t1
    return Result(
        float(getattr(g, key.rsplit(".", 1)[1])),
        f"QD with m = {s.qd_m_t1:.4f} (the m giving α = {s.t1_alpha:g}); see '{SEC_GAINS}'",
    )


@CLAIMS.claim("text.qd_m_alpha_0.3")
def _qd_m(s: SteelmanStudy) -> Result:
    return Result(s.qd_m_t1)


# ------------------------------------------------------------------ Tables 3-5
def _alpha_of(key: str) -> float:
    return float(key.split(".", 2)[2])


@CLAIMS.family(r"table3\.approx\.[0-9.]+")
def _t3_approx(s: SteelmanStudy, key: str) -> Result:
    r = s.table345_row(_alpha_of(key))
    e6 = s.cfg["eq53_exponent_6db"]
    return Result(
        r["wT_6dB_eq53"], f"eq 53 with exponent {e6:g} as the text says; see '{SEC_T345}'"
    )


@CLAIMS.family(r"table3\.exact\.[0-9.]+")
def _t3_exact(s: SteelmanStudy, key: str) -> Result:
    r = s.table345_row(_alpha_of(key))
    return Result(
        r["wT_6dB_exact"],
        f"exact -6 dB frequency {r['wT_6dB_exact']:.4f}, |X̄/X| = 0.5 at "
        f"{r['wT_half_exact']:.4f}; the printed 'exact' values are not the exact crossing of "
        f"the standard α-β-γ tracker (read off Fig. 2?); see '{SEC_T345}'",
        (
            Reading(
                "ωT where |X̄/X| = 0.5 (−6.02 dB) instead of −6 dB",
                r["wT_half_exact"],
                SEC_T345,
                family="convention:half amplitude instead of -6 dB",
            ),
        ),
    )


@CLAIMS.family(r"table4\.exact\.[0-9.]+")
def _t4_exact(s: SteelmanStudy, key: str) -> Result:
    return Result(s.table345_row(_alpha_of(key))["overshoot_exact"])


@CLAIMS.family(r"table4\.approx\.[0-9.]+")
def _t4_approx(s: SteelmanStudy, key: str) -> Result:
    v = s.table345_row(_alpha_of(key))["overshoot_eq55"]
    return Result(
        v,
        f"eq 55 as printed gives {v:.4f}; no reading tried (M/D alone, the α-β or QD tracker "
        f"with the same α) gives the printed value; see '{SEC_T345}' and '{SEC_EQS}'",
    )


@CLAIMS.family(r"table5\.exact\.[0-9.]+")
def _t5_exact(s: SteelmanStudy, key: str) -> Result:
    v = s.table345_row(_alpha_of(key))["wTmax_exact"]
    return Result(
        v,
        f"exact peak at ωT = {v:.7f} (two independent routes agree); see '{SEC_T345}'",
    )


@CLAIMS.family(r"table5\.approx\.[0-9.]+")
def _t5_approx(s: SteelmanStudy, key: str) -> Result:
    r = s.table345_row(_alpha_of(key))
    return Result(
        r["wTmax_eq54"],
        f"sqrt(β/2) = {r['wTmax_eq54']:.7f} with β = {r['beta']:.7f}; see '{SEC_T345}'",
    )


# ------------------------------------------------------------------ design example (p. 8)
@CLAIMS.claim("design.wT_3db")
def _de_wt(s: SteelmanStudy) -> Result:
    return Result(s.design_exact["wT_3dB"])


@CLAIMS.claim("design.T")
def _de_T(s: SteelmanStudy) -> Result:
    return Result(s.design_exact["T_s"])


@CLAIMS.claim("design.rate")
def _de_rate(s: SteelmanStudy) -> Result:
    ex, pr = s.design_exact, s.design_printed
    return Result(
        ex["rate_per_s"],
        f"1/T is {ex['rate_per_s']:.1f}/s from the exact ωT, {pr['rate_per_s']:.1f}/s from the "
        f"printed {s.printed('design.wT_3db')} and {1.0 / s.value('design.T'):.1f}/s from the "
        f"printed T = {s.printed('design.T')}; none rounds to {s.printed('design.rate')} "
        f"(a rate rounded up for margin?); see '{SEC_DESIGN}'",
        (
            Reading(
                f"1/T with the printed T = {s.printed('design.T')}",
                1.0 / s.value("design.T"),
                SEC_DESIGN,
                family="typo:rounded intermediate (the printed T)",
            ),
        ),
    )


def _hz(s: SteelmanStudy, name: str) -> str:
    return f"{s.cfg['design_example'][name]:g}"


@CLAIMS.claim("design.wT_60hz")
def _de_wt60(s: SteelmanStudy) -> Result:
    return Result(
        s.design_exact["wT_60Hz"],
        readings=(
            Reading(
                f"({_hz(s, 'interference_hz')}/{_hz(s, 'passband_hz')}) × the printed "
                f"{s.printed('design.wT_3db')} (the graph reading)",
                s.design_printed["wT_60Hz"],
                SEC_DESIGN,
                family="typo:rounded intermediate (the printed graph reading)",
            ),
        ),
    )


@CLAIMS.claim("design.attenuation_60hz_db")
def _de_att(s: SteelmanStudy) -> Result:
    return Result(s.design_exact["atten_60Hz_dB"])


@CLAIMS.claim("design.first_max_offset")
def _de_d(s: SteelmanStudy) -> Result:
    return Result(s.design_exact["d"])


def _printed_d_T(s: SteelmanStudy) -> str:
    return (
        f"with the printed d = {s.printed('design.first_max_offset')} "
        f"and T = {s.printed('design.T')}"
    )


@CLAIMS.claim("design.omega_first_max")
def _de_omega(s: SteelmanStudy) -> Result:
    return Result(
        s.design_exact["omega_first_max"],
        readings=(
            Reading(
                f"(2π − d)/T {_printed_d_T(s)}",
                s.design_printed["omega_first_max"],
                SEC_DESIGN,
                family="typo:rounded intermediate (the printed d and T)",
            ),
        ),
    )


@CLAIMS.claim("design.f_first_max")
def _de_f(s: SteelmanStudy) -> Result:
    return Result(
        s.design_exact["f_first_max_Hz"],
        readings=(
            Reading(
                f"(2π − d)/(2π T) {_printed_d_T(s)}",
                s.design_printed["f_first_max_Hz"],
                SEC_DESIGN,
                family="typo:rounded intermediate (the printed d and T)",
            ),
        ),
    )


# ------------------------------------------------------------------ equations (table of agreement)
def _eq_label(key: str) -> str:
    return key.split(".", 1)[1].replace("_", "-")


@CLAIMS.family(r"eq\.\d+(_\d+)?")
def _equation(s: SteelmanStudy, key: str) -> Result:
    """A printed equation the text presents as exact: it holds on every checked gain set
    (``holds`` of the table of agreement); the note names what it equals instead."""
    eq = _eq_label(key)
    rows = s.equations[s.equations["equation"] == eq]
    holds = bool(rows["holds"].astype(bool).all())
    note = (
        f"{len(rows)} gain sets ({', '.join(rows['case'])}); worst relative difference from the "
        f"exact route {roundoff(float(rows['rel_diff'].max()))}"
    )
    matches = sorted({m for x in rows["matches"] for m in str(x).split(", ") if m})
    if not holds and matches:
        note += (
            f"; the printed form equals the exact {' and '.join(matches)} VRF (one-step "
            f"prediction) to rounding, not the smoothed-output k(0) that the text defines with "
            f"Simpson's eqs 11-13"
        )
    if eq == "32":
        note += "; printed k_y(0) is read as k_v(0) (OCR)"
    if eq == "20":
        note += "; printed A_x² in eq 20 is read as A_a² (OCR)"
    readings = ()
    per_set = [set(str(x).split(", ")) - {""} for x in rows["matches"]]
    common = sorted(set.intersection(*per_set)) if per_set else []
    if not holds and common:
        # the chance that an unrelated closed form agrees with the named exact VRF to the
        # check's relative tolerance r on one gain set: a window of 2 r |v| in the decade
        # of v (at least 0.9 |v| long), so at most 2 r / 0.9 per candidate output (the
        # other gain sets, each as unlikely, are not counted: a bound)
        rtol = float(s.cfg["equation_checks"]["exact_rtol"])
        readings = (
            Reading(
                f"the printed form as the exact {' and '.join(common)} VRF (one-step "
                f"prediction) on all {len(rows)} gain sets",
                True,
                SEC_EQS,
                family="convention:predicted instead of smoothed estimate",
                chance=len(common) * 2 * rtol / 0.9,
            ),
        )
    return Result(holds, f"{note}; see '{SEC_EQS}'", readings)


# ------------------------------------------------------------------ stability (eqs 42-49)
def _stab(s: SteelmanStudy, eq: str):
    return s.stability.set_index("equations").loc[eq]


def _n(r) -> str:
    return f"{int(r['samples'])} random gain sets"


@CLAIMS.claim("claim.jury_exact")
def _jury(s: SteelmanStudy) -> Result:
    r = _stab(s, "45-48")
    ok = r["criterion_true_but_unstable"] == 0 and r["agree"] == r["samples"]
    return Result(bool(ok), f"{_n(r)}, {int(r['agree'])} agree with the poles; see '{SEC_STAB}'")


@CLAIMS.claim("claim.eqs42_44_exact")
def _jury_ab(s: SteelmanStudy) -> Result:
    r = _stab(s, "42-44")
    ok = r["criterion_true_but_unstable"] == 0 and r["agree"] == r["samples"]
    return Result(
        bool(ok), f"{_n(r)} (γ = 0), {int(r['agree'])} agree with the poles; see '{SEC_STAB}'"
    )


@CLAIMS.claim("claim.eq49_sufficient")
def _eq49(s: SteelmanStudy) -> Result:
    r = _stab(s, "45,46,48,49")
    return Result(
        bool(r["criterion_true_but_unstable"] == 0),
        f"{_n(r)}, {int(r['criterion_true_but_unstable'])} pass eq 49 but are unstable; "
        f"see '{SEC_STAB}'",
    )


@CLAIMS.claim("claim.eq49_not_necessary")
def _eq49_nn(s: SteelmanStudy) -> Result:
    r = _stab(s, "45,46,48,49")
    k = int(r["criterion_false_but_stable"])
    return Result(
        k > 0,
        f"{_n(r)}: {k} of {int(r['stable_by_poles'])} stable sets fail eq 49; see '{SEC_STAB}'",
    )


@CLAIMS.family(r"claim\.(eqs42_44_imply_45|eqs45_47_48_imply_43|gamma0_reduces_stability)")
def _implication(s: SteelmanStudy, key: str) -> Result:
    eq = {
        "claim.eqs42_44_imply_45": "42-44 ⇒ 45",
        "claim.eqs45_47_48_imply_43": "45,47,48 ⇒ 43",
        "claim.gamma0_reduces_stability": "45-47 at γ=0 ⇔ 42-44",
    }[key]
    r = _stab(s, eq)
    note = f"{_n(r)}, {int(r['agree'])} agree; see '{SEC_STAB}'"
    if key == "claim.gamma0_reduces_stability":
        note = f"eq 48 (γ > 0) cannot hold at γ = 0 and is left out; {note}"
    return Result(bool(r["agree"] == r["samples"]), note)


# ------------------------------------------------------------------ frequency-domain claims
@CLAIMS.claim("claim.eq50_min_at_pi")
def _eq50_min(s: SteelmanStudy) -> Result:
    grid = s.wt_linear[1:]
    at_pi = [
        np.argmin(np.abs(A.frequency_response(s.std(a), "x_smooth", grid))) == grid.size - 1
        for a in s.check_alphas
    ]
    return Result(all(at_pi), f"checked on the {grid.size}-point linear grid")


@CLAIMS.claim("claim.eq50_gamma_free")
def _eq50_gamma(s: SteelmanStudy) -> Result:
    g = s.std(s.check_alphas[0])
    vals = [
        abs(A.frequency_response(Gains(g.alpha, g.beta, gm), "x_smooth", np.pi))
        for gm in (0.0, g.gamma, 2 * g.gamma)
    ]
    rtol = s.cfg["equation_checks"]["exact_rtol"]
    return Result(bool(np.ptp(vals) <= rtol * vals[0]), f"γ = 0, γ_std, 2γ_std at α = {g.alpha:g}")


@CLAIMS.claim("claim.eq51_exact")
def _eq51(s: SteelmanStudy) -> Result:
    rtol = s.cfg["equation_checks"]["exact_rtol"]
    ok = []
    for a in s.check_alphas:
        g = s.std(a)
        exact = A.omega_at_gain(g, 0.0)
        ok.append(abs(A.omega_unity_eq51(g) - exact) <= rtol * exact)
    return Result(all(ok), f"standard α-β-γ at α = {', '.join(f'{a:g}' for a in s.check_alphas)}")


@CLAIMS.claim("claim.fig3_phase_monotone")
def _fig3_phase(s: SteelmanStudy) -> Result:
    grid = s.wt_linear[1:]
    ph = np.degrees(np.unwrap(np.angle(A.frequency_response(s.std(s.t1_alpha), "x_pred", grid))))
    top = int(np.argmax(ph))
    return Result(
        bool(np.all(np.diff(ph) < 0)),
        f"the phase first rises to +{ph[top]:.4f}° at ωT = {grid[top]:.3f} (a small lead of the "
        f"predictor), then decreases monotonically; see '{SEC_FIGS}'",
    )


@CLAIMS.claim("claim.fig3_magnitude_similar", depends_on=(SIMILAR,))
def _fig3_mag(s: SteelmanStudy) -> Result:
    gap, where = s.fig3_gap
    th = float(s.judging["similar_db"])
    return Result(
        gap <= th,
        f"|X_p/X| and |X̄/X| (α = {s.t1_alpha:g}) differ by at most {gap:.3f} dB (at ωT = "
        f"{where:.3f}) on ωT {s.wt_log[0]:g}..π; 'very similar' read as within {th:g} dB; "
        f"see '{SEC_TEXT}'",
    )


@CLAIMS.claim("claim.fig4_similar_above_0.2", depends_on=(SIMILAR,))
def _fig4(s: SteelmanStudy) -> Result:
    gap, where, _, _ = s.fig4_gap
    th = float(s.judging["similar_db"])
    return Result(
        gap <= th,
        f"|X̄/X| and |{s.fig4_scale:g}T²Ā/X| (α = {s.fig4_alpha:g}) differ by at most {gap:.3f} dB "
        f"for ωT > {s.judging['fig4_above_wT']:g} (at ωT = {where:.3f}); they stay within "
        f"{th:g} dB from ωT = {s.similar_from(th):.3f} on; see '{SEC_TEXT}'",
    )


@CLAIMS.claim("claim.log_straight_line", depends_on=(SIMILAR,))
def _straight(s: SteelmanStudy) -> Result:
    dev = s.straight_line
    th = float(s.judging["similar_db"])
    return Result(
        max(dev.values()) <= th,
        "max deviation of 20 log|X̄/X| from the straight line (log ωT) between |X̄/X| = 1 and "
        "ωT = π: "
        + ", ".join(f"{v:.2f} dB at α = {a:g}" for a, v in dev.items())
        + f"; 'nearly' read as within {th:g} dB; see '{SEC_TEXT}'",
    )


def _within(s: SteelmanStudy, column: str, what: str) -> Result:
    t = s.approximations
    rtol = float(s.judging["approx_rtol"])
    worst = float(t[column].max())
    return Result(
        worst <= rtol,
        f"{what}: relative error "
        + ", ".join(f"{e:.2%} at α = {a:g}" for a, e in zip(t["alpha"], t[column], strict=True))
        + f"; read as good within {rtol:.0%}; see '{SEC_TEXT}'",
    )


@CLAIMS.claim("claim.eq52_good", depends_on=(APPROX,))
def _eq52(s: SteelmanStudy) -> Result:
    return _within(s, "eq52_rel_err", "eq 52 against the exact ωT of |X̄/X| = 1")


@CLAIMS.claim("claim.eq53_reasonable", depends_on=(APPROX,))
def _eq53(s: SteelmanStudy) -> Result:
    return _within(s, "eq53_rel_err", "eq 53 (-3 dB, as printed) against the exact -3 dB ωT")


@CLAIMS.claim("claim.max_near_midpoint", depends_on=(APPROX,))
def _midpoint(s: SteelmanStudy) -> Result:
    return _within(s, "midpoint_rel_err", "ωT_max against half the ωT of |X̄/X| = 1")


@CLAIMS.claim("claim.cubic_0707")
def _cubic(s: SteelmanStudy) -> Result:
    rtol = s.cfg["equation_checks"]["exact_rtol"]
    ok, parts = [], []
    for a, (deg, root, exact) in s.cubic.items():
        ok.append(deg == 3 and abs(root - exact) <= 1e3 * rtol * exact)
        parts.append(f"α = {a:g}: degree {deg}, root ωT = {root:.6f} (exact {exact:.6f})")
    return Result(
        all(ok),
        "the target is |X̄/X| = 1/√2 exactly, the half-power point the text's 0.707 stands for "
        "(the abstract's row takes 0.707 as printed: a slightly larger ωT): |X̄/X|² = 1/2 as a "
        "polynomial in cos ωT: " + "; ".join(parts) + f"; see '{SEC_TEXT}'",
    )


@CLAIMS.claim("claim.overshoot_decreasing_alpha")
def _overshoot_alpha(s: SteelmanStudy) -> Result:
    overs = [float(A.peak(s.std(a))[1]) for a in s.check_alphas]
    return Result(
        bool(np.all(np.diff(overs) < 0)),
        "overshoot "
        + ", ".join(f"{o:.3f}" for o in overs)
        + " at α = "
        + ", ".join(f"{a:g}" for a in s.check_alphas),
    )


@CLAIMS.claim("claim.decrease_alpha_attenuation")
def _atten_alpha(s: SteelmanStudy) -> Result:
    trend = s.attenuation_trend
    db = [d for _, d in trend]
    return Result(
        bool(np.all(np.diff(db) < 0)),
        f"dB down at the 60 Hz ωT = {s.design_exact['wT_60Hz']:.3f}: "
        + ", ".join(f"{d:.1f} at α = {a:g}" for a, d in trend)
        + f"; see '{SEC_TEXT}'",
    )


@CLAIMS.claim("claim.overshoot_increasing_gamma")
def _overshoot_gamma(s: SteelmanStudy) -> Result:
    g = s.std(s.t1_alpha)
    fr = s.cfg["equation_checks"]["gamma_fractions"]
    og = [float(A.peak(Gains(g.alpha, g.beta, f * g.alpha * g.beta / 2))[1]) for f in fr]
    return Result(
        bool(np.all(np.diff(og) > 0)),
        "γ = ("
        + ", ".join(f"{f:g}" for f in fr)
        + ") × αβ/2: overshoot "
        + ", ".join(f"{o:.4f}" for o in og),
    )


# ------------------------------------------------------------------ definitions and conclusions
@CLAIMS.family(r"claim\.std_(abg|ab)_fading_memory")
def _fading(s: SteelmanStudy, key: str) -> Result:
    order = 3 if "abg" in key else 2
    errs = {a: e for (o, a), e in s.fading_memory.items() if o == order}
    worst = max(errs.values())
    return Result(
        worst <= 1e3 * s.cfg["equation_checks"]["exact_rtol"],
        f"impulse response of the standard tracker against the weights of the exponentially "
        f"weighted least-squares {'parabola' if order == 3 else 'line'} (θ of eqs 22-24 / p. 5): "
        f"max difference {roundoff(worst)} at α = {', '.join(f'{a:g}' for a in errs)}; "
        f"see '{SEC_TEXT}'",
    )


@CLAIMS.claim("claim.qd_least_squares")
def _qd_ls(s: SteelmanStudy) -> Result:
    g = s.qd_t2
    return Result(
        None,
        "the intercept and slope constraints are not stated (refs. 5-6, a WSMR report and a "
        "draft, are not among the seeds), so the fit cannot be set up; eqs 28-30 are used as "
        f"the definition (m = {s.cfg['table2']['qd_m']:g}: α = {g.alpha:.5f}, β = {g.beta:.5f}, "
        f"γ = {g.gamma:.6f}); see '{SEC_GAINS}'",
    )


@CLAIMS.claim("claim.simpson_reduces_to_bb")
def _simpson_bb(s: SteelmanStudy) -> Result:
    lim = s.simpson_limit
    worst = max(lim.values())
    return Result(
        worst <= 1e-6,
        "eqs 11, 12, 15, 16 at γ = 1e-9·β against the α-β VRF (Lyapunov) and D² (summed) of the "
        f"standard α-β gains: worst relative difference {_f(worst, 3)} (at γ = 0 itself "
        f"Y² = 0 and the forms are 0/0: the reduction is the limit γ → 0); see '{SEC_TEXT}'",
    )


@CLAIMS.claim("claim.eq21_minimizes")
def _eq21(s: SteelmanStudy) -> Result:
    res = []
    for name, g in (("standard", s.std(s.t1_alpha)), ("QD", s.qd_t1)):
        res.append(f"{name} {2 * g.beta - g.alpha * (g.alpha + g.beta + g.gamma / 2):.4f}")
    return Result(
        None,
        "the text does not say which combination of the measures is minimized, over which "
        "gains, nor what is held fixed (one equation in three unknowns, as it notes), and "
        "Simpson 1963 is not among the seeds; no single β at fixed α, γ minimizes all nine "
        "measures of eqs 11-20. Residual 2β - α(α + β + γ/2) of the Table 1 gains at "
        f"α = {s.t1_alpha:g}: " + ", ".join(res),
    )


@CLAIMS.claim("claim.summary_useful")
def _summary(s: SteelmanStudy) -> Result:
    t = s.approximations
    eq50 = s.equations[s.equations["equation"] == "50"]["rel_diff"].max()
    return Result(
        None,
        "'useful' is a judgement, not a number; their accuracy on the table alphas: eq 50 exact "
        f"(relative difference {roundoff(float(eq50))}), eq 53 within "
        f"{t['eq53_rel_err'].max():.1%} of the exact -3 dB ωT, eq 55 within "
        f"{t['eq55_rel_err'].max():.1%} of the exact overshoot; see '{SEC_T345}' and '{SEC_TEXT}'",
    )


# ------------------------------------------------------------------ abstract (added in v0.4.0)
@CLAIMS.claim("claim.abstract_0707", depends_on=(APPROX,))
def _abstract_0707(s: SteelmanStudy) -> Result:
    """The abstract: "equations are given for the frequency at which the output is 0.707
    of the input". The body gives no exact one (before eq 51: it "would require the
    symbolic solution of a cubic equation"); eq 53 is the only equation for it, so the
    claim is judged as eq 53 giving the 0.707 frequency, with the tolerance that reads
    "good"/"reasonable" elsewhere in the text (``judging.approx_rtol``)."""
    t = s.abstract_0707
    rtol = float(s.judging["approx_rtol"])
    return Result(
        bool(t["rel_err"].max() <= rtol),
        "no exact equation is given (the text says it needs a cubic); eq 53 (-.15) against the "
        "ωT where |X̄/X| = 0.707, the abstract's level as printed (Brent on the frequency "
        "response; not 1/√2, whose slightly smaller ωT is the cubic's row): "
        + ", ".join(
            f"{w53:.4f} vs {w:.4f} ({e:.2%}) at α = {a:g}"
            for a, w, w53, e in zip(
                t["alpha"], t["wT_0707"], t["wT_eq53"], t["rel_err"], strict=True
            )
        )
        + f"; 'given for' read as within {rtol:.0%}, as 'reasonable' for eq 53; see '{SEC_TEXT}'",
    )
