"""Every published claim of seed 003 (``data/published/faa_bendix``), one declaration each.

The letter report (``program.*``), Sinsky's memo (``memo.*``) and the plot captions
(``captions.*``). The only assumed input is the plot's height in grid divisions
(``faa_bendix.plot_divisions``), on which the reconstructed scale factors SFY depend.
"""

from __future__ import annotations

import re

import numpy as np

from ...common.tables import roundoff
from ...verdicts import tolerance_from_printed
from .._claims import ClaimSet, Reading, Result
from . import program as bendix
from .study import FaaBendixStudy

__all__ = ["CLAIMS", "STUDY"]

CLAIMS = ClaimSet("faa_bendix")
STUDY = FaaBendixStudy

_ROUNDING = "Memo table: rounding of the gains"
_DIVISIONS = "faa_bendix.plot_divisions"


# --------------------------------------------------------------------------- the letter report
@CLAIMS.claim("program.equations")
def _equations(s: FaaBendixStudy) -> Result:
    worst = s.literal_difference
    n = s.responses.groupby(["table", "period_s", "input"]).ngroups
    return Result(
        worst <= 1e-12,
        f"largest |literal program - abglib.track(init='zero')| over {n} runs x 3 graphs: "
        f"{roundoff(worst)}",
    )


@CLAIMS.claim("program.impulse")
def _impulse(s: FaaBendixStudy) -> Result:
    ok, areas = True, []
    for p in s.periods:
        z = s.input("impulse", p)
        area = float(np.sum(z) * p)
        areas.append(area)
        ok &= bool(np.count_nonzero(z) == 1 and z[0] == 1.0 / p and abs(area - 1.0) <= 1e-12)
    lo, hi = f"{min(areas):g}", f"{max(areas):g}"
    area = f"{lo} for every T" if lo == hi else f"{lo}-{hi} over the periods"
    return Result(ok, f"one nonzero sample 1/T at k = 0; area T * sum(z) = {area}")


def _ramp_rises(z: np.ndarray, T: float) -> int:
    """Leading samplings over which the input rises by exactly T."""
    steps = np.diff(z)
    n = 0
    while n < steps.size and abs(steps[n] - T) <= 1e-12 * max(1.0, T):
        n += 1
    return n


@CLAIMS.claim("program.ramp")
def _ramp(s: FaaBendixStudy) -> Result:
    ok = True
    for p in s.periods:
        z = s.input("ramp", p)
        n = _ramp_rises(z, float(p))
        ok &= bool(z[0] == 0.0 and n >= 1 and np.all(z[n + 1 :] == 0.0))
    return Result(ok, "z[0] = 0, z[k] = k T while rising (slope 1), then 0 to the end")


@CLAIMS.claim("program.ramp.periods")
def _ramp_periods(s: FaaBendixStudy) -> Result:
    counts = {_ramp_rises(s.input("ramp", p), float(p)) for p in s.periods}
    if len(counts) != 1:
        return Result(None, f"the ramp rises over different numbers of samplings: {sorted(counts)}")
    return Result(float(counts.pop()), "samplings the generated ramp input rises by T")


@CLAIMS.claim("program.intervals")
def _intervals(s: FaaBendixStudy) -> Result:
    sizes = set(s.responses.groupby(["table", "period_s", "input"]).size())
    if len(sizes) != 1:
        return Result(None, f"runs of different lengths: {sorted(sizes)}")
    return Result(float(sizes.pop()), "samples per graph of every run")


@CLAIMS.claim("program.graphs")
def _graphs(s: FaaBendixStudy) -> Result:
    n = s.responses["input"].nunique() * len(bendix.GRAPHS)
    return Result(float(n), "test inputs x graphed outputs of one run")


# --------------------------------------------------------------------------- the memo
def _memo_key(key: str) -> tuple[int, str]:
    """``'memo.T7.beta'`` -> ``(7, 'beta')``."""
    p, name = re.fullmatch(r"memo\.T(\d+)\.(\w+)", key).groups()
    return int(p), name


@CLAIMS.family(r"memo\.T\d+\.(alpha|beta)")
def _memo_gain(s: FaaBendixStudy, key: str) -> Result:
    p, _ = _memo_key(key)
    d = s.damping_lags.set_index("period_s").loc[p]
    return Result(
        None,
        "an input of the memo's row, not derived: Guarino's selection rule (Bendix TN "
        "FB-467-012) is not among the seeds (see the 'optimum' row); the set is "
        f"{d['damping']}, zeta = {d['zeta']:.3f}, beta = {d['beta_over_benedict']:.2f} x "
        "the Benedict-Bordner beta",
    )


@CLAIMS.family(r"memo\.T\d+\.(position|velocity)")
def _memo_ratio(s: FaaBendixStudy, key: str) -> Result:
    p, k = _memo_key(key)
    m = s.closed_form.loc[p]
    value = float(m[f"{k}_closed"])
    note = ""
    printed = s.printed(key)
    if abs(value - float(printed)) > tolerance_from_printed(printed):
        m = s.monte_carlo_row(p) | dict(m)  # the simulation only where the note shows it
        note = (
            f"closed form = Lyapunov {value:.5f}; Monte Carlo {m[f'{k}_mc']:.4f} (95% CI "
            f"{m[f'{k}_mc_lo']:.4f}-{m[f'{k}_mc_hi']:.4f}) with the printed gains"
        )
    r = s.rounding.set_index("period_s").loc[p]
    readings = ()
    if bool(r["both_reproduced"]):
        readings = (
            Reading(
                f"unrounded gains alpha={r['best_alpha']:.4f}, beta={r['best_beta']:.4f} "
                f"(which print as the memo's {m['alpha']:.3f}, {m['beta']:.3f}; both ratios "
                f"of the row reproduced together: {r['best_position']:.4f}, "
                f"{r['best_velocity']:.4f})",
                float(r[f"best_{k}"]),
                _ROUNDING,
                family="typo:rounded intermediate (the memo's rounded gains)",
            ),
        )
    return Result(value, note, readings)


def _example_row(s: FaaBendixStudy):
    return s.closed_form.loc[int(s.cfg["example_period_s"])]


@CLAIMS.claim("memo.example.angle")
def _example_angle(s: FaaBendixStudy) -> Result:
    return Result(
        float(_example_row(s)["position_closed"]), "closed form, memo gains of the example's period"
    )


@CLAIMS.claim("memo.example.rate")
def _example_rate(s: FaaBendixStudy) -> Result:
    return Result(
        float(_example_row(s)["velocity_closed"]), "closed form, memo gains of the example's period"
    )


@CLAIMS.claim("memo.claim.columns")
def _columns(s: FaaBendixStudy) -> Result:
    m = s.closed_form
    tol = np.array([tolerance_from_printed(s.printed(f"memo.T{p}.velocity")) for p in m.index])
    vel_ok = np.abs(m["velocity_closed"] - m["velocity_published"]).to_numpy() <= tol
    later = m.index > 1  # at T = 1 s the two readings coincide
    per_sample = np.abs(m["velocity_per_sample"] - m["velocity_published"]).to_numpy() <= tol
    return Result(
        bool(np.all(vel_ok) and not np.any(per_sample[later])),
        f"{int(vel_ok.sum())} of {len(m)} rows agree with sqrt(k_v) in 1/s; "
        f"{int(per_sample[later].sum())} of {int(later.sum())} (T >= 2 s) with the per-sample "
        "sqrt(k_v) T; section 'What the memo's columns are'",
    )


@CLAIMS.claim("memo.claim.reduction")
def _reduction(s: FaaBendixStudy) -> Result:
    pos = s.closed_form["position_closed"]
    return Result(
        bool(np.all(pos < 1.0)),
        f"smoothed-position ratio {pos.min():.3f}-{pos.max():.3f}; section 'Memo table'",
    )


@CLAIMS.claim("memo.claim.optimum")
def _optimum(s: FaaBendixStudy) -> Result:
    d = s.damping_lags
    classes = ", ".join(sorted(set(d["damping"])))
    return Result(
        None,
        "the memo does not state the optimality criterion and the Bendix TN FB-467-012 is "
        "not among the seeds; the gains are neither critically damped nor Benedict-Bordner "
        f"(beta is {d['beta_over_benedict'].min():.1f}-{d['beta_over_benedict'].max():.1f} "
        f"times the Benedict-Bordner beta: {classes}), see section 'Beyond the source'",
    )


# --------------------------------------------------------------------------- the captions
def _caption_key(key: str):
    kind, p, name = re.fullmatch(r"captions\.(impulse|ramp)\.T(\d+)\.(\w+)", key).groups()
    return kind, int(p), name


def _caption_row(s: FaaBendixStudy, kind: str, p: int):
    c = s.captions_table
    return c[(c["input"] == kind) & (c["period_s"] == p)].iloc[0]


@CLAIMS.family(r"captions\.(impulse|ramp)\.T\d+\.(alpha|beta)")
def _caption_gain(s: FaaBendixStudy, key: str) -> Result:
    kind, p, name = _caption_key(key)
    r = _caption_row(s, kind, p)
    memo = float(r[f"{name}_memo"])
    return Result(
        memo,
        f"memo {name} {s.printed(f'memo.T{p}.{name}')}: rounded to the caption's decimals "
        f"{r[f'{name}_memo_rounded']:.2f}, truncated {r[f'{name}_memo_truncated']:.2f}",
        (
            Reading(
                f"the memo's {name} {s.printed(f'memo.T{p}.{name}')} truncated (not rounded) "
                "to the caption's two decimals",
                float(r[f"{name}_memo_truncated"]),
                "The gain tables and what their difference does",
                family="typo:truncated (the memo's gain)",
            ),
        ),
    )


@CLAIMS.family(r"captions\.(impulse|ramp)\.T\d+\.period")
def _caption_period(s: FaaBendixStudy, key: str) -> Result:
    kind, p, _ = _caption_key(key)
    r = _caption_row(s, kind, p)
    return Result(
        float(r["nearest_memo_period"]), "period of the memo row nearest the caption's gains"
    )


@CLAIMS.family(r"captions\.(impulse|ramp)\.T\d+\.sfy", depends_on=(_DIVISIONS,))
def _caption_sfy(s: FaaBendixStudy, key: str) -> Result:
    kind, p, _ = _caption_key(key)
    r = _caption_row(s, kind, p)
    return Result(
        float(r["sfy_reconstructed"]),
        f"reconstructed rule: the power of ten that fits the {kind} input's peak "
        f"{r['input_peak']:.4g} in {s.cfg['plot_divisions']:g} divisions (the program's "
        f"scaling is not printed); at the printed SFY the peak is "
        f"{r['input_peak_in_sfy']:.3g} divisions",
    )


# --------------------------------------------------------------------------- added in v0.4.0
@CLAIMS.claim("captions.ramp.T5.predicted_twice")
def _t5_predicted_twice(s: FaaBendixStudy) -> Result:
    """The T = 5 s ramp captions print PREDICTED POSITION XP(K) on two of the three
    graphs and SMOOTHED VELOCITY on none: judged, as the captions literally say, against
    the program's graphs of one run (graphs 4-6: each ramp output once) and its T = 5 s
    ramp outputs at the captions' gains."""
    p = 5
    sfy = float(s.caption("ramp", p)["sfy"])
    r = s.responses
    run = r[(r["table"] == "captions") & (r["period_s"] == p) & (r["input"] == "ramp")]
    outs = list(bendix.GRAPHS)
    n_pred = outs.count("x_pred")
    gaps = {
        (a, b): float(np.max(np.abs(run[a].to_numpy() - run[b].to_numpy())))
        for i, a in enumerate(outs)
        for b in outs[i + 1 :]
    }
    peak = {o: float(np.max(np.abs(run[o].to_numpy()))) for o in outs}
    return Result(
        n_pred >= 2,
        f"the program draws each of its {len(outs)} ramp outputs once per run "
        f"({', '.join(bendix.GRAPHS.values())}) and they differ (smallest largest difference "
        f"{min(gaps.values()):.3g}), so one of the two PREDICTED POSITION captions labels the "
        f"SMOOTHED VELOCITY graph: a misprinted caption, not a second X_PK graph. Which one the "
        f"lost figures do not show; at the printed SFY = {sfy:g} that graph's curve peaks at "
        f"{peak['v_smooth'] / sfy:.2f} divisions (|X_DKB| <= {peak['v_smooth']:.3g}), the "
        f"predicted position's at {peak['x_pred'] / sfy:.2f}. The scan's page order points to "
        f"the first of the two: the ramp captions of the other periods run smoothed "
        f"position, predicted position, smoothed velocity (cyclically)",
    )
